/* test_sobol.c (chapter 7): the stratified pairs (sobol.h) are spread evenly, uniform,
 * independent of each other, and leave the path tracer's image unchanged in the mean.
 *   - stratification: for 2^m samples of one pixel, every grid of 2^a x 2^b cells
 *     (a + b = m) has exactly one point in each cell, for several pixels' keys;
 *   - uniformity: one sample's point, over 40,000 pixels' keys, is uniform on a 16 x 16
 *     grid (chi-square), for the first sample and a later one;
 *   - independence: a sample's pairs 0 and 1 (keys mixed with the pair's number, as
 *     rng_pair does) are independent: (u0, v0, u1, v1) uniform on 4^4 cells;
 *   - the path tracer with PIXEL_STRATIFIED against PIXEL_RANDOM on the room, pixel by
 *     pixel (agreement.h). The stratified render's own per-pixel error (render.h)
 *     assumes independent samples, which overstates a stratified mean's error and
 *     would make the test weak; so its error is measured from 64 independent runs
 *     (seeds) of 16 spp: their mean's standard error is sd / sqrt(64). (With the spread
 *     itself estimated, z follows Student's t with 63 degrees of freedom, whose tail
 *     beyond the corrected bound of 4.2 is about twice the normal's: a false alarm
 *     about 2% of the time rather than 1%.)
 * Planted, each caught here: the second dimension's columns built with v ^= v >> 2
 * (stratification: an empty cell); the seed not added in laine_karras (uniformity:
 * sample 0 always at (0, 0), chi-square p = 0; the agreement test too, z = -4.4);
 * rng_pair using one key for all the pairs of a sample (independence, p = 0; the
 * agreement test, z = -10.7: the second vertex's lamp point is tied to the first
 * bounce).
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include "renderer.h"
#include "agreement.h"
#include "chi_square.h"
#include "path_final.h"
#include "scene_file.h"
#include "sobol.h"

static void test_every_elementary_interval_holds_one_point(void **state)
{
    enum {
        M = 8,
        N = 1 << M
    };
    for (uint64_t key = 1; key <= 5; key++) {
        double u[N], v[N];
        for (int i = 0; i < N; i++)
            sobol_pair((uint32_t)i, key * 0x9e3779b97f4a7c15ULL, &u[i], &v[i]);
        for (int a = 0; a <= M; a++) {
            int columns = 1 << a, rows = 1 << (M - a);
            static int count[N];
            for (int c = 0; c < N; c++)
                count[c] = 0;
            for (int i = 0; i < N; i++) {
                assert_true(u[i] >= 0.0 && u[i] < 1.0 && v[i] >= 0.0 && v[i] < 1.0);
                count[(int)(v[i] * rows) * columns + (int)(u[i] * columns)]++;
            }
            for (int c = 0; c < N; c++)
                if (count[c] != 1)
                    fail_msg("key %llu, %d x %d cells: cell %d holds %d points",
                             (unsigned long long)key, columns, rows, c, count[c]);
        }
    }
}

/* One sample's point over many pixels' keys, on a 16 x 16 grid. */
static double uniformity_p(uint32_t index)
{
    enum {
        CELLS = 16,
        KEYS = 40000
    };
    double observed[CELLS * CELLS] = {0}, expected[CELLS * CELLS];
    for (int c = 0; c < CELLS * CELLS; c++)
        expected[c] = (double)KEYS / (CELLS * CELLS);
    for (uint64_t k = 0; k < KEYS; k++) {
        double u, v;
        sobol_pair(index, rng_hash(k + 1), &u, &v);
        observed[(int)(v * CELLS) * CELLS + (int)(u * CELLS)] += 1.0;
    }
    int dof;
    double x2 = chi_square_statistic(observed, expected, CELLS * CELLS, &dof);
    double p = chi_square_p_value(x2, dof);
    print_message("    sample %u over %d keys: X^2 = %.1f, %d dof, p = %.3f\n", index, KEYS, x2,
                  dof, p);
    return p;
}

static void test_each_point_is_uniform_over_keys(void **state)
{
    assert_true(uniformity_p(0) > 1e-3);
    assert_true(uniformity_p(37) > 1e-3);
}

