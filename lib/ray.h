/* ray.h: a ray x(t) = origin + t * dir (report §3.6.2, eq. 20) and how to start one
 * on a surface without hitting that surface again.
 *
 * Introduced in chapter 1. `dir` is unit length everywhere in this renderer, so t is
 * a distance.
 *
 * Self-intersection ("shadow acne"): a hit point computed in floating point lies a
 * rounding error above or below the true surface, so a ray started there may hit the
 * surface it just left at t ~ 1e-16. We move the origin off the surface along the
 * geometric normal, to the side the new ray travels into, by
 *     RAY_OFFSET * (1 + max |p_i|),
 * an offset relative to the size of the coordinates (so it scales with the scene,
 * tested at 1e-3 and 1e3) that is many orders of magnitude above the intersection
 * routines' rounding error (a few ulps, about 1e-16 relative in double) and far below
 * any feature of the scene. Moving along the normal rather than along the ray keeps
 * the offset effective at grazing angles, and choosing the side by the new direction
 * makes refraction into a sphere and shadow rays behave alike.
 */
#ifndef RAY_H
#define RAY_H

#include "vec.h"

#define RAY_OFFSET 1e-9

typedef struct { Vec3 origin, dir; } Ray;

static inline Vec3 ray_at(Ray ray, double t) { return vec3_add_scaled(ray.origin, ray.dir, t); }

/* Start a ray at surface point p with geometric normal n (either orientation),
 * travelling in unit direction dir. */
Ray ray_spawn(Vec3 p, Vec3 n, Vec3 dir);

/* The offset point itself: p moved off the surface to the side `towards` points to. */
Vec3 ray_offset_origin(Vec3 p, Vec3 n, Vec3 towards);

#endif
