/* roulette.h (chapter 6): Russian roulette, ending paths without bias (report §2.2, §4.7).
 *
 * Introduced in chapter 6. At a diffuse surface the path goes on with probability
 * alpha, and a surviving path's weight is divided by alpha:
 *     E[estimate] = alpha * (X / alpha) + (1 - alpha) * 0 = E[X],
 * so the expected value is unchanged while the mean path length becomes finite.
 * Small alpha: short paths, fast and noisy; alpha = 1: no roulette.
 * Erratum (SPEC §8.5): the report calls alpha the probability of termination, but its
 * Figure 12 and Table 1 behave as if alpha were the probability of survival (alpha =
 * 0.01 is fastest and noisiest). Here alpha is the survival probability.
 */
#ifndef ROULETTE_H
#define ROULETTE_H

#include "rng.h"
#include "vec.h"

/* Whether the path survives (probability alpha); alpha >= 1 always survives without
 * drawing a random number. */
int roulette_survives(double alpha, Rng *rng);

/* The bounded-weight survival probability min(1, max component of throughput). */
double roulette_survival_from_throughput(Vec3 throughput);

#endif
