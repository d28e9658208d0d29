/* test_path.c (chapter 2): Tests of the path tracer (lib/path.c; chapters 2, 3, 4, 6 and 7):
 * the estimators are unbiased, checked against closed forms and against each other on the
 * room; a coloured mirror and glass seen from outside have exact or closed-form answers too.
 *
 * White furnace (SPEC §7; the boxes are in furnace.h): in a closed box whose every
 * surface is Lambertian with reflectance rho and emits Le, the radiance everywhere is
 *     L = Le + rho L  =>  L = Le / (1 - rho),
 * and a path limited to D segments sees exactly the first D terms of that series,
 *     L_D = Le (1 - rho^D) / (1 - rho).
 * Each test averages many independent samples, computes the standard error of the mean
 * from their spread, and requires |mean - expected| < 4 standard errors (a false
 * failure about once in 16,000 runs; the seed is fixed, so a run is reproducible).
 * Each also requires the standard error to be small, so the test has the power to see
 * a bias of a few percent.
 *
 * Three facts these tests rely on, worth knowing:
 *   - in the uniform box, chapter 2's estimator has zero variance: every vertex adds Le
 *     and every bounce multiplies by rho, whatever the direction; its mean must then be
 *     exact (to rounding);
 *   - shadow rays in a box that emits up to its edges have infinite variance (furnace.h),
 *     so every test with shadow rays uses the bordered box, whose radiance is 2;
 *   - roulette multiplies the weight by rho / alpha at each survival, so the second
 *     moment is a geometric series in rho^2 / alpha: the variance is finite only for
 *     alpha > rho^2. The roulette tests choose rho and alpha on that side; below it, the
 *     measured standard error itself cannot be trusted (the room's alpha = 0.01 of
 *     Figure 12 is far below it, which is why that image is so noisy).
 * Chapter 7's estimators (mis, mirror_light) each get a furnace (the mirrored box of
 * furnace.h for the mirror's images) and a room agreement test. In the room, mis moves
 * little light (the lamp is seen from afar, where light sampling's density dwarfs the
 * BRDF's), so its furnace, whose lights are close, is the test with power for it.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include "chi_square.h"
#include "furnace.h"
#include "measure.h"
#include "path.h"
#include "scene_file.h"

#define SAMPLES 200000
#define TOLERANCE_SIGMAS 4.0

/* Mean radiance (average of the channels) and its standard error over SAMPLES rays
 * from `origin` in random directions. */
static void estimate(const Scene *scene, const PathSettings *settings, Vec3 origin,
                     uint64_t seed, double *mean, double *std_error)
{
    double sum = 0.0, sum_squares = 0.0;
    RayCounts counts = {0, 0, 0};
    for (int i = 0; i < SAMPLES; i++) {
        Rng rng = rng_for_sample(seed, 0, (uint64_t)i);
        double z = 2.0 * rng_uniform(&rng) - 1.0, phi = 2.0 * PI * rng_uniform(&rng);
        double r = sqrt(1.0 - z * z);
        Ray ray = {origin, vec3(r * cos(phi), r * sin(phi), z)};
        double value = vec3_average(path_radiance(scene, ray, &rng, settings, &counts));
        sum += value;
        sum_squares += value * value;
    }
    *mean = sum / SAMPLES;
    *std_error = sqrt((sum_squares / SAMPLES - *mean * *mean) / (SAMPLES - 1));
}

/* |mean - expected| within TOLERANCE_SIGMAS standard errors (plus rounding, for the
 * zero-variance cases), and a standard error below max_relative_error * expected. */
static void assert_close(double mean, double std_error, double expected, double max_relative_error)
{
    print_message("    mean %.6f +- %.6f, expected %.6f\n", mean, std_error, expected);
    assert_true(fabs(mean - expected) <= TOLERANCE_SIGMAS * std_error + 1e-12 * expected);
    assert_true(std_error < max_relative_error * expected);
}

