/* path_caustics.h (chapter 8): chapter 7's final path tracer (path_final.h) with the
 * caustics from a photon map (photon.h), beyond the report.
 *
 * Light reaching a diffuse vertex splits by the way it came from the lamp: straight
 * (L D) to the shadow rays; by one planar mirror straight on (L M D) to the mirror's
 * images where the vertex samples them (the first K, PathSettings.mirror_light), else to
 * the map; through any other chain of mirrors and glass (L S+ D) to the map, so the path
 * adds no emission it hits that way. Each light path is counted by exactly one
 * estimator; chapter 7's final estimator is its oracle.
 */
#ifndef PATH_CAUSTICS_H
#define PATH_CAUSTICS_H

#include "path.h"
#include "photon.h"

typedef struct {
    PathSettings path;
    const PhotonMap *split;    /* L S+ D but L M D (PHOTON_SPLIT): beside the images */
    const PhotonMap *caustics; /* all of L S+ D (PHOTON_CAUSTIC): at the other vertices */
    double radius;             /* of the maps' radiance estimate */
} CausticPathSettings;

/* An Estimator (render.h); settings points to a CausticPathSettings. */
Vec3 path_caustics_radiance(const Scene *scene, Ray ray, Rng *rng, const void *settings,
                            RayCounts *counts);

#endif
