/* sphere.h (chapter 1): the sphere |x - c|^2 = r^2 and a ray's first hit on it (report
 * §3.6.2, eqs. 19-20).
 *
 * With x = o + t d, |d| = 1: t^2 - 2 t b + c = 0, b = d.(c - o), c = |o - c|^2 - r^2.
 * The discriminant is computed as r^2 - |(o - c) + b d|^2, the squared half-chord,
 * which does not cancel for a small sphere far away (docs/chapter1.md).
 */
#ifndef SPHERE_H
#define SPHERE_H

#include "ray.h"

typedef struct {
    Vec3 center;
    double radius;
    int material;
} Sphere;

/* Exercise 1.1: the smallest t in (tmin, tmax) where the ray meets the sphere, or INFINITY. */
double sphere_intersect(const Sphere *sphere, Ray ray, double tmin, double tmax);

/* Outward unit normal at surface point p (or at the surface point nearest p). */
Vec3 sphere_normal(const Sphere *sphere, Vec3 p);

#endif