/* The uniform box of furnace.h: rho, Le = 1. */
static void uniform_furnace(const PathSettings *settings, double rho, double expected)
{
    Scene scene;
    furnace_box_uniform(&scene, rho, 1.0);
    assert_int_equal(scene_prepare(&scene), 0);
    double mean, std_error;
    estimate(&scene, settings, vec3(0.1, -0.2, 0.3), 7, &mean, &std_error);
    assert_close(mean, std_error, expected, 0.01);
    scene_free(&scene);
}

#if CHAPTER >= 3
/* A box of furnace.h whose radiance is 2 everywhere (for an unlimited depth). */
static void radiance_two_furnace(void (*make_box)(Scene *), const PathSettings *settings)
{
    Scene scene;
    make_box(&scene);
    assert_int_equal(scene_prepare(&scene), 0);
    double mean, std_error;
    estimate(&scene, settings, vec3(0.1, -0.2, 0.3), 7, &mean, &std_error);
    assert_close(mean, std_error, FURNACE_BORDERED_RADIANCE, 0.01);
    scene_free(&scene);
}

static void bordered_furnace(const PathSettings *settings)
{
    radiance_two_furnace(furnace_box_bordered, settings);
}
#endif

/* Chapter 2's estimator (no shadow rays, no roulette) with depth D sees the first D
 * terms of the series: rho = 0.5, D = 6 gives (1 - 0.5^6) / 0.5 = 1.96875. */
static void test_furnace_chapter2_truncated_series(void **state)
{
    (void)state;
    PathSettings settings = {.max_depth = 6};
    uniform_furnace(&settings, 0.5, (1.0 - pow(0.5, 6)) / 0.5);
}

#if CHAPTER >= 3
/* Chapter 3's estimator, one and four shadow rays, no roulette; depth 40 leaves out
 * ~1e-7 of the series (furnace.h). */
static void test_furnace_chapter3_shadow_rays(void **state)
{
    (void)state;
    PathSettings one = {.max_depth = 40, .shadow_rays = 1};
    bordered_furnace(&one);
    PathSettings four = {.max_depth = 40, .shadow_rays = 4};
    bordered_furnace(&four);
}
#endif

#if CHAPTER >= 6
/* Chapter 6's estimator (roulette alpha = 0.75, depth practically unlimited), with and
 * without shadow rays. */
static void test_furnace_chapter6_roulette(void **state)
{
    (void)state;
    PathSettings hitting = {.max_depth = 200, .rr_survival = 0.75};
    bordered_furnace(&hitting);
    PathSettings shadow = {.max_depth = 200, .shadow_rays = 1, .rr_survival = 0.75};
    bordered_furnace(&shadow);
}
#endif

#if CHAPTER >= 6
/* Roulette with bounded weights (roulette.h) from the first segment and from the third,
 * with and without shadow rays, in the bordered box. */
static void test_furnace_chapter6_bounded_roulette(void **state)
{
    (void)state;
    PathSettings hitting = {.max_depth = 200, .rr_throughput = 1};
    bordered_furnace(&hitting);
    PathSettings shadow = {.max_depth = 200, .shadow_rays = 1, .rr_throughput = 3};
    bordered_furnace(&shadow);
}

/* A bright uniform box, rho = 0.9, no shadow rays: the survival probability is then 0.9
 * at every bounce after the first (the throughput is 1 after each survival), paths are
 * long (mean 10 segments), and the mean must match (1 - 0.9^200) / 0.1. */
static void test_bounded_roulette_on_a_bright_furnace(void **state)
{
    (void)state;
    PathSettings bounded = {.max_depth = 200, .rr_throughput = 1};
    uniform_furnace(&bounded, 0.9, (1.0 - pow(0.9, 200)) / 0.1);
}
#endif

#if CHAPTER >= 7
/* Multiple importance sampling (mis.h), one and four shadow rays: the power heuristic's
 * weights of the two ways of finding each light sum to 1, so the mean stays 2. */
