/* triangle.h (chapter 1): a triangle and the Möller-Trumbore ray intersection (report
 * §3.6.1, eqs. 15-18).
 *
 * T(u, v) = (1-u-v) v0 + u v1 + v v2 with u, v >= 0, u + v <= 1 (eqs. 15-16); equal to
 * the ray, it gives [-d, e1, e2] (t, u, v)^T = o - v0 (eq. 18), solved by Cramer's rule.
 * u and v are accepted down to minus a bound on their own rounding error, so that two
 * triangles sharing an edge leave no pinhole (docs/chapter1.md). The front side is the
 * one the normal (v1 - v0) x (v2 - v0) points to.
 */
#ifndef TRIANGLE_H
#define TRIANGLE_H

#include <float.h>

#include "ray.h"

/* In units of (|s| + |e|) |e| / |det|, with a margin over what the tests need. */
#define TRIANGLE_EDGE_SLACK (16 * DBL_EPSILON)

typedef struct {
    Vec3 v0, e1, e2;
    Vec3 normal; /* unit (e1 x e2): the front side */
    double area;
    double longest_edge; /* max |component| of e1 and e2, for the edge slack */
    int material;
} Triangle;

Triangle triangle_make(Vec3 v0, Vec3 v1, Vec3 v2, int material);

/* Exercise 1.2: the smallest t in (tmin, tmax) where the ray meets the triangle (either
 * side), or INFINITY. Inline here: the hierarchy's leaves call it for nearly every ray. */
static inline double triangle_intersect(const Triangle *tri, Ray ray, double tmin, double tmax)
{
    Vec3 p = vec3_cross(ray.dir, tri->e2);
    double det = vec3_dot(tri->e1, p);
    /* det = -d . (e1 x e2) = -2 area cos(angle to normal); relative to 2 area it is the
     * cosine of the incidence angle, and a ray within ~1e-14 of parallel misses. */
    if (fabs(det) <= 1e-14 * 2.0 * tri->area)
        return INFINITY;
    double inv_det = 1.0 / det;
    Vec3 s = vec3_sub(ray.origin, tri->v0);
    /* The rounding error bound of u and v (above): accepting down to -slack closes
     * shared edges. */
    double edge = tri->longest_edge;
    double slack = TRIANGLE_EDGE_SLACK * (vec3_max_abs(s) + edge) * edge * fabs(inv_det);
    double u = vec3_dot(s, p) * inv_det;
    Vec3 q = vec3_cross(s, tri->e1);
    double v = vec3_dot(ray.dir, q) * inv_det;
    double t = vec3_dot(tri->e2, q) * inv_det;
    /* All the conditions at once, with & rather than &&: cheaper than a branch that
     * goes either way at random. */
    int inside = (u >= -slack) & (u <= 1.0 + slack) & (v >= -slack) & (u + v <= 1.0 + slack);
    return (inside & (t > tmin) & (t < tmax)) ? t : INFINITY;
}
#if CHAPTER >= 3

/* The point T(u, v) of eq. 16: where a lamp is sampled (area_light.h). */
static inline Vec3 triangle_point(const Triangle *tri, double u, double v)
{
    return vec3_add_scaled(vec3_add_scaled(tri->v0, tri->e1, u), tri->e2, v);
}
#endif

#endif
