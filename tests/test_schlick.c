/* test_schlick.c (chapter 1): Schlick's Fresnel approximation (schlick.h, report §3.5.2, eqs.
 * 6-7, with the erratum of schlick.h).
 *
 * Checked against hand values (R0 of glass, the 80 degree value), at the extremes of
 * (grazing incidence, n_i = n_t, exactly at the critical angle), and for the
 * erratum: leaving glass, R must rise continuously to 1 at the critical angle instead
 * of jumping there from about R0.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>

#include "check.h"
#include "schlick.h"
#include "snell.h"

static double degrees(double d) { return d * PI / 180.0; }

/* At normal incidence R = R0 = ((n1 - n2) / (n1 + n2))^2 (eq. 7), the same both ways:
 * 0.04 for glass of 1.5, 0.02 for water, 0.36 for n = 4. */
static void test_normal_incidence(void **state)
{
    const double iors[] = {1.0001, 1.333, 1.5, 2.42, 4.0};
    for (int i = 0; i < 5; i++) {
        double r0 = pow((1.0 - iors[i]) / (1.0 + iors[i]), 2);
        assert_close(schlick_reflectance(1.0, 1.0, iors[i]), r0, 1e-15);
        assert_close(schlick_reflectance(1.0, iors[i], 1.0), r0, 1e-15);
        assert_close(schlick_reflectance(1.0, 1.2, iors[i] * 1.2), r0, 1e-15);
    }
    assert_close(schlick_reflectance(1.0, 1.0, 1.5), 0.04, 1e-15);
    assert_close(schlick_reflectance(1.0, 1.0, 4.0), 0.36, 1e-15);
}

/* Entering glass of 1.5 at 80 degrees: 0.04 + 0.96 (1 - cos 80)^5 = 0.4099. */
static void test_eighty_degrees(void **state)
{
    assert_close(schlick_reflectance(cos(degrees(80)), 1.0, 1.5), 0.4099, 1e-3);
}

/* Grazing incidence entering a denser medium reflects everything: R(cos 0) = 1. */
static void test_grazing_entering(void **state)
{
    assert_close(schlick_reflectance(0.0, 1.0, 1.5), 1.0, 0);
    assert_close(schlick_reflectance(0.0, 1.0, 1.0001), 1.0, 0);
    assert_close(schlick_reflectance(0.0, 1.0, 4.0), 1.0, 0);
}

/* n_i = n_t: there is no interface and nothing reflects, at every angle (eq. 6 alone
 * would still give (1 - cos)^5). */
static void test_equal_indices(void **state)
{
    const double iors[] = {1.0, 1.5, 4.0};
    for (int i = 0; i < 3; i++)
        for (int k = 0; k <= 90; k++)
            assert_close(schlick_reflectance(cos(degrees(k)), iors[i], iors[i]), 0.0, 0);
}

/* Leaving glass (the erratum): R = 1 exactly at the critical angle and beyond it; just
 * below, R climbs to 1 continuously -- each step of 10 closer (1e-2 to 1e-10 rad)
 * brings it closer, to within 1e-4 -- instead of jumping from ~R0 as eq. 6 with the
 * incidence angle would. */
static void test_leaving_glass(void **state)
{
    const double iors[] = {1.0001, 1.333, 1.5, 2.42, 4.0};
    for (int i = 0; i < 5; i++) {
        double n_i = iors[i], critical = test_critical_angle(n_i, 1.0);
        assert_close(schlick_reflectance(cos(critical), n_i, 1.0), 1.0, 0);
        for (int k = 1; k <= 10; k++) {
            double beyond = critical + (0.5 * PI - critical) * k / 10.0;
            assert_close(schlick_reflectance(cos(beyond), n_i, 1.0), 1.0, 0);
        }
        double previous = 0.0;
        for (int e = 2; e <= 10; e++) {
            double r = schlick_reflectance(cos(critical - pow(10.0, -e)), n_i, 1.0);
            assert_true(r > previous && r < 1.0);
            previous = r;
        }
        assert_true(1.0 - previous < 1e-4);
    }
}

/* Over angles 0 to 90 degrees in steps of 0.01, both directions, IORs from 1.0001 to
 * 4: never NaN, always in [0, 1], and never decreasing as the angle grows. */
static void test_range_and_monotonic(void **state)
{
    for (double n = 1.0001; n <= 4.0; n = 1.0 + (n - 1.0) * 1.5) {
        double previous_in = 0.0, previous_out = 0.0;
        for (int k = 0; k <= 9000; k++) {
            double cos_i = k == 9000 ? 0.0 : cos(degrees(k / 100.0));
            double r_in = schlick_reflectance(cos_i, 1.0, n);
            double r_out = schlick_reflectance(cos_i, n, 1.0);
            assert_true(r_in >= 0.0 && r_in <= 1.0);
            assert_true(r_out >= 0.0 && r_out <= 1.0);
            assert_true(r_in >= previous_in && r_out >= previous_out);
            previous_in = r_in;
            previous_out = r_out;
        }
        assert_close(previous_in, 1.0, 0);
        assert_close(previous_out, 1.0, 0);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_normal_incidence), cmocka_unit_test(test_eighty_degrees),
        cmocka_unit_test(test_grazing_entering), cmocka_unit_test(test_equal_indices),
        cmocka_unit_test(test_leaving_glass),    cmocka_unit_test(test_range_and_monotonic),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
