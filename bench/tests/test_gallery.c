/* test_gallery.c (bench, chapter 1): the page of every figure (gallery.h).
 *
 * A fixture folder under $CHAPTER_DIR (default build), test_gallery/, is filled with what
 * chapter programs write: tiny PNGs and PFMs (image.h), CSVs written by hand (quoted
 * fields, a doubled quote, CRLF lines, an empty cell, a short row, columns for an error's
 * spread and an infinite-variance mark), a settings file, a run record and a diff. The
 * page written from it is read back as text and checked:
 *   - every src and href resolves: to a file of the folder (after undoing the HTML and
 *     percent escapes), or to an id on the page; none holds a character a URL must
 *     escape (space, #, ?); every file of a chapter is reachable;
 *   - each table carries its CSV cell by cell, numbers right-aligned;
 *   - a chapter without files has its section and says it is not rendered yet;
 *   - figures are shown, panels (a PFM of the same size beside them) only linked, the
 *     solution's exercise pictures and verdicts under their own heading after the plots;
 *   - text from files is escaped, and the page has no script;
 *   - a figure links to the lab with its settings where the page knows the lab.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "gallery.h"
#include "image.h"

static char fixture[2048];

static const GalleryChapter CHAPTERS[] = {
    {1, "First", "What the first teaches.", "Figure 1", NULL, "ch01_figure1", NULL},
    {2, "Second", "What the second teaches.", "Figure 2", "ch02_plot",
     "ch02_figure2 ch02_plot ch02_figure8", NULL},
    {3, "Third, not rendered", "What the third teaches.", "Figure 3", NULL, NULL, NULL},
    {4, "Fourth", "What the fourth teaches.", "Figure 4", NULL, NULL, NULL},
};
#define CHAPTER_COUNT 4

/* ch01_table.csv as written, and the cells the page must show (rows padded to the
 * header's six columns); "n" marks the cells that are numbers. */
static const char TABLE_CSV[] =
    "panel,settings,spp,rmse,rmse_spread,variance\n"
    "\"alpha=0.01\",\"4 spp, M=1 \"\"quoted\"\"\",4,0.97277,0.05,infinite\n"
    "\"alpha=0.5\",\"4 spp, <b>M=1</b>\",16,0.41241,2e-3,\n"
    "plain,short\n";
#define TABLE_ROWS 4
#define TABLE_COLUMNS 6
static const char *const TABLE_CELLS[TABLE_ROWS][TABLE_COLUMNS] = {
    {"panel", "settings", "spp", "rmse", "rmse_spread", "variance"},
    {"alpha=0.01", "4 spp, M=1 \"quoted\"", "4", "0.97277", "0.05", "infinite"},
    {"alpha=0.5", "4 spp, <b>M=1</b>", "16", "0.41241", "2e-3", ""},
    {"plain", "short", "", "", "", ""},
};
static const char *const TABLE_NUMERIC[TABLE_ROWS] = {"..nnn.", "..nnn.", "..nnn.", "......"};

static const char DATA_CSV[] = "x,y\r\n1,2\r\n3,-4.5\r\n";
static const char *const DATA_CELLS[3][2] = {{"x", "y"}, {"1", "2"}, {"3", "-4.5"}};

static void write_text(const char *name, const char *text)
{
    char path[4200];
    snprintf(path, sizeof path, "%s/%s", fixture, name);
    FILE *file = fopen(path, "wb");
    assert_non_null(file);
    assert_int_equal(fputs(text, file) >= 0, 1);
    assert_int_equal(fclose(file), 0);
}

static void write_png(const char *name, int width, int height, int pfm_too)
{
    Image image = image_new(width, height);
    assert_non_null(image.pixels);
    for (int row = 0; row < height; row++)
        for (int col = 0; col < width; col++)
            image_set(&image, col, row, vec3(col / (double)width, row / (double)height, 0.5));
    char path[4200];
    snprintf(path, sizeof path, "%s/%s.png", fixture, name);
    assert_int_equal(image_write_png(&image, path, 1.0), 0);
    if (pfm_too) {
        snprintf(path, sizeof path, "%s/%s.pfm", fixture, name);
        assert_int_equal(image_write_pfm(&image, path), 0);
    }
    image_free(&image);
}

