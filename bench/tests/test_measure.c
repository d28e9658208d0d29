/* test_measure.c (bench, chapter 2): error metrics, and the hash that names a reference
 * (measure.h).
 *
 * The metrics are checked against sums done by hand on images of a few pixels, and
 * statistically: the image mean's standard error against images of known variance and
 * by the z-scores of many independent renders (standard normal: Kolmogorov-Smirnov);
 * the error corrected for the reference's noise against synthetic images whose noise is
 * known; the summaries of several runs and the infinite-variance mark by hand. The hash
 * against the published FNV-1a 64 test vectors (the cache itself: test_reference_cache.c).
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
#include "measure.h"
#include "path.h"
#if CHAPTER >= 3
#include "path_direct.h"
#endif
#include "renderer.h"
#include "scene_file.h"

/* An image whose values, channel by channel in reading order, are `values`. */
static Image image_of(int width, int height, const float *values)
{
    Image image = image_new(width, height);
    assert_non_null(image.pixels);
    memcpy(image.pixels, values, sizeof(float) * 3 * (size_t)width * (size_t)height);
    return image;
}

/* RMSE and relative MSE are sums over every channel of every pixel, divided by N = 6
 * here. Differences 0.5, 0, 0, 1, 0, -0.5 against references 0.5, 0.5, 0, 1, 0.25, 0.5:
 *     RMSE    = sqrt((0.25 + 1 + 0.25) / 6) = 0.5
 *     rel_MSE = (0.25/0.26 + 1/1.01 + 0.25/0.26) / 6 = 0.48552932...
 * A channel with no error adds nothing, whatever its reference. */
static void test_error_by_hand(void **state)
{
    const float values[] = {1.0f, 0.5f, 0.0f, 2.0f, 0.25f, 0.0f};
    const float truth[] = {0.5f, 0.5f, 0.0f, 1.0f, 0.25f, 0.5f};
    Image image = image_of(2, 1, values), reference = image_of(2, 1, truth);
    double rmse, rel_mse;
    measure_error(&image, &reference, &rmse, &rel_mse);
    assert_close(rmse, 0.5, 1e-15);
    assert_close(rel_mse, (0.25 / 0.26 + 1.0 / 1.01 + 0.25 / 0.26) / 6.0, 1e-15);
    assert_close(rel_mse, 0.4855293221, 1e-10);
    image_free(&image);
    image_free(&reference);
}

/* The 0.01 in the denominator: against a black reference the relative error of a
 * value x is x^2 / 0.01 (finite, not a division by zero), while against a bright one
 * the same absolute error weighs far less: 0.1 off against 0 counts 1, 0.1 off
 * against 10 counts 0.01 / 100.01. The RMSE treats both alike. */
static void test_relative_error_weights_dark_pixels(void **state)
{
    const float values[] = {0.5f, 0.5f, 0.5f};
    const float dark[] = {0.0f, 0.0f, 0.0f}, bright[] = {10.0f, 10.0f, 10.0f};
    const float bright_values[] = {10.5f, 10.5f, 10.5f};
    Image image = image_of(1, 1, values), black = image_of(1, 1, dark);
    Image brighter = image_of(1, 1, bright_values), white = image_of(1, 1, bright);
    double rmse_dark, rel_dark, rmse_bright, rel_bright;
    measure_error(&image, &black, &rmse_dark, &rel_dark);
    measure_error(&brighter, &white, &rmse_bright, &rel_bright);
    assert_close(rel_dark, 0.25 / 0.01, 1e-12);
    assert_close(rel_bright, 0.25 / 100.01, 1e-12);
    assert_close(rmse_dark, 0.5, 1e-15);
    assert_close(rmse_bright, 0.5, 1e-15);
    image_free(&image);
    image_free(&black);
    image_free(&brighter);
    image_free(&white);
}

/* An image compared with itself has no error at all, exactly. */
static void test_identical_images_have_no_error(void **state)
{
    const float values[] = {0.0f, 0.3f, 7.0f, 1e-6f, 123.0f, 0.5f};
    Image image = image_of(2, 1, values);
    double rmse = -1.0, rel_mse = -1.0;
    measure_error(&image, &image, &rmse, &rel_mse);
    assert_true(rmse == 0.0);
    assert_true(rel_mse == 0.0);
    image_free(&image);
}

