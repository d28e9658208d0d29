/* test_metamorphic_direct.c (bench, chapter 3): the metamorphic cases (metamorphic.h)
 * with chapter 3's path tracer, one shadow ray per diffuse hit (eq. 21), depth 8.
 *
 * 24 x 24 pixels, 64 samples each at random positions in the pixel (PIXEL_RANDOM), so
 * that the samples are independent and each pixel's standard error is unbiased
 * (render_batches.h says why sub-pixels' are not).
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include "metamorphic_render.h"
#include "path_direct.h"

static int render_direct(const char *text, const Scene *scene, uint64_t seed, Rendering *out)
{
    PathSettings path = {.max_depth = 8, .shadow_rays = 1};
    return render_path(scene, seed, path_direct_radiance, &path, 64, out);
}

static void test_direct(void **state)
{
    Renderer direct = {"3 direct", render_direct, 0, 0};
    run_cases(&direct);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_direct),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
