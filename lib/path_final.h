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

/* Another estimator of some of the light reaching a diffuse vertex: the radiance it
 * brings to x towards the path, given whether x sampled the mirror images and how many
 * diffuse vertices came before it. The light it finds arrives through mirrors and glass
 * (L S+ D), but for one planar mirror straight on where x sampled the images, so the
 * path adds no emission it hits that way. */
typedef struct {
    Vec3 (*radiance)(const Scene *scene, const Vertex *x, int images, int diffuse_vertices,
                     const void *context);
    const void *context;
} DiffuseEstimate;

/* The final path tracer, with another estimate added at every diffuse vertex (NULL:
 * none, path_final_radiance). */
Vec3 path_final_trace(const Scene *scene, Ray ray, Rng *rng, const PathSettings *settings,
                      const DiffuseEstimate *other, RayCounts *counts);

#endif
