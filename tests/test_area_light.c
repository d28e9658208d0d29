/* test_area_light.c (chapter 3): Tests of area-light sampling and the direct-light estimator of
 * eq. 21 (lib/area_light.c, chapter 3).
 *
 * 1. Chi-square goodness of fit (chi_square.h) of area_light_sample: two lights of
 *    different areas; each sample is binned by which light it landed on and where, in
 *    the light's own (u, v) coordinates (eq. 16) on an n x n grid. Uniform density
 *    over the total area means each light gets area_i / A of the samples, spread
 *    uniformly over its triangle {u, v >= 0, u + v <= 1}: a grid cell below the
 *    diagonal expects all of its share, a cell the diagonal cuts expects half.
 *    Significance level 1%, 400,000 samples, fixed seed. The same test rejects a
 *    deliberately wrong sampler (s = u1 instead of sqrt(u1), which crowds the samples
 *    towards v0): observed X^2 = 330,686 with 71 degrees of freedom, p = 0
 *    (the correct sampler: X^2 = 83.8, p = 0.14).
 * 2. Eq. 21 against a closed form: a point on the floor right under the corner of a
 *    parallel a x b rectangular light at height h. Its configuration factor is
 *        F = 1/(2 pi) [ A/sqrt(1+A^2) atan(B/sqrt(1+A^2)) + B/sqrt(1+B^2) atan(A/sqrt(1+B^2))
 * ], A = a/h, B = b/h, so a Lambertian point there reflects L = rho Le F
 *    (configuration_factor.h, shared with the photon tests).
 *    The mean of many estimates must be within 4 standard errors of it, for M = 1 and
 *    M = 64 shadow rays; and M = 64 must have about 1/64 of the variance of M = 1.
 *    The same light cut into three triangles of unequal areas must give the same
 *    value: a triangle must be chosen by its area, not by its index.
 * 3. One-sided lamps: a point behind the lamp gets nothing (and spends no shadow ray);
 *    no point anywhere around it gets negative light.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include "area_light.h"
#include "check.h"
#include "chi_square.h"
#include "configuration_factor.h"

#define GRID 8
#define SAMPLES 400000

/* Two lights: a triangle of area 2 and one of area 0.5, in different places. */
static void two_lights(Scene *scene)
{
    scene_init(scene);
    Material lamp = {.name = "lamp", .kind = MATERIAL_LIGHT, .emission = vec3(1, 2, 3)};
    int m = scene_add_material(scene, lamp);
    scene_add_triangle(scene, triangle_make(vec3(0, 0, 0), vec3(2, 0, 0), vec3(0, 2, 0), m));
    scene_add_triangle(scene, triangle_make(vec3(5, 0, 1), vec3(5, 1, 1), vec3(5, 0, 2), m));
    assert_int_equal(scene_prepare(scene), 0);
}

/* The bin of point p on light triangle `light` (its (u, v) cell). */
static int bin_of(const Scene *scene, int light, Vec3 p)
{
    const Triangle *t = &scene->triangles[scene->light_triangles[light]];
    /* Solve p - v0 = u e1 + v e2 in the least-squares sense (exact for p in the plane). */
    Vec3 d = vec3_sub(p, t->v0);
    double a = vec3_dot(t->e1, t->e1), b = vec3_dot(t->e1, t->e2), c = vec3_dot(t->e2, t->e2);
    double r = vec3_dot(d, t->e1), s = vec3_dot(d, t->e2), det = a * c - b * b;
    double u = (c * r - b * s) / det, v = (a * s - b * r) / det;
    int i = (int)fmin(GRID - 1, fmax(0, floor(u * GRID)));
    int j = (int)fmin(GRID - 1, fmax(0, floor(v * GRID)));
    return (light * GRID + i) * GRID + j;
}

