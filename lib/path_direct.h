/* path_direct.h (chapter 3): the path tracer with shadow rays (report §3.7, eq. 21).
 *
 * At every diffuse vertex, M shadow rays estimate the light that comes straight from
 * the lamps (area_light.h). The path then must not add the emission it hits right after
 * that diffuse bounce: the shadow rays counted it. Emission seen from the camera, or
 * after a mirror or glass bounce, is added, since no shadow ray accounts for it. With
 * M = 0 this is chapter 2's estimator (path.h), its oracle (docs/chapter3.md).
 */
#ifndef PATH_DIRECT_H
#define PATH_DIRECT_H

#include "path.h"

/* An Estimator (render.h); settings points to a PathSettings. */
Vec3 path_direct_radiance(const Scene *scene, Ray ray, Rng *rng, const void *settings,
                          RayCounts *counts);

#endif
