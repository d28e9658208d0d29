/* grading.c (bench, chapter 1): verdicts, numbers and the warp test. See grading.h. */
#include "grading.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "chi_square.h"
#include "figure.h"
#include "font.h"
#include "scene_file.h"
#include "student_t.h"

#define PANEL 200

static void append(char *text, size_t size, const char *format, va_list args)
{
    size_t used = strlen(text);
    if (used + 1 < size)
        vsnprintf(text + used, size - used, format, args);
}

const Exercise *exercise_find(const char *id)
{
    for (int i = 0; i < exercise_count; i++)
        if (strcmp(exercises[i].id, id) == 0)
            return &exercises[i];
    return NULL;
}

#define MAX_USED 16

/* Append the exercises `e` uses, each after those it uses itself and each once, to
 * order[*count], `depth` uses deep. Returns 0, or -1 after failing on an id the table
 * does not have or on a circle of uses. */
static int used_in_order(Grading *g, const Exercise *e, int depth, const Exercise **order,
                         int *count)
{
    for (const char *at = e->uses; *at;) {
        at += strspn(at, " ");
        int length = (int)strcspn(at, " ");
        if (length == 0)
            break;
        char id[16];
        snprintf(id, sizeof id, "%.*s", length, at);
        at += length;
        const Exercise *used = exercise_find(id);
        if (!used || *count >= MAX_USED || depth >= MAX_USED) {
            grading_fail(g,
                         "the grader's table says exercise %s uses exercise %s, which it "
                         "does not grade, or which uses it in turn",
                         e->id, id);
            return -1;
        }
        if (used_in_order(g, used, depth + 1, order, count) != 0)
            return -1;
        int seen = 0;
        for (int i = 0; i < *count; i++)
            seen |= order[i] == used;
        if (!seen)
            order[(*count)++] = used;
    }
    return 0;
}

/* Grade `used` as a part of g's exercise, on the same answers. Returns 1 when it passes;
 * else g fails, naming it first. */
static int grade_used(Grading *g, const Exercise *e, const Exercise *used)
{
    Grading part;
    memset(&part, 0, sizeof part);
    part.id = used->id;
    part.out = g->out;
    part.references = g->references;
    part.writer = g->writer;
    part.answers = g->answers;
    part.ended = g->ended;
    part.next = g->next;
    part.seed = g->seed;
    used->grade(&part);
    g->next = part.next;
    if (!part.failed) {
        grading_note(g, "exercise %s (%s), which %s depends on, passes", used->id,
                     used->function, e->function);
        return 1;
    }
    grading_fail(g, "exercise %s (%s), which %s depends on, is wrong first: %s", used->id,
                 used->function, e->function, part.message);
    size_t length = strlen(part.numbers);
    if (length > 0 && part.numbers[length - 1] == '\n')
        part.numbers[length - 1] = '\0';
    if (length > 1)
        grading_note(g, "exercise %s: %s", used->id, part.numbers);
    return 0;
}

void exercise_grade(const Exercise *e, Grading *g)
{
    const Exercise *order[MAX_USED];
    int count = 0;
    if (used_in_order(g, e, 0, order, &count) != 0)
        return;
    for (int i = 0; i < count; i++)
        if (!grade_used(g, e, order[i]))
            return;
    e->grade(g);
}

int grading_probing(const Grading *g) { return g->writer != NULL; }

double grading_level(void) { return -expm1(log1p(-COURSE_FALSE_ALARM) / COURSE_CHECKS); }

double grading_z(double level)
{
    double low = 0.0, high = 40.0; /* erfc(z / sqrt 2) falls from 1 to 0 */
    for (int i = 0; i < 200; i++) {
        double mid = 0.5 * (low + high);
        if (erfc(mid / sqrt(2.0)) > level)
            low = mid;
        else
            high = mid;
    }
    return 0.5 * (low + high);
}

