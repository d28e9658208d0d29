/* test_bias_variance.c (bench, chapter 8): a setting's error split into bias and variance
 * (bias_variance.h).
 *
 * Synthetic images of known bias and variance: a random truth T per value; K = 4 images
 * T + b + N(0, s^2) and two references T + N(0, r^2). The estimates must find s^2 and b^2
 * within 5 of their standard errors (about 6e-7 of 1: fixed seeds), though the
 * references' noise is as large as the images'. Pixels marked as left out change
 * nothing, however wrong they are. The bright mask and the table by hand.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "assert_close.h"
#include "bias_variance.h"
#include "rng.h"

enum {
    SIDE = 128,
    K = 4
};
#define BIAS 0.05
#define NOISE 0.1     /* s: each image's */
#define REF_NOISE 0.1 /* r: each reference's */

/* A normal number by Box-Muller. */
static double normal(Rng *rng)
{
    double u = 1.0 - rng_uniform(rng), v = rng_uniform(rng);
    return sqrt(-2.0 * log(u)) * cos(2.0 * PI * v);
}

static Image noisy(const Image *truth, double bias, double sigma, uint64_t seed)
{
    Image image = image_new(truth->width, truth->height);
    assert_non_null(image.pixels);
    Rng rng = rng_for_sample(seed, 0, 0);
    for (long i = 0; i < 3L * truth->width * truth->height; i++)
        image.pixels[i] = (float)(truth->pixels[i] + bias + sigma * normal(&rng));
    return image;
}

/* The estimates from K images and two references; pixels marked in left_out get a bias
 * of 100 in every image. */
static BiasVariance estimate(const unsigned char *left_out)
{
    Image truth = image_new(SIDE, SIDE);
    assert_non_null(truth.pixels);
    Rng rng = rng_for_sample(1, 2, 3);
    for (long i = 0; i < 3L * SIDE * SIDE; i++)
        truth.pixels[i] = (float)(1.0 + rng_uniform(&rng));
    Image references[2] = {noisy(&truth, 0.0, REF_NOISE, 100),
                           noisy(&truth, 0.0, REF_NOISE, 101)};
    SeedImages seeds;
    assert_int_equal(seed_images_begin(&seeds, SIDE, SIDE, left_out), 0);
    for (int k = 0; k < K; k++) {
        Image image = noisy(&truth, BIAS, NOISE, 200 + (uint64_t)k);
        for (long p = 0; left_out && p < SIDE * SIDE; p++)
            for (int c = 0; c < 3; c++)
                image.pixels[3 * p + c] += left_out[p] ? 100.0f : 0.0f;
        seed_images_add(&seeds, &image, 1.0 + k, 2.0, &references[0]);
        image_free(&image);
    }
    BiasVariance result;
    seed_images_finish(&seeds, &references[0], &references[1], &result);
    image_free(&references[0]);
    image_free(&references[1]);
    image_free(&truth);
    return result;
}

/* Standard errors over N values: of the variance estimate, s^2 sqrt(2 / (K - 1) / N); of
 * the mean product, sqrt(Var / N) with, for A = b + N(0, s^2 / K) and the references'
 * noise of variance r^2 (docs/chapter8.md),
 *     Var[(A - n_1)(A - n_2)] = 4 b^2 a + 2 a^2 + 2 r^2 (b^2 + a) + r^4,  a = s^2 / K. */
static void assert_found(BiasVariance e, double values)
{
    double s2 = NOISE * NOISE, r2 = REF_NOISE * REF_NOISE, b2 = BIAS * BIAS, a = s2 / K;
    double variance_se = s2 * sqrt(2.0 / (K - 1) / values);
    double product_se = sqrt((4 * b2 * a + 2 * a * a + 2 * r2 * (b2 + a) + r2 * r2) / values);
    print_message("    variance %.6f (true %.6f +- %.6f), bias^2 %.6f (true %.6f +- %.6f)\n",
                  e.variance, s2, variance_se, e.bias2, b2, product_se);
    assert_close(e.variance, s2, 5 * variance_se);
    assert_close(e.bias2, b2, 5 * (product_se + variance_se / K));
    assert_close(e.error, sqrt(e.bias2 + e.variance), 1e-15);
}

