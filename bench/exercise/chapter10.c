/* chapter10.c (bench, chapter 10): chapter 10's exercises and their graders (grading.h).
 *
 * The error estimate against its closed form at every pixel of half-images the grader lays
 * out (dark pixels, where the 0.01 in the measure matters, and bright ones; corners, edges
 * and the inside of the image), known wrong forms named (section 1). The stopping rule
 * against its definition on a grid of settings, counts and estimates that holds the
 * minimum, the threshold and the maximum exactly, with a catalogue (section 2). Both are
 * closed forms: no statistical check.
 */
#include <math.h>
#include <stdio.h>

#include "adaptive.h"
#include "grading.h"

#define COUNT(list) (int)(sizeof list / sizeof list[0])

/* ---- 10.1: the error estimate ---------------------------------------------------------- */

/* One point of the estimate: {stream, width, height, col, row}; the half-images follow the
 * stream, so that a catalogue's form (one input array) can lay them out again. */
enum {
    ESTIMATE_ARITY = 5,
    MOST_PIXELS = 64
};

/* Half-images first and second of width x height: pixel values from 0.002 to 2, about a
 * third of them dark (below 0.1, where the 0.01 in the measure matters). */
static void lay_out(uint64_t stream, int width, int height, Vec3 *first, Vec3 *second)
{
    for (int p = 0; p < width * height; p++) {
        Rng rng = rng_for_sample(stream, (uint64_t)p, 0);
        double v[6];
        for (int c = 0; c < 6; c++) {
            double u = rng_uniform(&rng);
            v[c] = 0.002 + 2.0 * u * u * u;
        }
        first[p] = vec3(v[0], v[1], v[2]);
        second[p] = vec3(v[3], v[4], v[5]);
    }
}

static double channel_of(Vec3 v, int c) { return c == 0 ? v.x : c == 1 ? v.y : v.z; }

/* The ways of forming the estimate: the right one and the known wrong ones. */
typedef enum {
    FORM_RIGHT,
    FORM_NO_QUARTER,   /* (a - b)^2 without the 1/4 */
    FORM_DIVIDED_BY_9, /* outside pixels skipped, the mean still over 9 */
    FORM_CLAMPED,      /* outside pixels replaced by the nearest edge pixel */
    FORM_VALUE,        /* ((a + b) / 2)^2, the value F, where the difference belongs */
    FORM_NO_FLOOR,     /* / m^2, the 0.01 left out */
    FORM_PIXEL_ONLY,   /* no window: the pixel alone */
    FORM_CHANNEL_SUM,  /* the three channels summed, not averaged */
    FORM_RATIO_OF_SUMS /* the window's summed numerators over its summed denominators */
} EstimateForm;

static double estimate_form(const double *x, EstimateForm form)
{
    int width = (int)x[1], height = (int)x[2], col = (int)x[3], row = (int)x[4];
    Vec3 first[MOST_PIXELS], second[MOST_PIXELS];
    lay_out((uint64_t)x[0], width, height, first, second);
    double sum = 0.0, numerators = 0.0, denominators = 0.0;
    int count = 0, reach = form == FORM_PIXEL_ONLY ? 0 : 1;
    for (int y = row - reach; y <= row + reach; y++)
        for (int xx = col - reach; xx <= col + reach; xx++) {
            int px = xx, py = y;
            if (form == FORM_CLAMPED) {
                px = px < 0 ? 0 : px >= width ? width - 1 : px;
                py = py < 0 ? 0 : py >= height ? height - 1 : py;
            } else if (px < 0 || py < 0 || px >= width || py >= height)
                continue;
            int p = py * width + px;
            for (int c = 0; c < 3; c++) {
                double a = channel_of(first[p], c), b = channel_of(second[p], c);
                double m = (a + b) / 2.0;
                double numerator = form == FORM_NO_QUARTER ? (a - b) * (a - b)
                                   : form == FORM_VALUE    ? m * m
                                                           : (a - b) * (a - b) / 4.0;
                double denominator = form == FORM_NO_FLOOR ? m * m : m * m + 0.01;
                sum += numerator / denominator / (form == FORM_CHANNEL_SUM ? 1.0 : 3.0);
                numerators += numerator;
                denominators += denominator;
            }
            count++;
        }
    if (form == FORM_RATIO_OF_SUMS)
        return numerators / denominators;
    return sum / (form == FORM_DIVIDED_BY_9 ? 9 : count);
}