double grading_detectable(double se)
{
    /* one-sided: P(Z > z) = 1 - power is the two-sided level 2 (1 - power) */
    return (grading_z(grading_level()) + grading_z(2.0 * (1.0 - GRADING_POWER))) * se;
}

int grading_seed_from_environment(uint64_t *seed, char *error, size_t size)
{
    const char *text = getenv("GRADE_SEED");
    *seed = 0;
    if (!text || !*text)
        return 0;
    char *end;
    errno = 0;
    unsigned long long value = strtoull(text, &end, 10);
    if (*end || errno || text[0] < '0' || text[0] > '9' || value > 0xffffffffULL) {
        snprintf(error, size, "GRADE_SEED=%s is not a whole number from 0 to 4294967295", text);
        return -1;
    }
    *seed = value;
    return 0;
}

uint64_t grading_stream(const Grading *g, uint64_t stream) { return stream ^ (g->seed << 32); }

const WrongAnswer *grading_known_wrong(const WrongAnswer *list, int count, const double *inputs,
                                       int arity, const double *got, int points)
{
    if (points < 2)
        return NULL;
    for (int i = 0; i < count; i++) {
        int k = 0;
        for (; k < points; k++) {
            double wrong = list[i].value(inputs + (long)k * arity);
            if (!(fabs(got[k] - wrong) <= 1e-9 * fabs(wrong) + 1e-300))
                break;
        }
        if (k == points)
            return &list[i];
    }
    return NULL;
}

Strata grading_strata(int dims, const int *divisions)
{
    Strata strata = {.dims = dims, .cells = 1};
    for (int k = 0; k < dims; k++) {
        strata.divisions[k] = divisions[k];
        strata.cells *= divisions[k];
    }
    while ((1L << strata.bits) < strata.cells)
        strata.bits++;
    return strata;
}

/* A bijection of [0, 2^bits) that scatters neighbours: odd multipliers and xorshifts,
 * each invertible modulo 2^bits. */
static uint64_t scatter(uint64_t x, int bits)
{
    uint64_t mask = (1ULL << bits) - 1;
    int shift = bits / 2 + 1;
    x = (x * 0x9e3779b97f4a7c15ULL) & mask;
    x ^= x >> shift;
    x = (x * 0xbf58476d1ce4e5b9ULL) & mask;
    return x ^ (x >> shift);
}

void grading_stratify(const Strata *strata, long index, double *u)
{
    /* scattered until it falls among the cells: a bijection of them (cycle walking) */
    uint64_t cell = (uint64_t)(index % strata->cells);
    do
        cell = scatter(cell, strata->bits);
    while (cell >= (uint64_t)strata->cells);
    for (int k = strata->dims - 1; k >= 0; k--) {
        int n = strata->divisions[k];
        u[k] = ((double)(cell % n) + u[k]) / n;
        cell /= n;
    }
}

int grading_replicate_test(Grading *g, const char *what, const double *replicate_means,
                           int replicates, double exact, const char *hint)
{
    double mean = 0.0, spread = 0.0, largest = fabs(exact);
    for (int r = 0; r < replicates; r++) {
        mean += replicate_means[r] / replicates;
        largest = fmax(largest, fabs(replicate_means[r]));
    }
    for (int r = 0; r < replicates; r++)
        spread += (replicate_means[r] - mean) * (replicate_means[r] - mean);
    double se = sqrt(spread / (replicates - 1) / replicates);
    double difference = fabs(mean - exact) <= 1e-12 * largest ? 0.0 : mean - exact;
    double t = se > 0.0 ? difference / se : (difference == 0.0 ? 0.0 : INFINITY);
    double detectable =
        student_t_detectable(grading_level(), GRADING_POWER, replicates - 1) * se;
    grading_note(g,
                 "%s: %.6f, exactly %.6f (t = %+.1f over %d replicates; a bias of %.2g "
                 "detected at power %.2f)",
                 what, mean, exact, t, replicates, detectable, GRADING_POWER);
    if (student_t_tail(t, replicates - 1) >= grading_level())
        return 1;
    char off[64];
    if (exact != 0.0)
        snprintf(off, sizeof off, "%+.2f%%", 100.0 * (mean / exact - 1.0));
    else
        snprintf(off, sizeof off, "%+.6f", mean);
    return grading_fail(g,
                        "%s is %.6f where %.6f is exact (%s, t = %+.1f over %d independent "
                        "replicates, each the mean of a stratified grid of inputs): %s",
                        what, mean, exact, off, t, replicates, hint);
}

