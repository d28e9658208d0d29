/* pixel_sampling.c (chapter 2): random positions and stratified, jittered sub-pixels.
 * See pixel_sampling.h. */
#include "pixel_sampling.h"

#include <math.h>

/* The row of cell m among n cells: r = round(sqrt(n)) rows, row k starting at cell
 * floor(k n / r); the row's first cell and its number of cells. */
static void stratum_row(uint64_t m, uint64_t n, uint64_t *first, uint64_t *columns)
{
    uint64_t r = (uint64_t)(sqrt((double)n) + 0.5);
    if (r == 0)
        r = 1;
    uint64_t k = ((m + 1) * r - 1) / n;
    *first = k * n / r;
    *columns = (k + 1) * n / r - *first;
}

void pixel_stratum_bounds(int cell, int samples, double *u0, double *v0, double *width,
                          double *height)
{
    uint64_t first, columns;
    stratum_row((uint64_t)cell, (uint64_t)samples, &first, &columns);
    *u0 = (double)((uint64_t)cell - first) / (double)columns;
    *v0 = (double)first / samples;
    *width = 1.0 / (double)columns;
    *height = (double)columns / samples;
}

void pixel_position(PixelSampling sampling, int sample, int samples, Rng *rng, double *u,
                    double *v)
{
    if (sampling == PIXEL_RANDOM) {
        *u = rng_uniform(rng);
        *v = rng_uniform(rng);
    } else if (pixel_uses_subpixels(sampling)) {
        uint64_t cell = (uint64_t)sample, first, columns;
        stratum_row(cell, (uint64_t)samples, &first, &columns);
        /* Uniform in the cell; each quotient stays below 1. */
        double ju = rng_uniform(rng), jv = rng_uniform(rng);
        *u = ((double)(cell - first) + ju) / (double)columns;
        *v = ((double)first + jv * (double)columns) / samples;
    } else {
        *u = 0.5;
        *v = 0.5;
    }
}