static void test_furnace_chapter7_mis(void **state)
{
    (void)state;
    PathSettings one = {.max_depth = 40, .shadow_rays = 1, .mis = 1};
    bordered_furnace(&one);
    PathSettings four = {.max_depth = 40, .shadow_rays = 4, .mis = 1, .rr_throughput = 3};
    bordered_furnace(&four);
}

/* The lights seen in a mirror wall (mirror_light.h), in the box with one mirror wall:
 * without shadow rays (the reference: light found only by hitting it), with shadow rays
 * alone, with the mirror's images at every diffuse hit, and at the first two only with
 * mis (later hits find that light by hitting it). Each must give 2. Bounded roulette
 * keeps the long paths that the mirror allows cheap (depth 200). */
static void test_furnace_chapter7_mirror_light(void **state)
{
    (void)state;
    PathSettings hitting = {.max_depth = 200, .rr_throughput = 3};
    radiance_two_furnace(furnace_box_mirrored, &hitting);
    PathSettings shadow = {.max_depth = 200, .shadow_rays = 1, .rr_throughput = 3};
    radiance_two_furnace(furnace_box_mirrored, &shadow);
    PathSettings mirror = {.max_depth = 200, .shadow_rays = 1, .rr_throughput = 3, .mirror_light = 200};
    radiance_two_furnace(furnace_box_mirrored, &mirror);
    PathSettings both = {.max_depth = 200, .shadow_rays = 2, .rr_throughput = 3, .mis = 1,
                         .mirror_light = 2};
    radiance_two_furnace(furnace_box_mirrored, &both);
}
#endif

/* Reflectance 0 and 1 (SPEC §7): rho = 0 sees only the emission (with shadow rays too:
 * they meet rho = 0); rho = 1 with depth D sees exactly D times it (every term of the
 * series is Le). Both have zero variance. */
static void test_furnace_reflectance_extremes(void **state)
{
    (void)state;
    PathSettings black = {.max_depth = 10};
    uniform_furnace(&black, 0.0, 1.0);
#if CHAPTER >= 6
    PathSettings black_shadow = {.max_depth = 10, .shadow_rays = 1, .rr_survival = 0.5};
    uniform_furnace(&black_shadow, 0.0, 1.0);
#endif
    PathSettings white = {.max_depth = 10};
    uniform_furnace(&white, 1.0, 10.0);
}

#if CHAPTER >= 6
/* Roulette is unbiased (chapter 6 "must show"): in the uniform furnace, alpha = 0.05,
 * 0.5 and 1 give the same mean within their combined standard errors. rho = 0.2, so
 * that even alpha = 0.05 > rho^2 = 0.04 has finite variance; no shadow rays, so the
 * only variance is roulette's. */
static void test_roulette_unbiased(void **state)
{
    (void)state;
    Scene scene;
    furnace_box_uniform(&scene, 0.2, 1.0);
    assert_int_equal(scene_prepare(&scene), 0);
    const double alphas[] = {0.05, 0.5, 1.0};
    double means[3], errors[3];
    for (int i = 0; i < 3; i++) {
        PathSettings settings = {.max_depth = 40, .rr_survival = alphas[i]};
        estimate(&scene, &settings, vec3(0.3, 0.3, -0.5), 11 + (uint64_t)i, &means[i], &errors[i]);
        print_message("    alpha %.2f: %.5f +- %.5f\n", alphas[i], means[i], errors[i]);
    }
    for (int i = 0; i < 3; i++)
        for (int j = i + 1; j < 3; j++)
            assert_true(fabs(means[i] - means[j]) <
                        TOLERANCE_SIGMAS * sqrt(errors[i] * errors[i] + errors[j] * errors[j]));
    /* And they all agree with the closed form, (1 - 0.2^40) / (1 - 0.2). */
    for (int i = 0; i < 3; i++)
        assert_close(means[i], errors[i], (1.0 - pow(0.2, 40)) / 0.8, 0.02);
    scene_free(&scene);
}
#endif

