/* test_mis.c (chapter 7): Tests of the power heuristic (lib/mis.c, chapter 7).
 *
 * The weights of the two strategies for the same direction must add up to 1 (that is
 * what keeps multiple importance sampling unbiased; the furnace and room tests in
 * test_path.c check the whole estimator), take the values of the formula, count each
 * strategy's samples, and stay finite where one density is 0 or enormous (a lamp seen
 * edge-on has p_light = d^2 / (A cos beta) -> infinity).
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>

#include "check.h"
#include "rng.h"
#include "mis.h"

static void test_weights_sum_to_one(void **state)
{
    Rng rng = rng_for_sample(1, 0, 0);
    for (int i = 0; i < 100000; i++) {
        int count_f = 1 + (int)(8 * rng_uniform(&rng)),
            count_g = 1 + (int)(8 * rng_uniform(&rng));
        double pdf_f = exp(30.0 * (rng_uniform(&rng) - 0.5)),
               pdf_g = exp(30.0 * (rng_uniform(&rng) - 0.5));
        double w_f = mis_power_heuristic(count_f, pdf_f, count_g, pdf_g);
        double w_g = mis_power_heuristic(count_g, pdf_g, count_f, pdf_f);
        assert_true(w_f >= 0.0 && w_f <= 1.0);
        assert_close(w_f + w_g, 1.0, 1e-12);
    }
}

static void test_values(void **state)
{
    assert_close(mis_power_heuristic(1, 2.0, 1, 2.0), 0.5, 1e-15);
    assert_close(mis_power_heuristic(1, 3.0, 1, 1.0), 0.9, 1e-15);         /* 9 / (9 + 1) */
    assert_close(mis_power_heuristic(4, 1.0, 1, 1.0), 16.0 / 17.0, 1e-15); /* counts */
    assert_close(mis_power_heuristic(1, 1.0, 4, 1.0), 1.0 / 17.0, 1e-15);
    assert_close(mis_power_heuristic(2, 1.0, 1, 2.0), 0.5, 1e-15);
}

static void test_zero_and_huge_densities(void **state)
{
    assert_true(mis_power_heuristic(1, 0.0, 1, 1.0) == 0.0);
    assert_true(mis_power_heuristic(1, 1.0, 1, 0.0) == 1.0);
    assert_true(mis_power_heuristic(1, 0.0, 1, 0.0) == 0.0);
    assert_true(mis_power_heuristic(1, 1e300, 1, 1.0) == 1.0);
    assert_true(mis_power_heuristic(1, 1.0, 1, 1e300) == 0.0);
    assert_true(mis_power_heuristic(1, INFINITY, 1, 1.0) == 1.0);
    assert_true(mis_power_heuristic(1, 1e-300, 1, 1e-300) == 0.5);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_weights_sum_to_one),
        cmocka_unit_test(test_values),
        cmocka_unit_test(test_zero_and_huge_densities),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
