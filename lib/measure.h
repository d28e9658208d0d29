/* measure.h (chapter 2): how far an image is from the truth, and the reference that stands for it
 * (SPEC §6).
 *
 * Introduced in chapter 2. The truth is unknown, so each experiment renders a reference:
 * the same scene and quantity at many more samples, usually with a lower-variance
 * estimator of the same expectation (the path tracer with shadow rays stands in for the
 * one without: both estimate the same integral, path.h). A reference is rendered once
 * and cached in build/references/, named by a 64-bit FNV-1a hash of the scene file's
 * bytes and of a text describing everything that changes its pixels (estimator
 * settings, size, samples, seed).
 *
 * Its own noise is printed beside it: the RMS over pixels and channels of its per-pixel
 * standard errors. An image's RMSE cannot be trusted below about that level.
 *
 * Errors, over all pixels and the three channels (N values):
 *     RMSE    = sqrt( sum (x - r)^2 / N )
 *     rel_MSE = sum (x - r)^2 / (r^2 + 0.01) / N
 * (the 0.01 keeps black pixels from dominating the relative error).
 */
#ifndef MEASURE_H
#define MEASURE_H

#include <stddef.h>
#include <stdint.h>

#include "image.h"
#include "table.h"

typedef struct {
    Image image;
    Image std_error;
    double noise;   /* RMS of std_error: the reference's own standard error */
    double spp;
    double seconds; /* how long it took to render (when it was rendered) */
    int cached;     /* read from the cache rather than rendered now */
} Reference;

/* FNV-1a over `size` bytes, continuing from `hash` (start with MEASURE_HASH_START). */
#define MEASURE_HASH_START 0xcbf29ce484222325ULL
uint64_t measure_hash(uint64_t hash, const void *data, size_t size);

/* RMSE and relative MSE of image against reference (same size). */
void measure_error(const Image *image, const Image *reference, double *rmse, double *rel_mse);

/* Root mean square over all pixels and channels. */
double measure_rms(const Image *image);

/* The mean over all pixels and channels of an image of per-pixel means, and the
 * standard error of that mean from the per-pixel standard errors (pixels are
 * independent: se = sqrt(sum se_i^2) / N). */
void measure_image_mean(const Image *image, const Image *std_error, double *mean,
                        double *mean_std_error);

/* Fill a table row's error columns from an image and the reference. */
void measure_fill_row(TableRow *row, const Image *image, const Reference *reference);

/* Load a cached reference "DIR/HASH.pfm" with its "DIR/HASH-stderr.pfm" and "DIR/HASH.txt"
 * (spp and seconds), both images width x height. Returns 0, or -1 when it is not there,
 * unreadable, or of another size. */
int measure_load_reference(const char *directory, uint64_t key, int width, int height,
                           Reference *reference);

/* Store one: the two images, then the .txt that completes the entry. Returns 0, or -1
 * with errno set and nothing of the entry left behind. */
int measure_save_reference(const char *directory, uint64_t key, const Reference *reference);

void measure_reference_free(Reference *reference);

#endif