int grading_fail_known(Grading *g, const char *quantity, const WrongAnswer *known, int points)
{
    return grading_fail(g, "your %s equals %s, at each of the %d inputs tried (to 1e-9): %s",
                        quantity, known->wrong, points, known->right);
}

double grading_ask(Grading *g, double value)
{
    if (grading_probing(g)) {
        if (answer_put(g->writer, value) != 0) {
            fprintf(stderr, "grade: cannot send an answer to the grader: %s\n",
                    strerror(errno));
            _exit(3);
        }
        return value;
    }
    if (g->next < g->answers->count)
        return g->answers->values[g->next++];
    grading_fail(g, "%s", g->ended);
    return NAN;
}

Vec3 grading_ask_vec3(Grading *g, Vec3 value)
{
    double x = grading_ask(g, value.x), y = grading_ask(g, value.y);
    return vec3(x, y, grading_ask(g, value.z));
}

void grading_ask_floats(Grading *g, float *values, long count)
{
    for (long i = 0; i < count; i++)
        values[i] = (float)grading_ask(g, values[i]);
}

void grading_note(Grading *g, const char *format, ...)
{
    va_list args;
    va_start(args, format);
    append(g->numbers, sizeof g->numbers, format, args);
    va_end(args);
    size_t used = strlen(g->numbers);
    if (used + 1 < sizeof g->numbers)
        strcpy(g->numbers + used, "\n");
}

int grading_fail(Grading *g, const char *format, ...)
{
    if (g->failed)
        return 0;
    g->failed = 1;
    va_list args;
    va_start(args, format);
    vsnprintf(g->message, sizeof g->message, format, args);
    va_end(args);
    return 0;
}

int grading_not_finite(Grading *g, double value, const char *what)
{
    if (isfinite(value))
        return 0;
    grading_fail(g, "%s is %s", what,
                 isnan(value) ? "NaN (a 0 / 0, a sqrt of a negative "
                                "number or an uninitialised variable?)"
                              : "infinite (a division by 0?)");
    return 1;
}

int grading_decimals(double a, double b)
{
    for (int decimals = 4; decimals < 17; decimals++) {
        char x[64], y[64];
        snprintf(x, sizeof x, "%.*f", decimals, a);
        snprintf(y, sizeof y, "%.*f", decimals, b);
        if (strcmp(x, y) != 0)
            return decimals;
    }
    return 17;
}

char *grading_count(double count, char *text, size_t size)
{
    char digits[64];
    snprintf(digits, sizeof digits, "%.0f", fabs(count));
    size_t n = strlen(digits), out = 0;
    if (count < 0 && out + 1 < size)
        text[out++] = '-';
    for (size_t i = 0; i < n && out + 2 < size; i++) {
        if (i > 0 && (n - i) % 3 == 0)
            text[out++] = ',';
        text[out++] = digits[i];
    }
    text[out] = '\0';
    return text;
}

char *grading_p(double p, char *text, size_t size)
{
    if (p < 1e-9)
        snprintf(text, size, "p < 1e-9");
    else
        snprintf(text, size, "p = %.2g", p);
    return text;
}

