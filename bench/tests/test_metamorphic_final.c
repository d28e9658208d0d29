/* test_metamorphic_final.c (bench, chapter 7): the metamorphic cases (metamorphic.h)
 * with chapter 7's final estimator, as Figure 7 renders it (experiment_final_estimator):
 * depth 64, one shadow ray, roulette with bounded weights, the lamps' images in every
 * planar mirror (found in each scene afresh) at every diffuse hit, bounces aimed at the
 * spheres.
 *
 * 24 x 24 pixels, 48 samples each at random positions (PIXEL_RANDOM, without the
 * stratified pairs, so that each pixel's samples are independent and its standard
 * error unbiased).
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include "metamorphic_render.h"
#include "experiment.h"
#include "path_final.h"

static int render_final(const char *text, const Scene *scene, uint64_t seed, Rendering *out)
{
    MirrorPlanes mirrors;
    if (mirror_light_find_planes(scene, &mirrors) != 0)
        return -1;
    Options figure7 = {.depth = 64, .shadow_rays = 1};
    PathSettings path = experiment_final_estimator(&figure7, &mirrors);
    int status = render_path(scene, seed, path_final_radiance, &path, 48, out);
    mirror_planes_free(&mirrors);
    return status;
}

static void test_final(void **state)
{
    Renderer final = {"7 final", render_final, 0, 0};
    run_cases(&final);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_final),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
