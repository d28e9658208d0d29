/* test_roulette.c (chapter 6): Russian roulette with survival probability alpha (roulette.h,
 * report §2.2 and §4.7, with the erratum of roulette.h).
 *
 * A path that meets roulette survives with probability alpha and then carries X / alpha;
 * otherwise it carries 0. With B the survival indicator (a Bernoulli(alpha) variable)
 * the estimate is X' = X B / alpha, and
 *     E[X']   = E[X],                    (unbiased)
 *     E[X'^2] = E[X^2] / alpha,          (each roulette multiplies the second moment
 *                                         by 1 / alpha: with a bounce's rho^2 this is
 *                                         chapter 6's "finite only for alpha > rho^2")
 *     Var[X'] = E[X^2] / alpha - E[X]^2, which for a constant X is X^2 (1 - alpha) / alpha.
 * The tests check that alpha >= 1 is no roulette at all (the generator is not touched),
 * that alpha < 1 draws exactly one number, that alpha = 0 always ends the path, and then
 * the three formulas above by simulation with a fixed seed. Every statistical check
 * allows 5 standard errors: a correct implementation fails one with probability about
 * 6e-7 (two-sided normal tail), and the seed is fixed, so a run is reproducible.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>

#include "roulette.h"

#define DRAWS 1000000
#define SIGMAS 5.0

static const double ALPHAS[] = {0.01, 0.25, 0.5, 0.9};
enum {
    ALPHA_COUNT = sizeof ALPHAS / sizeof ALPHAS[0]
};

static int same_state(Rng a, Rng b) { return a.state == b.state && a.increment == b.increment; }

/* alpha >= 1 (including absurdly large and infinite alpha) always survives and draws no
 * random number: the generator's state is unchanged, so switching roulette off leaves
 * the rest of a path's random numbers, and so the image, exactly as without roulette. */
static void test_alpha_at_least_one_always_survives_without_drawing(void **state)
{
    const double alphas[] = {1.0, 1.5, 1e300, INFINITY};
    for (int k = 0; k < 4; k++) {
        Rng rng = rng_for_sample(1, 0, (uint64_t)k), before = rng;
        for (int i = 0; i < 1000; i++)
            assert_true(roulette_survives(alphas[k], &rng));
        assert_true(same_state(rng, before));
    }
}

/* alpha < 1 draws exactly one uniform number u and survives iff u < alpha: after the
 * call the generator is where one rng_uniform takes it, and the decision agrees. */
static void test_alpha_below_one_draws_exactly_one_number(void **state)
{
    const double alphas[] = {0.0, 0.3, 0.999};
    for (int k = 0; k < 3; k++) {
        Rng rng = rng_for_sample(2, 0, (uint64_t)k);
        for (int i = 0; i < 1000; i++) {
            Rng copy = rng;
            double u = rng_uniform(&copy);
            assert_int_equal(roulette_survives(alphas[k], &rng) != 0, u < alphas[k]);
            assert_true(same_state(rng, copy));
        }
    }
}

/* alpha = 0 (the limit "near 0") ends every path: u >= 0 is never < 0. */
static void test_alpha_zero_never_survives(void **state)
{
    Rng rng = rng_for_sample(3, 0, 0);
    for (int i = 0; i < DRAWS / 10; i++)
        assert_false(roulette_survives(0.0, &rng));
}

/* The survival frequency over DRAWS calls is alpha: the count of survivors is
 * binomial(DRAWS, alpha), so the frequency is within SIGMAS binomial standard errors
 * sqrt(alpha (1 - alpha) / DRAWS) of alpha. Alpha is the probability of SURVIVAL, not
 * of termination (the erratum): alpha = 0.01 keeps 1% of the paths. */
static void test_survival_frequency_is_alpha(void **state)
{
    for (int k = 0; k < ALPHA_COUNT; k++) {
        double alpha = ALPHAS[k];
        Rng rng = rng_for_sample(4, 0, (uint64_t)k);
        long survivors = 0;
        for (int i = 0; i < DRAWS; i++)
            survivors += roulette_survives(alpha, &rng);
        double frequency = (double)survivors / DRAWS;
        double std_error = sqrt(alpha * (1.0 - alpha) / DRAWS);
        print_message("    alpha %.2f: survived %.6f (%+.2f standard errors)\n", alpha,
                      frequency, (frequency - alpha) / std_error);
        assert_true(fabs(frequency - alpha) <= SIGMAS * std_error);
    }
}

/* X' = X / alpha on survival, 0 otherwise, for a constant X = 3. Its mean is X
 * (unbiased) and its variance X^2 (1 - alpha) / alpha: the price of the shorter paths.
 * Both are checked against the simulated values. The simulated (population) variance
 * is exactly c^2 p (1 - p), c = X / alpha, p the survival frequency; with
 * p = alpha + delta it differs from the truth by c^2 (delta (1 - 2 alpha) - delta^2),
 * so |delta| <= SIGMAS binomial standard errors bounds it; that is the tolerance. */
