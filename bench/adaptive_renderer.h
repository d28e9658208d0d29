/* adaptive_renderer.h (bench, chapter 10): chapter 10's passes (lib/adaptive.h) on every
 * core, until an error or a time is reached.
 *
 * Each pass plans on one thread (adaptive_plan), then the threads take rows and add each
 * pixel's samples (adaptive_sample_rows); a pixel's samples depend only on the seed, the
 * pixel and their numbers, so the image is the same for any thread count. The passes end
 * when no pixel is above the threshold, when the image's estimated relative RMSE,
 * sqrt(mean over pixels of the estimate), is at most the target, when the wall-clock time
 * is up, or at SIGINT (after the pass in progress).
 */
#ifndef ADAPTIVE_RENDERER_H
#define ADAPTIVE_RENDERER_H

#include "adaptive.h"
#include "renderer.h"

typedef struct {
    AdaptiveSettings rule; /* its threshold: target_error^2 if a target is given; without
                              one, each pass's image mean of the estimates, so that the
                              pixels above the mean get the samples */
    double target_error;   /* the image's estimated relative RMSE to stop at; 0: none */
    double time_limit;     /* wall-clock seconds; 0: none */
} AdaptiveGoal;

typedef struct {
    RenderResult render;       /* the kept image; time (wall), rays, samples (and
                                  those dropped), threads */
    Image samples;             /* grey: each pixel's samples */
    Image error;               /* grey: each pixel's estimated relative RMSE */
    double estimated_rel_rmse; /* of the image, when the passes ended */
    double cpu_seconds;        /* processor time, all threads together */
    int passes;
} AdaptiveResult;

/* Render (settings: size, seed, threads, progress, the samples' placement). Returns 0, or
 * -1 when memory runs out (nothing is then allocated). */
int adaptive_renderer_run(const Scene *scene, const RenderSettings *settings,
                          Estimator estimate, const void *estimator_settings,
                          const AdaptiveGoal *goal, AdaptiveResult *result);

void adaptive_result_free(AdaptiveResult *result);

#endif
