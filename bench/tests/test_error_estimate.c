/* test_error_estimate.c (bench, chapter 7): the error estimated from an image's own samples
 * and the render to a target error or a time limit (error_estimate.h, --target-error,
 * --time).
 *
 * - Known noise: halves made of a known image plus Gaussian noise of a known, different
 *   spread in every pixel; the estimate matches the true relative MSE (known in closed
 *   form, and as measured against the known image) within its own standard error, and
 *   over many images its standard error is the spread of the estimates.
 * - A real render of scenes/room.scene, small, against a reference rendered here with 32
 *   times its samples: the estimate agrees with the error measured against the reference.
 * - The stops: by error (the estimate reached is at most the target), by time (a render with
 *   a time limit stops and says so; the rule is checked on given times, never timed), and
 *   the programs' flags (bad values refused, naming the flag) and their lines.
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
#include <unistd.h>

#include "error_estimate.h"
#include "path_final.h"
#include "render_batches.h"
#include "run_command.h"
#include "scene_file.h"
#include "sphere_guide.h"
#include "test_random.h"
#if CHAPTER >= 8
#include "ppm.h"
#endif

/* A standard normal number (Box and Muller). */
static double test_normal(TestRandom *random)
{
    double u1 = 1.0 - test_uniform(random), u2 = test_uniform(random);
    return sqrt(-2.0 * log(u1)) * cos(2.0 * PI * u2);
}

enum {
    SIDE = 64,
    MOST_PASSES = 100 /* a render that never reaches its target fails, rather than hangs */
};

/* Pixel p's channel c: its truth (from dark to bright, where the 0.01 matters and where it
 * does not) and the standard deviation of each half's noise. */
static double truth_of(long p, int c)
{
    return 0.02 + 1.5 * (double)((p * 7 + c * 13) % 97) / 97;
}
static double sigma_of(long p, int c)
{
    return 0.01 + 0.2 * (double)((p * 11 + c * 5) % 53) / 53;
}

/* Halves a and b of image seed `seed`; the true relative MSE of F = (a + b) / 2 in
 * expectation (sigma^2 / 2 over truth^2 + 0.01) and as drawn (against the truth). */
static void noisy_halves(uint64_t seed, Image *a, Image *b, double *expected, double *drawn)
{
    *a = image_new(SIDE, SIDE);
    *b = image_new(SIDE, SIDE);
    assert_non_null(a->pixels);
    assert_non_null(b->pixels);
    TestRandom random = test_random(seed, 37, 0);
    double sum_expected = 0.0, sum_drawn = 0.0;
    for (long p = 0; p < SIDE * SIDE; p++)
        for (int c = 0; c < 3; c++) {
            double truth = truth_of(p, c), sigma = sigma_of(p, c),
                   weight = truth * truth + 0.01;
            double x = truth + sigma * test_normal(&random),
                   y = truth + sigma * test_normal(&random);
            a->pixels[3 * p + c] = (float)x;
            b->pixels[3 * p + c] = (float)y;
            sum_expected += sigma * sigma / 2.0 / weight;
            sum_drawn += ((x + y) / 2.0 - truth) * ((x + y) / 2.0 - truth) / weight;
        }
    *expected = sum_expected / (3.0 * SIDE * SIDE);
    *drawn = sum_drawn / (3.0 * SIDE * SIDE);
}

