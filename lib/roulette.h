/* roulette.h (chapter 6): Russian roulette, ending paths without bias (report §2.2, §4.7).
 *
 * At a diffuse vertex the path goes on with probability alpha and a survivor's weight
 * is divided by alpha: E = alpha (X / alpha) + (1 - alpha) 0 = E[X]. Erratum: the report
 * calls alpha the probability of termination, but its Figure 12 and Table 1 behave as
 * if it were the probability of survival, which it is here. The variance is finite only
 * for alpha > rho^2; bounded-weight roulette, q = min(1, max channel of the throughput),
 * keeps it finite for any rho < 1 (docs/chapter6.md).
 */
#ifndef ROULETTE_H
#define ROULETTE_H

#include "path.h"

/* Whether the path survives (probability alpha); alpha >= 1 always survives without
 * drawing a random number. */
int roulette_survives(double alpha, Rng *rng);

/* Exercise 6.2: the bounded-weight survival probability min(1, max component of throughput). */
double roulette_survival_from_throughput(Vec3 throughput);

/* Exercise 6.1: roulette at a diffuse vertex on `segment` with the settings' alpha or
 * bounded weights: 0 if the path ends, else 1 with the survivor's throughput divided by
 * its probability. */
int roulette_continues(const PathSettings *settings, int segment, Vec3 *throughput, Rng *rng);

#endif
