/* test_photon.c (chapter 8): Tests of photon emission, tracing and the photon map
 * (lib/photon.c, chapter 8).
 *
 * 1. Power: photons from one lamp carry Phi / N each, Phi = pi Le A, so they add up to
 *    Phi to rounding; from two lamps of different radiance and area, the sum's mean is
 *    pi (Le_1 A_1 + Le_2 A_2) (within 4 standard errors). In a closed box of diffuse
 *    walls every photon lands on a wall: the direct map stores all of them, with total
 *    power Phi, and the caustic map none.
 * 2. Directions: chi-square goodness of fit (chi_square.h) of the emitted directions
 *    against the cosine density about the lamp's front normal, on a tilted lamp. Under
 *    that density sin^2(theta) and phi are independent and uniform (hemisphere.h), so
 *    a 10 x 10 grid in (sin^2 theta, phi / 2 pi) expects N / 100 in every cell.
 *    Significance level 1%, 100,000 photons, fixed seed. The same test rejects two
 *    planted bugs: directions uniform over the hemisphere (cos theta uniform instead of
 *    cos^2 theta), and directions about the back of the lamp.
 * 3. Tracing, against closed forms: a photon sent at a coloured mirror is stored on the
 *    floor where the mirror sends it, its power filtered by the mirror's colour, with
 *    the direction it came from and the floor's normal; a photon straight down through
 *    a glass sphere crosses two interfaces of reflectance R = ((n-1)/(n+1))^2 = 0.04 at
 *    normal incidence, and reaches the floor below with probability
 *    (1-R)^2 (1 + R^2 + R^4 + ...) = (1-R)/(1+R) (the repeated internal reflections
 *    of the sum go up and out), its power unchanged.
 * 4. The map is the same for any number of threads.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <string.h>

#include "check.h"
#include "chi_square.h"
#include "frame.h"
#include "furnace.h"
#include "photon.h"
#include "ppm.h"

/* A lamp quad of radiance le: corner p, edges e1, e2 (front normal e1 x e2). */
static void add_lamp(Scene *scene, Vec3 p, Vec3 e1, Vec3 e2, Vec3 le)
{
    Material lamp = {.name = "lamp", .kind = MATERIAL_LIGHT, .emission = le};
    int m = scene_add_material(scene, lamp);
    Vec3 p1 = vec3_add(p, e1), p2 = vec3_add(p1, e2), p3 = vec3_add(p, e2);
    assert_true(scene_add_triangle(scene, triangle_make(p, p1, p2, m)) >= 0);
    assert_true(scene_add_triangle(scene, triangle_make(p, p2, p3, m)) >= 0);
}

/* Sum of the powers of n photons emitted (channel x). */
static double emitted_power(const Scene *scene, int n)
{
    double sum = 0.0;
    for (int k = 0; k < n; k++) {
        Rng rng = rng_for_sample(17, (uint64_t)k, 0);
        double u[5];
        for (int i = 0; i < 5; i++)
            u[i] = rng_uniform(&rng);
        sum += photon_emit(scene, n, u[0], u[1], u[2], u[3], u[4]).power.x;
    }
    return sum;
}

static void test_emitted_power_adds_to_phi(void **state)
{
    Scene scene;
    scene_init(&scene);
    add_lamp(&scene, vec3(0, 0, 2), vec3(0, 1.5, 0), vec3(2, 0, 0),
             vec3(25, 25, 25)); /* A = 3 */
    assert_int_equal(scene_prepare(&scene), 0);
    double phi = PI * 25 * 3;
    assert_close(emitted_power(&scene, 1000), phi, 1e-9 * phi);
    scene_free(&scene);

    /* Two lamps: A_1 = 2, Le_1 = 10; A_2 = 0.5, Le_2 = 30. A photon's power is pi A Le / N,
     * A = 2.5: 10 pi (with probability 0.8) or 30 pi (0.2), standard deviation 8 pi. */
    scene_init(&scene);
    add_lamp(&scene, vec3(0, 0, 2), vec3(0, 1, 0), vec3(2, 0, 0), vec3(10, 10, 10));
    add_lamp(&scene, vec3(5, 0, 2), vec3(0, 0.5, 0), vec3(1, 0, 0), vec3(30, 30, 30));
    assert_int_equal(scene_prepare(&scene), 0);
    const int n = 100000;
    phi = PI * (10 * 2 + 30 * 0.5);
    double sum = emitted_power(&scene, n), std_error = 8 * PI * 2.5 / sqrt(n);
    print_message("    two lamps: %.4f, Phi = %.4f, standard error %.4f\n", sum, phi,
                  std_error);
    assert_true(fabs(sum - phi) < 4 * std_error);
    scene_free(&scene);
}

