/* ppm.h (chapter 8): probabilistic progressive photon mapping.
 * Knaus and Zwicker, "Progressive photon mapping: a probabilistic approach", 2011.
 *
 * Introduced in chapter 8. One caustic map with a fixed radius r is biased (the blur
 * of photon_estimate.h) however many passes are averaged: more photons lower the
 * variance, not the bias. Knaus and Zwicker make it consistent with independent
 * passes: pass i shoots a fresh photon map, renders the image with it (the path tracer
 * with caustics from the map, path.h, at spp camera samples per pixel) at radius
 *     r_i^2 = r_1^2 i^(alpha - 1),    0 < alpha < 1
 * (alpha = 1 keeps the radius fixed: the biased method, for comparison), and the result
 * is the average of the pass images. The radius shrinks slowly enough
 * that each pass's variance grows only as i^(1 - alpha), so the average's variance
 * still falls, as P^(-alpha) after P passes, while the bias falls as P^(alpha - 1).
 * The squared bias, P^(2 alpha - 2), and the variance, P^(-alpha), fall alike for
 * alpha = 2/3, and the mean squared error then goes to zero as P^(-2/3).
 *
 * Each pass's image, photons and camera samples alike, uses its own seeds, derived from
 * the render's seed and the pass number; the image is the same for any thread count.
 * The pass images are independent, so the spread between them gives each pixel's
 * standard error: sqrt(s^2 / P) from their sample variance s^2 (an estimate: the
 * passes are not identically distributed, the later ones having smaller radii).
 */
#ifndef PPM_H
#define PPM_H

#include "path.h"
#include "photon.h"

#define PPM_ALPHA (2.0 / 3.0)

typedef struct {
    PathSettings path;    /* the path tracer's settings (its fresnel also for photons) */
    int photons;          /* emitted per pass */
    double radius;        /* r_1 */
    double alpha;         /* of the radius schedule */
    int spp;              /* camera samples per pixel per pass */
    int passes;           /* passes to render */
    double cpu_seconds;   /* > 0: a budget of processor time (stats_cpu_now): passes are
                           * rendered while one more would end nearer the budget than
                           * stopping (judged by the mean pass so far); at least one */
} PpmSettings;

typedef struct {
    RenderResult render; /* the mean of the passes and its standard error; time, rays */
    int passes;          /* passes rendered */
    double cpu_seconds;  /* processor time used, all threads together */
    double radius;       /* the last pass's radius */
    double stored;       /* photons stored per pass, on average */
} PpmResult;

/* r_i for pass i = 1, 2, ... */
double ppm_radius(double first_radius, double alpha, int pass);

/* Render with `render`'s size, threads, seed and progress (its spp and sampling are
 * those of each pass: settings->spp, and render->sampling). A SIGINT stops after the
 * pass in progress, which is dropped; result->render.interrupted says so. Returns 0,
 * or -1 when memory runs out (nothing is then allocated). */
int ppm_render(const Scene *scene, const RenderSettings *render, const PpmSettings *settings,
               PpmResult *result);

void ppm_result_free(PpmResult *result);

#endif