int grading_scene(Grading *g, const char *text, Scene *scene)
{
    char error[512];
    if (scene_parse(text, strlen(text), "exercise.scene", scene, NULL, error, sizeof error) ==
        0)
        return 0;
    grading_fail(g, "the exercise's scene does not load: %s", error);
    return -1;
}

int warp_new(Grading *g, Warp *warp, int rows, int cols, int shown, WarpLabels labels)
{
    memset(warp, 0, sizeof *warp);
    warp->labels = labels;
    warp->rows = rows;
    warp->cols = cols;
    warp->shown = shown;
    size_t cells = (size_t)rows * cols + 1;
    warp->observed = calloc(cells, sizeof *warp->observed);
    warp->expected = calloc(cells, sizeof *warp->expected);
    warp->square = calloc(2 * (size_t)shown, sizeof *warp->square);
    warp->mapped = calloc(2 * (size_t)shown, sizeof *warp->mapped);
    if (!warp->observed || !warp->expected || !warp->square || !warp->mapped) {
        warp_free(warp);
        grading_fail(g, "out of memory");
        return -1;
    }
    return 0;
}

void warp_free(Warp *warp)
{
    free(warp->observed);
    free(warp->expected);
    free(warp->square);
    free(warp->mapped);
    memset(warp, 0, sizeof *warp);
}

void warp_add(Warp *warp, long index, int row, int col, double u1, double u2, double x,
              double y)
{
    int cell = row < 0 ? warp->rows * warp->cols : row * warp->cols + col;
    warp->observed[cell] += 1.0;
    if (index < warp->shown) {
        warp->square[2 * index] = u1;
        warp->square[2 * index + 1] = u2;
        warp->mapped[2 * index] = x;
        warp->mapped[2 * index + 1] = y;
    }
}

void warp_add_hemisphere(Warp *warp, long index, double u1, double u2, Vec3 local)
{
    if (!(fabs(vec3_length(local) - 1.0) < 1e-6) || !(local.z > 0.0)) {
        warp_add(warp, index, -1, 0, u1, u2, NAN, NAN);
        return;
    }
    int ring = (int)((1.0 - local.z) * warp->rows);
    int sector = (int)((atan2(local.y, local.x) + PI) / (2.0 * PI) * warp->cols);
    warp_add(warp, index, ring < warp->rows ? ring : warp->rows - 1,
             sector < warp->cols ? sector : warp->cols - 1, u1, u2, local.x, local.y);
}

void warp_expect_cosine(Warp *warp, long samples)
{
    for (int r = 0; r < warp->rows; r++) {
        double top = 1.0 - (double)r / warp->rows, bottom = 1.0 - (double)(r + 1) / warp->rows;
        for (int s = 0; s < warp->cols; s++)
            warp->expected[r * warp->cols + s] =
                (double)samples * (top * top - bottom * bottom) / warp->cols;
    }
}

/* A sample's colour: where it started on the square, as a 4 x 4 checkerboard of hues. */
static Vec3 sample_colour(double u1, double u2)
{
    int check = ((int)(u1 * 4) + (int)(u2 * 4)) % 2;
    Vec3 base = vec3(0.15 + 0.85 * u1, 0.15 + 0.85 * u2, 0.9 - 0.7 * u1);
    return check ? base : vec3_scale(base, 0.45);
}

static void dot(Image *image, double x, double y, Vec3 colour)
{
    int col = (int)floor(x), row = (int)floor(y);
    for (int dy = 0; dy < 2; dy++)
        for (int dx = 0; dx < 2; dx++)
            if (col + dx >= 0 && col + dx < image->width && row + dy >= 0 &&
                row + dy < image->height)
                image_set(image, col + dx, row + dy, colour);
}

/* Counts as grey levels, the same scale for observed and expected; the impossible cell
 * (when it has samples) makes the whole panel's border red. */