/* RMS over pixels and channels: 1, 2, 2 gives sqrt(9/3) = sqrt(3); the sign of a value
 * does not matter; a constant image's RMS is that constant's magnitude. */
static void test_rms_by_hand(void **state)
{
    const float values[] = {1.0f, -2.0f, 2.0f};
    const float constant[] = {-0.25f, -0.25f, -0.25f, -0.25f, -0.25f, -0.25f};
    Image image = image_of(1, 1, values), flat = image_of(2, 1, constant);
    assert_close(measure_rms(&image), sqrt(3.0), 1e-15);
    assert_close(measure_rms(&flat), 0.25, 1e-15);
    image_free(&image);
    image_free(&flat);
}

/* The image mean is over pixels of each pixel's channel mean: (1 + 2 + 3) / 3 = 2 and
 * (4 + 5 + 6) / 3 = 5 give 3.5. Its standard error adds the pixels' standard errors of
 * their channel means in quadrature, over P = 2: sqrt(3^2 + 4^2) / 2 = 2.5. Given
 * per-channel errors instead, a pixel's mean error is read (the fully correlated bound):
 * errors 1, 2, 3 and 0, 0, 0 give sqrt(2^2) / 2 = 1. */
static void test_image_mean_by_hand(void **state)
{
    const float values[] = {1, 2, 3, 4, 5, 6}, grey[] = {3, 3, 3, 4, 4, 4};
    const float channels[] = {1, 2, 3, 0, 0, 0};
    Image image = image_of(2, 1, values), average_error = image_of(2, 1, grey);
    Image channel_error = image_of(2, 1, channels);
    double mean, mean_std_error;
    measure_image_mean(&image, &average_error, &mean, &mean_std_error);
    assert_close(mean, 3.5, 1e-15);
    assert_close(mean_std_error, 2.5, 1e-15);
    measure_image_mean(&image, &channel_error, &mean, &mean_std_error);
    assert_close(mean_std_error, 1.0, 1e-15);
    image_free(&image);
    image_free(&average_error);
    image_free(&channel_error);
}

/* Channel means by hand: pixels (1, 2, 4) and (3, 6, 0) give (2, 4, 2). */
static void test_channel_means_by_hand(void **state)
{
    const float values[] = {1, 2, 4, 3, 6, 0};
    Image image = image_of(1, 2, values);
    double means[3];
    measure_channel_means(&image, means);
    assert_close(means[0], 2.0, 1e-15);
    assert_close(means[1], 4.0, 1e-15);
    assert_close(means[2], 2.0, 1e-15);
    image_free(&image);
}

/* The most efficient row that can be ranked: not of infinite variance, its efficiency
 * measured (not NaN); -1 when none is. */
static void test_most_efficient(void **state)
{
    TableRow rows[4] = {{.efficiency = NAN},
                        {.efficiency = 3},
                        {.efficiency = 9, .infinite_variance = 1},
                        {.efficiency = 5}};
    assert_int_equal(measure_most_efficient(rows, 4), 3);
    assert_int_equal(measure_most_efficient(rows, 3), 1);
    assert_int_equal(measure_most_efficient(rows, 1), -1);
    assert_int_equal(measure_most_efficient(&rows[2], 1), -1);
}

/* Clearly lower: relative MSE 1 and 2 from 4 runs each of spread 0.6 have a difference
 * of standard error sqrt(2) 0.3 = 0.42, so 1 is more than twice that below 2, but not
 * below 1.8; one run has no spread to weigh; and nothing is lower than itself. */
static void test_clearly_lower(void **state)
{
    TableRow low = {.rel_mse = 1, .rel_mse_spread = 0.6, .runs = 4};
    TableRow high = {.rel_mse = 2, .rel_mse_spread = 0.6, .runs = 4};
    TableRow near = {.rel_mse = 1.8, .rel_mse_spread = 0.6, .runs = 4};
    TableRow single = {.rel_mse = 1.1, .rel_mse_spread = NAN, .runs = 1};
    assert_true(measure_clearly_lower(&low, &high));
    assert_false(measure_clearly_lower(&high, &low));
    assert_false(measure_clearly_lower(&low, &near));
    assert_false(measure_clearly_lower(&low, &low));
    TableRow single_high = {.rel_mse = 1.2, .rel_mse_spread = NAN, .runs = 1};
    assert_true(measure_clearly_lower(&single, &single_high));
}

