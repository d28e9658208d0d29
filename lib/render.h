/* render.h (chapter 1): the image as a Monte Carlo estimate, one pixel at a time (report §3.3).
 *
 * Introduced in chapter 1. A pixel's value is the mean of `spp` samples; sample s of
 * pixel p traces one camera ray (camera.h) and asks an estimator for the radiance
 * arriving along it, with its own random generator rng_for_sample(seed, p, s).
 *
 * The estimator is a function, so the same loop serves Whitted (whitted.h) and the
 * path tracer (path.h):
 *     Vec3 estimate(const Scene *, Ray, Rng *, const void *settings, RayCounts *)
 *
 * Samples are taken in passes (pass s takes sample s of every pixel), each pass split
 * among the threads by rows. Each pixel's samples are always accumulated in sample
 * order, so the image is bit-for-bit the same for any thread count. Per pixel we keep
 * the count n of samples, their running mean and M2, their summed squared deviations
 * from it, updated by Welford's method (Welford 1962; Knuth, TAOCP vol. 2, §4.2.2):
 *     delta = x - mean,   mean += delta / n,   M2 += delta (x - mean),
 * so that variance = M2 / (n - 1). (The textbook sum of squares, (sum x^2 - n mean^2) /
 * (n - 1), subtracts two nearly equal large numbers: for a bright pixel of small spread
 * it loses most of its digits, even to a negative variance.) Thus
 *   - a non-finite sample (NaN or infinity) is dropped and counted, never averaged in;
 *   - an interrupted render (SIGINT, see render_install_interrupt) stops after the rows
 *     in progress and is still normalised correctly, pixel by pixel (and unbiased for
 *     sub-pixels too: camera.h visits each pixel's strata from a random start);
 *   - the standard error of every pixel's mean is known, per channel and for the mean of
 *     its three channels (R + G + B) / 3. The latter is kept from the samples' own
 *     channel means, not from the three channels' errors, because the channels of one
 *     sample are strongly correlated (one path carries all three): measure.h's image
 *     mean needs it.
 * A pixel's generator for placing its strata is rng_for_sample(seed, pixel,
 * RENDER_PIXEL_STREAM), a stream no sample uses.
 */
#ifndef RENDER_H
#define RENDER_H

#include "image.h"
#include "rng.h"
#include "scene.h"
#include "stats.h"

typedef Vec3 (*Estimator)(const Scene *scene, Ray ray, Rng *rng, const void *settings,
                          RayCounts *counts);

typedef struct {
    int width, height;
    int spp;
    PixelSampling sampling;
    int threads;    /* 0: one per core */
    uint64_t seed;
    int progress;   /* show progress on stderr (only if it is a terminal) */
    const char *label; /* what the progress line names */
} RenderSettings;

typedef struct {
    Image image;    /* per-pixel mean */
    Image std_error; /* per-pixel standard error of that mean, sqrt(var / n) */
    Image average_std_error; /* grey: per pixel, in all three channels, the standard
                                error of the mean of (R + G + B) / 3 */
    double seconds;
    int threads;
    RayCounts rays;
    uint64_t samples;    /* samples taken (finite or not) */
    uint64_t nonfinite;  /* samples dropped for being NaN or infinite */
    int interrupted;     /* stopped early by SIGINT */
} RenderResult;

/* What one pixel has received so far: for the three channels and their mean (index 3),
 * Welford's running mean and M2 (above) over `finite` values. render() keeps one per
 * pixel of its samples; render_batches.h (chapter 7) of its batches' means. */
typedef struct {
    double mean[4];
    double m2[4];
    uint32_t finite;   /* values averaged in */
} PixelSum;

/* Welford's update with one finite value. */
void pixel_sum_add(PixelSum *pixel, Vec3 radiance);

/* Every pixel's mean and standard errors, sqrt(M2 / (n - 1) / n) (0 for n <= 1), from
 * pixels[width * height] into result's image, std_error and average_std_error, which
 * must already be allocated at that size. */
void pixel_sums_finish(const PixelSum *pixels, RenderResult *result);

/* The sample number of each pixel's own generator (camera_first_stratum). */
#define RENDER_PIXEL_STREAM UINT64_MAX
#if CHAPTER >= 7
/* Mixed with the seed and the pixel into the key of its stratified pairs. */
#define RENDER_STRATA_STREAM 0x5b0b01ULL
#endif

/* Render. Returns 0, or -1 when memory runs out (nothing is then allocated). */
int render(const Scene *scene, const RenderSettings *settings, Estimator estimate,
           const void *estimator_settings, RenderResult *result);

void render_result_free(RenderResult *result);

/* Mean samples per pixel actually taken (less than spp after an interruption). */
double render_samples_per_pixel(const RenderResult *result);

/* From now on, SIGINT asks a running render to stop early instead of killing the
 * program. SIGTERM, SIGHUP and a second SIGINT still end it, as their default action
 * does, but only after removing the temporary files being written (atomic_file.h). */
void render_install_interrupt(void);

/* Whether SIGINT has asked to stop. */
int render_interrupted(void);

/* Number of cores online. */
int render_core_count(void);

#endif