/* A coloured mirror in a glowing box: furnace.h's uniform box with rho = 0 and Le = 1,
 * and a mirror sphere of reflectance (0.9, 0.5, 0.2) in it. A ray that meets the mirror
 * is reflected onto a wall, which adds Le weighted by the mirror's colour; the black
 * wall then adds nothing more (and its shadow rays see rho = 0). So every ray aimed
 * at the sphere returns exactly (0.9, 0.5, 0.2), with or without shadow rays, and every
 * ray that misses it exactly 1. A path tracer that forgets the mirror's colour returns
 * (1, 1, 1) for both: the room's only mirrors are white, so no other test sees it. */
static void test_coloured_mirror(void **state)
{
    (void)state;
    Scene scene;
    furnace_box_uniform(&scene, 0.0, 1.0);
    Material mirror = {"mirror", MATERIAL_MIRROR, vec3(0.9, 0.5, 0.2), vec3(0, 0, 0), 0.0, 1.0};
    Vec3 centre = vec3(0.4, 0.1, -0.2);
    assert_true(scene_add_sphere(&scene, (Sphere){centre, 0.3, scene_add_material(&scene, mirror)}) >= 0);
    assert_int_equal(scene_prepare(&scene), 0);
    RayCounts counts = {0, 0, 0};
#if CHAPTER >= 3
    const int shadow_ray_counts = 2; /* M = 0 and M = 1 */
#else
    const int shadow_ray_counts = 1;
#endif
    for (int m = 0; m < shadow_ray_counts; m++) {
        PathSettings settings = {.max_depth = 10};
#if CHAPTER >= 3
        settings.shadow_rays = m;
#endif
        for (int i = 0; i < 1000; i++) {
            Rng rng = rng_for_sample(21, (uint64_t)m, (uint64_t)i);
            /* Aimed at a point inside the sphere (within 0.15 sqrt 3 = 0.26 of its centre):
             * the ray meets its surface. */
            Vec3 offset = vec3(rng_uniform(&rng) - 0.5, rng_uniform(&rng) - 0.5, rng_uniform(&rng) - 0.5);
            Vec3 origin = vec3(-0.5, 0, 0), target = vec3_add_scaled(centre, offset, 0.3);
            Ray ray = {origin, vec3_normalize(vec3_sub(target, origin))};
            Vec3 hit = path_radiance(&scene, ray, &rng, &settings, &counts);
            assert_true(fabs(hit.x - 0.9) < 1e-12 && fabs(hit.y - 0.5) < 1e-12 &&
                        fabs(hit.z - 0.2) < 1e-12);
            Vec3 away = path_radiance(&scene, (Ray){vec3(-0.5, 0, 0), vec3(-1, 0, 0)}, &rng,
                                      &settings, &counts);
            assert_true(away.x == 1.0 && away.y == 1.0 && away.z == 1.0);
        }
    }
    scene_free(&scene);
}

/* Glass seen from outside, at normal incidence: a glass sphere (index 1.5) in a box of
 * lamps, the wall behind the camera red (1, 0, 0), the other five blue (0, 0, 1). A ray
 * along the sphere's axis meets both surfaces head on, where R = (0.5 / 2.5)^2 = 0.04
 * (Schlick and exact agree there). Each time it reflects (probability R) it turns back;
 * each time it refracts it goes on along the axis. It leaves towards the red wall after
 * an odd number of reflections, so the red share is
 *     R + (1 - R)^2 R (1 + R^2 + R^4 + ...) = 2 R / (1 + R) = 0.076923,
 * and every sample is either red or blue, nothing lost. 200,000 samples, within 4
 * standard errors (about 0.0024). Glass that refracts with probability R instead of
 * 1 - R turns back 96% of the time at the first surface, and a ray that got in mostly
 * stays trapped: red share 0.978 (the planted bug). (Until now only rays that start
 * inside a sphere, test_glass_furnace.c, could tell.) */