static double estimate_right(const double *x) { return estimate_form(x, FORM_RIGHT); }
static double estimate_no_quarter(const double *x) { return estimate_form(x, FORM_NO_QUARTER); }
static double estimate_by_9(const double *x) { return estimate_form(x, FORM_DIVIDED_BY_9); }
static double estimate_clamped(const double *x) { return estimate_form(x, FORM_CLAMPED); }
static double estimate_value(const double *x) { return estimate_form(x, FORM_VALUE); }
static double estimate_no_floor(const double *x) { return estimate_form(x, FORM_NO_FLOOR); }
static double estimate_pixel(const double *x) { return estimate_form(x, FORM_PIXEL_ONLY); }
static double estimate_channels(const double *x) { return estimate_form(x, FORM_CHANNEL_SUM); }
static double estimate_ratio(const double *x) { return estimate_form(x, FORM_RATIO_OF_SUMS); }

static const WrongAnswer wrong_estimate[] = {
    {"((A - B))^2 / (m^2 + 0.01) without the 1/4: 4 times the error",
     "the mean (A + B) / 2 has the variance E[((A - B) / 2)^2], the half-difference squared",
     estimate_no_quarter},
    {"the window's sum divided by 9 even at the image's edge, where fewer of its pixels are "
     "inside",
     "the mean is over the window's pixels inside the image: 4 at a corner, 6 on an edge",
     estimate_by_9},
    {"the window clamped at the image's edge, its edge pixels counted again for those outside",
     "the window holds only its pixels inside the image, each once", estimate_clamped},
    {"the value F = (A + B) / 2 squared where the half-difference (A - B) / 2 belongs",
     "the error is ((A - B) / 2)^2: two independent halves differ by their noise only",
     estimate_value},
    {"((A - B) / 2)^2 divided by m^2, without the 0.01: dark pixels' relative error blows "
     "up",
     "the measure is relative to m^2 + 0.01, as measure.h's relative MSE", estimate_no_floor},
    {"the pixel alone, without its 3 x 3 window",
     "the mean over the 3 x 3 window around it, against heavy tails", estimate_pixel},
    {"the three channels summed: 3 times their mean", "the mean over the three channels",
     estimate_channels},
    {"the window's summed ((A - B) / 2)^2 over its summed m^2 + 0.01",
     "each pixel's and channel's own ratio, then their mean", estimate_ratio},
};

/* Where pixel (col, row) of a width x height image lies: 0 inside, 1 on an edge, 2 at a
 * corner (of both edges), and in words. */
static int edges_of(int width, int height, int col, int row)
{
    return (col == 0 || col == width - 1) + (row == 0 || row == height - 1);
}
static const char *const WHERE[3] = {"inside", "on an edge", "at a corner"};

static void grade_estimate(Grading *g)
{
    static const int sizes[][2] = {{6, 5}, {4, 1}, {3, 3}};
    double x[ESTIMATE_ARITY * 3 * MOST_PIXELS], got[3 * MOST_PIXELS];
    int points = 0, wrong = -1, right_at[3] = {0}, tried_at[3] = {0};
    for (int s = 0; s < COUNT(sizes); s++) {
        int width = sizes[s][0], height = sizes[s][1];
        /* 52 bits, so that the stream survives as an input (a double) */
        uint64_t stream = grading_stream(g, 101 + (uint64_t)s) & ((1ull << 52) - 1);
        Vec3 first[MOST_PIXELS], second[MOST_PIXELS];
        lay_out(stream, width, height, first, second);
        for (int row = 0; row < height; row++)
            for (int col = 0; col < width; col++) {
                double *p = x + ESTIMATE_ARITY * points;
                p[0] = (double)stream, p[1] = width, p[2] = height, p[3] = col, p[4] = row;
                got[points] =
                    ASK(g, adaptive_error_estimate(first, second, width, height, col, row));
                if (grading_not_finite(g, got[points], "the estimate"))
                    return;
                if (!grading_probing(g)) {
                    double want = estimate_right(p);
                    int right = fabs(got[points] - want) <= 1e-9 * want;
                    int kind = edges_of(width, height, col, row);
                    tried_at[kind]++;
                    right_at[kind] += right;
                    if (!right && wrong < 0)
                        wrong = points;
                }
                points++;
            }
    }
    if (grading_probing(g))
        return;
    grading_note(g,
                 "%d pixels of %d images: right at %d of %d inside, %d of %d on an edge, "
                 "%d of %d at a corner",
                 points, COUNT(sizes), right_at[0], tried_at[0], right_at[1], tried_at[1],
                 right_at[2], tried_at[2]);
    grading_note(g, "pixel (0, 0) of the 6 x 5 image: %.8f (right: %.8f)", got[0],
                 estimate_right(x));
    if (wrong < 0)
        return;
    const WrongAnswer *match = grading_known_wrong(wrong_estimate, COUNT(wrong_estimate), x,
                                                   ESTIMATE_ARITY, got, points);
    if (match) {
        grading_fail_known(g, "estimate", match, points);
        return;
    }
    const double *p = x + ESTIMATE_ARITY * wrong;
    double want = estimate_right(p);
    int width = (int)p[1], height = (int)p[2], col = (int)p[3], row = (int)p[4];
    grading_fail(g,
                 "the estimate at pixel (%d, %d), %s of a %d x %d image, is %.*f where the "
                 "window's mean of ((A - B) / 2)^2 / (m^2 + 0.01) is %.*f (%.6g times "
                 "that)%s",
                 col, row, WHERE[edges_of(width, height, col, row)], width, height,
                 grading_decimals(got[wrong], want), got[wrong],
                 grading_decimals(got[wrong], want), want, got[wrong] / want,
                 right_at[0] == tried_at[0]
                     ? ": right inside the image, wrong at its edge: the window holds only its "
                       "pixels inside the image, and the mean is over those"
                     : "");
}

