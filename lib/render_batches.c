/* render_batches.c (chapter 7): independent batches of a stratified render, and the
 * variance of their mean. See render_batches.h. */
#include "render_batches.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

/* Welford's update (render.h) of one value's running mean and M2 with its n-th draw. */
static void welford(double *mean, double *m2, int n, double x)
{
    double delta = x - *mean;
    *mean += delta / n;
    *m2 += delta * (x - *mean);
}

/* sqrt(M2 / (B - 1) / B): the standard error of the mean of B draws. */
static float standard_error(double m2, int batches)
{
    return (float)sqrt(m2 / (batches - 1) / batches);
}

int render_batches(const Scene *scene, const RenderSettings *settings, int batches,
                   Estimator estimate, const void *estimator_settings, RenderResult *result)
{
    if (batches < 2 || settings->spp % batches != 0)
        return -1;
    size_t pixels = (size_t)settings->width * settings->height;
    RenderResult r = {0};
    r.image = image_new(settings->width, settings->height);
    r.std_error = image_new(settings->width, settings->height);
    r.average_std_error = image_new(settings->width, settings->height);
    double *mean = calloc(4 * pixels, sizeof *mean); /* three channels, then the grey */
    double *m2 = calloc(4 * pixels, sizeof *m2);
    if (!r.image.pixels || !r.std_error.pixels || !r.average_std_error.pixels || !mean || !m2) {
        free(mean);
        free(m2);
        render_result_free(&r);
        return -1;
    }
    RenderSettings batch = *settings;
    batch.spp = settings->spp / batches;
    char label[128];
    batch.label = label;
    for (int b = 1; b <= batches && !r.interrupted; b++) {
        batch.seed = rng_hash(settings->seed ^ rng_hash((uint64_t)b));
        snprintf(label, sizeof label, "%s, batch %d of %d", settings->label ? settings->label : "render",
                 b, batches);
        RenderResult one;
        if (render(scene, &batch, estimate, estimator_settings, &one) != 0) {
            free(mean);
            free(m2);
            render_result_free(&r);
            return -1;
        }
        for (size_t p = 0; p < pixels; p++) {
            const float *x = one.image.pixels + 3 * p;
            for (int c = 0; c < 3; c++)
                welford(&mean[3 * p + c], &m2[3 * p + c], b, x[c]);
            welford(&mean[3 * pixels + p], &m2[3 * pixels + p], b, ((double)x[0] + x[1] + x[2]) / 3.0);
        }
        r.seconds += one.seconds;
        r.threads = one.threads;
        ray_counts_add(&r.rays, one.rays);
        r.samples += one.samples;
        r.nonfinite += one.nonfinite;
        r.interrupted = one.interrupted;
        render_result_free(&one);
    }
    for (size_t p = 0; p < pixels; p++) {
        for (int c = 0; c < 3; c++) {
            r.image.pixels[3 * p + c] = (float)mean[3 * p + c];
            r.std_error.pixels[3 * p + c] = standard_error(m2[3 * p + c], batches);
            r.average_std_error.pixels[3 * p + c] = standard_error(m2[3 * pixels + p], batches);
        }
    }
    free(mean);
    free(m2);
    *result = r;
    return 0;
}
