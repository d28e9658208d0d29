/* test_photon_estimate.c (chapter 8): Tests of the photon density estimate
 * (lib/photon_estimate.c, chapter 8), against the closed form of direct light from a rectangle
 * (configuration_factor.h).
 *
 * A 2 x 1 lamp of radiance Le = 2 faces down from height 1.5 over a large floor. A map
 * of direct photons (PHOTON_DIRECT: stored where they first land) has, in a disk of
 * radius r around x, the flux that fell on that disk; for a Lambertian floor of
 * reflectance rho the estimate of photon_estimate.h is then rho/pi times the mean
 * irradiance over the disk. The closed form gives the irradiance at every point,
 * pi Le F(x), so the estimate's exact expectation is rho Le times F averaged over the
 * disk (computed here by quadrature), and its bias against rho Le F(x) (the box
 * kernel's blur) is known too: it is printed, and within 1.2% at these points.
 *
 * 1. Lambert, at 12 points under and beside the lamp (disks apart, so nearly
 *    independent): z = (estimate - expectation) / sigma, sigma from the binomial count
 *    of photons in the disk, each |z| under the Sidak-corrected level for 12 tests at
 *    a family-wise 0.1% (|z| < 3.95), and every estimate within its kernel bias plus
 *    4 sigma of the closed form at the point itself.
 * 2. Oren-Nayar (sigma = 0.5) seen at a grazing angle: the BRDF now depends on each
 *    photon's direction. Its expectation is the direct light there (eq. 21 with many
 *    shadow rays, area_light.c) times the same blur as Lambert's at that point; a
 *    z-test at the 0.1% level.
 * Planted bugs they reject: the estimate divided by r^2 instead of pi r^2 (z = +161 at
 * the first point); photons emitted uniformly over the hemisphere instead of by the
 * cosine (z = -33); Lambert's BRDF used for every diffuse surface (Oren-Nayar z = +17).
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include "area_light.h"
#include "configuration_factor.h"
#include "path_caustics.h"
#include "photon_estimate.h"
#include "ppm.h"

#define LAMP_A 2.0
#define LAMP_B 1.0
#define LAMP_H 1.5
#define LE 2.0
#define PHOTONS 400000
#define RADIUS 0.2

/* The quad p0 p1 p2 p3, facing along (p1 - p0) x (p2 - p0). */
static void add_quad(Scene *scene, Vec3 p0, Vec3 p1, Vec3 p2, Vec3 p3, int material)
{
    assert_true(scene_add_triangle(scene, triangle_make(p0, p1, p2, material)) >= 0);
    assert_true(scene_add_triangle(scene, triangle_make(p0, p2, p3, material)) >= 0);
}

/* The estimate by the reachable area at the point p of a surface with normal n, seen
 * from wo. */
static Vec3 estimate_at(const Scene *scene, const PhotonMap *map, double radius, Vec3 p, Vec3 n,
                        Vec3 wo, const Material *m)
{
    Vertex x = {.hit = {.t = 1.0,
                        .point = p,
                        .normal = n,
                        .triangle = 0,
                        .scale = fmax(vec3_max_abs(p), 1.0)},
                .material = m,
                .front = 1,
                .normal = n,
                .wo = wo};
    return photon_estimate_reachable(scene, map, radius, &x);
}

static void lamp_over_floor(Scene *scene, Material floor)
{
    scene_init(scene);
    Material lamp = {.name = "lamp", .kind = MATERIAL_LIGHT, .emission = vec3(LE, LE, LE)};
    int light = scene_add_material(scene, lamp), diffuse = scene_add_material(scene, floor);
    Vec3 p0 = vec3(0, 0, LAMP_H), p1 = vec3(0, LAMP_B, LAMP_H),
         p2 = vec3(LAMP_A, LAMP_B, LAMP_H), p3 = vec3(LAMP_A, 0, LAMP_H);
    scene_add_triangle(scene, triangle_make(p0, p1, p2, light)); /* facing down */
    scene_add_triangle(scene, triangle_make(p0, p2, p3, light));
    Vec3 f0 = vec3(-30, -30, 0), f1 = vec3(30, -30, 0), f2 = vec3(30, 30, 0),
         f3 = vec3(-30, 30, 0);
    scene_add_triangle(scene, triangle_make(f0, f1, f2, diffuse));
    scene_add_triangle(scene, triangle_make(f0, f2, f3, diffuse));
    assert_int_equal(scene_prepare(scene), 0);
}

