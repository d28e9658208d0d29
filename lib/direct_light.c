/* direct_light.c (chapter 7): shadow rays to the lamps and their mirror images, weighted
 * by multiple importance sampling. See direct_light.h. */
#include "direct_light.h"

#include "area_light.h"
#include "mis.h"
#include "sphere_guide.h"

/* A light sample's share: all of it, or with mis its power-heuristic weight against
 * the bounce's sampling of the same direction, by the density the bounce draws from
 * (the sphere guide's mixture when it is on: the hit's share uses that one too). */
static Vec3 weighted(ShadowRay sample, Vec3 n, const SphereGuide *bounce, const PathSettings *s)
{
    if (!s->mis)
        return sample.value;
    double weight = mis_power_heuristic(s->shadow_rays, sample.pdf, 1,
                                        sphere_guide_pdf(bounce, n, sample.wi));
    return vec3_scale(sample.value, weight);
}

Vec3 direct_light(const Scene *scene, const Vertex *x, int images, const PathSettings *s,
                  Rng *rng, RayCounts *counts)
{
    Vec3 sum = vec3(0, 0, 0), p = x->hit.point, n = x->normal;
    SphereGuide bounce = {.count = 0, .cosine_share = 1.0}; /* cosine-weighted */
    if (s->mis && s->sphere_guide > 0.0)
        sphere_guide_at(scene, p, n, s->sphere_guide, &bounce);
    for (int k = 0; k < s->shadow_rays; k++)
        sum = vec3_add(
            sum, weighted(area_light_shadow_ray(scene, p, n, x->wo, x->material, rng, counts),
                          n, &bounce, s));
    for (int plane = 0; images && plane < s->mirrors->count; plane++)
        for (int k = 0; k < s->shadow_rays; k++) {
            ShadowRay sample = mirror_light_shadow_ray(scene, &s->mirrors->planes[plane], p, n,
                                                       x->wo, x->material, rng, counts);
            sum = vec3_add(sum, weighted(sample, n, &bounce, s));
        }
    return vec3_scale(sum, 1.0 / s->shadow_rays);
}

double direct_light_hit_weight(const Scene *scene, const PathSettings *s, double bsdf_pdf,
                               double distance, double cos_beta)
{
    double light_pdf = area_light_pdf(scene, distance, cos_beta);
    return mis_power_heuristic(1, bsdf_pdf, s->shadow_rays, light_pdf);
}
