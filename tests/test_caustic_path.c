/* test_caustic_path.c (chapter 8): Tests of chapter 8's estimator (lib/path_caustics.c: chapter
 * 7's final estimator plus the photon maps) and of progressive photon mapping (bench/ppm.c):
 * the images, the map and the path count every light path exactly once.
 *
 * 1. A room without mirrors or glass (the report's room with both made white Lambert):
 *    the map is empty, and chapter 8's estimator draws exactly chapter 7's final
 *    estimator's samples: the images are bit for bit the same. Progressive photon
 *    mapping's pass-averaged image then equals chapter 7's within noise.
 *    Per pixel and channel, z = (a - b) / sqrt(se_a^2 + se_b^2) must stay under the
 *    Sidak-corrected level for 768 tests at a family-wise 0.1% (|z| < 4.87); and over
 *    4 x 4-pixel blocks, the sum of the blocks' z^2 is a chi-square with 48 degrees of
 *    freedom, tested at the 0.1% level.
 *    With the mirror wall kept (the spheres white Lambert) and empty maps, chapter 8's
 *    estimator still draws chapter 7's samples, with mis and without, at depths 2, 3, 4
 *    and 64 (planted: the images sampled one segment past the depth limit, 444 values
 *    of 768 differ at depth 2; mis at a lamp hit after the mirror weighed at the last
 *    segment's length instead of the unfolded distance, 9 differ at depth 3).
 * 2. The report's room, 16 x 16 pixels: progressive photon mapping (many passes, the
 *    radius shrinking as in ppm.h), with the mirror's images at every diffuse vertex
 *    and at the first only (the caustic map bringing L M D at the others), against
 *    chapter 7's final estimator at 4000 samples per pixel: the block test; and no
 *    double counting, on the image's mean (over every pixel but the lamp and its images
 *    in the mirrors, the noisiest; the kernel's blur cancels in a mean): the combined
 *    mean equals the reference's within 4 standard errors, and the maps' share (the
 *    combined image minus the path's with empty maps) is more than 8 of them, so that
 *    counting it twice or not at all is rejected. A pixel's channels come from the same
 *    paths: the mean's standard error adds each pixel's variance of its channels' mean.
 * 3. The mirrored glass furnace (radiance 2 everywhere): light through the mirror wall
 *    alone, through the glass, and through both; the images at every vertex and at the
 *    first only. And with a mirror sphere in place of the glass, images at the first
 *    vertex, mis off and on: a sphere is no planar mirror (planted as one in the split
 *    map: 1.952 +- 0.008; in the path, mis on: 2.043 +- 0.008).
 * Planted bugs, each rejected by 2 (block p and mean) and 3 (when correct: reference
 * 0.17152 +- 0.00057, combined 0.16957 +- 0.00099, block p = 0.91; furnace 1.979 +- 0.008):
 *   - the path adding emission it hits after a diffuse vertex and glass or a mirror
 *     sphere (L S+ D counted by the map and again by the path): combined 0.18042, block
 *     p = 2e-151; furnace 2.201 +- 0.009;
 *   - the photon tracer storing one planar mirror straight on too (L M D counted by the
 *     mirror's images and again by the map): combined 0.18557, p = 0; furnace 2.221;
 * and, with the images at the first vertex only (when correct: combined 0.16932 +-
 * 0.00100, p = 0.99; furnace 1.998 +- 0.009):
 *   - the other vertices gathering from the split map (L M D left out there): combined
 *     0.16123, p = 2e-269; furnace 1.846 +- 0.008;
 *   - the path adding emission after one planar mirror straight from a vertex that did
 *     not sample the images (L M D counted by the path and the caustic map): combined
 *     0.17654, p = 6e-7; furnace 2.151 +- 0.010.
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
#include "furnace.h"
#include "path_check.h"
#include "path_final.h"
#include "ppm.h"
#include "scene_file.h"
#include "sphere_guide.h"

#define SIDE 16
#define BLOCK 4

/* Chapter 7's final estimator (Figure 7's), with the scene's mirror planes. */
static PathSettings final_estimator(const MirrorPlanes *mirrors)
{
    PathSettings path = {.max_depth = 64,
                         .shadow_rays = 1,
                         .fresnel = FRESNEL_EXACT,
                         .rr_throughput = 1,
                         .mirror_light = 64,
                         .mirrors = mirrors,
                         .sphere_guide = SPHERE_GUIDE_STRENGTH};
    return path;
}

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
                        variance +=
                            pow(a->std_error.pixels[i], 2) + pow(b->std_error.pixels[i], 2);
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
    MirrorPlanes mirrors;
    assert_int_equal(mirror_light_find_planes(&scene, &mirrors), 0);
    const PathSettings CHAPTER7 = final_estimator(&mirrors);
    RayCounts counts = {0, 0, 0};
    PhotonMapSettings photons = {20000, PHOTON_SPLIT, FRESNEL_EXACT, 3};
    PhotonMap map;
    assert_int_equal(ppm_photon_map(&map, &scene, &photons, 0.2, 0, &counts), 0);
    assert_int_equal(map.count, 0);
    CausticPathSettings with_map = {CHAPTER7, &map, &map, 0.2};
    RenderSettings settings = {{SIDE, SIDE, 64, PIXEL_RANDOM, 5}, 0, 0, "test"};
    RenderResult a, b;
    assert_int_equal(render(&scene, &settings, path_final_radiance, &CHAPTER7, &a), 0);
    assert_int_equal(render(&scene, &settings, path_caustics_radiance, &with_map, &b), 0);
    assert_int_equal(memcmp(a.image.pixels, b.image.pixels, sizeof(float) * 3 * SIDE * SIDE),
                     0);
    photon_map_free(&map);
    render_result_free(&b);

    PpmSettings ppm = {CHAPTER7, 20000, 0.2, PPM_ALPHA, 8, 16, 0.0, 0.0, 0.0};
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
    mirror_planes_free(&mirrors);
    scene_free(&scene);
}

