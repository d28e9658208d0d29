/* test_caustic_path.c (chapter 8): Tests of the path tracer with caustics from photon maps (lib/path.c's chapter 8
 * option, and progressive photon mapping, bench/ppm.c): the two estimators together
 * count every light path exactly once, so they estimate chapter 7's image.
 *
 * 1. A room without mirrors or glass (the report's room with both made white Lambert):
 *    no photon reaches a diffuse surface after a specular bounce, so the caustic map is
 *    empty, and the path tracer with it draws exactly chapter 7's samples: the images
 *    are bit for bit the same. Progressive photon mapping's pass-averaged image then
 *    equals chapter 7's within noise.
 *    Per pixel and channel, z = (a - b) / sqrt(se_a^2 + se_b^2) must stay under the
 *    Sidak-corrected level for 768 tests at a family-wise 0.1% (|z| < 4.87); and over
 *    4 x 4-pixel blocks, the sum of the blocks' z^2 is a chi-square with 48 degrees of
 *    freedom, tested at the 0.1% level.
 * 2. The report's room, 16 x 16 pixels: progressive photon mapping (many passes, the
 *    radius shrinking as in ppm.h) against the path tracer's reference, chapter 7's
 *    estimator (with one shadow ray) at 4000 samples per pixel: the block test. Not the per-pixel test: the
 *    reference finds caustics only by hitting the lamp, so single pixels of it are
 *    heavy-tailed. One pixel of this reference (on the red wall) is 8 of its own
 *    standard errors below what 40,000 samples give, where the photon map agrees with
 *    those; a block of 16 pixels averages such misses out.
 * 3. No double counting, on the image's mean (over every pixel but the lamp and its
 *    images in the mirrors, which are the same in every estimator and the noisiest;
 *    the kernel's blur cancels in a mean): the caustic map's share (the combined image
 *    minus the path tracer's with an empty map) is many standard errors, and the
 *    combined image's mean equals the reference's within 4 standard errors. Counting
 *    the caustics twice, or leaving them out, moves the mean by that share; the test
 *    checks that either would be rejected.
 * Planted bugs, each rejected by both 2 and 3 (mean 0.17004 +- 0.00054 for the
 * reference, 0.16980 +- 0.00059 combined, when correct):
 *   - the path tracer still adding emission it hits after a diffuse and then a specular
 *     bounce (L S+ D counted twice): combined mean 0.19691, block p = 2e-106;
 *   - the photon tracer also storing photons whose first surface is diffuse (direct
 *     light counted by the shadow rays and again by the map): 0.30212, p = 0 (and 1
 *     fails: the map is no longer empty);
 *   - the caustic estimate left out (L S+ D counted by neither): 0.14246, p = 0.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <string.h>

#include "renderer.h"
#include "chi_square.h"
#include "measure.h"
#include "path_roulette.h"
#include "ppm.h"
#include "scene_file.h"

#define SIDE 16
#define BLOCK 4

static const PathSettings CHAPTER7 = {.max_depth = 64, .shadow_rays = 4, .fresnel = FRESNEL_EXACT,
                                      .rr_survival = 0.75};

static void load_room(Scene *scene, int specular)
{
    char error[256];
    assert_int_equal(scene_load("scenes/room.scene", scene, error, sizeof error), 0);
    for (int i = 0; !specular && i < scene->material_count; i++) {
        Material *m = &scene->materials[i];
        if (m->kind == MATERIAL_MIRROR || m->kind == MATERIAL_GLASS) {
            m->kind = MATERIAL_LAMBERT;
            m->reflectance = vec3(0.75, 0.75, 0.75);
        }
    }
}

/* The largest |z| over single pixels and channels. */
static double largest_pixel_z(const RenderResult *a, const RenderResult *b)
{
    double largest = 0.0;
    for (int i = 0; i < 3 * SIDE * SIDE; i++) {
        double z = (a->image.pixels[i] - b->image.pixels[i]) /
                   sqrt(pow(a->std_error.pixels[i], 2) + pow(b->std_error.pixels[i], 2));
        largest = fmax(largest, fabs(z));
    }
    return largest;
}

/* The p-value of the sum of z^2 over the blocks' channel means (chi-square with one
 * degree of freedom per block and channel). */
static double block_p_value(const RenderResult *a, const RenderResult *b)
{
    double sum_z2 = 0.0;
    int blocks = 0;
    for (int by = 0; by < SIDE / BLOCK; by++)
        for (int bx = 0; bx < SIDE / BLOCK; bx++)
            for (int c = 0; c < 3; c++) {
                double difference = 0.0, variance = 0.0;
                for (int y = by * BLOCK; y < (by + 1) * BLOCK; y++)
                    for (int x = bx * BLOCK; x < (bx + 1) * BLOCK; x++) {
                        int i = 3 * (y * SIDE + x) + c;
                        difference += a->image.pixels[i] - b->image.pixels[i];
                        variance += pow(a->std_error.pixels[i], 2) + pow(b->std_error.pixels[i], 2);
                    }
                sum_z2 += difference * difference / variance;
                blocks++;
            }
    double p = chi_square_p_value(sum_z2, blocks);
    print_message("    blocks: sum of z^2 = %.1f over %d, p = %.3g\n", sum_z2, blocks, p);
    return p;
}