static void test_known_noise(void **state)
{
    Image a, b;
    double expected, drawn;
    noisy_halves(1, &a, &b, &expected, &drawn);
    RelativeError estimate = error_estimate_halves(&a, &b);
    /* Its standard error is a few percent of it at 4096 pixels, not a bound that anything
     * meets. */
    assert_true(estimate.std_error > 0.0 && estimate.std_error < 0.05 * estimate.rel_mse);
    if (fabs(estimate.rel_mse - expected) > 3.0 * estimate.std_error)
        fail_msg("estimate %g +- %g, true relative MSE %g (in expectation)", estimate.rel_mse,
                 estimate.std_error, expected);
    if (fabs(estimate.rel_mse - drawn) > 3.0 * estimate.std_error)
        fail_msg("estimate %g +- %g, true relative MSE %g (as drawn)", estimate.rel_mse,
                 estimate.std_error, drawn);
    /* The same sums through HalfImages, passes added in turn. */
    HalfImages halves;
    assert_int_equal(half_images_begin(&halves, SIDE, SIDE), 0);
    half_images_add(&halves, &a, 3.0);
    half_images_add(&halves, &b, 3.0);
    RelativeError summed = half_images_estimate(&halves);
    assert_true(fabs(summed.rel_mse - estimate.rel_mse) < 1e-6 * estimate.rel_mse);
    Image mean = image_new(SIDE, SIDE);
    half_images_mean(&halves, &mean);
    assert_true(fabs(mean.pixels[5] - (a.pixels[5] + b.pixels[5]) / 2.0) < 1e-6);
    image_free(&mean);
    half_images_free(&halves);
    image_free(&a);
    image_free(&b);
}

/* Over IMAGES images, the estimates' z-scores against the expectation: mean near 0 (no
 * bias) and mean square near 1 (the standard error it gives is its spread). */
#define IMAGES 60
/* The oracle's gain: 1 where every pixel's variance is the same (at any scale), and
 * mean(e) / mean(sqrt e)^2 for a tenth of the pixels 100 times as variable as the rest:
 * (0.1 * 100 + 0.9) / (0.1 * 10 + 0.9)^2 = 10.9 / 3.61. */
static void test_allocation_gain(void **state)
{
    (void)state;
    Image image = image_new(10, 8), std_error = image_new(10, 8), small = image_new(4, 4);
    for (long p = 0; p < 80; p++)
        for (int c = 0; c < 3; c++) {
            image.pixels[3 * p + c] = (float)(0.2 + 0.3 * c); /* its own weight per channel */
            std_error.pixels[3 * p + c] =
                (float)(0.01 * sqrt(image.pixels[3 * p + c] * image.pixels[3 * p + c] + 0.01));
        }
    assert_true(fabs(error_allocation_gain(&image, &std_error) - 1.0) < 1e-9);
    for (long p = 0; p < 80; p += 10)
        for (int c = 0; c < 3; c++)
            std_error.pixels[3 * p + c] *= 10.0f;
    double gain = error_allocation_gain(&image, &std_error);
    print_message("a tenth of the pixels 100 times as variable: gain %.6f, exactly %.6f\n",
                  gain, 10.9 / 3.61);
    assert_true(fabs(gain - 10.9 / 3.61) < 1e-5);
    assert_true(isnan(error_allocation_gain(&image, &small)));
    image_free(&small);
    small = image_new(10, 8); /* all zero: no variance */
    assert_true(isnan(error_allocation_gain(&image, &small)));
    image_free(&small);
    image_free(&image);
    image_free(&std_error);
}

static void test_estimate_spread(void **state)
{
    double sum_z = 0.0, sum_z2 = 0.0;
    for (int k = 0; k < IMAGES; k++) {
        Image a, b;
        double expected, drawn;
        noisy_halves(100 + (uint64_t)k, &a, &b, &expected, &drawn);
        RelativeError estimate = error_estimate_halves(&a, &b);
        double z = (estimate.rel_mse - expected) / estimate.std_error;
        sum_z += z;
        sum_z2 += z * z;
        image_free(&a);
        image_free(&b);
    }
    double mean_z = sum_z / IMAGES, mean_z2 = sum_z2 / IMAGES;
    if (fabs(mean_z) > 4.0 / sqrt(IMAGES) || mean_z2 < 0.5 || mean_z2 > 1.6)
        fail_msg("z-scores of %d estimates: mean %.3f, mean square %.3f (expected 0 and 1)",
                 IMAGES, mean_z, mean_z2);
}

/* The room, small, with the reference program's estimator. */
typedef struct {
    Scene scene;
    MirrorPlanes mirrors;
    PathSettings path;
    RenderSettings settings;
} Room;

