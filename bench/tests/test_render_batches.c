/* test_render_batches.c (bench, chapter 7): the batched render (render_batches.h).
 *
 * - Its standard errors are unbiased: over many independent batched renders of an image
 *   with an edge through its pixels and noise on top, the mean of the squared standard
 *   errors matches the variance of the pixels across the renders, channel by channel.
 * - Why batches: a single sub-pixel render's own standard errors (from the spread of its
 *   samples) overstate that variance at the edge severalfold.
 * - Bookkeeping: samples and rays summed over the batches, a noiseless image gets
 *   standard error 0, and a batch count that does not divide the samples is refused.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdlib.h>

#include "render_batches.h"

/* Red: 1 on one side of an oblique plane through the eye, so a line across several
 * pixels of the 4 x 4 image, where only the pixel position varies; green: a uniform
 * random number (noise that stratification cannot touch); blue: both. */
static Vec3 edge_and_noise(const Scene *scene, Ray ray, Rng *rng, const void *settings,
                           RayCounts *counts)
{
    double edge = ray.dir.x + 0.37 * ray.dir.y - 0.11 * ray.dir.z > 0.0 ? 1.0 : 0.0;
    double u = rng_uniform(rng);
    return vec3(edge, u, edge + u);
}

static Vec3 constant(const Scene *scene, Ray ray, Rng *rng, const void *settings,
                     RayCounts *counts)
{
    return vec3(1, 2, 3);
}

static Scene tiny_scene(void)
{
    Scene scene;
    scene_init(&scene);
    scene.camera = camera_make(vec3(0, 0, 0), vec3(-1, -1, 1), vec3(1, -1, 1), vec3(-1, 1, 1));
    return scene;
}

#define SIDE 4
#define PIXELS (SIDE * SIDE)
#define VALUES (4 * PIXELS) /* three channels, then the grey (R + G + B) / 3 */
#define RENDERS 400

/* Over RENDERS renders with seeds 1, 2, ...: per channel (and for the grey, the channel
 * mean, whose error is average_std_error), the sum over pixels of the variance of the
 * pixel across the renders, and the sum of the mean squared standard error the renders
 * claimed. batches 0: plain render(). */
static void variance_and_claim(int batches, int spp, double variance[4], double claimed[4])
{
    Scene scene = tiny_scene();
    double *sum = calloc(VALUES, sizeof *sum), *squares = calloc(VALUES, sizeof *squares);
    double *claims = calloc(VALUES, sizeof *claims);
    assert_non_null(sum);
    assert_non_null(squares);
    assert_non_null(claims);
    for (int k = 1; k <= RENDERS; k++) {
        RenderSettings settings = {.image = {.width = SIDE,
                                             .height = SIDE,
                                             .spp = spp,
                                             .sampling = PIXEL_SUBPIXELS,
                                             .seed = (uint64_t)k},
                                   .threads = 1,
                                   .label = "test"};
        RenderResult result;
        if (batches > 0)
            assert_int_equal(
                render_batches(&scene, &settings, batches, edge_and_noise, NULL, &result), 0);
        else
            assert_int_equal(render(&scene, &settings, edge_and_noise, NULL, &result), 0);
        for (int p = 0; p < PIXELS; p++) {
            const float *x = result.image.pixels + 3 * p, *se = result.std_error.pixels + 3 * p;
            double values[4] = {x[0], x[1], x[2], ((double)x[0] + x[1] + x[2]) / 3.0};
            double errors[4] = {se[0], se[1], se[2], result.average_std_error.pixels[3 * p]};
            for (int c = 0; c < 4; c++) {
                sum[4 * p + c] += values[c];
                squares[4 * p + c] += values[c] * values[c];
                claims[4 * p + c] += errors[c] * errors[c] / RENDERS;
            }
        }
        render_result_free(&result);
    }
    for (int c = 0; c < 4; c++)
        variance[c] = claimed[c] = 0.0;
    for (int i = 0; i < VALUES; i++) {
        double mean = sum[i] / RENDERS;
        variance[i % 4] += (squares[i] - RENDERS * mean * mean) / (RENDERS - 1);
        claimed[i % 4] += claims[i];
    }
    free(sum);
    free(squares);
    free(claims);
}

/* 4 batches of 8 sub-pixel samples. The sums' own spread is a few per cent (400
 * renders); a batch estimate divided by B instead of B - 1 claims 3/4 of the variance. */
static void test_standard_errors_unbiased(void **state)
{
    double variance[4], claimed[4];
    variance_and_claim(4, 32, variance, claimed);
    for (int c = 0; c < 4; c++) {
        print_message(
            "    channel %d: variance across renders %.3e, claimed %.3e, ratio %.3f\n", c,
            variance[c], claimed[c], claimed[c] / variance[c]);
        assert_true(variance[c] > 0.0);
        assert_true(fabs(claimed[c] / variance[c] - 1.0) < 0.12);
    }
}

/* One render of 32 jittered sub-pixels: its own errors, from the spread of the
 * samples, overstate the edge's variance (red) severalfold; the noise (green) has
 * independent samples, and its errors are right. */
static void test_one_stratified_render_overstates(void **state)
{
    double variance[4], claimed[4];
    variance_and_claim(0, 32, variance, claimed);
    print_message("    one render: red claimed / variance %.2f, green %.3f\n",
                  claimed[0] / variance[0], claimed[1] / variance[1]);
    assert_true(claimed[0] > 2.0 * variance[0]);
    assert_true(fabs(claimed[1] / variance[1] - 1.0) < 0.12);
}

static void test_bookkeeping(void **state)
{
    Scene scene = tiny_scene();
    RenderSettings settings = {.image = {.width = SIDE,
                                         .height = SIDE,
                                         .spp = 12,
                                         .sampling = PIXEL_SUBPIXELS,
                                         .seed = 5},
                               .threads = 2,
                               .label = "test"};
    RenderResult result;
    assert_int_equal(render_batches(&scene, &settings, 3, constant, NULL, &result), 0);
    assert_true(result.samples == SIDE * SIDE * 12 && result.rays.camera == SIDE * SIDE * 12);
    assert_true(result.nonfinite == 0 && !result.interrupted);
    for (int i = 0; i < 3 * PIXELS; i++) {
        assert_true(result.image.pixels[i] == (float)(i % 3 + 1));
        assert_true(result.std_error.pixels[i] == 0.0f);
        assert_true(result.average_std_error.pixels[i] == 0.0f);
    }
    render_result_free(&result);
    assert_int_equal(render_batches(&scene, &settings, 5, constant, NULL, &result), -1);
    assert_int_equal(render_batches(&scene, &settings, 1, constant, NULL, &result), -1);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_standard_errors_unbiased),
        cmocka_unit_test(test_one_stratified_render_overstates),
        cmocka_unit_test(test_bookkeeping),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
