/* error_estimate.h (bench, chapter 7): an image's error estimated from its own samples, and
 * rendering until it is small enough or the time is up (--target-error, --time).
 *
 * Render in passes and add them in turn to two half-images, A (passes 1, 3, ...) and B
 * (passes 2, 4, ...), of equal samples. The image is F = (A + B) / 2. A and B are
 * independent with the same mean, so per pixel and channel
 *     E[((A - B) / 2)^2] = (Var A + Var B) / 4 = Var F,
 * the variance of F without bias, from F's own samples. The relative MSE of measure.h,
 * mean of (F - truth)^2 / (truth^2 + 0.01), is then estimated by
 *     rel_MSE_est = mean over pixels and channels of ((A - B) / 2)^2 / (F^2 + 0.01),
 * with F in the weight for the unknown truth (nearly, not exactly, unbiased). It sees the
 * variance only: an estimator's bias (the photon map's blur, chapter 8) is not in it, and
 * only a reference shows it. Its uncertainty: the spread over pixels of each pixel's three
 * channels' terms (which one path carries together), / sqrt(pixels). docs/running.md.
 */
#ifndef ERROR_ESTIMATE_H
#define ERROR_ESTIMATE_H

#include "image.h"
#include "measure.h"
#include "renderer.h"

/* A relative MSE (a mean over pixels and channels) and the standard error of that mean
 * over the pixels. */
typedef struct {
    double rel_mse;
    double std_error;
} RelativeError;

/* The estimate above from the two half-images a and b (same size, equal samples);
 * NaN fields when the sizes differ. */
RelativeError error_estimate_halves(const Image *a, const Image *b);

/* The image's relative MSE against the reference, less the reference's own variance
 * (measure_error_estimate), with its standard error over the pixels; NaN fields when
 * the sizes differ. */
RelativeError error_against_reference(const Image *image, const Reference *reference);

/* The most any allocation of a render's samples among its pixels could buy. Pixel p's
 * relative variance e_p = sum over channels of se^2 / (F^2 + 0.01) / 3, from the image F
 * and its per-pixel standard error se (the same count n of independent samples, or
 * passes, everywhere, at equal cost each). Spending n_p in proportion to sqrt(e_p)
 * instead of n everywhere lowers the relative MSE at equal cost by
 *     G = mean(e) / mean(sqrt e)^2 >= 1   (1 when every e_p is equal),
 * the efficiency gain of an oracle: e_p known, nothing spent to learn it, every sample
 * kept (docs/chapter10.md). e_p from few samples spreads more than the truth, so G reads
 * high. NaN when the sizes differ or no pixel has variance. */
double error_allocation_gain(const Image *image, const Image *std_error);

/* A relative MSE's square root as a percentage, and that of its standard error
 * (se / (2 sqrt(rel_mse)), to first order); a negative rel_mse (a reference that cannot
 * tell the image from the truth) as 0. */
double error_percent(double rel_mse);
double error_percent_std_error(const RelativeError *error);

/* The two halves: the sums of the passes' images added to each, weighted by their
 * samples per pixel. */
typedef struct {
    Image sum[2];
    double samples[2];
    int passes;
} HalfImages;

/* Returns 0, or -1 when memory runs out (nothing is then allocated). */
int half_images_begin(HalfImages *halves, int width, int height);

/* Add one pass's image of `samples` samples per pixel to half passes % 2. */
void half_images_add(HalfImages *halves, const Image *pass, double samples);

/* The estimate, from the halves' means (their samples must be equal). */
RelativeError half_images_estimate(const HalfImages *halves);

/* The mean of every pass, weighted by samples, into image (allocated, that size). */
void half_images_mean(const HalfImages *halves, Image *image);

void half_images_free(HalfImages *halves);

/* When a render in passes stops. */
typedef enum {
    TARGET_REACHED,     /* the estimate is at most the target */
    TARGET_TIME_UP,     /* the next pair of passes would end after the time limit */
    TARGET_MOST_PASSES, /* the most passes allowed are done */
    TARGET_INTERRUPTED  /* SIGINT */
} TargetStop;

typedef struct {
    double target_error; /* relative RMSE; 0: none */
    double time_limit;   /* seconds; 0: none */
    int first_spp;       /* samples per pixel of each of the first two passes */
    int grow;            /* each later pair adds an eighth of the samples so far (at least
                            first_spp per pass); 0: every pass first_spp */
    int max_passes;      /* stop after this many (even) */
} TargetSettings;

/* A pair of passes is started only if, at the mean time per sample so far, it ends within
 * the time limit (the first pair always; a grown pair is made smaller to fit). The stop is
 * judged after each pair. */
typedef struct {
    RenderResult render;    /* the image F; seconds (with the estimates), rays, samples;
                               std_error from the spread of the passes when they are all
                               alike (grow 0), else |A - B| / 2 */
    RelativeError estimate; /* from the halves, at the stop */
    int passes;
    TargetStop stop;
} TargetResult;

/* Render passes of `settings` (each with its own seed, from settings->image.seed and the
 * pass: independent images) until `target` says stop. Returns 0, or -1 for settings
 * that cannot stop (neither a target nor a time limit nor a most passes) or when memory
 * runs out (nothing is then allocated). */
int render_to_target(const Scene *scene, const RenderSettings *settings, Estimator estimate,
                     const void *estimator_settings, const TargetSettings *target,
                     TargetResult *result);

/* Whether to stop after an even number of passes with this estimate, `seconds` spent on
 * `spp` samples per pixel; else, in *next_spp, the samples per pass of the next pair. */
int target_should_stop(const TargetSettings *target, const RelativeError *estimate, int passes,
                       double seconds, double spp, int *next_spp, TargetStop *stop);

/* What the stop says, e.g. "reached" or "time up". */
const char *target_stop_name(TargetStop stop);

/* The line a program prints: "target 1.00 %: reached 0.98 % (estimated) / 1.03 % +/- 0.02
 * (against the reference) in 12.3 s, 96 spp, 1.2e+07 rays, 12 passes (time up)".
 * reference NULL: the estimate alone. */
void target_describe(const TargetSettings *target, const RelativeError *estimate,
                     const RelativeError *against, TargetStop stop, double seconds, double spp,
                     double rays, int passes, char *text, size_t size);

#endif
