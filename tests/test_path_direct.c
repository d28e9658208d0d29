/* test_path_direct.c (chapter 3): the path tracer with shadow rays (lib/path_direct.c) is
 * unbiased: the white furnace's closed form, the coloured mirror, and agreement with
 * chapter 2's estimator, which finds light only by hitting it, on the report's room.
 *
 * Shadow rays in a box that emits up to its edges have infinite variance (furnace.h), so
 * the furnace here is the bordered box, whose radiance is 2 everywhere; a depth of 40
 * leaves out about 1e-7 of the series.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include "block_agreement.h"
#include "path_check.h"
#include "path_direct.h"

/* One and four shadow rays. */
static void test_furnace_shadow_rays(void **state)
{
    PathSettings one = {.max_depth = 40, .shadow_rays = 1};
    radiance_two_furnace(furnace_box_bordered, path_direct_radiance, &one);
    PathSettings four = {.max_depth = 40, .shadow_rays = 4};
    radiance_two_furnace(furnace_box_bordered, path_direct_radiance, &four);
}

/* The coloured mirror of path_check.h, with and without a shadow ray. */
static void test_coloured_mirror(void **state)
{
    for (int m = 0; m < 2; m++) {
        PathSettings settings = {.max_depth = 10, .shadow_rays = m};
        coloured_mirror(path_direct_radiance, &settings, (uint64_t)m);
    }
}

/* On the room, glass and mirrors included: one shadow ray against chapter 2's estimator.
 * A double-counted or missing light path, the classic bug when shadow rays are added,
 * shifts every block (block_agreement.h). */
static void test_shadow_rays_agree_with_hitting_on_the_room(void **state)
{
    PathSettings hitting = {.max_depth = 6}, shadow = {.max_depth = 6, .shadow_rays = 1};
    assert_agree_on_the_room(path_radiance, &hitting, 2000, path_direct_radiance, &shadow, 400);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_furnace_shadow_rays),
        cmocka_unit_test(test_coloured_mirror),
        cmocka_unit_test(test_shadow_rays_agree_with_hitting_on_the_room),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