/* Which light a point lies on: the one whose plane it is in. */
static int light_of(const Scene *scene, Vec3 p)
{
    for (int k = 0; k < scene->light_count; k++) {
        const Triangle *t = &scene->triangles[scene->light_triangles[k]];
        if (fabs(vec3_dot(vec3_sub(p, t->v0), t->normal)) < 1e-9)
            return k;
    }
    fail_msg("sample on no light");
    return -1;
}

typedef LightSample (*Sampler)(const Scene *scene, double u_select, double u1, double u2);

/* The p-value of the chi-square test of `sample` against uniform density by area. */
static double area_sampling_p_value(Sampler sample)
{
    Scene scene;
    two_lights(&scene);
    enum {
        BINS = 2 * GRID * GRID
    };
    double observed[BINS] = {0}, expected[BINS];
    for (int i = 0; i < SAMPLES; i++) {
        Rng rng = rng_for_sample(99, 0, (uint64_t)i);
        double u_select = rng_uniform(&rng), u1 = rng_uniform(&rng), u2 = rng_uniform(&rng);
        LightSample s = sample(&scene, u_select, u1, u2);
        observed[bin_of(&scene, light_of(&scene, s.point), s.point)] += 1.0;
    }
    for (int k = 0; k < 2; k++) {
        double share = scene.triangles[scene.light_triangles[k]].area / scene.light_area;
        for (int i = 0; i < GRID; i++)
            for (int j = 0; j < GRID; j++) {
                /* Fraction of the (u, v) triangle (area 1/2) in cell (i, j). */
                double cell = 1.0 / (GRID * GRID);
                double inside = i + j < GRID - 1 ? cell : i + j == GRID - 1 ? cell / 2 : 0.0;
                expected[(k * GRID + i) * GRID + j] = SAMPLES * share * inside / 0.5;
            }
    }
    int dof;
    double statistic = chi_square_statistic(observed, expected, BINS, &dof);
    double p = chi_square_p_value(statistic, dof);
    print_message("    X^2 = %.1f, %d degrees of freedom, p = %.3g\n", statistic, dof, p);
    scene_free(&scene);
    return p;
}

/* The wrong sampler of the header comment: s = u1 instead of sqrt(u1). */
static LightSample wrong_sample(const Scene *scene, double u_select, double u1, double u2)
{
    LightSample right = area_light_sample(scene, u_select, u1, u2);
    int k = light_of(scene, right.point);
    const Triangle *t = &scene->triangles[scene->light_triangles[k]];
    right.point = triangle_point(t, u1 * (1.0 - u2), u1 * u2);
    return right;
}

static void test_sampling_is_uniform_by_area(void **state)
{
    assert_true(area_sampling_p_value(area_light_sample) > 0.01);
}

static void test_wrong_sampler_is_rejected(void **state)
{
    assert_true(area_sampling_p_value(wrong_sample) < 0.01);
}

/* Samples carry their light's normal and emission. */
static void test_sample_fields(void **state)
{
    Scene scene;
    two_lights(&scene);
    LightSample s = area_light_sample(&scene, 0.99, 0.3, 0.3);
    assert_true(fabs(s.point.x - 5.0) < 1e-12); /* u_select 0.99 > 2/2.5: the second light */
    assert_true(fabs(s.normal.x - 1.0) < 1e-12);
    assert_true(s.emission.z == 3.0);
    scene_free(&scene);
}

/* The rectangle light of the closed form; an optional occluder in between. */
static void rectangle_light(Scene *scene, double a, double b, double h, int occluded)
{
    scene_init(scene);
    Material lamp = {.name = "lamp", .kind = MATERIAL_LIGHT, .emission = vec3(2, 2, 2)};
    Material white = {
        .name = "white", .kind = MATERIAL_LAMBERT, .reflectance = vec3(0.5, 0.5, 0.5)};
    int light = scene_add_material(scene, lamp), diffuse = scene_add_material(scene, white);
    Vec3 p0 = vec3(0, 0, h), p1 = vec3(0, b, h), p2 = vec3(a, b, h), p3 = vec3(a, 0, h);
    scene_add_triangle(scene, triangle_make(p0, p1, p2, light)); /* facing down */
    scene_add_triangle(scene, triangle_make(p0, p2, p3, light));
    if (occluded)
        scene_add_sphere(scene, (Sphere){vec3(0, 0, 0.5 * h), 0.25 * h, diffuse});
    assert_int_equal(scene_prepare(scene), 0);
}

