/* test_table.c (bench, chapter 1): the cost/accuracy table on the terminal and as CSV
 * (table.h).
 *
 * The CSV is read back with a small RFC 4180 reader (quoted fields, "" for a quote) and
 * every number compared with the row it came from; the printed table is captured in
 * memory and checked line by line: one per row under a header, "-" where nothing was
 * measured, and every line as long as the header, so columns stay aligned. A table of
 * numbers as CSV, by hand.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "assert_close.h"
#include "table.h"

#define FIELDS 18
#define FIELD_SIZE 128

/* Two rows as a chapter would make them: one measured against a reference, one not. */
static void sample_rows(TableRow rows[2])
{
    rows[0] = (TableRow){.panel = "Figure 11a",
                         .settings = "64 spp, M=1 depth=5",
                         .spp = 64,
                         .seconds = 1.5,
                         .threads = 8,
                         .rays = {1000000, 1500000, 500000},
                         .rmse = 0.0123,
                         .rel_mse = 4.56e-3,
                         .efficiency = 146.198830409,
                         .nonfinite = 3,
                         .runs = 5,
                         .rmse_spread = 0.0021,
                         .rel_mse_spread = 3e-4,
                         .reference_share = 0.125,
                         .infinite_variance = 1};
    rows[1] = (TableRow){.panel = "Figure 1",
                         .settings = "1 ray/pixel, depth 5",
                         .spp = 1,
                         .seconds = 0.25,
                         .threads = 1,
                         .rays = {40000, 10000, 30000},
                         .rmse = NAN,
                         .rel_mse = NAN,
                         .efficiency = NAN,
                         .rmse_spread = NAN,
                         .rel_mse_spread = NAN,
                         .reference_share = NAN};
}

/* Mrays/s is all rays (camera + bounce + shadow) per second, in millions: 3e6 rays in
 * 1.5 s is 2; a row that took no time (or an impossible negative time) reports 0
 * rather than infinity. */
static void test_mrays_per_second(void **state)
{
    TableRow rows[2];
    sample_rows(rows);
    assert_close(table_mrays_per_second(&rows[0]), 2.0, 1e-15);
    assert_close(table_mrays_per_second(&rows[1]), 0.32, 1e-15);
    rows[0].seconds = 0.0;
    assert_true(table_mrays_per_second(&rows[0]) == 0.0);
    rows[0].seconds = -1.0;
    assert_true(table_mrays_per_second(&rows[0]) == 0.0);
}

/* Splits one CSV line (without its newline) into fields, RFC 4180 style: a field in
 * double quotes may hold commas, and "" inside it is one quote. Returns the count. */
static int parse_csv_line(const char *line, char fields[][FIELD_SIZE], int max_fields)
{
    int count = 0;
    const char *p = line;
    for (;;) {
        assert_true(count < max_fields);
        char *out = fields[count++];
        size_t length = 0;
        if (*p == '"') {
            for (p++; *p && !(*p == '"' && p[1] != '"'); p++) {
                if (*p == '"')
                    p++;
                out[length++] = *p;
            }
            assert_int_equal(*p, '"');
            p++;
        } else {
            for (; *p && *p != ','; p++)
                out[length++] = *p;
        }
        assert_true(length < FIELD_SIZE);
        out[length] = '\0';
        if (*p != ',') {
            assert_int_equal(*p, '\0');
            return count;
        }
        p++;
    }
}

/* A number field, parsed whole (nothing may follow the number). */
static double number(const char *field)
{
    char *end;
    double value = strtod(field, &end);
    assert_true(end != field && *end == '\0');
    return value;
}

static char scratch_dir[64], csv_path[128];

static int make_scratch(void **state)
{
    strcpy(scratch_dir, "/tmp/test_table_XXXXXX");
    if (!mkdtemp(scratch_dir))
        return -1;
    snprintf(csv_path, sizeof csv_path, "%s/table.csv", scratch_dir);
    return 0;
}

static int remove_scratch(void **state)
{
    remove(csv_path);
    return rmdir(scratch_dir);
}