static void test_constant_estimate_mean_and_variance(void **state)
{
    const double x = 3.0;
    for (int k = 0; k < ALPHA_COUNT; k++) {
        double alpha = ALPHAS[k];
        Rng rng = rng_for_sample(5, 0, (uint64_t)k);
        double sum = 0.0, sum_squares = 0.0;
        for (int i = 0; i < DRAWS; i++) {
            double estimate = roulette_survives(alpha, &rng) ? x / alpha : 0.0;
            sum += estimate;
            sum_squares += estimate * estimate;
        }
        double mean = sum / DRAWS, variance = sum_squares / DRAWS - mean * mean;
        double expected_variance = x * x * (1.0 - alpha) / alpha;
        double c = x / alpha, delta = SIGMAS * sqrt(alpha * (1.0 - alpha) / DRAWS);
        double variance_tolerance = c * c * (delta * fabs(1.0 - 2.0 * alpha) + delta * delta);
        print_message("    alpha %.2f: mean %.5f (expected %.1f), variance %.4f"
                      " (expected %.4f)\n",
                      alpha, mean, x, variance, expected_variance);
        assert_true(fabs(mean - x) <= SIGMAS * sqrt(expected_variance / DRAWS));
        assert_true(fabs(variance - expected_variance) <=
                    variance_tolerance + 1e-9 * expected_variance);
    }
}

/* The same for a random X, uniform on [0, 2) and independent of the roulette (a path's
 * value is random too): E[X] = 1, E[X^k] = 2^k / (k + 1), so X' has raw moments
 * m_k = E[X^k] / alpha^(k-1) and Var[X'] = m_2 - 1 = 4 / (3 alpha) - 1. The mean is
 * checked within SIGMAS standard errors sqrt(Var / N), the variance within SIGMAS
 * standard errors of a sample variance, sqrt((mu_4 - Var^2) / N), with mu_4 the fourth
 * central moment from m_1..m_4. */
static void test_random_estimate_mean_and_variance(void **state)
{
    for (int k = 0; k < ALPHA_COUNT; k++) {
        double alpha = ALPHAS[k];
        Rng value_rng = rng_for_sample(6, 0, (uint64_t)k);
        Rng roulette_rng = rng_for_sample(6, 1, (uint64_t)k);
        double sum = 0.0, sum_squares = 0.0;
        for (int i = 0; i < DRAWS; i++) {
            double x = 2.0 * rng_uniform(&value_rng);
            double estimate = roulette_survives(alpha, &roulette_rng) ? x / alpha : 0.0;
            sum += estimate;
            sum_squares += estimate * estimate;
        }
        double mean = sum / DRAWS, variance = sum_squares / DRAWS - mean * mean;
        double m2 = 4.0 / 3.0 / alpha, m3 = 2.0 / pow(alpha, 2), m4 = 3.2 / pow(alpha, 3);
        double expected_variance = m2 - 1.0;
        double mu4 = m4 - 4.0 * m3 + 6.0 * m2 - 3.0;
        double variance_error = sqrt((mu4 - expected_variance * expected_variance) / DRAWS);
        print_message("    alpha %.2f: mean %.5f (expected 1), variance %.4f"
                      " (expected %.4f +- %.4f)\n",
                      alpha, mean, variance, expected_variance, variance_error);
        assert_true(fabs(mean - 1.0) <= SIGMAS * sqrt(expected_variance / DRAWS));
        assert_true(fabs(variance - expected_variance) <= SIGMAS * variance_error);
    }
}

/* Bounded weights: the survival probability is the throughput's largest channel, capped
 * at 1, so a survivor's weight T / q never exceeds 1 in that channel. */
static void test_survival_from_throughput_bounds_the_weight(void **state)
{
    assert_true(roulette_survival_from_throughput(vec3(0.2, 0.6, 0.1)) == 0.6);
    assert_true(roulette_survival_from_throughput(vec3(0.05, 0.01, 0.02)) == 0.05);
    assert_true(roulette_survival_from_throughput(vec3(0.3, 2.5, 1.0)) == 1.0);
    assert_true(roulette_survival_from_throughput(vec3(0, 0, 0)) == 0.0);
    const Vec3 throughputs[] = {{0.75, 0.15, 0.15}, {1e-3, 2e-3, 5e-4}, {0.9, 0.9, 0.9}};
    for (int k = 0; k < 3; k++) {
        double q = roulette_survival_from_throughput(throughputs[k]);
        assert_true(fabs(vec3_max_component(vec3_scale(throughputs[k], 1.0 / q)) - 1.0) <
                    1e-15);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_alpha_at_least_one_always_survives_without_drawing),
        cmocka_unit_test(test_alpha_below_one_draws_exactly_one_number),
        cmocka_unit_test(test_alpha_zero_never_survives),
        cmocka_unit_test(test_survival_frequency_is_alpha),
        cmocka_unit_test(test_constant_estimate_mean_and_variance),
        cmocka_unit_test(test_random_estimate_mean_and_variance),
        cmocka_unit_test(test_survival_from_throughput_bounds_the_weight),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
