/* pixel_sampling.c (chapter 2): random positions and stratified, jittered sub-pixels.
 * See pixel_sampling.h. */
#include "pixel_sampling.h"

#include <math.h>

int pixel_first_stratum(Rng *pixel_rng, int samples)
{
    if (samples <= 1)
        return 0;
    /* Uniform in [0, n) exactly: of the 2^32 values, reject the lowest 2^32 mod n, so
     * that the rest is a whole number of runs of n. */
    uint32_t n = (uint32_t)samples, rejected = (uint32_t)(-n) % n;
    uint32_t r;
    do
        r = rng_next(pixel_rng);
    while (r < rejected);
    return (int)(r % n);
}

static uint64_t greatest_common_divisor(uint64_t a, uint64_t b)
{
    while (b != 0) {
        uint64_t t = a % b;
        a = b;
        b = t;
    }
    return a;
}

/* The stride g of the visit sigma(j) = j g mod n: the integer nearest n / phi that
 * shares no factor with n, so that sigma is a permutation of the n cells. */
static uint64_t golden_stride(uint64_t n)
{
    const double inverse_phi = 0.6180339887498949;
    uint64_t g = (uint64_t)((double)n * inverse_phi + 0.5);
    for (uint64_t d = 0;; d++) {
        if (d <= g && greatest_common_divisor(g - d, n) == 1)
            return g - d;
        if (greatest_common_divisor(g + d, n) == 1)
            return g + d;
    }
}

int pixel_stratum(int sample, int samples, int first_stratum)
{
    uint64_t n = (uint64_t)samples;
    uint64_t j = ((uint64_t)first_stratum + (uint64_t)sample) % n;
    return (int)(j * golden_stride(n) % n);
}

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

void pixel_position(PixelSampling sampling, int sample, int samples, int first_stratum,
                    Rng *rng, double *u, double *v)
{
    if (sampling == PIXEL_RANDOM) {
        *u = rng_uniform(rng);
        *v = rng_uniform(rng);
    } else if (pixel_uses_subpixels(sampling)) {
        uint64_t cell = (uint64_t)pixel_stratum(sample, samples, first_stratum), first, columns;
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
