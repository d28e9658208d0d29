/* path_final.h (chapter 7): the final path tracer: the report's (shadow rays, Fresnel
 * glass, Russian roulette) with the levers that spend its samples where the error is.
 *
 * Multiple importance sampling of the lamps (mis.h), shadow rays to the lamps' images in
 * the planar mirror (mirror_light.h) at the first mirror_light diffuse vertices, and
 * bounces aimed at the mirror and glass spheres (sphere_guide.h), each a setting
 * (path.h); with them all off it is chapter 6's estimator, its oracle. A path that
 * goes from a vertex that sampled the images straight to a planar mirror and on to a
 * lamp adds that emission only in the share mis leaves it (docs/chapter7.md).
 */
#ifndef PATH_FINAL_H
#define PATH_FINAL_H

#include "path.h"

/* An Estimator (render.h); settings points to a PathSettings. */
Vec3 path_final_radiance(const Scene *scene, Ray ray, Rng *rng, const void *settings,
                         RayCounts *counts);

#endif
