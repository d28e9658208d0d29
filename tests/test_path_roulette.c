/* test_path_roulette.c (chapter 6): the path tracer with Russian roulette
 * (lib/path_roulette.c) is unbiased: closed forms in the white furnace, the same mean
 * for every alpha, and agreement with chapter 3's estimator, which only the depth limit
 * ends, on the room.
 *
 * Roulette multiplies the weight by rho / alpha at each survival, so the second moment
 * is a geometric series in rho^2 / alpha: the variance is finite only for alpha > rho^2.
 * These tests choose rho and alpha on that side; below it the measured standard error
 * itself cannot be trusted (Figure 12's alpha = 0.01 in the room is far below it).
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include "block_agreement.h"
#include "path_check.h"
#include "path_direct.h"
#include "path_roulette.h"

/* alpha = 0.75 with depth 200, practically unlimited (furnace.h: finite second moment),
 * with and without shadow rays. */
static void test_furnace_roulette(void **state)
{
    PathSettings hitting = {.max_depth = 200, .rr_survival = 0.75};
    radiance_two_furnace(furnace_box_bordered, path_roulette_radiance, &hitting);
    PathSettings shadow = {.max_depth = 200, .shadow_rays = 1, .rr_survival = 0.75};
    radiance_two_furnace(furnace_box_bordered, path_roulette_radiance, &shadow);
}

/* Bounded weights (roulette.h) from the first segment and from the third, with and
 * without shadow rays. */
static void test_furnace_bounded_roulette(void **state)
{
    PathSettings hitting = {.max_depth = 200, .rr_throughput = 1};
    radiance_two_furnace(furnace_box_bordered, path_roulette_radiance, &hitting);
    PathSettings shadow = {.max_depth = 200, .shadow_rays = 1, .rr_throughput = 3};
    radiance_two_furnace(furnace_box_bordered, path_roulette_radiance, &shadow);
}

/* A bright uniform box, rho = 0.9, no shadow rays: bounded weights survive with 0.9 at
 * every bounce after the first (the throughput is 1 after each survival), paths are long
 * (mean 10 segments), and the mean must match (1 - 0.9^200) / 0.1. */
static void test_bounded_roulette_on_a_bright_furnace(void **state)
{
    PathSettings bounded = {.max_depth = 200, .rr_throughput = 1};
    uniform_furnace(path_roulette_radiance, &bounded, 0.9, (1.0 - pow(0.9, 200)) / 0.1);
}

/* rho = 0 sees only the emission, with a shadow ray (it meets rho = 0) and roulette. */
static void test_black_furnace(void **state)
{
    PathSettings black = {.max_depth = 10, .shadow_rays = 1, .rr_survival = 0.5};
    uniform_furnace(path_roulette_radiance, &black, 0.0, 1.0);
}

/* In the uniform furnace, alpha = 0.05, 0.5 and 1 give the same mean within their
 * combined standard errors, and the closed form. rho = 0.2, so that even alpha = 0.05 >
 * rho^2 = 0.04 has finite variance; no shadow rays, so the only variance is roulette's. */
static void test_roulette_unbiased(void **state)
{
    Scene scene;
    furnace_box_uniform(&scene, 0.2, 1.0);
    assert_int_equal(scene_prepare(&scene), 0);
    const double alphas[] = {0.05, 0.5, 1.0};
    double means[3], errors[3];
    for (int i = 0; i < 3; i++) {
        PathSettings settings = {.max_depth = 40, .rr_survival = alphas[i]};
        estimate(&scene, path_roulette_radiance, &settings, vec3(0.3, 0.3, -0.5),
                 11 + (uint64_t)i, &means[i], &errors[i]);
        print_message("    alpha %.2f: %.5f +- %.5f\n", alphas[i], means[i], errors[i]);
    }
    for (int i = 0; i < 3; i++)
        for (int j = i + 1; j < 3; j++)
            assert_true(fabs(means[i] - means[j]) <
                        TOLERANCE_SIGMAS * sqrt(errors[i] * errors[i] + errors[j] * errors[j]));
    for (int i = 0; i < 3; i++)
        assert_estimate(means[i], errors[i], (1.0 - pow(0.2, 40)) / 0.8, 0.02);
    scene_free(&scene);
}

/* On the room: bounded roulette (from segment 2) agrees with chapter 3's estimator at the
 * same depth limit, one shadow ray in both. */
static void test_bounded_roulette_agrees_on_the_room(void **state)
{
    PathSettings plain = {.max_depth = 8, .shadow_rays = 1};
    PathSettings bounded = {.max_depth = 8, .shadow_rays = 1, .rr_throughput = 2};
    assert_agree_on_the_room(path_direct_radiance, &plain, 400, path_roulette_radiance,
                             &bounded, 400);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_furnace_roulette),
        cmocka_unit_test(test_furnace_bounded_roulette),
        cmocka_unit_test(test_bounded_roulette_on_a_bright_furnace),
        cmocka_unit_test(test_black_furnace),
        cmocka_unit_test(test_roulette_unbiased),
        cmocka_unit_test(test_bounded_roulette_agrees_on_the_room),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
