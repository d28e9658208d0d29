/* path_caustics.c (chapter 8): the final path tracer with caustics from a photon map. See
 * path_caustics.h. */
#include "path_caustics.h"

#include "path_final.h"
#include "photon_estimate.h"

/* L S+ D at diffuse vertex x: L M D from the images where x sampled them, else from the
 * map. The disc's reachable area where the camera sees it; after a diffuse bounce,
 * pi r^2 (the bounce blurs an edge more than the kernel does). */
static Vec3 caustic_radiance(const Scene *scene, const Vertex *x, int images,
                             int diffuse_vertices, const void *context)
{
    const CausticPathSettings *c = context;
    const PhotonMap *map = images ? c->split : c->caustics;
    if (diffuse_vertices == 0)
        return photon_estimate_reachable(scene, map, c->radius, x);
    return photon_estimate_radiance(map, c->radius, x->hit.point, x->normal, x->wo,
                                    x->material);
}

Vec3 path_caustics_radiance(const Scene *scene, Ray ray, Rng *rng, const void *settings,
                            RayCounts *counts)
{
    const CausticPathSettings *c = settings;
    DiffuseEstimate caustics = {caustic_radiance, c};
    return path_final_trace(scene, ray, rng, &c->path, &caustics, counts);
}
