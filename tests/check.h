/* check.h (chapter 1): small helpers shared by the geometry tests (include after cmocka.h).
 *
 * assert_close compares doubles and, unlike cmocka's float-only assert_float_equal,
 * prints both values at full precision when it fails. The tests' random numbers are
 * their own (test_random.h). The random directions are
 * uniform over the unit sphere: z = cos(theta) uniform in [-1, 1] (Archimedes' hat-box
 * theorem) and phi uniform in [0, 2 pi).
 */
#ifndef CHECK_H
#define CHECK_H

#include "ray.h"
#include "test_random.h"

#define assert_close(a, b, tol) \
    do { \
        double a_ = (a), b_ = (b); \
        if (!(fabs(a_ - b_) <= (tol))) \
            fail_msg("%s = %.17g, expected %.17g within %.3g", #a, a_, b_, (double)(tol)); \
    } while (0)

/* The direction with z = 2 u1 - 1 and phi = 2 pi u2: uniform over the sphere for
 * uniform u1, u2. */
static inline Vec3 unit_vector_from(double u1, double u2)
{
    double z = 2.0 * u1 - 1.0, phi = 2.0 * PI * u2;
    double s = sqrt(fmax(0.0, 1.0 - z * z));
    return vec3(s * cos(phi), s * sin(phi), z);
}

static inline Vec3 random_unit_vector(TestRandom *random)
{
    double u1 = test_uniform(random), u2 = test_uniform(random);
    return unit_vector_from(u1, u2);
}

/* Two unit vectors t, b that with the unit vector n make a right-handed orthonormal
 * frame (t from the axis least along n): the tests' own, apart from the lesson's
 * (frame.h, chapter 2). */
static inline void test_frame(Vec3 n, Vec3 *t, Vec3 *b)
{
    Vec3 axis = fabs(n.x) < 0.5 ? vec3(1, 0, 0) : vec3(0, 1, 0);
    *b = vec3_normalize(vec3_cross(n, axis));
    *t = vec3_cross(*b, n);
}

/* x t + y b + z n for local = (x, y, z). */
static inline Vec3 test_from_frame(Vec3 local, Vec3 t, Vec3 b, Vec3 n)
{
    return vec3_add(vec3_add(vec3_scale(t, local.x), vec3_scale(b, local.y)), vec3_scale(n, local.z));
}

/* The ray from `origin` through `target`. */
static inline Ray ray_through(Vec3 origin, Vec3 target)
{
    Ray ray = {origin, vec3_normalize(vec3_sub(target, origin))};
    return ray;
}

#endif
