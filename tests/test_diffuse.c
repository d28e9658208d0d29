/* test_diffuse.c (chapter 2): the diffuse BRDFs and their sampling in world space
 * (diffuse.h: Lambert, eq. 8, cosine sampling, eqs. 9-12; from chapter 5 Oren-Nayar,
 * eqs. 13-14 corrected).
 *
 * diffuse.c only moves directions into the local frame around the normal n and back,
 * so what can go wrong is the frame: a BRDF evaluated in a wrong or tilted frame, or
 * samples drawn around the wrong axis. The tests therefore use random tilted normals and
 * compare with a frame of their own, built independently by Gram-Schmidt:
 *   - Lambert's BRDF is rho / pi whatever the directions;
 *   - Oren-Nayar's equals oren_nayar_brdf of the directions' coordinates in that frame
 *     (any frame around n will do, since the model is isotropic), including one value
 *     worked by hand, and is unchanged when both directions turn about n;
 *   - a sample is a unit direction on n's side whose weight is f cos / pdf, pdf = cos/pi;
 *   - the samples follow cos(theta) / pi about n: a chi-square test at significance
 *     0.01 with a fixed seed, shown to reject the same samples binned about an axis
 *     1 degree off.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include "check.h"
#include "chi_square.h"
#include "diffuse.h"
#include "frame.h"
#if CHAPTER >= 5
#include "oren_nayar.h"
#endif

#define PAIRS 100000
#define RELATIVE 1e-12
#define SAMPLES 1000000
#define COS_BINS 10
#define PHI_BINS 20
#define SIGNIFICANCE 0.01

static const Vec3 RHO = {0.75, 0.4, 0.15};

static Material lambert_material(void)
{
    Material m = {.name = "lambert", .kind = MATERIAL_LAMBERT, .reflectance = RHO};
    return m;
}

/* An orthonormal frame (t, b, n) by Gram-Schmidt from whichever axis is far from n:
 * deliberately not vec3_basis, so the comparison is independent of diffuse.c's frame. */
static void own_frame(Vec3 n, Vec3 *t, Vec3 *b)
{
    Vec3 axis = fabs(n.x) < 0.9 ? vec3(1, 0, 0) : vec3(0, 1, 0);
    *t = vec3_normalize(vec3_add_scaled(axis, n, -vec3_dot(axis, n)));
    *b = vec3_cross(n, *t);
}

static Vec3 to_own_frame(Vec3 w, Vec3 t, Vec3 b, Vec3 n)
{
    return vec3(vec3_dot(w, t), vec3_dot(w, b), vec3_dot(w, n));
}

/* A random unit direction on n's side of the surface. */
static Vec3 random_above(TestRandom *rng, Vec3 n)
{
    Vec3 w = random_unit_vector(rng);
    return vec3_dot(w, n) < 0.0 ? vec3_neg(w) : w;
}

#if CHAPTER >= 5
static Material rough_material(double sigma)
{
    Material m = {
        .name = "rough", .kind = MATERIAL_OREN_NAYAR, .reflectance = RHO, .sigma = sigma};
    return m;
}

/* v turned by angle phi about the unit axis n (Rodrigues' formula). */
static Vec3 rotate_about(Vec3 v, Vec3 n, double phi)
{
    Vec3 r = vec3_add(vec3_scale(v, cos(phi)), vec3_scale(vec3_cross(n, v), sin(phi)));
    return vec3_add_scaled(r, n, vec3_dot(n, v) * (1.0 - cos(phi)));
}
#endif

static void assert_colour_close(Vec3 a, Vec3 b, double relative)
{
    assert_close(a.x, b.x, relative * fabs(b.x));
    assert_close(a.y, b.y, relative * fabs(b.y));
    assert_close(a.z, b.z, relative * fabs(b.z));
}

/* Eq. 8: a Lambertian surface's BRDF is rho / pi for any normal and any pair of
 * directions, on either side: it does not depend on direction at all. */
static void test_lambert_is_rho_over_pi_everywhere(void **state)
{
    Material m = lambert_material();
    TestRandom rng = test_random(1, 0, 0);
    for (int i = 0; i < PAIRS; i++) {
        Vec3 n = random_unit_vector(&rng), wi = random_unit_vector(&rng);
        Vec3 wo = random_unit_vector(&rng);
        assert_colour_close(diffuse_brdf(&m, n, wi, wo), vec3_scale(RHO, 1.0 / PI), RELATIVE);
    }
}

#if CHAPTER >= 5
/* Oren-Nayar in world space equals eq. 13 of the directions' local coordinates, here
 * computed in the test's own frame around random tilted normals, for smooth to very
 * rough surfaces. A frame that is not orthonormal, or not around n, changes the
 * angles and fails this. */
