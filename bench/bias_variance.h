/* bias_variance.h (bench, chapter 8): a setting's error split into bias and variance, from
 * K images of independent seeds and two references of independent seeds, and the table of
 * such settings (docs/chapter8.md). For the K images, V is the mean over values (pixels and
 * channels) of their sample variance: one image's variance. Their mean X has error
 * X - T = b + e (bias b, noise e of variance V / K), each reference R_j - T = n_j, and
 * E[(X - R_1)(X - R_2)] = b^2 + V / K: the references' noise drops out of the product. So
 * bias^2 is the mean of that product minus V / K, and one image's mean squared error is
 * bias^2 + V.
 */
#ifndef BIAS_VARIANCE_H
#define BIAS_VARIANCE_H

#include <stdio.h>

#include "image.h"

typedef struct {
    double seconds, cpu;              /* wall-clock and processor time, means over the images */
    double rmse, rmse_low, rmse_high; /* against the first reference, over the whole image:
                                         mean, lowest and highest of the images */
    double error;                     /* sqrt(max(bias^2, 0) + variance) */
    double bias2, variance;           /* means over the values left in */
} BiasVariance;

/* The K images of one setting as they are added. */
typedef struct {
    double *sum, *sum_squares;     /* per value */
    const unsigned char *left_out; /* per pixel, 1: left out of bias^2 and variance */
    long values;
    int count;
    double rmse_sum, rmse_low, rmse_high, seconds, cpu;
} SeedImages;

/* Start for width x height images, leaving out the pixels marked in left_out (kept, not
 * copied; NULL: none). Returns 0, or -1 when memory runs out. */
int seed_images_begin(SeedImages *seeds, int width, int height, const unsigned char *left_out);

/* Add one image, its times, and its RMSE against `reference` (measure_error). */
void seed_images_add(SeedImages *seeds, const Image *image, double seconds, double cpu,
                     const Image *reference);

/* Bias^2, variance and the rest from K >= 2 images and the two references, and free the
 * sums. NaN where no value is left in. */
void seed_images_finish(SeedImages *seeds, const Image *reference_1, const Image *reference_2,
                        BiasVariance *result);

/* The pixels brighter than `threshold` in a channel, and their eight neighbours: one byte
 * per pixel, 1 where marked, *marked of them; NULL when memory runs out. */
unsigned char *bias_variance_bright_mask(const Image *image, double threshold, int *marked);

/* One row of the table: a setting and its error. */
typedef struct {
    char estimator[24];
    int spp, photons, passes; /* samples per pixel (per pass for the photon map) */
    double radius, alpha;     /* the photon map's first radius and alpha (0: none) */
    BiasVariance error;
} SettingError;

/* The table, aligned for a reader. */
void bias_variance_print(FILE *out, const SettingError *rows, int count);

/* The table as CSV through an atomic file. Returns 0, or -1 with errno set. */
int bias_variance_write_csv(const char *path, const SettingError *rows, int count);

#endif
