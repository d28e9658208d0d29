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
 *
 * Bounded weights (pbrt, smallpt): a constant alpha divides a survivor's weight by alpha
 * at every diffuse bounce, so on bright walls the weight grows as (rho / alpha)^k and
 * its variance is finite only for alpha > rho^2. Taking the survival probability from
 * the path's own throughput T (the product of its weights so far),
 *     q = min(1, max over the channels of T),
 * keeps every survivor's weight T / q at most 1 in its largest channel, whatever the
 * reflectances: a dim path is likely to end, a bright one goes on, and the second
 * moment stays finite for any rho < 1. It is unbiased for the same reason as constant
 * alpha: any q in (0, 1] will do, as long as the weight is divided by the q used.
 * On the room it is about 1.3 times as efficient as alpha = 0.75 (chapter 7's levers).
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
