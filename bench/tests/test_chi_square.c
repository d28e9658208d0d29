/* test_chi_square.c (bench, chapter 2): Pearson's chi-square test (chi_square.h).
 *
 * The statistic is checked by hand, the merging of sparse bins by hand, and the p-value
 * against tabulated quantiles and against the closed forms for 1 and for even degrees
 * of freedom. Finally the whole test is run on a fair die many times with a fixed seed:
 * it must reject a correct sampler about as often as its significance level says.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>

#include "chi_square.h"
#include "rng.h"

/* Three bins by hand: (10 - 20)^2 / 20 + 0 + (30 - 20)^2 / 20 = 10, with 2 degrees of
 * freedom. */
static void test_statistic_by_hand(void **state)
{
    const double observed[] = {10, 20, 30}, expected[] = {20, 20, 20};
    int dof;
    assert_float_equal(chi_square_statistic(observed, expected, 3, &dof), 10.0, 1e-12);
    assert_int_equal(dof, 2);
}

/* Bins expecting fewer than 5 are merged in order: expected {2, 2, 2 | 10 | 1, 3}
 * gives the groups 6 and 10, and the remainder 4 joins the last: 6 and 14, one degree
 * of freedom. Observed {3, 1, 4 | 9 | 2, 2} -> 8 and 13:
 *     X^2 = (8 - 6)^2 / 6 + (13 - 14)^2 / 14 = 2/3 + 1/14. */
static void test_sparse_bins_are_merged(void **state)
{
    const double observed[] = {3, 1, 4, 9, 2, 2}, expected[] = {2, 2, 2, 10, 1, 3};
    int dof;
    double statistic = chi_square_statistic(observed, expected, 6, &dof);
    assert_int_equal(dof, 1);
    assert_float_equal(statistic, 2.0 / 3.0 + 1.0 / 14.0, 1e-12);
}

/* Bins are merged by what they expect, never by what they received: expected {2, 2, 2,
 * 10} against observed {6, 0, 0, 10} merges the first three (6 against 6) and fits
 * exactly, X^2 = 0; merging by the observed counts would pair 6 with 2 and give 9.1. */
static void test_bins_merged_by_expected_counts(void **state)
{
    const double observed[] = {6, 0, 0, 10}, expected[] = {2, 2, 2, 10};
    int dof;
    double statistic = chi_square_statistic(observed, expected, 4, &dof);
    assert_int_equal(dof, 1);
    assert_float_equal(statistic, 0.0, 1e-12);
}

/* Degenerate inputs: too few expected samples to form two groups leaves nothing to test
 * (dof 0, p = 1); a sample where none can occur is an infinite statistic (p = 0). */
static void test_degenerate_inputs(void **state)
{
    const double few_observed[] = {1, 2}, few_expected[] = {2, 1};
    int dof;
    double statistic = chi_square_statistic(few_observed, few_expected, 2, &dof);
    assert_int_equal(dof, 0);
    assert_true(chi_square_p_value(statistic, dof) == 1.0);

    const double observed[] = {50, 49, 1}, expected[] = {50, 50, 0};
    statistic = chi_square_statistic(observed, expected, 3, &dof);
    assert_true(isinf(statistic));
    assert_true(chi_square_p_value(statistic, dof) == 0.0);
    assert_true(chi_square_p_value(NAN, 5) == 0.0);
    assert_true(chi_square_p_value(0.0, 5) == 1.0);
}

/* Tabulated quantiles of the chi-square distribution (upper 5% and 1% points). */
static void test_p_value_at_tabulated_quantiles(void **state)
{
    assert_float_equal(chi_square_p_value(3.841, 1), 0.05, 1e-3);
    assert_float_equal(chi_square_p_value(18.307, 10), 0.05, 1e-3);
    assert_float_equal(chi_square_p_value(124.342, 100), 0.05, 1e-3);
    assert_float_equal(chi_square_p_value(6.635, 1), 0.01, 1e-4);
    assert_float_equal(chi_square_p_value(23.209, 10), 0.01, 1e-4);
    assert_float_equal(chi_square_p_value(135.807, 100), 0.01, 1e-4);
}

/* Closed forms, to near machine precision, over x from 1e-3 to 1e3 (both the series
 * and the continued fraction, and p from 1 down to 1e-200):
 *     1 degree of freedom:   p = erfc(sqrt(x / 2)),
 *     k = 2m degrees:        p = e^(-x/2) sum_{i < m} (x/2)^i / i!. */
static void test_p_value_closed_forms(void **state)
{
    const int even_dofs[] = {2, 10, 100};
    for (double x = 1e-3; x <= 1e3; x *= 1.1) {
        double exact = erfc(sqrt(0.5 * x));
        assert_float_equal(chi_square_p_value(x, 1), exact, 1e-13 + 1e-10 * exact);
        for (int k = 0; k < 3; k++) {
            double term = exp(-0.5 * x), sum = 0.0;
            for (int i = 0; i < even_dofs[k] / 2; i++) {
                sum += term;
                term *= 0.5 * x / (i + 1);
            }
            assert_float_equal(chi_square_p_value(x, even_dofs[k]), sum, 1e-13 + 1e-10 * sum);
        }
    }
}

/* The test's false alarm rate: 1000 experiments of 600 fair die rolls each, tested at
 * level 0.05, should reject about 50 of them (binomial, standard deviation 6.9); a
 * wrong p-value would reject far more or far fewer. Observed with this seed: 46. */
static void test_rejects_fair_die_at_its_significance_level(void **state)
{
    const int experiments = 1000, rolls = 600;
    int rejected = 0;
    for (int e = 0; e < experiments; e++) {
        Rng rng = rng_for_sample(6, (uint64_t)e, 0);
        double observed[6] = {0}, expected[6];
        for (int face = 0; face < 6; face++)
            expected[face] = rolls / 6.0;
        for (int r = 0; r < rolls; r++)
            observed[(int)(6.0 * rng_uniform(&rng))] += 1.0;
        int dof;
        double statistic = chi_square_statistic(observed, expected, 6, &dof);
        rejected += chi_square_p_value(statistic, dof) < 0.05;
    }
    print_message("fair die rejected at level 0.05: %d of %d\n", rejected, experiments);
    assert_in_range(rejected, 30, 70);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_statistic_by_hand),
        cmocka_unit_test(test_sparse_bins_are_merged),
        cmocka_unit_test(test_bins_merged_by_expected_counts),
        cmocka_unit_test(test_degenerate_inputs),
        cmocka_unit_test(test_p_value_at_tabulated_quantiles),
        cmocka_unit_test(test_p_value_closed_forms),
        cmocka_unit_test(test_rejects_fair_die_at_its_significance_level),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