/* The room with its two spheres made white Lambert, its mirror wall kept: with empty
 * maps, chapter 8's estimator counts only what chapter 7's final one counts (shadow
 * rays, the images, the emission it hits, and with mis their shares), so the two draw
 * the same samples and the images are bit for bit the same, with mis and without, at
 * depths 2, 3, 4 and 64: the images are sampled only where their two segments fit, and
 * a lamp hit after the mirror is weighed at the distance unfolded there. */
static void test_empty_maps_are_chapter7_with_the_mirror_wall(void **state)
{
    Scene scene;
    load_room(&scene, 1);
    Material white = {
        .name = "white", .kind = MATERIAL_LAMBERT, .reflectance = vec3(0.75, 0.75, 0.75)};
    int w = scene_add_material(&scene, white);
    assert_true(w >= 0);
    for (int i = 0; i < scene.sphere_count; i++)
        scene.spheres[i].material = w;
    MirrorPlanes mirrors;
    assert_int_equal(mirror_light_find_planes(&scene, &mirrors), 0);
    assert_int_equal(mirrors.count, 1);
    PhotonMap empty;
    assert_int_equal(photon_map_build(&empty, NULL, 0, 0, 0.1), 0);
    const int depths[4] = {2, 3, 4, 64};
    for (int mis = 0; mis < 2; mis++)
        for (int d = 0; d < 4; d++) {
            PathSettings chapter7 = final_estimator(&mirrors);
            chapter7.max_depth = chapter7.mirror_light = depths[d];
            chapter7.mis = mis;
            CausticPathSettings chapter8 = {chapter7, &empty, &empty, 0.1};
            RenderSettings settings = {{SIDE, SIDE, 64, PIXEL_RANDOM, 17}, 0, 0, "test"};
            RenderResult a, b;
            assert_int_equal(render(&scene, &settings, path_final_radiance, &chapter7, &a), 0);
            assert_int_equal(render(&scene, &settings, path_caustics_radiance, &chapter8, &b),
                             0);
            int differ = 0;
            for (int i = 0; i < 3 * SIDE * SIDE; i++)
                differ += a.image.pixels[i] != b.image.pixels[i];
            print_message("    depth %2d%s: %d of %d values differ\n", depths[d],
                          mis ? ", mis" : "", differ, 3 * SIDE * SIDE);
            assert_int_equal(differ, 0);
            render_result_free(&a);
            render_result_free(&b);
        }
    photon_map_free(&empty);
    mirror_planes_free(&mirrors);
    scene_free(&scene);
}

/* The mean over the pixels where `mask` is below 1.5 in every channel of their channels'
 * mean, and its standard error: pixels are independent, but a pixel's three channels
 * come from the same paths, so each pixel adds the variance of its channels' mean
 * (average_std_error), not three variances as if they were independent. */
