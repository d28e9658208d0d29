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

double ppm_first_radius(const Scene *scene, double fraction)
{
    Vec3 lights = vec3(0, 0, 0); /* the lights' centroid, by area */
    for (int i = 0; i < scene->light_count; i++) {
        const Triangle *t = &scene->triangles[scene->light_triangles[i]];
        Vec3 centroid = triangle_point(t, 1.0 / 3.0, 1.0 / 3.0);
        lights = vec3_add_scaled(lights, centroid, t->area / scene->light_area);
    }
    const Camera *c = &scene->camera;
    Vec3 plane = vec3_add_scaled(vec3_add_scaled(c->bottom_left, c->right, 0.5), c->up, 0.5);
    double width = vec3_length(c->right) * vec3_length(vec3_sub(lights, c->eye)) /
                   vec3_length(vec3_sub(plane, c->eye));
    return fraction * width;
}

double ppm_radius(double first_radius, double alpha, int pass)
{
    return first_radius * sqrt(pow((double)pass, alpha - 1.0));
}
