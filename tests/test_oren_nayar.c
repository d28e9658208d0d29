/* test_oren_nayar.c (chapter 5): the Oren-Nayar BRDF with the errata of oren_nayar.h (
 * chapter 5).
 *
 * Checked: the corrected coefficients A and B (eq. 14), one value of eq. 13 by hand,
 * that sigma = 0 is Lambert, reciprocity, finite values at normal and grazing incidence
 * and for huge sigma, and a white-furnace test: the albedo of a white rough surface
 * (rho = 1), estimated by Monte Carlo with a fixed seed, against its closed form, and
 * where it exceeds 1 (the published model is not energy conserving for sigma < 0.33).
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>

#include "hemisphere.h"
#include "lambert.h"
#include "oren_nayar.h"
#include "rng.h"

#define PAIRS 100000

/* A random pair of directions above the surface (cosine-distributed, which covers the
 * whole open hemisphere). */
static void random_pair(Rng *rng, Vec3 *wi, Vec3 *wo)
{
    double u1 = rng_uniform(rng), u2 = rng_uniform(rng);
    *wi = hemisphere_sample_cosine(u1, u2);
    u1 = rng_uniform(rng);
    u2 = rng_uniform(rng);
    *wo = hemisphere_sample_cosine(u1, u2);
}

/* The unit direction at height z (cos theta) and azimuth phi. */
static Vec3 direction(double z, double phi)
{
    double s = sqrt(1.0 - z * z);
    return vec3(s * cos(phi), s * sin(phi), z);
}

/* Eq. 14 with the erratum: sigma = 0 gives exactly A = 1, B = 0; sigma = 0.5 gives
 * A = 1 - 0.25 / 1.16 = 0.784483, B = 0.1125 / 0.34 = 0.330882; an infinitely rough
 * surface tends to A = 1/2, B = 0.45, with no inf / inf on the way. */
static void test_coefficients(void **state)
{
    assert_true(oren_nayar_a(0.0) == 1.0);
    assert_true(oren_nayar_b(0.0) == 0.0);
    assert_float_equal(oren_nayar_a(0.5), 0.784483, 1e-6);
    assert_float_equal(oren_nayar_b(0.5), 0.330882, 1e-6);
    const double huge[] = {1e10, 1e200, INFINITY};
    for (int k = 0; k < 3; k++) {
        assert_float_equal(oren_nayar_a(huge[k]), 0.5, 1e-12);
        assert_float_equal(oren_nayar_b(huge[k]), 0.45, 1e-12);
    }
}

/* Eq. 13 by hand for sigma = 0.5, rho = (1, 0.5, 0.25), theta_i = 60 deg, phi_i = 0,
 * theta_o = 30 deg, phi_o = 60 deg: alpha = 60, beta = 30 deg, and
 *     cos(60) sin(60) tan(30) = 0.5 * (sqrt(3)/2) * (1/sqrt(3)) = 0.25,
 *     A + 0.25 B = 0.784483 + 0.082721 = 0.867203,   f = rho * 0.867203 / pi
 *     = (0.276039, 0.138020, 0.069010). */
static void test_value_by_hand(void **state)
{
    Vec3 wi = direction(0.5, 0.0), wo = direction(sqrt(3.0) / 2.0, PI / 3.0);
    assert_float_equal(oren_nayar_factor(0.5, wi, wo), 0.867203, 1e-6);
    Vec3 f = oren_nayar_brdf(vec3(1.0, 0.5, 0.25), 0.5, wi, wo);
    assert_float_equal(f.x, 0.276039, 1e-6);
    assert_float_equal(f.y, 0.138020, 1e-6);
    assert_float_equal(f.z, 0.069010, 1e-6);
}

/* sigma = 0 is the Lambertian BRDF rho / pi for every pair of directions. */
static void test_smooth_is_lambert(void **state)
{
    const Vec3 rho = vec3(0.75, 0.15, 0.6);
    Vec3 lambert = lambert_brdf(rho);
    Rng rng = rng_for_sample(5, 0, 0);
    for (int i = 0; i < PAIRS; i++) {
        Vec3 wi, wo;
        random_pair(&rng, &wi, &wo);
        Vec3 difference = vec3_sub(oren_nayar_brdf(rho, 0.0, wi, wo), lambert);
        assert_float_equal(vec3_max_abs(difference), 0.0, 1e-12);
    }
}

