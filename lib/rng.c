/* rng.c (chapter 2): PCG32 seeded by SplitMix64. See rng.h. */
#include "rng.h"

/* SplitMix64's finaliser (Steele, Lea, Flood 2014): a bijective mix of 64 bits, so
 * nearby inputs (pixel 7 and pixel 8) give unrelated outputs. */
uint64_t rng_hash(uint64_t x)
{
    x += 0x9e3779b97f4a7c15ULL;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
    return x ^ (x >> 31);
}

Rng rng_for_sample(uint64_t seed, uint64_t pixel, uint64_t sample)
{
    uint64_t key = rng_hash(rng_hash(rng_hash(seed) ^ pixel) ^ sample);
    Rng rng = {0};
    rng.increment = (rng_hash(key) << 1) | 1u; /* the LCG increment must be odd */
    rng_next(&rng);
    rng.state += key;
    rng_next(&rng);
    return rng;
}

uint32_t rng_next(Rng *rng)
{
    uint64_t old = rng->state;
    rng->state = old * 6364136223846793005ULL + rng->increment;
    uint32_t xorshifted = (uint32_t)(((old >> 18) ^ old) >> 27);
    uint32_t rotation = (uint32_t)(old >> 59);
    return (xorshifted >> rotation) | (xorshifted << ((32u - rotation) & 31u));
}

double rng_uniform(Rng *rng) { return rng_next(rng) * 0x1p-32; }

#if CHAPTER < 7
void rng_pair(Rng *rng, double *u, double *v)
{
    *u = rng_uniform(rng);
    *v = rng_uniform(rng);
}
#endif