static void room_begin(Room *room, int width)
{
    char error[512];
    if (scene_load("scenes/room.scene", &room->scene, error, sizeof error) != 0)
        fail_msg("%s", error);
    assert_int_equal(mirror_light_find_planes(&room->scene, &room->mirrors), 0);
    room->path = (PathSettings){.max_depth = 64,
                                .shadow_rays = 1,
                                .rr_throughput = 1,
                                .mirror_light = 64,
                                .mirrors = &room->mirrors,
                                .sphere_guide = SPHERE_GUIDE_STRENGTH};
    room->settings = (RenderSettings){0};
    room->settings.image.width = width;
    room->settings.image.height = (int)lround(width / scene_file_aspect(&room->scene.camera));
    room->settings.image.sampling = PIXEL_SUBPIXELS;
    room->settings.label = "test";
}

static void room_end(Room *room)
{
    mirror_planes_free(&room->mirrors);
    scene_free(&room->scene);
}

#define ROOM_WIDTH 20
#define ROOM_TARGET 0.08
static void test_room_against_reference(void **state)
{
    Room room;
    room_begin(&room, ROOM_WIDTH);
    TargetSettings target = {ROOM_TARGET, 0.0, 4, 1, MOST_PASSES};
    room.settings.image.seed = 7;
    TargetResult result;
    assert_int_equal(render_to_target(&room.scene, &room.settings, path_final_radiance,
                                      &room.path, &target, &result),
                     0);
    assert_int_equal(result.stop, TARGET_REACHED);
    assert_true(sqrt(result.estimate.rel_mse) <= ROOM_TARGET);
    double spp = render_samples_per_pixel(&result.render);
    RenderResult rendered;
    RenderSettings reference_settings = room.settings;
    reference_settings.image.seed = 1234567;
    reference_settings.image.spp = 32 * 8 * ((int)ceil(spp / 8.0));
    assert_int_equal(render_batches(&room.scene, &reference_settings, 8, path_final_radiance,
                                    &room.path, &rendered),
                     0);
    Reference reference = {.image = rendered.image, .std_error = rendered.std_error};
    RelativeError against = error_against_reference(&result.render.image, &reference);
    double difference = result.estimate.rel_mse - against.rel_mse;
    double spread = sqrt(result.estimate.std_error * result.estimate.std_error +
                         against.std_error * against.std_error);
    print_message("room %d px, %.0f spp: estimated %.3f %% +- %.3f, against the reference %.3f "
                  "%% +- %.3f\n",
                  ROOM_WIDTH, spp, error_percent(result.estimate.rel_mse),
                  error_percent_std_error(&result.estimate), error_percent(against.rel_mse),
                  error_percent_std_error(&against));
    if (fabs(difference) > 3.0 * spread)
        fail_msg("estimated relative MSE %g, against the reference %g: %.1f standard errors",
                 result.estimate.rel_mse, against.rel_mse, difference / spread);
    render_result_free(&rendered);
    render_result_free(&result.render);
    room_end(&room);
}

/* A pixel's value: a uniform number (noise of known spread, 1/12 per sample). */
static Vec3 noise(const Scene *scene, Ray ray, Rng *rng, const void *settings,
                  RayCounts *counts)
{
    double u = rng_uniform(rng);
    counts->camera++;
    return vec3(u, 0.5 + u, 2.0 * u);
}

static Scene tiny_scene(void)
{
    Scene scene;
    scene_init(&scene);
    scene.camera = camera_make(vec3(0, 0, 0), vec3(-1, -1, 1), vec3(1, -1, 1), vec3(-1, 1, 1));
    return scene;
}

static RenderSettings tiny_settings(void)
{
    return (RenderSettings){{16, 16, 1, PIXEL_RANDOM, 3}, 1, 0, "test"};
}

static void test_stop_by_error(void **state)
{
    Scene scene = tiny_scene();
    RenderSettings settings = tiny_settings();
    const double targets[] = {0.2, 0.05, 0.02};
    for (int i = 0; i < 3; i++) {
        TargetSettings target = {targets[i], 0.0, 2, 1, MOST_PASSES};
        TargetResult result;
        assert_int_equal(render_to_target(&scene, &settings, noise, NULL, &target, &result), 0);
        assert_int_equal(result.stop, TARGET_REACHED);
        assert_true(result.passes >= 2 && result.passes % 2 == 0);
        assert_true(sqrt(result.estimate.rel_mse) <= targets[i]);
        /* Not far past it either, once each pair adds an eighth of the samples. */
        if (i > 0)
            assert_true(sqrt(result.estimate.rel_mse) > 0.8 * targets[i]);
        assert_int_equal(result.render.samples,
                         (uint64_t)(render_samples_per_pixel(&result.render) * 256 + 0.5));
        render_result_free(&result.render);
    }
    /* Nothing to stop it: refused. */
    TargetSettings endless = {0.0, 0.0, 2, 1, 0};
    TargetResult result;
    assert_int_equal(render_to_target(&scene, &settings, noise, NULL, &endless, &result), -1);
    scene_free(&scene);
}