static void test_glass_from_outside_at_normal_incidence(void **state)
{
    (void)state;
    Scene scene;
    scene_init(&scene);
    Material red = {"red", MATERIAL_LIGHT, vec3(0, 0, 0), vec3(1, 0, 0), 0.0, 1.0};
    Material blue = {"blue", MATERIAL_LIGHT, vec3(0, 0, 0), vec3(0, 0, 1), 0.0, 1.0};
    Material glass = {"glass", MATERIAL_GLASS, vec3(0, 0, 0), vec3(0, 0, 0), 0.0, 1.5};
    int red_index = scene_add_material(&scene, red), blue_index = scene_add_material(&scene, blue);
    for (int axis = 0; axis < 3; axis++)
        for (int side = -1; side <= 1; side += 2)
            furnace_wall_piece(&scene, axis, side, -1.0, 1.0, -1.0, 1.0,
                               axis == 0 && side < 0 ? red_index : blue_index);
    assert_true(scene_add_sphere(&scene, (Sphere){vec3(0.3, 0, 0), 0.3,
                                                  scene_add_material(&scene, glass)}) >= 0);
    assert_int_equal(scene_prepare(&scene), 0);
    const double r = 0.04, expected = 2.0 * r / (1.0 + r);
#if CHAPTER >= 4
    const FresnelMode modes[2] = {FRESNEL_SCHLICK, FRESNEL_EXACT};
    const int mode_count = 2;
#else
    const int mode_count = 1; /* Schlick's, until chapter 4 */
#endif
    for (int k = 0; k < mode_count; k++) {
        PathSettings settings = {.max_depth = 64};
#if CHAPTER >= 4
        settings.fresnel = modes[k];
        const char *mode_name = modes[k] == FRESNEL_EXACT ? "exact" : "Schlick";
#else
        const char *mode_name = "Schlick";
#endif
        RayCounts counts = {0, 0, 0};
        double red_share = 0.0;
        int lost = 0;
        for (int i = 0; i < SAMPLES; i++) {
            Rng rng = rng_for_sample(31, (uint64_t)k, (uint64_t)i);
            Vec3 radiance = path_radiance(&scene, (Ray){vec3(-0.5, 0, 0), vec3(1, 0, 0)}, &rng,
                                          &settings, &counts);
            lost += !(radiance.y == 0.0 && radiance.x + radiance.z == 1.0);
            red_share += radiance.x / SAMPLES;
        }
        double std_error = sqrt(expected * (1.0 - expected) / SAMPLES);
        print_message("    %s: red share %.5f, expected %.5f +- %.5f; %d samples neither red nor blue\n",
                      mode_name, red_share, expected, std_error,
                      lost);
        assert_true(fabs(red_share - expected) < TOLERANCE_SIGMAS * std_error);
        assert_int_equal(lost, 0);
    }
    scene_free(&scene);
}

#if CHAPTER >= 3
/* Chapter 3's estimator (shadow rays) converges to chapter 2's (light found only by
 * hitting it) on the report's room, glass and mirrors included. The image is cut into
 * 3 x 3-pixel blocks; for each block and channel, z = (a - b) / sqrt(se_a^2 + se_b^2)
 * of the two block means should be a standard normal variable, so the sum of z^2 over
 * the N block channels is chi-square with N degrees of freedom. (Blocks rather than
 * single pixels: chapter 2's estimator finds the lamp rarely, so one pixel's standard
 * error is itself noisy and its z heavy-tailed; averaging nine pixels tames that.)
 * A double-counted or missing light path, the classic bug when shadow rays are added,
 * shifts every block by many standard errors. Significance level 0.1%, fixed seeds;
 * other seeds gave p from 0.02 to 0.85. */
#define BLOCK 3
#define SIDE 12

static void block_means(const RenderResult *r, int bx, int by, int c, double *mean, double *se)
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

/* Estimators a (spp_a samples) and b (spp_b) agree on a scene at SIDE x SIDE pixels:
 * the block chi-square above at significance level 0.1%, and the image means within 4
 * standard errors. */
