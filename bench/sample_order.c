/* sample_order.c (bench, chapter 1): each pixel's samples from a random first one, by a
 * golden-ratio stride. See sample_order.h. */
#include "sample_order.h"

static uint64_t greatest_common_divisor(uint64_t a, uint64_t b)
{
    while (b != 0) {
        uint64_t t = a % b;
        a = b;
        b = t;
    }
    return a;
}

/* The integer nearest n / phi that shares no factor with n. */
static uint64_t golden_stride(uint64_t n)
{
    uint64_t g = (uint64_t)((double)n * 0.6180339887498949 + 0.5);
    for (uint64_t d = 0;; d++) {
        if (d <= g && greatest_common_divisor(g - d, n) == 1)
            return g - d;
        if (greatest_common_divisor(g + d, n) == 1)
            return g + d;
    }
}

SampleOrder sample_order_make(const ImageSettings *image)
{
    uint64_t n = (uint64_t)image->spp;
#if CHAPTER >= 2
    int shuffled = pixel_uses_subpixels(image->sampling) && n > 1;
    uint64_t seed = image->seed;
#else
    int shuffled = 0;
    uint64_t seed = 0; /* chapter 1's samples draw no random numbers */
#endif
    return (SampleOrder){seed, n, shuffled ? golden_stride(n) : 0};
}

int sample_order_first(const SampleOrder *order, uint64_t pixel)
{
    /* Uniform in [0, n) exactly: of the 2^32 values, reject the lowest 2^32 mod n, so that
     * the rest is a whole number of runs of n. */
#if CHAPTER >= 2
    if (order->samples <= 1)
        return 0;
    Rng rng = rng_for_sample(order->seed, pixel, UINT64_MAX);
    uint32_t n = (uint32_t)order->samples, rejected = (uint32_t)(-n) % n, r;
    do
        r = rng_next(&rng);
    while (r < rejected);
    return (int)(r % n);
#else
    return 0;          /* chapter 1 shuffles nothing (sample_order_make), nor has a generator */
#endif
}

int sample_order_sample(const SampleOrder *order, uint64_t pixel, int pass)
{
    if (order->stride == 0)
        return pass;
    uint64_t j = (uint64_t)sample_order_first(order, pixel) + (uint64_t)pass;
    if (j >= order->samples)
        j -= order->samples; /* (f + pass) mod n, as f and pass are below n */
    return (int)(j * order->stride % order->samples);
}