/* z by hand: 5 +- 3 against 1 +- 4 is 4 / 5 = 0.8 standard errors above; the other
 * way, -0.8. Changed pixels by hand: of three, one differs in its blue channel alone. */
static void test_z_and_changed_fraction_by_hand(void **state)
{
    assert_close(measure_z(5, 3, 1, 4), 0.8, 1e-15);
    assert_close(measure_z(1, 4, 5, 3), -0.8, 1e-15);
    const float a_values[] = {1, 2, 3, 4, 5, 6, 7, 8, 9},
                b_values[] = {1, 2, 3, 4, 5, 6.5f, 7, 8, 9};
    Image a = image_of(3, 1, a_values), b = image_of(3, 1, b_values);
    assert_close(measure_changed_fraction(&a, &b), 1.0 / 3.0, 1e-15);
    assert_close(measure_changed_fraction(&a, &a), 0.0, 0.0);
    image_free(&a);
    image_free(&b);
}

/* A window's brightness by hand, on a 3 x 2 image whose pixels are grey 0 .. 5 in reading
 * order with standard errors 1 .. 6 in the red channel alone (their channel mean, 1/3 ..
 * 2): the 3 x 3 window around pixel (1, 0) repeats the top row for the row above the
 * image, so it holds 0, 1, 2 twice and 3, 4, 5: mean 18 / 9 = 2, standard error
 * sqrt(2 (1 + 4 + 9) + 16 + 25 + 36) / 9 / 3. Half 0 is the pixel alone; the window
 * around the corner (2, 1) with half 1 repeats the last column and row: 1, 2, 2, 4, 5, 5,
 * 4, 5, 5, mean 33 / 9. */
static void test_window_mean_by_hand(void **state)
{
    float grey[18], errors[18] = {0};
    for (int i = 0; i < 6; i++) {
        grey[3 * i] = grey[3 * i + 1] = grey[3 * i + 2] = (float)i;
        errors[3 * i] = (float)(i + 1);
    }
    Image image = image_of(3, 2, grey), std_error = image_of(3, 2, errors);
    double mean, error;
    measure_window_mean(&image, &std_error, 1, 0, 1, &mean, &error);
    assert_close(mean, 2.0, 1e-15);
    assert_close(error, sqrt(2.0 * (1 + 4 + 9) + 16 + 25 + 36) / 9.0 / 3.0, 1e-15);
    measure_window_mean(&image, &std_error, 2, 1, 0, &mean, &error);
    assert_close(mean, 5.0, 1e-15);
    assert_close(error, 2.0, 1e-15);
    measure_window_mean(&image, &std_error, 2, 1, 1, &mean, &error);
    assert_close(mean, 33.0 / 9.0, 1e-15);
    image_free(&image);
    image_free(&std_error);
}

/* Averaging P independent pixels each with standard error s gives s / sqrt(P): four
 * pixels with s = 0.5 give 0.25. */
static void test_image_mean_error_shrinks_as_root_n(void **state)
{
    float values[12], errors[12];
    for (int i = 0; i < 12; i++) {
        values[i] = 2.0f;
        errors[i] = 0.5f;
    }
    Image image = image_of(2, 2, values), std_error = image_of(2, 2, errors);
    double mean, mean_std_error;
    measure_image_mean(&image, &std_error, &mean, &mean_std_error);
    assert_close(mean, 2.0, 1e-15);
    assert_close(mean_std_error, 0.25, 1e-15);
    image_free(&image);
    image_free(&std_error);
}

/* Synthetic images of known variance, rendered (renderer.h) so that the standard errors
 * are estimated from the samples as a chapter's are: 16 x 16 pixels, 50 samples each, a
 * sample's channels (u, u, u) with u uniform on [0, 1) (fully correlated, as one path
 * carries all three) or (u1, u2, u3) (independent). The image mean's true standard
 * error is sqrt(Var(m) / (P n)), Var(m) the variance of one sample's channel mean:
 * 1/12 correlated, 1/36 independent. measure_image_mean must find it within 3% (the
 * estimate from 12,800 samples scatters by about 0.6%). Treating the channels as
 * independent, as it once did, gives 1/sqrt(3) of the truth for the correlated image:
 * the planted bug fails here. */
