/* test_adaptive.c (chapter 10): Tests of adaptive sampling (lib/adaptive.c) on pixels whose
 * samples have a known distribution: an estimator that ignores its ray and returns a value
 * uniform in [0, 2 V) with probability P, else 0 (the heavy tail of a path that rarely finds
 * a small bright lamp), so every pixel's expectation is mu = P V exactly.
 *
 * 1. The error estimate: over 32 x 32 pixels of 4096 samples, the mean estimated relative
 *    MSE of the kept value against the true one, Var / n / (mu^2 + 0.01), for both rules
 *    (within 15 %: the estimate's own spread over 1024 pixels is about 4.4 %).
 * 2. The rule's bias, per pixel: 8 x 8 dark pixels (P = 0.02, V = 2.5), each rendered
 *    adaptively with 64 seeds (at least 64 samples, then passes of 8 up to 1024 while its
 *    estimate is above 0.001); each pixel's mean over the seeds against mu by the
 *    per-pixel z-test (agreement.h). The unbiased rule agrees; the biased one, which stops
 *    a pixel whose first samples saw no light, does not, and its bias is printed.
 * 3. The rule stops: never below the minimum, never beyond the maximum, nothing more once
 *    a pixel is at or below the threshold; a noiseless image takes the minimum only.
 * 4. Non-finite samples: an estimator returning NaN or infinity for a fifth of its samples,
 *    else 0.5: every pixel's value and estimate stay finite, the values exactly 0.5 (the
 *    mean of the finite samples), and the count dropped is the count returned.
 * Planted bugs they reject: the estimate without the factor 1/4 of ((A - B) / 2)^2 (1: 4 x
 * the true error); the unbiased rule keeping A, the half it decides from (2: disagrees);
 * the rule without its maximum (3); the sample kept whatever it is (4: NaN pixels).
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include <stdlib.h>

#include "adaptive.h"
#include "agreement.h"
#include "image.h"
#include "scene_file.h"

typedef struct {
    double probability, value;
} HeavyTail;

/* An Estimator (render.h): with probability P a value uniform in [0, 2 V), else 0, in
 * every channel: mean mu = P V, variance P 4 V^2 / 3 - mu^2. */
static Vec3 heavy_tail(const Scene *scene, Ray ray, Rng *rng, const void *settings,
                       RayCounts *counts)
{
    const HeavyTail *tail = settings;
    double x =
        rng_uniform(rng) < tail->probability ? 2.0 * tail->value * rng_uniform(rng) : 0.0;
    return vec3(x, x, x);
}

static Scene load_room(void)
{
    Scene scene;
    char error[256];
    assert_int_equal(scene_load("scenes/room.scene", &scene, error, sizeof error), 0);
    return scene;
}

/* The mean estimate over the pixels after `samples` samples each, against the truth. */
static void check_estimate(AdaptiveRule rule, double kept_samples_share)
{
    enum {
        SIDE = 32,
        SAMPLES = 4096
    };
    Scene scene = load_room();
    HeavyTail tail = {0.05, 2.0};
    ImageSettings image = {SIDE, SIDE, 0, PIXEL_RANDOM, 7};
    AdaptivePixel *pixels = calloc(SIDE * SIDE, sizeof *pixels);
    double *estimate = calloc(SIDE * SIDE, sizeof *estimate);
    int *to_add = calloc(SIDE * SIDE, sizeof *to_add);
    assert_non_null(pixels);
    assert_non_null(estimate);
    assert_non_null(to_add);
    for (int p = 0; p < SIDE * SIDE; p++)
        to_add[p] = SAMPLES;
    RayCounts counts = {0, 0, 0};
    adaptive_sample_rows(&scene, &image, heavy_tail, &tail, pixels, to_add, 0, SIDE, &counts);
    AdaptiveSettings settings = {rule, 4, SAMPLES, 4, 0.0};
    assert_int_equal(adaptive_plan(&settings, pixels, SIDE, SIDE, estimate, to_add), 0);
    double mean = 0.0;
    for (int p = 0; p < SIDE * SIDE; p++)
        mean += estimate[p] / (SIDE * SIDE);
    double mu = tail.probability * tail.value,
           variance = tail.probability * 4.0 * tail.value * tail.value / 3.0 - mu * mu;
    double truth = variance / (SAMPLES * kept_samples_share) / (mu * mu + 0.01);
    print_message("    %s rule: mean estimated relative MSE %.5f, true %.5f (ratio %.3f)\n",
                  rule == ADAPTIVE_BIASED ? "biased" : "unbiased", mean, truth, mean / truth);
    assert_true(fabs(mean / truth - 1.0) < 0.15);
    free(pixels);
    free(estimate);
    free(to_add);
    scene_free(&scene);
}

