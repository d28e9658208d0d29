/* sobol.h (chapter 7): pairs of numbers stratified across a pixel's samples, from a
 * scrambled Sobol (0,2)-sequence.
 *
 * The k-th pair a sample draws (k < SOBOL_PAIRS: its first shadow ray's lamp point, its
 * first bounce, ...) comes from one point set per pixel and per k, whose first 2^m
 * points put one point in each cell of any 2^a x 2^b grid, a + b = m (Sobol 1967).
 * Owen's nested scramble of the digits, by Laine and Karras's hash (Burley 2020), makes
 * every point uniform, so only the variance changes, never the mean (docs/chapter7.md).
 */
#ifndef SOBOL_H
#define SOBOL_H

#include <stdint.h>

/* The pairs of a sample that are stratified; later pairs are independent numbers. The
 * room's first diffuse hit draws three (docs/chapter7.md: what more would cost). */
#define SOBOL_PAIRS 3

/* Point `index` of the (0,2)-sequence scrambled by `key`, in [0, 1)^2. */
void sobol_pair(uint32_t index, uint64_t key, double *u, double *v);

#endif
