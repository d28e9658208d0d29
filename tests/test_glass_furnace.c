/* test_glass_furnace.c (chapter 4): the glass furnace: a glass sphere in a closed box
 * of uniform radiance is invisible (lib/glass.c through the path tracers).
 *
 * In a closed box where every surface sends out L = Le + rho L, whatever arrives, the
 * radiance is L at every point and in every direction (the white furnace of
 * test_path.c, where L = Le / (1 - rho)). Put a glass sphere in the box and nothing
 * changes:
 *   - glass neither absorbs nor emits;
 *   - at each interface the path tracer reflects with probability R and refracts with
 *     probability 1 - R, with weight 1 either way, so its expected value is
 *     R L_reflected + (1 - R) L_refracted: splitting by R is unbiased, and in a field
 *     where both are L the result is L again, whatever R is.
 * So the glass must be invisible with Schlick's R and with the exact Fresnel R, through
 * total internal reflection, and with shadow rays that the sphere blocks (the light they
 * miss is found by the paths that cross the glass: after a specular bounce the path
 * tracer adds the emission it hits). The path tracer carries radiance across a
 * refraction unchanged (no factor n^2: it computes L / n^2, which is L in the air where
 * the camera is), so along rays that start INSIDE the sphere it is L as well.
 *
 * The test fails if glass loses or creates energy: a wrong branch weight, a refracted ray
 * started on the wrong side of the surface (self-intersection), light counted twice or
 * not at all after a glass bounce. It cannot tell whether R itself is right
 * (test_fresnel.c checks that).
 *
 * The box is furnace.h's bordered one (radiance 2 everywhere, and shadow rays of finite
 * variance: with walls emitting up to their edges, a trial of 120 seeds with one shadow
 * ray had 7 runs fail the criteria below, one giving 2.37 +- 0.35; with the border, the
 * z-scores had mean 0.06 and spread 1.01, all within 2.2).
 *
 * Each estimate averages many independent rays and requires |mean - 2| < 4 standard
 * errors (a false failure about once in 16,000 runs; the seed is fixed, so a run is
 * reproducible) and a standard error below 1% of 2, so that a bias of a few percent
 * would be seen.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include "furnace.h"
#include "path_direct.h"
#if CHAPTER >= 6
#include "path_roulette.h"
#endif

#define TOLERANCE_SIGMAS 4.0
#define EXPECTED FURNACE_BORDERED_RADIANCE

/* The rays aimed at the sphere leave it towards the middle of the wall x = -1. */
static const Vec3 SPHERE_CENTRE = {-0.2, 0.0, 0.0};
#define SPHERE_RADIUS 0.5
static const Vec3 OUTSIDE_POINT = {0.6, 0.1, 0.05};  /* in the box, outside the sphere */
static const Vec3 INSIDE_POINT = {-0.1, 0.15, -0.1}; /* in the sphere, off its centre */

/* furnace.h's bordered box with a glass sphere of index 1.5 in it. */
static void glass_furnace_box(Scene *scene)
{
    furnace_box_bordered(scene);
    Material glass = {.name = "glass", .kind = MATERIAL_GLASS, .ior = 1.5};
    Sphere sphere = {SPHERE_CENTRE, SPHERE_RADIUS, scene_add_material(scene, glass)};
    assert_true(scene_add_sphere(scene, sphere) >= 0);
    assert_int_equal(scene_prepare(scene), 0);
}

static Vec3 uniform_direction(Rng *rng)
{
    double z = 2.0 * rng_uniform(rng) - 1.0, phi = 2.0 * PI * rng_uniform(rng);
    double r = sqrt(1.0 - z * z);
    return vec3(r * cos(phi), r * sin(phi), z);
}

/* The three kinds of ray the test follows. */
typedef enum {
    FROM_OUTSIDE,
    AT_THE_SPHERE,
    FROM_INSIDE
} RayKind;
static const char *const KIND_NAMES[] = {"outside, any direction",
                                         "outside, aimed at the sphere", "inside the sphere"};

static Ray ray_of_kind(RayKind kind, Rng *rng)
{
    if (kind == FROM_INSIDE)
        return (Ray){INSIDE_POINT, uniform_direction(rng)};
    if (kind == FROM_OUTSIDE)
        return (Ray){OUTSIDE_POINT, uniform_direction(rng)};
    /* Towards a point inside the sphere (within 0.9 of its radius), so it hits it. */
    Vec3 target = vec3_add_scaled(SPHERE_CENTRE, uniform_direction(rng),
                                  0.9 * SPHERE_RADIUS * rng_uniform(rng));
    return (Ray){OUTSIDE_POINT, vec3_normalize(vec3_sub(target, OUTSIDE_POINT))};
}