static void test_estimate_matches_the_true_error(void **state)
{
    check_estimate(ADAPTIVE_BIASED, 1.0);   /* keeps all n samples */
    check_estimate(ADAPTIVE_UNBIASED, 0.5); /* keeps B: n / 2 */
}

/* Each pixel's mean over SEEDS adaptive renders against mu; returns the agreement and
 * the mean relative bias over the pixels and seeds with its standard error. Each pixel is
 * an image of its own, 1 x 1, so that its window is itself and the pixels are independent. */
static Agreement agreement_over_seeds(AdaptiveRule rule, double *bias, double *bias_error)
{
    enum {
        SIDE = 8,
        SEEDS = 64,
        PIXELS = SIDE * SIDE
    };
    Scene scene = load_room();
    HeavyTail tail = {0.02, 2.5};
    double mu = tail.probability * tail.value;
    AdaptiveSettings settings = {rule, 64, 1024, 8, 0.001};
    double sum[PIXELS] = {0}, squares[PIXELS] = {0}, total = 0.0, total_squares = 0.0;
    for (int p = 0; p < PIXELS; p++)
        for (int seed = 0; seed < SEEDS; seed++) {
            ImageSettings image = {1, 1, 0, PIXEL_RANDOM, (uint64_t)(p * SEEDS + seed)};
            AdaptivePixel pixel = {0};
            double estimate;
            RayCounts counts = {0, 0, 0};
            assert_int_equal(adaptive_render(&scene, &image, heavy_tail, &tail, &settings,
                                             &pixel, &estimate, &counts),
                             0);
            assert_true(pixel.samples >= settings.min_samples);
            assert_true(pixel.samples <= settings.max_samples);
            double x = adaptive_pixel_value(&pixel, rule).x;
            sum[p] += x;
            squares[p] += x * x;
            total += x;
            total_squares += x * x;
        }
    Image mean = image_new(SIDE, SIDE), std_error = image_new(SIDE, SIDE),
          truth = image_new(SIDE, SIDE), exact = image_new(SIDE, SIDE);
    assert_non_null(mean.pixels);
    assert_non_null(std_error.pixels);
    assert_non_null(truth.pixels);
    assert_non_null(exact.pixels);
    for (int p = 0; p < PIXELS; p++) {
        double m = sum[p] / SEEDS, var = (squares[p] - SEEDS * m * m) / (SEEDS - 1);
        for (int c = 0; c < 3; c++) {
            mean.pixels[3 * p + c] = (float)m;
            std_error.pixels[3 * p + c] = (float)sqrt(fmax(var, 0.0) / SEEDS);
            truth.pixels[3 * p + c] = (float)mu;
        }
    }
    Agreement agreement = agreement_test(&mean, &std_error, &truth, &exact, 0.01);
    double m = total / (PIXELS * SEEDS);
    *bias = m / mu - 1.0;
    *bias_error = sqrt((total_squares / (PIXELS * SEEDS) - m * m) / (PIXELS * SEEDS - 1)) / mu;
    image_free(&mean);
    image_free(&std_error);
    image_free(&truth);
    image_free(&exact);
    scene_free(&scene);
    return agreement;
}

static void test_unbiased_rule_agrees_and_biased_rule_does_not(void **state)
{
    double bias, bias_error;
    Agreement unbiased = agreement_over_seeds(ADAPTIVE_UNBIASED, &bias, &bias_error);
    agreement_print("unbiased rule (decide from A, keep B), 64 seeds, against mu", &unbiased);
    print_message("    unbiased rule: image mean / mu - 1 = %+.4f +- %.4f\n", bias, bias_error);
    assert_true(agreement_holds(&unbiased));
    Agreement biased = agreement_over_seeds(ADAPTIVE_BIASED, &bias, &bias_error);
    agreement_print("biased rule (decide and keep all samples), 64 seeds, against mu", &biased);
    print_message("    biased rule: image mean / mu - 1 = %+.4f +- %.4f\n", bias, bias_error);
    assert_false(agreement_holds(&biased));
    assert_true(bias < -4.0 * bias_error); /* dark pixels come out darker */
}

