/* ppm.h (bench, chapter 8): rendering with progressive photon mapping, pass by pass
 * (Knaus and Zwicker 2011), on every core.
 *
 * Pass i shoots fresh photon maps (photon.h: the caustic map and the split one, of the
 * same photons) on the threads, renders the image with them (path_caustics.h) at radius
 * ppm_radius(r_1, alpha, i), and the result is the mean of the pass images. Each pass's photons
 * and camera samples have their own seeds, derived from the render's seed and the pass number,
 * so the image is the same for any thread count; the spread between the independent passes
 * gives each pixel's standard error. A budget of processor time can end the passes
 * (docs/chapter8.md).
 */
#ifndef PPM_H
#define PPM_H

#include "error_estimate.h"
#include "path_caustics.h"
#include "photon_estimate.h"
#include "renderer.h"

/* The first radius on an 800-pixel-wide image, as a fraction of the view's width where
 * the camera looks (ppm_first_radius), scaled by 800 / width for other widths: chapter
 * 8's, the lab's and the tests' (docs/chapter8.md: how it was chosen). */
#define PPM_FIRST_RADIUS_AT_800 0.0034

typedef struct {
    PathSettings path;   /* the path tracer's settings (its fresnel also for photons) */
    int photons;         /* emitted per pass */
    double radius;       /* r_1 */
    double alpha;        /* of the radius schedule */
    int spp;             /* camera samples per pixel per pass */
    int passes;          /* passes to render */
    double cpu_seconds;  /* > 0: a budget of processor time (stats_cpu_now): passes are
                          * rendered while one more would end nearer the budget than
                          * stopping (judged by the mean pass so far); at least one */
    double target_error; /* > 0: stop after a pair of passes whose estimate from the
                          * halves (odd and even passes, error_estimate.h) is at most this */
    double time_limit;   /* > 0: start a pair of passes only if it ends within this many
                          * seconds of the start (judged by the mean pass so far) */
} PpmSettings;

typedef struct {
    RenderResult render;    /* the mean of the passes and its standard error; time, rays */
    int passes;             /* passes rendered */
    double cpu_seconds;     /* processor time used, all threads together */
    double radius;          /* the last pass's radius */
    double stored;          /* photons stored per pass in the caustic map, on average */
    RelativeError estimate; /* from the odd and even passes (with a target or time limit) */
    TargetStop stop;        /* and why the passes stopped then */
} PpmResult;

/* The map of settings->emitted photons for estimates of `radius`, shot by `threads`
 * threads (0: one per core; no more than there are photons); the same map for any count.
 * Returns 0, or -1 when memory runs out. */
int ppm_photon_map(PhotonMap *map, const Scene *scene, const PhotonMapSettings *settings,
                   double radius, int threads, RayCounts *counts);

/* Two independent 64-bit seeds for pass `pass` (from 1) of a render of seed `seed`: its
 * camera samples (unless PIXEL_PROGRESSIVE continues the render's own) and its photons. */
void ppm_pass_seeds(uint64_t seed, int pass, uint64_t *image_seed, uint64_t *photon_seed);

/* Render with `render`'s size, threads, seed and progress (its spp and sampling are
 * those of each pass: settings->spp, and render->sampling; PIXEL_PROGRESSIVE continues
 * each pixel's one sequence from pass to pass). A SIGINT stops after the
 * pass in progress, which is dropped; result->render.interrupted says so. Returns 0,
 * or -1 when memory runs out (nothing is then allocated). */
int ppm_render(const Scene *scene, const RenderSettings *render, const PpmSettings *settings,
               PpmResult *result);

void ppm_result_free(PpmResult *result);

/* Whether to render another pass after `done` passes that took `cpu_used` seconds: one
 * is left and, with a budget, the total with it (judged by the mean pass so far) ends
 * nearer the budget than without it; the first pass always. */
int ppm_budget_allows(const PpmSettings *settings, int done, double cpu_used);

#endif