static void masked_mean(const RenderResult *r, const Image *mask, double *mean, double *error)
{
    double sum = 0.0, variance = 0.0;
    int n = 0;
    for (int p = 0; p < SIDE * SIDE; p++) {
        if (vec3_max_component(image_get(mask, p % SIDE, p / SIDE)) >= 1.5)
            continue;
        sum +=
            (r->image.pixels[3 * p] + r->image.pixels[3 * p + 1] + r->image.pixels[3 * p + 2]) /
            3.0;
        variance += pow(r->average_std_error.pixels[3 * p], 2);
        n++;
    }
    *mean = sum / n;
    *error = sqrt(variance) / n;
}

static void test_room_converges_and_counts_once(void **state)
{
    Scene scene;
    load_room(&scene, 1);
    MirrorPlanes mirrors;
    assert_int_equal(mirror_light_find_planes(&scene, &mirrors), 0);
    const PathSettings CHAPTER7 = final_estimator(&mirrors);
    RenderSettings many = {{SIDE, SIDE, 4000, PIXEL_RANDOM, 11}, 0, 0, "test"};
    RenderResult reference;
    assert_int_equal(render(&scene, &many, path_final_radiance, &CHAPTER7, &reference), 0);

    /* The path tracer's own share: caustic option on, the maps empty. */
    PhotonMap empty;
    RayCounts counts = {0, 0, 0};
    PhotonMapSettings none = {0, PHOTON_SPLIT, FRESNEL_EXACT, 1};
    assert_int_equal(ppm_photon_map(&empty, &scene, &none, 0.15, 0, &counts), 0);
    CausticPathSettings without = {CHAPTER7, &empty, &empty, 0.15};
    RenderSettings path_only = {{SIDE, SIDE, 1024, PIXEL_RANDOM, 13}, 0, 0, "test"};
    RenderResult path_part;
    assert_int_equal(render(&scene, &path_only, path_caustics_radiance, &without, &path_part),
                     0);
    /* Leave out the lamp and its images in the mirrors (the path tracer's own image
     * says where): the same in every estimator, and the noisiest pixels. */
    double ref_mean, ref_error, path_mean, path_error;
    masked_mean(&reference, &path_part.image, &ref_mean, &ref_error);
    masked_mean(&path_part, &path_part.image, &path_mean, &path_error);

    /* The images at every diffuse vertex (chapter 7's), then at the first only (chapter
     * 8's): the caustic map brings L M D at the others. */
    const int images_at[2] = {CHAPTER7.mirror_light, 1};
    for (int k = 0; k < 2; k++) {
        RenderSettings passes = {{SIDE, SIDE, 1, PIXEL_RANDOM, 12}, 0, 0, "test"};
        PpmSettings ppm = {CHAPTER7, 20000, 0.1, PPM_ALPHA, 16, 64, 0.0, 0.0, 0.0};
        ppm.path.mirror_light = images_at[k];
        PpmResult combined;
        assert_int_equal(ppm_render(&scene, &passes, &ppm, &combined), 0);
        assert_true(combined.stored > 100);
        print_message(
            "    images at the first %d diffuse vertices: %d passes of %d photons (%.0f "
            "stored), radius %.3f to %.3f\n",
            images_at[k], combined.passes, ppm.photons, combined.stored, ppm.radius,
            combined.radius);
        double p = block_p_value(&reference, &combined.render);
        double mean, error;
        masked_mean(&combined.render, &path_part.image, &mean, &error);
        double share = mean - path_mean,
               share_error = sqrt(error * error + path_error * path_error);
        double difference_error = sqrt(error * error + ref_error * ref_error);
        print_message("    means: reference %.5f +- %.5f, combined %.5f +- %.5f; the maps' "
                      "share %.5f +- %.5f (%.1f%%)\n",
                      ref_mean, ref_error, mean, error, share, share_error, 100 * share / mean);
        assert_true(fabs(mean - ref_mean) < 4 * difference_error);
        /* The test can see a double count: the share, counted twice or not at all, would
         * move the mean by more than 8 standard errors of the difference. */
        assert_true(share > 8 * difference_error);
        assert_true(p > 0.001);
        ppm_result_free(&combined);
    }
    photon_map_free(&empty);
    render_result_free(&path_part);
    render_result_free(&reference);
    mirror_planes_free(&mirrors);
    scene_free(&scene);
}

/* The mirrored furnace: furnace.h's bordered box (radiance 2 everywhere) with its wall
 * at x = +1 a perfect mirror and a glass sphere inside: light reaches the walls through
 * the mirror alone (the images'), through the glass, and through both (the map's). The
 * map of 10^6 photons is one random draw, which the 200,000 camera rays share: over
 * the whole box its error is that of ~10^5 stored photons (0.3% of a share of ~10%);
 * the radius 0.01 leaves a blur bias only along the box's edges (~0.1% of the walls'
 * area within reach of another wall). So the mean must be 2 within 4 standard errors
 * (the 99.99% level; seed 7). */
