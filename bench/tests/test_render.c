/* test_render.c (bench, chapter 1): the threaded renderer (renderer.h) around the pixel
 * sample of the lesson (render_sample, lib/render.h).
 *
 * - Determinism: the room rendered with 1, 2 and 7 threads is the same image bit for
 *   bit (every sample has its own generator, every pixel its own stratum start, and
 *   every pixel sums its samples in order), so a result never depends on the machine.
 *   Chapter 1 renders it with Whitted through each pixel's centre; from chapter 2 on,
 *   also with random positions and with sub-pixels; from chapter 6 on, also with the
 *   path tracer with shadow rays, exact Fresnel and roulette.
 * - The lesson's loop (render_image, lib/render.h, run by render_serial) gives each of
 *   those images bit for bit, and the same ray counts, but on sub-pixels, whose samples
 *   the threaded renderer takes in another order (sample_order.h); from chapter 2 on,
 *   also the path tracer of chapter 2's pictures.
 * - Estimates: with an estimator that returns a known value per sample, each pixel is
 *   the mean of its samples and its standard errors (per channel, and of the channel
 *   mean) are the textbook ones, also for a bright pixel of small spread, where only a
 *   numerically stable update (Welford's) keeps them.
 * - Non-finite samples are dropped and counted (no image may carry a NaN or an
 *   infinity); the pixel is the mean of the others.
 * - An interrupted render (SIGINT) stops early, and every pixel is still the mean of
 *   the samples it actually received.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <signal.h>
#include <string.h>

#include "renderer.h"
#include "scene_file.h"
#include "whitted_estimator.h"
#if CHAPTER >= 2
#include "path.h"
#endif
#if CHAPTER >= 6
#include "path_roulette.h"
#endif

#define SIDE 48

/* The lesson's serial loop renders the same image as `threaded`, bit for bit, with the
 * same ray counts. */
static void assert_lesson_loop_gives(const Scene *scene, const RenderResult *threaded,
                                     ImageSettings image, Estimator estimate,
                                     const void *estimator_settings)
{
    RenderSettings settings = {.image = image, .label = "test"};
    RenderResult lesson;
    assert_int_equal(render_serial(scene, &settings, estimate, estimator_settings, &lesson), 0);
    assert_memory_equal(threaded->image.pixels, lesson.image.pixels,
                        3 * sizeof(float) * (size_t)image.width * (size_t)image.height);
    assert_true(threaded->samples == lesson.samples);
    assert_true(threaded->rays.camera == lesson.rays.camera);
    assert_true(threaded->rays.bounce == lesson.rays.bounce);
    assert_true(threaded->rays.shadow == lesson.rays.shadow);
    render_result_free(&lesson);
}

/* Render `image` (its size SIDE x SIDE) with 1, 2 and 7 threads: the same images bit
 * for bit, and the same ray counts: one camera ray per sample, and bounce and shadow
 * rays (the room has mirrors and a light), counted in full whichever thread traced them;
 * but on sub-pixels, the lesson's loop gives them too. The one-thread result is left in
 * *first. */
static void assert_same_for_any_thread_count(const Scene *scene, ImageSettings image,
                                             Estimator estimate, const void *estimator_settings,
                                             RenderResult *first)
{
    const int threads[] = {1, 2, 7};
    size_t bytes = 3 * SIDE * SIDE * sizeof(float);
    uint64_t samples = (uint64_t)SIDE * SIDE * (uint64_t)image.spp;
    RenderResult results[3];
    for (int i = 0; i < 3; i++) {
        RenderSettings settings = {.image = image, .threads = threads[i], .label = "test"};
        assert_int_equal(render(scene, &settings, estimate, estimator_settings, &results[i]),
                         0);
        assert_int_equal(results[i].threads, threads[i]);
        assert_true(results[i].samples == samples && results[i].rays.camera == samples);
    }
    assert_true(results[0].rays.bounce > 0 && results[0].rays.shadow > 0);
    for (int i = 1; i < 3; i++) {
        assert_memory_equal(results[0].image.pixels, results[i].image.pixels, bytes);
        assert_memory_equal(results[0].std_error.pixels, results[i].std_error.pixels, bytes);
        assert_memory_equal(results[0].average_std_error.pixels,
                            results[i].average_std_error.pixels, bytes);
        assert_true(results[0].rays.bounce == results[i].rays.bounce);
        assert_true(results[0].rays.shadow == results[i].rays.shadow);
        render_result_free(&results[i]);
    }
#if CHAPTER >= 2
    if (!pixel_uses_subpixels(image.sampling))
#endif
        assert_lesson_loop_gives(scene, &results[0], image, estimate, estimator_settings);
    *first = results[0];
}

