/* gallery.c (bench, chapter 1): the page of every figure, from the files in the figures folder.
 * See gallery.h. */
#include "gallery.h"

#include <ctype.h>
#include <dirent.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "atomic_file.h"

typedef struct {
    char **names;
    int count;
} Names;

/* What `make figures` recorded about its run (run.txt); empty strings when not said. */
typedef struct {
    int present, quick;
    char started[64], finished[64], seconds[32], threads[32];
} Run;

/* The page being written: where it goes, what the folder holds, where errors go. */
typedef struct {
    FILE *out;
    const GalleryPage *page;
    Names files; /* the folder's file names, sorted */
    Run run;
    char *error;
    int error_size;
} Writer;

typedef enum {
    FILE_FIGURE,
    FILE_PLOT,
    FILE_TABLE,
    FILE_TEXT,
    FILE_EXERCISE,
    FILE_OTHER
} FileKind;

static int fail(Writer *w, const char *what, const char *name)
{
    snprintf(w->error, (size_t)w->error_size, "%s %s: %s", what, name, strerror(errno));
    return -1;
}

static int ends_with(const char *text, const char *end)
{
    size_t length = strlen(text), end_length = strlen(end);
    return length >= end_length && strcmp(text + length - end_length, end) == 0;
}

/* dir/name into path[size]; -1 (errno ENAMETOOLONG) when it does not fit. */
static int join(char *path, size_t size, const char *dir, const char *name)
{
    if ((size_t)snprintf(path, size, "%s/%s", dir, name) >= size) {
        errno = ENAMETOOLONG;
        return -1;
    }
    return 0;
}

/* The whole file as a NUL-terminated string (*text to free). Returns 0, or -1 with errno. */
static int read_text(const char *path, char **text)
{
    FILE *file = fopen(path, "rb");
    if (!file)
        return -1;
    size_t length = 0, capacity = 4096;
    char *buffer = malloc(capacity);
    while (buffer) {
        length += fread(buffer + length, 1, capacity - 1 - length, file);
        if (length < capacity - 1)
            break;
        char *bigger = realloc(buffer, 2 * capacity);
        if (!bigger)
            free(buffer);
        buffer = bigger;
        capacity *= 2;
    }
    int failed = !buffer || ferror(file);
    int reason = buffer ? EIO : ENOMEM;
    fclose(file);
    if (failed) {
        free(buffer);
        errno = reason;
        return -1;
    }
    buffer[length] = '\0';
    *text = buffer;
    return 0;
}

static void names_free(Names *names)
{
    for (int i = 0; i < names->count; i++)
        free(names->names[i]);
    free(names->names);
    names->names = NULL;
    names->count = 0;
}