/* Writes `rows` as CSV and reads it back into lines[][FIELDS] (at most 4 lines),
 * checking each line has all 13 fields. Returns the number of lines. */
static int csv_round_trip(const TableRow *rows, int count, char lines[][FIELDS][FIELD_SIZE])
{
    assert_int_equal(table_write_csv(csv_path, rows, count), 0);
    FILE *file = fopen(csv_path, "r");
    assert_non_null(file);
    char text[1024];
    int n = 0;
    while (fgets(text, sizeof text, file)) {
        assert_true(n < 4);
        size_t length = strlen(text);
        assert_true(length > 0 && text[length - 1] == '\n');
        text[length - 1] = '\0';
        assert_int_equal(parse_csv_line(text, lines[n++], FIELDS), FIELDS);
    }
    fclose(file);
    return n;
}

/* The CSV has the header scripts read, then one line per row whose fields are the
 * row's values: text as given (the settings, which hold commas, survive because they
 * are quoted), numbers equal to the row's to the precision written, Mrays/s computed,
 * and empty error fields where there was no reference. */
static void test_csv_values(void **state)
{
    TableRow rows[2];
    sample_rows(rows);
    char lines[4][FIELDS][FIELD_SIZE];
    assert_int_equal(csv_round_trip(rows, 2, lines), 3);
    const char *header[FIELDS] = {"panel",
                                  "settings",
                                  "spp",
                                  "seconds",
                                  "threads",
                                  "camera_rays",
                                  "bounce_rays",
                                  "shadow_rays",
                                  "mrays_per_second",
                                  "rmse",
                                  "rel_mse",
                                  "efficiency",
                                  "nonfinite",
                                  "runs",
                                  "rmse_sd",
                                  "rel_mse_sd",
                                  "reference_share",
                                  "variance"};
    for (int f = 0; f < FIELDS; f++)
        assert_string_equal(lines[0][f], header[f]);
    for (int i = 0; i < 2; i++) {
        char(*fields)[FIELD_SIZE] = lines[i + 1];
        const TableRow *r = &rows[i];
        assert_string_equal(fields[0], r->panel);
        assert_string_equal(fields[1], r->settings);
        assert_true(number(fields[2]) == r->spp);
        assert_close(number(fields[3]), r->seconds, 1e-6);
        assert_true(number(fields[4]) == r->threads);
        assert_true(number(fields[5]) == (double)r->rays.camera);
        assert_true(number(fields[6]) == (double)r->rays.bounce);
        assert_true(number(fields[7]) == (double)r->rays.shadow);
        assert_close(number(fields[8]), table_mrays_per_second(r), 1e-5);
        assert_true(number(fields[12]) == (double)r->nonfinite);
        assert_true(number(fields[13]) == (r->runs > 1 ? r->runs : 1));
        if (isnan(r->rmse_spread))
            assert_string_equal(fields[14], "");
        else
            assert_close(number(fields[14]), r->rmse_spread, 1e-9);
        if (isnan(r->rel_mse_spread))
            assert_string_equal(fields[15], "");
        else
            assert_close(number(fields[15]), r->rel_mse_spread, 1e-9);
        if (isnan(r->reference_share))
            assert_string_equal(fields[16], "");
        else
            assert_close(number(fields[16]), r->reference_share, 1e-9);
        assert_string_equal(fields[17], r->infinite_variance ? "infinite" : "finite");
    }
    assert_close(number(lines[1][9]), 0.0123, 1e-12);
    assert_close(number(lines[1][10]), 4.56e-3, 1e-12);
    assert_close(number(lines[1][11]), 146.198830409, 1e-6);
    /* The row without a reference leaves its error fields empty (not "nan", which a
     * spreadsheet would read as text); the field after them is still in its place. */
    for (int f = 9; f <= 11; f++)
        assert_string_equal(lines[2][f], "");
    assert_string_equal(lines[2][12], "0");
}

/* Settings text holding a double quote, and a panel name holding a comma, still read
 * back as one field each. */