static void load(const char *path, Scene *scene)
{
    char error[256];
    if (scene_load(path, scene, error, sizeof error) != 0)
        fail_msg("%s", error);
}

/* Whitted through each pixel's centre (chapter 1's only sampling; the default later). */
static void test_same_image_for_any_thread_count(void **state)
{
    Scene scene;
    load("scenes/room_whitted.scene", &scene);
    WhittedSettings whitted = {10};
    ImageSettings image = {.width = SIDE, .height = SIDE, .spp = 3};
    RenderResult first;
    assert_same_for_any_thread_count(&scene, image, whitted_estimate, &whitted, &first);
    render_result_free(&first);
    scene_free(&scene);
}

#if CHAPTER >= 2
/* With random positions and with sub-pixels, `estimate` gives the same image for any
 * thread count; a different seed gives a different image, so the comparison is not
 * vacuous. */
static void assert_sampled_same_for_any_thread_count(const Scene *scene, Estimator estimate,
                                                     const void *estimator_settings)
{
    ImageSettings image = {
        .width = SIDE, .height = SIDE, .spp = 3, .seed = 2019, .sampling = PIXEL_RANDOM};
    RenderResult random, subpixels;
    assert_same_for_any_thread_count(scene, image, estimate, estimator_settings, &random);
    image.sampling = PIXEL_SUBPIXELS;
    assert_same_for_any_thread_count(scene, image, estimate, estimator_settings, &subpixels);
    size_t bytes = 3 * SIDE * SIDE * sizeof(float);
    image.sampling = PIXEL_RANDOM;
    image.seed = 2020;
    RenderSettings other = {.image = image, .threads = 2, .label = "test"};
    RenderResult different;
    assert_int_equal(render(scene, &other, estimate, estimator_settings, &different), 0);
    assert_true(memcmp(random.image.pixels, different.image.pixels, bytes) != 0);
    render_result_free(&random);
    render_result_free(&subpixels);
    render_result_free(&different);
}

/* Whitted at random points of each pixel and on sub-pixels (chapter 2). */
static void test_same_sampled_image_for_any_thread_count(void **state)
{
    Scene scene;
    load("scenes/room_whitted.scene", &scene);
    WhittedSettings whitted = {10};
    assert_sampled_same_for_any_thread_count(&scene, whitted_estimate, &whitted);
    scene_free(&scene);
}
#endif

#if CHAPTER >= 2
/* Chapter 2's path tracer (light by hitting only) at random points of each pixel: the
 * lesson's loop and the threaded renderer on 1, 2 and 3 threads give the same image. */
static void test_lesson_loop_gives_the_path_traced_image(void **state)
{
    Scene scene;
    load("scenes/room.scene", &scene);
    PathSettings path = {.max_depth = 8};
    ImageSettings image = {
        .width = SIDE, .height = SIDE, .spp = 4, .seed = 7, .sampling = PIXEL_RANDOM};
    for (int threads = 1; threads <= 3; threads++) {
        RenderSettings settings = {.image = image, .threads = threads, .label = "test"};
        RenderResult result;
        assert_int_equal(render(&scene, &settings, path_radiance, &path, &result), 0);
        assert_true(result.rays.bounce > 0);
        assert_lesson_loop_gives(&scene, &result, image, path_radiance, &path);
        render_result_free(&result);
    }
    scene_free(&scene);
}
#endif

#if CHAPTER >= 6
/* The path tracer, which draws many numbers per sample and ends paths at random. */
static void test_same_path_traced_image_for_any_thread_count(void **state)
{
    Scene scene;
    load("scenes/room.scene", &scene);
    PathSettings path = {
        .max_depth = 64, .shadow_rays = 1, .fresnel = FRESNEL_EXACT, .rr_survival = 0.5};
    assert_sampled_same_for_any_thread_count(&scene, path_roulette_radiance, &path);
    scene_free(&scene);
}
#endif

#if CHAPTER >= 2
/* (u, 2u, 1) with u the sample's first random number. */
static Vec3 sample_number(const Scene *scene, Ray ray, Rng *rng, const void *settings,
                          RayCounts *counts)
{
    double u = rng_uniform(rng);
    return vec3(u, 2.0 * u, 1.0);
}

