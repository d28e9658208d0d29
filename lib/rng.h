/* rng.h (chapter 1): the random numbers behind every Monte Carlo estimate.
 *
 * Introduced in chapter 1 (jittered pixel positions), used by every chapter after.
 * PCG32 (O'Neill 2014, "PCG: A Family of Simple Fast Space-Efficient Statistically
 * Good Algorithms for Random Number Generation"): a 64-bit linear congruential state,
 * output permuted by an xorshift and a data-dependent rotation, 32 bits per step.
 *
 * Every sample gets its own generator, seeded from (seed, pixel, sample) through a
 * SplitMix64 hash (SPEC §9). A pixel's samples therefore do not depend on which thread
 * renders them or in what order, and an image is bit-for-bit the same for any thread
 * count and any run.
 */
#ifndef RNG_H
#define RNG_H

#include <stdint.h>

typedef struct {
    uint64_t state, increment;
#if CHAPTER >= 7
    /* Stratified pairs (sobol.h): 0, or the pixel's key for them; the sample's number
     * in its pixel; the pairs it has drawn so far. */
    uint64_t strata_key;
    uint32_t strata_index, pairs_drawn;
#endif
} Rng;

/* The generator for one sample of one pixel of one image. */
Rng rng_for_sample(uint64_t seed, uint64_t pixel, uint64_t sample);

/* The next 32 uniformly distributed bits. */
uint32_t rng_next(Rng *rng);

/* A uniform double in [0, 1): 32 random bits scaled by 2^-32, so never 1. */
double rng_uniform(Rng *rng);

/* Two uniform numbers in [0, 1) that belong together (a point on a lamp, a direction):
 * two rng_uniform draws; from chapter 7 on, when the generator has a strata_key, the
 * sample's point of a stratified pair (sobol.h) for its first SOBOL_PAIRS pairs. */
void rng_pair(Rng *rng, double *u, double *v);

/* SplitMix64's finaliser (see rng.c): 64 bits mixed into 64 unrelated-looking ones. */
uint64_t rng_hash(uint64_t x);

#endif
