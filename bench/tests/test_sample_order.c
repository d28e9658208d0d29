/* test_sample_order.c (bench, chapter 2): the order in which the renderer takes a pixel's
 * sub-pixel samples (sample_order.h), so that a render stopped early is unbiased.
 *
 * The passes take every sample once, for every sample count up to 64 from every first
 * sample, and for 1000 and 2^20 from three; the first sample is uniform (chi-square);
 * placements other than sub-pixels take sample j at pass j. And what it is for: the
 * samples the first k passes take, placed by the lesson (pixel_position), are uniform
 * over the pixel for every sample count n and every k (chi-square).
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <string.h>

#include "chi_square.h"
#include "sample_order.h"

static SampleOrder order_of(int samples, PixelSampling sampling, uint64_t seed)
{
    ImageSettings image = {
        .width = 1, .height = 1, .spp = samples, .sampling = sampling, .seed = seed};
    return sample_order_make(&image);
}

/* The n passes of a pixel take each of its n samples once. Pixels are chosen so that
 * their first samples cover every value of [0, n) for n up to 64 (checked), and three
 * pixels for n = 1000 and 2^20. */
static void assert_every_sample_once(const SampleOrder *order, uint64_t pixel)
{
    static unsigned char seen[1 << 20];
    int n = (int)order->samples;
    memset(seen, 0, (size_t)n);
    for (int pass = 0; pass < n; pass++) {
        int sample = sample_order_sample(order, pixel, pass);
        assert_true(sample >= 0 && sample < n);
        assert_false(seen[sample]);
        seen[sample] = 1;
    }
}

static void test_every_sample_once(void **state)
{
    for (int n = 1; n <= 64; n++) {
        SampleOrder order = order_of(n, PIXEL_SUBPIXELS, 9);
        unsigned char first_seen[64] = {0};
        int firsts = 0;
        for (uint64_t pixel = 0; firsts < n; pixel++) {
            assert_true(pixel < 100000);
            int first = sample_order_first(&order, pixel);
            if (first_seen[first])
                continue;
            first_seen[first] = 1;
            firsts++;
            assert_every_sample_once(&order, pixel);
        }
    }
    const int large[] = {1000, 1 << 20};
    for (int k = 0; k < 2; k++) {
        SampleOrder order = order_of(large[k], PIXEL_SUBPIXELS, 9);
        for (uint64_t pixel = 0; pixel < 3; pixel++)
            assert_every_sample_once(&order, pixel);
    }
}

/* The first sample is uniform over [0, n): chi-square over the n values, 1% level,
 * 70,000 pixels each for n = 7 and 30. One sample needs no start. Chapter 1's centres
 * and random positions take sample j at pass j. */
static void test_first_sample_uniform(void **state)
{
    const int ns[] = {7, 30};
    for (int k = 0; k < 2; k++) {
        double observed[30] = {0}, expected[30];
        const int pixels = 70000;
        SampleOrder order = order_of(ns[k], PIXEL_SUBPIXELS, 11);
        for (int p = 0; p < pixels; p++) {
            int s = sample_order_first(&order, (uint64_t)p);
            assert_true(s >= 0 && s < ns[k]);
            observed[s] += 1;
        }
        for (int j = 0; j < ns[k]; j++)
            expected[j] = (double)pixels / ns[k];
        int dof;
        double x2 = chi_square_statistic(observed, expected, ns[k], &dof);
        print_message("    n = %d: X^2 = %.1f, %d dof, p = %.3f\n", ns[k], x2, dof,
                      chi_square_p_value(x2, dof));
        assert_true(chi_square_p_value(x2, dof) > 0.01);
    }
    SampleOrder one = order_of(1, PIXEL_SUBPIXELS, 11);
    assert_int_equal(sample_order_first(&one, 5), 0);
    assert_int_equal(sample_order_sample(&one, 5, 0), 0);
    const PixelSampling in_order[] = {PIXEL_CENTRE, PIXEL_RANDOM};
    for (int k = 0; k < 2; k++) {
        SampleOrder order = order_of(16, in_order[k], 11);
        for (int pass = 0; pass < 16; pass++)
            assert_int_equal(sample_order_sample(&order, 3, pass), pass);
    }
}

/* The samples of the first k passes are uniform over the pixel, for every sample count
 * and every k: an unbiased estimate of the pixel's integral however many passes a render
 * took before it stopped. For n = 1, 2, 3, 4, 5, 7, 16, 30 and each k = 1 ... n, the
 * first k passes of each of PIXELS pixels (each with its own start and jitter, as the
 * renderer and render.c draw them) are counted in a 6 x 6 grid over the pixel and
 * compared with the uniform density by Pearson's chi-square. 68 tests, each at level
 * 0.01 / 68 (Bonferroni: 1% for the family); fixed seeds. Planted bugs, each rejected
 * at the first pass with p = 0: every pixel from sample 0 (no random start), so that a
 * stopped render samples only the top of each pixel; and a start that is the same for
 * every pixel. */
#define PIXELS 2000
#define GRID 6

static double prefix_p_value(int n, int k)
{
    double observed[GRID * GRID] = {0}, expected[GRID * GRID];
    ImageSettings image = {
        .width = PIXELS, .height = 1, .spp = n, .sampling = PIXEL_SUBPIXELS, .seed = 2024};
    SampleOrder order = sample_order_make(&image);
    for (int p = 0; p < PIXELS; p++)
        for (int pass = 0; pass < k; pass++) {
            int sample = sample_order_sample(&order, (uint64_t)p, pass);
            Rng rng = rng_for_sample(2024, (uint64_t)p, (uint64_t)sample);
            double u, v;
            pixel_position(PIXEL_SUBPIXELS, sample, n, &rng, &u, &v);
            observed[(int)(v * GRID) * GRID + (int)(u * GRID)] += 1;
        }
    for (int b = 0; b < GRID * GRID; b++)
        expected[b] = (double)PIXELS * k / (GRID * GRID);
    int dof;
    double x2 = chi_square_statistic(observed, expected, GRID * GRID, &dof);
    return chi_square_p_value(x2, dof);
}

static void test_every_prefix_uniform(void **state)
{
    const int ns[] = {1, 2, 3, 4, 5, 7, 16, 30};
    const int tests = 1 + 2 + 3 + 4 + 5 + 7 + 16 + 30;
    double smallest = 1.0;
    for (int j = 0; j < 8; j++)
        for (int k = 1; k <= ns[j]; k++) {
            double p = prefix_p_value(ns[j], k);
            if (p < 0.01 / tests)
                fail_msg("n = %d, first %d passes: p = %.3g", ns[j], k, p);
            smallest = fmin(smallest, p);
        }
    print_message("    %d prefixes, smallest p = %.4f\n", tests, smallest);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_every_sample_once),
        cmocka_unit_test(test_first_sample_uniform),
        cmocka_unit_test(test_every_prefix_uniform),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