/* How an estimator is checked: how many rays of each kind, and how far below
 * Le / (1 - rho) its depth limit may leave the mean. */
typedef struct {
    Estimator estimate;
    int samples;
    double truncation;
} Check;

/* Without roulette, every path runs to the depth limit of 60 (40 left a bias of 5e-5,
 * five standard errors of the light-by-hitting estimate, whose variance is tiny in the
 * furnace). A ray trapped inside the sphere by total internal reflection can still
 * reach it: about 2e-7 is left out. */
static const Check DEPTH_60 = {path_direct_radiance, 20000, 1e-6};

/* The mean radiance (average of the channels) along the check's rays of one kind, with
 * its standard error, checked against Le / (1 - rho). */
static void assert_furnace_radiance(const Scene *scene, const Check *check,
                                    const PathSettings *settings, RayKind kind, uint64_t seed)
{
    double sum = 0.0, sum_squares = 0.0;
    RayCounts counts = {0, 0, 0};
    for (int i = 0; i < check->samples; i++) {
        Rng rng = rng_for_sample(seed, (uint64_t)kind, (uint64_t)i);
        double value = vec3_average(
            check->estimate(scene, ray_of_kind(kind, &rng), &rng, settings, &counts));
        sum += value;
        sum_squares += value * value;
    }
    double mean = sum / check->samples;
    double std_error =
        sqrt((sum_squares / check->samples - mean * mean) / (check->samples - 1));
    print_message("    %-30s M=%d %-7s: %.9f +- %.9f (expected %.1f)\n", KIND_NAMES[kind],
                  settings->shadow_rays,
                  settings->fresnel == FRESNEL_EXACT ? "exact" : "schlick", mean, std_error,
                  EXPECTED);
    assert_true(fabs(mean - EXPECTED) < TOLERANCE_SIGMAS * std_error + check->truncation);
    assert_true(std_error < 0.01 * EXPECTED);
}

/* Every kind of ray sees Le / (1 - rho) with these settings. */
static void glass_furnace(const Check *check, const PathSettings *settings)
{
    Scene scene;
    glass_furnace_box(&scene);
    for (RayKind kind = FROM_OUTSIDE; kind <= FROM_INSIDE; kind++)
        assert_furnace_radiance(&scene, check, settings, kind, 17);
    scene_free(&scene);
}

/* Chapter 2's way of finding light (M = 0: only by hitting it), Schlick's R. */
static void test_glass_invisible_hitting_schlick(void **state)
{
    PathSettings settings = {.max_depth = 60, .fresnel = FRESNEL_SCHLICK};
    glass_furnace(&DEPTH_60, &settings);
}

/* The same with the exact Fresnel R. */
static void test_glass_invisible_hitting_exact(void **state)
{
    PathSettings settings = {.max_depth = 60, .fresnel = FRESNEL_EXACT};
    glass_furnace(&DEPTH_60, &settings);
}

/* One shadow ray per diffuse hit (chapter 3), some of them blocked by the sphere: the
 * light behind it arrives through the paths that cross the glass instead. Schlick. */
static void test_glass_invisible_shadow_rays_schlick(void **state)
{
    PathSettings settings = {.max_depth = 60, .shadow_rays = 1, .fresnel = FRESNEL_SCHLICK};
    glass_furnace(&DEPTH_60, &settings);
}

/* The same with the exact Fresnel R. */
static void test_glass_invisible_shadow_rays_exact(void **state)
{
    PathSettings settings = {.max_depth = 60, .shadow_rays = 1, .fresnel = FRESNEL_EXACT};
    glass_furnace(&DEPTH_60, &settings);
}

#if CHAPTER >= 6
/* Chapter 6's estimator, roulette alpha = 0.75 with depth 200, practically unlimited
 * (furnace.h: finite second moment): nothing is left out. Both ways of finding light,
 * both reflectances. */
static void test_glass_invisible_with_roulette(void **state)
{
    const Check roulette = {path_roulette_radiance, 100000, 0.0};
    const FresnelMode modes[2] = {FRESNEL_SCHLICK, FRESNEL_EXACT};
    for (int m = 0; m <= 1; m++)
        for (int k = 0; k < 2; k++) {
            PathSettings settings = {
                .max_depth = 200, .shadow_rays = m, .fresnel = modes[k], .rr_survival = 0.75};
            glass_furnace(&roulette, &settings);
        }
}
#endif

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_glass_invisible_hitting_schlick),
        cmocka_unit_test(test_glass_invisible_hitting_exact),
        cmocka_unit_test(test_glass_invisible_shadow_rays_schlick),
        cmocka_unit_test(test_glass_invisible_shadow_rays_exact),
#if CHAPTER >= 6
        cmocka_unit_test(test_glass_invisible_with_roulette),
#endif
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