typedef struct {
    int images_at; /* the mirror's images at the first K diffuse vertices */
    int mis;
} FurnaceSetting;

/* The mirrored furnace with a sphere of material `ball` inside, estimated at each of
 * the settings. */
static void mirrored_furnace(Material ball, const FurnaceSetting *settings, int count)
{
    Scene scene;
    furnace_box_bordered(&scene);
    Material mirror = {.name = "mirror", .kind = MATERIAL_MIRROR, .reflectance = vec3(1, 1, 1)};
    int mirror_index = scene_add_material(&scene, mirror);
    Sphere sphere = {vec3(-0.2, 0.0, 0.0), 0.5, scene_add_material(&scene, ball)};
    assert_true(mirror_index >= 0 && sphere.material >= 0);
    for (int i = 0; i < scene.triangle_count; i++)
        if (scene.triangles[i].normal.x < -0.5)
            scene.triangles[i].material = mirror_index;
    assert_true(scene_add_sphere(&scene, sphere) >= 0);
    assert_int_equal(scene_prepare(&scene), 0);
    MirrorPlanes mirrors;
    assert_int_equal(mirror_light_find_planes(&scene, &mirrors), 0);
    PhotonMapSettings photons = {1000000, PHOTON_CAUSTIC, FRESNEL_EXACT, 5};
    PhotonMapSettings split_photons = photons;
    split_photons.paths = PHOTON_SPLIT;
    PhotonMap caustics, split;
    RayCounts counts = {0, 0, 0};
    assert_int_equal(ppm_photon_map(&caustics, &scene, &photons, 0.01, 0, &counts), 0);
    assert_int_equal(ppm_photon_map(&split, &scene, &split_photons, 0.01, 0, &counts), 0);
    print_message("    a %s sphere: %d photons stored of %d, %d of them in the split map\n",
                  ball.name, caustics.count, photons.emitted, split.count);
    for (int k = 0; k < count; k++) {
        CausticPathSettings c = {{.max_depth = 200,
                                  .shadow_rays = 1,
                                  .fresnel = FRESNEL_EXACT,
                                  .rr_throughput = 3,
                                  .mis = settings[k].mis,
                                  .mirror_light = settings[k].images_at,
                                  .mirrors = &mirrors,
                                  .sphere_guide = SPHERE_GUIDE_STRENGTH},
                                 &split,
                                 &caustics,
                                 0.01};
        double mean, std_error;
        /* The path settings are the first member: the estimator is handed the whole. */
        estimate(&scene, path_caustics_radiance, &c.path, vec3(0.6, 0.1, 0.05), 7, &mean,
                 &std_error);
        print_message("    images at the first %d diffuse vertices%s:\n", settings[k].images_at,
                      settings[k].mis ? ", mis" : "");
        assert_estimate(mean, std_error, FURNACE_BORDERED_RADIANCE, 0.01);
    }
    photon_map_free(&caustics);
    photon_map_free(&split);
    mirror_planes_free(&mirrors);
    scene_free(&scene);
}

/* The images at every diffuse vertex (chapter 7's), then at the first only (chapter
 * 8's): the caustic map brings L M D at the others. */
static void test_mirrored_glass_furnace(void **state)
{
    Material glass = {.name = "glass", .kind = MATERIAL_GLASS, .ior = 1.5};
    const FurnaceSetting settings[2] = {{200, 0}, {1, 0}};
    mirrored_furnace(glass, settings, 2);
}

/* A mirror sphere in place of the glass: a mirror, but not a planar one, so it has no
 * images; its light (L M D by the sphere) is the maps' at every vertex, the split
 * map's included, and never the path's, with mis or without. A sphere taken for the
 * planar mirror leaves that light out of the split map, or has the path add a share of
 * it that the map counts too. */
static void test_mirrored_mirror_sphere_furnace(void **state)
{
    Material ball = {.name = "mirror", .kind = MATERIAL_MIRROR, .reflectance = vec3(1, 1, 1)};
    const FurnaceSetting settings[2] = {{1, 0}, {1, 1}};
    mirrored_furnace(ball, settings, 2);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_room_without_specular_is_chapter7),
        cmocka_unit_test(test_empty_maps_are_chapter7_with_the_mirror_wall),
        cmocka_unit_test(test_room_converges_and_counts_once),
        cmocka_unit_test(test_mirrored_glass_furnace),
        cmocka_unit_test(test_mirrored_mirror_sphere_furnace),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