static void histogram_panel(Image *image, const Warp *warp, const double *counts, double top)
{
    for (int row = 0; row < PANEL; row++)
        for (int col = 0; col < PANEL; col++) {
            int r = row * warp->rows / PANEL, c = col * warp->cols / PANEL;
            double v = top > 0.0 ? counts[r * warp->cols + c] / top : 0.0;
            image_set(image, col, row, vec3(v, v, v));
        }
    if (counts[warp->rows * warp->cols] > 0.0)
        for (int i = 0; i < PANEL; i++)
            for (int k = 0; k < 3; k++) {
                image_set(image, i, k, vec3(1, 0, 0));
                image_set(image, i, PANEL - 1 - k, vec3(1, 0, 0));
                image_set(image, k, i, vec3(1, 0, 0));
                image_set(image, PANEL - 1 - k, i, vec3(1, 0, 0));
            }
}

static void write_warp_picture(Grading *g, const Warp *warp, const char *what,
                               const char *verdict)
{
    Image panels[4];
    for (int i = 0; i < 4; i++)
        panels[i] = image_new(PANEL, PANEL);
    for (int i = 0; i < 4; i++)
        if (!panels[i].pixels)
            goto done;
    for (int i = 0; i < warp->shown; i++) {
        double u1 = warp->square[2 * i], u2 = warp->square[2 * i + 1];
        Vec3 colour = sample_colour(u1, u2);
        dot(&panels[0], u1 * (PANEL - 2), (1.0 - u2) * (PANEL - 2), colour);
        double x = warp->mapped[2 * i], y = warp->mapped[2 * i + 1];
        if (isfinite(x) && isfinite(y))
            dot(&panels[1], (0.5 + 0.5 * x) * (PANEL - 2), (0.5 - 0.5 * y) * (PANEL - 2),
                colour);
    }
    double top = 0.0;
    for (int i = 0; i < warp->rows * warp->cols; i++)
        top = fmax(top, fmax(warp->observed[i], warp->expected[i]));
    histogram_panel(&panels[2], warp, warp->observed, top);
    histogram_panel(&panels[3], warp, warp->expected, top);
    char mapped[400], observed[400], expected[400];
    snprintf(mapped, sizeof mapped, "where they went: %s", what);
    snprintf(observed, sizeof observed, "observed counts (%d %ss of %d cells)\n%s", warp->rows,
             warp->labels.row_name, warp->cols, verdict);
    snprintf(expected, sizeof expected, "expected counts\n(%s at the top)",
             warp->labels.first_row);
    const char *captions[4] = {"the samples (u1, u2)\non the unit square", mapped, observed,
                               expected};
    char path[1024], error[256];
    if (g->pictures++ == 0)
        snprintf(path, sizeof path, "%s/exercise-%s-warp.png", g->out, g->id);
    else /* a second warp test of the same exercise */
        snprintf(path, sizeof path, "%s/exercise-%s-warp-%d.png", g->out, g->id, g->pictures);
    Font font;
    if (font_load(&font, FONT_PATH, error, sizeof error) != 0) {
        grading_note(g, "no picture: %s", error);
        goto done;
    }
    if (figure_write_png(path, &font, panels, captions, 4, 1.0) == 0)
        grading_note(g, "picture: %s", path);
    else
        grading_note(g, "no picture: %s could not be written (%s)", path, strerror(errno));
    font_free(&font);
done:
    for (int i = 0; i < 4; i++)
        image_free(&panels[i]);
}

/* Sum of the histogram over one row (by_row) or one column. */
static void marginal(const Warp *warp, int by_row, int index, double *observed,
                     double *expected)
{
    *observed = *expected = 0.0;
    int count = by_row ? warp->cols : warp->rows;
    for (int k = 0; k < count; k++) {
        int cell = by_row ? index * warp->cols + k : k * warp->cols + index;
        *observed += warp->observed[cell];
        *expected += warp->expected[cell];
    }
}

