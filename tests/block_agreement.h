/* block_agreement.h (chapter 3): do two path tracers estimate the same image? A block
 * chi-square test on a small render (include after cmocka.h).
 *
 * The image is cut into 3 x 3-pixel blocks; for each block and channel, z = (a - b) /
 * sqrt(se_a^2 + se_b^2) of the two block means should be standard normal, so the sum of
 * z^2 over the N block channels is chi-square with N degrees of freedom. (Blocks rather
 * than pixels: an estimator that finds the lamp rarely has noisy per-pixel errors and
 * heavy-tailed z; nine pixels tame that.) A double-counted or missing light path shifts
 * every block by many standard errors. Significance level 0.1%, fixed seeds.
 */
#ifndef BLOCK_AGREEMENT_H
#define BLOCK_AGREEMENT_H

#include "chi_square.h"
#include "experiment.h"
#include "measure.h"
#include "path.h"
#include "renderer.h"
#include "scene_file.h"

#define BLOCK 3
#define SIDE 12

static inline void block_means(const RenderResult *r, int bx, int by, int c, double *mean,
                               double *se)
{
    double sum = 0.0, variance = 0.0;
    for (int y = by * BLOCK; y < (by + 1) * BLOCK; y++)
        for (int x = bx * BLOCK; x < (bx + 1) * BLOCK; x++) {
            sum += r->image.pixels[3 * (y * SIDE + x) + c];
            double e = r->std_error.pixels[3 * (y * SIDE + x) + c];
            variance += e * e;
        }
    *mean = sum / (BLOCK * BLOCK);
    *se = sqrt(variance) / (BLOCK * BLOCK);
}

/* Estimator a with settings a (spp_a samples) and b (spp_b) agree on a scene at
 * SIDE x SIDE pixels: the block chi-square above at significance level 0.1%, and the
 * image means within 4 standard errors. */
static inline void assert_agree_on(const Scene *scene, Estimator a,
                                   const PathSettings *a_settings, int spp_a, Estimator b,
                                   const PathSettings *b_settings, int spp_b)
{
    RenderSettings first = {{SIDE, SIDE, spp_a, PIXEL_RANDOM, 1}, 0, 0, "test"};
    RenderSettings second = {{SIDE, SIDE, spp_b, PIXEL_RANDOM, 2}, 0, 0, "test"};
    RenderResult ra, rb;
    assert_int_equal(render(scene, &first, a, a_settings, &ra), 0);
    assert_int_equal(render(scene, &second, b, b_settings, &rb), 0);
    double sum_z2 = 0.0, largest = 0.0;
    int n = 0;
    for (int by = 0; by < SIDE / BLOCK; by++)
        for (int bx = 0; bx < SIDE / BLOCK; bx++)
            for (int c = 0; c < 3; c++) {
                double mean_a, se_a, mean_b, se_b;
                block_means(&ra, bx, by, c, &mean_a, &se_a);
                block_means(&rb, bx, by, c, &mean_b, &se_b);
                double z = (mean_a - mean_b) / sqrt(se_a * se_a + se_b * se_b);
                sum_z2 += z * z;
                largest = fmax(largest, fabs(z));
                n++;
            }
    double p = chi_square_p_value(sum_z2, n);
    double mean_a, error_a, mean_b, error_b;
    measure_image_mean(&ra.image, &ra.average_std_error, &mean_a, &error_a);
    measure_image_mean(&rb.image, &rb.average_std_error, &mean_b, &error_b);
    char text_a[96], text_b[96];
    describe_path(a_settings, text_a, sizeof text_a);
    describe_path(b_settings, text_b, sizeof text_b);
    print_message("    image means: %s %.5f +- %.5f, %s %.5f +- %.5f\n", text_a, mean_a,
                  error_a, text_b, mean_b, error_b);
    print_message("    sum of z^2 = %.1f over %d block channels (p = %.3f), largest |z| %.2f\n",
                  sum_z2, n, p, largest);
    assert_true(p > 0.001);
    assert_true(fabs(mean_a - mean_b) < 4.0 * sqrt(error_a * error_a + error_b * error_b));
    render_result_free(&ra);
    render_result_free(&rb);
}

static inline void assert_agree_on_the_room(Estimator a, const PathSettings *a_settings,
                                            int spp_a, Estimator b,
                                            const PathSettings *b_settings, int spp_b)
{
    Scene scene;
    char error[256];
    assert_int_equal(scene_load("scenes/room.scene", &scene, error, sizeof error), 0);
    assert_agree_on(&scene, a, a_settings, spp_a, b, b_settings, spp_b);
    scene_free(&scene);
}

#endif
