/* ray.h (chapter 1): a ray x(t) = origin + t * dir (report §3.6.2, eq. 20) and how to start one
 * on a surface without hitting that surface again.
 *
 * Introduced in chapter 1. `dir` is unit length everywhere in this renderer, so t is
 * a distance.
 *
 * Self-intersection ("shadow acne"): a hit point computed in floating point lies a
 * rounding error above or below the true surface, so a ray started there may hit the
 * surface it just left at t ~ 1e-16. We move the origin off the surface along the
 * geometric normal, to the side the new ray travels into, by
 *     RAY_OFFSET * max(scale, max |p_i|),
 * where `scale` is the scene's largest coordinate magnitude (Scene.scale: geometry,
 * point lights and camera). The offset must be relative to the scene, not to the point
 * alone: a hit point's rounding error is relative to the coordinates of the ray's
 * origin and of the surface, so a point near (0,0,0) on a large floor needs more than
 * a point-relative offset. Nor may it be absolute: an absolute floor of RAY_OFFSET
 * (this file until issue 9) jumped through the walls of a room scaled by 1e-12 and
 * left half its pixels black. RAY_OFFSET sits between two limits, both tested at scene
 * scales from 1e-45 to 1e45 (tests/test_scene.c): above the rounding error of hit
 * points (a few ulps of the scale), and below the gap to the nearest other surface: two
 * planes 1e-6 of the scene apart must still see each other. Moving along the normal rather
 * than along the ray keeps the offset effective at grazing angles, and choosing the
 * side by the new direction makes refraction into a sphere and shadow rays behave alike.
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
