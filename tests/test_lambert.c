/* test_lambert.c (chapter 2): the Lambertian BRDF (lambert.h, chapter 2).
 *
 * The BRDF is the constant rho / pi (eq. 8), and the 1/pi is exactly what makes the
 * surface reflect the fraction rho of the light it receives: its directional albedo,
 * the integral of f cos(theta_i) over the hemisphere, is rho.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>

#include "hemisphere.h"
#include "lambert.h"
#include "rng.h"

/* The largest difference between two colours' channels. */
static double channel_difference(Vec3 a, Vec3 b) { return vec3_max_abs(vec3_sub(a, b)); }

/* Eq. 8 per colour channel, including the extremes rho = 0 (black: nothing reflected)
 * and rho = 1 (white: 1 / pi). */
static void test_brdf_is_rho_over_pi(void **state)
{
    const Vec3 rho = vec3(0.75, 0.15, 0.3), black = vec3(0, 0, 0), white = vec3(1, 1, 1);
    Vec3 expected = vec3(0.75 / PI, 0.15 / PI, 0.3 / PI);
    assert_float_equal(channel_difference(lambert_brdf(rho), expected), 0.0, 1e-15);
    assert_float_equal(channel_difference(lambert_brdf(black), black), 0.0, 0.0);
    Vec3 white_expected = vec3(1.0 / PI, 1.0 / PI, 1.0 / PI);
    assert_float_equal(channel_difference(lambert_brdf(white), white_expected), 0.0, 1e-15);
}

/* The albedo by quadrature: integral over theta of (rho / pi) cos(theta) times the
 * ring's solid angle 2 pi sin(theta) dtheta, by the midpoint rule, equals rho. */
static void test_albedo_by_quadrature_is_rho(void **state)
{
    const Vec3 rho = vec3(0.8, 0.35, 0.6);
    const int rings = 10000;
    const double d_theta = 0.5 * PI / rings;
    Vec3 albedo = vec3(0.0, 0.0, 0.0);
    for (int i = 0; i < rings; i++) {
        double theta = (i + 0.5) * d_theta;
        double ring = cos(theta) * 2.0 * PI * sin(theta) * d_theta;
        albedo = vec3_add_scaled(albedo, lambert_brdf(rho), ring);
    }
    assert_float_equal(channel_difference(albedo, rho), 0.0, 1e-8);
}

/* The albedo by Monte Carlo with cosine-weighted directions: every sample's estimate
 * f cos(theta) / pdf is exactly rho (to rounding), so the estimate has no variance. */
static void test_albedo_per_cosine_sample_is_rho(void **state)
{
    const Vec3 rho = vec3(0.75, 0.15, 0.15);
    Rng rng = rng_for_sample(8, 0, 0);
    for (int i = 0; i < 100000; i++) {
        double u1 = rng_uniform(&rng), u2 = rng_uniform(&rng);
        Vec3 wi = hemisphere_sample_cosine(u1, u2);
        Vec3 estimate = vec3_scale(lambert_brdf(rho), wi.z / hemisphere_pdf_cosine(wi));
        assert_float_equal(channel_difference(estimate, rho), 0.0, 1e-12);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_brdf_is_rho_over_pi),
        cmocka_unit_test(test_albedo_by_quadrature_is_rho),
        cmocka_unit_test(test_albedo_per_cosine_sample_is_rho),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