static void test_csv_quotes_text(void **state)
{
    TableRow rows[2];
    sample_rows(rows);
    strcpy(rows[0].panel, "Figure 9, left");
    strcpy(rows[0].settings, "scene \"small room\", 4 spp");
    char lines[4][FIELDS][FIELD_SIZE];
    assert_int_equal(csv_round_trip(rows, 1, lines), 2);
    assert_string_equal(lines[1][0], "Figure 9, left");
    assert_string_equal(lines[1][1], "scene \"small room\", 4 spp");
    assert_true(number(lines[1][2]) == 64);
}

/* No rows: the header alone. A directory that does not exist: -1, nothing written. */
static void test_csv_edge_cases(void **state)
{
    char lines[4][FIELDS][FIELD_SIZE];
    assert_int_equal(csv_round_trip(NULL, 0, lines), 1);
    assert_string_equal(lines[0][0], "panel");
    TableRow rows[2];
    sample_rows(rows);
    char missing[160];
    snprintf(missing, sizeof missing, "%s/no_such_dir/table.csv", scratch_dir);
    assert_int_equal(table_write_csv(missing, rows, 2), -1);
}

/* table_print's output, captured: the lines, split in place, and their count. */
typedef struct {
    char *text;
    size_t size;
    char *lines[8];
    int count;
} Printed;

static Printed print_rows(const TableRow *rows, int count)
{
    Printed printed = {0};
    FILE *out = open_memstream(&printed.text, &printed.size);
    assert_non_null(out);
    table_print(out, rows, count);
    assert_int_equal(fclose(out), 0);
    for (char *line = printed.text; *line;) {
        char *end = strchr(line, '\n');
        assert_non_null(end);
        assert_true(printed.count < 8);
        *end = '\0';
        printed.lines[printed.count++] = line;
        line = end + 1;
    }
    return printed;
}

/* The n-th whitespace-separated word counted from the end of a line (0 is the last),
 * copied into `word`: the numeric columns, whatever spaces the settings hold. */
static const char *word_from_end(const char *line, int n, char word[32])
{
    const char *end = line + strlen(line);
    for (;;) {
        while (end > line && end[-1] == ' ')
            end--;
        const char *start = end;
        while (start > line && start[-1] != ' ')
            start--;
        if (n-- == 0) {
            assert_true(end - start < 32);
            memcpy(word, start, (size_t)(end - start));
            word[end - start] = '\0';
            return word;
        }
        end = start;
    }
}

/* A header then one line per row, each starting with its panel and settings; the
 * numeric columns read the row's values in the documented formats; a row without a
 * reference shows "-" in each error column; a row of infinite variance is marked, and
 * the note saying why its error cannot be pinned down follows the table. */
static void test_print_rows(void **state)
{
    TableRow rows[2];
    sample_rows(rows);
    Printed printed = print_rows(rows, 2);
    assert_int_equal(printed.count, 4);
    assert_string_equal(printed.lines[3], TABLE_INFINITE_VARIANCE_NOTE);
    assert_true(strncmp(printed.lines[0], "panel", 5) == 0);
    assert_non_null(strstr(printed.lines[0], "efficiency"));
    for (int i = 0; i < 2; i++) {
        assert_true(strncmp(printed.lines[i + 1], rows[i].panel, strlen(rows[i].panel)) == 0);
        assert_non_null(strstr(printed.lines[i + 1], rows[i].settings));
    }
    const char *measured[] = {"3",         "inf-var",   "5",       "12%",  "146",
                              "4.560e-03", "+-0.00210", "0.01230", "2.00", "500000",
                              "1500000",   "1000000",   "8",       "1.50", "64.0"};
    const char *unmeasured[] = {"0",    "finite", "1",     "-",     "-", "-",    "-",  "-",
                                "0.32", "30000",  "10000", "40000", "1", "0.25", "1.0"};
    char word[32];
    for (int n = 0; n < 15; n++) {
        assert_string_equal(word_from_end(printed.lines[1], n, word), measured[n]);
        assert_string_equal(word_from_end(printed.lines[2], n, word), unmeasured[n]);
    }
    free(printed.text);
}