static void direct_map(const Scene *scene, PhotonMap *map)
{
    RayCounts counts = {0, 0, 0};
    PhotonMapSettings settings = {PHOTONS, PHOTON_DIRECT, FRESNEL_EXACT, 77};
    assert_int_equal(ppm_photon_map(map, scene, &settings, RADIUS, 0, &counts), 0);
}

/* F averaged over the disk of radius r around (x, y): midpoint rule in polar
 * coordinates (error far below the test's noise). */
static double disk_average_factor(double x, double y, double r)
{
    enum {
        RINGS = 40,
        SECTORS = 64
    };
    double sum = 0.0;
    for (int i = 0; i < RINGS; i++) {
        double rho = r * (i + 0.5) / RINGS;
        for (int j = 0; j < SECTORS; j++) {
            double phi = 2 * PI * (j + 0.5) / SECTORS;
            sum += rho * configuration_factor_at(x + rho * cos(phi), y + rho * sin(phi), LAMP_A,
                                                 LAMP_B, LAMP_H);
        }
    }
    return sum * (r / RINGS) * (2 * PI / SECTORS) / (PI * r * r);
}

/* The standard deviation of an estimate of mean `mean` around (x, y): the photons in
 * the disk are binomial, k of N with mean k_mean = N F_disk pi r^2 / A (the disk's
 * flux pi Le F_disk pi r^2 over a photon's pi Le A / N), so the relative standard
 * deviation is sqrt((1 - p) / k_mean), p = k_mean / N. (Oren-Nayar's weights vary a
 * little from photon to photon, which this neglects.) */
static double estimate_sigma(double mean, double x, double y)
{
    double k_mean =
        PHOTONS * disk_average_factor(x, y, RADIUS) * PI * RADIUS * RADIUS / (LAMP_A * LAMP_B);
    return mean * sqrt((1.0 - k_mean / PHOTONS) / k_mean);
}

static void test_lambert_matches_configuration_factor(void **state)
{
    const double rho = 0.5;
    Material white = {
        .name = "white", .kind = MATERIAL_LAMBERT, .reflectance = vec3(rho, rho, rho)};
    Scene scene;
    lamp_over_floor(&scene, white);
    PhotonMap map;
    direct_map(&scene, &map);
    const double points[12][2] = {{1.0, 0.5}, {0.3, 0.2},   {1.7, 0.8},  {0.5, 0.8},
                                  {1.5, 0.2}, {1.0, -0.6},  {-0.6, 0.5}, {2.6, 0.5},
                                  {1.0, 1.6}, {-0.4, -0.4}, {2.4, 1.3},  {1.8, -0.5}};
    const double z_limit = 3.95; /* two-sided 1 - (1 - 0.001)^(1/12) */
    double largest_bias = 0.0;
    for (int i = 0; i < 12; i++) {
        double x = points[i][0], y = points[i][1];
        Vec3 up = vec3(0, 0, 1), wo = vec3_normalize(vec3(0.2, -0.3, 1.0));
        double estimate =
            photon_estimate_radiance(&map, RADIUS, vec3(x, y, 0), up, wo, &white).x;
        double at_point = rho * LE * configuration_factor_at(x, y, LAMP_A, LAMP_B, LAMP_H);
        double expected = rho * LE * disk_average_factor(x, y, RADIUS);
        double sigma = estimate_sigma(expected, x, y), z = (estimate - expected) / sigma;
        double bias = expected - at_point;
        largest_bias = fmax(largest_bias, fabs(bias) / at_point);
        print_message(
            "    (%4.1f, %4.1f): %.5f, disk mean %.5f +- %.5f (z %+.2f), at the point "
            "%.5f (kernel bias %+.2f%%)\n",
            x, y, estimate, expected, sigma, z, at_point, 100 * bias / at_point);
        assert_true(fabs(z) < z_limit);
        assert_true(fabs(estimate - at_point) < fabs(bias) + 4 * sigma);
        assert_true(sigma < 0.025 * expected); /* power to see a few percent */
    }
    assert_true(largest_bias < 0.012);
    photon_map_free(&map);
    scene_free(&scene);
}