/* ---- 10.2: the samples to add ---------------------------------------------------------- */

/* One point of the rule: {min, max, pass, threshold, samples, estimate}. */
enum {
    RULE_ARITY = 6
};

/* The ways of choosing: the right one and the known wrong ones. */
typedef enum {
    RULE_RIGHT,
    RULE_MINIMUM_INCLUSIVE, /* samples <= minimum taken for below it */
    RULE_UNCLIPPED,         /* a whole pass near the maximum */
    RULE_NO_MAXIMUM,        /* passes at or beyond the maximum */
    RULE_AT_THRESHOLD,      /* estimate >= threshold taken for above it */
    RULE_WHOLE_MINIMUM,     /* the whole minimum added below it */
    RULE_NO_MINIMUM,        /* below the minimum, judged by the threshold */
    RULE_INVERTED           /* samples at or below the threshold, none above */
} RuleForm;

static double rule_form(const double *x, RuleForm form)
{
    double min = x[0], max = x[1], pass = x[2], threshold = x[3], samples = x[4],
           estimate = x[5];
    int below_minimum = form == RULE_MINIMUM_INCLUSIVE ? samples <= min : samples < min;
    if (below_minimum && form != RULE_NO_MINIMUM)
        return form == RULE_WHOLE_MINIMUM ? min : min - samples;
    int above = form == RULE_AT_THRESHOLD ? estimate >= threshold
                : form == RULE_INVERTED   ? estimate <= threshold
                                          : estimate > threshold;
    if (!above || (samples >= max && form != RULE_NO_MAXIMUM))
        return 0;
    if (form == RULE_UNCLIPPED || samples >= max)
        return pass;
    return fmin(pass, max - samples);
}

static double rule_right(const double *x) { return rule_form(x, RULE_RIGHT); }
static double rule_inclusive(const double *x) { return rule_form(x, RULE_MINIMUM_INCLUSIVE); }
static double rule_unclipped(const double *x) { return rule_form(x, RULE_UNCLIPPED); }
static double rule_no_maximum(const double *x) { return rule_form(x, RULE_NO_MAXIMUM); }
static double rule_at_threshold(const double *x) { return rule_form(x, RULE_AT_THRESHOLD); }
static double rule_whole_minimum(const double *x) { return rule_form(x, RULE_WHOLE_MINIMUM); }
static double rule_no_minimum(const double *x) { return rule_form(x, RULE_NO_MINIMUM); }
static double rule_inverted(const double *x) { return rule_form(x, RULE_INVERTED); }

static const WrongAnswer wrong_rule[] = {
    {"nothing at exactly the minimum (samples <= minimum taken for below it, off by one): a "
     "pixel at the minimum never gets a pass",
     "below the minimum means samples < minimum; at it, the threshold decides", rule_inclusive},
    {"a whole pass's worth near the maximum, beyond it",
     "never beyond the maximum: the smaller of the pass's worth and maximum - samples",
     rule_unclipped},
    {"passes beyond the maximum: a pixel at or beyond it still gets samples",
     "nothing once samples >= maximum", rule_no_maximum},
    {"a pass at the threshold exactly (estimate >= threshold taken for above it)",
     "only an estimate above the threshold gets a pass: at it, the pixel has converged",
     rule_at_threshold},
    {"the whole minimum added below it, not what is missing",
     "up to the minimum: minimum - samples", rule_whole_minimum},
    {"the minimum ignored: a pixel below it is judged by the threshold",
     "up to the minimum first, whatever the estimate (the estimate of few samples is not "
     "trusted)",
     rule_no_minimum},
    {"samples where the estimate is at or below the threshold, none above it",
     "a pass where the estimate is above the threshold", rule_inverted},
};

