/* path_caustics.h (chapter 8): the path tracer with its caustics from a photon map
 * (photon.h), beyond the report.
 *
 * Light reaching a diffuse vertex splits by the way it came from the lamp: straight
 * (L D) to the shadow rays; through mirrors and glass (L S+ D) to the caustic map's
 * estimate (photon_estimate.h); via another diffuse surface to the rest of the path.
 * So after a diffuse bounce, emission the path hits after mirrors or glass is not added:
 * the map counted it. Each light path is counted by exactly one estimator, and chapter
 * 6's estimator, which finds caustics by hitting the lamp, is its oracle.
 */
#ifndef PATH_CAUSTICS_H
#define PATH_CAUSTICS_H

#include "path.h"
#include "photon.h"

typedef struct {
    PathSettings path;
    const PhotonMap *caustics; /* the caustic map (PHOTON_CAUSTIC) */
    double radius;             /* of its radiance estimate */
} CausticPathSettings;

/* An Estimator (render.h); settings points to a CausticPathSettings. */
Vec3 path_caustics_radiance(const Scene *scene, Ray ray, Rng *rng, const void *settings,
                            RayCounts *counts);

#endif
