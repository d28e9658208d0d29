/* mirror_light.h (chapter 7): the lamps seen in a planar mirror, as lights of their own.
 *
 * Introduced in chapter 7: "model what the scene requires". The room's largest error
 * is the lamp's light that reaches the walls by way of the mirror wall (a caustic):
 * shadow rays cannot find it (they go straight to the lamp), so a path gets it only
 * when its BRDF-sampled direction happens to hit the mirror and then the lamp, rarely
 * and brightly. But a plane mirror makes an exact image: seen from x in front of a
 * mirror with plane n . p = c, a lamp point y appears at its reflection
 *     y' = y - 2 (n . y - c) n,
 * as far away as the folded path x -> q -> y is long, with its normal reflected too.
 * So the mirror's image of the lamps is a second area light, sampled exactly like the
 * first (area_light.h): draw y uniformly over the lamps, reflect it, and send the
 * shadow ray from x towards y'. It must hit the mirror first (at q, inside the mirror's
 * polygon: the ray's first hit is a mirror triangle in that plane), and the segment from
 * q to y must be unblocked. Then, with the mirror's reflectance R,
 *     L = A R Le f cos(alpha) cos(beta') / |x - y'|^2,
 * beta' the angle at y' between the reflected normal and the ray (that is, at y
 * between the lamp's normal and q - y); its direction's density in solid angle is
 * area_light_pdf over the distance |x - y'|.
 * This counts the light of every path diffuse vertex -> planar mirror -> lamp, so the
 * path tracer must not count it again when its own path does that (path.h): every path
 * is counted by exactly one estimator, or with mis shared by the power heuristic. It is
 * unbiased for any number of planar mirrors (each plane is its own image), and useless
 * for the curved mirror sphere, which has no such image.
 *
 * The planes are found once, when the scene is prepared: the distinct planes of the
 * triangles whose material is a mirror (two triangles of a quad share one).
 */
#ifndef MIRROR_LIGHT_H
#define MIRROR_LIGHT_H

#include "area_light.h"

/* Fill scene->mirror_planes with the distinct planes of its mirror triangles (called by
 * scene_prepare). Returns 0, or -1 when memory runs out. */
int mirror_light_find_planes(Scene *scene);

/* One shadow ray at diffuse point x (normal n facing the viewer, direction wo, material
 * m) to the image of a light point in `plane`: its value, direction and density (zero
 * value when the light or the surface faces away, the ray's first hit is not a mirror
 * triangle in this plane, or the way from the mirror to the lamp is blocked). */
ShadowRay mirror_light_shadow_ray(const Scene *scene, const MirrorPlane *plane, Vec3 x, Vec3 n,
                                  Vec3 wo, const Material *m, Rng *rng, RayCounts *counts);

#endif
