/* ray.h (chapter 1): a ray x(t) = origin + t dir (eq. 20), and how to start one on a
 * surface without hitting that surface again.
 *
 * dir is unit length, so t is a distance. A hit point computed in floating point lies a
 * rounding error off the true surface, a few ulps of the largest coordinate that went
 * into it: the point's own, the ray's origin's, the surface's. A new ray starts
 * RAY_OFFSET times that magnitude off the surface, along the normal, on the side it
 * travels into: an offset of the point and its surface, whatever else is in the scene
 * (docs/chapter1.md).
 */
#ifndef RAY_H
#define RAY_H

#include "vec.h"

#define RAY_OFFSET 1e-10

typedef struct { Vec3 origin, dir; } Ray;

static inline Vec3 ray_at(Ray ray, double t) { return vec3_add_scaled(ray.origin, ray.dir, t); }

/* Start a ray at surface point p with geometric normal n (either orientation),
 * travelling in unit direction dir; scale is the largest coordinate magnitude behind p
 * other than p's own (Hit.scale). */
Ray ray_spawn(Vec3 p, Vec3 n, Vec3 dir, double scale);

/* The offset point itself: p moved off the surface to the side `towards` points to. */
Vec3 ray_offset_origin(Vec3 p, Vec3 n, Vec3 towards, double scale);

#endif