static void test_stop_by_time(void **state)
{
    Scene scene = tiny_scene();
    RenderSettings settings = tiny_settings();
    TargetSettings target = {1e-9, 0.2, 2, 1, 0};
    TargetResult result;
    assert_int_equal(render_to_target(&scene, &settings, noise, NULL, &target, &result), 0);
    assert_int_equal(result.stop, TARGET_TIME_UP);
    assert_true(result.passes >= 2 && result.passes % 2 == 0);
    assert_true(result.estimate.rel_mse > 0.0);
    char line[512];
    target_describe(&target, &result.estimate, NULL, result.stop, result.render.seconds,
                    render_samples_per_pixel(&result.render), 1e6, result.passes, line,
                    sizeof line);
    assert_non_null(strstr(line, "(time up)"));
    assert_non_null(strstr(line, "stopped at"));
    render_result_free(&result.render);
    scene_free(&scene);
}

/* The time rule on given times: a pair is started only if it fits. */
static void test_time_rule(void **state)
{
    RelativeError far = {1.0, 0.1};
    TargetSettings fixed = {0.01, 10.0, 4, 0, 0}, growing = fixed;
    growing.grow = 1;
    int next = -1;
    TargetStop stop;
    /* 1 s for 16 spp: a pair of 4 takes 0.5 s. */
    assert_false(target_should_stop(&fixed, &far, 2, 1.0, 16.0, &next, &stop));
    assert_int_equal(next, 4);
    assert_true(target_should_stop(&fixed, &far, 2, 9.6, 16.0, &next, &stop));
    assert_int_equal(stop, TARGET_TIME_UP);
    /* Growing: an eighth of 320 spp, 20 per pass; with 1 s left at 0.05 s a sample, 10. */
    assert_false(target_should_stop(&growing, &far, 8, 1.0, 320.0, &next, &stop));
    assert_int_equal(next, 20);
    assert_false(target_should_stop(&growing, &far, 8, 9.0, 180.0, &next, &stop));
    assert_int_equal(next, 10);
    /* Reached wins; a most-passes limit stops too. */
    RelativeError near = {0.5e-4, 0.0};
    assert_true(target_should_stop(&fixed, &near, 2, 9.9, 16.0, &next, &stop));
    assert_int_equal(stop, TARGET_REACHED);
    TargetSettings few = {0.01, 0.0, 4, 0, 4};
    assert_true(target_should_stop(&few, &far, 4, 1.0, 16.0, &next, &stop));
    assert_int_equal(stop, TARGET_MOST_PASSES);
}

#if CHAPTER >= 8
/* The photon map in pairs of passes: stops at the target, with an even pass count. */
static void test_photon_map_to_target(void **state)
{
    Room room;
    room_begin(&room, 16);
    room.path.mirror_light = 1;
    room.settings.image.spp = 2;
    room.settings.image.sampling = PIXEL_STRATIFIED;
    room.settings.image.seed = 5;
    PpmSettings ppm = {
        room.path, 200, ppm_first_radius(&room.scene, PPM_FIRST_RADIUS_AT_800) * 50,
        PPM_ALPHA, 2,   MOST_PASSES,
        0.0,       0.3, 0.0};
    PpmResult result;
    assert_int_equal(ppm_render(&room.scene, &room.settings, &ppm, &result), 0);
    assert_int_equal(result.stop, TARGET_REACHED);
    assert_true(result.passes % 2 == 0 && sqrt(result.estimate.rel_mse) <= 0.3);
    ppm_result_free(&result);
    room_end(&room);
}
#endif