static void test_the_pairs_of_a_sample_are_independent(void **state)
{
    enum {
        CELLS = 4,
        BINS = CELLS * CELLS * CELLS * CELLS,
        SAMPLES = 51200
    };
    double observed[BINS] = {0}, expected[BINS];
    for (int b = 0; b < BINS; b++)
        expected[b] = (double)SAMPLES / BINS;
    for (uint32_t s = 0; s < SAMPLES; s++) {
        /* Sample s % 64 of pixel s, drawn as render.c and rng_pair do: one sample per
         * pixel, so that the samples are independent (a pixel's own are stratified). */
        Rng rng = rng_for_sample(3, s, s % 64);
        rng.strata_key = rng_hash(s) | 1u;
        rng.strata_index = s % 64;
        double u0, v0, u1, v1;
        rng_pair(&rng, &u0, &v0);
        rng_pair(&rng, &u1, &v1);
        int cell = (int)(u0 * CELLS);
        cell = cell * CELLS + (int)(v0 * CELLS);
        cell = cell * CELLS + (int)(u1 * CELLS);
        cell = cell * CELLS + (int)(v1 * CELLS);
        observed[cell] += 1.0;
    }
    int dof;
    double x2 = chi_square_statistic(observed, expected, BINS, &dof);
    double p = chi_square_p_value(x2, dof);
    print_message("    pairs 0 and 1 of %d samples: X^2 = %.1f, %d dof, p = %.3f\n", SAMPLES,
                  x2, dof, p);
    assert_true(p > 1e-3);
}

/* The room at 10 x 10 pixels, depth 8, one shadow ray, the mirror light: PIXEL_STRATIFIED
 * over 64 runs of 16 spp against PIXEL_RANDOM with 4096 spp. */
enum {
    SIDE = 10,
    RUNS = 64,
    SPP = 16
};

static void test_path_tracer_mean_unchanged(void **state)
{
    Scene scene;
    char error[256];
    assert_int_equal(scene_load("scenes/room.scene", &scene, error, sizeof error), 0);
    MirrorPlanes mirrors;
    assert_int_equal(mirror_light_find_planes(&scene, &mirrors), 0);
    PathSettings path = {.max_depth = 8,
                         .shadow_rays = 1,
                         .rr_throughput = 1,
                         .mirror_light = 8,
                         .mirrors = &mirrors};
    Image sum = image_new(SIDE, SIDE), sum2 = image_new(SIDE, SIDE);
    for (int run = 0; run < RUNS; run++) {
        RenderSettings settings = {
            {SIDE, SIDE, SPP, PIXEL_STRATIFIED, 100 + (uint64_t)run}, 1, 0, "test"};
        RenderResult r;
        assert_int_equal(render(&scene, &settings, path_final_radiance, &path, &r), 0);
        for (int i = 0; i < 3 * SIDE * SIDE; i++) {
            sum.pixels[i] += r.image.pixels[i];
            sum2.pixels[i] += r.image.pixels[i] * r.image.pixels[i];
        }
        render_result_free(&r);
    }
    Image mean = image_new(SIDE, SIDE), error_of_mean = image_new(SIDE, SIDE);
    for (int i = 0; i < 3 * SIDE * SIDE; i++) {
        double m = sum.pixels[i] / RUNS,
               variance = (sum2.pixels[i] - RUNS * m * m) / (RUNS - 1);
        mean.pixels[i] = (float)m;
        error_of_mean.pixels[i] = (float)sqrt(fmax(variance, 0.0) / RUNS);
    }
    RenderSettings independent = {{SIDE, SIDE, 4096, PIXEL_RANDOM, 7}, 1, 0, "test"};
    RenderResult r;
    assert_int_equal(render(&scene, &independent, path_final_radiance, &path, &r), 0);
    Agreement agreement = agreement_test(&mean, &error_of_mean, &r.image, &r.std_error, 0.01);
    agreement_print("stratified (64 runs) against independent", &agreement);
    assert_true(agreement_holds(&agreement));
    render_result_free(&r);
    image_free(&sum);
    image_free(&sum2);
    image_free(&mean);
    image_free(&error_of_mean);
    mirror_planes_free(&mirrors);
    scene_free(&scene);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_every_elementary_interval_holds_one_point),
        cmocka_unit_test(test_each_point_is_uniform_over_keys),
        cmocka_unit_test(test_the_pairs_of_a_sample_are_independent),
        cmocka_unit_test(test_path_tracer_mean_unchanged),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