/* An empty fixture folder (what an earlier run left is removed). */
static void empty_fixture(void)
{
    const char *build = getenv("CHAPTER_DIR");
    snprintf(fixture, sizeof fixture, "%s/test_gallery.%d", build ? build : "build",
             (int)getpid());
    mkdir(fixture, 0777);
    DIR *folder = opendir(fixture);
    assert_non_null(folder);
    struct dirent *entry;
    while ((entry = readdir(folder)) != NULL) {
        char path[4200];
        snprintf(path, sizeof path, "%s/%s", fixture, entry->d_name);
        if (entry->d_name[0] != '.')
            assert_int_equal(unlink(path), 0);
    }
    closedir(folder);
}

/* Chapter 1: a figure, a panel (PNG and PFM), a table, a settings file; chapter 2: a
 * figure, a plot, a CRLF table, an exercise's picture and verdicts; chapter 3: nothing; chapter
 * 4: a figure whose name needs escaping. A run record (QUICK) and a diff for chapter 2. */
static void make_fixture(void)
{
    empty_fixture();
    write_png("ch01_figure1", 6, 9, 0);
    write_png("ch01_panel", 6, 6, 1);
    write_text("ch01_table.csv", TABLE_CSV);
    write_text("ch01_settings.txt", "--size 200 <script>alert(1)</script> & more\n");
    write_png("ch02_figure2", 8, 5, 0);
    write_png("ch02_plot", 10, 7, 0);
    write_text("ch02_data.csv", DATA_CSV);
    write_png("ch02_exercise-2.1-warp", 7, 4, 0);
    write_text("ch02_exercises.txt", "exercise 2.1 (hemisphere_sample_cosine): pass\n");
    write_png("ch04_a b&c#d", 5, 5, 0);
    write_text("run.txt", "started=2026-01-02 03:04:05 +0000\nfinished=2026-01-02 03:05:20 "
                          "+0000\nseconds=75\nthreads=2\nquick=1\n");
    write_text("diff-chapter2.txt", "--- a/lib/x.c\n+++ b/lib/x.c\n@@ -1 +1,2 @@\n int x;\n"
                                    "+int y < 1;\n");
}

/* The page written from the fixture as `page` says, as a string to free. */
static char *written(const GalleryPage *page)
{
    char error[4400] = "";
    int status = gallery_write(page, error, sizeof error);
    if (status != 0)
        fail_msg("gallery_write: %s", error);
    char path[4200];
    snprintf(path, sizeof path, "%s/index.html", fixture);
    FILE *file = fopen(path, "rb");
    assert_non_null(file);
    static char buffer[1 << 20];
    size_t length = fread(buffer, 1, sizeof buffer - 1, file);
    fclose(file);
    buffer[length] = '\0';
    return strdup(buffer);
}

/* The page written from the fixture, as a string to free. */
static char *make_page(void)
{
    make_fixture();
    GalleryPage page = {"Test gallery", fixture, fixture, CHAPTERS,
                        CHAPTER_COUNT,  0,       NULL,    NULL};
    return written(&page);
}

/* HTML text back to plain text: the five escapes gallery.c writes. */
static void unescape_html(const char *text, size_t length, char *out, size_t size)
{
    static const char *const escapes[][2] = {
        {"&amp;", "&"}, {"&lt;", "<"}, {"&gt;", ">"}, {"&quot;", "\""}, {"&#39;", "'"}};
    size_t n = 0;
    for (size_t i = 0; i < length && n + 1 < size;) {
        int matched = 0;
        for (int e = 0; e < 5 && !matched; e++) {
            size_t escape_length = strlen(escapes[e][0]);
            if (strncmp(text + i, escapes[e][0], escape_length) == 0) {
                out[n++] = escapes[e][1][0];
                i += escape_length;
                matched = 1;
            }
        }
        if (!matched)
            out[n++] = text[i++];
    }
    out[n] = '\0';
}

static void percent_decode(char *text)
{
    char *write = text;
    for (const char *read = text; *read; write++) {
        unsigned code;
        if (read[0] == '%' && sscanf(read + 1, "%2x", &code) == 1) {
            *write = (char)code;
            read += 3;
        } else {
            *write = *read++;
        }
    }
    *write = '\0';
}

static int is_file(const char *name)
{
    char path[4200];
    struct stat info;
    snprintf(path, sizeof path, "%s/%s", fixture, name);
    return strchr(name, '/') == NULL && stat(path, &info) == 0 && S_ISREG(info.st_mode);
}

/* Every src="..." and href="..." of the page resolves; returns how many there were, and
 * marks in reached[] the fixture's files they lead to. */
