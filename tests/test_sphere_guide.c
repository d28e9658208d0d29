/* test_sphere_guide.c (chapter 7): bounces aimed at the mirror and glass spheres
 * (sphere_guide.h) are drawn with the density the path tracer divides by, and change
 * the image only in its noise.
 *   - the density integrates to 1 over all directions (uniform directions, 400,000),
 *     for a point near a sphere, one far from two, one whose cones are half below its
 *     surface, and one where the cap of 1/2 holds;
 *   - the draws follow that density: for regions R of directions (the upper hemisphere,
 *     each cone, a band), the mean of [w in R] / p(w) over the draws is the solid angle
 *     of R where p > 0 (a sampler whose draws had another density q would give
 *     the integral of q / p over R instead);
 *   - a furnace: the bordered box of furnace.h with a glass and a mirror sphere in it,
 *     radiance 2 everywhere, estimated with the guide;
 *   - the room, pixel by pixel (agreement.h): the final estimator with the guide against
 *     the same without it.
 * Planted, each caught: the cone's density without its solid angle's factor 2 (the
 * integral 1.49 +- 0.006 under the glass sphere; the draws' test; the furnace 1.841 +-
 * 0.006; the room's 12 x 12 pixels did not see it, z = -3.05), the cone drawn with
 * cos theta = 1 - u1 (1 + cos_max), too wide (the draws' test; the furnace 5.2; the
 * room, z = 15), the mixture's cosine share left out of the density (all four: the
 * integral 1.49, the furnace 1.46, the room z = -22); with mis, light samples weighed
 * against the cosine density instead of the mixture the bounce draws from (the furnace
 * with mis 1.830 +- 0.005).
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include "renderer.h"
#include "agreement.h"
#include "check.h"
#include "rng.h"
#include "furnace.h"
#include "path_final.h"
#include "scene_file.h"
#include "sphere_guide.h"

/* A scene of two spheres, glass and mirror, and a diffuse floor under them. */
static void two_spheres(Scene *scene)
{
    scene_init(scene);
    Material glass = {.name = "glass", .kind = MATERIAL_GLASS, .ior = 1.5};
    Material mirror = {.name = "mirror", .kind = MATERIAL_MIRROR, .reflectance = vec3(1, 1, 1)};
    Material white = {
        .name = "white", .kind = MATERIAL_LAMBERT, .reflectance = vec3(0.5, 0.5, 0.5)};
    Sphere a = {vec3(0, 0, 1), 0.5, scene_add_material(scene, glass)};
    Sphere b = {vec3(2, 0, 0.4), 0.4, scene_add_material(scene, mirror)};
    Sphere c = {vec3(-3, 0, 1), 0.5, scene_add_material(scene, white)}; /* not specular */
    assert_true(scene_add_sphere(scene, a) >= 0);
    assert_true(scene_add_sphere(scene, b) >= 0);
    assert_true(scene_add_sphere(scene, c) >= 0);
}

typedef struct {
    const char *name;
    Vec3 x, n;
    double strength;
    int cones; /* expected number of cones */
} Place;

static const Place PLACES[] = {
    {"under the glass sphere", {0, 0, 0}, {0, 0, 1}, 8.0, 2},
    {"far from both", {0, 30, 0}, {0, 0, 1}, 8.0, 2},
    {"a cone half below", {0.8, 0, 1.0}, {0, 0, 1}, 8.0, 1},
    {"capped at 1/2", {0.2, 0, 0.2}, {0, 0, 1}, 1000.0, 2},
    {"sideways", {1, 0, 0.3}, {-1, 0, 0}, 8.0, 1},
};
enum {
    PLACE_COUNT = sizeof PLACES / sizeof PLACES[0]
};

