/* path.c: the Monte Carlo path tracer (chapters 2-7; caustics from photons, chapter 8).
 * See path.h. */
#include "path.h"

#include <stdio.h>

#include "area_light.h"
#include "diffuse.h"
#include "fresnel.h"
#include "mirror.h"
#include "photon_estimate.h"
#include "roulette.h"
#include "schlick.h"
#include "snell.h"

Vec3 glass_scatter(Vec3 d, Vec3 n, int entering, double ior, FresnelMode mode, Rng *rng)
{
    double n_i = entering ? 1.0 : ior, n_t = entering ? ior : 1.0;
    double cos_i = -vec3_dot(d, n);
    double reflectance = mode == FRESNEL_EXACT ? fresnel_reflectance(cos_i, n_i, n_t)
                                               : schlick_reflectance(cos_i, n_i, n_t);
    Vec3 refracted;
    if (rng_uniform(rng) >= reflectance && snell_refract(d, n, n_i, n_t, &refracted))
        return refracted;
    return mirror_reflect(d, n);
}

/* One path. With `caustics` (chapter 8), light reaching a diffuse hit through mirrors
 * and glass comes from the photon map instead of from hitting the lamp (path.h). */
static Vec3 trace_path(const Scene *scene, Ray ray, Rng *rng, const PathSettings *s,
                       const CausticPathSettings *caustics, RayCounts *counts)
{
    Vec3 radiance = vec3(0, 0, 0), throughput = vec3(1, 1, 1);
    int add_emission = 1; /* camera ray, or after a specular bounce, or M = 0 */
    int after_diffuse = 0; /* a diffuse bounce came before */
    for (int segment = 1;; segment++) {
        Hit hit;
        if (!scene_intersect(scene, ray, INFINITY, &hit))
            break;
        const Material *m = &scene->materials[hit.material];
        int front = vec3_dot(ray.dir, hit.normal) < 0.0;
        Vec3 n = front ? hit.normal : vec3_neg(hit.normal); /* facing the incoming ray */
        Vec3 wo = vec3_neg(ray.dir);
        if (front && add_emission)
            radiance = vec3_add(radiance, vec3_mul(throughput, m->emission));
        if (m->kind == MATERIAL_LIGHT || segment >= s->max_depth)
            break; /* an emitter reflects nothing; or no segment may follow this one */

        Vec3 direction;
        if (material_is_diffuse(m)) {
            if (s->shadow_rays > 0) {
                Vec3 direct = area_light_direct(scene, hit.point, n, wo, m, s->shadow_rays, rng, counts);
                radiance = vec3_add(radiance, vec3_mul(throughput, direct));
            }
            if (caustics) {
                Vec3 caustic = photon_estimate_radiance(caustics->caustics, caustics->radius,
                                                        hit.point, n, wo, m);
                radiance = vec3_add(radiance, vec3_mul(throughput, caustic));
            }
            if (!roulette_survives(s->rr_survival, rng))
                break;
            if (s->rr_survival < 1.0)
                throughput = vec3_scale(throughput, 1.0 / s->rr_survival);
            double u1 = rng_uniform(rng), u2 = rng_uniform(rng);
            throughput = vec3_mul(throughput, diffuse_sample(m, n, wo, u1, u2, &direction));
            add_emission = s->shadow_rays == 0;
            after_diffuse = 1;
        } else if (m->kind == MATERIAL_MIRROR) {
            direction = mirror_reflect(ray.dir, n);
            throughput = vec3_mul(throughput, m->reflectance);
            add_emission = !caustics || !after_diffuse;
        } else {
            direction = glass_scatter(ray.dir, n, front, m->ior, s->fresnel, rng);
            add_emission = !caustics || !after_diffuse;
        }
        counts->bounce++;
        ray = ray_spawn(hit.point, n, direction);
    }
    return radiance;
}

Vec3 path_radiance(const Scene *scene, Ray ray, Rng *rng, const void *settings, RayCounts *counts)
{
    return trace_path(scene, ray, rng, settings, NULL, counts);
}

Vec3 path_radiance_caustics(const Scene *scene, Ray ray, Rng *rng, const void *settings,
                            RayCounts *counts)
{
    const CausticPathSettings *caustics = settings;
    return trace_path(scene, ray, rng, &caustics->path, caustics, counts);
}

void path_describe(const PathSettings *s, char *text, int size)
{
    snprintf(text, (size_t)size, "M=%d rr=%g depth=%d %s", s->shadow_rays, s->rr_survival,
             s->max_depth, s->fresnel == FRESNEL_EXACT ? "exact" : "schlick");
}