static int check_links(const char *page, const char *const *files, int file_count, int *reached)
{
    int links = 0;
    for (const char *at = page; (at = strpbrk(at, "sh")) != NULL; at++) {
        size_t prefix = strncmp(at, "src=\"", 5) == 0    ? 5
                        : strncmp(at, "href=\"", 6) == 0 ? 6
                                                         : 0;
        if (!prefix || (at > page && at[-1] != ' '))
            continue;
        const char *value = at + prefix, *end = strchr(value, '"');
        assert_non_null(end);
        char target[1024];
        unescape_html(value, (size_t)(end - value), target, sizeof target);
        links++;
        /* what a relative URL cannot hold as it is: a browser would cut it there */
        if (strpbrk(target + (target[0] == '#'), " #?\\<>"))
            fail_msg("link \"%s\" is not escaped as a URL", target);
        if (target[0] == '#') {
            char id[1100];
            snprintf(id, sizeof id, " id=\"%s\"", target + 1);
            if (!strstr(page, id))
                fail_msg("link %s leads to no id on the page", target);
            continue;
        }
        percent_decode(target);
        if (!is_file(target))
            fail_msg("link \"%.*s\" (%s) is no file of %s", (int)(end - value), value, target,
                     fixture);
        for (int i = 0; i < file_count; i++)
            reached[i] |= strcmp(files[i], target) == 0;
    }
    return links;
}

static void test_links_resolve(void **state)
{
    char *page = make_page();
    const char *const files[] = {"ch01_figure1.png",  "ch01_panel.png",
                                 "ch01_panel.pfm",    "ch01_table.csv",
                                 "ch01_settings.txt", "ch02_figure2.png",
                                 "ch02_plot.png",     "ch02_data.csv",
                                 "ch04_a b&c#d.png",  "ch02_exercise-2.1-warp.png",
                                 "ch02_exercises.txt"};
    const int count = (int)(sizeof files / sizeof files[0]);
    int reached[sizeof files / sizeof files[0]] = {0};
    int links = check_links(page, files, count, reached);
    assert_true(links >= count + CHAPTER_COUNT); /* the files, and the table of contents */
    for (int i = 0; i < count; i++)
        if (!reached[i])
            fail_msg("no link to %s", files[i]);
    free(page);
}

/* The cells of the table that follows the link to `csv`: text and whether right-aligned,
 * row by row. Returns the number of rows. */
static int table_cells(const char *page, const char *csv, int columns, char cells[][8][128],
                       char numeric[][9], int max_rows)
{
    char link[256];
    snprintf(link, sizeof link, "href=\"%s\"", csv);
    const char *at = strstr(page, link);
    if (!at)
        fail_msg("no link to %s", csv);
    const char *table = strstr(at, "<table>"), *end = strstr(at, "</table>");
    assert_non_null(table);
    assert_true(end > table);
    int rows = 0;
    for (const char *row = strstr(table, "<tr>"); row && row < end;
         row = strstr(row + 1, "<tr>")) {
        assert_true(rows < max_rows);
        const char *row_end = strstr(row, "</tr>");
        int column = 0;
        for (const char *cell = strstr(row, "<t"); cell && cell < row_end;
             cell = strstr(cell + 1, "<t")) {
            if (cell[2] != 'd' && cell[2] != 'h')
                continue;
            assert_true(column < columns);
            const char *text = strchr(cell, '>') + 1, *text_end = strstr(text, "</t");
            numeric[rows][column] = strncmp(cell + 3, " class=\"n\"", 10) == 0 ? 'n' : '.';
            unescape_html(text, (size_t)(text_end - text), cells[rows][column], 128);
            column++;
        }
        if (column != columns)
            fail_msg("%s row %d has %d cells, expected %d", csv, rows, column, columns);
        numeric[rows][column] = '\0';
        rows++;
    }
    return rows;
}

static void test_tables_carry_the_csv(void **state)
{
    char *page = make_page();
    char cells[8][8][128], numeric[8][9];
    int rows = table_cells(page, "ch01_table.csv", TABLE_COLUMNS, cells, numeric, 8);
    assert_int_equal(rows, TABLE_ROWS);
    for (int row = 0; row < TABLE_ROWS; row++) {
        for (int column = 0; column < TABLE_COLUMNS; column++)
            assert_string_equal(cells[row][column], TABLE_CELLS[row][column]);
        assert_string_equal(numeric[row], TABLE_NUMERIC[row]);
    }
    rows = table_cells(page, "ch02_data.csv", 2, cells, numeric, 8);
    assert_int_equal(rows, 3);
    for (int row = 0; row < 3; row++)
        for (int column = 0; column < 2; column++)
            assert_string_equal(cells[row][column], DATA_CELLS[row][column]);
    assert_string_equal(numeric[2], "nn");
    free(page);
}

