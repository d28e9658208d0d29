/* test_path.c (chapter 2): the path tracer that finds light by hitting it (lib/path.c) is
 * unbiased: closed forms in a white furnace, a coloured mirror and glass seen from
 * outside.
 *
 * White furnace (furnace.h): in a closed box whose every surface is Lambertian with
 * reflectance rho and emits Le, the radiance is L = Le + rho L = Le / (1 - rho), and a
 * path of at most D segments sees exactly the series' first D terms,
 *     L_D = Le (1 - rho^D) / (1 - rho).
 * In the uniform box this estimator has zero variance (every vertex adds Le and every
 * bounce multiplies by rho, whatever the direction): its mean must be exact. The checks
 * are path_check.h's.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include "path_check.h"

/* rho = 0.5, D = 6: (1 - 0.5^6) / 0.5 = 1.96875. */
static void test_furnace_truncated_series(void **state)
{
    PathSettings settings = {.max_depth = 6};
    uniform_furnace(path_radiance, &settings, 0.5, (1.0 - pow(0.5, 6)) / 0.5);
}

/* Reflectance 0 and 1: rho = 0 sees only the emission; rho = 1 with depth D sees
 * exactly D times it (every term of the series is Le). Both have zero variance. */
static void test_furnace_reflectance_extremes(void **state)
{
    PathSettings settings = {.max_depth = 10};
    uniform_furnace(path_radiance, &settings, 0.0, 1.0);
    uniform_furnace(path_radiance, &settings, 1.0, 10.0);
}

static void test_coloured_mirror(void **state)
{
    PathSettings settings = {.max_depth = 10};
    coloured_mirror(path_radiance, &settings, 0);
}

/* Glass seen from outside, at normal incidence: a glass sphere (index 1.5) in a box of
 * lamps, the wall behind the camera red (1, 0, 0), the other five blue (0, 0, 1). A ray
 * along the sphere's axis meets both surfaces head on, where R = (0.5 / 2.5)^2 = 0.04
 * (Schlick and exact agree there). Each time it reflects (probability R) it turns back;
 * each time it refracts it goes on along the axis. It leaves towards the red wall after
 * an odd number of reflections, so the red share is
 *     R + (1 - R)^2 R (1 + R^2 + R^4 + ...) = 2 R / (1 + R) = 0.076923,
 * and every sample is either red or blue, nothing lost. 200,000 samples, within 4
 * standard errors (about 0.0024). Glass that refracts with probability R instead of
 * 1 - R turns back 96% of the time at the first surface, and a ray that got in mostly
 * stays trapped: red share 0.978 (the planted bug). */
static void glass_from_outside(const PathSettings *settings, uint64_t stream,
                               const char *mode_name)
{
    Scene scene;
    scene_init(&scene);
    Material red = {.name = "red", .kind = MATERIAL_LIGHT, .emission = vec3(1, 0, 0)};
    Material blue = {.name = "blue", .kind = MATERIAL_LIGHT, .emission = vec3(0, 0, 1)};
    Material glass = {.name = "glass", .kind = MATERIAL_GLASS, .ior = 1.5};
    int red_index = scene_add_material(&scene, red),
        blue_index = scene_add_material(&scene, blue);
    for (int axis = 0; axis < 3; axis++)
        for (int side = -1; side <= 1; side += 2)
            furnace_wall_piece(&scene, axis, side, -1.0, 1.0, -1.0, 1.0,
                               axis == 0 && side < 0 ? red_index : blue_index);
    assert_true(scene_add_sphere(&scene, (Sphere){vec3(0.3, 0, 0), 0.3,
                                                  scene_add_material(&scene, glass)}) >= 0);
    assert_int_equal(scene_prepare(&scene), 0);
    const double r = 0.04, expected = 2.0 * r / (1.0 + r);
    RayCounts counts = {0, 0, 0};
    double red_share = 0.0;
    int lost = 0;
    for (int i = 0; i < SAMPLES; i++) {
        Rng rng = rng_for_sample(31, stream, (uint64_t)i);
        Vec3 radiance = path_radiance(&scene, (Ray){vec3(-0.5, 0, 0), vec3(1, 0, 0)}, &rng,
                                      settings, &counts);
        lost += !(radiance.y == 0.0 && radiance.x + radiance.z == 1.0);
        red_share += radiance.x / SAMPLES;
    }
    double std_error = sqrt(expected * (1.0 - expected) / SAMPLES);
    print_message(
        "    %s: red share %.5f, expected %.5f +- %.5f; %d samples neither red nor blue\n",
        mode_name, red_share, expected, std_error, lost);
    assert_true(fabs(red_share - expected) < TOLERANCE_SIGMAS * std_error);
    assert_int_equal(lost, 0);
    scene_free(&scene);
}

static void test_glass_from_outside_at_normal_incidence(void **state)
{
    PathSettings settings = {.max_depth = 64};
    glass_from_outside(&settings, 0, "Schlick");
}

#if CHAPTER >= 4
/* The same with the exact Fresnel reflectance (chapter 4). */
static void test_glass_from_outside_exact_fresnel(void **state)
{
    PathSettings settings = {.max_depth = 64, .fresnel = FRESNEL_EXACT};
    glass_from_outside(&settings, 1, "exact");
}
#endif

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_furnace_truncated_series),
        cmocka_unit_test(test_furnace_reflectance_extremes),
        cmocka_unit_test(test_coloured_mirror),
        cmocka_unit_test(test_glass_from_outside_at_normal_incidence),
#if CHAPTER >= 4
        cmocka_unit_test(test_glass_from_outside_exact_fresnel),
#endif
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