/* Each pixel's value and standard errors against the same samples drawn by hand. The
 * channel mean (u + 2u + 1) / 3 = u + 1/3 has the standard error of u itself, which the
 * three channels' errors, taken as independent, would put at sqrt(1 + 4 + 0) / 3 =
 * 0.75 of it. */
static void test_pixel_is_mean_of_samples(void **state)
{
    Scene scene;
    scene_init(&scene);
    scene.camera = camera_make(vec3(0, 0, 0), vec3(-1, -1, 1), vec3(1, -1, 1), vec3(-1, 1, 1));
    /* Through each pixel's centre: the sampling draws no number before the estimator. */
    RenderSettings settings = {.image = {.width = 4, .height = 4, .spp = 5, .seed = 77},
                               .threads = 2,
                               .label = "test"};
    RenderResult result;
    assert_int_equal(render(&scene, &settings, sample_number, NULL, &result), 0);
    for (int pixel = 0; pixel < 16; pixel++) {
        double sum = 0, sum_squares = 0;
        for (int s = 0; s < 5; s++) {
            Rng rng = rng_for_sample(77, (uint64_t)pixel, (uint64_t)s);
            double u = rng_uniform(&rng);
            sum += u;
            sum_squares += u * u;
        }
        double mean = sum / 5, std_error = sqrt((sum_squares - 5 * mean * mean) / 4 / 5);
        Vec3 value = image_get(&result.image, pixel % 4, pixel / 4);
        Vec3 error = image_get(&result.std_error, pixel % 4, pixel / 4);
        assert_true(fabs(value.x - mean) < 1e-6 && fabs(value.y - 2 * mean) < 1e-6);
        assert_true(value.z == 1.0f && error.z == 0.0f);
        assert_true(fabs(error.x - std_error) < 1e-6);
        assert_true(fabs(error.y - 2 * std_error) < 1e-6);
        Vec3 average_error = image_get(&result.average_std_error, pixel % 4, pixel / 4);
        assert_true(fabs(average_error.x - std_error) < 1e-6);
        assert_true(average_error.x == average_error.y && average_error.x == average_error.z);
    }
    assert_true(result.samples == 80 && result.nonfinite == 0 && !result.interrupted);
    render_result_free(&result);
}

/* A bright pixel of small spread: 10^9 + u, with u the sample's first random number;
 * channel 1 is u alone. */
#define BRIGHT 1e9

static Vec3 bright_sample(const Scene *scene, Ray ray, Rng *rng, const void *settings,
                          RayCounts *counts)
{
    double u = rng_uniform(rng);
    return vec3(BRIGHT + u, u, BRIGHT + u);
}

/* Welford's method (renderer.h) keeps the spread of a bright pixel: its standard error
 * is that of u, within 0.1%, computed here by the two-pass formula (mean first, then
 * squared deviations from it). The textbook sum of squares, sum x^2 - n mean^2 with
 * x = 10^9 + u, subtracts numbers near 10^20 whose rounding (about 10^4 each) swamps
 * the variance 1/12: with it the test fails. 200 samples per pixel. */
static void test_variance_of_a_bright_pixel(void **state)
{
    Scene scene;
    scene_init(&scene);
    scene.camera = camera_make(vec3(0, 0, 0), vec3(-1, -1, 1), vec3(1, -1, 1), vec3(-1, 1, 1));
    const int spp = 200;
    RenderSettings settings = {.image = {.width = 4, .height = 4, .spp = spp, .seed = 31},
                               .threads = 2,
                               .label = "test"};
    RenderResult result;
    assert_int_equal(render(&scene, &settings, bright_sample, NULL, &result), 0);
    for (int pixel = 0; pixel < 16; pixel++) {
        double u[200], mean = 0.0, squares = 0.0;
        for (int s = 0; s < spp; s++) {
            Rng rng = rng_for_sample(31, (uint64_t)pixel, (uint64_t)s);
            u[s] = rng_uniform(&rng);
            mean += u[s] / spp;
        }
        for (int s = 0; s < spp; s++)
            squares += (u[s] - mean) * (u[s] - mean);
        double expected = sqrt(squares / (spp - 1) / spp);
        Vec3 error = image_get(&result.std_error, pixel % 4, pixel / 4);
        Vec3 average_error = image_get(&result.average_std_error, pixel % 4, pixel / 4);
        if (pixel == 0)
            print_message("    standard error %.6f, expected %.6f (u alone: %.6f)\n", error.x,
                          expected, error.y);
        assert_true(fabs(error.x - expected) < 1e-3 * expected);
        assert_true(fabs(error.z - expected) < 1e-3 * expected);
        assert_true(fabs(error.y - expected) < 1e-6 * expected);
        assert_true(fabs(average_error.x - expected) < 1e-3 * expected);
    }
    render_result_free(&result);
}