int grading_warp(Grading *g, const Warp *warp, const char *what, double level, int tests,
                 const char *hint)
{
    if (g->failed)
        return 0;
    int cells = warp->rows * warp->cols + 1, dof;
    double statistic = chi_square_statistic(warp->observed, warp->expected, cells, &dof);
    double p = chi_square_p_value(statistic, dof);
    double corrected = -expm1(log1p(-level) / tests);
    char ptext[32], verdict[200];
    grading_p(p, ptext, sizeof ptext);
    snprintf(verdict, sizeof verdict, "chi^2 = %.0f on %d degrees of freedom, %s", statistic,
             dof, ptext);
    grading_note(g, "warp test of %s: %s (level %.2g, Sidak-corrected for %d tests)", what,
                 verdict, corrected, tests);
    int passed = p >= corrected;
    char picture_verdict[300];
    snprintf(picture_verdict, sizeof picture_verdict, "%s: %s", verdict,
             passed ? "passes" : "FAILS");
    if (!grading_probing(g))
        write_warp_picture(g, warp, what, picture_verdict);
    if (passed)
        return 1;
    char observed_text[32], expected_text[32];
    double impossible = warp->observed[cells - 1];
    if (impossible > 0.0) {
        grading_fail(g, "%s of the samples fell %s, where the density is 0 (%s): %s",
                     grading_count(impossible, observed_text, sizeof observed_text),
                     warp->labels.impossible, verdict, hint);
        return 0;
    }
    /* Every sample in one cell: the same direction or point whatever the numbers. */
    int filled = 0, only = 0;
    for (int i = 0; i < cells - 1; i++)
        if (warp->observed[i] > 0.0) {
            filled++;
            only = i;
        }
    if (filled == 1 && warp->observed[only] > 1.0) {
        int row = only / warp->cols;
        const char *at = row == 0                ? warp->labels.first_row
                         : row == warp->rows - 1 ? warp->labels.last_row
                                                 : "";
        grading_fail(g,
                     "all %s samples fell into one cell, %s %d of %d%s%s%s and %s %d of %d: "
                     "does the result change with the random numbers at all? (%s): %s",
                     grading_count(warp->observed[only], observed_text, sizeof observed_text),
                     warp->labels.row_name, row + 1, warp->rows, *at ? " (" : "", at,
                     *at ? ")" : "", warp->labels.col_name, only % warp->cols + 1, warp->cols,
                     verdict, hint);
        return 0;
    }
    /* The row or column whose total is furthest from its expected total, in standard
     * deviations. */
    int worst_row = 1, worst_index = 0;
    double worst = -1.0, worst_observed = 0.0, worst_expected = 0.0;
    for (int by_row = 1; by_row >= 0; by_row--)
        for (int i = 0; i < (by_row ? warp->rows : warp->cols); i++) {
            double o, e;
            marginal(warp, by_row, i, &o, &e);
            double z = e > 0.0 ? fabs(o - e) / sqrt(e) : (o > 0.0 ? INFINITY : 0.0);
            if (z > worst) {
                worst = z;
                worst_row = by_row;
                worst_index = i;
                worst_observed = o;
                worst_expected = e;
            }
        }
    int count = worst_row ? warp->rows : warp->cols;
    const char *name = worst_row ? warp->labels.row_name : warp->labels.col_name;
    char where[200] = "";
    if (worst_row && worst_index == 0)
        snprintf(where, sizeof where, " (%s)", warp->labels.first_row);
    else if (worst_row && worst_index == count - 1)
        snprintf(where, sizeof where, " (%s)", warp->labels.last_row);
    grading_fail(
        g, "too %s samples in %s %d of %d%s: %s observed where %s are expected (%s): %s",
        worst_observed < worst_expected ? "few" : "many", name, worst_index + 1, count, where,
        grading_count(worst_observed, observed_text, sizeof observed_text),
        grading_count(worst_expected, expected_text, sizeof expected_text), verdict, hint);
    return 0;
}
