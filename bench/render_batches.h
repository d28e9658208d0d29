/* render_batches.h (bench, chapter 7): a stratified render whose variance is still known, from
 * independent batches (for the references, measure.h).
 *
 * A reference judges a panel by its own per-pixel variance, which the chapters subtract
 * from their MSE (measure.h). render.h estimates that variance from the spread of a
 * pixel's samples, s^2 / n, which is unbiased only when the samples are independent:
 * random pixel positions (PIXEL_RANDOM). Jittered sub-pixels (camera.h) are not: each
 * sample is confined to its own cell, so the samples differ more from each other than
 * their mean varies from render to render, and s^2 / n overstates the variance of the
 * mean (a pixel across an edge: the cells on either side always disagree, yet the mean
 * hardly moves). Subtracting that would bias every panel's error low.
 *
 * Yet sub-pixels are the cheaper reference: at a pixel across an edge, where the lamp or
 * an object ends, their error falls faster than 1/sqrt(n). Measured with the final
 * estimator, per sample (the variance of a pixel's mean times its samples, averaged):
 * 0.518 for random positions, 0.153 for 8 batches of sub-pixels, at 200 x 200 (256 spp);
 * at 800 x 800, where fewer pixels hold an edge, 0.176 against 0.101 (128 spp).
 *
 * So render B independent stratified images, each of spp / B samples, with seeds that
 * share nothing (rng_hash of the seed and the batch), and average them. Their means
 * x_1 .. x_B are independent draws of one distribution, so with xbar their average,
 *     Var(xbar) is estimated without bias by  sum_b (x_b - xbar)^2 / (B - 1) / B,
 * whatever the samples inside a batch are like: the same sums that render() keeps of a
 * pixel's samples (PixelSum, renderer.h), kept of the batches' means. B - 1 degrees of freedom
 * make each pixel's estimate rough (with B = 8, its relative spread is about sqrt(2 / 7) =
 * 53%), but sums over many pixels, all that measure.h takes from it, are sharp. More batches
 * mean finer per-pixel estimates but coarser strata, so more noise per sample
 * (docs/chapter7.md gives the noise measured for 4 to 32 batches).
 */
#ifndef RENDER_BATCHES_H
#define RENDER_BATCHES_H

#include "renderer.h"

/* Render `batches` >= 2 independent images of settings->spp / batches samples each
 * (settings->spp must be a multiple of batches), with settings->sampling, and combine
 * them into result: image their mean; std_error and average_std_error (render.h) from
 * the spread of the batches' means as above (the progress line names the batch); seconds, rays,
 * samples and non-finite samples summed. Stops after the batch in which SIGINT arrived
 * (result->interrupted; its images are then not to be used). Returns 0, or -1 for a wrong batch
 * count or when memory runs out (nothing is then allocated). */
int render_batches(const Scene *scene, const RenderSettings *settings, int batches,
                   Estimator estimate, const void *estimator_settings, RenderResult *result);

#endif
