/* chapter6.c (bench, chapter 6): chapter 6's exercises and their graders (grading.h).
 *
 * Roulette keeps the expected throughput (docs/chapter6.md, section 1): over 100,000 to
 * 4,200,000 trials per setting, every survivor carries exactly the throughput before / q
 * (known wrong forms named), and the share going on is q, at the course's level
 * (grading.h) paired with the solution's decision from the same random number, as a
 * binomial share (any valid drawing) and over replicates of generators whose first numbers
 * are stratified (any rule on one number); with roulette off, or before bounded weights
 * start, nothing changes. The survival probability against min(1, max component), with a
 * catalogue of known wrong ones.
 */
#include <math.h>
#include <stdio.h>

#include "grading.h"
#include "roulette.h"

#define TRIALS 100000
#define BOUNDED_TRIALS 500000 /* q = 0.5: its share to 1.1 % for any drawing at all */
#define ALPHA_TRIALS 4200000  /* alpha = 0.6: its share to 0.3 % for any valid drawing */
/* The share's replicate test: replicates of one generator per cell of [0, 1). */
#define SHARE_REPLICATES 64
#define SHARE_CELLS 509 /* prime: neither q = 0.5 nor 0.6 falls on a cell's edge */
#define COUNT(list) (int)(sizeof list / sizeof list[0])

/* What a survivor's throughput can be, for throughput t and survival probability q. */
enum {
    SURVIVOR_RIGHT,
    SURVIVOR_UNCHANGED,
    SURVIVOR_TIMES,
    SURVIVOR_BY_END,
    SURVIVOR_FORMS
};
static const char *const survivor_words[SURVIVOR_FORMS] = {
    "",
    "the throughput unchanged: the survivors are not divided by the survival probability, "
    "so energy is lost (the image darkens by that probability at each roulette)",
    "the throughput times the survival probability, where it is divided by it",
    "the throughput divided by the probability of ending, 1 - q, where the survival "
    "probability q belongs"};

static Vec3 survivor_form(int form, Vec3 t, double q)
{
    switch (form) {
    case SURVIVOR_RIGHT:
        return vec3_scale(t, 1.0 / q);
    case SURVIVOR_UNCHANGED:
        return t;
    case SURVIVOR_TIMES:
        return vec3_scale(t, q);
    default:
        return vec3_scale(t, 1.0 / (1.0 - q));
    }
}

static int same_colour(Vec3 a, Vec3 b)
{
    return fabs(a.x - b.x) <= 1e-12 * fabs(b.x) && fabs(a.y - b.y) <= 1e-12 * fabs(b.y) &&
           fabs(a.z - b.z) <= 1e-12 * fabs(b.z);
}

/* What a share of paths going on other than the survival probability q means: the
 * complement (unless q is near 1/2, where both are alike), never, or a rule that is off. */
static const char *share_meaning(double share, double survival)
{
    if (fabs(share - (1.0 - survival)) < 0.01 && fabs(survival - 0.5) > 0.02)
        return "the path ends with probability q, where q is the probability that it goes "
               "on (the report's erratum: alpha is the survival probability)";
    if (share == 1.0)
        return "roulette never ends a path here";
    return share > survival
               ? "too many paths go on: a path goes on exactly when a uniform number is "
                 "below q itself (roulette_survives)"
               : "too few paths go on: a path goes on exactly when a uniform number is below "
                 "q itself (roulette_survives)";
}

/* Roulette at `segment` with `settings` on throughput t, TRIALS times: it must go on
 * with probability `survival`, a survivor carrying t / survival. Returns 1 when it does. */