static void grade_rule(Grading *g)
{
    /* {min, max, pass, threshold}: both maxima overshot by the last pass (60 + 8 > 64,
     * 32 + 8 > 36); counts from 0 to beyond the maximum */
    static const double settings[][4] = {{16, 64, 8, 1e-3}, {8, 36, 8, 4e-4}};
    enum {
        COUNTS = 10,
        ESTIMATES = 6,
        POINTS = 2 * COUNTS * ESTIMATES
    };
    double x[RULE_ARITY * POINTS], got[POINTS];
    int wrong = -1;
    for (int k = 0; k < POINTS; k++) {
        const double *s = settings[k / (COUNTS * ESTIMATES)];
        const double counts[COUNTS] = {0,         4,        s[0] - 4, s[0], s[0] + 4,
                                       s[1] - 12, s[1] - 8, s[1] - 4, s[1], s[1] + 4};
        const double estimates[ESTIMATES] = {0.0,      s[3] / 2, s[3], s[3] * (1 + 1e-9),
                                             2 * s[3], 1e6};
        double *p = x + RULE_ARITY * k;
        p[0] = s[0], p[1] = s[1], p[2] = s[2], p[3] = s[3];
        p[4] = counts[k / ESTIMATES % COUNTS], p[5] = estimates[k % ESTIMATES];
        AdaptiveSettings rule = {ADAPTIVE_UNBIASED, (int)p[0], (int)p[1], (int)p[2], p[3]};
        got[k] = ASK(g, adaptive_samples_to_add(&rule, (int)p[4], p[5]));
        if (!grading_probing(g) && wrong < 0 && got[k] != rule_right(p))
            wrong = k;
    }
    if (grading_probing(g))
        return;
    /* the case of the minimum with an estimate above the threshold, and at it */
    int above = 3 * ESTIMATES + 4, at = 3 * ESTIMATES + 2;
    grading_note(g,
                 "%d cases; minimum %g, maximum %g, passes of %g, threshold %g: at the minimum "
                 "with an estimate above the threshold %g (right: %g), at it %g (right: 0)",
                 POINTS, x[0], x[1], x[2], x[3], got[above], rule_right(x + RULE_ARITY * above),
                 got[at]);
    if (wrong < 0)
        return;
    const WrongAnswer *match =
        grading_known_wrong(wrong_rule, COUNT(wrong_rule), x, RULE_ARITY, got, POINTS);
    if (match) {
        grading_fail_known(g, "samples to add", match, POINTS);
        return;
    }
    const double *p = x + RULE_ARITY * wrong;
    const char *why = p[4] < p[0]    ? "below the minimum: minimum - samples"
                      : p[4] >= p[1] ? "at or beyond the maximum: nothing"
                      : p[5] <= p[3] ? "at or below the threshold: nothing"
                                     : "above the threshold: a pass, never beyond the maximum";
    grading_fail(g,
                 "with minimum %g, maximum %g, passes of %g and threshold %g, a pixel of %g "
                 "samples and estimate %.10g gets %g where %g is right (%s)",
                 p[0], p[1], p[2], p[3], p[4], p[5], got[wrong], rule_right(p), why);
}

const Exercise exercises[] = {
    {"10.1", "adaptive_error_estimate",
     "Return the estimated relative MSE of pixel (col, row) of the mean of two independent "
     "half-images `first` and `second` (width x height): over the pixels of the 3 x 3 window "
     "around it that lie inside the image, and the three channels, the mean of ((a - b) / "
     "2)^2 / (m^2 + 0.01), a and b the two half-images' values and m = (a + b) / 2. See "
     "docs/chapter10.md, section 1.",
     "return 0.0;", grade_estimate, NULL, ""},
    {"10.2", "adaptive_samples_to_add",
     "Return the samples to add to a pixel that has `samples`, of estimated relative MSE "
     "`estimate`: below settings->min_samples, what is missing up to it; else, if the "
     "estimate is above settings->threshold and samples < settings->max_samples, "
     "settings->pass_samples but never beyond the maximum; else 0. See docs/chapter10.md, "
     "section 2.",
     "return 0;", grade_rule, NULL, ""},
};
const int exercise_count = sizeof exercises / sizeof exercises[0];