static void assert_agree_on(const Scene *scene, const PathSettings *a_settings, int spp_a,
                            const PathSettings *b_settings, int spp_b)
{
    RenderSettings first = {SIDE, SIDE, spp_a, PIXEL_RANDOM, 0, 1, 0, "test"};
    RenderSettings second = {SIDE, SIDE, spp_b, PIXEL_RANDOM, 0, 2, 0, "test"};
    RenderResult a, b;
    assert_int_equal(render(scene, &first, path_radiance, a_settings, &a), 0);
    assert_int_equal(render(scene, &second, path_radiance, b_settings, &b), 0);
    double sum_z2 = 0.0, largest = 0.0;
    int n = 0;
    for (int by = 0; by < SIDE / BLOCK; by++)
        for (int bx = 0; bx < SIDE / BLOCK; bx++)
            for (int c = 0; c < 3; c++) {
                double mean_a, se_a, mean_b, se_b;
                block_means(&a, bx, by, c, &mean_a, &se_a);
                block_means(&b, bx, by, c, &mean_b, &se_b);
                double z = (mean_a - mean_b) / sqrt(se_a * se_a + se_b * se_b);
                sum_z2 += z * z;
                largest = fmax(largest, fabs(z));
                n++;
            }
    double p = chi_square_p_value(sum_z2, n);
    double mean_a, error_a, mean_b, error_b;
    measure_image_mean(&a.image, &a.average_std_error, &mean_a, &error_a);
    measure_image_mean(&b.image, &b.average_std_error, &mean_b, &error_b);
    char text_a[96], text_b[96];
    describe_path(a_settings, text_a, sizeof text_a);
    describe_path(b_settings, text_b, sizeof text_b);
    print_message("    image means: %s %.5f +- %.5f, %s %.5f +- %.5f\n", text_a, mean_a,
                  error_a, text_b, mean_b, error_b);
    print_message("    sum of z^2 = %.1f over %d block channels (p = %.3f), largest |z| %.2f\n",
                  sum_z2, n, p, largest);
    assert_true(p > 0.001);
    assert_true(fabs(mean_a - mean_b) < 4.0 * sqrt(error_a * error_a + error_b * error_b));
    render_result_free(&a);
    render_result_free(&b);
}

static void assert_agree_on_the_room(const PathSettings *a_settings, int spp_a,
                                     const PathSettings *b_settings, int spp_b)
{
    Scene scene;
    char error[256];
    assert_int_equal(scene_load("scenes/room.scene", &scene, error, sizeof error), 0);
    assert_agree_on(&scene, a_settings, spp_a, b_settings, spp_b);
    scene_free(&scene);
}

static void test_shadow_rays_agree_with_hitting_on_the_room(void **state)
{
    (void)state;
    PathSettings hitting = {.max_depth = 6}, shadow = {.max_depth = 6, .shadow_rays = 1};
    assert_agree_on_the_room(&hitting, 2000, &shadow, 400);
}

#if CHAPTER >= 6
/* On the room: bounded roulette (from segment 2) agrees with no roulette at the same
 * depth limit, shadow rays in both. */
static void test_bounded_roulette_agrees_on_the_room(void **state)
{
    (void)state;
    PathSettings plain = {.max_depth = 8, .shadow_rays = 1};
    PathSettings bounded = {.max_depth = 8, .shadow_rays = 1, .rr_throughput = 2};
    assert_agree_on_the_room(&plain, 400, &bounded, 400);
}
#endif

#if CHAPTER >= 7
/* A tinted mirror (reflectance 0.5, 0.4, 0.3) in the mirrored box, depth limit 3: no
 * closed form, but shadow rays alone and with the mirror's images must agree (each
 * within its standard error; the box has little noise, so this sees 0.2%). With depth
 * 3 only a diffuse hit on the first segment may use the images (two more segments). */
