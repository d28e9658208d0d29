/* ray.h (chapter 1): a ray x(t) = origin + t dir (eq. 20), and how to start one on a
 * surface without hitting that surface again.
 *
 * dir is unit length, so t is a distance. A hit point, put back on its surface from the
 * surface's own numbers (scene.h), lies off it by a few ulps of those numbers and of its
 * own coordinates. A new ray starts RAY_OFFSET times that magnitude off the surface, to
 * the side it travels into. The offset is relative, so it holds for a scene of any
 * scale, and it depends on nothing but the point and its surface.
 */
#ifndef RAY_H
#define RAY_H

#include "vec.h"

/* About 450,000 ulps (an ulp of a magnitude is 2^-52, 2.2e-16, of it): far above a hit
 * point's error, and far below any feature of a scene relative to its distance from the
 * origin. */
#define RAY_OFFSET 1e-10

typedef struct {
    Vec3 origin, dir;
} Ray;

static inline Vec3 ray_at(Ray ray, double t) { return vec3_add_scaled(ray.origin, ray.dir, t); }

/* Start a ray at surface point p with geometric normal n (either orientation),
 * travelling in unit direction dir. scale is the magnitude of the numbers p was computed
 * from, other than its own coordinates (Hit.scale). */
Ray ray_spawn(Vec3 p, Vec3 n, Vec3 dir, double scale);

/* The offset point itself: p moved off the surface to the side `towards` points to. */
Vec3 ray_offset_origin(Vec3 p, Vec3 n, Vec3 towards, double scale);

#endif