/* Mean and variance of eq. 21's estimate at the origin (normal +z), M shadow rays. */
static void direct_light_statistics(const Scene *scene, int m, int samples, double *mean,
                                    double *variance)
{
    const Material *white = &scene->materials[1];
    RayCounts counts = {0, 0, 0};
    double sum = 0.0, sum_squares = 0.0;
    for (int i = 0; i < samples; i++) {
        Rng rng = rng_for_sample(5, (uint64_t)m, (uint64_t)i);
        Vec3 value = area_light_direct(scene, vec3(0, 0, 0), vec3(0, 0, 1), vec3(0, 0, 1),
                                       white, m, &rng, &counts);
        sum += value.x;
        sum_squares += value.x * value.x;
    }
    *mean = sum / samples;
    *variance = (sum_squares / samples - *mean * *mean) * samples / (samples - 1);
    assert_int_equal(counts.shadow, (uint64_t)m * samples); /* every sample faces the point */
}

static void test_direct_light_matches_closed_form(void **state)
{
    const double a = 2.0, b = 1.0, h = 1.5;
    Scene scene;
    rectangle_light(&scene, a, b, h, 0);
    double expected = 0.5 * 2.0 * configuration_factor(a, b, h); /* rho Le F */
    double mean1, variance1, mean64, variance64;
    direct_light_statistics(&scene, 1, 200000, &mean1, &variance1);
    direct_light_statistics(&scene, 64, 20000, &mean64, &variance64);
    double error1 = sqrt(variance1 / 200000), error64 = sqrt(variance64 / 20000);
    print_message("    expected %.6f; M=1: %.6f +- %.6f; M=64: %.6f +- %.6f\n", expected, mean1,
                  error1, mean64, error64);
    assert_true(fabs(mean1 - expected) < 4.0 * error1);
    assert_true(fabs(mean64 - expected) < 4.0 * error64);
    assert_true(error1 < 0.01 * expected && error64 < 0.01 * expected);
    /* Variance of the mean of M independent shadow rays is 1/M of one's: within 10%. */
    double ratio = variance1 / variance64;
    print_message("    variance ratio M=1 / M=64: %.1f\n", ratio);
    assert_true(ratio > 0.9 * 64 && ratio < 1.1 * 64);
    scene_free(&scene);
}

/* A sphere between the point and the light's corner blocks some shadow rays: the
 * estimate drops but stays positive; a point facing away gets nothing. */
static void test_occlusion_and_facing(void **state)
{
    Scene open, blocked;
    rectangle_light(&open, 2.0, 1.0, 1.5, 0);
    rectangle_light(&blocked, 2.0, 1.0, 1.5, 1);
    double open_mean, blocked_mean, variance;
    direct_light_statistics(&open, 1, 20000, &open_mean, &variance);
    direct_light_statistics(&blocked, 1, 20000, &blocked_mean, &variance);
    assert_true(blocked_mean < 0.9 * open_mean && blocked_mean > 0.0);

    RayCounts counts = {0, 0, 0};
    Rng rng = rng_for_sample(1, 2, 3);
    Vec3 away = area_light_direct(&open, vec3(0, 0, 0), vec3(0, 0, -1), vec3(0, 0, -1),
                                  &open.materials[1], 8, &rng, &counts);
    assert_true(away.x == 0.0 && counts.shadow == 0); /* no shadow ray wasted */
    scene_free(&open);
    scene_free(&blocked);
}