static void test_room_without_specular_is_chapter7(void **state)
{
    Scene scene;
    load_room(&scene, 0);
    RayCounts counts = {0, 0, 0};
    PhotonMapSettings photons = {20000, PHOTON_CAUSTIC, FRESNEL_EXACT, 3};
    PhotonMap map;
    assert_int_equal(ppm_photon_map(&map, &scene, &photons, 0, &counts), 0);
    assert_int_equal(map.count, 0);
    CausticPathSettings with_map = {CHAPTER7, &map, 0.2};
    RenderSettings settings = {{SIDE, SIDE, 64, PIXEL_RANDOM, 5}, 0, 0, "test"};
    RenderResult a, b;
    assert_int_equal(render(&scene, &settings, path_roulette_radiance, &CHAPTER7, &a), 0);
    assert_int_equal(render(&scene, &settings, path_caustics_radiance, &with_map, &b), 0);
    assert_int_equal(memcmp(a.image.pixels, b.image.pixels, sizeof(float) * 3 * SIDE * SIDE), 0);
    photon_map_free(&map);
    render_result_free(&b);

    PpmSettings ppm = {CHAPTER7, 20000, 0.2, PPM_ALPHA, 8, 16, 0.0};
    PpmResult progressive;
    assert_int_equal(ppm_render(&scene, &settings, &ppm, &progressive), 0);
    assert_int_equal(progressive.passes, 16);
    assert_true(progressive.stored == 0.0);
    /* Sidak: each of n tests at 1 - (1 - 0.001)^(1/n); n = 768 gives |z| < 4.87. */
    double largest = largest_pixel_z(&a, &progressive.render);
    print_message("    largest per-pixel |z| %.2f (limit 4.87)\n", largest);
    assert_true(largest < 4.87);
    assert_true(block_p_value(&a, &progressive.render) > 0.001);
    ppm_result_free(&progressive);
    render_result_free(&a);
    scene_free(&scene);
}

/* The mean over the pixels and channels where `mask` is below 1.5 in every channel,
 * and its standard error (pixels are independent). */
static void masked_mean(const RenderResult *r, const Image *mask, double *mean, double *error)
{
    double sum = 0.0, variance = 0.0;
    int n = 0;
    for (int p = 0; p < SIDE * SIDE; p++) {
        if (vec3_max_component(image_get(mask, p % SIDE, p / SIDE)) >= 1.5)
            continue;
        for (int c = 0; c < 3; c++) {
            sum += r->image.pixels[3 * p + c];
            variance += pow(r->std_error.pixels[3 * p + c], 2);
            n++;
        }
    }
    *mean = sum / n;
    *error = sqrt(variance) / n;
}

static void test_room_converges_and_counts_once(void **state)
{
    Scene scene;
    load_room(&scene, 1);
    PathSettings one_shadow_ray = CHAPTER7;
    one_shadow_ray.shadow_rays = 1; /* the same expectation, cheaper per sample */
    RenderSettings many = {{SIDE, SIDE, 4000, PIXEL_RANDOM, 11}, 0, 0, "test"};
    RenderResult reference;
    assert_int_equal(render(&scene, &many, path_roulette_radiance, &one_shadow_ray, &reference), 0);

    RenderSettings passes = {{SIDE, SIDE, 1, PIXEL_RANDOM, 12}, 0, 0, "test"};
    PpmSettings ppm = {CHAPTER7, 20000, 0.1, PPM_ALPHA, 16, 64, 0.0};
    PpmResult combined;
    assert_int_equal(ppm_render(&scene, &passes, &ppm, &combined), 0);
    assert_true(combined.stored > 1000);
    print_message("    %d passes of %d photons (%.0f stored), radius %.3f to %.3f\n",
                  combined.passes, ppm.photons, combined.stored, ppm.radius, combined.radius);
    double p = block_p_value(&reference, &combined.render);

    /* The path tracer's own share: caustic option on, the map empty. */
    PhotonMap empty;
    RayCounts counts = {0, 0, 0};
    PhotonMapSettings none = {0, PHOTON_CAUSTIC, FRESNEL_EXACT, 1};
    assert_int_equal(ppm_photon_map(&empty, &scene, &none, 0, &counts), 0);
    CausticPathSettings without = {CHAPTER7, &empty, 0.15};
    RenderSettings path_only = {{SIDE, SIDE, 1024, PIXEL_RANDOM, 13}, 0, 0, "test"};
    RenderResult path_part;
    assert_int_equal(render(&scene, &path_only, path_caustics_radiance, &without, &path_part), 0);

    /* Leave out the lamp and its images in the mirrors (the path tracer's own image
     * says where): the same in every estimator, and the noisiest pixels. */
    double ref_mean, ref_error, mean, error, path_mean, path_error;
    masked_mean(&reference, &path_part.image, &ref_mean, &ref_error);
    masked_mean(&combined.render, &path_part.image, &mean, &error);
    masked_mean(&path_part, &path_part.image, &path_mean, &path_error);
    double share = mean - path_mean, share_error = sqrt(error * error + path_error * path_error);
    double difference_error = sqrt(error * error + ref_error * ref_error);
    print_message("    means: reference %.5f +- %.5f, combined %.5f +- %.5f; the caustic "
                  "map's share %.5f +- %.5f (%.1f%%)\n", ref_mean, ref_error, mean, error, share,
                  share_error, 100 * share / mean);
    assert_true(fabs(mean - ref_mean) < 4 * difference_error);
    /* Counting the share twice (or not at all) would be rejected by the same test. */
    assert_true(share - 4 * share_error > 8 * difference_error);
    assert_true(p > 0.001);
    photon_map_free(&empty);
    render_result_free(&path_part);
    ppm_result_free(&combined);
    render_result_free(&reference);
    scene_free(&scene);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_room_without_specular_is_chapter7),
        cmocka_unit_test(test_room_converges_and_counts_once),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
