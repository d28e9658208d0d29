/* test_snell.c (chapter 1): refraction by Snell's law and total internal reflection (snell.h,
 * report §3.5.2, eq. 2, with the critical angle corrected).
 *
 * The refracted direction must obey eq. 2 over the whole range of angles and of IORs
 * (1.0001 to 4, entering and leaving), stay in the plane of incidence, and behave at
 * the extremes: n_i = n_t, normal incidence, 90 degrees incidence, and
 * exactly at the critical angle.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include "check.h"
#include "snell.h"

/* A unit direction arriving at angle theta to the normal n (so d . n = -cos theta),
 * at azimuth phi around it. */
static Vec3 incident(Vec3 n, double theta, double phi)
{
    Vec3 t, b;
    test_frame(n, &t, &b);
    return test_from_frame(vec3(sin(theta) * cos(phi), sin(theta) * sin(phi), -cos(theta)), t,
                           b, n);
}

/* An index of refraction from 1.0001 to 4, log-uniform in n - 1 so that indices
 * barely above 1 are tested as often as 2 to 4. */
static double random_ior(TestRandom *rng)
{
    return 1.0 + pow(10.0, -4.0 + log10(3e4) * test_uniform(rng));
}

/* sin of the angle between unit vector v and the normal line. */
static double sin_to_normal(Vec3 v, Vec3 n) { return vec3_length(vec3_cross(v, n)); }

/* 10^5 random normals, angles and IOR pairs with n in [1.0001, 4], entering and
 * leaving glass, from air and between two media (below the critical angle): the refracted
 * direction is unit length, continues through the surface, lies in the plane of incidence on
 * the same side as d's tangential part, and satisfies n_i sin(theta_i) = n_t sin(theta_t) to
 * 1e-9. */
static void test_snells_law(void **state)
{
    TestRandom rng = test_random(12, 0, 0);
    for (int k = 0; k < 100000; k++) {
        double a = random_ior(&rng), b = random_ior(&rng);
        const double pairs[4][2] = {
            {1.0, a}, {a, 1.0}, {fmin(a, b), fmax(a, b)}, {fmax(a, b), fmin(a, b)}};
        double n_i = pairs[k % 4][0], n_t = pairs[k % 4][1];
        double theta_max = test_critical_angle(n_i, n_t);
        double theta = theta_max * test_uniform(&rng) * (1.0 - 1e-6);
        Vec3 n = random_unit_vector(&rng),
             d = incident(n, theta, 2.0 * PI * test_uniform(&rng)), t;
        assert_true(snell_refract(d, n, n_i, n_t, &t));
        assert_close(vec3_length(t), 1, 1e-14);
        assert_true(vec3_dot(t, n) < 0);
        assert_close(vec3_dot(vec3_cross(d, n), t), 0, 1e-14);
        Vec3 d_tangent = vec3_add_scaled(d, n, -vec3_dot(d, n));
        Vec3 t_tangent = vec3_add_scaled(t, n, -vec3_dot(t, n));
        assert_true(vec3_dot(d_tangent, t_tangent) >= 0);
        assert_close(n_i * sin_to_normal(d, n), n_t * sin_to_normal(t, n), 1e-9);
    }
}

/* n_i = n_t: no interface, the ray goes on undeviated at every angle up to 90
 * degrees, for indices 1, 1.5 and 4. */
static void test_equal_indices(void **state)
{
    const double iors[] = {1.0, 1.5, 4.0};
    Vec3 n = vec3_normalize(vec3(0.2, -0.3, 0.9));
    for (int i = 0; i < 3; i++)
        for (int k = 0; k <= 90; k++) {
            Vec3 d = incident(n, k * PI / 180.0, 0.7), t;
            assert_true(snell_refract(d, n, iors[i], iors[i], &t));
            assert_close(vec3_length(vec3_sub(t, d)), 0, 1e-14);
        }
}

/* Normal incidence goes straight through, entering and leaving, for any IOR. */
static void test_normal_incidence(void **state)
{
    Vec3 n = vec3(0, 0, 1), d = vec3(0, 0, -1), t;
    const double iors[] = {1.0001, 1.33, 1.5, 2.42, 4.0};
    for (int i = 0; i < 5; i++) {
        assert_true(snell_refract(d, n, 1.0, iors[i], &t));
        assert_true(t.x == 0 && t.y == 0 && t.z == -1);
        assert_true(snell_refract(d, n, iors[i], 1.0, &t));
        assert_true(t.x == 0 && t.y == 0 && t.z == -1);
    }
}

/* Leaving glass (n_i > n_t): exactly at the critical angle, where theta_t would be 90
 * degrees and no light is transmitted, and beyond it up to 90 degrees, every ray is
 * totally reflected; just below it (1e-6 rad) the ray refracts, close to grazing. */
static void test_total_internal_reflection(void **state)
{
    TestRandom rng = test_random(13, 0, 0);
    Vec3 t;
    for (int k = 0; k < 10000; k++) {
        double n_t = 1.0 + 2.0 * test_uniform(&rng),
               n_i = n_t * (1.0001 + 2.0 * test_uniform(&rng));
        double critical = test_critical_angle(n_i, n_t);
        Vec3 n = vec3(0, 0, 1);
        double phi = 2.0 * PI * test_uniform(&rng);
        double beyond = critical + (0.5 * PI - critical) * test_uniform(&rng);
        assert_false(snell_refract(incident(n, critical, phi), n, n_i, n_t, &t));
        assert_false(snell_refract(incident(n, beyond, phi), n, n_i, n_t, &t));
        assert_false(snell_refract(incident(n, 0.5 * PI, phi), n, n_i, n_t, &t));
        assert_true(snell_refract(incident(n, critical - 1e-6, phi), n, n_i, n_t, &t));
        assert_true(vec3_is_finite(t) && t.z < 0 && t.z > -0.01);
        assert_close(snell_cos_transmitted(cos(critical), n_i, n_t), -1, 0);
    }
}

/* 90 degrees incidence: d in the tangent plane (and a hair past it, d . n = +1e-17)
 * gives no NaN. Entering, sin(theta_t) = n_i / n_t, the largest refraction angle;
 * leaving, total internal reflection. */
static void test_grazing_incidence(void **state)
{
    Vec3 n = vec3(0, 0, 1), t;
    Vec3 along[2] = {vec3(1, 0, 0), vec3_normalize(vec3(1, 0, 1e-17))};
    for (int i = 0; i < 2; i++) {
        assert_true(snell_refract(along[i], n, 1.0, 1.5, &t));
        assert_true(vec3_is_finite(t));
        assert_close(sin_to_normal(t, n), 1.0 / 1.5, 1e-15);
        assert_false(snell_refract(along[i], n, 1.5, 1.0, &t));
        assert_close(snell_cos_transmitted(0.0, 1.0, 4.0), sqrt(1.0 - 1.0 / 16.0), 1e-15);
        assert_close(snell_cos_transmitted(0.0, 4.0, 1.0), -1, 0);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_snells_law),
        cmocka_unit_test(test_equal_indices),
        cmocka_unit_test(test_normal_incidence),
        cmocka_unit_test(test_total_internal_reflection),
        cmocka_unit_test(test_grazing_incidence),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