/* A lamp emits from its front only (area_light.h). A point above the rectangle light,
 * which faces down, with its normal facing down towards the lamp's back: every light
 * sample has cos(beta) < 0 and must add nothing, without a shadow ray spent. Then a
 * scatter of points all around the lamp (above, below, beside it, in its plane), with
 * random normals: no estimate may ever be negative. Without the cos(beta) <= 0
 * rejection the point behind the lamp receives -0.373, from 64 shadow rays (the planted
 * bug). */
static void test_nothing_behind_a_one_sided_lamp(void **state)
{
    Scene scene;
    rectangle_light(&scene, 2.0, 1.0, 1.5, 0);
    const Material *white = &scene.materials[1];
    RayCounts counts = {0, 0, 0};
    Rng rng = rng_for_sample(4, 4, 4);
    Vec3 behind = area_light_direct(&scene, vec3(1.0, 0.5, 2.5), vec3(0, 0, -1), vec3(0, 0, -1),
                                    white, 64, &rng, &counts);
    print_message("    behind the lamp: %g, %llu shadow rays\n", behind.x,
                  (unsigned long long)counts.shadow);
    assert_true(behind.x == 0.0 && behind.y == 0.0 && behind.z == 0.0);
    assert_true(counts.shadow == 0);
    for (int i = 0; i < 20000; i++) {
        Rng r = rng_for_sample(6, 0, (uint64_t)i);
        Vec3 x = vec3(4.0 * rng_uniform(&r) - 1.0, 3.0 * rng_uniform(&r) - 1.0,
                      3.0 * rng_uniform(&r));
        double z = 2.0 * rng_uniform(&r) - 1.0, phi = 2.0 * PI * rng_uniform(&r);
        Vec3 n = vec3(sqrt(1.0 - z * z) * cos(phi), sqrt(1.0 - z * z) * sin(phi), z);
        Vec3 value = area_light_direct(&scene, x, n, n, white, 4, &r, &counts);
        assert_true(value.x >= 0.0 && value.y >= 0.0 && value.z >= 0.0);
    }
    scene_free(&scene);
}

/* The closed form again, with the same a x b rectangle cut into three triangles of
 * unequal areas ab/8, 3ab/8 and ab/2, fanned from the corner above the point. Each
 * must be chosen with probability area / A for eq. 21's A/M weight to be right;
 * choosing a triangle by its index (probability 1/3 each, the planted bug) gives
 * 0.1403 +- 0.0002 against the closed form's 0.1224. M = 1, 200,000 estimates, within 4
 * standard errors. */
static void test_unequal_triangles_match_closed_form(void **state)
{
    const double a = 2.0, b = 1.0, h = 1.5;
    Scene scene;
    scene_init(&scene);
    Material lamp = {.name = "lamp", .kind = MATERIAL_LIGHT, .emission = vec3(2, 2, 2)};
    Material white = {
        .name = "white", .kind = MATERIAL_LAMBERT, .reflectance = vec3(0.5, 0.5, 0.5)};
    int light = scene_add_material(&scene, lamp);
    scene_add_material(&scene, white);
    Vec3 p0 = vec3(0, 0, h), p1 = vec3(0, b, h), q = vec3(a / 4, b, h), p2 = vec3(a, b, h),
         p3 = vec3(a, 0, h);
    scene_add_triangle(&scene, triangle_make(p0, p1, q, light)); /* all facing down */
    scene_add_triangle(&scene, triangle_make(p0, q, p2, light));
    scene_add_triangle(&scene, triangle_make(p0, p2, p3, light));
    assert_int_equal(scene_prepare(&scene), 0);
    assert_true(fabs(scene.triangles[0].area - a * b / 8) < 1e-12);
    assert_true(fabs(scene.triangles[1].area - 3 * a * b / 8) < 1e-12);
    double expected = 0.5 * 2.0 * configuration_factor(a, b, h), mean, variance;
    direct_light_statistics(&scene, 1, 200000, &mean, &variance);
    double error = sqrt(variance / 200000);
    print_message("    expected %.6f; M=1: %.6f +- %.6f\n", expected, mean, error);
    assert_true(fabs(mean - expected) < 4.0 * error);
    scene_free(&scene);
}