static void test_oren_nayar_matches_shadow_rays(void **state)
{
    Material rough = {.name = "rough",
                      .kind = MATERIAL_OREN_NAYAR,
                      .reflectance = vec3(0.6, 0.6, 0.6),
                      .sigma = 0.5};
    Scene scene;
    lamp_over_floor(&scene, rough);
    PhotonMap map;
    direct_map(&scene, &map);
    const double x = 0.4, y = 0.3;
    Vec3 point = vec3(x, y, 0), up = vec3(0, 0, 1);
    Vec3 wo = vec3_normalize(vec3(-2.0, -1.0, 0.5)); /* 77 degrees from the normal */
    double estimate = photon_estimate_radiance(&map, RADIUS, point, up, wo, &rough).x;
    /* The direct light at the point, by eq. 21, and the blur of the kernel there. */
    double sum = 0.0, sum_squares = 0.0;
    const int n = 20000;
    RayCounts counts = {0, 0, 0};
    for (int i = 0; i < n; i++) {
        Rng rng = rng_for_sample(41, 0, (uint64_t)i);
        double v = area_light_direct(&scene, point, up, wo, &rough, 16, &rng, &counts).x;
        sum += v;
        sum_squares += v * v;
    }
    double direct = sum / n, direct_error = sqrt((sum_squares / n - direct * direct) / (n - 1));
    double blur = disk_average_factor(x, y, RADIUS) /
                  configuration_factor_at(x, y, LAMP_A, LAMP_B, LAMP_H);
    double expected = direct * blur;
    /* The photons' noise and the shadow rays' own. */
    double sigma = sqrt(pow(estimate_sigma(expected, x, y), 2) + pow(direct_error * blur, 2));
    double z = (estimate - expected) / sigma;
    print_message(
        "    Oren-Nayar: %.5f, shadow rays %.5f +- %.5f, blur %.4f: expected %.5f +- %.5f "
        "(z %+.2f)\n",
        estimate, direct, direct_error, blur, expected, sigma, z);
    assert_true(fabs(z) < 3.29); /* two-sided 0.1% */
    assert_true(sigma < 0.03 * expected);
    /* And not what a Lambert surface of the same reflectance would give. */
    assert_true(fabs(0.6 * LE * disk_average_factor(x, y, RADIUS) - expected) > 5 * sigma);
    photon_map_free(&map);
    scene_free(&scene);
}

/* The first radius follows the view and the scene's size, never ~0. A camera at the
 * origin looks along +z through a wide image plane (4 x 1, at depth 1) at a wall at depth
 * 3 s: the view is 4 x 3 s wide there, so the radius is 0.01 x 12 s. Each case says what
 * must not change it, or what it must be:
 * - the scale s = 1e-3 or 1e3 scales it (a radius in world units would not);
 * - a sphere 1e12 away and the wall 1e6 wide (out of view) change nothing (a radius from
 *   the scene's extent would grow), nor does the scene moved 1e6 s away;
 * - lamps: one above the eye and one below it (their centroid the eye, where a distance
 *   from the eye to the lamps gave 1e-16), or out of view to the side, change nothing;
 * - half the view empty (the wall only on its right): still the wall's depth;
 * - nothing in view: the farthest lamp corner's distance takes the depth's place;
 * - the eye 1e-12 from the wall: the depth is 1e-9 of the image plane's (1), not 1e-12,
 *   so the radius stays far above the rounding of the plane's coordinates.
 * The plane's height (1) in place of its width (4) would give a quarter. */
