/* test_ppm.c (chapter 8): Tests of progressive photon mapping's pass loop (bench/ppm.c, chapter
 * 8). Whether the passes converge to the path tracer's image is tested in test_caustic_path.c;
 * here:
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
 *   gives exactly one; passes of d seconds against a budget B give the number of
 *   passes whose total is nearest B;
 * - progressive pixel sampling (PIXEL_PROGRESSIVE, render_from) continues each pixel's
 *   samples from pass to pass, so that all the passes together are stratified, and are
 *   one render of all their samples; a sample's position is independent of its pairs;
 * - each pass shoots its own photons and gathers them at its own radius: the spread of
 *   a pixel over the passes is the binomial spread of photon counts at the scheduled
 *   radii.
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
#include "path_final.h"
#include "path_roulette.h"
#include "ppm.h"
#include "scene_file.h"

static const PathSettings CHAPTER7 = {
    .max_depth = 64, .shadow_rays = 4, .fresnel = FRESNEL_EXACT, .rr_survival = 0.75};

/* The room; without `specular`, its mirrors and glass made white Lambert. */
static void load_room(Scene *scene, int specular)
{
    char error[256];
    assert_int_equal(scene_load("scenes/room.scene", scene, error, sizeof error), 0);
    for (int i = 0; !specular && i < scene->material_count; i++)
        if (scene->materials[i].kind == MATERIAL_MIRROR ||
            scene->materials[i].kind == MATERIAL_GLASS) {
            scene->materials[i].kind = MATERIAL_LAMBERT;
            scene->materials[i].reflectance = vec3(0.75, 0.75, 0.75);
        }
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
    load_room(&scene, 1);
    PpmSettings ppm = {CHAPTER7, 5000, 0.2, PPM_ALPHA, 2, 3, 0.0, 0.0, 0.0};
    PpmResult results[3];
    const int threads[] = {1, 2, 5};
    for (int i = 0; i < 3; i++) {
        RenderSettings settings = {{24, 24, 1, PIXEL_RANDOM, 8}, threads[i], 0, "test"};
        assert_int_equal(ppm_render(&scene, &settings, &ppm, &results[i]), 0);
        assert_int_equal(results[i].passes, 3);
    }
    size_t bytes = 3 * 24 * 24 * sizeof(float);
    for (int i = 1; i < 3; i++) {
        assert_memory_equal(results[0].render.image.pixels, results[i].render.image.pixels,
                            bytes);
        assert_memory_equal(results[0].render.std_error.pixels,
                            results[i].render.std_error.pixels, bytes);
        assert_true(results[0].stored == results[i].stored);
    }
    assert_true(results[0].stored > 0.0);
    assert_close(results[0].radius, ppm_radius(0.2, PPM_ALPHA, 3), 1e-15);
    RenderSettings other = {{24, 24, 1, PIXEL_RANDOM, 9}, 2, 0, "test"};
    PpmResult different;
    assert_int_equal(ppm_render(&scene, &other, &ppm, &different), 0);
    assert_true(memcmp(results[0].render.image.pixels, different.render.image.pixels, bytes) !=
                0);
    for (int i = 0; i < 3; i++)
        ppm_result_free(&results[i]);
    ppm_result_free(&different);
    scene_free(&scene);
}

