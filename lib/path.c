/* path.c (chapter 2): the Monte Carlo path tracer (caustics from photons: chapter 8).
 * See path.h. */
#include "path.h"

#include <stdarg.h>
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
#if CHAPTER >= 7
#include "mirror_light.h"
#include "mis.h"
#include "sphere_guide.h"
#endif
#if CHAPTER >= 8
#include "photon_estimate.h"
#endif

Vec3 glass_scatter(Vec3 d, Vec3 n, int entering, double ior, const PathSettings *s, Rng *rng)
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

#if CHAPTER >= 7
/* A light sample's share: all of it, or with mis its power-heuristic weight against the
 * BRDF sampling of the same direction (mis.h). */
static Vec3 weighted(ShadowRay sample, Vec3 n, const PathSettings *s)
{
    if (!s->mis)
        return sample.value;
    double weight = mis_power_heuristic(s->shadow_rays, sample.pdf, 1, diffuse_pdf(n, sample.wi));
    return vec3_scale(sample.value, weight);
}

/* The direct light at a diffuse vertex x (chapter 7's eq. 21): M shadow rays to the
 * lamps and, if `images`, M to each planar mirror's image of them (mirror_light.h);
 * each weighted (above). With mis off and no images it is area_light_direct. */
static Vec3 direct_light(const Scene *scene, Vec3 x, Vec3 n, Vec3 wo, const Material *m,
                         int images, const PathSettings *s, Rng *rng, RayCounts *counts)
{
    Vec3 sum = vec3(0, 0, 0);
    for (int k = 0; k < s->shadow_rays; k++)
        sum = vec3_add(sum, weighted(area_light_shadow_ray(scene, x, n, wo, m, rng, counts), n, s));
    if (images)
        for (int p = 0; p < scene->mirror_plane_count; p++)
            for (int k = 0; k < s->shadow_rays; k++) {
                ShadowRay sample = mirror_light_shadow_ray(scene, &scene->mirror_planes[p], x, n,
                                                           wo, m, rng, counts);
                sum = vec3_add(sum, weighted(sample, n, s));
            }
    return vec3_scale(sum, 1.0 / s->shadow_rays);
}

/* The diffuse bounce: cosine-weighted (diffuse.h) or, with sphere_guide, from the mixture
 * aimed at the mirror and glass spheres (sphere_guide.h). Returns the weight f cos / p
 * (0 for a direction below the surface), and the density p in *pdf. */
static Vec3 diffuse_bounce(const Scene *scene, Vec3 x, Vec3 n, Vec3 wo, const Material *m,
                           const PathSettings *s, Rng *rng, Vec3 *wi, double *pdf)
{
    if (s->sphere_guide > 0.0) {
        SphereGuide guide;
        sphere_guide_at(scene, x, n, s->sphere_guide, &guide);
        if (guide.count > 0) {
            double u_select = rng_uniform(rng), u1, u2;
            rng_pair(rng, &u1, &u2);
            *wi = sphere_guide_sample(&guide, n, u_select, u1, u2);
            *pdf = sphere_guide_pdf(&guide, n, *wi);
            double cos_theta = vec3_dot(n, *wi);
            if (cos_theta <= 0.0)
                return vec3(0, 0, 0);
            return vec3_scale(diffuse_brdf(m, n, *wi, wo), cos_theta / *pdf);
        }
    }
    double u1, u2;
    rng_pair(rng, &u1, &u2);
    Vec3 weight = diffuse_sample(m, n, wo, u1, u2, wi);
    *pdf = diffuse_pdf(n, *wi);
    return weight;
}
#endif

#if CHAPTER >= 8
/* One path. With `caustics`, light reaching a diffuse hit through mirrors and glass
 * comes from the photon map instead of from hitting the lamp (path.h). */
