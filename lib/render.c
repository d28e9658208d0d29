/* render.c (chapter 1): one sample of one pixel. See render.h. */
#include "render.h"

#include <stddef.h>

Vec3 render_sample(const Scene *scene, const ImageSettings *image, int col, int row, int sample,
                   Estimator estimate, const void *settings, RayCounts *counts)
{
#if CHAPTER >= 2
    uint64_t pixel = (uint64_t)row * (uint64_t)image->width + (uint64_t)col;
    Rng generator = rng_for_sample(image->seed, pixel, (uint64_t)sample), *rng = &generator;
    double u, v;
    pixel_position(image->sampling, sample, image->spp, rng, &u, &v);
#else
    Rng *rng = NULL;
    double u = 0.5, v = 0.5; /* the pixel's centre */
#endif
#if CHAPTER >= 7
    if (image->sampling == PIXEL_STRATIFIED)
        rng_stratify(rng, image->seed, pixel, (uint32_t)sample);
#endif
#if CHAPTER >= 8
    if (image->sampling == PIXEL_PROGRESSIVE) {
        rng_stratify(rng, image->seed, pixel, (uint32_t)sample);
        sobol_pair((uint32_t)sample, rng_hash(~rng->strata_key), &u,
                   &v); /* a key no pair uses */
    }
#endif
    Ray ray = camera_ray(&scene->camera, image->width, image->height, col, row, u, v);
    counts->camera++;
    return estimate(scene, ray, rng, settings, counts);
}