/* The section of chapter n, from its start to the next one's (or the end). */
static const char *section(const char *page, int n, const char **end)
{
    char id[64];
    snprintf(id, sizeof id, "<section id=\"chapter%d\">", n);
    const char *start = strstr(page, id);
    if (!start)
        fail_msg("no section for chapter %d", n);
    *end = start ? strstr(start + 1, "<section") : NULL;
    if (!*end)
        *end = start + strlen(start);
    return start;
}

static int in_range(const char *start, const char *end, const char *text)
{
    const char *found = strstr(start, text);
    return found && found < end;
}

static void test_missing_chapter_and_figure_are_listed(void **state)
{
    char *page = make_page();
    const char *previous = page, *end;
    for (int n = 1; n <= CHAPTER_COUNT; n++) {
        const char *start = section(page, n, &end);
        assert_true(start > previous); /* in order */
        previous = start;
        assert_int_equal(in_range(start, end, "Not rendered yet"), n == 3);
        /* Chapter 2 has files but not its Figure 8: that one is said to be missing. */
        assert_int_equal(in_range(start, end, "Not rendered:</strong> ch02_figure8.png"),
                         n == 2);
        assert_int_equal(in_range(start, end, "Not rendered:</strong> ch02_figure2.png"), 0);
        assert_true(in_range(start, end, CHAPTERS[n - 1].teaches));
    }
    const char *toc = strstr(page, "<nav>"), *toc_end = strstr(page, "</nav>");
    assert_true(in_range(toc, toc_end, "Third, not rendered</a> <em>(not rendered yet)</em>"));
    assert_false(in_range(toc, toc_end, "First</a> <em>"));
    free(page);
}

/* Figures shown where they belong; the panel only linked; the plot under Plots; the diff
 * folded in chapter 2; QUICK and the run's numbers in the header. */
static void test_layout(void **state)
{
    char *page = make_page();
    const char *end, *one = section(page, 1, &end);
    assert_true(in_range(one, end, "<img src=\"ch01_figure1.png\""));
    assert_true(in_range(one, end, "width=\"6\" height=\"9\""));
    assert_false(in_range(one, end, "<img src=\"ch01_panel.png\""));
    assert_true(in_range(one, end, "<a href=\"ch01_panel.png\">"));
    const char *two = section(page, 2, &end);
    const char *plots = strstr(two, "<h3>Plots</h3>");
    assert_true(plots && plots < end && strstr(plots, "<img src=\"ch02_plot.png\"") < end);
    assert_true(strstr(two, "<img src=\"ch02_figure2.png\"") < plots);
    const char *exercises = strstr(two, "<h3>Exercises: the solution's verdicts and pictures "
                                        "(make check-exercise-chapter2)</h3>");
    assert_true(exercises && exercises > plots && exercises < end);
    assert_true(in_range(exercises, end, "<img src=\"ch02_exercise-2.1-warp.png\""));
    assert_true(in_range(exercises, end, "exercise 2.1 (hemisphere_sample_cosine): pass"));
    assert_false(in_range(two, exercises, "ch02_exercise"));
    assert_true(in_range(two, end, "<details>"));
    assert_true(in_range(two, end, "<span class=\"add\">+int y &lt; 1;</span>"));
    assert_false(in_range(one, section(page, 2, &end), "<details>"));
    const char *body = strstr(page, "<body>");
    assert_true(in_range(page, body, "<title>Test gallery (QUICK)</title>"));
    const char *nav = strstr(page, "<nav>");
    assert_true(in_range(body, nav, "QUICK=1"));
    assert_true(in_range(body, nav, "took 75 s"));
    assert_true(in_range(body, nav, "on 2 threads"));
    assert_true(in_range(body, nav, "started 2026-01-02 03:04:05 +0000"));
    free(page);
}

static void test_text_is_escaped_and_no_script(void **state)
{
    char *page = make_page();
    assert_non_null(
        strstr(page, "--size 200 &lt;script&gt;alert(1)&lt;/script&gt; &amp; more"));
    for (char *c = page; *c; c++)
        *c = (char)(*c >= 'A' && *c <= 'Z' ? *c - 'A' + 'a' : *c);
    assert_null(strstr(page, "<script"));
    assert_null(strstr(page, "<b>"));
    assert_null(strstr(page, "http:"));
    assert_null(strstr(page, "https:"));
    free(page);
}