static Vec3 trace_path(const Scene *scene, Ray ray, Rng *rng, const PathSettings *s,
                       const CausticPathSettings *caustics, RayCounts *counts)
{
#else
Vec3 path_radiance(const Scene *scene, Ray ray, Rng *rng, const void *settings_pointer,
                   RayCounts *counts)
{
    const PathSettings *s = settings_pointer;
#endif
    Vec3 radiance = vec3(0, 0, 0), throughput = vec3(1, 1, 1);
    int add_emission = 1; /* camera ray, or after a specular bounce, or M = 0 */
#if CHAPTER >= 7
    /* The diffuse vertices so far; since the last one: its segment (-1: none yet),
     * whether it sampled the mirror images, the density of the direction sampled there,
     * and the distance travelled since (up to the last mirror). */
    int diffuse_vertices = 0, diffuse_segment = -1, images = 0;
    double bsdf_pdf = 0.0, travelled = 0.0;
#endif
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
#if CHAPTER >= 7
        else if (front && s->mis && material_emits(m)) {
            /* Light that the last diffuse vertex also sampled (mis.h): its density there in
             * solid angle is area_light_pdf over the whole (unfolded) distance. */
            double light_pdf = area_light_pdf(scene, travelled + hit.t, -vec3_dot(ray.dir, hit.normal));
            double weight = mis_power_heuristic(1, bsdf_pdf, s->shadow_rays, light_pdf);
            radiance = vec3_add(radiance, vec3_mul(throughput, vec3_scale(m->emission, weight)));
        }
#endif
        if (m->kind == MATERIAL_LIGHT || segment >= s->max_depth)
            break; /* an emitter reflects nothing; or no segment may follow this one */

        Vec3 direction;
        if (material_is_diffuse(m)) {
#if CHAPTER >= 3
            if (s->shadow_rays > 0) {
#if CHAPTER >= 7
                /* The images' paths have two segments, which must fit in max_depth. */
                images = diffuse_vertices < s->mirror_light && segment + 2 <= s->max_depth;
                Vec3 direct = direct_light(scene, hit.point, n, wo, m, images, s, rng, counts);
#else
                Vec3 direct = area_light_direct(scene, hit.point, n, wo, m, s->shadow_rays, rng, counts);
#endif
                radiance = vec3_add(radiance, vec3_mul(throughput, direct));
            }
#if CHAPTER >= 8
            if (caustics) {
                Vec3 caustic = photon_estimate_radiance(caustics->caustics, caustics->radius,
                                                        hit.point, n, wo, m);
                radiance = vec3_add(radiance, vec3_mul(throughput, caustic));
            }
#endif
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
#if CHAPTER >= 7
            Vec3 weight = diffuse_bounce(scene, hit.point, n, wo, m, s, rng, &direction, &bsdf_pdf);
            if (weight.x == 0.0 && weight.y == 0.0 && weight.z == 0.0)
                break; /* a guided direction below the surface */
            throughput = vec3_mul(throughput, weight);
            diffuse_vertices++;
            diffuse_segment = segment;
            travelled = 0.0;
#else
            double u1, u2;
            rng_pair(rng, &u1, &u2);
            throughput = vec3_mul(throughput, diffuse_sample(m, n, wo, u1, u2, &direction));
#endif
        } else if (m->kind == MATERIAL_MIRROR) {
            direction = mirror_reflect(ray.dir, n);
            throughput = vec3_mul(throughput, m->reflectance);
#if CHAPTER >= 7
            /* Straight from a diffuse vertex to a planar mirror: that vertex sampled the
             * mirror's image of the lamps (mirror_light.h), so hitting a lamp next is light
             * already counted there (with mis: weighted, above). */
            add_emission = !(images && hit.triangle >= 0 && diffuse_segment == segment - 1);
            travelled += hit.t;
#else
            add_emission = 1;
#endif
#if CHAPTER >= 8
            /* After a diffuse bounce, light through mirrors is the caustic map's. */
            add_emission = add_emission && !(caustics && diffuse_vertices > 0);
#endif
        } else {
            direction = glass_scatter(ray.dir, n, front, m->ior, s, rng);
            add_emission = 1;
#if CHAPTER >= 8
            add_emission = !(caustics && diffuse_vertices > 0); /* and through glass */
#endif
        }
        counts->bounce++;
        ray = ray_spawn(hit.point, n, direction, scene->scale);
    }
    return radiance;
}

#if CHAPTER >= 8
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
#endif

/* Append printf-style text at text[*used], never past text[size - 1]. */
static void append(char *text, int size, int *used, const char *format, ...)
{
    if (*used >= size - 1)
        return;
    va_list args;
    va_start(args, format);
    int n = vsnprintf(text + *used, (size_t)(size - *used), format, args);
    va_end(args);
    *used = n < 0 ? size : *used + n;
}

void path_describe(const PathSettings *s, char *text, int size)
{
    int used = 0;
    text[0] = '\0';
    append(text, size, &used, "depth=%d", s->max_depth);
#if CHAPTER >= 3
    append(text, size, &used, " M=%d", s->shadow_rays);
#endif
#if CHAPTER >= 4
    append(text, size, &used, " %s", s->fresnel == FRESNEL_EXACT ? "exact" : "schlick");
#endif
#if CHAPTER >= 6
    if (s->rr_throughput > 0)
        append(text, size, &used, " rr=throughput@%d", s->rr_throughput);
    else
        append(text, size, &used, " rr=%g", s->rr_survival > 0.0 ? s->rr_survival : 1.0);
#endif
#if CHAPTER >= 7
    if (s->mis)
        append(text, size, &used, " mis");
    if (s->mirror_light > 0)
        append(text, size, &used, " mirror-light@%d", s->mirror_light);
    if (s->sphere_guide > 0.0)
        append(text, size, &used, " sphere-guide=%g", s->sphere_guide);
#endif
}
