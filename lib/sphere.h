/* sphere.h (chapter 1): the implicit sphere |x - c|^2 = r^2 and a ray's first hit on it
 * (report §3.6.2, eqs. 19-20).
 *
 * Introduced in chapter 1. Substituting x = o + t d (|d| = 1) into eq. 19 gives
 *     t^2 - 2 t b + c = 0,  b = d.(c - o),  c = |o - c|^2 - r^2,
 * with roots b -+ sqrt(b^2 - c). The naive discriminant b^2 - c cancels
 * catastrophically for a small sphere far away; we compute it as
 *     r^2 - |(o - c) + b d|^2,
 * the squared half-chord, whose terms are both of the size of r^2 ("Precision
 * Improvements for Ray/Sphere Intersection", Ray Tracing Gems, ch. 7). A ray from inside
 * the sphere gets the far root; a tangent ray (discriminant 0) touches at one point.
 */
#ifndef SPHERE_H
#define SPHERE_H

#include "ray.h"

typedef struct {
    Vec3 center;
    double radius;
    int material;
} Sphere;

/* Smallest t in (tmin, tmax) where the ray meets the sphere, or INFINITY. */
double sphere_intersect(const Sphere *sphere, Ray ray, double tmin, double tmax);

/* Outward unit normal at surface point p. */
Vec3 sphere_normal(const Sphere *sphere, Vec3 p);

#endif
