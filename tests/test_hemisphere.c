/* test_hemisphere.c (chapter 2): cosine-weighted hemisphere sampling (hemisphere.h, chapter 2).
 *
 * The sampler must produce unit directions above the surface with exactly the density
 * cos(theta) / pi that hemisphere_pdf_cosine reports, or every diffuse bounce is biased.
 * The main test is a chi-square goodness-of-fit test on a (theta, phi) grid, at
 * significance level 0.01 with a fixed seed; it is shown to reject a wrong sampler.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>

#include "chi_square.h"
#include "hemisphere.h"
#include "rng.h"

#define SAMPLES 1000000
#define THETA_BINS 10
#define PHI_BINS 20
#define SIGNIFICANCE 0.01
#define SEED 2019

typedef Vec3 (*Sampler)(double u1, double u2);

/* Every sample is a unit vector strictly above the surface, including at the extreme
 * random numbers 0 and 1 - 2^-32 (u1 = 0 is the normal itself). */
static void test_samples_unit_and_above_surface(void **state)
{
    const double top = 1.0 - 0x1p-32;
    const double extremes[][2] = {{0.0, 0.0}, {0.0, top}, {top, 0.0}, {top, top}};
    for (int k = 0; k < 4; k++) {
        Vec3 w = hemisphere_sample_cosine(extremes[k][0], extremes[k][1]);
        assert_float_equal(vec3_length(w), 1.0, 1e-12);
        assert_true(w.z > 0.0);
    }
    Rng rng = rng_for_sample(SEED, 0, 0);
    for (int i = 0; i < 100000; i++) {
        double u1 = rng_uniform(&rng), u2 = rng_uniform(&rng);
        Vec3 w = hemisphere_sample_cosine(u1, u2);
        assert_float_equal(vec3_length(w), 1.0, 1e-12);
        assert_true(w.z > 0.0);
    }
}

/* The inversion of eq. 12 by hand: P(theta) = sin^2(theta) = u1, so u1 = 1/4 gives
 * theta = 30 degrees; phi = 2 pi u2, so u2 = 1/4 points along +y. */
static void test_inverse_cdf_by_hand(void **state)
{
    Vec3 w = hemisphere_sample_cosine(0.25, 0.25);
    assert_float_equal(w.x, 0.0, 1e-15);
    assert_float_equal(w.y, 0.5, 1e-15);
    assert_float_equal(w.z, sqrt(3.0) / 2.0, 1e-15);
}

/* The pdf is non-negative (eq. 9), cos(theta) / pi above the surface, 0 on and below
 * it, and integrates to 1 over the whole sphere (eq. 10): midpoint quadrature in
 * (theta, phi) with dw = sin(theta) dtheta dphi, error O(h^2) ~ 1e-7. */
static void test_pdf_integrates_to_one(void **state)
{
    const int n_theta = 2000, n_phi = 16;
    const double d_theta = PI / n_theta, d_phi = 2.0 * PI / n_phi;
    double integral = 0.0;
    for (int i = 0; i < n_theta; i++) {
        double theta = (i + 0.5) * d_theta;
        for (int j = 0; j < n_phi; j++) {
            double phi = (j + 0.5) * d_phi;
            Vec3 w = vec3(sin(theta) * cos(phi), sin(theta) * sin(phi), cos(theta));
            double pdf = hemisphere_pdf_cosine(w);
            assert_true(pdf >= 0.0);
            assert_float_equal(pdf, fmax(0.0, cos(theta)) / PI, 1e-15);
            integral += pdf * sin(theta) * d_theta * d_phi;
        }
    }
    assert_float_equal(integral, 1.0, 1e-6);
    assert_true(hemisphere_pdf_cosine(vec3(1.0, 0.0, 0.0)) == 0.0);
    assert_true(hemisphere_pdf_cosine(vec3(0.0, 0.0, -1.0)) == 0.0);
}

/* The wrong sampler of the rejection test: cos(theta) = 1 - u1 is uniform over the
 * hemisphere's solid angle (pdf 1 / (2 pi)), the classic mistake of drawing cos(theta)
 * uniformly. */
static Vec3 sample_uniform_by_mistake(double u1, double u2)
{
    double cos_theta = 1.0 - u1;
    double sin_theta = sqrt(1.0 - cos_theta * cos_theta);
    double phi = 2.0 * PI * u2;
    return vec3(sin_theta * cos(phi), sin_theta * sin(phi), cos_theta);
}