static void test_finds_known_bias_and_variance(void **state)
{
    BiasVariance e = estimate(NULL);
    assert_found(e, 3.0 * SIDE * SIDE);
    assert_close(e.seconds, 2.5, 1e-15); /* 1, 2, 3 and 4 */
    assert_close(e.cpu, 2.0, 1e-15);
    assert_true(e.rmse_low <= e.rmse && e.rmse <= e.rmse_high);
    /* Each image against the first reference: sqrt(b^2 + s^2 + r^2) = 0.15 */
    assert_close(e.rmse, 0.15, 0.002);
}

/* The left half of the rows, every other pixel, left out: biased by 100, they change
 * nothing of bias^2 and the variance (the RMSE is of the whole image). */
static void test_left_out_pixels_change_nothing(void **state)
{
    static unsigned char left_out[SIDE * SIDE];
    for (int p = 0; p < SIDE * SIDE; p++)
        left_out[p] = (unsigned char)(p % 2 == 0 && p % SIDE < SIDE / 2);
    BiasVariance e = estimate(left_out);
    assert_found(e, 3.0 * SIDE * SIDE * 3 / 4);
    assert_true(e.rmse > 10.0);
}

/* Bright pixels (a channel above 1) and their eight neighbours, on a 5 x 4 image with one
 * in the corner (0, 0) and one at (3, 2): 4 + 9 - 0 marked (the squares do not meet). A
 * value of exactly 1 is not bright. */
static void test_bright_mask_by_hand(void **state)
{
    Image image = image_new(5, 4);
    assert_non_null(image.pixels);
    image_set(&image, 0, 0, vec3(0, 1.5, 0));
    image_set(&image, 3, 2, vec3(2, 2, 2));
    image_set(&image, 0, 3, vec3(1, 1, 1));
    int marked;
    unsigned char *mask = bias_variance_bright_mask(&image, 1.0, &marked);
    assert_non_null(mask);
    const char *expected = "11000"
                           "11111"
                           "00111"
                           "00111";
    for (int p = 0; p < 20; p++)
        if (mask[p] != expected[p] - '0')
            fail_msg("pixel (%d, %d): %d", p % 5, p / 5, mask[p]);
    assert_int_equal(marked, 13);
    free(mask);
    image_free(&image);
}

/* The table's shares by hand: bias^2 3 and variance 1 are 75% and 25%; a negative bias^2
 * (noise) counts as 0. */
static void test_table_by_hand(void **state)
{
    SettingError rows[2] = {
        {"photon map a=0.67", 2, 128, 16, 0.5, 2.0 / 3.0, {1, 2, 0.3, 0.2, 0.4, 2.0, 3.0, 1.0}},
        {"chapter 7 final", 32, 0, 0, 0, 0, {1, 2, 0.3, 0.2, 0.4, 1.0, -0.5, 1.0}},
    };
    char text[2048] = "";
    FILE *out = fmemopen(text, sizeof text, "w");
    assert_non_null(out);
    bias_variance_print(out, rows, 2);
    fclose(out);
    print_message("%s", text);
    assert_non_null(strstr(text, "  75%   25%\n"));
    assert_non_null(strstr(text, "   0%  100%\n"));
    char path[] = "/tmp/test_bias_variance_XXXXXX";
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    assert_int_equal(bias_variance_write_csv(path, rows, 2), 0);
    FILE *csv = fopen(path, "r");
    assert_non_null(csv);
    char line[512];
    assert_non_null(fgets(line, sizeof line, csv));
    assert_non_null(fgets(line, sizeof line, csv));
    assert_string_equal(
        line, "photon map a=0.67,2,128,0.5,0.666667,16,1,2,0.3,0.2,0.4,2,3,1,0.75,0.25\n");
    fclose(csv);
    remove(path);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_finds_known_bias_and_variance),
        cmocka_unit_test(test_left_out_pixels_change_nothing),
        cmocka_unit_test(test_bright_mask_by_hand),
        cmocka_unit_test(test_table_by_hand),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