static void test_rule_stops(void **state)
{
    AdaptiveSettings settings = {ADAPTIVE_UNBIASED, 16, 64, 12, 0.01};
    assert_int_equal(adaptive_samples_to_add(&settings, 0, 0.0), 16);
    assert_int_equal(adaptive_samples_to_add(&settings, 4, 1.0), 12);
    assert_int_equal(adaptive_samples_to_add(&settings, 16, 0.01), 0);
    assert_int_equal(adaptive_samples_to_add(&settings, 16, 0.02), 12);
    assert_int_equal(adaptive_samples_to_add(&settings, 52, 1.0), 12);
    assert_int_equal(adaptive_samples_to_add(&settings, 60, 1.0), 4);
    assert_int_equal(adaptive_samples_to_add(&settings, 64, 1.0), 0);
    /* Any path of the rule stays within [min, max] and ends. */
    Rng rng = rng_for_sample(3, 0, 0);
    for (int trial = 0; trial < 1000; trial++) {
        int samples = 0, passes = 0, added;
        while ((added = adaptive_samples_to_add(&settings, samples, 0.02 * rng_uniform(&rng))) >
               0) {
            samples += added;
            passes++;
            assert_true(samples <= settings.max_samples);
            assert_true(passes <= 64);
        }
        assert_true(samples >= settings.min_samples);
    }
    /* A noiseless image: every pixel takes the minimum and no more. */
    Scene scene = load_room();
    HeavyTail constant = {0.0, 1.0}; /* every sample 0 */
    ImageSettings image = {6, 6, 0, PIXEL_RANDOM, 1};
    AdaptivePixel pixels[36] = {0};
    double estimate[36];
    RayCounts counts = {0, 0, 0};
    assert_int_equal(adaptive_render(&scene, &image, heavy_tail, &constant, &settings, pixels,
                                     estimate, &counts),
                     0);
    for (int p = 0; p < 36; p++) {
        assert_int_equal(pixels[p].samples, settings.min_samples);
        assert_true(estimate[p] == 0.0);
    }
    scene_free(&scene);
}

typedef struct {
    long *nonfinite_returned; /* counts what it returns that is not finite */
} Spoiler;

/* An Estimator: NaN with probability 0.1, +infinity with 0.1, else 0.5. */
static Vec3 spoiled(const Scene *scene, Ray ray, Rng *rng, const void *settings,
                    RayCounts *counts)
{
    const Spoiler *spoiler = settings;
    double u = rng_uniform(rng), x = u < 0.1 ? NAN : u < 0.2 ? INFINITY : 0.5;
    *spoiler->nonfinite_returned += !isfinite(x);
    return vec3(x, x, x);
}

static void test_nonfinite_samples_are_dropped_and_counted(void **state)
{
    enum {
        SIDE = 8,
        SAMPLES = 64
    };
    Scene scene = load_room();
    long returned = 0;
    Spoiler spoiler = {&returned};
    ImageSettings image = {SIDE, SIDE, 0, PIXEL_RANDOM, 5};
    AdaptivePixel pixels[SIDE * SIDE] = {0};
    int to_add[SIDE * SIDE];
    double estimate[SIDE * SIDE];
    for (int p = 0; p < SIDE * SIDE; p++)
        to_add[p] = SAMPLES;
    RayCounts counts = {0, 0, 0};
    uint64_t dropped = adaptive_sample_rows(&scene, &image, spoiled, &spoiler, pixels, to_add,
                                            0, SIDE, &counts);
    assert_true(returned > SIDE * SIDE * SAMPLES / 10); /* the test does spoil samples */
    assert_int_equal(dropped, returned);
    long in_pixels = 0;
    for (int p = 0; p < SIDE * SIDE; p++)
        for (int q = 0; q < 4; q++)
            in_pixels += pixels[p].dropped[q];
    assert_int_equal(in_pixels, returned);
    for (int rule = ADAPTIVE_BIASED; rule <= ADAPTIVE_UNBIASED; rule++) {
        AdaptiveSettings settings = {rule, 4, SAMPLES, 4, 0.0};
        assert_true(adaptive_plan(&settings, pixels, SIDE, SIDE, estimate, to_add) >= 0);
        for (int p = 0; p < SIDE * SIDE; p++) {
            Vec3 value = adaptive_pixel_value(&pixels[p], rule);
            assert_true(vec3_is_finite(value));
            assert_true(value.x == 0.5 && value.y == 0.5 && value.z == 0.5);
            assert_true(isfinite(estimate[p]) && estimate[p] == 0.0);
        }
    }
    scene_free(&scene);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_estimate_matches_the_true_error),
        cmocka_unit_test(test_unbiased_rule_agrees_and_biased_rule_does_not),
        cmocka_unit_test(test_rule_stops),
        cmocka_unit_test(test_nonfinite_samples_are_dropped_and_counted),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
