/* sample_order.h (bench, chapter 1): the order in which a render takes each pixel's
 * samples, so that a render stopped early is unbiased (docs/chapter2.md).
 *
 * Sample s of n looks through sub-pixel s (pixel_sampling.h), so taking samples 0, 1, ...
 * and stopping after k < n would cover the top k/n of every pixel only. Instead each
 * pixel starts at its own first sample f, uniform in [0, n) and drawn from a generator of
 * the pixel's that no sample uses, and pass j takes sample
 *     ((f + j) mod n) g mod n,
 * g sharing no factor with n, so that the n passes take each sample once. Whatever j, the
 * sample is uniform over the n sub-pixels and, jittered, over the pixel: so the mean of
 * any first k passes is unbiased. Any such g would do; the integer nearest n / phi (the
 * golden ratio) spreads the sub-pixels a stopped render has taken across the pixel. Other
 * placements (and chapter 1's pixel centres) take sample j at pass j.
 */
#ifndef SAMPLE_ORDER_H
#define SAMPLE_ORDER_H

#include "render.h"

typedef struct {
    uint64_t seed, samples;
    uint64_t stride; /* g; 0: sample j at pass j */
} SampleOrder;

/* The order of a render's samples, computed once per render. */
SampleOrder sample_order_make(const ImageSettings *image);

/* The pixel's first sample f, uniform in [0, samples), from its own generator. */
int sample_order_first(const SampleOrder *order, uint64_t pixel);

/* The sample that pass `pass` (0 <= pass < samples) takes of the pixel. */
int sample_order_sample(const SampleOrder *order, uint64_t pixel, int pass);

#endif
