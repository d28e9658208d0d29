/* test_random.h (bench, chapter 1): random numbers for the tests and the graders.
 *
 * Chapter 1's lesson draws no random numbers (its generator, rng.h, arrives with chapter
 * 2's Monte Carlo), but its tests send random rays and its graders random inputs. These
 * are theirs, in every chapter: Marsaglia's xorshift64*, seeded from three numbers.
 * The random directions are uniform over the unit sphere: z = cos(theta) uniform in
 * [-1, 1] (Archimedes' hat-box theorem) and phi uniform in [0, 2 pi).
 */
#ifndef TEST_RANDOM_H
#define TEST_RANDOM_H

#include <stdint.h>

#include "vec.h"

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
                          (c + 1) * 0x94d049bb133111ebULL) |
                         1u};
    for (int i = 0; i < 8; i++)
        test_uniform(&random);
    return random;
}

/* The direction with z = 2 u1 - 1 and phi = 2 pi u2: uniform over the sphere for
 * uniform u1, u2. */
static inline Vec3 unit_vector_from(double u1, double u2)
{
    double z = 2.0 * u1 - 1.0, phi = 2.0 * PI * u2;
    double s = sqrt(fmax(0.0, 1.0 - z * z));
    return vec3(s * cos(phi), s * sin(phi), z);
}

static inline Vec3 random_unit_vector(TestRandom *random)
{
    double u1 = test_uniform(random), u2 = test_uniform(random);
    return unit_vector_from(u1, u2);
}

#endif