/* A closed box of Lambert walls with a lamp under its ceiling: every photon lands on a
 * wall, so the direct map stores them all and the caustic map none. */
static void test_closed_box_stores_all_power(void **state)
{
    Scene scene;
    furnace_box_uniform(&scene, 0.5, 0.0);
    add_lamp(&scene, vec3(-0.5, -0.5, 0.99), vec3(0, 0.8, 0), vec3(1, 0, 0), vec3(3, 2, 1));
    assert_int_equal(scene_prepare(&scene), 0);
    const int n = 20000;
    double phi_red = PI * 3 * 0.8;
    RayCounts counts = {0, 0, 0};
    PhotonMapSettings direct = {n, PHOTON_DIRECT, FRESNEL_EXACT, 5};
    PhotonMap map;
    assert_int_equal(ppm_photon_map(&map, &scene, &direct, 0.1, 2, &counts), 0);
    assert_int_equal(map.count, n);
    assert_int_equal(counts.bounce, (uint64_t)n);
    double red = 0.0, blue = 0.0;
    for (int i = 0; i < map.count; i++) {
        red += map.photons[i].power.x;
        blue += map.photons[i].power.z;
    }
    assert_close(red, phi_red, 1e-9 * phi_red);
    assert_close(blue, phi_red / 3, 1e-9 * phi_red);
    photon_map_free(&map);

    PhotonMapSettings caustic = {n, PHOTON_CAUSTIC, FRESNEL_EXACT, 5};
    assert_int_equal(ppm_photon_map(&map, &scene, &caustic, 0.1, 2, &counts), 0);
    assert_int_equal(map.count, 0);
    photon_map_free(&map);
    scene_free(&scene);
}

typedef PhotonRay (*Emitter)(const Scene *scene, int emitted, double u_select, double u1,
                             double u2, double u3, double u4);

/* Planted bug 1: directions uniform over the hemisphere (cos theta = 1 - u3). */
static PhotonRay uniform_emit(const Scene *scene, int emitted, double u_select, double u1,
                              double u2, double u3, double u4)
{
    PhotonRay right = photon_emit(scene, emitted, u_select, u1, u2, u3, u4);
    Vec3 n = scene->triangles[0].normal, t, b;
    vec3_basis(n, &t, &b);
    double z = 1.0 - u3, s = sqrt(1.0 - z * z);
    right.ray.dir =
        vec3_from_local(vec3(s * cos(2 * PI * u4), s * sin(2 * PI * u4), z), t, b, n);
    return right;
}

/* Planted bug 2: about the back of the lamp. */
static PhotonRay backwards_emit(const Scene *scene, int emitted, double u_select, double u1,
                                double u2, double u3, double u4)
{
    PhotonRay right = photon_emit(scene, emitted, u_select, u1, u2, u3, u4);
    right.ray.dir = vec3_neg(right.ray.dir);
    return right;
}

#define GRID 10

static double direction_p_value(Emitter emit)
{
    Scene scene;
    scene_init(&scene);
    add_lamp(&scene, vec3(1, 2, 3), vec3(0.3, 1, 0.2), vec3(1, -0.2, 0.5), vec3(5, 5, 5));
    assert_int_equal(scene_prepare(&scene), 0);
    Vec3 n = scene.triangles[0].normal, t, b;
    vec3_basis(n, &t, &b);
    enum {
        N = 100000
    };
    double observed[GRID * GRID] = {0}, expected[GRID * GRID];
    for (int k = 0; k < N; k++) {
        Rng rng = rng_for_sample(23, (uint64_t)k, 0);
        double u[5];
        for (int i = 0; i < 5; i++)
            u[i] = rng_uniform(&rng);
        PhotonRay photon = emit(&scene, N, u[0], u[1], u[2], u[3], u[4]);
        double cos_theta = vec3_dot(photon.ray.dir, n);
        if (cos_theta <= 0.0) {
            observed[0] = INFINITY; /* an impossible direction */
            continue;
        }
        double sin2 = 1.0 - cos_theta * cos_theta;
        double phi = atan2(vec3_dot(photon.ray.dir, b), vec3_dot(photon.ray.dir, t));
        int i = (int)fmin(GRID - 1, floor(sin2 * GRID));
        int j = (int)fmin(GRID - 1, floor((phi / (2 * PI) + 0.5) * GRID));
        observed[i * GRID + j] += 1.0;
    }
    for (int i = 0; i < GRID * GRID; i++)
        expected[i] = (double)N / (GRID * GRID);
    int dof;
    double statistic = chi_square_statistic(observed, expected, GRID * GRID, &dof);
    double p = chi_square_p_value(statistic, dof);
    print_message("    X^2 = %.1f, %d degrees of freedom, p = %.3g\n", statistic, dof, p);
    scene_free(&scene);
    return p;
}