/* Every third sample is NaN or infinite. */
static Vec3 sometimes_nonfinite(const Scene *scene, Ray ray, Rng *rng, const void *settings,
                                RayCounts *counts)
{
    uint32_t r = rng_next(rng) % 3;
    return r == 0 ? vec3(NAN, 1, 1) : r == 1 ? vec3(1, INFINITY, 1) : vec3(0.5, 0.5, 0.5);
}

static void test_nonfinite_samples_dropped_and_counted(void **state)
{
    Scene scene;
    scene_init(&scene);
    scene.camera = camera_make(vec3(0, 0, 0), vec3(-1, -1, 1), vec3(1, -1, 1), vec3(-1, 1, 1));
    RenderSettings settings = {.image = {.width = 8, .height = 8, .spp = 30, .seed = 5},
                               .threads = 2,
                               .label = "test"};
    RenderResult result;
    assert_int_equal(render(&scene, &settings, sometimes_nonfinite, NULL, &result), 0);
    uint64_t expected = 0;
    for (int pixel = 0; pixel < 64; pixel++)
        for (int s = 0; s < 30; s++) {
            Rng rng = rng_for_sample(5, (uint64_t)pixel, (uint64_t)s);
            expected += rng_next(&rng) % 3 != 2;
        }
    assert_true(result.nonfinite == expected && expected > 0);
    for (int i = 0; i < 3 * 64; i++)
        assert_true(result.image.pixels[i] == 0.5f || result.image.pixels[i] == 0.0f);
    render_result_free(&result);
}

#endif

/* Returns 1 per sample, and raises SIGINT during pass 3. */
#if CHAPTER >= 2
static Vec3 interrupt_midway(const Scene *scene, Ray ray, Rng *rng, const void *settings,
                             RayCounts *counts)
#else
static Vec3 interrupt_midway(const Scene *scene, Ray ray, const void *settings,
                             RayCounts *counts)
#endif
{
    const int *pass_to_interrupt = settings;
    static int calls;
    if (++calls == 64 * 64 * *pass_to_interrupt + 100)
        raise(SIGINT);
    return vec3(1, 1, 1);
}

static void test_interrupt_keeps_a_normalised_image(void **state)
{
    Scene scene;
    scene_init(&scene);
    scene.camera = camera_make(vec3(0, 0, 0), vec3(-1, -1, 1), vec3(1, -1, 1), vec3(-1, 1, 1));
    render_install_interrupt();
    RenderSettings settings = {
        .image = {.width = 64, .height = 64, .spp = 1000}, .threads = 1, .label = "test"};
    int pass_to_interrupt = 3;
    RenderResult result;
    assert_int_equal(render(&scene, &settings, interrupt_midway, &pass_to_interrupt, &result),
                     0);
    assert_true(result.interrupted);
    double spp = render_samples_per_pixel(&result);
    print_message("    stopped after %.3f of 1000 samples per pixel\n", spp);
    assert_true(spp > 3.0 && spp < 4.0); /* the row in progress finished, then it stopped */
    for (int i = 0; i < 3 * 64 * 64; i++)
        assert_true(result.image.pixels[i] == 1.0f); /* each pixel: its sum / its count */
    render_result_free(&result);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_same_image_for_any_thread_count),
#if CHAPTER >= 2
        cmocka_unit_test(test_same_sampled_image_for_any_thread_count),
        cmocka_unit_test(test_lesson_loop_gives_the_path_traced_image),
#endif
#if CHAPTER >= 6
        cmocka_unit_test(test_same_path_traced_image_for_any_thread_count),
#endif
#if CHAPTER >= 2
        cmocka_unit_test(test_pixel_is_mean_of_samples),
        cmocka_unit_test(test_variance_of_a_bright_pixel),
        cmocka_unit_test(test_nonfinite_samples_dropped_and_counted),
#endif
        cmocka_unit_test(test_interrupt_keeps_a_normalised_image),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