/* Without a run record the page says so; a folder that is not there is an error naming
 * it, and no page is left behind. */
static void test_no_run_and_errors(void **state)
{
    empty_fixture();
    GalleryPage page = {"Test gallery", fixture, NULL, CHAPTERS, CHAPTER_COUNT, 0, NULL, NULL};
    char error[4400] = "";
    assert_int_equal(gallery_write(&page, error, sizeof error), 0);
    char path[4200];
    snprintf(path, sizeof path, "%s/index.html", fixture);
    FILE *file = fopen(path, "rb");
    assert_non_null(file);
    static char text[1 << 16];
    text[fread(text, 1, sizeof text - 1, file)] = '\0';
    fclose(file);
    assert_non_null(strstr(text, "No run was recorded"));
    assert_null(strstr(text, "QUICK"));
    page.figures = "build/no such folder";
    assert_int_equal(gallery_write(&page, error, sizeof error), -1);
    assert_non_null(strstr(error, "build/no such folder"));
}

/* Where the page knows the lab, a figure with settings there links to it with them and
 * with the width of its chapter's panels (chapter 1's PFM is 6 wide; chapter 2 has none);
 * a figure without settings, or a page without the lab, has no such link. */
static void test_figures_link_to_the_lab(void **state)
{
    make_fixture();
    GalleryChapter chapters[CHAPTER_COUNT];
    memcpy(chapters, CHAPTERS, sizeof chapters);
    chapters[0].lab = "ch01_figure1 chapter=1&M=2";
    chapters[1].lab = "ch02_figure8 chapter=2&spp=9  ch02_plot chapter=2&b.spp=4";
    GalleryPage page = {"Test gallery",      fixture, fixture, chapters, CHAPTER_COUNT, 0,
                        "../lab/index.html", NULL};
    char *text = written(&page);
    const char *one = strstr(text, "<img src=\"ch01_figure1.png\""),
               *plot = strstr(text, "<img src=\"ch02_plot.png\"");
    const char *figure = strstr(text, "<img src=\"ch02_figure2.png\"");
    assert_non_null(one);
    assert_non_null(plot);
    assert_non_null(figure);
    const char *link =
        "<a class=\"lab\" href=\"../lab/index.html#chapter=1&amp;M=2&amp;size=6\">live in the "
        "lab</a>";
    assert_true(in_range(one, strstr(one, "</figure>"), link));
    assert_true(
        in_range(plot, strstr(plot, "</figure>"),
                 "<a class=\"lab\" href=\"../lab/index.html#chapter=2&amp;b.spp=4\">live in "
                 "the lab</a>"));
    assert_false(in_range(figure, strstr(figure, "</figure>"), "live in the lab"));
    int links = 0;
    for (const char *at = text; (at = strstr(at, "live in the lab")) != NULL; at++)
        links++;
    assert_int_equal(links, 2);
    free(text);
    page.lab = NULL;
    text = written(&page);
    assert_null(strstr(text, "live in the lab"));
    free(text);
}

/* Where the page knows the book, it links to the book's index and each chapter to its page
 * there; without it, nowhere. */
static void test_chapters_link_to_the_book(void **state)
{
    make_fixture();
    GalleryPage page = {"Test gallery", fixture, fixture, CHAPTERS,
                        CHAPTER_COUNT,  0,       NULL,    "../book"};
    char *text = written(&page);
    assert_non_null(strstr(text, "<a class=\"book\" href=\"../book/index.html\">"));
    for (int i = 0; i < CHAPTER_COUNT; i++) {
        char section[64], link[96];
        snprintf(section, sizeof section, "<section id=\"chapter%d\">", CHAPTERS[i].number);
        snprintf(link, sizeof link, "<a class=\"book\" href=\"../book/chapter%d.html\">",
                 CHAPTERS[i].number);
        const char *at = strstr(text, section);
        assert_non_null(at);
        assert_true(in_range(at, strstr(at, "</section>"), link));
    }
    free(text);
    page.book = NULL;
    text = written(&page);
    assert_null(strstr(text, "../book"));
    free(text);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_links_resolve),
        cmocka_unit_test(test_tables_carry_the_csv),
        cmocka_unit_test(test_missing_chapter_and_figure_are_listed),
        cmocka_unit_test(test_layout),
        cmocka_unit_test(test_text_is_escaped_and_no_script),
        cmocka_unit_test(test_no_run_and_errors),
        cmocka_unit_test(test_figures_link_to_the_lab),
        cmocka_unit_test(test_chapters_link_to_the_book),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