static void test_directions_are_cosine_weighted(void **state)
{
    assert_true(direction_p_value(photon_emit) > 0.01);
}

static void test_wrong_directions_are_rejected(void **state)
{
    assert_true(direction_p_value(uniform_emit) < 0.01);
    assert_true(direction_p_value(backwards_emit) < 0.01);
}

/* The photon starts on the lamp (off it by the ray offset), in front of it. */
static void test_emission_starts_on_the_lamp(void **state)
{
    Scene scene;
    scene_init(&scene);
    add_lamp(&scene, vec3(0, 0, 2), vec3(0, 1.5, 0), vec3(2, 0, 0), vec3(1, 1, 1));
    assert_int_equal(scene_prepare(&scene), 0);
    PhotonRay photon = photon_emit(&scene, 1, 0.3, 0.4, 0.5, 0.6, 0.7);
    assert_true(photon.ray.origin.z < 2.0 && photon.ray.origin.z > 2.0 - 1e-8); /* faces down */
    assert_true(photon.ray.dir.z < 0.0);
    assert_close(vec3_length(photon.ray.dir), 1.0, 1e-12);
    scene_free(&scene);
}

/* A floor z = 0 (Lambert), a mirror x = 2 of colour (0.5, 0.8, 1) facing -x. */
static void mirror_scene(Scene *scene)
{
    scene_init(scene);
    Material white = {
        .name = "white", .kind = MATERIAL_LAMBERT, .reflectance = vec3(0.5, 0.5, 0.5)};
    Material mirror = {
        .name = "mirror", .kind = MATERIAL_MIRROR, .reflectance = vec3(0.5, 0.8, 1.0)};
    int w = scene_add_material(scene, white), m = scene_add_material(scene, mirror);
    Vec3 f0 = vec3(-5, -5, 0), f1 = vec3(5, -5, 0), f2 = vec3(5, 5, 0), f3 = vec3(-5, 5, 0);
    scene_add_triangle(scene, triangle_make(f0, f1, f2, w));
    scene_add_triangle(scene, triangle_make(f0, f2, f3, w));
    Vec3 m0 = vec3(2, -5, 0), m1 = vec3(2, 5, 0), m2 = vec3(2, 5, 5), m3 = vec3(2, -5, 5);
    scene_add_triangle(scene, triangle_make(m0, m1, m2, m));
    scene_add_triangle(scene, triangle_make(m0, m2, m3, m));
    add_lamp(scene, vec3(-1, -1, 4), vec3(0, 2, 0), vec3(2, 0, 0), vec3(1, 1, 1));
    assert_int_equal(scene_prepare(scene), 0);
}

static void test_mirror_photon(void **state)
{
    Scene scene;
    mirror_scene(&scene);
    /* From (0, 0, 3) to the mirror at (2, 0, 1.5), direction (0.8, 0, -0.6); reflected
     * to (-0.8, 0, -0.6), it meets the floor at the origin. */
    PhotonRay photon = {ray_through(vec3(0, 0, 3), vec3(2, 0, 1.5)), vec3(1, 1, 1)};
    Rng rng = rng_for_sample(1, 2, 3);
    RayCounts counts = {0, 0, 0};
    Photon stored;
    assert_int_equal(
        photon_trace(&scene, photon, PHOTON_CAUSTIC, FRESNEL_EXACT, &rng, &stored, &counts), 1);
    assert_close(stored.position.x, 0.0, 1e-9);
    assert_close(stored.position.y, 0.0, 1e-9);
    assert_close(stored.position.z, 0.0, 1e-9);
    assert_close(stored.incoming.x, 0.8, 1e-12); /* back towards the mirror */
    assert_close(stored.incoming.z, 0.6, 1e-12);
    assert_close(stored.normal.z, 1.0, 1e-12);
    assert_true(stored.power.x == 0.5 && stored.power.y == 0.8 && stored.power.z == 1.0);
    assert_int_equal(counts.bounce, 2);
    /* The direct map does not want it; a photon straight to the floor is the reverse. */
    assert_int_equal(
        photon_trace(&scene, photon, PHOTON_DIRECT, FRESNEL_EXACT, &rng, &stored, &counts), 0);
    PhotonRay down = {ray_through(vec3(0, 0, 3), vec3(0.5, 0.5, 0)), vec3(1, 1, 1)};
    assert_int_equal(
        photon_trace(&scene, down, PHOTON_CAUSTIC, FRESNEL_EXACT, &rng, &stored, &counts), 0);
    assert_int_equal(
        photon_trace(&scene, down, PHOTON_DIRECT, FRESNEL_EXACT, &rng, &stored, &counts), 1);
    assert_close(stored.position.x, 0.5, 1e-9);
    /* Into the lamp from below: absorbed. Up into the sky: lost. */
    PhotonRay up = {ray_through(vec3(0, 0, 3), vec3(0, 0, 5)), vec3(1, 1, 1)};
    assert_int_equal(
        photon_trace(&scene, up, PHOTON_CAUSTIC, FRESNEL_EXACT, &rng, &stored, &counts), 0);
    PhotonRay away = {ray_through(vec3(0, 0, 3), vec3(-6, 0, 4)), vec3(1, 1, 1)};
    assert_int_equal(
        photon_trace(&scene, away, PHOTON_CAUSTIC, FRESNEL_EXACT, &rng, &stored, &counts), 0);
    scene_free(&scene);
}

