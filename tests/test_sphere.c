/* test_sphere.c (chapter 1): ray-sphere intersection (sphere.h, report §3.6.2, eqs. 19-20,
 * chapter 1).
 *
 * Known hits, misses, rays from inside (the far root: glass spheres are traced from
 * within), the tangent ray, the (tmin, tmax) window, and precision at the extremes:
 * a sphere of radius 1e-3 seen from 1e3 away, and whole set-ups scaled by 1e-3 and 1e3.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include "check.h"
#include "sphere.h"

/* Scale factors of the whole set-up: scenes are tested at 1e-3 and 1e3. */
static const double scales[] = {1e-3, 1.0, 1e3};

/* From outside, at every scale: straight at the centre t = distance - radius; along
 * (0, 0.6, 0.8) towards a sphere of radius 4 at distance 5, t^2 - 8t + 9 = 0 gives
 * t = 4 - sqrt(7). */
static void test_hit_from_outside(void **state)
{
    for (int i = 0; i < 3; i++) {
        double s = scales[i];
        Sphere sphere = {vec3(0, 0, 5 * s), 1 * s, 0};
        Ray head_on = {vec3(0, 0, 0), vec3(0, 0, 1)};
        assert_close(sphere_intersect(&sphere, head_on, 0, INFINITY), 4 * s, 1e-15 * s);
        Sphere big = {vec3(0, 0, 5 * s), 4 * s, 0};
        Ray oblique = {vec3(0, 0, 0), vec3(0, 0.6, 0.8)};
        assert_close(sphere_intersect(&big, oblique, 0, INFINITY), (4 - sqrt(7)) * s,
                     1e-15 * s);
    }
}

/* A ray that passes beside the sphere, and one that points away from it, miss. */
static void test_miss(void **state)
{
    Sphere sphere = {vec3(0, 0, 5), 1, 0};
    Ray beside = {vec3(0, 1.5, 0), vec3(0, 0, 1)};
    Ray away = {vec3(0, 0, 0), vec3(1, 0, 0)};
    assert_true(isinf(sphere_intersect(&sphere, beside, 0, INFINITY)));
    assert_true(isinf(sphere_intersect(&sphere, away, 0, INFINITY)));
}

/* A sphere wholly behind the ray's origin is not hit (both roots negative). */
static void test_behind_origin(void **state)
{
    Sphere sphere = {vec3(0, 0, -5), 1, 0};
    Ray ray = {vec3(0, 0, 0), vec3(0, 0, 1)};
    assert_true(isinf(sphere_intersect(&sphere, ray, 0, INFINITY)));
}

/* From inside the near root is negative, so the far root is returned: from the
 * centre t = r in every direction; from off-centre the chord's far end. */
static void test_from_inside(void **state)
{
    TestRandom rng = test_random(1, 2, 3);
    for (int i = 0; i < 3; i++) {
        double s = scales[i];
        Sphere sphere = {vec3(2 * s, -1 * s, 5 * s), 1 * s, 0};
        for (int k = 0; k < 100; k++) {
            Ray ray = {sphere.center, random_unit_vector(&rng)};
            assert_close(sphere_intersect(&sphere, ray, 0, INFINITY), s, 1e-15 * s);
        }
        Ray up = {vec3(2 * s, -1 * s, 5.5 * s), vec3(0, 0, 1)};
        Ray down = {up.origin, vec3(0, 0, -1)};
        assert_close(sphere_intersect(&sphere, up, 0, INFINITY), 0.5 * s, 1e-15 * s);
        assert_close(sphere_intersect(&sphere, down, 0, INFINITY), 1.5 * s, 1e-15 * s);
    }
}

/* The tangent ray, discriminant exactly 0 (b^2 == c: from (-5,1,0) along x past the
 * unit sphere at the origin), touches at t = 5. Rays 1e-12 inside the tangent hit
 * near there; 1e-12 outside miss. */
static void test_tangent(void **state)
{
    Sphere sphere = {vec3(0, 0, 0), 1, 0};
    Ray tangent = {vec3(-5, 1, 0), vec3(1, 0, 0)};
    assert_close(sphere_intersect(&sphere, tangent, 0, INFINITY), 5, 1e-15);
    Ray inside = {vec3(-5, 1 - 1e-12, 0), vec3(1, 0, 0)};
    double t = sphere_intersect(&sphere, inside, 0, INFINITY);
    assert_close(t, 5 - sqrt(2e-12), 1e-9);
    Ray outside = {vec3(-5, 1 + 1e-12, 0), vec3(1, 0, 0)};
    assert_true(isinf(sphere_intersect(&sphere, outside, 0, INFINITY)));
}

