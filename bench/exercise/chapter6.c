/* chapter6.c (bench, chapter 6): chapter 6's exercises and their graders (grading.h).
 *
 * Roulette must keep the expected throughput (docs/chapter6.md, section 1): over
 * 100,000 trials at a fixed seed, the share of paths that go on is compared with the
 * survival probability (a binomial z) and the mean throughput after roulette with the
 * one before (a z from the trials' own spread), both at significance level 0.01
 * (|z| <= 2.58); with roulette off, or before bounded weights start, nothing changes.
 * The survival probability against min(1, max component).
 */
#include <math.h>
#include <stdio.h>

#include "grading.h"
#include "roulette.h"

#define TRIALS 100000
#define Z_LEVEL 2.58 /* two-sided, significance level 0.01 */

/* Roulette at `segment` with `settings` on throughput t, TRIALS times: it must go on
 * with probability `survival` and keep t in expectation. Returns 1 when it does. */
static int roulette_trials(Grading *g, const PathSettings *settings, int segment, Vec3 t,
                           double survival, const char *setting)
{
    double kept = 0.0, sum[3] = {0, 0, 0}, sum2[3] = {0, 0, 0}, before[3] = {t.x, t.y, t.z};
    for (long i = 0; i < TRIALS; i++) {
        Rng rng = rng_for_sample(61, (uint64_t)segment, (uint64_t)i);
        Vec3 after = t;
        int goes_on = ASK(g, roulette_continues(settings, segment, &after, &rng)) != 0.0;
        if (goes_on)
            after = grading_ask_vec3(g, after);
        double v[3] = {after.x, after.y, after.z};
        kept += goes_on != 0;
        for (int c = 0; c < 3; c++) {
            double x = goes_on ? v[c] : 0.0;
            if (grading_not_finite(g, x, "the throughput after roulette"))
                return 0;
            sum[c] += x;
            sum2[c] += x * x;
        }
    }
    double share = kept / TRIALS;
    double share_se = sqrt(fmax(survival * (1.0 - survival), 1.0 / TRIALS) / TRIALS);
    double mean = sum[1] / TRIALS, var = sum2[1] / TRIALS - mean * mean;
    double se = sqrt(fmax(var, 0.0) / TRIALS);
    double mean_z = se > 0.0 ? (mean - before[1]) / se : (mean == before[1] ? 0.0 : INFINITY);
    grading_note(g,
                 "%s: %.4f of the paths go on (%.4f expected), mean throughput after %.4f "
                 "+- %.4f where it was %.4f before",
                 setting, share, survival, mean, se, before[1]);
    if (fabs(share - survival) / share_se > Z_LEVEL)
        return grading_fail(g,
                            "%s: %.1f%% of the paths go on where the survival probability "
                            "is %.1f%%",
                            setting, 100.0 * share, 100.0 * survival);
    if (fabs(mean_z) > Z_LEVEL) {
        double ratio = mean / before[1];
        return grading_fail(g,
                            "%s: the throughput after roulette is on average %.3f times what "
                            "it was (z = %.1f): %s",
                            setting, ratio, mean_z,
                            fabs(ratio - survival) < 0.02
                                ? "the survivors are not divided by the survival probability, "
                                  "so energy is lost (the image darkens)"
                                : "roulette must keep the expected throughput: a survivor "
                                  "carries throughput / survival");
    }
    for (int c = 0; c < 3; c++)
        if (fabs(sum[c] / TRIALS - before[c]) > 0.05 * before[c] + 6.0 * se)
            return grading_fail(g,
                                "%s: channel %d's throughput changes on average from %.4f to "
                                "%.4f: every channel is divided by the same probability",
                                setting, c, before[c], sum[c] / TRIALS);
    return 1;
}

static void grade_continues(Grading *g)
{
    Vec3 t = vec3(0.3, 0.5, 0.2);
    PathSettings alpha = {.max_depth = 10, .rr_survival = 0.6};
    PathSettings bounded = {.max_depth = 10, .rr_throughput = 2};
    PathSettings off = {.max_depth = 10};
    if (!roulette_trials(g, &alpha, 3, t, 0.6, "alpha = 0.6") ||
        !roulette_trials(g, &bounded, 3, t, 0.5,
                         "bounded weights from segment 2, at segment 3 "
                         "with throughput (0.3, 0.5, 0.2)") ||
        !roulette_trials(g, &bounded, 2, t, 0.5,
                         "bounded weights from segment 2, at segment 2 "
                         "with throughput (0.3, 0.5, 0.2)") ||
        !roulette_trials(g, &bounded, 1, t, 1.0,
                         "bounded weights from segment 2, at segment 1") ||
        !roulette_trials(g, &off, 3, t, 1.0, "no roulette (rr_survival 0, rr_throughput 0)"))
        return;
}

static void grade_survival(Grading *g)
{
    const Vec3 throughputs[] = {
        {0.3, 0.5, 0.2}, {2.0, 0.1, 0.1}, {0.1, 0.05, 0.9}, {0.0, 0.0, 0.0}, {0.7, 0.7, 0.7}};
    for (int i = 0; i < (int)(sizeof throughputs / sizeof throughputs[0]) && !g->failed; i++) {
        Vec3 t = throughputs[i];
        double got = ASK(g, roulette_survival_from_throughput(t));
        double want = fmin(1.0, vec3_max_component(t));
        grading_note(g, "throughput (%.2f, %.2f, %.2f): survival %.4f; min(1, max) = %.4f", t.x,
                     t.y, t.z, got, want);
        if (grading_not_finite(g, got, "the survival probability") || fabs(got - want) <= 1e-12)
            continue;
        if (got > 1.0)
            grading_fail(g,
                         "survival %.3f > 1 for throughput (%.2f, %.2f, %.2f): a probability "
                         "is at most 1 (min(1, ...))",
                         got, t.x, t.y, t.z);
        else if (fabs(got - (t.x + t.y + t.z) / 3.0) <= 1e-12)
            grading_fail(g,
                         "survival %.3f for throughput (%.2f, %.2f, %.2f) is the channels' "
                         "mean; the largest channel bounds the weight",
                         got, t.x, t.y, t.z);
        else
            grading_fail(g,
                         "survival %.*f for throughput (%.2f, %.2f, %.2f), where min(1, max "
                         "component) = %.*f",
                         grading_decimals(got, want), got, t.x, t.y, t.z,
                         grading_decimals(got, want), want);
    }
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
