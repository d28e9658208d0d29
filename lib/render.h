/* render.h (chapter 1): the image as a Monte Carlo estimate (report §3.3).
 *
 * A pixel's value is the mean of spp samples. A sample traces one camera ray and asks an
 * estimator, a function, for the radiance arriving along it, counting the rays it
 * traces. Whitted's (whitted.h) is the first estimator.
 */
#ifndef RENDER_H
#define RENDER_H

#include <stdint.h>

#include "scene.h"
#if CHAPTER >= 2
#include "pixel_sampling.h"
#include "rng.h"
#endif
#if CHAPTER >= 8
#include "sobol.h" /* PIXEL_PROGRESSIVE's positions */
#endif

/* Rays traced, by purpose: camera, bounce (a path continues), shadow (towards a light). */
typedef struct {
    uint64_t camera, bounce, shadow;
} RayCounts;

#if CHAPTER >= 2
/* rng: the sample's own generator, rng_for_sample(seed, pixel, sample). */
typedef Vec3 (*Estimator)(const Scene *scene, Ray ray, Rng *rng, const void *settings,
                          RayCounts *counts);
#else
typedef Vec3 (*Estimator)(const Scene *scene, Ray ray, const void *settings, RayCounts *counts);
#endif

typedef struct {
    int width, height;
    int spp; /* samples per pixel */
#if CHAPTER >= 2
    PixelSampling sampling; /* where in its pixel each sample looks */
    uint64_t seed;
#endif
} ImageSettings;

/* Sample `sample` of pixel (col, row): the radiance that estimate() brings back along
 * the sample's camera ray. */
Vec3 render_sample(const Scene *scene, const ImageSettings *image, int col, int row, int sample,
                   Estimator estimate, const void *settings, RayCounts *counts);

/* The whole image, row by row from the top: pixels[row * width + col] is the mean of
 * the pixel's spp samples, kept as a running mean (mean += (x - mean) / n after n). */
void render_image(const Scene *scene, const ImageSettings *image, Estimator estimate,
                  const void *settings, Vec3 *pixels, RayCounts *counts);

#endif
