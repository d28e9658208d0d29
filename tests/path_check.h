/* path_check.h (chapter 2): estimating a path tracer's mean radiance at a point, for the
 * furnace tests of every estimator (include after cmocka.h).
 *
 * The mean of the channels' average over SAMPLES rays from a point in uniformly random
 * directions, with the standard error of that mean from the samples' spread. A check
 * requires |mean - expected| < TOLERANCE_SIGMAS standard errors (a false failure about
 * once in 16,000 runs; the seeds are fixed, so a run is reproducible) and a standard
 * error small enough that a bias of a few percent would be seen.
 */
#ifndef PATH_CHECK_H
#define PATH_CHECK_H

#include "check.h"
#include "furnace.h"
#include "path.h"

#define SAMPLES 200000
#define TOLERANCE_SIGMAS 4.0

static inline void estimate(const Scene *scene, Estimator path, const PathSettings *settings,
                            Vec3 origin, uint64_t seed, double *mean, double *std_error)
{
    double sum = 0.0, sum_squares = 0.0;
    RayCounts counts = {0, 0, 0};
    for (int i = 0; i < SAMPLES; i++) {
        Rng rng = rng_for_sample(seed, 0, (uint64_t)i);
        double u1 = rng_uniform(&rng), u2 = rng_uniform(&rng);
        Ray ray = {origin, unit_vector_from(u1, u2)};
        double value = vec3_average(path(scene, ray, &rng, settings, &counts));
        sum += value;
        sum_squares += value * value;
    }
    *mean = sum / SAMPLES;
    *std_error = sqrt((sum_squares / SAMPLES - *mean * *mean) / (SAMPLES - 1));
}

/* |mean - expected| within TOLERANCE_SIGMAS standard errors (plus rounding, for the
 * zero-variance cases), and a standard error below max_relative_error * expected. */
static inline void assert_estimate(double mean, double std_error, double expected,
                                   double max_relative_error)
{
    print_message("    mean %.6f +- %.6f, expected %.6f\n", mean, std_error, expected);
    assert_true(fabs(mean - expected) <= TOLERANCE_SIGMAS * std_error + 1e-12 * expected);
    assert_true(std_error < max_relative_error * expected);
}

/* The uniform box of furnace.h (rho, Le = 1) gives `expected`. */
static inline void uniform_furnace(Estimator path, const PathSettings *settings, double rho,
                                   double expected)
{
    Scene scene;
    furnace_box_uniform(&scene, rho, 1.0);
    assert_int_equal(scene_prepare(&scene), 0);
    double mean, std_error;
    estimate(&scene, path, settings, vec3(0.1, -0.2, 0.3), 7, &mean, &std_error);
    assert_estimate(mean, std_error, expected, 0.01);
    scene_free(&scene);
}

/* A box of furnace.h whose radiance is 2 everywhere (for an unlimited depth). */
static inline void radiance_two_furnace(void (*make_box)(Scene *), Estimator path,
                                        const PathSettings *settings)
{
    Scene scene;
    make_box(&scene);
    assert_int_equal(scene_prepare(&scene), 0);
    double mean, std_error;
    estimate(&scene, path, settings, vec3(0.1, -0.2, 0.3), 7, &mean, &std_error);
    assert_estimate(mean, std_error, FURNACE_BORDERED_RADIANCE, 0.01);
    scene_free(&scene);
}

/* A coloured mirror in a glowing box: the uniform box with rho = 0 and Le = 1, and a
 * mirror sphere of reflectance (0.9, 0.5, 0.2) in it. A ray that meets the mirror is
 * reflected onto a wall, which adds Le weighted by the mirror's colour; the black wall
 * then adds nothing more (and its shadow rays, from chapter 3, see rho = 0). So every ray aimed
 * at the sphere returns exactly (0.9, 0.5, 0.2), and every ray that misses it exactly 1. A path
 * tracer that forgets the mirror's colour returns (1, 1, 1) for both: the room's only mirrors
 * are white, so no other test sees it. */
static inline void coloured_mirror(Estimator path, const PathSettings *settings,
                                   uint64_t stream)
{
    Scene scene;
    furnace_box_uniform(&scene, 0.0, 1.0);
    Material mirror = {
        .name = "mirror", .kind = MATERIAL_MIRROR, .reflectance = vec3(0.9, 0.5, 0.2)};
    Vec3 centre = vec3(0.4, 0.1, -0.2);
    assert_true(scene_add_sphere(
                    &scene, (Sphere){centre, 0.3, scene_add_material(&scene, mirror)}) >= 0);
    assert_int_equal(scene_prepare(&scene), 0);
    RayCounts counts = {0, 0, 0};
    for (int i = 0; i < 1000; i++) {
        Rng rng = rng_for_sample(21, stream, (uint64_t)i);
        /* Aimed at a point inside the sphere (within 0.15 sqrt 3 = 0.26 of its centre):
         * the ray meets its surface. */
        Vec3 offset =
            vec3(rng_uniform(&rng) - 0.5, rng_uniform(&rng) - 0.5, rng_uniform(&rng) - 0.5);
        Ray ray = ray_through(vec3(-0.5, 0, 0), vec3_add_scaled(centre, offset, 0.3));
        Vec3 hit = path(&scene, ray, &rng, settings, &counts);
        assert_true(fabs(hit.x - 0.9) < 1e-12 && fabs(hit.y - 0.5) < 1e-12 &&
                    fabs(hit.z - 0.2) < 1e-12);
        Vec3 away =
            path(&scene, (Ray){vec3(-0.5, 0, 0), vec3(-1, 0, 0)}, &rng, settings, &counts);
        assert_true(away.x == 1.0 && away.y == 1.0 && away.z == 1.0);
    }
    scene_free(&scene);
}

#endif