/* area_light_pdf is a density of directions: seen from a point x, its integral over the
 * lamp's solid angle is 1 (midpoint rule over the lamp's area, dw = cos(beta) / d^2 dA);
 * and it is the density of area_light_sample's directions: the mean of 1 / pdf over its
 * samples is the solid angle the lamp subtends (E_p[1 / p] = integral of dw). The lamp is
 * tilted and off to the side, so that d and beta vary over it: a density without the
 * cosine at the lamp, or without the d^2, fails both. */
static void test_pdf_is_the_samplers_density(void **state)
{
    Scene scene;
    scene_init(&scene);
    Material lamp = {.name = "lamp", .kind = MATERIAL_LIGHT, .emission = vec3(1, 1, 1)};
    int m = scene_add_material(&scene, lamp);
    Vec3 p0 = vec3(1, 0, 1), p1 = vec3(1, 1, 1.6), p2 = vec3(2.5, 1, 2.2),
         p3 = vec3(2.5, 0, 1.6);
    scene_add_triangle(&scene, triangle_make(p0, p1, p2, m)); /* facing down, to x */
    scene_add_triangle(&scene, triangle_make(p0, p2, p3, m));
    assert_int_equal(scene_prepare(&scene), 0);
    const Vec3 x = vec3(0, 0.3, 0);
    enum {
        CELLS = 400
    };
    double integral = 0.0, solid_angle = 0.0;
    for (int t = 0; t < scene.light_count; t++) {
        const Triangle *tri = &scene.triangles[scene.light_triangles[t]];
        for (int i = 0; i < CELLS; i++)
            for (int j = 0; j < CELLS - i; j++) {
                /* The cells of the triangle's (u, v) grid below the diagonal, and half of
                 * each one the diagonal cuts, at its midpoint. */
                double u = (i + 0.5) / CELLS, v = (j + 0.5) / CELLS;
                double weight = i + j == CELLS - 1 ? 0.5 : 1.0;
                if (u + v > 1.0 && weight == 1.0)
                    continue;
                Vec3 y = triangle_point(tri, u, v), to_x = vec3_sub(x, y);
                double d = vec3_length(to_x), cos_beta = vec3_dot(tri->normal, to_x) / d;
                double dw =
                    weight * 2.0 * tri->area / ((double)CELLS * CELLS) * cos_beta / (d * d);
                integral += area_light_pdf(&scene, d, cos_beta) * dw;
                solid_angle += dw;
            }
    }
    Rng rng = rng_for_sample(3, 0, 0);
    double sum = 0.0, sum_squares = 0.0;
    for (int i = 0; i < SAMPLES; i++) {
        double u_select = rng_uniform(&rng), u1 = rng_uniform(&rng), u2 = rng_uniform(&rng);
        LightSample y = area_light_sample(&scene, u_select, u1, u2);
        Vec3 to_x = vec3_sub(x, y.point);
        double d = vec3_length(to_x),
               inverse = 1.0 / area_light_pdf(&scene, d, vec3_dot(y.normal, to_x) / d);
        sum += inverse;
        sum_squares += inverse * inverse;
    }
    double mean = sum / SAMPLES,
           error = sqrt((sum_squares / SAMPLES - mean * mean) / (SAMPLES - 1));
    print_message("    integral of the pdf %.6f; mean 1 / pdf %.6f +- %.6f, solid angle %.6f\n",
                  integral, mean, error, solid_angle);
    assert_true(fabs(integral - 1.0) < 1e-3);
    assert_true(fabs(mean - solid_angle) < 4.0 * error + 1e-3 * solid_angle);
    scene_free(&scene);
}

