/* photon_estimate.c (chapter 8): the photon density estimate of reflected radiance.
 * See photon_estimate.h. */
#include "photon_estimate.h"

#include "diffuse.h"

/* Lambert's f is the same for every photon, so it multiplies their summed power once. */
typedef struct {
    const PhotonMap *map;
    Vec3 n, wo;
    const Material *m;
    int lambert;
    Vec3 sum; /* sum of f * Phi (Lambert: of Phi) over the photons that count */
} Gather;

static void add_photon(int index, double distance2, void *context)
{
    Gather *g = context;
    const Photon *p = &g->map->photons[index];
    if (vec3_dot(p->normal, g->n) < PHOTON_NORMAL_COS || vec3_dot(p->incoming, g->n) <= 0.0)
        return;
    Vec3 weighted = g->lambert ? p->power : vec3_mul(diffuse_brdf(g->m, g->n, p->incoming, g->wo), p->power);
    g->sum = vec3_add(g->sum, weighted);
}

Vec3 photon_estimate_radiance(const PhotonMap *map, double radius, Vec3 x, Vec3 n, Vec3 wo,
                              const Material *m)
{
    Gather g = {map, n, wo, m, m->kind == MATERIAL_LAMBERT, vec3(0, 0, 0)};
    kdtree_query_radius(&map->tree, x, radius, add_photon, &g);
    Vec3 sum = g.lambert ? vec3_mul(diffuse_brdf(m, n, wo, wo), g.sum) : g.sum;
    return vec3_scale(sum, 1.0 / (PI * radius * radius));
}

double ppm_radius(double first_radius, double alpha, int pass)
{
    return first_radius * sqrt(pow((double)pass, alpha - 1.0));
}