static void test_oren_nayar_matches_own_local_frame(void **state)
{
    const double sigmas[] = {0.0, 0.2, 0.5, 1.0, 10.0};
    TestRandom rng = test_random(2, 0, 0);
    for (int k = 0; k < 5; k++) {
        Material m = rough_material(sigmas[k]);
        for (int i = 0; i < PAIRS / 5; i++) {
            Vec3 n = random_unit_vector(&rng), t, b;
            Vec3 wi = random_above(&rng, n), wo = random_above(&rng, n);
            own_frame(n, &t, &b);
            Vec3 expected = oren_nayar_brdf(RHO, sigmas[k], to_own_frame(wi, t, b, n),
                                            to_own_frame(wo, t, b, n));
            assert_colour_close(diffuse_brdf(&m, n, wi, wo), expected, RELATIVE);
        }
    }
}
#endif

#if CHAPTER >= 5
/* One value by hand around a tilted normal: sigma = 0.5, theta_i = 60 deg at azimuth 0,
 * theta_o = 30 deg at azimuth 60 deg (azimuths in the test's own frame) give
 * A + B cos(60) sin(60) tan(30) = 0.784483 + 0.25 * 0.330882 = 0.867203
 * (test_oren_nayar.c works the same numbers in the local frame). */
static void test_oren_nayar_value_by_hand_around_tilted_normal(void **state)
{
    Material m = rough_material(0.5);
    Vec3 n = vec3_normalize(vec3(0.3, -0.8, 0.5)), t, b;
    own_frame(n, &t, &b);
    Vec3 wi = vec3_from_local(vec3(sqrt(3.0) / 2.0, 0.0, 0.5), t, b, n);
    Vec3 wo = vec3_from_local(vec3(0.25, sqrt(3.0) / 4.0, sqrt(3.0) / 2.0), t, b, n);
    Vec3 f = diffuse_brdf(&m, n, wi, wo);
    assert_close(f.x, RHO.x * 0.867203 / PI, 1e-6);
    assert_close(f.y, RHO.y * 0.867203 / PI, 1e-6);
    assert_close(f.z, RHO.z * 0.867203 / PI, 1e-6);
}
#endif

#if CHAPTER >= 5
/* The model is isotropic: turning wi and wo together about n by any angle leaves the
 * BRDF unchanged (only theta_i, theta_o and phi_i - phi_o enter eq. 13). */
static void test_oren_nayar_invariant_under_rotation_about_normal(void **state)
{
    Material m = rough_material(0.7);
    TestRandom rng = test_random(3, 0, 0);
    for (int i = 0; i < PAIRS; i++) {
        Vec3 n = random_unit_vector(&rng);
        Vec3 wi = random_above(&rng, n), wo = random_above(&rng, n);
        double phi = 2.0 * PI * test_uniform(&rng);
        Vec3 turned = diffuse_brdf(&m, n, rotate_about(wi, n, phi), rotate_about(wo, n, phi));
        assert_colour_close(turned, diffuse_brdf(&m, n, wi, wo), RELATIVE);
    }
}
#endif

/* The sample numbers of the next two tests: the extreme corners of [0, 1)^2 first. */
static void sample_numbers(int i, TestRandom *rng, Vec3 *n, Vec3 *wo, double *u1, double *u2)
{
    const double top = 1.0 - 0x1p-32;
    *n = i == 0 ? vec3(0, 0, -1) : random_unit_vector(rng);
    *wo = random_above(rng, *n);
    *u1 = i < 4 ? (i & 1) * top : test_uniform(rng);
    *u2 = i < 4 ? (i >> 1) * top : test_uniform(rng);
}

/* A sample is a unit direction on n's side (never on or below the surface, even for the
 * extreme random numbers), and its weight is f(wi, wo) cos / pdf with pdf = cos / pi:
 * rho exactly for Lambert. diffuse_pdf is that pdf. */
static void test_sample_direction_and_weight(void **state)
{
    Material lambert = lambert_material();
    TestRandom rng = test_random(4, 0, 0);
    for (int i = 0; i < PAIRS; i++) {
        Vec3 n, wo, wi;
        double u1, u2;
        sample_numbers(i, &rng, &n, &wo, &u1, &u2);
        Vec3 weight = diffuse_sample(&lambert, n, wo, u1, u2, &wi);
        assert_close(vec3_length(wi), 1.0, 1e-15);
        double cos_theta = vec3_dot(wi, n);
        assert_true(cos_theta > 0.0);
        double pdf = cos_theta / PI;
        assert_close(diffuse_pdf(n, wi), pdf, 1e-15);
        Vec3 f = diffuse_brdf(&lambert, n, wi, wo);
        assert_true(weight.x == RHO.x && weight.y == RHO.y && weight.z == RHO.z);
        assert_colour_close(weight, vec3_scale(f, cos_theta / pdf), RELATIVE);
    }
}