/* A grey material, or a light of this emission (> 0). */
static int add_material(Scene *scene, double emission)
{
    Material m = {.kind = emission > 0.0 ? MATERIAL_LIGHT : MATERIAL_LAMBERT,
                  .reflectance = vec3(0.5, 0.5, 0.5),
                  .emission = vec3(emission, emission, emission)};
    return scene_add_material(scene, m);
}

/* scene_prepare lists exactly the emitting triangles, in order, with the running sum
 * of their areas (2 and 0.5 here): choosing a light by area needs exactly this. A
 * second call rebuilds the same list, and a scene without lights has none. */
static void test_light_list(void **state)
{
    Scene scene;
    scene_init(&scene);
    int white = add_material(&scene, 0);
    int lamp = add_material(&scene, 25);
    scene_add_triangle(&scene,
                       triangle_make(vec3(0, 0, 0), vec3(9, 0, 0), vec3(0, 9, 0), white));
    scene_add_triangle(&scene,
                       triangle_make(vec3(0, 0, 5), vec3(0, 2, 5), vec3(2, 0, 5), lamp));
    scene_add_triangle(&scene,
                       triangle_make(vec3(0, 0, 1), vec3(3, 0, 1), vec3(0, 3, 1), white));
    scene_add_triangle(&scene,
                       triangle_make(vec3(0, 0, 6), vec3(0, 1, 6), vec3(1, 0, 6), lamp));
    Sphere ball = {vec3(5, 5, 5), 1, lamp}; /* emitting spheres are not area lights */
    scene_add_sphere(&scene, ball);
    for (int round = 0; round < 2; round++) {
        assert_int_equal(scene_prepare(&scene), 0);
        assert_int_equal(scene.light_count, 2);
        assert_int_equal(scene.light_triangles[0], 1);
        assert_int_equal(scene.light_triangles[1], 3);
        assert_close(scene.light_cumulative[0], 2.0, 1e-15);
        assert_close(scene.light_cumulative[1], 2.5, 1e-15);
        assert_close(scene.light_area, 2.5, 1e-15);
    }
    scene_free(&scene);

    scene_init(&scene);
    white = add_material(&scene, 0);
    scene_add_triangle(&scene,
                       triangle_make(vec3(0, 0, 0), vec3(1, 0, 0), vec3(0, 1, 0), white));
    assert_int_equal(scene_prepare(&scene), 0);
    assert_int_equal(scene.light_count, 0);
    assert_close(scene.light_area, 0, 0);
    scene_free(&scene);
}

/* triangle_point(u, v) is eq. 16: the vertices at (0,0), (1,0), (0,1), the centroid
 * at (1/3, 1/3). */
static void test_point(void **state)
{
    Vec3 a = vec3(1, 2, 3), b = vec3(4, -2, 0), c = vec3(-1, 0, 6);
    Triangle tri = triangle_make(a, b, c, 0);
    Vec3 centroid = vec3_scale(vec3_add(vec3_add(a, b), c), 1.0 / 3.0);
    Vec3 points[4] = {triangle_point(&tri, 0, 0), triangle_point(&tri, 1, 0),
                      triangle_point(&tri, 0, 1), triangle_point(&tri, 1.0 / 3, 1.0 / 3)};
    Vec3 expected[4] = {a, b, c, centroid};
    for (int i = 0; i < 4; i++)
        assert_close(vec3_length(vec3_sub(points[i], expected[i])), 0, 1e-14);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_light_list),
        cmocka_unit_test(test_point),
        cmocka_unit_test(test_sampling_is_uniform_by_area),
        cmocka_unit_test(test_wrong_sampler_is_rejected),
        cmocka_unit_test(test_sample_fields),
        cmocka_unit_test(test_direct_light_matches_closed_form),
        cmocka_unit_test(test_occlusion_and_facing),
        cmocka_unit_test(test_nothing_behind_a_one_sided_lamp),
        cmocka_unit_test(test_unequal_triangles_match_closed_form),
        cmocka_unit_test(test_pdf_is_the_samplers_density),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
