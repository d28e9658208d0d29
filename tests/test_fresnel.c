/* test_fresnel.c (chapter 4): the exact Fresnel reflectance with the errata of fresnel.h and
 * snell.h (fresnel.h, chapter 4).
 *
 * Landmark values (normal and grazing incidence, Brewster's angle, the critical angle,
 * no interface), a value at 80 degrees against Schlick's approximation, the unpolarised
 * reflectance by hand at Brewster's angle, 45 and 30 degrees, and a sweep over
 * angles and indices in both directions: never NaN, always in [0, 1].
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>

#include "fresnel.h"
#include "schlick.h"
#include "snell.h"

#define GLASS 1.5
#define DEGREES (PI / 180.0)

/* Normal incidence: both polarisations reflect ((n1 - n2) / (n1 + n2))^2, the same
 * entering and leaving: 0.04 for air and glass, 0.1739 for air and index 2.5. */
static void test_normal_incidence(void **state)
{
    const double n2s[] = {GLASS, 2.5, 1.0001, 4.0};
    for (int k = 0; k < 4; k++) {
        double r0 = (1.0 - n2s[k]) / (1.0 + n2s[k]);
        r0 *= r0;
        assert_float_equal(fresnel_reflectance(1.0, 1.0, n2s[k]), r0, 1e-15);
        assert_float_equal(fresnel_reflectance(1.0, n2s[k], 1.0), r0, 1e-15);
        assert_float_equal(fresnel_s(1.0, 1.0, n2s[k]), r0, 1e-15);
        assert_float_equal(fresnel_p(1.0, n2s[k], 1.0), r0, 1e-15);
    }
    assert_float_equal(fresnel_reflectance(1.0, 1.0, GLASS), 0.04, 1e-15);
}

/* 80 degrees from air into glass, by hand: sin_t = sin(80) / 1.5 = 0.656539,
 * cos_t = 0.754293, R_s = (-0.957791 / 1.305087)^2 = 0.538595,
 * R_p = (0.493820 / 1.014765)^2 = 0.236814, R = 0.387704. Schlick gives
 * 0.04 + 0.96 (1 - cos 80)^5 = 0.409910 there: 2.2 percentage points too high. */
static void test_value_at_80_degrees(void **state)
{
    double cos_i = cos(80.0 * DEGREES);
    assert_float_equal(fresnel_s(cos_i, 1.0, GLASS), 0.538595, 1e-6);
    assert_float_equal(fresnel_p(cos_i, 1.0, GLASS), 0.236814, 1e-6);
    assert_float_equal(fresnel_reflectance(cos_i, 1.0, GLASS), 0.3877, 1e-3);
    assert_float_equal(schlick_reflectance(cos_i, 1.0, GLASS), 0.4099, 1e-3);
}

/* Leaving glass: R = 1 at the critical angle arcsin(1 / 1.5) = 41.81 degrees and
 * beyond (total internal reflection), and R rises to it continuously: just below the
 * critical angle R is already close to 1 and it never decreases on the way. */
static void test_total_internal_reflection(void **state)
{
    double critical = fresnel_critical_angle(GLASS, 1.0);
    assert_float_equal(critical, asin(1.0 / GLASS), 1e-15);
    assert_float_equal(fresnel_reflectance(cos(critical), GLASS, 1.0), 1.0, 1e-6);
    for (double angle = critical + 1e-9; angle <= 0.5 * PI; angle += 0.001)
        assert_true(fresnel_reflectance(cos(angle), GLASS, 1.0) == 1.0);
    assert_true(fresnel_reflectance(0.0, GLASS, 1.0) == 1.0);
    assert_float_equal(fresnel_reflectance(cos(critical - 1e-10), GLASS, 1.0), 1.0, 1e-3);
    double previous = 0.0;
    for (int k = 0; k <= 100000; k++) {
        double r = fresnel_reflectance(cos(critical * k / 100000.0), GLASS, 1.0);
        assert_true(r >= previous - 1e-12);
        previous = r;
    }
}

/* No interface (n_i = n_t): nothing is reflected, at any angle including grazing. */
static void test_no_interface_reflects_nothing(void **state)
{
    for (int degrees = 0; degrees <= 90; degrees++) {
        double cos_i = cos(degrees * DEGREES);
        assert_true(fresnel_reflectance(cos_i, GLASS, GLASS) == 0.0);
        assert_true(fresnel_reflectance(cos_i, 1.0, 1.0) == 0.0);
    }
    assert_true(fresnel_reflectance(0.0, GLASS, GLASS) == 0.0);
}

/* Grazing incidence (90 degrees) entering a denser medium: everything is reflected. */
static void test_grazing_reflects_everything(void **state)
{
    const double n2s[] = {1.0001, GLASS, 4.0};
    for (int k = 0; k < 3; k++) {
        assert_float_equal(fresnel_reflectance(0.0, 1.0, n2s[k]), 1.0, 1e-15);
        assert_float_equal(fresnel_s(0.0, 1.0, n2s[k]), 1.0, 1e-15);
        assert_float_equal(fresnel_p(0.0, 1.0, n2s[k]), 1.0, 1e-15);
    }
}

/* Brewster's angle atan(n_t / n_i): the p-polarised reflectance vanishes (56.31 degrees
 * entering glass, 33.69 degrees leaving it), while R_s does not. */