#if CHAPTER >= 5
/* An Oren-Nayar sample takes the Lambertian sample's direction (the sampling does not
 * depend on the BRDF), and its weight is f(wi, wo) cos / pdf = rho * oren_nayar_factor. */
static void test_oren_nayar_sample_weight(void **state)
{
    Material lambert = lambert_material(), rough = rough_material(0.6);
    TestRandom rng = test_random(4, 0, 0);
    for (int i = 0; i < PAIRS; i++) {
        Vec3 n, wo, wi, wi_rough, t, b;
        double u1, u2;
        sample_numbers(i, &rng, &n, &wo, &u1, &u2);
        diffuse_sample(&lambert, n, wo, u1, u2, &wi);
        Vec3 weight_rough = diffuse_sample(&rough, n, wo, u1, u2, &wi_rough);
        assert_true(wi.x == wi_rough.x && wi.y == wi_rough.y && wi.z == wi_rough.z);
        double cos_theta = vec3_dot(wi, n), pdf = cos_theta / PI;
        Vec3 f_rough = diffuse_brdf(&rough, n, wi, wo);
        assert_colour_close(weight_rough, vec3_scale(f_rough, cos_theta / pdf), RELATIVE);
        own_frame(n, &t, &b);
        Vec3 wi_local = to_own_frame(wi, t, b, n), wo_local = to_own_frame(wo, t, b, n);
        double factor = oren_nayar_factor(0.6, wi_local, wo_local);
        assert_colour_close(weight_rough, vec3_scale(RHO, factor), RELATIVE);
    }
}
#endif

/* diffuse_pdf is a density of directions: its integral over the sphere around a tilted
 * normal is 1 (midpoint rule in theta and phi, dw = sin theta dtheta dphi), and it is
 * diffuse_sample's density: for g = cos^2 theta the mean of g / pdf over the samples is
 * the integral of g over the hemisphere, 2 pi / 3 (E_p[g / p] = integral of g dw; with
 * this g the ratio is bounded, so its standard error can be trusted). */
static void test_pdf_integrates_to_one_and_matches_the_samples(void **state)
{
    enum {
        STEPS = 400
    };
    Vec3 n = vec3_normalize(vec3(0.3, -0.8, 0.5)), t, b;
    own_frame(n, &t, &b);
    double integral = 0.0;
    for (int i = 0; i < STEPS; i++)
        for (int j = 0; j < 2 * STEPS; j++) {
            double theta = (i + 0.5) * PI / STEPS, phi = (j + 0.5) * PI / STEPS;
            Vec3 w = vec3_from_local(
                vec3(sin(theta) * cos(phi), sin(theta) * sin(phi), cos(theta)), t, b, n);
            integral += diffuse_pdf(n, w) * sin(theta) * (PI / STEPS) * (PI / STEPS);
        }
    Material lambert = lambert_material();
    TestRandom rng = test_random(6, 0, 0);
    double sum = 0.0, sum_squares = 0.0;
    for (int k = 0; k < PAIRS; k++) {
        double u1 = test_uniform(&rng), u2 = test_uniform(&rng);
        Vec3 wi;
        diffuse_sample(&lambert, n, n, u1, u2, &wi);
        double cos_theta = vec3_dot(n, wi), ratio = cos_theta * cos_theta / diffuse_pdf(n, wi);
        sum += ratio;
        sum_squares += ratio * ratio;
    }
    double mean = sum / PAIRS, error = sqrt((sum_squares / PAIRS - mean * mean) / (PAIRS - 1));
    print_message("    integral %.6f; mean cos^2 / pdf %.5f +- %.5f, 2 pi / 3 = %.5f\n",
                  integral, mean, error, 2.0 * PI / 3.0);
    assert_true(fabs(integral - 1.0) < 1e-4);
    assert_true(fabs(mean - 2.0 * PI / 3.0) < 4.0 * error);
}