static int compare_names(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

/* The regular files of `dir`, sorted; hidden files and atomic_file.h's temporary files
 * ("NAME.tmp.PID") left out. Returns 0, or -1 with errno. */
static int list_files(const char *dir, Names *names)
{
    names->names = NULL;
    names->count = 0;
    DIR *folder = opendir(dir);
    if (!folder)
        return -1;
    int capacity = 0, status = 0;
    struct dirent *entry;
    while (status == 0 && (entry = readdir(folder)) != NULL) {
        char path[4200];
        struct stat info;
        if (entry->d_name[0] == '.' || strstr(entry->d_name, ".tmp.") ||
            join(path, sizeof path, dir, entry->d_name) != 0 || stat(path, &info) != 0 ||
            !S_ISREG(info.st_mode))
            continue;
        if (names->count == capacity) {
            capacity = capacity ? 2 * capacity : 64;
            char **bigger = realloc(names->names, (size_t)capacity * sizeof *bigger);
            if (!bigger) {
                status = -1;
                break;
            }
            names->names = bigger;
        }
        names->names[names->count] = strdup(entry->d_name);
        if (!names->names[names->count])
            status = -1;
        else
            names->count++;
    }
    closedir(folder);
    if (status != 0) {
        names_free(names);
        errno = ENOMEM;
        return -1;
    }
    if (names->count > 0)
        qsort(names->names, (size_t)names->count, sizeof *names->names, compare_names);
    return 0;
}

static int has_file(const Writer *w, const char *name)
{
    return w->files.count > 0 && bsearch(&name, w->files.names, (size_t)w->files.count,
                                         sizeof *w->files.names, compare_names) != NULL;
}

/* Width and height of a PNG, from its IHDR chunk (bytes 16-23, big-endian); 0 when the
 * file is not a PNG. */
static void png_size(const char *path, int *width, int *height)
{
    unsigned char header[24];
    *width = *height = 0;
    FILE *file = fopen(path, "rb");
    if (!file)
        return;
    size_t got = fread(header, 1, sizeof header, file);
    fclose(file);
    if (got != sizeof header || memcmp(header, "\x89PNG\r\n\x1a\n", 8) != 0 ||
        memcmp(header + 12, "IHDR", 4) != 0)
        return;
    unsigned long w = 0, h = 0;
    for (int i = 0; i < 4; i++) {
        w = w << 8 | header[16 + i];
        h = h << 8 | header[20 + i];
    }
    if (w <= 1u << 30 && h <= 1u << 30) {
        *width = (int)w;
        *height = (int)h;
    }
}

/* Width and height of a PFM from its header ("PF\nW H\n..."); 0 when not a PFM. */
static void pfm_size(const char *path, int *width, int *height)
{
    *width = *height = 0;
    FILE *file = fopen(path, "rb");
    if (!file)
        return;
    char kind;
    if (fscanf(file, "P%c %d %d", &kind, width, height) != 3 || (kind != 'F' && kind != 'f'))
        *width = *height = 0;
    fclose(file);
}

/* Is `word` (length bytes) one of the space-separated words of `list`? */
static int listed(const char *list, const char *word, size_t length)
{
    while (list && *list) {
        size_t span = strcspn(list, " ");
        if (span == length && strncmp(list, word, length) == 0)
            return 1;
        list += span;
        list += strspn(list, " ");
    }
    return 0;
}

/* A PNG is a figure unless a PFM of its name and its size lies beside it (gallery.h). */
static FileKind kind_of(const Writer *w, const GalleryChapter *chapter, const char *name)
{
    if (strlen(name) > strlen("chNN_") && strncmp(name + strlen("chNN_"), "exercise", 8) == 0 &&
        (ends_with(name, ".png") || ends_with(name, ".txt")))
        return FILE_EXERCISE;
    if (ends_with(name, ".csv"))
        return FILE_TABLE;
    if (ends_with(name, ".txt"))
        return FILE_TEXT;
    if (!ends_with(name, ".png"))
        return FILE_OTHER;
    size_t stem = strlen(name) - 4;
    char pfm[1024], path[4200];
    if (stem + 5 <= sizeof pfm) {
        snprintf(pfm, sizeof pfm, "%.*s.pfm", (int)stem, name);
        int png_width, png_height, pfm_width, pfm_height;
        if (has_file(w, pfm) && join(path, sizeof path, w->page->figures, name) == 0) {
            png_size(path, &png_width, &png_height);
            join(path, sizeof path, w->page->figures, pfm);
            pfm_size(path, &pfm_width, &pfm_height);
            if (png_width > 0 && png_width == pfm_width && png_height == pfm_height)
                return FILE_OTHER;
        }
    }
    return listed(chapter->plots, name, stem) ? FILE_PLOT : FILE_FIGURE;
}

/* Text as HTML: the five characters that mean something in markup escaped. */
static void html(FILE *out, const char *text, size_t length)
{
    for (size_t i = 0; i < length; i++) {
        switch (text[i]) {
        case '&':
            fputs("&amp;", out);
            break;
        case '<':
            fputs("&lt;", out);
            break;
        case '>':
            fputs("&gt;", out);
            break;
        case '"':
            fputs("&quot;", out);
            break;
        case '\'':
            fputs("&#39;", out);
            break;
        default:
            fputc(text[i], out);
        }
    }
}

static void html_text(FILE *out, const char *text) { html(out, text, strlen(text)); }

/* A file name as a relative URL: every byte but letters, digits and "-._~"
 * percent-encoded, so that no name can leave the folder or the attribute. */
static void url(FILE *out, const char *name)
{
    for (const unsigned char *c = (const unsigned char *)name; *c; c++) {
        if (isalnum(*c) || strchr("-._~", *c))
            fputc(*c, out);
        else
            fprintf(out, "%%%02X", *c);
    }
}

static void link_to(FILE *out, const char *name)
{
    fputs("<a href=\"", out);
    url(out, name);
    fputs("\">", out);
    html_text(out, name);
    fputs("</a>", out);
}

/* value of "key=value" lines into `value` (of `size`), when `line` has that key. */
static void run_value(const char *line, size_t length, const char *key, char *value,
                      size_t size)
{
    size_t key_length = strlen(key);
    if (length > key_length && strncmp(line, key, key_length) == 0 && line[key_length] == '=')
        snprintf(value, size, "%.*s", (int)(length - key_length - 1), line + key_length + 1);
}

static int read_run(Writer *w)
{
    char path[4200], *text, quick[8] = "";
    memset(&w->run, 0, sizeof w->run);
    if (join(path, sizeof path, w->page->figures, "run.txt") != 0)
        return fail(w, "cannot name", "run.txt");
    if (read_text(path, &text) != 0)
        return errno == ENOENT ? 0 : fail(w, "cannot read", path);
    w->run.present = 1;
    for (const char *line = text; *line;) {
        size_t length = strcspn(line, "\r\n");
        run_value(line, length, "started", w->run.started, sizeof w->run.started);
        run_value(line, length, "finished", w->run.finished, sizeof w->run.finished);
        run_value(line, length, "seconds", w->run.seconds, sizeof w->run.seconds);
        run_value(line, length, "threads", w->run.threads, sizeof w->run.threads);
        run_value(line, length, "quick", quick, sizeof quick);
        line += length;
        line += strspn(line, "\r\n");
    }
    w->run.quick = strcmp(quick, "1") == 0;
    free(text);
    return 0;
}

static const char STYLE[] =
    "body{font:15px/1.45 sans-serif;margin:0 auto;max-width:84em;padding:0 1em 3em;color:#222}"
    "h2{border-top:2px solid #bbb;padding-top:.6em;margin-top:2.2em}"
    ".quick{background:#fff3c4;border:1px solid #d9a400;padding:.4em .8em}"
    ".missing{background:#fde8e8;border:1px solid #d88;padding:.4em .8em}"
    "figure{display:inline-block;vertical-align:top;margin:.5em 1.5em .8em 0}"
    "img{max-width:100%;height:auto;border:1px solid #ccc}"
    "figcaption,.file{font-size:90%;color:#555}.scroll{overflow-x:auto}"
    "table{border-collapse:collapse;font-size:85%;margin:.3em 0 1em}"
    "th,td{border:1px solid #ccc;padding:.15em .45em;white-space:nowrap}th{background:#eee}"
    ".n{text-align:right;font-variant-numeric:tabular-nums}"
    "pre{background:#f5f5f5;padding:.5em;overflow-x:auto}"
    ".add{color:#060}.del{color:#a00}.hunk{color:#05a}nav ol{columns:2}"
    ".files{padding:0}.files li{display:inline-block;margin:0 1.2em .2em 0}";

/* The number of the chapter's files, chNN_*. */
static int chapter_file_count(const Writer *w, const char *prefix)
{
    int count = 0;
    for (int i = 0; i < w->files.count; i++)
        count += strncmp(w->files.names[i], prefix, strlen(prefix)) == 0;
    return count;
}

/* Each figure the chapter writes but the folder lacks, said to be missing: a chapter
 * stopped halfway must not look complete. */
static void write_missing_figures(const Writer *w, const GalleryChapter *chapter)
{
    for (const char *name = chapter->figures; name && *name;) {
        size_t length = strcspn(name, " ");
        char file[128];
        snprintf(file, sizeof file, "%.*s.png", (int)length, name);
        if (length > 0 && !has_file(w, file))
            fprintf(w->out,
                    "<p class=\"missing\"><strong>Not rendered:</strong> %s. "
                    "<code>make chapter%d</code> renders it.</p>\n",
                    file, chapter->number);
        name += length;
        name += strspn(name, " ");
    }
}

static void chapter_prefix(char prefix[16], int number)
{
    snprintf(prefix, 16, "ch%02d_", number % 100);
}

static void write_header(Writer *w)
{
    FILE *out = w->out;
    const GalleryPage *page = w->page;
    char made[64];
    struct tm local;
    if (!localtime_r(&page->made, &local) ||
        strftime(made, sizeof made, "%Y-%m-%d %H:%M:%S %z", &local) == 0)
        snprintf(made, sizeof made, "(unknown time)");
    fputs("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
          "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>",
          out);
    html_text(out, page->title);
    fprintf(out, "%s</title>\n<style>%s</style>\n</head>\n<body>\n<h1>",
            w->run.quick ? " (QUICK)" : "", STYLE);
    html_text(out, page->title);
    fprintf(out, "%s</h1>\n", w->run.quick ? " <span class=\"quick\">QUICK</span>" : "");
    if (w->run.quick)
        fputs("<p class=\"quick\"><strong>QUICK figures</strong> (<code>make figures "
              "QUICK=1</code>): a quarter of each image's size, and more runs of each measured "
              "setting, for a first look. They are not the report's settings; <code>make "
              "figures</code> "
              "renders those.</p>\n",
              out);
    fprintf(out, "<p>Page made %s.", made);
    if (w->run.present) {
        fprintf(out, " From the run of <code>make figures%s</code>",
                w->run.quick ? " QUICK=1" : "");
        if (w->run.started[0]) {
            fputs(" started ", out);
            html_text(out, w->run.started);
        }
        if (w->run.finished[0]) {
            fputs(", finished ", out);
            html_text(out, w->run.finished);
        }
        if (w->run.seconds[0]) {
            fputs(": the whole run took ", out);
            html_text(out, w->run.seconds);
            long seconds = strtol(w->run.seconds, NULL, 10);
            fputs(" s", out);
            if (seconds >= 120)
                fprintf(out, " (%ld min %ld s)", seconds / 60, seconds % 60);
        }
        if (w->run.threads[0]) {
            fputs(", on ", out);
            html_text(out, w->run.threads);
            fputs(" threads (one per core, the chapters' default)", out);
        }
        fputs(".", out);
    } else {
        fputs(" No run was recorded here (run.txt is written by <code>make figures</code>): "
              "the page shows the files the folder holds.",
              out);
    }
    fputs(" Each table says what a render cost (seconds, rays) and what it bought (its error "
          "against a reference). Every image links to its full-size file; the folder can be "
          "copied or zipped as it is.</p>\n",
          out);
    if (page->book) {
        fputs("<p>Each chapter's derivations and code: <a class=\"book\" href=\"", out);
        html_text(out, page->book);
        fputs("/index.html\">the book</a>.</p>\n", out);
    }
    fputs("<nav>\n<h2>Chapters</h2>\n<ol>\n", out);
    for (int i = 0; i < page->chapter_count; i++) {
        const GalleryChapter *chapter = &page->chapters[i];
        char prefix[16];
        chapter_prefix(prefix, chapter->number);
        fprintf(out, "<li value=\"%d\"><a href=\"#chapter%d\">", chapter->number,
                chapter->number);
        html_text(out, chapter->title);
        fprintf(out, "</a>%s</li>\n",
                chapter_file_count(w, prefix) ? "" : " <em>(not rendered yet)</em>");
    }
    fputs("</ol>\n</nav>\n", out);
}

/* Fields of a CSV (RFC 4180), split in place: field[i] ends its row when ends_row[i]. */
typedef struct {
    char **field;
    char *ends_row;
    int count, capacity;
} Cells;

static int cells_add(Cells *cells, char *field, int ends_row)
{
    if (cells->count == cells->capacity) {
        int capacity = cells->capacity ? 2 * cells->capacity : 256;
        char **fields = realloc(cells->field, (size_t)capacity * sizeof *fields);
        if (fields)
            cells->field = fields;
        char *ends = realloc(cells->ends_row, (size_t)capacity);
        if (ends)
            cells->ends_row = ends;
        if (!fields || !ends)
            return -1;
        cells->capacity = capacity;
    }
    cells->field[cells->count] = field;
    cells->ends_row[cells->count] = (char)ends_row;
    cells->count++;
    return 0;
}

/* Split `text` into fields: commas between fields, a line break (LF or CRLF) between rows,
 * a field in double quotes may hold both, and "" inside it is one quote. Each field is
 * unquoted where it stands (it only ever gets shorter). Returns 0, or -1 (out of memory). */
static int csv_split(char *text, Cells *cells)
{
    char *read = text;
    while (*read) {
        char *field = read, *write = read;
        if (*read == '"') {
            for (read++; *read && !(read[0] == '"' && read[1] != '"'); read++) {
                if (*read == '"')
                    read++;
                *write++ = *read;
            }
            if (*read == '"')
                read++;
        }
        while (*read && *read != ',' && *read != '\n' && *read != '\r')
            *write++ = *read++;
        char separator = *read;
        if (separator == '\r' && read[1] == '\n')
            read++;
        if (separator)
            read++;
        *write = '\0';
        if (cells_add(cells, field, separator != ',') != 0)
            return -1;
    }
    return 0;
}

static int is_number(const char *text)
{
    char *end;
    if (*text == '\0' || isspace((unsigned char)*text))
        return 0;
    (void)strtod(text, &end);
    return *end == '\0';
}

/* A row of the table from cells[first..], padded with empty cells to `columns`; returns
 * the index after the row. A cell is right-aligned when it is a number, a header cell
 * (`numeric` given) when numeric[column] says its column holds numbers only. */
static int write_row(FILE *out, const Cells *cells, int first, int columns, const char *numeric)
{
    const char *cell = numeric ? "th" : "td";
    int i = first, column = 0;
    fputs("<tr>", out);
    for (; i < cells->count; i++, column++) {
        const char *field = cells->field[i];
        int right = numeric ? column < columns && numeric[column] : is_number(field);
        fprintf(out, "<%s%s>", cell, right ? " class=\"n\"" : "");
        html_text(out, field);
        fprintf(out, "</%s>", cell);
        if (cells->ends_row[i])
            break;
    }
    for (column++; column < columns; column++)
        fprintf(out, "<%s></%s>", cell, cell);
    fputs("</tr>\n", out);
    return i + 1;
}

/* numeric[c] = 1 when column c (of `columns`) has a number and no other text below the
 * header, which ends at cells[header_end]. */
static void numeric_columns(const Cells *cells, int header_end, int columns, char *numeric)
{
    memset(numeric, 1, (size_t)columns);
    char *seen_number = numeric + columns;
    memset(seen_number, 0, (size_t)columns);
    int column = 0;
    for (int i = header_end + 1; i < cells->count; i++) {
        const char *field = cells->field[i];
        if (column < columns && field[0]) {
            if (is_number(field))
                seen_number[column] = 1;
            else
                numeric[column] = 0;
        }
        column = cells->ends_row[i] ? 0 : column + 1;
    }
    for (column = 0; column < columns; column++)
        numeric[column] = numeric[column] && seen_number[column];
}

/* The table of a CSV whose header row has `columns` fields; numeric[2 * columns] is room
 * for numeric_columns. */
static void write_cells(FILE *out, const Cells *cells, int columns, char *numeric)
{
    fputs("<div class=\"scroll\"><table>\n", out);
    if (cells->count > 0) {
        numeric_columns(cells, columns - 1, columns, numeric);
        fputs("<thead>", out);
        int next = write_row(out, cells, 0, columns, numeric);
        fputs("</thead>\n<tbody>\n", out);
        while (next < cells->count) {
            if (cells->ends_row[next] && cells->field[next][0] == '\0')
                next++; /* a blank line */
            else
                next = write_row(out, cells, next, columns, NULL);
        }
        fputs("</tbody>\n", out);
    }
    fputs("</table></div>\n", out);
}

static int write_table(Writer *w, const char *name)
{
    char path[4200], *text;
    if (join(path, sizeof path, w->page->figures, name) != 0 || read_text(path, &text) != 0)
        return fail(w, "cannot read", path);
    Cells cells = {0};
    int columns = 0;
    char *numeric = NULL;
    if (csv_split(text, &cells) == 0) {
        while (columns < cells.count && !cells.ends_row[columns++])
            ;
        numeric = malloc(2 * (size_t)columns + 1);
    }
    if (numeric) {
        fputs("<h4 class=\"file\">", w->out);
        link_to(w->out, name);
        fputs("</h4>\n", w->out);
        write_cells(w->out, &cells, columns, numeric);
    }
    free(cells.field);
    free(cells.ends_row);
    free(text);
    if (!numeric) {
        errno = ENOMEM;
        return fail(w, "cannot read", path);
    }
    free(numeric);
    return 0;
}

/* The fragment that follows `name` (length bytes) among the "NAME FRAGMENT" pairs of
 * `pairs`, and its length in *length; NULL when the name is not there. */
static const char *paired(const char *pairs, const char *name, size_t *length)
{
    while (pairs && *pairs) {
        size_t span = strcspn(pairs, " ");
        const char *value = pairs + span + strspn(pairs + span, " ");
        size_t value_span = strcspn(value, " ");
        if (span == *length && strncmp(pairs, name, span) == 0 && value_span > 0) {
            *length = value_span;
            return value;
        }
        pairs = value + value_span;
        pairs += strspn(pairs, " ");
    }
    return NULL;
}

/* The width of the chapter's panels: of its first PFM; 0 without one. */
static int panel_width(const Writer *w, const char *prefix)
{
    for (int i = 0; i < w->files.count; i++) {
        const char *name = w->files.names[i];
        char path[4200];
        int width, height;
        if (strncmp(name, prefix, strlen(prefix)) == 0 && ends_with(name, ".pfm") &&
            join(path, sizeof path, w->page->figures, name) == 0) {
            pfm_size(path, &width, &height);
            return width;
        }
    }
    return 0;
}

/* " live in the lab": a link to the lab with the figure's settings (gallery.h). */
static void write_lab_link(Writer *w, const GalleryChapter *chapter, const char *name)
{
    size_t length = strlen(name) - 4; /* without ".png" */
    const char *fragment = paired(chapter->lab, name, &length);
    if (!w->page->lab || !fragment)
        return;
    char prefix[16];
    chapter_prefix(prefix, chapter->number);
    int width = panel_width(w, prefix);
    fputs(" <a class=\"lab\" href=\"", w->out);
    html_text(w->out, w->page->lab);
    fputc('#', w->out);
    html(w->out, fragment, length);
    if (width > 0)
        fprintf(w->out, "&amp;size=%d", width);
    fputs("\">live in the lab</a>", w->out);
}

static void write_image(Writer *w, const GalleryChapter *chapter, const char *name)
{
    FILE *out = w->out;
    char path[4200];
    int width = 0, height = 0;
    if (join(path, sizeof path, w->page->figures, name) == 0)
        png_size(path, &width, &height);
    fputs("<figure><a href=\"", out);
    url(out, name);
    fputs("\"><img src=\"", out);
    url(out, name);
    fputs("\" alt=\"", out);
    html_text(out, name);
    fputc('"', out);
    if (width > 0)
        fprintf(out, " width=\"%d\" height=\"%d\"", width, height);
    fputs("></a><figcaption>", out);
    html_text(out, name);
    if (width > 0)
        fprintf(out, " (%d x %d)", width, height);
    write_lab_link(w, chapter, name);
    fputs("</figcaption></figure>\n", out);
}

/* A text file, as it is, in a preformatted block under a link to it. */
static int write_text(Writer *w, const char *name)
{
    char path[4200], *text;
    if (join(path, sizeof path, w->page->figures, name) != 0 || read_text(path, &text) != 0)
        return fail(w, "cannot read", path);
    fputs("<p class=\"file\">", w->out);
    link_to(w->out, name);
    fputs("</p>\n<pre>", w->out);
    html_text(w->out, text);
    fputs("</pre>\n", w->out);
    free(text);
    return 0;
}

/* Every file of the chapter of one kind, under a heading when there is any. */
static int write_kind(Writer *w, const GalleryChapter *chapter, FileKind kind,
                      const char *heading)
{
    char prefix[16];
    chapter_prefix(prefix, chapter->number);
    int shown = 0;
    for (int i = 0; i < w->files.count; i++) {
        const char *name = w->files.names[i];
        if (strncmp(name, prefix, strlen(prefix)) != 0 || kind_of(w, chapter, name) != kind)
            continue;
        if (shown++ == 0)
            fprintf(w->out, "<h3>%s</h3>\n%s", heading,
                    kind == FILE_OTHER ? "<ul class=\"files\">\n" : "");
        if (kind == FILE_FIGURE || kind == FILE_PLOT ||
            (kind == FILE_EXERCISE && ends_with(name, ".png"))) {
            write_image(w, chapter, name);
        } else if (kind == FILE_TABLE) {
            if (write_table(w, name) != 0)
                return -1;
        } else if (kind == FILE_TEXT || kind == FILE_EXERCISE) {
            if (write_text(w, name) != 0)
                return -1;
        } else {
            fputs("<li>", w->out);
            link_to(w->out, name);
            fputs("</li>\n", w->out);
        }
    }
    if (shown && kind == FILE_OTHER)
        fputs("</ul>\n", w->out);
    return 0;
}

/* The lines of `make diff-chapterN`, folded, when the diffs folder has them. */
static int write_diff(Writer *w, int number)
{
    if (!w->page->diffs)
        return 0;
    const char *endings[] = {"txt", "diff"};
    char name[64], path[4200], *text = NULL;
    for (int i = 0; i < 2 && !text; i++) {
        snprintf(name, sizeof name, "diff-chapter%d.%s", number, endings[i]);
        if (join(path, sizeof path, w->page->diffs, name) != 0)
            return fail(w, "cannot name", name);
        if (read_text(path, &text) != 0 && errno != ENOENT)
            return fail(w, "cannot read", path);
    }
    if (!text)
        return 0;
    int lines = 0, added = 0, removed = 0;
    for (const char *line = text; *line;) {
        lines++;
        added += line[0] == '+' && strncmp(line, "+++", 3) != 0;
        removed += line[0] == '-' && strncmp(line, "---", 3) != 0;
        line += strcspn(line, "\n");
        line += *line == '\n';
    }
    fprintf(w->out,
            "<details><summary><code>make diff-chapter%d</code>: what chapter %d adds to the "
            "library, %d lines (%d added, %d removed)</summary>\n<pre>",
            number, number, lines, added, removed);
    for (const char *line = text; *line;) {
        size_t length = strcspn(line, "\n");
        const char *class = line[0] == '@' && line[1] == '@'                 ? "hunk"
                            : line[0] == '+' && strncmp(line, "+++", 3) != 0 ? "add"
                            : line[0] == '-' && strncmp(line, "---", 3) != 0 ? "del"
                                                                             : NULL;
        if (class)
            fprintf(w->out, "<span class=\"%s\">", class);
        html(w->out, line, length);
        fputs(class ? "</span>\n" : "\n", w->out);
        line += length;
        line += *line == '\n';
    }
    fputs("</pre></details>\n", w->out);
    free(text);
    return 0;
}

static int write_chapter(Writer *w, const GalleryChapter *chapter)
{
    FILE *out = w->out;
    char prefix[16];
    chapter_prefix(prefix, chapter->number);
    int n = chapter->number;
    char exercises[128];
    snprintf(exercises, sizeof exercises,
             "Exercises: the solution's verdicts and pictures "
             "(make check-exercise-chapter%d)",
             n);
    fprintf(out, "<section id=\"chapter%d\">\n<h2>Chapter %d: ", n, n);
    html_text(out, chapter->title);
    fputs("</h2>\n", out);
    if (w->page->book) {
        fputs("<p><a class=\"book\" href=\"", out);
        html_text(out, w->page->book);
        fprintf(
            out,
            "/chapter%d.html\">Chapter %d in the book</a>: its derivations and its code.</p>\n",
            n, n);
    }
    fputs("<p>", out);
    html_text(out, chapter->teaches);
    fputs("</p>\n<p><strong>Reproduces:</strong> ", out);
    html_text(out, chapter->reproduces);
    fputs(".</p>\n", out);
    if (chapter_file_count(w, prefix) == 0)
        fprintf(out,
                "<p class=\"missing\"><strong>Not rendered yet:</strong> this folder has no "
                "file %s*. <code>make chapter%d</code> renders it.</p>\n",
                prefix, n);
    else
        write_missing_figures(w, chapter);
    if (write_kind(w, chapter, FILE_FIGURE, "Figures") != 0 ||
        write_kind(w, chapter, FILE_TABLE, "Tables") != 0 ||
        write_kind(w, chapter, FILE_PLOT, "Plots") != 0 ||
        write_kind(w, chapter, FILE_EXERCISE, exercises) != 0)
        return -1;
    fprintf(out,
            "<h3>Settings</h3>\n<p>To reproduce: <code>make chapter%d%s</code>. The settings "
            "are the program's defaults%s; <code>make chapter%d ARGS=--help</code> lists "
            "them, and each table's settings column names each render's.</p>\n",
            n, w->run.quick ? " QUICK=1" : "",
            w->run.quick ? ", with <code>--quick</code> (a quarter of the size, and more "
                           "runs of each measured setting)"
                         : "",
            n);
    if (write_kind(w, chapter, FILE_TEXT, "Settings files") != 0 ||
        write_kind(w, chapter, FILE_OTHER, "Panels and other files") != 0 ||
        write_diff(w, n) != 0)
        return -1;
    fputs("</section>\n", out);
    return 0;
}

int gallery_write(const GalleryPage *page, char *error, int error_size)
{
    Writer w = {NULL, page, {NULL, 0}, {0}, error, error_size};
    char path[4200];
    if (join(path, sizeof path, page->figures, "index.html") != 0)
        return fail(&w, "cannot name the page in", page->figures);
    if (list_files(page->figures, &w.files) != 0)
        return fail(&w, "cannot list", page->figures);
    if (read_run(&w) != 0) {
        names_free(&w.files);
        return -1;
    }
    AtomicFile file;
    if (atomic_open(&file, path) != 0) {
        names_free(&w.files);
        return fail(&w, "cannot write", path);
    }
    w.out = file.file;
    write_header(&w);
    int status = 0;
    for (int i = 0; i < page->chapter_count && status == 0; i++)
        status = write_chapter(&w, &page->chapters[i]);
    fputs("</body>\n</html>\n", w.out);
    names_free(&w.files);
    if (status != 0) {
        atomic_close(&file, 1);
        return -1;
    }
    if (atomic_close(&file, 0) != 0)
        return fail(&w, "cannot write", path);
    return 0;
}