/* Run `check` on the guide at every place of two_spheres. */
static void for_each_place(void (*check)(const Place *place, const SphereGuide *guide, int i))
{
    Scene scene;
    two_spheres(&scene);
    for (int i = 0; i < PLACE_COUNT; i++) {
        SphereGuide guide;
        sphere_guide_at(&scene, PLACES[i].x, PLACES[i].n, PLACES[i].strength, &guide);
        check(&PLACES[i], &guide, i);
    }
    scene_free(&scene);
}

static void integrates_to_one(const Place *place, const SphereGuide *guide, int i)
{
    assert_int_equal(guide->count, place->cones);
    assert_true(guide->cosine_share >= 0.5 - 1e-12);
    enum {
        N = 400000
    };
    double sum = 0.0, sum2 = 0.0;
    TestRandom rng = test_random(5, (uint64_t)i, 0);
    for (int k = 0; k < N; k++) {
        double value = 4.0 * PI * sphere_guide_pdf(guide, place->n, random_unit_vector(&rng));
        sum += value;
        sum2 += value * value;
    }
    double mean = sum / N, error = sqrt((sum2 / N - mean * mean) / (N - 1));
    print_message("    %-24s integral of p: %.4f +- %.4f (cosine share %.3f)\n", place->name,
                  mean, error, guide->cosine_share);
    assert_true(fabs(mean - 1.0) < 4.0 * error + 1e-9);
}

static void test_density_integrates_to_one(void **state) { for_each_place(integrates_to_one); }

/* Solid angle of the directions with cos(w, axis) >= c. */
static double cap_solid_angle(double c) { return 2.0 * PI * (1.0 - c); }

static void draws_follow_the_density(const Place *place, const SphereGuide *guide, int i)
{
    /* Regions: the upper hemisphere, each cone, the band 0.3 <= cos < 0.6 (where
     * the cosine part keeps p > 0 in all of them). */
    enum {
        N = 400000,
        REGIONS = 2 + SPHERE_GUIDE_MAX
    };
    int regions = 2 + guide->count;
    double sum[REGIONS] = {0}, sum2[REGIONS] = {0}, expected[REGIONS];
    expected[0] = 2.0 * PI;
    expected[1] = 2.0 * PI * (0.6 - 0.3);
    for (int k = 0; k < guide->count; k++)
        expected[2 + k] = cap_solid_angle(guide->cos_max[k]);
    TestRandom rng = test_random(6, (uint64_t)i, 0);
    for (int s = 0; s < N; s++) {
        double u = test_uniform(&rng), u1 = test_uniform(&rng), u2 = test_uniform(&rng);
        Vec3 w = sphere_guide_sample(guide, place->n, u, u1, u2);
        double p = sphere_guide_pdf(guide, place->n, w), cos_n = vec3_dot(w, place->n);
        assert_true(p > 0.0);
        int in[REGIONS] = {cos_n > 0.0, cos_n >= 0.3 && cos_n < 0.6};
        for (int k = 0; k < guide->count; k++)
            in[2 + k] = vec3_dot(w, guide->axis[k]) >= guide->cos_max[k];
        for (int r = 0; r < regions; r++) {
            double value = in[r] ? 1.0 / p : 0.0;
            sum[r] += value;
            sum2[r] += value * value;
        }
    }
    for (int r = 0; r < regions; r++) {
        double mean = sum[r] / N, error = sqrt((sum2[r] / N - mean * mean) / (N - 1));
        print_message("    %-24s region %d: %.4f +- %.4f sr (expected %.4f)\n", place->name, r,
                      mean, error, expected[r]);
        assert_true(fabs(mean - expected[r]) < 4.0 * error + 1e-9);
    }
}

static void test_draws_follow_the_density(void **state)
{
    for_each_place(draws_follow_the_density);
}

/* The bordered furnace with a glass sphere and a perfect mirror sphere: radiance 2,
 * without mis and with it (its light samples weighed against the mixture's density,
 * which the bounce's share of a lamp it hits uses too). */
