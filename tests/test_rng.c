/* test_rng.c (chapter 2): PCG32 seeded by (seed, pixel, sample) (rng.h).
 *
 * Every Monte Carlo estimate rests on these numbers, so besides determinism we test
 * the distribution itself: moments and a chi-square goodness-of-fit test, both for
 * one long stream and for the first draw of many neighbouring (pixel, sample)
 * streams, the way the renderer uses them. Fixed seeds throughout.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>

#include "chi_square.h"
#include "rng.h"

#define DRAWS 1000000
#define BINS 100
/* The chi-square tests reject the generator when p < 0.001: a uniform generator fails
 * them once in a thousand seeds, which the fixed seeds make either always or never. */
#define SIGNIFICANCE 0.001

/* A generator state whose next output is `bits`: PCG32 outputs bits 27..58 of
 * state ^ (state >> 18), rotated by the top 5 bits; with those 5 bits zero there is
 * no rotation, and each output bit fixes one state bit from the top down. */
static Rng rng_about_to_output(uint32_t bits)
{
    uint64_t state = 0;
    for (int i = 58; i >= 27; i--) {
        uint64_t above = i + 18 < 64 ? (state >> (i + 18)) & 1u : 0u;
        state |= ((((uint64_t)bits >> (i - 27)) & 1u) ^ above) << i;
    }
    Rng rng = {.state = state, .increment = 1};
    return rng;
}

/* The extreme outputs map to the ends of [0, 1): all zero bits give exactly 0 and all
 * one bits give 1 - 2^-32, never 1. */
static void test_uniform_extremes(void **state)
{
    Rng ones = rng_about_to_output(0xffffffffu), ones_copy = ones;
    assert_int_equal(rng_next(&ones_copy), 0xffffffffu);
    double top = rng_uniform(&ones);
    assert_true(top < 1.0);
    assert_true(top == 1.0 - 0x1p-32);
    Rng zeros = rng_about_to_output(0u);
    assert_true(rng_uniform(&zeros) == 0.0);
}

/* A million draws of one stream all lie in [0, 1). */
static void test_uniform_in_unit_interval(void **state)
{
    Rng rng = rng_for_sample(3, 14, 15);
    for (int i = 0; i < DRAWS; i++) {
        double x = rng_uniform(&rng);
        assert_true(x >= 0.0 && x < 1.0);
    }
}

/* The same (seed, pixel, sample) always gives the same stream, whatever was drawn
 * from other generators in between: an image does not depend on thread scheduling. */
static void test_deterministic(void **state)
{
    Rng a = rng_for_sample(42, 1234, 7);
    Rng other = rng_for_sample(42, 1235, 7);
    uint32_t first[1000];
    for (int i = 0; i < 1000; i++) {
        first[i] = rng_next(&a);
        rng_next(&other);
    }
    Rng b = rng_for_sample(42, 1234, 7);
    for (int i = 0; i < 1000; i++)
        assert_int_equal(rng_next(&b), first[i]);
}

/* Neighbouring pixels, samples and seeds give different streams: their first four
 * outputs never all agree. */
static void test_neighbours_differ(void **state)
{
    for (uint64_t k = 0; k < 1000; k++) {
        Rng base = rng_for_sample(k, k, k);
        Rng neighbours[3] = {rng_for_sample(k + 1, k, k), rng_for_sample(k, k + 1, k),
                             rng_for_sample(k, k, k + 1)};
        uint32_t mine[4];
        for (int i = 0; i < 4; i++)
            mine[i] = rng_next(&base);
        for (int n = 0; n < 3; n++) {
            int same = 0;
            for (int i = 0; i < 4; i++)
                same += rng_next(&neighbours[n]) == mine[i];
            assert_true(same < 4);
        }
    }
}

/* The first draws of pixel i and pixel i + 1 are uncorrelated: over 10^5 pixel pairs
 * the sample correlation is within 5 standard errors (1 / sqrt(N)) of 0. */