/* Straight down through a glass sphere onto the floor: reaches it with probability
 * (1 - R) / (1 + R), R = 0.04 (both Fresnel modes agree at normal incidence). */
static void test_glass_photons_follow_fresnel(void **state)
{
    Scene scene;
    mirror_scene(&scene);
    Material glass = {.name = "glass", .kind = MATERIAL_GLASS, .ior = 1.5};
    scene_add_sphere(&scene, (Sphere){vec3(0, 0, 2), 0.5, scene_add_material(&scene, glass)});
    assert_int_equal(scene_prepare(&scene), 0);
    const double r = 0.04, expected = (1 - r) / (1 + r);
    for (int mode = 0; mode < 2; mode++) {
        const int n = 100000;
        int reached = 0;
        RayCounts counts = {0, 0, 0};
        for (int k = 0; k < n; k++) {
            Rng rng = rng_for_sample(31, (uint64_t)k, (uint64_t)mode);
            PhotonRay photon = {{vec3(0, 0, 3.5), vec3(0, 0, -1)}, vec3(2, 2, 2)};
            Photon stored;
            if (photon_trace(&scene, photon, PHOTON_CAUSTIC, (FresnelMode)mode, &rng, &stored,
                             &counts)) {
                assert_true(stored.power.x == 2.0 && fabs(stored.position.x) < 1e-9);
                assert_close(stored.incoming.z, 1.0, 1e-12);
                reached++;
            }
        }
        double fraction = (double)reached / n, std_error = sqrt(expected * (1 - expected) / n);
        print_message("    %s: %.5f reached the floor, expected %.5f +- %.5f\n",
                      mode == FRESNEL_EXACT ? "exact" : "schlick", fraction, expected,
                      std_error);
        assert_true(fabs(fraction - expected) < 4 * std_error);
    }
    scene_free(&scene);
}

static void test_map_same_for_any_thread_count(void **state)
{
    Scene scene;
    mirror_scene(&scene);
    PhotonMap one, three;
    RayCounts counts = {0, 0, 0};
    PhotonMapSettings s1 = {30001, PHOTON_CAUSTIC, FRESNEL_EXACT, 9};
    PhotonMapSettings s3 = {30001, PHOTON_CAUSTIC, FRESNEL_EXACT, 9};
    assert_int_equal(ppm_photon_map(&one, &scene, &s1, 0.1, 1, &counts), 0);
    assert_int_equal(ppm_photon_map(&three, &scene, &s3, 0.1, 3, &counts), 0);
    assert_true(one.count > 1000);
    assert_int_equal(one.count, three.count);
    assert_int_equal(
        memcmp(one.photons, three.photons, (size_t)one.count * sizeof *one.photons), 0);
    assert_int_equal(one.grid.count, one.count);
    photon_map_free(&one);
    photon_map_free(&three);
    scene_free(&scene);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_emitted_power_adds_to_phi),
        cmocka_unit_test(test_closed_box_stores_all_power),
        cmocka_unit_test(test_directions_are_cosine_weighted),
        cmocka_unit_test(test_wrong_directions_are_rejected),
        cmocka_unit_test(test_emission_starts_on_the_lamp),
        cmocka_unit_test(test_mirror_photon),
        cmocka_unit_test(test_glass_photons_follow_fresnel),
        cmocka_unit_test(test_map_same_for_any_thread_count),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
