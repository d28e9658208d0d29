/* test_random.h (bench, chapter 1): random numbers for the tests and the graders.
 *
 * Chapter 1's lesson draws no random numbers (its generator, rng.h, arrives with chapter
 * 2's Monte Carlo), but its tests send random rays and its graders random inputs. These
 * are theirs, in every chapter: Marsaglia's xorshift64*, seeded from three numbers.
 */
#ifndef TEST_RANDOM_H
#define TEST_RANDOM_H

#include <stdint.h>

typedef struct {
    uint64_t state;
} TestRandom;

/* A uniform double in [0, 1). */
static inline double test_uniform(TestRandom *random)
{
    uint64_t x = random->state;
    x ^= x >> 12;
    x ^= x << 25;
    x ^= x >> 27;
    random->state = x;
    return (double)((x * 0x2545f4914f6cdd1dULL) >> 11) * 0x1p-53;
}

/* The generator for seed (a, b, c); never the all-zero state xorshift cannot leave. */
static inline TestRandom test_random(uint64_t a, uint64_t b, uint64_t c)
{
    TestRandom random = {((a + 1) * 0x9e3779b97f4a7c15ULL ^ (b + 1) * 0xbf58476d1ce4e5b9ULL ^
                          (c + 1) * 0x94d049bb133111ebULL) | 1u};
    for (int i = 0; i < 8; i++)
        test_uniform(&random);
    return random;
}

#endif