static int roulette_trials(Grading *g, long trials, const PathSettings *settings, int segment,
                           Vec3 t, double survival, const char *setting)
{
    long kept = 0, forms[SURVIVOR_FORMS] = {0};
    double dsum = 0.0, dsum2 = 0.0;
    Vec3 first_wrong = t;
    for (long i = 0; i < trials; i++) {
        Rng rng = rng_for_sample(grading_stream(g, 61), (uint64_t)segment, (uint64_t)i);
        Rng again = rng;
        Vec3 after = t;
        int goes_on = ASK(g, roulette_continues(settings, segment, &after, &rng)) != 0.0;
        if (goes_on) /* an ended path's throughput is never read */
            after = grading_ask_vec3(g, after);
        if (grading_probing(g))
            continue;
        /* the solution's decision from the same number */
        int right_goes_on = survival >= 1.0 || rng_uniform(&again) < survival;
        dsum += goes_on - right_goes_on;
        dsum2 += (goes_on - right_goes_on) * (goes_on - right_goes_on);
        if (!goes_on)
            continue;
        kept++;
        if (grading_not_finite(g, after.x + after.y + after.z,
                               "a survivor's throughput after roulette"))
            return 0;
        int matched = 0;
        for (int f = 0; f < SURVIVOR_FORMS; f++)
            if (same_colour(after, survivor_form(f, t, fmin(survival, 1.0))) && !matched) {
                forms[f]++;
                matched = 1;
            }
        if (!matched && same_colour(first_wrong, t))
            first_wrong = after;
    }
    if (grading_probing(g))
        return 1;
    double n = (double)trials, share = kept / n;
    double share_se = sqrt(fmax(survival * (1.0 - survival), 1.0 / n) / n);
    double dmean = dsum / n, dse = sqrt(fmax(0.0, dsum2 / n - dmean * dmean) / n);
    double share_z = (share - survival) / share_se;
    double paired_z = dse > 0.0 ? dmean / dse : (dmean == 0.0 ? 0.0 : INFINITY);
    double limit = grading_z(grading_level());
    grading_note(g,
                 "%s: %.5f of the paths go on (%.4f expected, z = %+.1f; paired with the "
                 "solution's decision from the same number: %+.5f, z = %+.1f; limit %.2f; "
                 "detectable %.2g%% of the share, exact when paired)",
                 setting, share, survival, share_z, dmean, paired_z, limit,
                 100.0 * grading_detectable(share_se) / survival);
    if (survival >= 1.0 && kept < trials)
        return grading_fail(g,
                            "%s: %.2f%% of the paths end where none may (the survival "
                            "probability is 1: no roulette)",
                            setting, 100.0 * (1.0 - share));
    if (fabs(share_z) > limit || fabs(paired_z) > limit)
        return grading_fail(g,
                            "%s: %.2f%% of the paths go on where the survival probability "
                            "is %.1f%%: %s",
                            setting, 100.0 * share, 100.0 * survival,
                            share_meaning(share, survival));
    if (forms[SURVIVOR_RIGHT] == kept)
        return 1;
    for (int f = 1; f < SURVIVOR_FORMS; f++)
        if (forms[f] == kept)
            return grading_fail(g, "%s: every survivor carries %s", setting, survivor_words[f]);
    if (survival >= 1.0)
        return grading_fail(g,
                            "%s: the throughput changes from (%.3f, %.3f, %.3f) to (%.4f, "
                            "%.4f, %.4f) where there is no roulette: leave it as it is",
                            setting, t.x, t.y, t.z, first_wrong.x, first_wrong.y,
                            first_wrong.z);
    Vec3 right = vec3_scale(t, 1.0 / survival);
    return grading_fail(g,
                        "%s: %ld of %ld survivors carry a throughput other than (%.4f, %.4f, "
                        "%.4f) = the one before / %.2f, e.g. (%.4f, %.4f, %.4f): every channel "
                        "is divided by the same survival probability",
                        setting, kept - forms[SURVIVOR_RIGHT], kept, right.x, right.y, right.z,
                        survival, first_wrong.x, first_wrong.y, first_wrong.z);
}

/* Replicate `replicate` of a setting's stratified generators: SHARE_CELLS generators whose
 * first numbers lie one in each of SHARE_CELLS equal cells of [0, 1), found by drawing
 * generators until every cell holds one. */
static void stratified_generators(Grading *g, int setting, int replicate, Rng *generators)
{
    char taken[SHARE_CELLS] = {0};
    uint64_t key = (uint64_t)setting * SHARE_REPLICATES + (uint64_t)replicate;
    for (uint64_t j = 0, filled = 0; filled < SHARE_CELLS; j++) {
        Rng rng = rng_for_sample(grading_stream(g, 62), key, j), look = rng;
        int cell = (int)(rng_uniform(&look) * SHARE_CELLS);
        if (!taken[cell]) {
            taken[cell] = 1;
            generators[cell] = rng;
            filled++;
        }
    }
}