static void test_furnace_with_spheres(void **state)
{
    Scene scene;
    furnace_box_bordered(&scene);
    Material glass = {.name = "glass", .kind = MATERIAL_GLASS, .ior = 1.5};
    Material mirror = {.name = "mirror", .kind = MATERIAL_MIRROR, .reflectance = vec3(1, 1, 1)};
    Sphere a = {vec3(-0.3, 0.2, -0.5), 0.35, scene_add_material(&scene, glass)};
    Sphere b = {vec3(0.5, -0.4, -0.6), 0.3, scene_add_material(&scene, mirror)};
    assert_true(scene_add_sphere(&scene, a) >= 0);
    assert_true(scene_add_sphere(&scene, b) >= 0);
    assert_int_equal(scene_prepare(&scene), 0);
    for (int mis = 0; mis < 2; mis++) {
        PathSettings settings = {.max_depth = 200,
                                 .shadow_rays = 1,
                                 .rr_throughput = 3,
                                 .mis = mis,
                                 .sphere_guide = SPHERE_GUIDE_STRENGTH};
        enum {
            N = 200000
        };
        double sum = 0.0, sum2 = 0.0;
        RayCounts counts = {0, 0, 0};
        for (int i = 0; i < N; i++) {
            Rng rng = rng_for_sample(9, 0, (uint64_t)i);
            double u1 = rng_uniform(&rng), u2 = rng_uniform(&rng);
            Ray ray = {vec3(0.1, 0.3, 0.4), unit_vector_from(u1, u2)};
            double value =
                vec3_average(path_final_radiance(&scene, ray, &rng, &settings, &counts));
            sum += value;
            sum2 += value * value;
        }
        double mean = sum / N, error = sqrt((sum2 / N - mean * mean) / (N - 1));
        print_message(
            "    furnace with a glass and a mirror sphere%s: %.5f +- %.5f (expected %.1f)\n",
            mis ? ", mis" : "", mean, error, FURNACE_BORDERED_RADIANCE);
        assert_true(fabs(mean - FURNACE_BORDERED_RADIANCE) < 4.0 * error);
        assert_true(error < 0.01);
    }
    scene_free(&scene);
}

/* The room at 12 x 12 pixels, depth 8: with the guide against without, independent
 * numbers (PIXEL_RANDOM) so that both renders' per-pixel errors are exact. */
static void test_room_agrees_without_the_guide(void **state)
{
    Scene scene;
    char error[256];
    assert_int_equal(scene_load("scenes/room.scene", &scene, error, sizeof error), 0);
    MirrorPlanes mirrors;
    assert_int_equal(mirror_light_find_planes(&scene, &mirrors), 0);
    PathSettings plain = {.max_depth = 8,
                          .shadow_rays = 1,
                          .rr_throughput = 1,
                          .mirror_light = 8,
                          .mirrors = &mirrors};
    PathSettings guided = plain;
    guided.sphere_guide = SPHERE_GUIDE_STRENGTH;
    RenderSettings a = {{12, 12, 4096, PIXEL_RANDOM, 21}, 0, 0, "test"};
    RenderSettings b = {{12, 12, 4096, PIXEL_RANDOM, 22}, 0, 0, "test"};
    RenderResult ra, rb;
    assert_int_equal(render(&scene, &a, path_final_radiance, &guided, &ra), 0);
    assert_int_equal(render(&scene, &b, path_final_radiance, &plain, &rb), 0);
    Agreement agreement =
        agreement_test(&ra.image, &ra.std_error, &rb.image, &rb.std_error, 0.01);
    agreement_print("room, guided against cosine only", &agreement);
    assert_true(agreement_holds(&agreement));
    render_result_free(&ra);
    render_result_free(&rb);
    mirror_planes_free(&mirrors);
    scene_free(&scene);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_density_integrates_to_one),
        cmocka_unit_test(test_draws_follow_the_density),
        cmocka_unit_test(test_furnace_with_spheres),
        cmocka_unit_test(test_room_agrees_without_the_guide),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
