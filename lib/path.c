/* path.c (chapter 2): the Monte Carlo path tracer. See path.h. */
#include "path.h"

#include <stdio.h>

#include "diffuse.h"
#include "mirror.h"
#include "schlick.h"
#include "snell.h"
#if CHAPTER >= 3
#include "area_light.h"
#endif
#if CHAPTER >= 6
#include "roulette.h"
#endif

/* Glass: pick reflection (probability R) or refraction for ray direction d hitting a
 * surface with normal n facing d's origin. Returns the new direction. */
static Vec3 glass_scatter(Vec3 d, Vec3 n, int entering, double ior, const PathSettings *s,
                          Rng *rng)
{
    double n_i = entering ? 1.0 : ior, n_t = entering ? ior : 1.0;
    double cos_i = -vec3_dot(d, n);
#if CHAPTER >= 4
    double reflectance = s->fresnel == FRESNEL_EXACT ? fresnel_reflectance(cos_i, n_i, n_t)
                                                     : schlick_reflectance(cos_i, n_i, n_t);
#else
    (void)s;
    double reflectance = schlick_reflectance(cos_i, n_i, n_t);
#endif
    Vec3 refracted;
    if (rng_uniform(rng) >= reflectance && snell_refract(d, n, n_i, n_t, &refracted))
        return refracted;
    return mirror_reflect(d, n);
}

Vec3 path_radiance(const Scene *scene, Ray ray, Rng *rng, const void *settings_pointer,
                   RayCounts *counts)
{
    const PathSettings *s = settings_pointer;
    Vec3 radiance = vec3(0, 0, 0), throughput = vec3(1, 1, 1);
    int add_emission = 1; /* camera ray, or after a specular bounce, or M = 0 */
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
#if CHAPTER >= 3
            if (s->shadow_rays > 0) {
                Vec3 direct = area_light_direct(scene, hit.point, n, wo, m, s->shadow_rays, rng, counts);
                radiance = vec3_add(radiance, vec3_mul(throughput, direct));
            }
            add_emission = s->shadow_rays == 0;
#else
            add_emission = 1;
#endif
#if CHAPTER >= 6
            double survival = s->rr_survival;
            if (s->rr_throughput > 0)
                survival = segment >= s->rr_throughput ? roulette_survival_from_throughput(throughput)
                                                       : 1.0;
            if (survival > 0.0 && survival < 1.0) {
                if (!roulette_survives(survival, rng))
                    break;
                throughput = vec3_scale(throughput, 1.0 / survival);
            }
#endif
            double u1 = rng_uniform(rng), u2 = rng_uniform(rng);
            throughput = vec3_mul(throughput, diffuse_sample(m, n, wo, u1, u2, &direction));
        } else if (m->kind == MATERIAL_MIRROR) {
            direction = mirror_reflect(ray.dir, n);
            throughput = vec3_mul(throughput, m->reflectance);
            add_emission = 1;
        } else {
            direction = glass_scatter(ray.dir, n, front, m->ior, s, rng);
            add_emission = 1;
        }
        counts->bounce++;
        ray = ray_spawn(hit.point, n, direction);
    }
    return radiance;
}

void path_describe(const PathSettings *s, char *text, int size)
{
    int used = snprintf(text, (size_t)size, "depth=%d", s->max_depth);
#if CHAPTER >= 3
    used += snprintf(text + used, (size_t)(size - used), " M=%d", s->shadow_rays);
#endif
#if CHAPTER >= 4
    used += snprintf(text + used, (size_t)(size - used), " %s",
                     s->fresnel == FRESNEL_EXACT ? "exact" : "schlick");
#endif
#if CHAPTER >= 6
    if (s->rr_throughput > 0)
        used += snprintf(text + used, (size_t)(size - used), " rr=throughput@%d", s->rr_throughput);
    else
        used += snprintf(text + used, (size_t)(size - used), " rr=%g",
                         s->rr_survival > 0.0 ? s->rr_survival : 1.0);
#endif
    (void)used;
}
