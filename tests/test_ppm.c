/* test_ppm.c (chapter 8): Tests of progressive photon mapping's pass loop (bench/ppm.c, chapter 8). Whether the
 * passes converge to the path tracer's image is tested in test_caustic_path.c; here:
 *
 * - the radius schedule r_i^2 = r_1^2 i^(alpha - 1): with alpha = 2/3, r_8^2 = r_1^2 / 2
 *   and r_27^2 = r_1^2 / 3;
 * - the same image, bit for bit, for any number of threads (each pass's photons and
 *   samples have their own seeds), and a different one for another seed;
 * - the standard error from the spread between passes: in the room without mirrors
 *   and glass the passes are plain path-traced images of 4 samples, so 32 of them
 *   must have the standard error of one render of 128 samples, whose own comes from
 *   the spread between samples: the RMS over pixels of the two agree within 5% (it
 *   measured 1.004; a standard error of one pass instead of their mean gives 5.7, and
 *   the same seed for every pass 0); and the image's mean agrees with that render's;
 * - the passes asked for are rendered, and a time budget too small for two passes
 *   gives exactly one;
 * - progressive pixel sampling (PIXEL_PROGRESSIVE, render_from) continues each pixel's
 *   samples from pass to pass, so that all the passes together are stratified.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <string.h>

#include "renderer.h"
#include "check.h"
#include "measure.h"
#include "path_roulette.h"
#include "ppm.h"
#include "scene_file.h"

static const PathSettings CHAPTER7 = {.max_depth = 64, .shadow_rays = 4, .fresnel = FRESNEL_EXACT,
                                      .rr_survival = 0.75};

static void load_room(Scene *scene)
{
    char error[256];
    assert_int_equal(scene_load("scenes/room.scene", scene, error, sizeof error), 0);
}

static void test_radius_schedule(void **state)
{
    assert_close(ppm_radius(0.3, PPM_ALPHA, 1), 0.3, 1e-15);
    assert_close(pow(ppm_radius(0.3, PPM_ALPHA, 8), 2), 0.09 / 2, 1e-14);
    assert_close(pow(ppm_radius(0.3, PPM_ALPHA, 27), 2), 0.09 / 3, 1e-14);
    assert_close(ppm_radius(0.3, 1.0, 1000), 0.3, 1e-15); /* alpha = 1: no shrinking */
}

static void test_same_image_for_any_thread_count(void **state)
{
    Scene scene;
    load_room(&scene);
    PpmSettings ppm = {CHAPTER7, 5000, 0.2, PPM_ALPHA, 2, 3, 0.0};
    PpmResult results[3];
    const int threads[] = {1, 2, 5};
    for (int i = 0; i < 3; i++) {
        RenderSettings settings = {{24, 24, 1, PIXEL_RANDOM, 8}, threads[i], 0, "test"};
        assert_int_equal(ppm_render(&scene, &settings, &ppm, &results[i]), 0);
        assert_int_equal(results[i].passes, 3);
    }
    size_t bytes = 3 * 24 * 24 * sizeof(float);
    for (int i = 1; i < 3; i++) {
        assert_memory_equal(results[0].render.image.pixels, results[i].render.image.pixels, bytes);
        assert_memory_equal(results[0].render.std_error.pixels, results[i].render.std_error.pixels, bytes);
        assert_true(results[0].stored == results[i].stored);
    }
    assert_true(results[0].stored > 0.0);
    assert_close(results[0].radius, ppm_radius(0.2, PPM_ALPHA, 3), 1e-15);
    RenderSettings other = {{24, 24, 1, PIXEL_RANDOM, 9}, 2, 0, "test"};
    PpmResult different;
    assert_int_equal(ppm_render(&scene, &other, &ppm, &different), 0);
    assert_true(memcmp(results[0].render.image.pixels, different.render.image.pixels, bytes) != 0);
    for (int i = 0; i < 3; i++)
        ppm_result_free(&results[i]);
    ppm_result_free(&different);
    scene_free(&scene);
}

static void test_standard_error_from_passes(void **state)
{
    Scene scene;
    load_room(&scene);
    for (int i = 0; i < scene.material_count; i++)
        if (scene.materials[i].kind == MATERIAL_MIRROR || scene.materials[i].kind == MATERIAL_GLASS) {
            scene.materials[i].kind = MATERIAL_LAMBERT;
            scene.materials[i].reflectance = vec3(0.75, 0.75, 0.75);
        }
    RenderSettings passes = {{20, 20, 1, PIXEL_RANDOM, 3}, 0, 0, "test"};
    PpmSettings ppm = {CHAPTER7, 1000, 0.2, PPM_ALPHA, 4, 32, 0.0};
    PpmResult progressive;
    assert_int_equal(ppm_render(&scene, &passes, &ppm, &progressive), 0);
    assert_int_equal(progressive.passes, 32);
    assert_int_equal(progressive.render.samples, 32 * 4 * 20 * 20);
    RenderSettings once = {{20, 20, 128, PIXEL_RANDOM, 4}, 0, 0, "test"};
    RenderResult single;
    assert_int_equal(render(&scene, &once, path_roulette_radiance, &CHAPTER7, &single), 0);
    double ratio = measure_rms(&progressive.render.std_error) / measure_rms(&single.std_error);
    double mean_a, error_a, mean_b, error_b;
    measure_image_mean(&progressive.render.image, &progressive.render.std_error, &mean_a, &error_a);
    measure_image_mean(&single.image, &single.std_error, &mean_b, &error_b);
    print_message("    RMS standard error: passes / samples = %.4f; means %.5f +- %.5f and %.5f +- %.5f\n",
                  ratio, mean_a, error_a, mean_b, error_b);
    assert_true(fabs(ratio - 1.0) < 0.05);
    assert_true(fabs(mean_a - mean_b) < 4 * sqrt(error_a * error_a + error_b * error_b));
    ppm_result_free(&progressive);
    render_result_free(&single);
    scene_free(&scene);
}