/* Counts SAMPLES directions from diffuse_sample around the normal n, binned about the
 * axis `axis` (n itself, or a wrong one) in the test's own frame, and returns the
 * chi-square p-value against the cosine density. Bins: cos^2(theta) in COS_BINS equal
 * steps and phi in PHI_BINS equal steps. Under cos(theta) / pi, P(cos theta <= c) =
 * c^2 (the CDF of eq. 11, sin^2 theta, from the other end) and phi is uniform, so every
 * bin expects SAMPLES / (COS_BINS * PHI_BINS) = 5000. A direction below the axis's
 * horizon is counted in the lowest bin (test_sample_direction_and_weight already
 * forbids those about n), so that a wrong axis is judged by the shape of the
 * distribution, not by a single impossible sample. */
static double cosine_fit_p_value(Vec3 n, Vec3 axis, double *statistic, int *dof)
{
    static double observed[COS_BINS * PHI_BINS], expected[COS_BINS * PHI_BINS];
    for (int j = 0; j < COS_BINS * PHI_BINS; j++) {
        observed[j] = 0.0;
        expected[j] = (double)SAMPLES / (COS_BINS * PHI_BINS);
    }
    Material m = lambert_material();
    Vec3 t, b, wi, wo = n;
    own_frame(axis, &t, &b);
    TestRandom rng = test_random(5, 0, 0);
    for (int k = 0; k < SAMPLES; k++) {
        double u1 = test_uniform(&rng), u2 = test_uniform(&rng);
        diffuse_sample(&m, n, wo, u1, u2, &wi);
        Vec3 local = to_own_frame(wi, t, b, axis);
        double cos_theta = fmax(0.0, local.z), phi = atan2(local.y, local.x);
        if (phi < 0.0)
            phi += 2.0 * PI;
        int i = (int)(cos_theta * cos_theta * COS_BINS), j = (int)(phi / (2.0 * PI) * PHI_BINS);
        i = i < COS_BINS ? i : COS_BINS - 1;
        j = j < PHI_BINS ? j : PHI_BINS - 1;
        observed[i * PHI_BINS + j] += 1.0;
    }
    *statistic = chi_square_statistic(observed, expected, COS_BINS * PHI_BINS, dof);
    return chi_square_p_value(*statistic, *dof);
}

/* The sampled directions follow cos(theta) / pi about the tilted normal: not rejected
 * at level 0.01 (fixed seed), for a generic normal and for n = -z, where vec3_basis
 * switches branch. Observed, 199 degrees of freedom: X^2 = 169.2 (p = 0.94) and
 * X^2 = 190.1 (p = 0.66). */
static void test_chi_square_cosine_about_tilted_normal(void **state)
{
    const Vec3 normals[] = {vec3_normalize(vec3(0.3, -0.8, 0.5)), vec3(0, 0, -1)};
    for (int k = 0; k < 2; k++) {
        double statistic;
        int dof;
        double p = cosine_fit_p_value(normals[k], normals[k], &statistic, &dof);
        print_message("    normal %d: X^2 = %.1f, dof = %d, p = %.3g\n", k, statistic, dof, p);
        assert_int_equal(dof, COS_BINS * PHI_BINS - 1);
        assert_true(p >= SIGNIFICANCE);
    }
}

/* The test has the power to see a frame that is slightly off: the same samples binned
 * about an axis 1 degree from n are rejected at level 0.01. Observed: X^2 = 1043 with
 * 199 degrees of freedom, p = 2e-114 (half a degree still gives X^2 = 399, p = 2e-15). */
static void test_chi_square_rejects_axis_one_degree_off(void **state)
{
    Vec3 n = vec3_normalize(vec3(0.3, -0.8, 0.5)), t, b;
    own_frame(n, &t, &b);
    double tilt = 1.0 * PI / 180.0;
    Vec3 axis = vec3_add(vec3_scale(n, cos(tilt)), vec3_scale(t, sin(tilt)));
    double statistic;
    int dof;
    double p = cosine_fit_p_value(n, axis, &statistic, &dof);
    print_message("    axis 1 degree off: X^2 = %.4g, dof = %d, p = %.3g\n", statistic, dof, p);
    assert_true(p < SIGNIFICANCE);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_lambert_is_rho_over_pi_everywhere),
#if CHAPTER >= 5
        cmocka_unit_test(test_oren_nayar_matches_own_local_frame),
        cmocka_unit_test(test_oren_nayar_value_by_hand_around_tilted_normal),
        cmocka_unit_test(test_oren_nayar_invariant_under_rotation_about_normal),
#endif
        cmocka_unit_test(test_sample_direction_and_weight),
#if CHAPTER >= 5
        cmocka_unit_test(test_oren_nayar_sample_weight),
#endif
        cmocka_unit_test(test_pdf_integrates_to_one_and_matches_the_samples),
        cmocka_unit_test(test_chi_square_cosine_about_tilted_normal),
        cmocka_unit_test(test_chi_square_rejects_axis_one_degree_off),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
