/* rng.h (chapter 2): the random numbers behind every Monte Carlo estimate.
 *
 * PCG32 (O'Neill 2014): a 64-bit linear congruential state whose output is permuted by
 * an xorshift and a data-dependent rotation. Every sample of every pixel gets its own
 * generator, seeded from (seed, pixel, sample) by a SplitMix64 hash, so an image is the
 * same bit for bit whichever thread renders which pixel.
 */
#ifndef RNG_H
#define RNG_H

#include <stdint.h>

typedef struct Rng {
    uint64_t state, increment;
#if CHAPTER >= 7
    uint64_t strata_key;   /* 0, or the pixel's key for its stratified pairs (sobol.h) */
    uint32_t strata_index; /* the sample's number in its pixel */
    uint32_t pairs_drawn;  /* the pairs it has drawn so far */
#endif
} Rng;

/* The generator for one sample of one pixel of one image. */
Rng rng_for_sample(uint64_t seed, uint64_t pixel, uint64_t sample);

/* The next 32 uniformly distributed bits. */
uint32_t rng_next(Rng *rng);

/* A uniform double in [0, 1): 32 random bits scaled by 2^-32, so never 1. */
double rng_uniform(Rng *rng);

/* Two uniform numbers in [0, 1) that belong together (a point on a lamp, a direction). */
void rng_pair(Rng *rng, double *u, double *v);

/* SplitMix64's finaliser: 64 bits mixed into 64 unrelated-looking ones. */
uint64_t rng_hash(uint64_t x);

#if CHAPTER >= 7
/* Make rng_pair's first pairs stratified across the samples of the pixel (sobol.h):
 * the pixel's key for them, and the sample's number. */
static inline void rng_stratify(Rng *rng, uint64_t seed, uint64_t pixel, uint32_t sample)
{
    rng->strata_key = rng_hash(rng_hash(seed ^ 0x5b0b01u) ^ pixel) | 1u;
    rng->strata_index = sample;
}
#endif

#endif
