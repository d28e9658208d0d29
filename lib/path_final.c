/* path_final.c (chapter 7): the final path tracer. See path_final.h. */
#include "path_final.h"

#include <stddef.h>

#include "direct_light.h"
#include "roulette.h"
#include "sphere_guide.h"

/* How much of the emission a path hits it adds: all (no other estimator finds that
 * light), the share mis leaves to the bounce (the shadow rays or the images found the
 * rest), or none (another estimate at the last diffuse vertex found it). */
typedef enum {
    EMISSION_ALL,
    EMISSION_SHARE,
    EMISSION_NONE
} Emission;

Vec3 path_final_trace(const Scene *scene, Ray ray, Rng *rng, const PathSettings *s,
                      const DiffuseEstimate *other, RayCounts *counts)
{
    Vec3 radiance = vec3(0, 0, 0), throughput = vec3(1, 1, 1);
    Emission emission = EMISSION_ALL; /* camera ray, after a mirror or glass, or M = 0 */
    /* Since the last diffuse vertex: its segment, whether it sampled the mirror images,
     * the density of the bounce it drew, and the distance travelled since. */
    int diffuse_vertices = 0, diffuse_segment = -1, images = 0;
    double bounce_pdf = 0.0, travelled = 0.0;
    Vertex x;
    for (int segment = 1; path_vertex(scene, ray, &x); segment++) {
        if (x.front && emission == EMISSION_ALL) {
            radiance = vec3_add(radiance, vec3_mul(throughput, x.material->emission));
        } else if (x.front && emission == EMISSION_SHARE && s->mis &&
                   material_emits(x.material)) {
            double weight = direct_light_hit_weight(scene, s, bounce_pdf, travelled + x.hit.t,
                                                    vec3_dot(x.wo, x.hit.normal));
            radiance = vec3_add(radiance,
                                vec3_mul(throughput, vec3_scale(x.material->emission, weight)));
        }
        if (x.material->kind == MATERIAL_LIGHT || segment >= s->max_depth)
            break;
        Vec3 direction, weight;
        if (material_is_diffuse(x.material)) {
            if (s->shadow_rays > 0) {
                /* The images' paths have two segments more, which must fit in max_depth. */
                images = s->mirrors && diffuse_vertices < s->mirror_light &&
                         segment + 2 <= s->max_depth;
                Vec3 direct = direct_light(scene, &x, images, s, rng, counts);
                radiance = vec3_add(radiance, vec3_mul(throughput, direct));
            }
            if (other) {
                Vec3 found =
                    other->radiance(scene, &x, images, diffuse_vertices, other->context);
                radiance = vec3_add(radiance, vec3_mul(throughput, found));
            }
            emission = s->shadow_rays > 0 ? EMISSION_SHARE : EMISSION_ALL;
            if (!roulette_continues(s, segment, &throughput, rng))
                break;
            weight =
                sphere_guide_bounce(scene, &x, s->sphere_guide, rng, &direction, &bounce_pdf);
            if (weight.x == 0.0 && weight.y == 0.0 && weight.z == 0.0)
                break; /* a guided direction below the surface */
            diffuse_vertices++;
            diffuse_segment = segment;
            travelled = 0.0;
        } else {
            weight = path_specular(&x, ray.dir, s, rng, &direction);
            /* Straight from a vertex that sampled the images to a planar mirror: a lamp
             * hit next was counted there, but for the share mis leaves this path. Any
             * other way through mirrors and glass from a diffuse vertex: the other
             * estimate's, where there is one. */
            int planar_mirror = x.material->kind == MATERIAL_MIRROR && x.hit.triangle >= 0;
            if (planar_mirror && images && diffuse_segment == segment - 1)
                emission = EMISSION_SHARE;
            else if (other && diffuse_vertices > 0)
                emission = EMISSION_NONE;
            else
                emission = EMISSION_ALL;
            travelled += x.hit.t; /* unfolded at mirrors */
        }
        throughput = vec3_mul(throughput, weight);
        counts->bounce++;
        ray = ray_spawn(x.hit.point, x.normal, direction, x.hit.scale);
    }
    return radiance;
}

Vec3 path_final_radiance(const Scene *scene, Ray ray, Rng *rng, const void *settings,
                         RayCounts *counts)
{
    return path_final_trace(scene, ray, rng, settings, NULL, counts);
}