static void test_time_budget(void **state)
{
    Scene scene;
    load_room(&scene);
    RenderSettings settings = {{8, 8, 1, PIXEL_RANDOM, 1}, 0, 0, "test"};
    PpmSettings ppm = {CHAPTER7, 1000, 0.2, PPM_ALPHA, 1, 1000, 1e-9};
    PpmResult result;
    assert_int_equal(ppm_render(&scene, &settings, &ppm, &result), 0);
    assert_int_equal(result.passes, 1); /* always one; a second would overrun */
    ppm_result_free(&result);
    scene_free(&scene);
}

/* Where each sample of a one-pixel image looks (the point of the image plane its
 * camera ray crosses, in [0, 1)^2) and the first pair it draws. */
typedef struct {
    double position[64][2], pair[64][2];
    int count;
} Samples;
typedef struct {
    Samples *out;
} Recorder;

static Vec3 record_sample(const Scene *scene, Ray ray, Rng *rng, const void *settings,
                          RayCounts *counts)
{
    Samples *s = ((const Recorder *)settings)->out;
    const Camera *c = &scene->camera;
    Vec3 normal = vec3_cross(c->right, c->up);
    double t = vec3_dot(vec3_sub(c->bottom_left, c->eye), normal) / vec3_dot(ray.dir, normal);
    Vec3 q = vec3_sub(vec3_add_scaled(c->eye, ray.dir, t), c->bottom_left);
    assert_true(s->count < 64);
    s->position[s->count][0] = vec3_dot(q, c->right) / vec3_dot(c->right, c->right);
    s->position[s->count][1] = vec3_dot(q, c->up) / vec3_dot(c->up, c->up);
    rng_pair(rng, &s->pair[s->count][0], &s->pair[s->count][1]);
    s->count++;
    return vec3(0, 0, 0);
}

/* The number of the 8 x 8 cells of [0, 1)^2 that hold none of the 64 points. */
static int empty_cells(double points[64][2])
{
    int seen[64] = {0}, empty = 0;
    for (int i = 0; i < 64; i++) {
        int cu = (int)(points[i][0] * 8), cv = (int)(points[i][1] * 8);
        assert_true(cu >= 0 && cu < 8 && cv >= 0 && cv < 8);
        seen[cv * 8 + cu]++;
    }
    for (int k = 0; k < 64; k++)
        empty += seen[k] == 0;
    return empty;
}

/* Eight passes of eight samples (first samples 0, 8, ..., 56) of a one-pixel image:
 * their 64 positions, and their 64 first pairs, put one point in each cell of the
 * pixel's 8 x 8 grid (the first 2^6 points of a (0,2)-sequence, sobol.h), for three
 * seeds. Passes of independent samples leave about 64/e = 23.5 cells empty (shown to
 * fail with every pass starting at sample 0: 56 cells empty). */
static void test_progressive_passes_stratify_together(void **state)
{
    Scene scene;
    load_room(&scene);
    for (uint64_t seed = 1; seed <= 3; seed++) {
        Samples samples = {.count = 0};
        Recorder recorder = {&samples};
        RenderSettings settings = {{1, 1, 8, PIXEL_PROGRESSIVE, seed}, 1, 0, "test"};
        for (int pass = 0; pass < 8; pass++) {
            RenderResult result;
            assert_int_equal(render_from(&scene, &settings, 8 * pass, record_sample, &recorder,
                                         &result), 0);
            render_result_free(&result);
        }
        assert_int_equal(samples.count, 64);
        int empty_positions = empty_cells(samples.position), empty_pairs = empty_cells(samples.pair);
        print_message("    seed %d: empty cells %d (positions), %d (pairs)\n", (int)seed,
                      empty_positions, empty_pairs);
        assert_int_equal(empty_positions, 0);
        assert_int_equal(empty_pairs, 0);
    }
    scene_free(&scene);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_radius_schedule),
        cmocka_unit_test(test_same_image_for_any_thread_count),
        cmocka_unit_test(test_standard_error_from_passes),
        cmocka_unit_test(test_time_budget),
        cmocka_unit_test(test_progressive_passes_stratify_together),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