typedef enum {
    VIEW_PLAIN,
    VIEW_FAR_OBJECTS,
    VIEW_MOVED,
    VIEW_LAMPS_ABOUT_THE_EYE,
    VIEW_HALF_EMPTY,
    VIEW_EMPTY,
    VIEW_AT_THE_WALL,
    VIEW_CASES
} ViewCase;

static double view_case_radius(ViewCase view, double s)
{
    Scene scene;
    scene_init(&scene);
    Material lamp = {.name = "lamp", .kind = MATERIAL_LIGHT, .emission = vec3(1, 1, 1)};
    Material grey = {
        .name = "grey", .kind = MATERIAL_LAMBERT, .reflectance = vec3(0.5, 0.5, 0.5)};
    int l = scene_add_material(&scene, lamp), g = scene_add_material(&scene, grey);
    Vec3 at = view == VIEW_MOVED ? vec3(1e6 * s, -2e6 * s, 3e6 * s) : vec3(0, 0, 0);
    double depth = view == VIEW_AT_THE_WALL ? 1e-12 : 3 * s,
           wide = view == VIEW_FAR_OBJECTS ? 1e6 : 20 * s;
    double left = view == VIEW_HALF_EMPTY ? 0.0 : -wide,
           z = view == VIEW_EMPTY ? -depth : depth;
    add_quad(&scene, vec3_add(at, vec3(left, -wide, z)), vec3_add(at, vec3(left, wide, z)),
             vec3_add(at, vec3(wide, wide, z)), vec3_add(at, vec3(wide, -wide, z)), g);
    /* Lamps 5 s above and below the eye, or one out of view to the side (the only
     * thing left to measure when the wall is behind the eye: its farthest corners
     * sqrt(36 + 1) s away), each 2 s x 2 s. */
    for (int k = 0; k < (view == VIEW_LAMPS_ABOUT_THE_EYE ? 2 : 1); k++) {
        Vec3 c = vec3_add(at, view == VIEW_LAMPS_ABOUT_THE_EYE ? vec3(0, k ? -5 * s : 5 * s, 0)
                                                               : vec3(5 * s, 0, 0));
        add_quad(&scene, vec3_add(c, vec3(-s, 0, -s)), vec3_add(c, vec3(s, 0, -s)),
                 vec3_add(c, vec3(s, 0, s)), vec3_add(c, vec3(-s, 0, s)), l);
    }
    if (view == VIEW_FAR_OBJECTS)
        assert_true(scene_add_sphere(&scene, (Sphere){vec3(1e12, 0, 0), 1.0, g}) >= 0);
    scene.camera = camera_make(at, vec3_add(at, vec3(-2 * s, -0.5 * s, s)),
                               vec3_add(at, vec3(2 * s, -0.5 * s, s)),
                               vec3_add(at, vec3(-2 * s, 0.5 * s, s)));
    assert_int_equal(scene_prepare(&scene), 0);
    double radius = ppm_first_radius(&scene, 0.01);
    scene_free(&scene);
    return radius;
}

static void test_first_radius_follows_the_view(void **state)
{
    const char *names[VIEW_CASES] = {"plain",
                                     "far objects",
                                     "moved 1e6 away",
                                     "lamps above and below the eye",
                                     "half the view empty",
                                     "nothing in view",
                                     "the eye 1e-12 from the wall"};
    const double scales[3] = {1.0, 1e-3, 1e3};
    for (int k = 0; k < 3; k++)
        for (ViewCase view = VIEW_PLAIN; view < VIEW_CASES; view++) {
            double s = scales[k], radius = view_case_radius(view, s);
            double expected = 0.01 * 4.0 *
                              (view == VIEW_EMPTY         ? sqrt(37.0) * s
                               : view == VIEW_AT_THE_WALL ? 1e-9
                                                          : 3 * s);
            if (view == VIEW_AT_THE_WALL && k > 0)
                continue; /* the wall's distance does not scale */
            print_message("    scale %g, %s: first radius %.9g, expected %.9g\n", s,
                          names[view], radius, expected);
            assert_true(fabs(radius - expected) <= 1e-9 * expected);
        }
}

