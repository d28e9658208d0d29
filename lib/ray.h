/* ray.h (chapter 1): a ray x(t) = origin + t dir (eq. 20), and how to start one on a
 * surface without hitting that surface again.
 *
 * dir is unit length, so t is a distance. A hit point computed in floating point lies a
 * rounding error off the true surface, so a new ray starts RAY_OFFSET times the scene's
 * scale off it, along the normal, on the side it travels into (docs/chapter1.md).
 */
#ifndef RAY_H
#define RAY_H

#include "vec.h"

#define RAY_OFFSET 1e-10

typedef struct { Vec3 origin, dir; } Ray;

static inline Vec3 ray_at(Ray ray, double t) { return vec3_add_scaled(ray.origin, ray.dir, t); }

/* Start a ray at surface point p with geometric normal n (either orientation),
 * travelling in unit direction dir, in a scene of the given scale (Scene.scale). */
Ray ray_spawn(Vec3 p, Vec3 n, Vec3 dir, double scale);

/* The offset point itself: p moved off the surface to the side `towards` points to. */
Vec3 ray_offset_origin(Vec3 p, Vec3 n, Vec3 towards, double scale);

#endif
