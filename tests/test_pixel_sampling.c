/* test_pixel_sampling.c (chapter 2): where in a pixel the samples go (pixel_sampling.h;
 * report §3.3.1).
 *
 * Sub-pixels: the layout tiles the pixel with n cells of equal area for any n, sample s
 * lies jittered in cell s, and the n samples of a pixel together are uniform over it for
 * every sample count (chi-square). Random positions stay inside the pixel and average to
 * its centre. (That every first k samples the renderer takes are uniform too, so that a
 * stopped render is unbiased, is the bench's: bench/tests/test_sample_order.c.)
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include "check.h"
#include "chi_square.h"
#include "pixel_sampling.h"

/* The sub-pixel layout of pixel_sampling.h for n cells: every cell has area 1/n, lies inside
 * the pixel, and no two overlap, so together they tile it; cells are nearly square
 * (sides within a factor 3 of each other: n = 3 is the worst). n = 16 is the 4 x 4 grid
 * numbered row by row; n = 5 a row of two above a row of three; n = 3 one cell above two. */
static void test_strata_tile_the_pixel(void **state)
{
    for (int n = 1; n <= 64; n++) {
        double u0[64], v0[64], w[64], h[64], area = 0.0;
        for (int m = 0; m < n; m++) {
            pixel_stratum_bounds(m, n, &u0[m], &v0[m], &w[m], &h[m]);
            assert_close(w[m] * h[m], 1.0 / n, 1e-15);
            assert_true(u0[m] >= 0 && v0[m] >= 0);
            assert_true(u0[m] + w[m] <= 1 + 1e-15 && v0[m] + h[m] <= 1 + 1e-15);
            assert_true(w[m] <= 3 * h[m] * (1 + 1e-12) && h[m] <= 3 * w[m] * (1 + 1e-12));
            for (int j = 0; j < m; j++) {
                double overlap_u = fmin(u0[m] + w[m], u0[j] + w[j]) - fmax(u0[m], u0[j]);
                double overlap_v = fmin(v0[m] + h[m], v0[j] + h[j]) - fmax(v0[m], v0[j]);
                assert_false(overlap_u > 1e-12 && overlap_v > 1e-12);
            }
            area += w[m] * h[m];
        }
        assert_close(area, 1.0, 1e-13);
    }
    for (int m = 0; m < 16; m++) {
        double u0, v0, w, h;
        pixel_stratum_bounds(m, 16, &u0, &v0, &w, &h);
        assert_true(u0 == (m % 4) / 4.0 && v0 == (m / 4) / 4.0 && w == 0.25 && h == 0.25);
    }
    const double u5[] = {0, 0.5, 0, 1 / 3.0, 2 / 3.0}, v5[] = {0, 0, 0.4, 0.4, 0.4};
    for (int m = 0; m < 5; m++) {
        double u0, v0, w, h;
        pixel_stratum_bounds(m, 5, &u0, &v0, &w, &h);
        assert_close(u0, u5[m], 1e-15);
        assert_close(v0, v5[m], 1e-15);
    }
    double u0, v0, w, h;
    pixel_stratum_bounds(0, 3, &u0, &v0, &w, &h);
    assert_true(u0 == 0 && v0 == 0 && w == 1);
    assert_close(h, 1 / 3.0, 1e-15);
}

/* Sub-pixel sample s lies in cell s and strictly inside the pixel; the jitter moves it:
 * over 1000 generators its positions are not all one, and none is the cell's centre (the
 * planted bug of the uniformity test). At
 * one sample per pixel, sub-pixels and random positions are the same positions, so
 * Figure 8's 1-spp panel and a random 1-spp panel are the same image. */
