/* test_student_t.c (bench, chapter 1): Student's t distribution (student_t.h).
 *
 * The tail against values computed with mpmath (its regularised incomplete beta at 30
 * digits) and against the closed forms for 1 and 2 degrees of freedom; the critical
 * values against the tail and a table; the detectable shift against mpmath's integral
 * and against the normal's 7.49 as the degrees of freedom grow. Finally the test itself,
 * run on simulated replicates: it must reject an unbiased estimate as often as its
 * level says, and detect a bias of the stated shift as often as its power says.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>

#include "assert_close.h"
#include "student_t.h"
#include "test_random.h"

/* The course's level, 1 - (1 - 1e-4)^(1/400) (grading.h). */
#define COURSE_LEVEL 2.50012469580273e-7

/* Two-sided tails from mpmath: betainc(nu / 2, 1 / 2, 0, nu / (nu + t^2), regularized). */
static void test_tail_against_mpmath(void **state)
{
    static const struct {
        double t;
        int dof;
        double p;
    } known[] = {
        {2.0, 10, 0.0733880347707},   {6.0, 63, 1.06149280553e-7},  {3.0, 2, 0.0954659662667},
        {5.5, 255, 9.22268911571e-8}, {10.0, 5, 0.000170947575743}, {0.5, 30, 0.620723004885},
        {8.0, 63, 3.56792865479e-11}, {2.5, 1000, 0.0125785678011}, {1.0, 1, 0.5},
    };
    for (size_t i = 0; i < sizeof known / sizeof known[0]; i++)
        assert_close(student_t_tail(known[i].t, known[i].dof), known[i].p, 1e-10 * known[i].p);
    assert_true(student_t_tail(INFINITY, 63) == 0.0);
    assert_close(student_t_tail(0.0, 63), 1.0, 1e-15);
}

/* Closed forms, over t from 1e-3 to 1e5 (both branches of the continued fraction):
 *     1 degree of freedom (Cauchy):  P(|T| > t) = 1 - (2 / pi) atan(t) = (2 / pi) atan(1 / t),
 *     2 degrees:                     P(|T| > t) = 1 - t / sqrt(2 + t^2). */
static void test_tail_closed_forms(void **state)
{
    for (double t = 1e-3; t <= 1e5; t *= 1.1) {
        double cauchy = 2.0 / PI * atan(1.0 / t);
        assert_close(student_t_tail(t, 1), cauchy, 1e-12 * cauchy);
        double two = 2.0 / (sqrt(2.0 + t * t) * (sqrt(2.0 + t * t) + t)); /* 1 - t / sqrt(..) */
        assert_close(student_t_tail(t, 2), two, 1e-12 * two);
    }
}

/* The critical values: a table's (10 degrees, level 0.05: 2.228139), mpmath's at the
 * course's level, and the tail at each equal to its level. */
static void test_critical_values(void **state)
{
    assert_close(student_t_critical(0.05, 10), 2.228139, 1e-6);
    assert_close(student_t_critical(COURSE_LEVEL, 63), 5.7802995, 1e-6);
    assert_close(student_t_critical(COURSE_LEVEL, 255), 5.3005974, 1e-6);
    assert_close(student_t_critical(COURSE_LEVEL, 1000000000), 5.1576920, 1e-5);
    static const int dofs[] = {1, 2, 7, 63, 178, 255, 5000};
    for (size_t i = 0; i < sizeof dofs / sizeof dofs[0]; i++) {
        double level = i % 2 ? COURSE_LEVEL : 0.02;
        assert_close(student_t_tail(student_t_critical(level, dofs[i]), dofs[i]), level,
                     1e-9 * level);
    }
}

/* The shift detected with probability 0.99 at the course's level, from mpmath's
 * quadrature of E_S[Phi(delta - t_crit S)]: 8.38006 at 63 degrees, 7.77626 at 178,
 * 7.68531 at 255; the normal's z_level + z_power = 5.15769 + 2.32635 as nu grows. */
static void test_detectable_shift(void **state)
{
    assert_close(student_t_detectable(COURSE_LEVEL, 0.99, 63), 8.38006, 2e-5);
    assert_close(student_t_detectable(COURSE_LEVEL, 0.99, 178), 7.77626, 2e-5);
    assert_close(student_t_detectable(COURSE_LEVEL, 0.99, 255), 7.68531, 2e-5);
    assert_close(student_t_detectable(COURSE_LEVEL, 0.99, 1000000), 7.48409, 2e-5);
    assert_close(student_t_power(8.38006, student_t_critical(COURSE_LEVEL, 63), 63), 0.99,
                 1e-6);
}

/* A standard normal number (Box-Muller's cosine half). */
static double normal(TestRandom *random)
{
    double u = test_uniform(random), v = test_uniform(random);
    return sqrt(-2.0 * log1p(-u)) * cos(2.0 * PI * v);
}

/* T of `replicates` normal replicate means of standard deviation 1 and mean `bias`. */
static double simulated_t(TestRandom *random, int replicates, double bias)
{
    double values[64], mean = 0.0, spread = 0.0;
    for (int r = 0; r < replicates; r++)
        mean += values[r] = bias + normal(random);
    mean /= replicates;
    for (int r = 0; r < replicates; r++)
        spread += (values[r] - mean) * (values[r] - mean);
    return mean / sqrt(spread / (replicates - 1) / replicates);
}

/* 20,000 tests of 64 replicates: without a bias, at level 0.05, about 1,000 reject
 * (binomial sd 31); with the bias the test detects at power 0.99 (level 0.001), about
 * 19,800 do (sd 14). The shifted central t's t_crit + t_power, printed beside it, is
 * smaller. */
static void test_level_and_power_on_simulated_replicates(void **state)
{
    const int tests = 20000, replicates = 64;
    double critical = student_t_critical(0.05, replicates - 1);
    double strict = student_t_critical(0.001, replicates - 1);
    double detectable = student_t_detectable(0.001, 0.99, replicates - 1);
    double se = 1.0 / sqrt(replicates);
    int rejected = 0, detected = 0;
    TestRandom random = test_random(7, 1, 0);
    for (int i = 0; i < tests; i++) {
        rejected += fabs(simulated_t(&random, replicates, 0.0)) > critical;
        detected += fabs(simulated_t(&random, replicates, detectable * se)) > strict;
    }
    print_message("level 0.05: %d of %d rejected; power 0.99: %d of %d detected (shift %.4f, "
                  "the shifted central t's %.4f)\n",
                  rejected, tests, detected, tests, detectable,
                  strict + student_t_critical(0.02, replicates - 1));
    assert_in_range(rejected, 900, 1100);
    assert_in_range(detected, 19750, 19850);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_tail_against_mpmath),
        cmocka_unit_test(test_tail_closed_forms),
        cmocka_unit_test(test_critical_values),
        cmocka_unit_test(test_detectable_shift),
        cmocka_unit_test(test_level_and_power_on_simulated_replicates),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
