/* sample_order.h (bench, chapter 1): which sample each pass of a render takes of each pixel,
 * so that a render stopped early is unbiased (docs/chapter2.md). On sub-pixels sample s
 * looks through cell s (pixel_sampling.h), so passes 0, 1, ... stopped at k < n would cover
 * the top k/n of every pixel. Instead each pixel starts at its own first sample f, uniform
 * in [0, n) from a generator of the pixel's that no sample uses, and pass j takes sample
 * ((f + j) mod n) g mod n, g the integer nearest n / phi (the golden ratio) that shares no
 * factor with n: each pass's sample is uniform over the cells, so over the pixel, the n
 * passes take each sample once, and that g spreads a stopped render's cells. Other
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