static Vec3 correlated_channels(const Scene *scene, Ray ray, Rng *rng, const void *settings,
                                RayCounts *counts)
{
    double u = rng_uniform(rng);
    return vec3(u, u, u);
}

static Vec3 independent_channels(const Scene *scene, Ray ray, Rng *rng, const void *settings,
                                 RayCounts *counts)
{
    double r = rng_uniform(rng), g = rng_uniform(rng);
    return vec3(r, g, rng_uniform(rng));
}

static double image_mean_std_error(Estimator estimate)
{
    Scene scene;
    scene_init(&scene);
    scene.camera = camera_make(vec3(0, 0, 0), vec3(-1, -1, 1), vec3(1, -1, 1), vec3(-1, 1, 1));
    RenderSettings settings = {
        .image = {.width = 16, .height = 16, .spp = 50, .sampling = PIXEL_RANDOM, .seed = 8},
        .threads = 2,
        .label = "test"};
    RenderResult result;
    assert_int_equal(render(&scene, &settings, estimate, NULL, &result), 0);
    double mean, std_error;
    measure_image_mean(&result.image, &result.average_std_error, &mean, &std_error);
    print_message("    mean %.5f +- %.6f\n", mean, std_error);
    assert_true(fabs(mean - 0.5) < 4 * std_error);
    render_result_free(&result);
    return std_error;
}

static void test_image_mean_error_of_known_variance(void **state)
{
    double correlated = sqrt(1.0 / 12 / (256 * 50)), independent = sqrt(1.0 / 36 / (256 * 50));
    assert_close(image_mean_std_error(correlated_channels), correlated, 0.03 * correlated);
    assert_close(image_mean_std_error(independent_channels), independent, 0.03 * independent);
}

/* The standard normal distribution function. */
static double normal_cdf(double z) { return 0.5 * erfc(-z / sqrt(2.0)); }

/* Kolmogorov-Smirnov test of n values against the standard normal distribution: the
 * largest distance D between their empirical distribution function and Phi, and its
 * p-value from Kolmogorov's limit distribution, Q(lambda) = 2 sum_k (-1)^(k-1)
 * exp(-2 k^2 lambda^2), with Stephens' small-sample correction lambda = (sqrt(n) + 0.12
 * + 0.11 / sqrt(n)) D. */