/* An error within the reference's noise (the corrected MSE not above 0: the RMSE is
 * then 0 and the relative MSE may be negative) is printed as "<ref" in both columns,
 * never as a negative number; an image as good as a noiseless reference says (RMSE 0,
 * no reference noise) is printed as 0. */
static void test_print_within_reference_noise(void **state)
{
    TableRow rows[2];
    sample_rows(rows);
    rows[0].rmse = 0.0;
    rows[0].rel_mse = -2.5e-5;
    rows[0].efficiency = NAN;
    rows[0].reference_share = 1.3;
    rows[1] = rows[0];
    rows[1].rel_mse = 0.0;
    rows[1].reference_share = 0.0;
    Printed printed = print_rows(rows, 2);
    char word[32];
    assert_string_equal(word_from_end(printed.lines[1], 7, word), "<ref");
    assert_string_equal(word_from_end(printed.lines[1], 5, word), "<ref");
    assert_null(strstr(printed.lines[1], "-2.5"));
    assert_string_equal(word_from_end(printed.lines[2], 7, word), "0.00000");
    assert_string_equal(word_from_end(printed.lines[2], 5, word), "<ref");
    assert_int_equal(strlen(printed.lines[1]), strlen(printed.lines[0]));
    free(printed.text);
}

/* Names as long as a row can hold (47 characters of panel, 95 of settings) do not push
 * the columns after them out of line: every line is exactly as long as the header, so
 * each number sits under its heading. */
static void test_print_long_names_keep_columns(void **state)
{
    TableRow rows[3];
    sample_rows(rows);
    rows[0].infinite_variance = 0; /* no note under the table: every line is a row */
    rows[2] = rows[0];
    memset(rows[2].panel, 'p', sizeof rows[2].panel - 1);
    rows[2].panel[sizeof rows[2].panel - 1] = '\0';
    memset(rows[2].settings, 's', sizeof rows[2].settings - 1);
    rows[2].settings[sizeof rows[2].settings - 1] = '\0';
    Printed printed = print_rows(rows, 3);
    assert_int_equal(printed.count, 4);
    size_t width = strlen(printed.lines[0]);
    for (int i = 1; i < printed.count; i++)
        if (strlen(printed.lines[i]) != width)
            fail_msg("line %d is %zu characters, the header %zu:\n%s\n%s", i,
                     strlen(printed.lines[i]), width, printed.lines[0], printed.lines[i]);
    free(printed.text);
}

/* A table of numbers as CSV, by hand: the header, then each row with its columns'
 * decimals (rounded, and negative numbers kept). No file is left where it cannot be
 * written. */
static void test_numbers_csv_by_hand(void **state)
{
    const double values[] = {5, 0.1234567, -2.5, 42.25, 1.0 / 3.0, 0.0};
    const int decimals[] = {0, 4, 2};
    assert_int_equal(table_write_numbers_csv(csv_path, "a,b,c", values, 2, 3, decimals), 0);
    FILE *file = fopen(csv_path, "r");
    assert_non_null(file);
    char text[256] = "";
    size_t length = fread(text, 1, sizeof text - 1, file);
    fclose(file);
    text[length] = '\0';
    assert_string_equal(text, "a,b,c\n5,0.1235,-2.50\n42,0.3333,0.00\n");
    assert_int_equal(
        table_write_numbers_csv("/nonexistent-folder/table.csv", "a", values, 1, 1, decimals),
        -1);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_mrays_per_second),
        cmocka_unit_test_setup_teardown(test_csv_values, make_scratch, remove_scratch),
        cmocka_unit_test_setup_teardown(test_csv_quotes_text, make_scratch, remove_scratch),
        cmocka_unit_test_setup_teardown(test_csv_edge_cases, make_scratch, remove_scratch),
        cmocka_unit_test_setup_teardown(test_numbers_csv_by_hand, make_scratch, remove_scratch),
        cmocka_unit_test(test_print_rows),
        cmocka_unit_test(test_print_within_reference_noise),
        cmocka_unit_test(test_print_long_names_keep_columns),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