static void test_mirror_light_agrees_at_a_depth_limit(void **state)
{
    (void)state;
    Scene scene;
    furnace_box_mirrored(&scene);
    scene.materials[scene.material_count - 1].reflectance = vec3(0.5, 0.4, 0.3);
    assert_int_equal(scene_prepare(&scene), 0);
    PathSettings plain = {.max_depth = 3, .shadow_rays = 1};
    PathSettings image = {.max_depth = 3, .shadow_rays = 1, .mirror_light = 3};
    double mean_plain, error_plain, mean_image, error_image;
    estimate(&scene, &plain, vec3(0.1, -0.2, 0.3), 100, &mean_plain, &error_plain);
    estimate(&scene, &image, vec3(0.1, -0.2, 0.3), 101, &mean_image, &error_image);
    print_message("    shadow rays %.5f +- %.5f, with the images %.5f +- %.5f\n", mean_plain,
                  error_plain, mean_image, error_image);
    assert_true(fabs(mean_plain - mean_image) <
                TOLERANCE_SIGMAS * sqrt(error_plain * error_plain + error_image * error_image));
    scene_free(&scene);
}

/* On the room: multiple importance sampling agrees with shadow rays alone. */
static void test_mis_agrees_on_the_room(void **state)
{
    (void)state;
    PathSettings plain = {.max_depth = 6, .shadow_rays = 1};
    PathSettings mis = {.max_depth = 6, .shadow_rays = 2, .mis = 1};
    assert_agree_on_the_room(&plain, 400, &mis, 300);
}

/* On the room, the mirror wall's image of the lamp agrees with shadow rays alone: at
 * every diffuse hit, and with mis at the first one only. The mirror is tinted
 * (reflectance 0.5, 0.7, 0.9 instead of 1) so that its reflectance must be applied to
 * the image's light. The depth limit 6 makes the mirror light's own limit matter (a
 * diffuse hit on segment 5 may not use it). */
static void test_mirror_light_agrees_on_the_room(void **state)
{
    (void)state;
    Scene scene;
    char error[256];
    assert_int_equal(scene_load("scenes/room.scene", &scene, error, sizeof error), 0);
    int mirror = scene_find_material(&scene, "mirror");
    assert_true(mirror >= 0);
    scene.materials[mirror].reflectance = vec3(0.5, 0.7, 0.9);
    PathSettings plain = {.max_depth = 6, .shadow_rays = 1};
    PathSettings image = {.max_depth = 6, .shadow_rays = 1, .mirror_light = 6};
    assert_agree_on(&scene, &plain, 2000, &image, 2000);
    PathSettings both = {.max_depth = 6, .shadow_rays = 2, .mis = 1, .mirror_light = 1};
    assert_agree_on(&scene, &plain, 2000, &both, 1000);
    scene_free(&scene);
}
#endif
#endif

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_furnace_chapter2_truncated_series),
        cmocka_unit_test(test_coloured_mirror),
        cmocka_unit_test(test_glass_from_outside_at_normal_incidence),
#if CHAPTER >= 3
        cmocka_unit_test(test_furnace_chapter3_shadow_rays),
        cmocka_unit_test(test_shadow_rays_agree_with_hitting_on_the_room),
#endif
#if CHAPTER >= 6
        cmocka_unit_test(test_furnace_chapter6_roulette),
        cmocka_unit_test(test_roulette_unbiased),
        cmocka_unit_test(test_furnace_chapter6_bounded_roulette),
        cmocka_unit_test(test_bounded_roulette_on_a_bright_furnace),
        cmocka_unit_test(test_bounded_roulette_agrees_on_the_room),
#endif
#if CHAPTER >= 7
        cmocka_unit_test(test_furnace_chapter7_mis),
        cmocka_unit_test(test_furnace_chapter7_mirror_light),
        cmocka_unit_test(test_mirror_light_agrees_at_a_depth_limit),
        cmocka_unit_test(test_mis_agrees_on_the_room),
        cmocka_unit_test(test_mirror_light_agrees_on_the_room),
#endif
        cmocka_unit_test(test_furnace_reflectance_extremes),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