static void test_standard_error_from_passes(void **state)
{
    Scene scene;
    load_room(&scene, 0);
    RenderSettings passes = {{20, 20, 1, PIXEL_RANDOM, 3}, 0, 0, "test"};
    PpmSettings ppm = {CHAPTER7, 1000, 0.2, PPM_ALPHA, 4, 32, 0.0, 0.0, 0.0};
    PpmResult progressive;
    assert_int_equal(ppm_render(&scene, &passes, &ppm, &progressive), 0);
    assert_int_equal(progressive.passes, 32);
    assert_int_equal(progressive.render.samples, 32 * 4 * 20 * 20);
    RenderSettings once = {{20, 20, 128, PIXEL_RANDOM, 4}, 0, 0, "test"};
    RenderResult single;
    assert_int_equal(render(&scene, &once, path_roulette_radiance, &CHAPTER7, &single), 0);
    double ratio = measure_rms(&progressive.render.std_error) / measure_rms(&single.std_error);
    double mean_a, error_a, mean_b, error_b;
    measure_image_mean(&progressive.render.image, &progressive.render.std_error, &mean_a,
                       &error_a);
    measure_image_mean(&single.image, &single.std_error, &mean_b, &error_b);
    print_message("    RMS standard error: passes / samples = %.4f; means %.5f +- %.5f and "
                  "%.5f +- %.5f\n",
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
    load_room(&scene, 1);
    RenderSettings settings = {{8, 8, 1, PIXEL_RANDOM, 1}, 0, 0, "test"};
    PpmSettings ppm = {CHAPTER7, 1000, 0.2, PPM_ALPHA, 1, 1000, 1e-9, 0.0, 0.0};
    PpmResult result;
    assert_int_equal(ppm_render(&scene, &settings, &ppm, &result), 0);
    assert_int_equal(result.passes, 1); /* always one; a second would overrun */
    ppm_result_free(&result);
    scene_free(&scene);
}

/* Where each sample of a side x side image looks in its pixel (the point of the image
 * plane its camera ray crosses, in [0, 1)^2 within the pixel) and the first pair it
 * draws, per pixel. */
typedef struct {
    double position[64][2], pair[64][2];
    int count;
} Samples;
typedef struct {
    Samples *out; /* side x side of them */
    int side;
} Recorder;

static Vec3 record_sample(const Scene *scene, Ray ray, Rng *rng, const void *settings,
                          RayCounts *counts)
{
    const Recorder *r = settings;
    const Camera *c = &scene->camera;
    Vec3 normal = vec3_cross(c->right, c->up);
    double t = vec3_dot(vec3_sub(c->bottom_left, c->eye), normal) / vec3_dot(ray.dir, normal);
    Vec3 q = vec3_sub(vec3_add_scaled(c->eye, ray.dir, t), c->bottom_left);
    double u = vec3_dot(q, c->right) / vec3_dot(c->right, c->right) * r->side;
    double v = vec3_dot(q, c->up) / vec3_dot(c->up, c->up) * r->side;
    Samples *s = &r->out[(int)floor(v) * r->side + (int)floor(u)];
    assert_true(s->count < 64);
    s->position[s->count][0] = u - floor(u);
    s->position[s->count][1] = v - floor(v);
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
    load_room(&scene, 1);
    for (uint64_t seed = 1; seed <= 3; seed++) {
        Samples samples = {.count = 0};
        Recorder recorder = {&samples, 1};
        RenderSettings settings = {{1, 1, 8, PIXEL_PROGRESSIVE, seed}, 1, 0, "test"};
        for (int pass = 0; pass < 8; pass++) {
            RenderResult result;
            assert_int_equal(
                render_from(&scene, &settings, 8 * pass, record_sample, &recorder, &result), 0);
            render_result_free(&result);
        }
        assert_int_equal(samples.count, 64);
        int empty_positions = empty_cells(samples.position),
            empty_pairs = empty_cells(samples.pair);
        print_message("    seed %d: empty cells %d (positions), %d (pairs)\n", (int)seed,
                      empty_positions, empty_pairs);
        assert_int_equal(empty_positions, 0);
        assert_int_equal(empty_pairs, 0);
    }
    scene_free(&scene);
}

/* The budget ends the passes nearest it: passes of d seconds each against a budget B
 * give the whole number of passes whose total is nearest B (at least one, at most the
 * passes asked for), so the total overshoots by at most half a pass. Starting another
 * pass whenever any budget is left would give 4 passes of 3 s for 10 s (12 s). */
static void test_budget_ends_nearest(void **state)
{
    const double budget = 10.0, pass_seconds[] = {0.7, 1.0, 1.3, 2.9, 3.0, 3.1, 4.9, 6.0, 15.0};
    for (size_t k = 0; k < sizeof pass_seconds / sizeof pass_seconds[0]; k++) {
        double d = pass_seconds[k];
        PpmSettings ppm = {CHAPTER7, 1000, 0.2, PPM_ALPHA, 1, 12, budget, 0.0, 0.0};
        int done = 0;
        while (ppm_budget_allows(&ppm, done, done * d))
            done++;
        int nearest = (int)floor(budget / d + 0.5);
        nearest = nearest < 1 ? 1 : nearest > ppm.passes ? ppm.passes : nearest;
        print_message("    passes of %.1f s for %.0f s: %d (%.1f s), nearest %d\n", d, budget,
                      done, done * d, nearest);
        assert_int_equal(done, nearest);
    }
}

/* The room without mirrors and glass (the maps are empty, and chapter 8's estimator
 * draws chapter 7's final estimator's samples, test_caustic_path.c): 4 progressive
 * passes of 4 samples are one render of 16 samples of the same seed, to the rounding of
 * the pass images' floats (a pass restarting at sample 0 repeats the first 4). */
static void test_progressive_passes_are_one_render(void **state)
{
    Scene scene;
    load_room(&scene, 0);
    PathSettings path = CHAPTER7;
    path.shadow_rays = 1;
    RenderSettings passes = {{12, 12, 1, PIXEL_PROGRESSIVE, 7}, 0, 0, "test"};
    PpmSettings ppm = {path, 2000, 0.2, PPM_ALPHA, 4, 4, 0.0, 0.0, 0.0};
    PpmResult progressive;
    assert_int_equal(ppm_render(&scene, &passes, &ppm, &progressive), 0);
    assert_true(progressive.stored == 0.0);
    RenderSettings once = {{12, 12, 16, PIXEL_PROGRESSIVE, 7}, 0, 0, "test"};
    RenderResult single;
    assert_int_equal(render(&scene, &once, path_final_radiance, &path, &single), 0);
    double largest = 0.0;
    for (int i = 0; i < 3 * 12 * 12; i++) {
        double a = progressive.render.image.pixels[i], b = single.image.pixels[i];
        largest = fmax(largest, fabs(a - b) / fmax(fabs(b), 1e-30));
    }
    print_message("    largest relative difference %.2e\n", largest);
    assert_true(largest < 1e-6);
    ppm_result_free(&progressive);
    render_result_free(&single);
    scene_free(&scene);
}

/* A sample's position in its pixel and its first pair (the lamp point) must be
 * independent: over 8 x 8 pixels of 64 progressive samples, the correlation between the
 * position's u and the pair's u (and v and v) is about N(0, 1/64) if they are, and below
 * 0.1 (6 standard deviations) here; drawn from one key they would be equal (1.0). */
static void test_positions_independent_of_first_pairs(void **state)
{
    Scene scene;
    load_room(&scene, 1);
    static Samples samples[64];
    Recorder recorder = {samples, 8};
    RenderSettings settings = {{8, 8, 64, PIXEL_PROGRESSIVE, 4}, 1, 0, "test"};
    RenderResult result;
    assert_int_equal(render(&scene, &settings, record_sample, &recorder, &result), 0);
    render_result_free(&result);
    for (int axis = 0; axis < 2; axis++) {
        double sum[2] = {0, 0}, sum2[2] = {0, 0}, product = 0.0;
        int n = 0;
        for (int p = 0; p < 64; p++) {
            assert_int_equal(samples[p].count, 64);
            for (int k = 0; k < 64; k++) {
                double position = samples[p].position[k][axis], pair = samples[p].pair[k][axis];
                sum[0] += position;
                sum[1] += pair;
                sum2[0] += position * position;
                sum2[1] += pair * pair;
                product += position * pair;
                n++;
            }
        }
        double covariance = product / n - sum[0] / n * sum[1] / n;
        double correlation = covariance / sqrt((sum2[0] / n - pow(sum[0] / n, 2)) *
                                               (sum2[1] / n - pow(sum[1] / n, 2)));
        print_message("    correlation of position and first pair (%s): %+.4f\n",
                      axis ? "v" : "u", correlation);
        assert_true(fabs(correlation) < 0.1);
    }
    scene_free(&scene);
}

/* Each pass shoots its own photons and gathers them at its own radius. A floor (rho =
 * 0.5) lit only through a mirror ceiling by a lamp facing up (so every photon on it is a
 * caustic photon), seen by 8 x 8 pixel centres 0.1 apart (discs of radius <= 0.045 do
 * not overlap); depth 2 and no shadow rays, so a pass's pixel is its map's estimate
 * alone: k photons of power Phi / N in the disc, L = k u_i, u_i = rho Phi / (pi N pi r_i^2).
 * k is binomial (N large, p small: variance = mean), so over the passes a pixel of mean
 * m has sample variance m u on average, u the mean of the u_i over the schedule; summed
 * over the pixels, variance / (m u) = 1 within about sqrt(2 / (64 x 15)) = 0.046
 * (16 passes). |ratio - 1| < 0.2: 4.3 of them. The same photons every pass, or every
 * pass at the first radius, give far less spread than that. */
static void test_passes_shoot_their_own_photons_at_their_own_radius(void **state)
{
    Scene scene;
    scene_init(&scene);
    Material lamp = {.name = "lamp", .kind = MATERIAL_LIGHT, .emission = vec3(1, 1, 1)};
    Material grey = {
        .name = "grey", .kind = MATERIAL_LAMBERT, .reflectance = vec3(0.5, 0.5, 0.5)};
    Material mirror = {.name = "mirror", .kind = MATERIAL_MIRROR, .reflectance = vec3(1, 1, 1)};
    int l = scene_add_material(&scene, lamp), g = scene_add_material(&scene, grey),
        m = scene_add_material(&scene, mirror);
    const double lamp_area = 0.2 * 0.2;
    Vec3 quads[3][4] = {{{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}}, /* floor, up */
                        {{-2, -2, 1}, {-2, 2, 1}, {2, 2, 1}, {2, -2, 1}}, /* mirror, down */
                        {{-0.9, -0.1, 0.5},
                         {-0.7, -0.1, 0.5},
                         {-0.7, 0.1, 0.5},
                         {-0.9, 0.1, 0.5}}}; /* lamp, up */
    const int materials[3] = {g, m, l};
    for (int q = 0; q < 3; q++) {
        assert_true(scene_add_triangle(&scene, triangle_make(quads[q][0], quads[q][1],
                                                             quads[q][2], materials[q])) >= 0);
        assert_true(scene_add_triangle(&scene, triangle_make(quads[q][0], quads[q][2],
                                                             quads[q][3], materials[q])) >= 0);
    }
    scene.camera = camera_make(vec3(0.3, 0, 0.4), vec3(0.2, 0.1, 0.3), vec3(0.4, 0.1, 0.3),
                               vec3(0.2, -0.1, 0.3));
    assert_int_equal(scene_prepare(&scene), 0);
    const int passes = 16, photons = 50000;
    const double r1 = 0.045, rho = 0.5, phi = PI * lamp_area;
    PpmSettings ppm = {{.max_depth = 2}, photons, r1, PPM_ALPHA, 1, passes, 0.0, 0.0, 0.0};
    RenderSettings settings = {{8, 8, 1, PIXEL_CENTRE, 21}, 0, 0, "test"};
    PpmResult result;
    assert_int_equal(ppm_render(&scene, &settings, &ppm, &result), 0);
    assert_int_equal(result.passes, passes);
    double u = 0.0;
    for (int i = 1; i <= passes; i++)
        u += rho * phi / (PI * photons * PI * pow(ppm_radius(r1, PPM_ALPHA, i), 2)) / passes;
    double variance = 0.0, predicted = 0.0;
    for (int p = 0; p < 64; p++) {
        Vec3 mean = image_get(&result.render.image, p % 8, p / 8);
        double se = image_get(&result.render.std_error, p % 8, p / 8).x;
        variance += se * se * passes;
        predicted += mean.x * u;
    }
    print_message("    %.0f photons stored per pass; spread over the passes / binomial: %.3f "
                  "(photons per disc at the first radius: %.1f on average)\n",
                  result.stored, variance / predicted,
                  predicted / u / 64 / (rho * phi / (PI * photons * PI * r1 * r1)));
    assert_true(predicted > 0.0);
    assert_true(fabs(variance / predicted - 1.0) < 0.2);
    ppm_result_free(&result);
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
        cmocka_unit_test(test_budget_ends_nearest),
        cmocka_unit_test(test_progressive_passes_are_one_render),
        cmocka_unit_test(test_positions_independent_of_first_pairs),
        cmocka_unit_test(test_passes_shoot_their_own_photons_at_their_own_radius),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