/* The share going on, over SHARE_REPLICATES replicates of stratified generators, against
 * q by a replicate test: a decision drawn from the generator's first number, as any rule
 * "goes on when u is below (or above) a threshold" draws it, then lands within one cell of
 * q in every replicate, so that a share off by far less than one independent trial's
 * noise shows. Returns 1 when it passes. */
static int roulette_share_replicates(Grading *g, int setting, const PathSettings *settings,
                                     int segment, Vec3 t, double survival, const char *words)
{
    Rng generators[SHARE_CELLS];
    double shares[SHARE_REPLICATES];
    for (int r = 0; r < SHARE_REPLICATES; r++) {
        stratified_generators(g, setting, r, generators);
        long kept = 0;
        for (int cell = 0; cell < SHARE_CELLS; cell++) {
            Vec3 after = t;
            kept +=
                ASK(g, roulette_continues(settings, segment, &after, &generators[cell])) != 0.0;
        }
        shares[r] = (double)kept / SHARE_CELLS;
    }
    if (grading_probing(g))
        return 1;
    char what[160];
    snprintf(what, sizeof what, "%s: the share going on over %d stratified generators", words,
             SHARE_CELLS);
    double mean = 0.0;
    for (int r = 0; r < SHARE_REPLICATES; r++)
        mean += shares[r] / SHARE_REPLICATES;
    return grading_replicate_test(g, what, shares, SHARE_REPLICATES, survival,
                                  share_meaning(mean, survival));
}

static void grade_continues(Grading *g)
{
    Vec3 t = vec3(0.3, 0.5, 0.2);
    PathSettings alpha = {.max_depth = 10, .rr_survival = 0.6};
    PathSettings bounded = {.max_depth = 10, .rr_throughput = 2};
    PathSettings off = {.max_depth = 10};
    const char *at_3 = "bounded weights from segment 2, at segment 3 with throughput (0.3, "
                       "0.5, 0.2)",
               *at_2 = "bounded weights from segment 2, at segment 2 with throughput (0.3, "
                       "0.5, 0.2)";
    if (!roulette_trials(g, ALPHA_TRIALS, &alpha, 3, t, 0.6, "alpha = 0.6") ||
        !roulette_trials(g, BOUNDED_TRIALS, &bounded, 3, t, 0.5, at_3) ||
        !roulette_trials(g, BOUNDED_TRIALS, &bounded, 2, t, 0.5, at_2) ||
        !roulette_trials(g, TRIALS, &bounded, 1, t, 1.0,
                         "bounded weights from segment 2, at segment 1") ||
        !roulette_trials(g, TRIALS, &off, 3, t, 1.0,
                         "no roulette (rr_survival 0, rr_throughput 0)"))
        return;
    if (!roulette_share_replicates(g, 0, &alpha, 3, t, 0.6, "alpha = 0.6") ||
        !roulette_share_replicates(g, 1, &bounded, 3, t, 0.5, at_3))
        return;
    roulette_share_replicates(g, 2, &bounded, 2, t, 0.5, at_2);
}

/* The survival probability's inputs: the throughput's r, g, b. */
static double survival_right(const double *x)
{
    return fmin(1.0, fmax(x[0], fmax(x[1], x[2])));
}
static double survival_mean(const double *x) { return fmin(1.0, (x[0] + x[1] + x[2]) / 3.0); }
static double survival_min(const double *x) { return fmin(1.0, fmin(x[0], fmin(x[1], x[2]))); }
static double survival_sum(const double *x) { return fmin(1.0, x[0] + x[1] + x[2]); }
static double survival_luminance(const double *x)
{
    return fmin(1.0, 0.2126 * x[0] + 0.7152 * x[1] + 0.0722 * x[2]);
}
static double survival_green(const double *x) { return fmin(1.0, x[1]); }
static double survival_unbounded(const double *x) { return fmax(x[0], fmax(x[1], x[2])); }
static double survival_ending(const double *x) { return fmax(0.0, 1.0 - survival_right(x)); }