/* A subtler wrong sampler: cos(theta) = (1 - u1)^0.49 instead of ^0.5, an exponent 2%
 * off; its pdf is within 5% of cos(theta) / pi for cos(theta) > 0.3. */
static Vec3 sample_slightly_wrong_exponent(double u1, double u2)
{
    double cos_theta = pow(1.0 - u1, 0.49);
    double sin_theta = sqrt(1.0 - cos_theta * cos_theta);
    double phi = 2.0 * PI * u2;
    return vec3(sin_theta * cos(phi), sin_theta * sin(phi), cos_theta);
}

/* Counts SAMPLES directions of `sampler` on a THETA_BINS x PHI_BINS grid (equal steps
 * of theta in [0, pi/2] and phi in [0, 2 pi)) against the cosine density, and returns the
 * chi-square p-value; the statistic and degrees of freedom go to *statistic, *dof.
 * Expected count of a cell: N times the integral of cos(theta)/pi sin(theta) over it,
 *     N (sin^2(theta_1) - sin^2(theta_0)) / 2 * (phi_1 - phi_0) / pi
 *   = N (sin^2(theta_1) - sin^2(theta_0)) / PHI_BINS. */
static double cosine_fit_p_value(Sampler sampler, double *statistic, int *dof)
{
    static double observed[THETA_BINS * PHI_BINS], expected[THETA_BINS * PHI_BINS];
    const double d_theta = 0.5 * PI / THETA_BINS;
    for (int i = 0; i < THETA_BINS; i++) {
        double sin0 = sin(i * d_theta), sin1 = sin((i + 1) * d_theta);
        for (int j = 0; j < PHI_BINS; j++) {
            expected[i * PHI_BINS + j] = SAMPLES * (sin1 * sin1 - sin0 * sin0) / PHI_BINS;
            observed[i * PHI_BINS + j] = 0.0;
        }
    }
    Rng rng = rng_for_sample(SEED, 1, 0);
    for (int k = 0; k < SAMPLES; k++) {
        double u1 = rng_uniform(&rng), u2 = rng_uniform(&rng);
        Vec3 w = sampler(u1, u2);
        double phi = atan2(w.y, w.x);
        if (phi < 0.0)
            phi += 2.0 * PI;
        int i = (int)(acos(fmin(1.0, w.z)) / d_theta);
        int j = (int)(phi / (2.0 * PI) * PHI_BINS);
        i = i < THETA_BINS ? i : THETA_BINS - 1;
        j = j < PHI_BINS ? j : PHI_BINS - 1;
        observed[i * PHI_BINS + j] += 1.0;
    }
    *statistic = chi_square_statistic(observed, expected, THETA_BINS * PHI_BINS, dof);
    return chi_square_p_value(*statistic, *dof);
}

/* The sampler's directions follow cos(theta) / pi: not rejected at level 0.01.
 * Observed with seed 2019: X^2 = 183.1 with 199 degrees of freedom, p = 0.78. */
static void test_chi_square_accepts_cosine_sampler(void **state)
{
    double statistic;
    int dof;
    double p = cosine_fit_p_value(hemisphere_sample_cosine, &statistic, &dof);
    print_message("cosine sampler: X^2 = %.1f, dof = %d, p = %.3g\n", statistic, dof, p);
    assert_int_equal(dof, THETA_BINS * PHI_BINS - 1);
    assert_true(p >= SIGNIFICANCE);
}

/* The same test has the power to catch wrong samplers: both are rejected at level 0.01.
 * Observed with seed 2019, 199 degrees of freedom: the uniform sampler X^2 = 9.19e5
 * (p = 0 in double precision); exponent 0.49 X^2 = 494.4 (p = 4e-27). */
static void test_chi_square_rejects_wrong_samplers(void **state)
{
    const Sampler wrong[] = {sample_uniform_by_mistake, sample_slightly_wrong_exponent};
    for (int k = 0; k < 2; k++) {
        double statistic;
        int dof;
        double p = cosine_fit_p_value(wrong[k], &statistic, &dof);
        print_message("wrong sampler %d: X^2 = %.4g, dof = %d, p = %.3g\n", k, statistic, dof,
                      p);
        assert_true(p < SIGNIFICANCE);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_samples_unit_and_above_surface),
        cmocka_unit_test(test_inverse_cdf_by_hand),
        cmocka_unit_test(test_pdf_integrates_to_one),
        cmocka_unit_test(test_chi_square_accepts_cosine_sampler),
        cmocka_unit_test(test_chi_square_rejects_wrong_samplers),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
