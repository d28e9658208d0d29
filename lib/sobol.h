/* sobol.h (chapter 7): stratified pairs of random numbers across a pixel's samples: a
 * scrambled Sobol (0,2)-sequence (issue 11: spend the samples where the error is).
 *
 * Chapter 2 stratified where in the pixel each sample looks (camera.h). The numbers a
 * path draws after that (the point on the lamp of the first shadow ray, the direction
 * of the first bounce, ...) were still independent from sample to sample, so two
 * samples of one pixel could put their shadow rays on the same corner of the lamp.
 * Here each pair of numbers a path draws, the k-th pair of the sample (k < SOBOL_PAIRS),
 * comes from one two-dimensional point set per pixel and per k, spread so evenly that
 * the first 2^m samples' points put exactly one point in each of the 2^m cells of any
 * grid of 2^a x 2^b cells with a + b = m: the first two dimensions of Sobol's sequence
 * (Sobol 1967), a (0,2)-sequence in base 2 (Niederreiter 1992):
 *     x_i = sum_j i_j 2^-(j+1)               (the bits of i, mirrored: van der Corput)
 *     y_i = the XOR of the columns v_j for the bits i_j = 1, v_0 = 1/2, v_(j+1) = v_j XOR v_j/2
 * Samples of a pixel take the points one by one, so any prefix of the samples is itself
 * spread evenly (an interrupted render stays a good one).
 *
 * Unbiased because every point is uniformly distributed on the unit square: each
 * coordinate is scrambled by a random nested permutation of its binary digits (Owen
 * 1995), drawn per pixel and per k. Owen's scramble flips each digit by a coin that
 * depends on the digits before it, which keeps the net's structure and makes every
 * point uniform; here the coins come from a hash (Laine and Karras 2011, as used by
 * Burley 2020, "Practical Hash-based Owen Scrambling"). The sample's number is shuffled
 * the same way (Burley 2020), with another key per k, so that the pairs k and k' of one
 * sample are independent of each other: together a path's numbers are uniform in the
 * unit cube, as the estimator needs. Only the variance changes, never the mean
 * (tests/test_sobol.c: the points' uniformity and stratification, and the path tracer's
 * mean against the one with independent numbers).
 *
 * The per-pixel standard error that render.h computes from the spread of the samples
 * overestimates the error of a stratified mean (it treats the samples as independent):
 * with strata it is an upper bound. Independent runs (--runs) measure the true spread.
 */
#ifndef SOBOL_H
#define SOBOL_H

#include <stdint.h>

/* The pairs of a sample that are stratified; later pairs are independent numbers. In
 * the room the first diffuse hit draws three (its shadow ray's lamp point, the lamp's
 * mirror image's, the bounce). Measured at 256 x 256 against an 8192-spp reference,
 * before the sphere guide: at 64 spp 3 pairs cut the relative RMSE from 0.0759 to
 * 0.0717 for 5% more time, 8 pairs to 0.0720 for 17% more (each pair costs a few
 * hashes); at 256 spp 3 pairs took it from 0.0395 to 0.0365. With the guide (chapter 7's
 * final estimator) the gain is smaller: 0.0494 -> 0.0482 at 64 spp, 0.0266 -> 0.0258 at
 * 256 (the levers table and `make bench` print it each time). */
#define SOBOL_PAIRS 3

/* Point `index` of the (0,2)-sequence scrambled by `key`, in [0, 1)^2. */
void sobol_pair(uint32_t index, uint64_t key, double *u, double *v);

#endif
