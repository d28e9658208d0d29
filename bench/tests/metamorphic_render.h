/* metamorphic_render.h (bench, chapter 2): a Monte Carlo render for the metamorphic
 * tests (metamorphic.h), as doubles with each value's standard error (include after
 * cmocka.h).
 */
#ifndef METAMORPHIC_RENDER_H
#define METAMORPHIC_RENDER_H

#include "metamorphic.h"
#include "renderer.h"

enum {
    MONTE_CARLO_SIDE = 24
};

/* The render's image and standard errors as a Rendering. */
static inline int rendering_of(const RenderResult *result, int samples, int independent,
                               Rendering *out)
{
    long n = 3L * result->image.width * result->image.height;
    *out = (Rendering){result->image.width,
                       result->image.height,
                       samples,
                       independent,
                       malloc((size_t)n * sizeof(double)),
                       malloc((size_t)n * sizeof(double))};
    if (!out->value || !out->error)
        return -1;
    for (long i = 0; i < n; i++) {
        out->value[i] = result->image.pixels[i];
        out->error[i] = result->std_error.pixels[i];
    }
    return 0;
}

/* MONTE_CARLO_SIDE pixels wide, `spp` samples at random positions in each pixel. */
static inline int render_path(const Scene *scene, uint64_t seed, Estimator estimate,
                              const void *settings, int spp, Rendering *out)
{
    int height = (int)lround(MONTE_CARLO_SIDE / scene_file_aspect(&scene->camera));
    RenderSettings render_settings = {
        {MONTE_CARLO_SIDE, height, spp, PIXEL_RANDOM, seed}, 0, 0, "test"};
    RenderResult result;
    if (render(scene, &render_settings, estimate, settings, &result) != 0)
        return -1;
    int status = rendering_of(&result, spp, 1, out);
    render_result_free(&result);
    return status;
}

#endif
