/* ray.h (chapter 1): a ray x(t) = origin + t dir (eq. 20), and how to start one on a
 * surface without hitting that surface again.
 *
 * dir is unit length, so t is a distance. A hit point, put back on its surface from the
 * surface's own numbers (scene.h), lies off it by a few ulps of those numbers and of its
 * own coordinates. A new ray starts RAY_OFFSET times that magnitude off the surface, to
 * the side it travels into: nothing absolute, nothing from the rest of the scene.
 */
#ifndef RAY_H
#define RAY_H

#include "vec.h"

#define RAY_OFFSET 1e-10

typedef struct {
    Vec3 origin, dir;
} Ray;

static inline Vec3 ray_at(Ray ray, double t) { return vec3_add_scaled(ray.origin, ray.dir, t); }

/* Start a ray at surface point p with geometric normal n (either orientation),
 * travelling in unit direction dir; scale: of the numbers behind p other than its own
 * coordinates (Hit.scale). */
Ray ray_spawn(Vec3 p, Vec3 n, Vec3 dir, double scale);

/* The offset point itself: p moved off the surface to the side `towards` points to. */
Vec3 ray_offset_origin(Vec3 p, Vec3 n, Vec3 towards, double scale);

#endif
