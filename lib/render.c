/* render.c (chapter 1): one sample of one pixel, and the loop that makes the image. See
 * render.h. */
#include "render.h"

#if CHAPTER >= 2
Vec3 render_sample(const Scene *scene, const ImageSettings *image, int col, int row, int sample,
                   Estimator estimate, const void *settings, RayCounts *counts)
{
    uint64_t pixel = (uint64_t)row * (uint64_t)image->width + (uint64_t)col;
    Rng generator = rng_for_sample(image->seed, pixel, (uint64_t)sample), *rng = &generator;
    double u, v;
    pixel_position(image->sampling, sample, image->spp, rng, &u, &v);
#if CHAPTER >= 7
    if (image->sampling == PIXEL_STRATIFIED)
        rng_stratify(rng, image->seed, pixel, (uint32_t)sample);
#endif
#if CHAPTER >= 8
    if (image->sampling == PIXEL_PROGRESSIVE) {
        rng_stratify(rng, image->seed, pixel, (uint32_t)sample);
        /* The position's own key, ~strata_key, is one that no pair of the path uses. */
        sobol_pair((uint32_t)sample, rng_hash(~rng->strata_key), &u, &v);
    }
#endif
    Ray ray = camera_ray(&scene->camera, image->width, image->height, col, row, u, v);
    counts->camera++;
    return estimate(scene, ray, rng, settings, counts);
}
#else
Vec3 render_sample(const Scene *scene, const ImageSettings *image, int col, int row, int sample,
                   Estimator estimate, const void *settings, RayCounts *counts)
{
    double u = 0.5, v = 0.5; /* the pixel's centre */
    Ray ray = camera_ray(&scene->camera, image->width, image->height, col, row, u, v);
    counts->camera++;
    return estimate(scene, ray, settings, counts);
}
#endif

void render_image(const Scene *scene, const ImageSettings *image, Estimator estimate,
                  const void *settings, Vec3 *pixels, RayCounts *counts)
{
    for (int row = 0; row < image->height; row++) {
        for (int col = 0; col < image->width; col++) {
            Vec3 mean = vec3(0, 0, 0);
            for (int sample = 0; sample < image->spp; sample++) {
                Vec3 x =
                    render_sample(scene, image, col, row, sample, estimate, settings, counts);
                double n = sample + 1;
                mean = vec3(mean.x + (x.x - mean.x) / n, mean.y + (x.y - mean.y) / n,
                            mean.z + (x.z - mean.z) / n);
            }
            pixels[(long)row * image->width + col] = mean;
        }
    }
}