/* The programs: bad values refused, naming the flag; a render with --time stops and says
 * so; one with --target-error reaches it and says so. */
static void test_programs(void **state)
{
    const char *directory = getenv("CHAPTER_DIR") ? getenv("CHAPTER_DIR") : "build";
    const char *bad[][3] = {
        {"--target-error", "0", "--target-error: expected a number in (0, 1), got '0'"},
        {"--target-error", "1", "--target-error: expected a number in (0, 1), got '1'"},
        {"--target-error", "-0.1", "--target-error: expected a number in (0, 1), got '-0.1'"},
        {"--target-error", "nan", "--target-error: 'nan' is not a decimal number"},
        {"--target-error", "1e-310", "--target-error: '1e-310' is too small"},
        {"--time", "0", "--time: expected a number of seconds above 0, got '0'"},
        {"--time", "-3", "--time: expected a number of seconds above 0, got '-3'"},
        {"--time", "inf", "--time: 'inf' is not a decimal number"},
        {"--time", "1e400", "--time: '1e400' is too large for a double"},
        {"--time", "", "--time: expected a number of seconds above 0, got an empty word"},
    };
    char command[1024], *output;
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        snprintf(command, sizeof command, "%s/ch07_final %s '%s' --help 2>&1", directory,
                 bad[i][0], bad[i][1]);
        int status = run_command(command, &output);
        if (status != 2 || !strstr(output, bad[i][2]))
            fail_msg("%s %s: status %d, '%s' (expected '%s')", bad[i][0], bad[i][1], status,
                     output, bad[i][2]);
        free(output);
    }
    snprintf(command, sizeof command,
             "%s/reference --scene scenes/room.scene --size 8 --reference-spp 8 --depth 2 "
             "--out /tmp --key 1 --time 0 2>&1",
             directory);
    assert_int_equal(run_command(command, &output), 2);
    assert_non_null(strstr(output, "--time: expected a number of seconds above 0"));
    free(output);
    const char *takers[] = {"ch07_final", "ch08_photon_map", "ch09_fast"};
    for (int i = 0; i < 3 && i <= CHAPTER - 7; i++) {
        snprintf(command, sizeof command, "%s/%s --help", directory, takers[i]);
        assert_int_equal(run_command(command, &output), 0);
        assert_non_null(strstr(output, "--target-error"));
        assert_non_null(strstr(output, "--time"));
        free(output);
    }
    char out_dir[] = "/tmp/test_error_estimate_XXXXXX";
    assert_non_null(mkdtemp(out_dir));
    snprintf(command, sizeof command,
             "%s/ch07_final --size 16 --reference-spp 16 --quiet --out %s --time 0.5 "
             "--target-error 0.001 2>&1",
             directory, out_dir);
    assert_int_equal(run_command(command, &output), 0);
    if (!strstr(output, "target 0.10 %: stopped at") || !strstr(output, "(time up)") ||
        !strstr(output, "(against the reference)"))
        fail_msg("--time 0.5: %s", output);
    free(output);
    snprintf(command, sizeof command, "%s/ch07_figure7.png", out_dir);
    assert_int_equal(access(command, F_OK), 0);
    snprintf(command, sizeof command,
             "%s/ch07_final --size 16 --reference-spp 16 --quiet --out %s --target-error 0.3 "
             "2>&1",
             directory, out_dir);
    assert_int_equal(run_command(command, &output), 0);
    if (!strstr(output, "target 30.00 %: reached "))
        fail_msg("--target-error 0.3: %s", output);
    free(output);
    snprintf(command, sizeof command, "rm -rf %s", out_dir);
    assert_int_equal(system(command), 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_known_noise),
        cmocka_unit_test(test_estimate_spread),
        cmocka_unit_test(test_allocation_gain),
        cmocka_unit_test(test_room_against_reference),
        cmocka_unit_test(test_stop_by_error),
        cmocka_unit_test(test_stop_by_time),
        cmocka_unit_test(test_time_rule),
#if CHAPTER >= 8
        cmocka_unit_test(test_photon_map_to_target),
#endif
        cmocka_unit_test(test_programs),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
