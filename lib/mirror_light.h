/* mirror_light.h (chapter 7): the lamps seen in a planar mirror, as lights of their own.
 *
 * A plane mirror n . p = c shows a lamp point y at its image y' = y - 2 (n . y - c) n,
 * as far away as the folded path x -> q -> y is long. So the mirror's image of the lamps
 * is a second area light, sampled like the first (area_light.h): its shadow ray must
 * first hit the mirror inside its polygon, at q, and q -> y must be clear; then
 *     L = A R Le f cos(alpha) cos(beta') / |x - y'|^2,   R the mirror's reflectance.
 * It counts every path diffuse vertex -> planar mirror -> lamp, so a path tracer using
 * it must not count such a path again when it hits the lamp itself (docs/chapter7.md).
 */
#ifndef MIRROR_LIGHT_H
#define MIRROR_LIGHT_H

#include "area_light.h"

/* A plane n . p = offset holding mirror triangles; largest_term is the largest |n_i p_i|
 * of the point p it was found from, the size the offset's rounding is relative to. */
typedef struct {
    Vec3 normal;
    double offset;
    double largest_term;
} MirrorPlane;

typedef struct {
    MirrorPlane *planes;
    int count;
} MirrorPlanes;

/* The distinct planes of the scene's mirror triangles (two triangles of a quad share
 * one). Returns 0, or -1 when memory runs out. */
int mirror_light_find_planes(const Scene *scene, MirrorPlanes *mirrors);
void mirror_planes_free(MirrorPlanes *mirrors);

/* Exercise 7.2: one shadow ray at diffuse point x (normal n facing the viewer, direction
 * wo, material m) to the image of a light point in `plane`: its value, direction and
 * density (zero value when the light or the surface faces away, the ray's first hit is
 * not a mirror triangle in this plane, or the way from the mirror to the lamp is blocked). */
ShadowRay mirror_light_shadow_ray(const Scene *scene, const MirrorPlane *plane, Vec3 x, Vec3 n,
                                  Vec3 wo, const Material *m, Rng *rng, RayCounts *counts);

#endif
