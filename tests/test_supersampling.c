/* test_supersampling.c (chapter 2): sub-pixels against random positions. Both estimate
 * the same image, and a stratified render stopped early is unbiased (camera.h, render.h).
 *
 * 1. The report's room at 12 x 12 pixels (large pixels: the lamp's, the sphere's and the
 *    walls' edges cross many of them), chapter 2's estimator (no shadow rays, depth 6).
 *    Sub-pixels: RUNS renders of STRATA samples per pixel (a non-square
 *    count), each with its own seed; a pixel's estimate is the mean of its RUNS values,
 *    and its standard error comes from their spread (so the gain from stratification is
 *    counted, which a single render's per-sample variance would not). Random positions:
 *    one render of RUNS x STRATA samples per pixel. For each pixel the channel mean
 *    gives z = (a - b) / sqrt(se_a^2 + se_b^2); pixels are independent, so the sum of
 *    z^2 over the 144 pixels is chi-square with 144 degrees of freedom if both estimate
 *    the same image. Significance level 0.1%, fixed seeds (p = 0.58; three other sets
 *    of seeds gave 0.58, 0.42, 0.72). Sub-pixels cut the variance of a pixel's 5-sample
 *    mean by 14% here (0.83 against 0.97). Samples at the cells' centres without jitter
 *    (the planted bug) estimate the image at fixed points instead, biased at every edge:
 *    rejected (sum of z^2 = 1414, largest |z| 22).
 * 2. An interrupted render: an estimator returning the sample's
 *    position (u, v, u v) within its pixel has pixel integrals 1/2, 1/2, 1/4. A render of
 *    1000 sub-pixel samples per pixel stopped by SIGINT after about 3 of them must still
 *    average to those, within 4 standard errors over the 1024 pixels: the renderer takes
 *    each pixel's samples from a random first one (bench/sample_order.h). Taking every
 *    pixel's from sample 0 (the planted bug) samples only the top of each pixel, and
 *    fails. This test raises SIGINT, after which the renderer's flag stays set: it runs
 *    last.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <signal.h>
#include <stdlib.h>

#include "renderer.h"
#include "chi_square.h"
#include "path.h"
#include "scene_file.h"

#define SIDE 12
#define PIXELS (SIDE * SIDE)
#define STRATA 5
#define RUNS 200

static void test_subpixels_and_random_estimate_the_same_image(void **state)
{
    Scene scene;
    char error[256];
    assert_int_equal(scene_load("scenes/room.scene", &scene, error, sizeof error), 0);
    PathSettings path = {.max_depth = 6};
    double *sum = calloc(PIXELS, sizeof *sum), *squares = calloc(PIXELS, sizeof *squares);
    assert_non_null(sum);
    assert_non_null(squares);
    for (int run = 0; run < RUNS; run++) {
        RenderSettings settings = {
            {SIDE, SIDE, STRATA, PIXEL_SUBPIXELS, 100 + (uint64_t)run}, 0, 0, "test"};
        RenderResult result;
        assert_int_equal(render(&scene, &settings, path_radiance, &path, &result), 0);
        for (int p = 0; p < PIXELS; p++) {
            double x = vec3_average(image_get(&result.image, p % SIDE, p / SIDE));
            sum[p] += x;
            squares[p] += x * x;
        }
        render_result_free(&result);
    }
    RenderSettings random = {{SIDE, SIDE, RUNS * STRATA, PIXEL_RANDOM, 99}, 0, 0, "test"};
    RenderResult b;
    assert_int_equal(render(&scene, &random, path_radiance, &path, &b), 0);
    double sum_z2 = 0.0, largest = 0.0, stratified_variance = 0.0, random_variance = 0.0;
    for (int p = 0; p < PIXELS; p++) {
        double mean_a = sum[p] / RUNS;
        double variance_a = (squares[p] - RUNS * mean_a * mean_a) / (RUNS - 1);
        double se_a2 = variance_a / RUNS;
        double mean_b = vec3_average(image_get(&b.image, p % SIDE, p / SIDE));
        double se_b = image_get(&b.average_std_error, p % SIDE, p / SIDE).x;
        double z = (mean_a - mean_b) / sqrt(se_a2 + se_b * se_b);
        stratified_variance += variance_a / PIXELS;
        random_variance += se_b * se_b * RUNS / PIXELS; /* of a mean of STRATA samples */
        sum_z2 += z * z;
        largest = fmax(largest, fabs(z));
    }
    double p = chi_square_p_value(sum_z2, PIXELS);
    print_message("    sum of z^2 = %.1f over %d pixels (p = %.3f), largest |z| %.2f\n", sum_z2,
                  PIXELS, p, largest);
    print_message("    variance of a %d-sample pixel mean: sub-pixels %.4f, random %.4f\n",
                  STRATA, stratified_variance, random_variance);
    assert_true(p > 0.001);
    free(sum);
    free(squares);
    render_result_free(&b);
    scene_free(&scene);
}

/* The image plane z = 1, x and y in [-1, 1], seen from the origin. */
#define POSITION_SIDE 32

/* (u, v, u v): where in its pixel the camera ray passed (camera.h's mapping inverted);
 * raises SIGINT during pass 3. */
static Vec3 position_in_pixel(const Scene *scene, Ray ray, Rng *rng, const void *settings,
                              RayCounts *counts)
{
    (void)scene, (void)rng, (void)settings, (void)counts;
    static long calls;
    if (++calls == POSITION_SIDE * POSITION_SIDE * 3L + 100)
        raise(SIGINT);
    double x = (ray.dir.x / ray.dir.z + 1.0) / 2.0, y = (ray.dir.y / ray.dir.z + 1.0) / 2.0;
    double across = x * POSITION_SIDE, down = (1.0 - y) * POSITION_SIDE;
    double u = across - floor(across), v = down - floor(down);
    return vec3(u, v, u * v);
}

static void test_interrupted_subpixel_render_is_unbiased(void **state)
{
    Scene scene;
    scene_init(&scene);
    scene.camera = camera_make(vec3(0, 0, 0), vec3(-1, -1, 1), vec3(1, -1, 1), vec3(-1, 1, 1));
    render_install_interrupt();
    RenderSettings settings = {
        {POSITION_SIDE, POSITION_SIDE, 1000, PIXEL_SUBPIXELS, 3}, 1, 0, "test"};
    RenderResult result;
    assert_int_equal(render(&scene, &settings, position_in_pixel, NULL, &result), 0);
    assert_true(result.interrupted);
    double spp = render_samples_per_pixel(&result);
    const double expected[3] = {0.5, 0.5, 0.25};
    const int n = POSITION_SIDE * POSITION_SIDE;
    for (int c = 0; c < 3; c++) {
        double sum = 0.0, squares = 0.0;
        for (int i = 0; i < n; i++) {
            double x = result.image.pixels[3 * i + c];
            sum += x;
            squares += x * x;
        }
        double mean = sum / n, se = sqrt((squares / n - mean * mean) / (n - 1));
        print_message("    after %.2f of 1000 spp, channel %d: %.4f +- %.4f, expected %.2f\n",
                      spp, c, mean, se, expected[c]);
        assert_true(fabs(mean - expected[c]) < 4 * se);
    }
    assert_true(spp > 3.0 && spp < 4.0);
    render_result_free(&result);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_subpixels_and_random_estimate_the_same_image),
        cmocka_unit_test(test_interrupted_subpixel_render_is_unbiased), /* last: SIGINT */
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
