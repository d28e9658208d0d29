/* render_batches.c (bench, chapter 7): independent batches of a stratified render, and the
 * variance of their mean. See render_batches.h. */
#include "render_batches.h"

#include <stdio.h>
#include <stdlib.h>

int render_batches(const Scene *scene, const RenderSettings *settings, int batches,
                   Estimator estimate, const void *estimator_settings, RenderResult *result)
{
    if (batches < 2 || settings->image.spp % batches != 0)
        return -1;
    size_t pixels = (size_t)settings->image.width * settings->image.height;
    PixelSum *sums = calloc(pixels, sizeof *sums); /* of the batches' means (render.h) */
    if (!sums)
        return -1;
    RenderResult r = {0};
    RenderSettings batch = *settings;
    batch.image.spp = settings->image.spp / batches;
    char label[128];
    batch.label = label;
    for (int b = 1; b <= batches && !r.interrupted; b++) {
        batch.image.seed = rng_hash(settings->image.seed ^ rng_hash((uint64_t)b));
        snprintf(label, sizeof label, "%s, batch %d of %d",
                 settings->label ? settings->label : "render", b, batches);
        RenderResult one;
        if (render(scene, &batch, estimate, estimator_settings, &one) != 0) {
            free(sums);
            return -1;
        }
        for (size_t p = 0; p < pixels; p++) {
            const float *x = one.image.pixels + 3 * p;
            pixel_sum_add(&sums[p], vec3(x[0], x[1], x[2]));
        }
        r.seconds += one.seconds;
        r.threads = one.threads;
        ray_counts_add(&r.rays, one.rays);
        r.samples += one.samples;
        r.nonfinite += one.nonfinite;
        r.interrupted = one.interrupted;
        render_result_free(&one);
    }
    r.image = image_new(settings->image.width, settings->image.height);
    r.std_error = image_new(settings->image.width, settings->image.height);
    r.average_std_error = image_new(settings->image.width, settings->image.height);
    int allocated = r.image.pixels && r.std_error.pixels && r.average_std_error.pixels;
    if (allocated)
        pixel_sums_finish(sums, &r);
    else
        render_result_free(&r);
    free(sums);
    if (!allocated)
        return -1;
    *result = r;
    return 0;
}
