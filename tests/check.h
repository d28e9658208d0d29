/* check.h (chapter 1): small helpers shared by the geometry tests (include after cmocka.h).
 *
 * assert_close compares doubles and, unlike cmocka's float-only assert_float_equal,
 * prints both values at full precision when it fails. The tests' random numbers and
 * directions are their own (test_random.h).
 */
#ifndef CHECK_H
#define CHECK_H

#include "triangle.h"
#include "test_random.h"

#define assert_close(a, b, tol)                                                                \
    do {                                                                                       \
        double a_ = (a), b_ = (b);                                                             \
        if (!(fabs(a_ - b_) <= (tol)))                                                         \
            fail_msg("%s = %.17g, expected %.17g within %.3g", #a, a_, b_, (double)(tol));     \
    } while (0)

/* The critical angle arcsin(n_t / n_i) for n_i > n_t, pi/2 when n_i <= n_t: the tests'
 * own, apart from the lesson's (fresnel.h, chapter 4). */
static inline double test_critical_angle(double n_i, double n_t)
{
    return n_i > n_t ? asin(n_t / n_i) : 0.5 * PI;
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
    return vec3_add(vec3_add(vec3_scale(t, local.x), vec3_scale(b, local.y)),
                    vec3_scale(n, local.z));
}

/* The point at barycentric (u, v) of a triangle: v0 + u e1 + v e2 (eq. 16). */
static inline Vec3 point_on_triangle(const Triangle *tri, double u, double v)
{
    return vec3_add_scaled(vec3_add_scaled(tri->v0, tri->e1, u), tri->e2, v);
}

/* The ray from `origin` through `target`. */
static inline Ray ray_through(Vec3 origin, Vec3 target)
{
    Ray ray = {origin, vec3_normalize(vec3_sub(target, origin))};
    return ray;
}

#endif