/* Reciprocity (Helmholtz): f(wi, wo) = f(wo, wi), for smooth to very rough surfaces. */
static void test_reciprocity(void **state)
{
    const double sigmas[] = {0.1, 0.5, 1.0, 1.5, 10.0};
    Rng rng = rng_for_sample(5, 1, 0);
    for (int i = 0; i < PAIRS; i++) {
        Vec3 wi, wo;
        random_pair(&rng, &wi, &wo);
        double sigma = sigmas[i % 5];
        double forward = oren_nayar_factor(sigma, wi, wo);
        assert_float_equal(forward, oren_nayar_factor(sigma, wo, wi), 1e-12);
    }
}

/* Normal incidence: the azimuth is undefined and the angular term vanishes
 * (sin(beta) = 0), so the factor is A whatever the other direction; no NaN from the
 * zero-length projection. */
static void test_normal_incidence(void **state)
{
    const Vec3 normal = vec3(0.0, 0.0, 1.0);
    Rng rng = rng_for_sample(5, 2, 0);
    for (int i = 0; i < 1000; i++) {
        Vec3 wi, wo;
        random_pair(&rng, &wi, &wo);
        assert_float_equal(oren_nayar_factor(0.7, normal, wo), oren_nayar_a(0.7), 1e-15);
        assert_float_equal(oren_nayar_factor(0.7, wi, normal), oren_nayar_a(0.7), 1e-15);
    }
    assert_float_equal(oren_nayar_factor(0.7, normal, normal), oren_nayar_a(0.7), 1e-15);
}

/* Grazing angles (z = 1e-12, 0, and -1e-17 as rounding might give), each direction or
 * both, at several azimuths and roughnesses: the BRDF is finite and non-negative, and
 * f cos(theta_i) / (rho / pi) never exceeds A + B, the bound implied by
 * sin(alpha) tan(beta) cos(theta_i) <= sin(theta_i) sin(theta_o) <= 1. */
static void test_grazing_is_finite(void **state)
{
    const double zs[] = {1e-12, 0.0, -1e-17, 0.5, 1.0};
    const double sigmas[] = {0.3, 1.5, 1e6};
    for (int s = 0; s < 3; s++) {
        double bound = oren_nayar_a(sigmas[s]) + oren_nayar_b(sigmas[s]);
        for (int i = 0; i < 5; i++)
            for (int o = 0; o < 5; o++)
                for (int k = 0; k < 8; k++) {
                    Vec3 wi = direction(zs[i], 0.3);
                    Vec3 wo = direction(zs[o], 0.3 + k * PI / 4.0);
                    double factor = oren_nayar_factor(sigmas[s], wi, wo);
                    assert_true(isfinite(factor));
                    assert_true(factor >= 0.0);
                    assert_true(factor * fmax(0.0, wi.z) <= bound * (1.0 + 1e-12));
                }
    }
}

/* The directional albedo of a white surface (rho = 1) seen from theta_o: the integral
 * of f cos(theta_i) over wi, in closed form. With rho / pi = 1 / pi, integrate first
 * over phi_i (the integral of max(0, cos(phi_i - phi_o)) is 2), then over theta_i,
 * split at theta_o where tan(beta) switches from tan(theta_i) to tan(theta_o):
 *     a(theta_o) = A + (2 B / pi) sin(theta_o) (I_1 + I_2),
 *     I_1 = integral_0^theta_o sin^2(t) dt = theta_o / 2 - sin(2 theta_o) / 4,
 *     I_2 = integral_theta_o^(pi/2) sin^2(t) cos(t) dt / cos(theta_o)
 *         = (1 - sin^3(theta_o)) / (3 cos(theta_o)).
 * It rises from A at theta_o = 0 to A + B / 2 at grazing. */
