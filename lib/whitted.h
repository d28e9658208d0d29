/* whitted.h (chapter 1): Whitted ray tracing (report §2.1, Figure 1).
 *
 * Introduced in chapter 1. From the eye, a ray tree:
 *   - at a diffuse surface the ray ends; the surface is shaded locally by one shadow ray
 *     to each point light (hard shadows: a point is wholly lit or wholly dark):
 *         L = sum over lights of  rho/pi * I * cos(theta) / d^2 * V,
 *     with rho/pi the Lambertian BRDF (eq. 8; Oren-Nayar surfaces are shaded as
 *     Lambertian here), I the light's intensity, theta the angle between the normal and
 *     the direction to the light, d its distance and V in {0, 1} its visibility;
 *   - at a perfect mirror the ray is reflected (report §3.5.1);
 *   - at glass it splits into a reflected and a refracted ray (Snell, eq. 2), weighted
 *     by Schlick's reflectance R and 1 - R (eqs. 6-7, with SPEC §8.2 and §8.4); beyond
 *     the critical angle all of it is reflected (total internal reflection);
 *   - an emitting surface seen from its front adds its radiance.
 * There is no diffuse interreflection, so no colour bleeding and no soft shadows: that
 * is what the Monte Carlo chapters add.
 *
 * Depth: a path of the tree has at most max_depth rays, the camera ray being the first.
 */
#ifndef WHITTED_H
#define WHITTED_H

#include "render.h"

typedef struct {
    int max_depth;
} WhittedSettings;

/* An Estimator (render.h); settings points to a WhittedSettings. The random generator
 * is not used: Whitted ray tracing is deterministic. */
Vec3 whitted_radiance(const Scene *scene, Ray ray, Rng *rng, const void *settings,
                      RayCounts *counts);

#endif
