/* renderer.h (bench, chapter 1): the whole image, on every core: each pixel the mean of
 * its samples (render_sample, lib/render.h), with its standard error.
 *
 * Pass j takes one sample of every pixel (sample j, or on sub-pixels the one
 * sample_order.h chooses, so that a stopped render is unbiased), split among threads by
 * rows; a pixel's samples are accumulated in order, so the image is the same bit for bit
 * for any thread count. Per pixel the running mean and M2 (the summed squared deviations)
 * follow Welford's update, delta = x - mean, mean += delta / n, M2 += delta (x - mean),
 * which loses no digits where the sum of squares would. A non-finite sample is dropped
 * and counted. SIGINT stops a render after the rows in progress, still normalised.
 */
#ifndef RENDERER_H
#define RENDERER_H

#include <sys/types.h>

#include "image.h"
#include "render.h"
#include "stats.h"

typedef struct {
    ImageSettings image; /* size, samples per pixel, where they look, seed */
    int threads;         /* 0: one per core */
    int progress;        /* show progress on stderr (only if it is a terminal) */
    const char *label;   /* what the progress line names */
} RenderSettings;

typedef struct {
    Image image;             /* per-pixel mean */
    Image std_error;         /* per-pixel standard error of that mean, sqrt(var / n) */
    Image average_std_error; /* grey: per pixel, in all three channels, the standard
                                error of the mean of (R + G + B) / 3 */
    double seconds;
    int threads;
    RayCounts rays;
    uint64_t samples;   /* samples taken (finite or not) */
    uint64_t nonfinite; /* samples dropped for being NaN or infinite */
    int interrupted;    /* stopped early by SIGINT */
} RenderResult;

/* What one pixel has received so far: for the three channels and their mean (index 3),
 * Welford's running mean and M2 (above) over `finite` values. render() keeps one per
 * pixel of its samples; render_batches.h (chapter 7) of its batches' means. */
typedef struct {
    double mean[4];
    double m2[4];
    uint32_t finite; /* values averaged in */
} PixelSum;

/* Welford's update with one finite value. */
void pixel_sum_add(PixelSum *pixel, Vec3 radiance);

/* Every pixel's mean and standard errors, sqrt(M2 / (n - 1) / n) (0 for n <= 1), from
 * pixels[width * height] into result's image, std_error and average_std_error, which
 * must already be allocated at that size. */
void pixel_sums_finish(const PixelSum *pixels, RenderResult *result);

/* Render. Returns 0, or -1 when memory runs out (nothing is then allocated). */
int render(const Scene *scene, const RenderSettings *settings, Estimator estimate,
           const void *estimator_settings, RenderResult *result);

/* The lesson's own loop, render_image (lib/render.h), on this thread: the same image as
 * render() bit for bit (bench/tests/test_render.c) while no sample is NaN or infinite
 * (render_image keeps them) and the placement is not on sub-pixels (render() takes their
 * samples in another order, sample_order.h). The standard errors are left 0. Returns 0,
 * or -1 when memory runs out. */
int render_serial(const Scene *scene, const RenderSettings *settings, Estimator estimate,
                  const void *estimator_settings, RenderResult *result);

/* Render samples first_sample .. first_sample + spp - 1 of every pixel (render: from 0),
 * as one of several renders that continue each other (PIXEL_PROGRESSIVE; on sub-pixels,
 * first_sample + the sample sample_order.h chooses). */
int render_from(const Scene *scene, const RenderSettings *settings, int first_sample,
                Estimator estimate, const void *estimator_settings, RenderResult *result);

void render_result_free(RenderResult *result);

/* Mean samples per pixel actually taken (less than spp after an interruption). */
double render_samples_per_pixel(const RenderResult *result);

/* From now on, SIGINT asks a running render to stop early instead of killing the
 * program. SIGTERM, SIGHUP and a second SIGINT still end it, as their default action
 * does, but only after removing the temporary files being written (atomic_file.h). */
void render_install_interrupt(void);

/* Hold back (hold = 1) or let through (0) SIGINT, SIGTERM and SIGHUP in this thread:
 * held while a child is started, so that none comes before it is known. */
void render_hold_signals(int hold);

/* A child process renders for this program (the reference renderer): from now on
 * SIGINT, SIGTERM and SIGHUP are passed on to it (a second ending one as SIGKILL), and
 * one that ends this program does so only at render_end_deferred, once the child has
 * ended and the caller has cleaned up. A SIGINT that came before is passed on now.
 * child 0: no child yet, only the deferral (while a temporary folder exists). */
void render_forward_signals(pid_t child);

/* Wait for that child: its exit status, 128 + the signal that ended it, or -1 if it
 * cannot be waited for. Signals are no longer passed on to it. */
int render_wait_for_child(void);

/* If a signal that ends the program came while the child ran, end the program now (as
 * that signal does); else go on, ending signals again ending it at once. */
void render_end_deferred(void);

/* Whether SIGINT has asked to stop. */
int render_interrupted(void);

/* Number of cores online. */
int render_core_count(void);

#endif