/* Only roots in (tmin, tmax) count: the roots of the head-on ray are 4 and 6. */
static void test_interval(void **state)
{
    Sphere sphere = {vec3(0, 0, 5), 1, 0};
    Ray ray = {vec3(0, 0, 0), vec3(0, 0, 1)};
    assert_true(isinf(sphere_intersect(&sphere, ray, 0, 3.99)));
    assert_close(sphere_intersect(&sphere, ray, 0, 4.01), 4, 1e-15);
    assert_close(sphere_intersect(&sphere, ray, 4.01, INFINITY), 6, 1e-15);
    assert_close(sphere_intersect(&sphere, ray, 3.99, 6.01), 4, 1e-15);
    assert_true(isinf(sphere_intersect(&sphere, ray, 4.01, 5.99)));
    assert_true(isinf(sphere_intersect(&sphere, ray, 6.01, INFINITY)));
}

/* The nearest root of |o + t d - c|^2 = r^2 in extended precision: the reference the
 * double routine is compared with. It keeps a = d.d, which differs from 1 by a
 * rounding error: at t = 1e3 that alone moves the root of a grazing hit by ~1e-7. */
static double reference_hit(const Sphere *sphere, Ray ray)
{
    long double ox = (long double)ray.origin.x - sphere->center.x;
    long double oy = (long double)ray.origin.y - sphere->center.y;
    long double oz = (long double)ray.origin.z - sphere->center.z;
    long double dx = ray.dir.x, dy = ray.dir.y, dz = ray.dir.z;
    long double a = dx * dx + dy * dy + dz * dz;
    long double b = -(ox * dx + oy * dy + oz * dz);
    long double c = ox * ox + oy * oy + oz * oz - (long double)sphere->radius * sphere->radius;
    return (double)((b - sqrtl(b * b - a * c)) / a);
}

/* Precision: a sphere of radius 1e-3 at distance 1e3, aimed at random points of its
 * visible side (incidence under 84 degrees), at scales 1e-3, 1 and 1e3. The naive
 * discriminant b^2 - c subtracts two numbers near 1e6 to get one near 1e-8 and keeps
 * about two digits, which puts the hit point ~1e-4 r off the surface; the half-chord
 * form must give t to 1e-9 relative and a hit point on the sphere to 1e-6 r. */
static void test_tiny_sphere_far_away(void **state)
{
    TestRandom rng = test_random(9, 9, 9);
    double worst_t = 0, worst_surface = 0;
    for (int i = 0; i < 3; i++) {
        double s = scales[i];
        for (int k = 0; k < 10000; k++) {
            Vec3 where = random_unit_vector(&rng);
            Sphere sphere = {vec3_scale(where, 1e3 * s), 1e-3 * s, 0};
            Vec3 towards_eye = vec3_neg(where), normal;
            do
                normal = random_unit_vector(&rng);
            while (vec3_dot(normal, towards_eye) < 0.1);
            Vec3 target = vec3_add_scaled(sphere.center, normal, sphere.radius);
            Ray ray = ray_through(vec3(0, 0, 0), target);
            double t = sphere_intersect(&sphere, ray, 0, INFINITY);
            double expected = reference_hit(&sphere, ray);
            double on_surface = vec3_length(vec3_sub(ray_at(ray, t), sphere.center));
            worst_t = fmax(worst_t, fabs(t - expected) / expected);
            worst_surface =
                fmax(worst_surface, fabs(on_surface - sphere.radius) / sphere.radius);
        }
    }
    print_message("tiny far sphere: worst relative t error %.2g, worst |p-c|-r over r %.2g\n",
                  worst_t, worst_surface);
    assert_true(worst_t < 1e-9);
    assert_true(worst_surface < 1e-6);
}

/* The normal is unit length and outward: against the ray for hits from outside,
 * along it for hits from inside. */
static void test_normal(void **state)
{
    TestRandom rng = test_random(4, 5, 6);
    Sphere sphere = {vec3(0.3, -0.7, 2.1), 0.8, 0};
    for (int k = 0; k < 10000; k++) {
        Vec3 outside = vec3_add_scaled(sphere.center, random_unit_vector(&rng), 3.0);
        Vec3 on = vec3_add_scaled(sphere.center, random_unit_vector(&rng), 0.5 * sphere.radius);
        Ray ray = ray_through(outside, on);
        double t = sphere_intersect(&sphere, ray, 0, INFINITY);
        Vec3 n = sphere_normal(&sphere, ray_at(ray, t));
        assert_close(vec3_length(n), 1, 1e-14);
        assert_true(vec3_dot(n, ray.dir) < 0);
        Ray from_inside = {on, random_unit_vector(&rng)};
        double t_in = sphere_intersect(&sphere, from_inside, 0, INFINITY);
        Vec3 n_in = sphere_normal(&sphere, ray_at(from_inside, t_in));
        assert_close(vec3_length(n_in), 1, 1e-14);
        assert_true(vec3_dot(n_in, from_inside.dir) > 0);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_hit_from_outside),
        cmocka_unit_test(test_miss),
        cmocka_unit_test(test_behind_origin),
        cmocka_unit_test(test_from_inside),
        cmocka_unit_test(test_tangent),
        cmocka_unit_test(test_interval),
        cmocka_unit_test(test_tiny_sphere_far_away),
        cmocka_unit_test(test_normal),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