static const WrongAnswer wrong_survival[] = {
    {"min(1, the channels' mean)",
     "the largest channel bounds the weight: min(1, max component) (vec3_max_component)",
     survival_mean},
    {"min(1, the smallest channel)",
     "the largest channel bounds the weight: the survivor's throughput / q <= 1 in every "
     "channel only for q = the largest",
     survival_min},
    {"min(1, the channels' sum)", "the largest channel, not the sum", survival_sum},
    {"min(1, the luminance)", "the largest channel bounds the weight, not the luminance",
     survival_luminance},
    {"min(1, the green channel)", "the largest of the three channels", survival_green},
    {"the largest channel without min(1, ...), above 1 for bright throughputs",
     "a probability is at most 1: min(1, max component)", survival_unbounded},
    {"1 - min(1, max component), the probability of ending",
     "the probability of going on: min(1, max component)", survival_ending},
};

static void grade_survival(Grading *g)
{
    const double throughputs[][3] = {{0.3, 0.5, 0.2}, {2.0, 0.1, 0.1},   {0.1, 0.05, 0.9},
                                     {0.0, 0.0, 0.0}, {0.7, 0.7, 0.7},   {0.05, 0.6, 0.3},
                                     {1.5, 3.0, 0.2}, {0.02, 0.01, 0.04}};
    enum {
        POINTS = sizeof throughputs / sizeof throughputs[0]
    };
    double got[POINTS];
    int wrong = -1;
    for (int i = 0; i < POINTS; i++) {
        const double *t = throughputs[i];
        got[i] = ASK(g, roulette_survival_from_throughput(vec3(t[0], t[1], t[2])));
        grading_note(g, "throughput (%.2f, %.2f, %.2f): survival %.4f; min(1, max) = %.4f",
                     t[0], t[1], t[2], got[i], survival_right(t));
        if (grading_not_finite(g, got[i], "the survival probability"))
            return;
        if (wrong < 0 && !(fabs(got[i] - survival_right(t)) <= 1e-12))
            wrong = i;
    }
    if (wrong < 0)
        return;
    const WrongAnswer *match = grading_known_wrong(wrong_survival, COUNT(wrong_survival),
                                                   &throughputs[0][0], 3, got, POINTS);
    if (match) {
        grading_fail_known(g, "survival probability", match, POINTS);
        return;
    }
    const double *t = throughputs[wrong];
    double want = survival_right(t);
    if (got[wrong] > 1.0)
        grading_fail(g,
                     "survival %.3f > 1 for throughput (%.2f, %.2f, %.2f): a probability "
                     "is at most 1 (min(1, ...))",
                     got[wrong], t[0], t[1], t[2]);
    else
        grading_fail(g,
                     "survival %.*f for throughput (%.2f, %.2f, %.2f), where min(1, max "
                     "component) = %.*f (%.4g times that): a survivor's throughput / q must "
                     "stay at most 1 in every channel",
                     grading_decimals(got[wrong], want), got[wrong], t[0], t[1], t[2],
                     grading_decimals(got[wrong], want), want, got[wrong] / want);
}

const Exercise exercises[] = {
    {"6.1", "roulette_continues",
     "Roulette at a diffuse vertex on `segment`: the survival probability is "
     "settings->rr_survival, or with bounded weights (settings->rr_throughput = k > 0) "
     "roulette_survival_from_throughput(*throughput) from segment k on and 1 before; with a "
     "probability not strictly between 0 and 1 there is no roulette (return 1); else the path "
     "ends (return 0) unless roulette_survives, and a survivor's throughput is divided by the "
     "probability (return 1). See docs/chapter6.md, sections 1 and 4.",
     "return 1;", grade_continues, NULL, "6.2"},
    {"6.2", "roulette_survival_from_throughput",
     "Return the bounded-weight survival probability min(1, largest component of the "
     "throughput) (vec3_max_component). See docs/chapter6.md, section 4.",
     "return 1.0;", grade_survival, NULL, ""},
};
const int exercise_count = sizeof exercises / sizeof exercises[0];