/* Only photons on a surface facing the same way count: at a floor point next to a wall
 * (normal +x), photons that landed on the wall within the radius are left out, so the
 * estimate is the floor's photons' alone: sum Phi rho / pi / (pi r^2). Without the
 * normal filter the wall's light would leak onto the floor at every corner. */
static void test_photons_on_a_wall_do_not_count_on_the_floor(void **state)
{
    enum {
        EACH = 50
    };
    Photon photons[2 * EACH];
    Rng rng = rng_for_sample(5, 0, 0);
    double floor_power = 0.0;
    for (int i = 0; i < EACH; i++) {
        double a = 2.0 * PI * rng_uniform(&rng), r = 0.1 * sqrt(rng_uniform(&rng));
        Vec3 power = vec3(0.01 * (1 + i % 3), 0.01, 0.01);
        photons[i] =
            (Photon){vec3(r * cos(a), r * sin(a), 0), vec3(0, 0, 1), vec3(0, 0, 1), power};
        floor_power += power.x;
        /* On the wall x = 0.05, within 0.1 of the origin too, arriving from above it. */
        Vec3 on_wall = vec3(0.05, 0.05 * (rng_uniform(&rng) - 0.5), 0.05 * rng_uniform(&rng));
        photons[EACH + i] =
            (Photon){on_wall, vec3(-0.6, 0, 0.8), vec3(-1, 0, 0), vec3(1, 1, 1)};
    }
    PhotonMap map;
    assert_int_equal(photon_map_build(&map, photons, 2 * EACH, 1000, 0.2), 0);
    Material white = {
        .name = "white", .kind = MATERIAL_LAMBERT, .reflectance = vec3(0.5, 0.5, 0.5)};
    Vec3 estimate = photon_estimate_radiance(&map, 0.2, vec3(0, 0, 0), vec3(0, 0, 1),
                                             vec3(0, 0, 1), &white);
    double expected = floor_power * 0.5 / PI / (PI * 0.2 * 0.2);
    print_message("    floor estimate %.6f, the floor's photons alone %.6f\n", estimate.x,
                  expected);
    assert_true(fabs(estimate.x - expected) <= 1e-12 * expected);
    photon_map_free(&map);
}

/* No dark edges. A floor (z = 0) lit evenly, irradiance E = 1, on x < 0: photons of
 * power 1/40000 on a jittered 100 x 200 grid over [-0.5, 0] x [-0.5, 0.5] (seed 9).
 * There it ends (1) at a wall x = 0 that rises from it, or (2) at an edge, a drop of h
 * to another floor, unlit, that reaches far beyond: h = 0.002, 0.02, 0.2 and 1 (a ray
 * past the edge lands there 1.2, 3, 21 and 101 times as far as the disc's point it
 * aimed at: not a point photons on this floor can reach). Near either, the disk of
 * radius r = 0.1 is partly behind the wall or off the floor, and dividing by pi r^2
 * would darken the estimate towards half at the edge. The closed form is rho E / pi at
 * every point, up to the edge: the mean of the estimate over 40 points along the edge
 * at each of 5 distances d must be within 4% of it (the pattern of reachable_area
 * quantises the disk's clipped area, and its rotation from point to point averages
 * that out; the grid's noise is far below 1%); and so must chapter 8's path, whose
 * camera ray meets the floor there (depth 2, no shadow rays: its first diffuse vertex's
 * map estimate alone). With pi r^2 (planted), the estimate at d = 0.002 is 0.51 of it. */
