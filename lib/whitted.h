/* whitted.h (chapter 1): Whitted ray tracing (report §2.1, Figure 1).
 *
 * From the eye, a ray tree: at a diffuse surface the ray ends and the surface is shaded
 * by one shadow ray to each point light (hard shadows),
 *     L = sum over lights of  rho/pi I cos(theta) / d^2 V;
 * a mirror reflects the ray; glass splits it into a reflected and a refracted ray
 * weighted by Schlick's R and 1 - R; an emitter seen from its front adds its radiance.
 * No interreflection, so no colour bleeding and no soft shadows. A path of the tree has
 * at most max_depth rays.
 */
#ifndef WHITTED_H
#define WHITTED_H

#include "render.h"

typedef struct {
    int max_depth;
} WhittedSettings;

/* An Estimator (render.h); settings points to a WhittedSettings. */
Vec3 whitted_radiance(const Scene *scene, Ray ray, Rng *rng, const void *settings,
                      RayCounts *counts);

#endif
