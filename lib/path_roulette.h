/* path_roulette.h (chapter 6): the report's path tracer: shadow rays (eq. 21) and Russian
 * roulette (roulette.h), which ends paths early without bias.
 *
 * It is chapter 3's estimator with one more step at each diffuse vertex: after the
 * shadow rays, the path survives roulette or ends there. Chapter 3's estimator, which
 * only the depth limit ends, is its oracle (docs/chapter6.md).
 */
#ifndef PATH_ROULETTE_H
#define PATH_ROULETTE_H

#include "path.h"

/* An Estimator (render.h); settings points to a PathSettings. */
Vec3 path_roulette_radiance(const Scene *scene, Ray ray, Rng *rng, const void *settings,
                            RayCounts *counts);

#endif
