/* pixel_sampling.h (chapter 2): where in its pixel each sample looks (report §3.3.1).
 *
 * PIXEL_RANDOM: a uniform point of the pixel ("ray randomization"). PIXEL_SUBPIXELS:
 * the report's sub-pixels, n = spp cells of equal area; sample s of n looks through cell
 * s, at a uniform point of it (jittered), so the n samples together take one cell each
 * and each estimates its cell's mean. A render stopped before all n must take them in
 * an order that leaves it unbiased: the bench's renderer does (docs/chapter2.md).
 */
#ifndef PIXEL_SAMPLING_H
#define PIXEL_SAMPLING_H

#include "rng.h"

typedef enum {
    PIXEL_CENTRE, /* u = v = 1/2: one ray through the centre, as in chapter 1 */
    PIXEL_SUBPIXELS,
    PIXEL_RANDOM,
#if CHAPTER >= 7
    PIXEL_STRATIFIED, /* sub-pixels, and the estimator's pairs of numbers too (sobol.h) */
#endif
#if CHAPTER >= 8
    /* Stratified across renders (the passes of a photon map): sample s takes its
     * position and pairs from point s of the pixel's Sobol sequences, whichever render
     * draws it (sobol.h) */
    PIXEL_PROGRESSIVE
#endif
} PixelSampling;

/* Whether the samples are placed on sub-pixels. */
static inline int pixel_uses_subpixels(PixelSampling sampling)
{
#if CHAPTER >= 7
    return sampling == PIXEL_SUBPIXELS || sampling == PIXEL_STRATIFIED;
#else
    return sampling == PIXEL_SUBPIXELS;
#endif
}

/* Where cell `cell` of `samples` lies: u in [u0, u0 + width), v in [v0, v0 + height). */
void pixel_stratum_bounds(int cell, int samples, double *u0, double *v0, double *width,
                          double *height);

/* Exercise 2.5: point (u, v) of sample `sample` out of `samples`: PIXEL_RANDOM draws u
 * then v from the sample's generator rng, PIXEL_SUBPIXELS the jitter within cell `sample`
 * (< samples); PIXEL_CENTRE draws nothing (rng may be NULL). */
void pixel_position(PixelSampling sampling, int sample, int samples, Rng *rng, double *u,
                    double *v);

#endif