static double albedo_closed_form(double sigma, double theta_o)
{
    double s = sin(theta_o), c = cos(theta_o);
    double i1 = 0.5 * theta_o - 0.25 * sin(2.0 * theta_o);
    double i2 = (1.0 - s * s * s) / (3.0 * c);
    return oren_nayar_a(sigma) + 2.0 * oren_nayar_b(sigma) / PI * s * (i1 + i2);
}

/* White furnace, rho = 1: the Monte Carlo albedo with cosine-weighted wi (each sample's
 * estimate is the factor itself), 1e5 samples per (sigma, theta_o), agrees with the
 * closed form within 4 standard errors (a false alarm has probability 6e-5 per case;
 * the seed is fixed). Where the model conserves energy (sigma >= 0.33, see
 * test_energy_balance) the estimate is also at most 1 within 3 standard errors.
 * Seen: all 20 cases within 1.7 standard errors; at normal wo every sample is A. */
static void test_white_furnace(void **state)
{
    const double sigmas[] = {0.25, 0.5, 1.0, 1.5};
    const double theta_o_degrees[] = {0.0, 30.0, 60.0, 80.0, 89.0};
    const int samples = 100000;
    for (int s = 0; s < 4; s++)
        for (int t = 0; t < 5; t++) {
            double theta_o = theta_o_degrees[t] * PI / 180.0;
            Vec3 wo = direction(cos(theta_o), 1.0);
            Rng rng = rng_for_sample(7, (uint64_t)s, (uint64_t)t);
            double sum = 0.0, sum_squares = 0.0;
            for (int i = 0; i < samples; i++) {
                double u1 = rng_uniform(&rng), u2 = rng_uniform(&rng);
                Vec3 wi = hemisphere_sample_cosine(u1, u2);
                double estimate = oren_nayar_factor(sigmas[s], wi, wo);
                sum += estimate;
                sum_squares += estimate * estimate;
            }
            double mean = sum / samples;
            double variance = fmax(0.0, sum_squares / samples - mean * mean);
            double standard_error = sqrt(variance / samples);
            double exact = albedo_closed_form(sigmas[s], theta_o);
            print_message("sigma %.2f theta_o %2.0f: albedo %.4f +- %.4f, exact %.4f\n",
                          sigmas[s], theta_o_degrees[t], mean, standard_error, exact);
            assert_float_equal(mean, exact, 4.0 * standard_error + 1e-12);
            if (sigmas[s] >= 0.33)
                assert_true(mean - 3.0 * standard_error <= 1.0);
        }
}

/* Energy balance of the model itself (the closed form above, on a 0.1 degree grid):
 * the albedo grows with theta_o towards A + B / 2. For sigma >= 0.33 rad that is at
 * most 1: no energy is created. For smoother surfaces the (qualitative) model reflects
 * slightly more than it receives near grazing, at most 1.52% (sigma = 0.2); this is
 * eq. 13 as published, not a bug, and is pinned here so nobody "fixes" it by accident. */
static void test_energy_balance(void **state)
{
    for (double sigma = 0.0; sigma <= 3.0; sigma += 0.01) {
        double limit = oren_nayar_a(sigma) + 0.5 * oren_nayar_b(sigma);
        double previous = oren_nayar_a(sigma);
        for (int tenth = 1; tenth < 900; tenth++) {
            double albedo = albedo_closed_form(sigma, tenth * PI / 1800.0);
            assert_true(albedo >= previous - 1e-12);
            assert_true(albedo <= limit + 1e-12);
            previous = albedo;
        }
        assert_true(limit <= 1.0152);
        if (sigma >= 0.33)
            assert_true(limit <= 1.0);
    }
    assert_true(oren_nayar_a(0.2) + 0.5 * oren_nayar_b(0.2) > 1.015);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_coefficients),      cmocka_unit_test(test_value_by_hand),
        cmocka_unit_test(test_smooth_is_lambert), cmocka_unit_test(test_reciprocity),
        cmocka_unit_test(test_normal_incidence),  cmocka_unit_test(test_grazing_is_finite),
        cmocka_unit_test(test_white_furnace),     cmocka_unit_test(test_energy_balance),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