static void test_brewster_angle(void **state)
{
    double entering = atan(GLASS / 1.0), leaving = atan(1.0 / GLASS);
    assert_float_equal(fresnel_p(cos(entering), 1.0, GLASS), 0.0, 1e-15);
    assert_float_equal(fresnel_p(cos(leaving), GLASS, 1.0), 0.0, 1e-15);
    assert_true(fresnel_s(cos(entering), 1.0, GLASS) > 0.1);
}

/* The unpolarised reflectance is the mean of the two polarisations, checked by values
 * worked out by hand rather than by 80 degrees alone. At Brewster's angle R_p = 0, so
 * R = R_s / 2, and there sin(theta_i - theta_t) = (n^2 - 1) / (n^2 + 1) with theta_i +
 * theta_t = 90 degrees: R = ((n^2 - 1) / (n^2 + 1))^2 / 2 = (1.25 / 3.25)^2 / 2 =
 * 0.0739645 for glass, entering and leaving alike. At 45 degrees entering glass:
 * cos_t = 0.881917, R_s = 0.0920134, R_p = 0.00846646, R = 0.0502399; at 30 degrees
 * leaving it: cos_t = 0.661438, R = (0.105773 + 0.00460754) / 2 = 0.0551902. A Fresnel
 * that returns R_s alone gives 0.148, 0.092 and 0.106 (the planted bug). */
static void test_unpolarised_by_hand(void **state)
{
    double brewster = (GLASS * GLASS - 1.0) / (GLASS * GLASS + 1.0);
    brewster = 0.5 * brewster * brewster;
    assert_float_equal(brewster, 0.0739645, 1e-7);
    assert_float_equal(fresnel_reflectance(cos(atan(GLASS)), 1.0, GLASS), brewster, 1e-12);
    assert_float_equal(fresnel_reflectance(cos(atan(1.0 / GLASS)), GLASS, 1.0), brewster,
                       1e-12);
    assert_float_equal(fresnel_reflectance(cos(45.0 * DEGREES), 1.0, GLASS), 0.0502399, 1e-7);
    assert_float_equal(fresnel_reflectance(cos(30.0 * DEGREES), GLASS, 1.0), 0.0551902, 1e-7);
}

/* With the labels corrected, R_s >= R_p at every angle entering glass: the
 * s-polarised wave is always reflected at least as strongly. */
static void test_s_reflects_at_least_p(void **state)
{
    for (int k = 0; k <= 9000; k++) {
        double cos_i = cos(k * 0.01 * DEGREES);
        assert_true(fresnel_s(cos_i, 1.0, GLASS) >= fresnel_p(cos_i, 1.0, GLASS));
    }
}

/* R_s, R_p and R are finite and in [0, 1] at incidence cosine cos_i, index n, both
 * from air into n and from n into air. */
static void assert_bounded_both_ways(double cos_i, double n)
{
    for (int leaving = 0; leaving < 2; leaving++) {
        double n_i = leaving ? n : 1.0, n_t = leaving ? 1.0 : n;
        const double r[] = {fresnel_s(cos_i, n_i, n_t), fresnel_p(cos_i, n_i, n_t),
                            fresnel_reflectance(cos_i, n_i, n_t)};
        for (int j = 0; j < 3; j++) {
            assert_true(isfinite(r[j]));
            assert_true(r[j] >= 0.0 && r[j] <= 1.0);
        }
    }
}

/* A sweep over angles 0 to 90 degrees in 0.01 degree steps, the exact end points
 * cos = 0 and 1, and cosines a rounding step outside [0, 1], for indices from 1.0001 to
 * 4, both directions: never NaN, never outside [0, 1]. */
static void test_sweep_finite_and_bounded(void **state)
{
    const double edges[] = {0.0, 1.0, -1e-17, 1.0 + 1e-15};
    for (int step = 0; step <= 60; step++) {
        double n = 1.0001 + step * (4.0 - 1.0001) / 60.0;
        for (int k = 0; k <= 9000; k++)
            assert_bounded_both_ways(cos(k * 0.01 * DEGREES), n);
        for (int e = 0; e < 4; e++)
            assert_bounded_both_ways(edges[e], n);
    }
}

/* The critical angle is arcsin(n_t / n_i) (not the report's n_i / n_t):
 * 41.81 degrees from glass of 1.5 into air, 48.61 from water; none (pi/2) entering a
 * denser medium or with n_i = n_t. */
static void test_critical_angle_values(void **state)
{
    assert_float_equal(fresnel_critical_angle(1.5, 1.0), asin(1.0 / 1.5), 1e-15);
    assert_float_equal(fresnel_critical_angle(1.5, 1.0) * 180.0 / PI, 41.8103, 1e-4);
    assert_float_equal(fresnel_critical_angle(1.333, 1.0) * 180.0 / PI, 48.6066, 1e-4);
    assert_float_equal(fresnel_critical_angle(4.0, 1.5), asin(1.5 / 4.0), 1e-15);
    assert_float_equal(fresnel_critical_angle(1.0, 1.5), 0.5 * PI, 0);
    assert_float_equal(fresnel_critical_angle(1.5, 1.5), 0.5 * PI, 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_normal_incidence),
        cmocka_unit_test(test_value_at_80_degrees),
        cmocka_unit_test(test_total_internal_reflection),
        cmocka_unit_test(test_critical_angle_values),
        cmocka_unit_test(test_no_interface_reflects_nothing),
        cmocka_unit_test(test_grazing_reflects_everything),
        cmocka_unit_test(test_brewster_angle),
        cmocka_unit_test(test_unpolarised_by_hand),
        cmocka_unit_test(test_s_reflects_at_least_p),
        cmocka_unit_test(test_sweep_finite_and_bounded),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
