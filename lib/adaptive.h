/* adaptive.h (chapter 10): render to an error, not to a sample count (beyond the report).
 *
 * Sample s of a pixel goes to quarter s mod 4, each quarter its own independent sequence.
 * The half-images A (quarters 0, 2) and B (1, 3) are independent means of n/2 samples, so
 * E[((A - B) / 2)^2] = Var((A + B) / 2): the error of the pixel, from its own samples,
 * pooled over a 3 x 3 window against heavy tails and divided by value^2 + 0.01 as measure.h's
 * relative MSE. Passes add samples where it is above a threshold. Deciding from the samples
 * that are averaged biases the image (ADAPTIVE_BIASED); deciding from quarters 0 and 2 and
 * keeping B, which the decision never saw, does not (ADAPTIVE_UNBIASED). Means are over the
 * finite samples. docs/chapter10.md.
 */
#ifndef ADAPTIVE_H
#define ADAPTIVE_H

#include "render.h"

typedef enum {
    ADAPTIVE_BIASED,  /* decide from A and B, keep (A + B) / 2 */
    ADAPTIVE_UNBIASED /* decide from quarters 0 and 2 (that is A), keep B */
} AdaptiveRule;

typedef struct {
    Vec3 sum[4];    /* of the finite samples s with s mod 4 = q */
    int samples;    /* taken, finite or not: a multiple of 4 */
    int dropped[4]; /* of quarter q's, NaN or infinite, left out of its sum */
} AdaptivePixel;

typedef struct {
    AdaptiveRule rule;
    int min_samples, max_samples, pass_samples; /* multiples of 4 */
    double threshold;                           /* on a pixel's estimated relative MSE */
} AdaptiveSettings;

/* Exercise 10.1: the estimated relative MSE of pixel (col, row) of the mean of two
 * independent half-images `first` and `second` (width x height): the mean over the 3 x 3
 * window W around it (its pixels inside the image) and the three channels c of
 *     ((first - second) / 2)^2 / (((first + second) / 2)^2 + 0.01). */
double adaptive_error_estimate(const Vec3 *first, const Vec3 *second, int width, int height,
                               int col, int row);

/* Exercise 10.2: the samples to add to a pixel that has `samples`, of estimated relative MSE
 * `estimate`: up to the minimum first; then, while it is above the threshold, a pass's
 * worth, never beyond the maximum; else 0. */
int adaptive_samples_to_add(const AdaptiveSettings *settings, int samples, double estimate);

/* The value the rule keeps: the mean of all samples (biased), of B's (unbiased). */
Vec3 adaptive_pixel_value(const AdaptivePixel *pixel, AdaptiveRule rule);

/* One pass's plan: each pixel's estimate (of the kept value's relative MSE, from the halves
 * the rule decides from) and the samples to add, judged by the largest estimate of the
 * windows it lies in. Returns how many pixels get samples, or
 * -1 when memory runs out. */
long adaptive_plan(const AdaptiveSettings *settings, const AdaptivePixel *pixels, int width,
                   int height, double *estimate, int *to_add);

/* Take to_add[p] more samples of each pixel p of rows first_row .. end_row - 1. A NaN or
 * infinite sample is dropped, as the uniform renderer drops it. Returns how many were. */
uint64_t adaptive_sample_rows(const Scene *scene, const ImageSettings *image,
                              Estimator estimate, const void *estimator_settings,
                              AdaptivePixel *pixels, const int *to_add, int first_row,
                              int end_row, RayCounts *counts);

/* The whole loop on this thread, from pixels all zero: plan, sample, until no pixel gets
 * samples; estimate[] is the last plan's. Returns 0, or -1 when memory runs out. */
int adaptive_render(const Scene *scene, const ImageSettings *image, Estimator estimate,
                    const void *estimator_settings, const AdaptiveSettings *settings,
                    AdaptivePixel *pixels, double *error_estimate, RayCounts *counts);

#endif
