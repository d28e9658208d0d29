/* test_path_final.c (chapter 7): the final path tracer (lib/path_final.c) is unbiased with
 * each of its levers: multiple importance sampling (mis.h) and the lamps' images in a
 * planar mirror (mirror_light.h), in furnaces and against chapter 3's estimator on the
 * room. (The sphere guide and the stratified pairs have tests of their own.)
 *
 * In the room mis moves little light (the lamp is seen from afar, where light
 * sampling's density dwarfs the BRDF's), so its furnace, whose lights are close, is the
 * test with power for it. The mirrored box is furnace.h's bordered box with one wall a
 * perfect mirror: a mirror sends out the radiance that arrives, so the radiance is
 * still 2 everywhere, and the other walls' lights are also seen in the mirror.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include "block_agreement.h"
#include "path_check.h"
#include "path_direct.h"
#include "path_final.h"

/* The bordered box with its wall at x = +1 a mirror of reflectance 1, prepared. */
static void mirrored_box(Scene *scene)
{
    furnace_box_bordered(scene);
    Material mirror = {.name = "mirror", .kind = MATERIAL_MIRROR, .reflectance = vec3(1, 1, 1)};
    int mirror_index = scene_add_material(scene, mirror);
    assert_true(mirror_index >= 0);
    for (int i = 0; i < scene->triangle_count; i++)
        if (scene->triangles[i].normal.x < -0.5)
            scene->triangles[i].material = mirror_index;
    assert_int_equal(scene_prepare(scene), 0);
}

/* The mean radiance in `scene` with the settings, the scene's mirror planes added. */
static void estimate_with_mirrors(const Scene *scene, PathSettings settings, uint64_t seed,
                                  double *mean, double *std_error)
{
    MirrorPlanes mirrors;
    assert_int_equal(mirror_light_find_planes(scene, &mirrors), 0);
    settings.mirrors = &mirrors;
    estimate(scene, path_final_radiance, &settings, vec3(0.1, -0.2, 0.3), seed, mean,
             std_error);
    mirror_planes_free(&mirrors);
}

/* The mirrored box gives 2. */
static void mirrored_furnace(const PathSettings *settings)
{
    Scene scene;
    mirrored_box(&scene);
    double mean, std_error;
    estimate_with_mirrors(&scene, *settings, 7, &mean, &std_error);
    assert_estimate(mean, std_error, FURNACE_BORDERED_RADIANCE, 0.01);
    scene_free(&scene);
}

/* mis, one and four shadow rays: the power heuristic's weights of the two ways of
 * finding each light sum to 1, so the mean stays 2. */
static void test_furnace_mis(void **state)
{
    PathSettings one = {.max_depth = 40, .shadow_rays = 1, .mis = 1};
    radiance_two_furnace(furnace_box_bordered, path_final_radiance, &one);
    PathSettings four = {.max_depth = 40, .shadow_rays = 4, .mis = 1, .rr_throughput = 3};
    radiance_two_furnace(furnace_box_bordered, path_final_radiance, &four);
}

/* The lights seen in the mirror wall: without shadow rays (light found only by hitting
 * it), with shadow rays alone, with the mirror's images at every diffuse hit, and at the
 * first two only with mis (later hits find that light by hitting it). Each must give 2.
 * Bounded roulette keeps cheap the long paths that the mirror allows (depth 200). */
static void test_furnace_mirror_light(void **state)
{
    PathSettings hitting = {.max_depth = 200, .rr_throughput = 3};
    mirrored_furnace(&hitting);
    PathSettings shadow = {.max_depth = 200, .shadow_rays = 1, .rr_throughput = 3};
    mirrored_furnace(&shadow);
    PathSettings mirror = {
        .max_depth = 200, .shadow_rays = 1, .rr_throughput = 3, .mirror_light = 200};
    mirrored_furnace(&mirror);
    PathSettings both = {
        .max_depth = 200, .shadow_rays = 2, .rr_throughput = 3, .mis = 1, .mirror_light = 2};
    mirrored_furnace(&both);
}

/* A tinted mirror (reflectance 0.5, 0.4, 0.3) in the mirrored box, depth limit 3: no
 * closed form, but shadow rays alone and with the mirror's images must agree (each
 * within its standard error; the box has little noise, so this sees 0.2%). With depth
 * 3 only a diffuse hit on the first segment may use the images (two more segments). */
static void test_mirror_light_agrees_at_a_depth_limit(void **state)
{
    Scene scene;
    mirrored_box(&scene);
    scene.materials[scene.material_count - 1].reflectance = vec3(0.5, 0.4, 0.3);
    PathSettings plain = {.max_depth = 3, .shadow_rays = 1};
    PathSettings image = {.max_depth = 3, .shadow_rays = 1, .mirror_light = 3};
    double mean_plain, error_plain, mean_image, error_image;
    estimate_with_mirrors(&scene, plain, 100, &mean_plain, &error_plain);
    estimate_with_mirrors(&scene, image, 101, &mean_image, &error_image);
    print_message("    shadow rays %.5f +- %.5f, with the images %.5f +- %.5f\n", mean_plain,
                  error_plain, mean_image, error_image);
    assert_true(fabs(mean_plain - mean_image) <
                TOLERANCE_SIGMAS * sqrt(error_plain * error_plain + error_image * error_image));
    scene_free(&scene);
}

/* On the room: multiple importance sampling agrees with chapter 3's estimator. */
static void test_mis_agrees_on_the_room(void **state)
{
    PathSettings plain = {.max_depth = 6, .shadow_rays = 1};
    PathSettings mis = {.max_depth = 6, .shadow_rays = 2, .mis = 1};
    assert_agree_on_the_room(path_direct_radiance, &plain, 400, path_final_radiance, &mis, 300);
}

/* On the room, the mirror wall's image of the lamp agrees with chapter 3's estimator: at
 * every diffuse hit, and with mis at the first one only. The mirror is tinted
 * (reflectance 0.5, 0.7, 0.9 instead of 1) so that its reflectance must be applied to
 * the image's light. The depth limit 6 makes the mirror light's own limit matter (a
 * diffuse hit on segment 5 may not use it). */
static void test_mirror_light_agrees_on_the_room(void **state)
{
    Scene scene;
    char error[256];
    assert_int_equal(scene_load("scenes/room.scene", &scene, error, sizeof error), 0);
    int mirror = scene_file_material(&scene, "mirror");
    assert_true(mirror >= 0);
    scene.materials[mirror].reflectance = vec3(0.5, 0.7, 0.9);
    MirrorPlanes mirrors;
    assert_int_equal(mirror_light_find_planes(&scene, &mirrors), 0);
    PathSettings plain = {.max_depth = 6, .shadow_rays = 1};
    PathSettings image = {
        .max_depth = 6, .shadow_rays = 1, .mirror_light = 6, .mirrors = &mirrors};
    assert_agree_on(&scene, path_direct_radiance, &plain, 2000, path_final_radiance, &image,
                    2000);
    PathSettings both = {
        .max_depth = 6, .shadow_rays = 2, .mis = 1, .mirror_light = 1, .mirrors = &mirrors};
    assert_agree_on(&scene, path_direct_radiance, &plain, 2000, path_final_radiance, &both,
                    1000);
    mirror_planes_free(&mirrors);
    scene_free(&scene);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_furnace_mis),
        cmocka_unit_test(test_furnace_mirror_light),
        cmocka_unit_test(test_mirror_light_agrees_at_a_depth_limit),
        cmocka_unit_test(test_mis_agrees_on_the_room),
        cmocka_unit_test(test_mirror_light_agrees_on_the_room),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
