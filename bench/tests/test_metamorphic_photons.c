/* test_metamorphic_photons.c (bench, chapter 8): the metamorphic cases (metamorphic.h)
 * with chapter 8's progressive photon mapping (bench/ppm.h) on chapter 7's final
 * estimator, its first radius and images at the first vertex as chapter 8 takes them.
 * 24 x 24 pixels, 24 passes of 2 samples and 1500 photons: a fixed count, not chapter 8's
 * equal time, which would give the two images different expectations. Each pixel's
 * standard error comes from its passes' spread (23 degrees of freedom); the photons are
 * shared by all pixels, so only pixels are judged. A scaling by a power of two is
 * judged by agreement: the reachable area's pattern turns by a hash of the point's bits.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include "metamorphic_render.h"
#include "experiment.h"
#include "ppm.h"

enum {
    PASSES = 24
};

/* The first radius's fraction of the view at 800 pixels wide, as chapters/ch08_photon_map.c
 * takes it. */

static int render_photons(const char *text, const Scene *scene, uint64_t seed, Rendering *out)
{
    MirrorPlanes mirrors;
    if (mirror_light_find_planes(scene, &mirrors) != 0)
        return -1;
    Options defaults = {.depth = 64, .shadow_rays = 1};
    PathSettings path = experiment_final_estimator(&defaults, &mirrors);
    path.mirror_light = 1;
    int height = (int)lround(MONTE_CARLO_SIDE / scene_file_aspect(&scene->camera));
    PpmSettings ppm = {
        path,
        1500,
        ppm_first_radius(scene, PPM_FIRST_RADIUS_AT_800) * 800.0 / MONTE_CARLO_SIDE,
        PPM_ALPHA,
        2,
        PASSES,
        0.0,
        0.0,
        0.0};
    RenderSettings settings = {{MONTE_CARLO_SIDE, height, 2, PIXEL_RANDOM, seed}, 0, 0, "test"};
    PpmResult result;
    int status = ppm_render(scene, &settings, &ppm, &result);
    if (status == 0) {
        status = rendering_of(&result.render, PASSES, 0, out);
        ppm_result_free(&result);
    }
    mirror_planes_free(&mirrors);
    return status;
}

static void test_photons(void **state)
{
    Renderer photons = {"8 photons", render_photons, 0, 1};
    run_cases(&photons);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_photons),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
