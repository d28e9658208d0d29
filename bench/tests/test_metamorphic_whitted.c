/* test_metamorphic_whitted.c (bench, chapter 1): the metamorphic cases (metamorphic.h)
 * with chapter 1's Whitted ray tracer.
 *
 * 64 x 64 pixels, one ray through each pixel's centre, depth 10, as chapter 1 renders:
 * deterministic, so judged bit for bit where the arithmetic is exact and otherwise value
 * by value (at most 1% of them off by more than 1e-2). The values are the estimator's
 * own doubles, compared times s^2 in a scene scaled by s (the point lights keep their
 * intensity, so their irradiance falls as 1 / s^2, beyond what a float holds at 1e40).
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include "metamorphic.h"
#include "whitted_estimator.h"

enum {
    SIDE = 64
};

static int render_whitted(const char *text, const Scene *scene, uint64_t seed, Rendering *out)
{
    WhittedSettings whitted = {10};
    int height = (int)lround(SIDE / scene_file_aspect(&scene->camera));
    ImageSettings image = {.width = SIDE, .height = height, .spp = 1};
    *out = (Rendering){SIDE, height, 1, 1, malloc(3 * sizeof(double) * SIDE * height), NULL};
    if (!out->value)
        return -1;
    RayCounts counts = {0, 0, 0};
    for (int i = 0; i < SIDE * height; i++) {
        Vec3 v = render_sample(scene, &image, i % SIDE, i / SIDE, 0, whitted_estimate, &whitted,
                               &counts);
        out->value[3 * i] = v.x;
        out->value[3 * i + 1] = v.y;
        out->value[3 * i + 2] = v.z;
    }
    return 0;
}

static void test_whitted(void **state)
{
    Renderer whitted = {"1 whitted", render_whitted, 1, 0};
    run_cases(&whitted);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_whitted),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