static int compare(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static double ks_normal_p_value(double *values, int n, double *distance)
{
    qsort(values, (size_t)n, sizeof *values, compare);
    double d = 0.0;
    for (int i = 0; i < n; i++) {
        double f = normal_cdf(values[i]);
        d = fmax(d, fmax(f - (double)i / n, (double)(i + 1) / n - f));
    }
    *distance = d;
    double lambda = (sqrt(n) + 0.12 + 0.11 / sqrt(n)) * d;
    if (lambda < 0.2)
        return 1.0;
    double q = 0.0;
    for (int k = 1; k <= 100; k++)
        q += (k % 2 ? 2.0 : -2.0) * exp(-2.0 * k * k * lambda * lambda);
    return fmin(fmax(q, 0.0), 1.0);
}

#if CHAPTER >=                                                                                 \
    3 /* the estimator with a shadow ray (path_direct.h), for noise without fireflies */
/* The z-score of an unbiased setting is standard normal when its standard error is
 * right (chapters 4 and 6 print such z-scores). The report's room at 8 x 8 pixels, the
 * path tracer with one shadow ray, depth 6, 32 spp: PAIRS pairs of renders with
 * different seeds, each pair giving z = (mean_a - mean_b) / sqrt(se_a^2 + se_b^2) of
 * their image means (independent renders of the same expectation, so no reference is
 * needed). The PAIRS values must pass a Kolmogorov-Smirnov test against N(0, 1) at the
 * 1% level (fixed seeds 1000 ... 1299: p = 0.54, spread 1.04; three other sets of seeds
 * gave p = 0.29 to 0.89, spreads 0.92 to 1.15: the caustics' rare bright samples make
 * the spread itself vary more than a normal sample's would). With the channels taken
 * as independent (the planted bug) the z-scores spread 1.8 times too wide: p = 0.000. */
#define PAIRS 150

static double room_image_mean(const Scene *scene, uint64_t seed, double *std_error)
{
    PathSettings path = {.max_depth = 6, .shadow_rays = 1};
    RenderSettings settings = {
        .image = {.width = 8, .height = 8, .spp = 32, .sampling = PIXEL_RANDOM, .seed = seed},
        .label = "test"};
    RenderResult result;
    assert_int_equal(render(scene, &settings, path_direct_radiance, &path, &result), 0);
    double mean;
    measure_image_mean(&result.image, &result.average_std_error, &mean, std_error);
    render_result_free(&result);
    return mean;
}

static void test_image_mean_z_scores_are_standard_normal(void **state)
{
    Scene scene;
    char error[256];
    assert_int_equal(scene_load("scenes/room.scene", &scene, error, sizeof error), 0);
    double z[PAIRS], sum = 0.0, squares = 0.0;
    for (int i = 0; i < PAIRS; i++) {
        double se_a, se_b;
        double a = room_image_mean(&scene, 1000 + 2 * (uint64_t)i, &se_a);
        double b = room_image_mean(&scene, 1001 + 2 * (uint64_t)i, &se_b);
        z[i] = (a - b) / sqrt(se_a * se_a + se_b * se_b);
        sum += z[i];
        squares += z[i] * z[i];
    }
    double distance, p = ks_normal_p_value(z, PAIRS, &distance);
    print_message("    %d z-scores: mean %.3f, spread %.3f; KS distance %.3f, p = %.3f\n",
                  PAIRS, sum / PAIRS, sqrt(squares / PAIRS - sum * sum / PAIRS / PAIRS),
                  distance, p);
    assert_true(p > 0.01);
    scene_free(&scene);
}
#endif

/* The KS test itself: 400 standard normal draws (Box-Muller) pass; the same draws
 * scaled by 1.5 or shifted by 0.25 fail (p < 0.01). */
static void test_ks_test_has_power(void **state)
{
    double normal[400], scaled[400], shifted[400], distance;
    Rng rng = rng_for_sample(5, 5, 5);
    for (int i = 0; i < 400; i++) {
        double r = sqrt(-2.0 * log(1.0 - rng_uniform(&rng))),
               phi = 2.0 * PI * rng_uniform(&rng);
        normal[i] = r * cos(phi);
        scaled[i] = 1.5 * normal[i];
        shifted[i] = normal[i] + 0.25;
    }
    assert_true(ks_normal_p_value(normal, 400, &distance) > 0.01);
    assert_true(ks_normal_p_value(scaled, 400, &distance) < 0.01);
    assert_true(ks_normal_p_value(shifted, 400, &distance) < 0.01);
}

/* The corrected error by hand. Image 1, 2, 0 and 0, 0, 0 against reference 0, 0, 0 and
 * 0, 0, 1 with standard errors 0.5 on every channel (N = 6):
 *     raw MSE = (1 + 4 + 1) / 6 = 1,   reference's part = 0.25,   MSE = 0.75,
 *     RMSE = sqrt(0.75),   share = 0.25;
 *     relative: raw (1 + 4) / 0.01 / 6 + 1 / 1.01 / 6, reference's part
 *     0.25 (5 / 0.01 + 1 / 1.01) / 6. */
static void test_error_estimate_by_hand(void **state)
{
    const float values[] = {1, 2, 0, 0, 0, 0}, truth[] = {0, 0, 0, 0, 0, 1};
    const float errors[] = {0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f};
    Image image = image_of(2, 1, values), reference = image_of(2, 1, truth);
    Image reference_error = image_of(2, 1, errors);
    ErrorEstimate e;
    assert_int_equal(measure_error_estimate(&image, &reference, &reference_error, &e), 0);
    assert_close(e.raw_mse, 1.0, 1e-15);
    assert_close(e.reference_mse, 0.25, 1e-15);
    assert_close(e.mse, 0.75, 1e-15);
    assert_close(e.rmse, sqrt(0.75), 1e-15);
    assert_close(e.reference_share, 0.25, 1e-15);
    double raw_relative = (5.0 / 0.01 + 1.0 / 1.01) / 6.0;
    double reference_relative = 0.25 * (5.0 / 0.01 + 1.0 / 1.01) / 6.0;
    assert_close(e.raw_rel_mse, raw_relative, 1e-12);
    assert_close(e.reference_rel_mse, reference_relative, 1e-12);
    assert_close(e.rel_mse, raw_relative - reference_relative, 1e-12);
    /* Without standard errors (NULL), nothing is subtracted: the raw error. */
    assert_int_equal(measure_error_estimate(&image, &reference, NULL, &e), 0);
    assert_true(e.mse == e.raw_mse && e.reference_mse == 0.0 && e.reference_share == 0.0);
    image_free(&image);
    image_free(&reference);
    image_free(&reference_error);
}

/* An image closer to the truth than the reference can tell: the corrected MSE is
 * negative, RMSE 0, the share above 1; an image identical to a noiseless reference has
 * share 0 (not 0 / 0). */
static void test_error_estimate_below_reference_noise(void **state)
{
    const float values[] = {0.1f, 0.1f, 0.1f}, truth[] = {0, 0, 0}, errors[] = {1, 1, 1};
    Image image = image_of(1, 1, values), reference = image_of(1, 1, truth);
    Image reference_error = image_of(1, 1, errors);
    ErrorEstimate e;
    assert_int_equal(measure_error_estimate(&image, &reference, &reference_error, &e), 0);
    assert_true(e.mse < 0 && e.rmse == 0.0 && e.reference_share > 1.0);
    assert_int_equal(measure_error_estimate(&reference, &reference, NULL, &e), 0);
    assert_true(e.raw_mse == 0.0 && e.reference_share == 0.0);
    image_free(&image);
    image_free(&reference);
    image_free(&reference_error);
}

/* Images of different sizes are not compared (a 1 x 1 reference in the cache must not
 * be read past its end): -1 and NaN, from both functions. */
static void test_error_of_mismatched_sizes(void **state)
{
    const float six[] = {0, 0, 0, 0, 0, 0};
    Image two = image_of(2, 1, six), one = image_of(1, 1, six), tall = image_of(1, 2, six);
    ErrorEstimate e;
    assert_int_equal(measure_error_estimate(&two, &one, NULL, &e), -1);
    assert_true(isnan(e.mse) && isnan(e.rmse) && isnan(e.reference_share));
    assert_int_equal(measure_error_estimate(&two, &two, &one, &e), -1);
    double rmse, rel_mse;
    assert_int_equal(measure_error(&two, &tall, &rmse, &rel_mse), -1);
    assert_true(isnan(rmse) && isnan(rel_mse));
    image_free(&two);
    image_free(&one);
    image_free(&tall);
}

/* A standard normal variable (Box-Muller). */
static double gaussian(Rng *rng)
{
    return sqrt(-2.0 * log(1.0 - rng_uniform(rng))) * cos(2.0 * PI * rng_uniform(rng));
}

/* The correction is unbiased (measure.h): a flat truth of 0.5 on 200 x 200 pixels, an
 * image with noise of standard deviation 0.1 on every value, a reference with 0.2
 * (and its standard-error image saying so). The raw MSE is 0.01 + 0.04 = 0.05; the
 * corrected MSE must be the image's own 0.01 within 2% (120,000 values: the estimate
 * scatters by about 1%), and the reference's share 0.8. Without the correction (the
 * planted bug) the MSE reads 0.05: five times the truth. */
static void test_error_estimate_removes_reference_variance(void **state)
{
    const int side = 200;
    Image image = image_new(side, side), reference = image_new(side, side);
    Image reference_error = image_new(side, side);
    assert_non_null(image.pixels);
    assert_non_null(reference.pixels);
    assert_non_null(reference_error.pixels);
    Rng rng = rng_for_sample(77, 0, 0);
    for (int i = 0; i < 3 * side * side; i++) {
        image.pixels[i] = (float)(0.5 + 0.1 * gaussian(&rng));
        reference.pixels[i] = (float)(0.5 + 0.2 * gaussian(&rng));
        reference_error.pixels[i] = 0.2f;
    }
    ErrorEstimate e;
    assert_int_equal(measure_error_estimate(&image, &reference, &reference_error, &e), 0);
    print_message("    raw MSE %.5f, reference's %.5f (share %.3f), corrected %.5f\n",
                  e.raw_mse, e.reference_mse, e.reference_share, e.mse);
    assert_close(e.raw_mse, 0.05, 0.02 * 0.05);
    assert_close(e.mse, 0.01, 0.02 * 0.01);
    assert_close(e.reference_share, 0.8, 0.01);
    image_free(&image);
    image_free(&reference);
    image_free(&reference_error);
}

/* A table row gets the corrected RMSE and relative MSE of measure_error_estimate, and
 * efficiency 1 / (rel_MSE * seconds) from the row's own time; the cost columns are left
 * alone. A reference without standard errors is taken as noiseless. When the
 * corrected relative MSE is not positive, efficiency cannot be measured: NaN. */
static void test_fill_row(void **state)
{
    const float values[] = {1.0f, 0.5f, 0.0f, 2.0f, 0.25f, 0.0f};
    const float truth[] = {0.5f, 0.5f, 0.0f, 1.0f, 0.25f, 0.5f};
    const float errors[] = {0.1f, 0.1f, 0.1f, 0.1f, 0.1f, 0.1f};
    Reference reference = {.image = image_of(2, 1, truth), .std_error = image_of(2, 1, errors)};
    Image image = image_of(2, 1, values);
    TableRow row = {.panel = "p", .spp = 4, .seconds = 2.0, .threads = 3, .rays = {1, 2, 3}};
    ErrorEstimate e;
    measure_error_estimate(&image, &reference.image, &reference.std_error, &e);
    measure_fill_row(&row, &image, &reference);
    assert_true(row.rmse == e.rmse && row.rmse < 0.5);
    assert_true(row.rel_mse == e.rel_mse);
    assert_close(row.efficiency, 1.0 / (e.rel_mse * 2.0), 1e-12);
    assert_true(row.seconds == 2.0 && row.spp == 4 && row.threads == 3);
    assert_int_equal(ray_counts_total(row.rays), 6);

    Reference noiseless = {.image = reference.image};
    double rmse, rel_mse;
    measure_error(&image, &reference.image, &rmse, &rel_mse);
    measure_fill_row(&row, &image, &noiseless);
    assert_true(row.rmse == rmse && row.rel_mse == rel_mse);
    assert_close(row.efficiency, 1.0298, 1e-4);

    measure_fill_row(&row, &reference.image, &reference);
    assert_true(row.rmse == 0.0 && row.rel_mse < 0.0 && isnan(row.efficiency));
    image_free(&image);
    measure_reference_free(&reference);
}

/* Runs summarised by hand: 3, 1, 4, 1, 5 have mean 2.8, squared deviations summing to
 * 12.8, so standard deviation sqrt(12.8 / 4) and standard error that over sqrt(5);
 * median 3, range 1 to 5. An even count's median is the mean of the middle two; one
 * run has no spread; values near 10^9 keep theirs (1, Welford's update); no runs is an
 * error. */
static void test_summarise_runs(void **state)
{
    RunSummary s;
    const double values[] = {3, 1, 4, 1, 5};
    assert_int_equal(measure_summarise_runs(values, 5, &s), 0);
    assert_int_equal(s.runs, 5);
    assert_close(s.mean, 2.8, 1e-15);
    assert_close(s.std_dev, sqrt(3.2), 1e-15);
    assert_close(s.std_error, sqrt(3.2 / 5), 1e-15);
    assert_true(s.median == 3 && s.min == 1 && s.max == 5);
    assert_true(values[0] == 3 && values[4] == 5); /* the input is left alone */

    const double even[] = {10, 2, 1, 3};
    assert_int_equal(measure_summarise_runs(even, 4, &s), 0);
    assert_true(s.median == 2.5 && s.min == 1 && s.max == 10);

    const double one = 7.5;
    assert_int_equal(measure_summarise_runs(&one, 1, &s), 0);
    assert_true(s.mean == 7.5 && s.median == 7.5 && s.std_dev == 0.0 && s.std_error == 0.0);

    const double bright[] = {1e9 + 1, 1e9 + 2, 1e9 + 3};
    assert_int_equal(measure_summarise_runs(bright, 3, &s), 0);
    assert_close(s.std_dev, 1.0, 1e-6);

    assert_int_equal(measure_summarise_runs(values, 0, &s), -1);
    assert_true(s.runs == 0 && isnan(s.mean) && isnan(s.median));
}

#if CHAPTER >= 6
/* Infinite variance of constant-alpha roulette: alpha <= rho_max^2. The room's brightest
 * diffuse surface has rho = 0.8 (rho^2 = 0.64): Table 1's alpha = 0.25 and Figure 12's
 * 0.01 are infinite, 0.75 and 0.9 finite. The boundary alpha = rho^2 (every term of the
 * series equal) is infinite: 0.25 for rho = 0.5, both exact in binary. alpha = 1 is no
 * roulette, finite even for rho = 1; a black scene is finite for any alpha. */
static void test_roulette_variance_infinite(void **state)
{
    assert_true(measure_roulette_variance_infinite(0.25, 0.8));
    assert_true(measure_roulette_variance_infinite(0.01, 0.8));
    assert_true(measure_roulette_variance_infinite(0.25, 0.5));
    assert_false(measure_roulette_variance_infinite(0.75, 0.8));
    assert_false(measure_roulette_variance_infinite(0.9, 0.8));
    assert_false(measure_roulette_variance_infinite(1.0, 1.0));
    assert_true(measure_roulette_variance_infinite(0.99, 1.0));
    assert_false(measure_roulette_variance_infinite(0.01, 0.0));
}
#endif

/* The published FNV-1a 64 test vectors: the empty string leaves the offset basis;
 * "a" and "foobar" have their known hashes. */
static void test_hash_vectors(void **state)
{
    assert_true(measure_hash(MEASURE_HASH_START, "", 0) == 0xcbf29ce484222325ULL);
    assert_true(measure_hash(MEASURE_HASH_START, "a", 1) == 0xaf63dc4c8601ec8cULL);
    assert_true(measure_hash(MEASURE_HASH_START, "foobar", 6) == 0x85944171f73967e8ULL);
}

/* Hashing continues from where it left off: "foo" then "bar" is "foobar", so a cache
 * key can be built from a scene file and a settings text without concatenating them. */
static void test_hash_chains(void **state)
{
    uint64_t foo = measure_hash(MEASURE_HASH_START, "foo", 3);
    assert_true(measure_hash(foo, "bar", 3) == measure_hash(MEASURE_HASH_START, "foobar", 6));
    assert_true(measure_hash(foo, "bar", 3) != measure_hash(MEASURE_HASH_START, "barfoo", 6));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_error_by_hand),
        cmocka_unit_test(test_relative_error_weights_dark_pixels),
        cmocka_unit_test(test_identical_images_have_no_error),
        cmocka_unit_test(test_rms_by_hand),
        cmocka_unit_test(test_image_mean_by_hand),
        cmocka_unit_test(test_channel_means_by_hand),
        cmocka_unit_test(test_z_and_changed_fraction_by_hand),
        cmocka_unit_test(test_most_efficient),
        cmocka_unit_test(test_clearly_lower),
        cmocka_unit_test(test_window_mean_by_hand),
        cmocka_unit_test(test_image_mean_error_shrinks_as_root_n),
        cmocka_unit_test(test_image_mean_error_of_known_variance),
        cmocka_unit_test(test_ks_test_has_power),
#if CHAPTER >= 3
        cmocka_unit_test(test_image_mean_z_scores_are_standard_normal),
#endif
        cmocka_unit_test(test_error_estimate_by_hand),
        cmocka_unit_test(test_error_estimate_below_reference_noise),
        cmocka_unit_test(test_error_of_mismatched_sizes),
        cmocka_unit_test(test_error_estimate_removes_reference_variance),
        cmocka_unit_test(test_fill_row),
        cmocka_unit_test(test_summarise_runs),
#if CHAPTER >= 6
        cmocka_unit_test(test_roulette_variance_infinite),
#endif
        cmocka_unit_test(test_hash_vectors),
        cmocka_unit_test(test_hash_chains),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
