/* sobol.c (chapter 7): the scrambled (0,2)-sequence of sobol.h, and rng_pair (rng.h)
 * drawing from it. */
#include "sobol.h"

#include "rng.h"

static uint32_t reverse_bits(uint32_t x)
{
    x = (x << 16) | (x >> 16);
    x = ((x & 0x00ff00ffu) << 8) | ((x & 0xff00ff00u) >> 8);
    x = ((x & 0x0f0f0f0fu) << 4) | ((x & 0xf0f0f0f0u) >> 4);
    x = ((x & 0x33333333u) << 2) | ((x & 0xccccccccu) >> 2);
    return ((x & 0x55555555u) << 1) | ((x & 0xaaaaaaaau) >> 1);
}

/* Laine and Karras's hash: each step flips bit j of x by a function of the bits below
 * it (adding the seed: by the carry and the seed's bit j; x ^= x * c with c even: by the
 * product, which bits below j alone decide). So on mirrored digits it is a nested
 * scramble, and for a uniformly random seed its value is uniform for any x (x + seed
 * is, and the rest is a bijection). */
static uint32_t laine_karras(uint32_t x, uint32_t seed)
{
    x += seed;
    x ^= x * 0x6c50b47cu;
    x ^= x * 0xb82f1e52u;
    x ^= x * 0xc7afe638u;
    x ^= x * 0x8d22f6e6u;
    return x;
}

/* Owen's nested scramble of the binary digits of x / 2^32, most significant first. */
static uint32_t owen_scramble(uint32_t x, uint32_t seed)
{
    return reverse_bits(laine_karras(reverse_bits(x), seed));
}

/* The second Sobol dimension: the XOR of the columns v_j for the set bits j of i. */
static uint32_t sobol_second(uint32_t i)
{
    uint32_t y = 0;
    for (uint32_t v = 1u << 31; i != 0; i >>= 1, v ^= v >> 1)
        if (i & 1u)
            y ^= v;
    return y;
}

void sobol_pair(uint32_t index, uint64_t key, double *u, double *v)
{
    uint64_t seeds = rng_hash(key), more = rng_hash(seeds);
    uint32_t shuffled = owen_scramble(index, (uint32_t)more);
    *u = owen_scramble(reverse_bits(shuffled), (uint32_t)seeds) * 0x1p-32;
    *v = owen_scramble(sobol_second(shuffled), (uint32_t)(seeds >> 32)) * 0x1p-32;
}

/* From this chapter on, a generator with a strata key (rng_stratify) draws its first
 * SOBOL_PAIRS pairs from the pixel's point sets. */
void rng_pair(Rng *rng, double *u, double *v)
{
    if (rng->strata_key != 0 && rng->pairs_drawn < SOBOL_PAIRS) {
        sobol_pair(rng->strata_index, rng_hash(rng->strata_key ^ rng->pairs_drawn++), u, v);
        return;
    }
    *u = rng_uniform(rng);
    *v = rng_uniform(rng);
}
