/* whitted.h (chapter 1): Whitted ray tracing (report §2.1, Figure 1).
 *
 * From the eye, a ray tree of at most max_depth rays a path: a diffuse surface is shaded
 * by one shadow ray to each point light, L = sum rho/pi I cos(theta) / d^2 V (hard
 * shadows); a mirror reflects the ray; glass splits it into a reflected and a refracted
 * ray weighted by Schlick's R and 1 - R; an emitter seen from its front adds its
 * radiance. No interreflection: no colour bleeding, no soft shadows.
 */
#ifndef WHITTED_H
#define WHITTED_H

#include "render.h"

typedef struct {
    int max_depth;
} WhittedSettings;

/* The radiance arriving along the ray; settings points to a WhittedSettings. In chapter 1
 * it is an Estimator (render.h). */
Vec3 whitted_radiance(const Scene *scene, Ray ray, const void *settings, RayCounts *counts);

#endif