static void test_no_dark_edge_at_a_wall_or_a_drop(void **state)
{
    enum {
        NX = 100,
        NY = 200,
        ALONG = 40,
        KINDS = 5
    };
    static Photon photons[NX * NY];
    Rng rng = rng_for_sample(9, 0, 0);
    for (int i = 0; i < NX; i++)
        for (int j = 0; j < NY; j++) {
            Vec3 p = vec3(-0.5 + (i + rng_uniform(&rng)) * 0.5 / NX,
                          -0.5 + (j + rng_uniform(&rng)) * 1.0 / NY, 0);
            photons[i * NY + j] = (Photon){p, vec3(0, 0, 1), vec3(0, 0, 1),
                                           vec3(1.0 / 40000, 1.0 / 40000, 1.0 / 40000)};
        }
    PhotonMap map;
    assert_int_equal(photon_map_build(&map, photons, NX * NY, NX * NY, 0.1), 0);
    Material white = {
        .name = "white", .kind = MATERIAL_LAMBERT, .reflectance = vec3(0.5, 0.5, 0.5)};
    const double distances[5] = {0.002, 0.02, 0.05, 0.08, 0.2}, expected = 0.5 / PI;
    const double drops[KINDS] = {0.0, 0.002, 0.02, 0.2, 1.0}; /* 0: the wall */
    CausticPathSettings path = {{.max_depth = 2}, &map, &map, 0.1};
    for (int kind = 0; kind < KINDS; kind++) {
        Scene scene;
        scene_init(&scene);
        int m = scene_add_material(&scene, white);
        double h = drops[kind];
        if (kind == 0) { /* the floor under the wall too, and the wall facing -x */
            add_quad(&scene, vec3(-30, -30, 0), vec3(30, -30, 0), vec3(30, 30, 0),
                     vec3(-30, 30, 0), m);
            add_quad(&scene, vec3(0, -30, 0), vec3(0, -30, 30), vec3(0, 30, 30), vec3(0, 30, 0),
                     m);
        } else { /* the floor ends at x = 0, another lies h below */
            add_quad(&scene, vec3(-30, -30, 0), vec3(0, -30, 0), vec3(0, 30, 0),
                     vec3(-30, 30, 0), m);
            add_quad(&scene, vec3(-30, -30, -h), vec3(30, -30, -h), vec3(30, 30, -h),
                     vec3(-30, 30, -h), m);
        }
        assert_int_equal(scene_prepare(&scene), 0);
        double ratios[2][5];
        for (int k = 0; k < 5; k++) {
            double sum = 0.0, path_sum = 0.0;
            RayCounts counts = {0, 0, 0};
            for (int j = 0; j < ALONG; j++) {
                Vec3 p = vec3(-distances[k], -0.2 + 0.4 * (j + 0.5) / ALONG, 0);
                sum +=
                    estimate_at(&scene, &map, 0.1, p, vec3(0, 0, 1), vec3(0, 0, 1), &white).x;
                Rng path_rng = rng_for_sample(10, (uint64_t)k, (uint64_t)j);
                Ray down = {vec3_add(p, vec3(0, 0, 1)), vec3(0, 0, -1)};
                path_sum += path_caustics_radiance(&scene, down, &path_rng, &path, &counts).x;
            }
            ratios[0][k] = sum / ALONG / expected;
            ratios[1][k] = path_sum / ALONG / expected;
        }
        for (int i = 0; i < 2; i++) {
            print_message("    %-14s %s at d = 0.002 ... 0.2:", kind ? "a drop" : "the wall",
                          i ? "the path's" : "estimate / closed form");
            for (int k = 0; k < 5; k++)
                print_message(" %.4f", ratios[i][k]);
            print_message(kind ? " (h = %g)\n" : "\n", h);
            for (int k = 0; k < 5; k++)
                assert_true(fabs(ratios[i][k] - 1.0) < 0.04);
        }
        scene_free(&scene);
    }
    photon_map_free(&map);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_lambert_matches_configuration_factor),
        cmocka_unit_test(test_oren_nayar_matches_shadow_rays),
        cmocka_unit_test(test_first_radius_follows_the_view),
        cmocka_unit_test(test_photons_on_a_wall_do_not_count_on_the_floor),
        cmocka_unit_test(test_no_dark_edge_at_a_wall_or_a_drop),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