static void test_subpixel_sample_in_its_cell(void **state)
{
    const int ns[] = {1, 2, 3, 5, 16, 30};
    for (int k = 0; k < 6; k++) {
        int n = ns[k];
        for (int i = 0; i < n; i++) {
            double first_u = -1;
            int all_same = 1;
            for (int g = 0; g < 1000; g++) {
                Rng rng = rng_for_sample(3, (uint64_t)g, (uint64_t)i);
                double u, v, u0, v0, w, h;
                pixel_position(PIXEL_SUBPIXELS, i, n, &rng, &u, &v);
                pixel_stratum_bounds(i, n, &u0, &v0, &w, &h);
                assert_true(u >= u0 && u < u0 + w + 1e-15 && v >= v0 && v < v0 + h + 1e-15);
                assert_true(u >= 0 && u < 1 && v >= 0 && v < 1);
                assert_false(u == u0 + w / 2 && v == v0 + h / 2);
                if (g == 0)
                    first_u = u;
                all_same &= u == first_u;
            }
            assert_false(all_same);
        }
    }
    /* One sample: one cell, the whole pixel, so sub-pixels are random positions, drawn
     * the same way: the same (u, v) from the same generator. */
    for (int g = 0; g < 100; g++) {
        Rng a = rng_for_sample(8, (uint64_t)g, 0), b = a;
        double ua, va, ub, vb;
        pixel_position(PIXEL_SUBPIXELS, 0, 1, &a, &ua, &va);
        pixel_position(PIXEL_RANDOM, 0, 1, &b, &ub, &vb);
        assert_true(ua == ub && va == vb);
    }
    /* Jitter up to the last representable value stays below 1 in the last cell. */
    double u, v;
    Rng rng = rng_for_sample(0, 0, 0);
    for (int n = 1; n <= 40; n++)
        for (int i = 0; i < n; i++) {
            pixel_position(PIXEL_SUBPIXELS, i, n, &rng, &u, &v);
            assert_true(u < 1 && v < 1);
        }
}

/* The n samples of a pixel together are uniform over it, for every sample count: for
 * n = 1, 2, 3, 4, 5, 7, 16 and 30, samples 0 .. n - 1 of each of PIXELS pixels (each
 * sample with its own generator, as render.c draws them) are counted in a 6 x 6 grid
 * over the pixel and compared with the uniform density by Pearson's chi-square, each at
 * level 0.01 / 8 (Bonferroni: 1% for the family); fixed seeds. Samples at their cells'
 * centres without jitter (the planted bug) are rejected with p = 0. */
#define PIXELS 2000
#define GRID 6

static double full_set_p_value(int n)
{
    double observed[GRID * GRID] = {0}, expected[GRID * GRID];
    for (int p = 0; p < PIXELS; p++)
        for (int i = 0; i < n; i++) {
            Rng rng = rng_for_sample(2024, (uint64_t)p, (uint64_t)i);
            double u, v;
            pixel_position(PIXEL_SUBPIXELS, i, n, &rng, &u, &v);
            observed[(int)(v * GRID) * GRID + (int)(u * GRID)] += 1;
        }
    for (int b = 0; b < GRID * GRID; b++)
        expected[b] = (double)PIXELS * n / (GRID * GRID);
    int dof;
    double x2 = chi_square_statistic(observed, expected, GRID * GRID, &dof);
    return chi_square_p_value(x2, dof);
}

static void test_subpixels_together_uniform(void **state)
{
    const int ns[] = {1, 2, 3, 4, 5, 7, 16, 30};
    double smallest = 1.0;
    for (int j = 0; j < 8; j++) {
        double p = full_set_p_value(ns[j]);
        if (p < 0.01 / 8)
            fail_msg("n = %d: p = %.3g", ns[j], p);
        smallest = fmin(smallest, p);
    }
    print_message("    8 sample counts, smallest p = %.4f\n", smallest);
}

/* PIXEL_CENTRE is always (1/2, 1/2); PIXEL_RANDOM stays in [0,1)^2, varies, and
 * averages to the centre (10^5 draws, within 5 standard errors sqrt(1/12/N)). */
static void test_centre_and_random(void **state)
{
    double u, v, sum_u = 0, sum_v = 0;
    pixel_position(PIXEL_CENTRE, 3, 16, NULL, &u, &v);
    assert_true(u == 0.5 && v == 0.5);
    Rng rng = rng_for_sample(2, 3, 4);
    const int n = 100000;
    double first_u;
    pixel_position(PIXEL_RANDOM, 0, n, &rng, &first_u, &v);
    int all_same = 1;
    for (int i = 0; i < n; i++) {
        pixel_position(PIXEL_RANDOM, i, n, &rng, &u, &v);
        assert_true(u >= 0 && u < 1 && v >= 0 && v < 1);
        all_same &= u == first_u;
        sum_u += u;
        sum_v += v;
    }
    assert_false(all_same);
    assert_true(fabs(sum_u / n - 0.5) < 5 * sqrt(1.0 / 12 / n));
    assert_true(fabs(sum_v / n - 0.5) < 5 * sqrt(1.0 / 12 / n));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_strata_tile_the_pixel),
        cmocka_unit_test(test_subpixel_sample_in_its_cell),
        cmocka_unit_test(test_subpixels_together_uniform),
        cmocka_unit_test(test_centre_and_random),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