static void test_neighbouring_pixels_uncorrelated(void **state)
{
    const int pairs = 100000;
    double sum_xy = 0, sum_x = 0, sum_y = 0, sum_xx = 0, sum_yy = 0;
    for (int i = 0; i < pairs; i++) {
        Rng a = rng_for_sample(5, (uint64_t)i, 0), b = rng_for_sample(5, (uint64_t)i + 1, 0);
        double x = rng_uniform(&a), y = rng_uniform(&b);
        sum_x += x;
        sum_y += y;
        sum_xy += x * y;
        sum_xx += x * x;
        sum_yy += y * y;
    }
    double cov = sum_xy / pairs - (sum_x / pairs) * (sum_y / pairs);
    double var_x = sum_xx / pairs - (sum_x / pairs) * (sum_x / pairs);
    double var_y = sum_yy / pairs - (sum_y / pairs) * (sum_y / pairs);
    double correlation = cov / sqrt(var_x * var_y);
    print_message("correlation of neighbouring pixels' first draws: %.5f\n", correlation);
    assert_true(fabs(correlation) < 5.0 / sqrt(pairs));
}

/* Mean and variance of 10^6 draws are within 5 standard errors of 1/2 and 1/12.
 * The standard error of the mean is sqrt(1/12 / N); that of the variance estimate is
 * sqrt(Var[(U - 1/2)^2] / N) with Var[(U - 1/2)^2] = 1/80 - 1/144 = 1/180. */
static void test_mean_and_variance(void **state)
{
    Rng rng = rng_for_sample(2019, 0, 0);
    double sum = 0, sum_sq = 0;
    for (int i = 0; i < DRAWS; i++) {
        double x = rng_uniform(&rng);
        sum += x;
        sum_sq += (x - 0.5) * (x - 0.5);
    }
    double mean = sum / DRAWS, variance = sum_sq / DRAWS;
    print_message("mean %.6f (z = %.2f), variance %.6f (z = %.2f)\n", mean,
                  (mean - 0.5) / sqrt(1.0 / 12.0 / DRAWS), variance,
                  (variance - 1.0 / 12.0) / sqrt(1.0 / 180.0 / DRAWS));
    assert_true(fabs(mean - 0.5) < 5.0 * sqrt(1.0 / 12.0 / DRAWS));
    assert_true(fabs(variance - 1.0 / 12.0) < 5.0 * sqrt(1.0 / 180.0 / DRAWS));
}

/* The p-value of Pearson's test of 10^6 draws counted in 100 equal bins (expected
 * 10^4 each; 99 degrees of freedom), using the chi-square concept of chapter 2. */
static double uniformity_p_value(const double counts[BINS], const char *what)
{
    double expected[BINS];
    for (int i = 0; i < BINS; i++)
        expected[i] = (double)DRAWS / BINS;
    int dof;
    double chi2 = chi_square_statistic(counts, expected, BINS, &dof);
    double p = chi_square_p_value(chi2, dof);
    print_message("chi-square, %s: %.1f with %d dof, p = %.3f\n", what, chi2, dof, p);
    assert_int_equal(dof, BINS - 1);
    return p;
}

/* Chi-square goodness of fit of one long stream to the uniform distribution, at
 * significance 0.001. */
static void test_chi_square_one_stream(void **state)
{
    double counts[BINS] = {0};
    Rng rng = rng_for_sample(7, 77, 777);
    for (int i = 0; i < DRAWS; i++)
        counts[(int)(rng_uniform(&rng) * BINS)]++;
    assert_true(uniformity_p_value(counts, "one stream") > SIGNIFICANCE);
}

/* The same test on the first draw of 10^6 different (pixel, sample) generators: the
 * seeding hash spreads neighbouring indices uniformly. Significance 0.001. */
static void test_chi_square_across_streams(void **state)
{
    double counts[BINS] = {0};
    for (int i = 0; i < DRAWS; i++) {
        Rng rng = rng_for_sample(1, (uint64_t)(i / 16), (uint64_t)(i % 16));
        counts[(int)(rng_uniform(&rng) * BINS)]++;
    }
    assert_true(uniformity_p_value(counts, "first draws") > SIGNIFICANCE);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_uniform_extremes),
        cmocka_unit_test(test_uniform_in_unit_interval),
        cmocka_unit_test(test_deterministic),
        cmocka_unit_test(test_neighbours_differ),
        cmocka_unit_test(test_neighbouring_pixels_uncorrelated),
        cmocka_unit_test(test_mean_and_variance),
        cmocka_unit_test(test_chi_square_one_stream),
        cmocka_unit_test(test_chi_square_across_streams),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
