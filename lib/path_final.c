/* path_final.c (chapter 7): the final path tracer. See path_final.h. */
#include "path_final.h"

#include "direct_light.h"
#include "roulette.h"
#include "sphere_guide.h"

Vec3 path_final_radiance(const Scene *scene, Ray ray, Rng *rng, const void *settings,
                         RayCounts *counts)
{
    const PathSettings *s = settings;
    Vec3 radiance = vec3(0, 0, 0), throughput = vec3(1, 1, 1);
    int add_emission = 1; /* camera ray, after a mirror or glass, or M = 0 */
    /* Since the last diffuse vertex: its segment, whether it sampled the mirror images,
     * the density of the bounce it drew, and the distance travelled since. */
    int diffuse_vertices = 0, diffuse_segment = -1, images = 0;
    double bounce_pdf = 0.0, travelled = 0.0;
    Vertex x;
    for (int segment = 1; path_vertex(scene, ray, &x); segment++) {
        if (x.front && add_emission) {
            radiance = vec3_add(radiance, vec3_mul(throughput, x.material->emission));
        } else if (x.front && s->mis && material_emits(x.material)) {
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
            add_emission = s->shadow_rays == 0;
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
             * hit next was counted there. */
            int planar_mirror = x.material->kind == MATERIAL_MIRROR && x.hit.triangle >= 0;
            add_emission = !(planar_mirror && images && diffuse_segment == segment - 1);
            travelled += x.hit.t; /* unfolded at mirrors */
        }
        throughput = vec3_mul(throughput, weight);
        counts->bounce++;
        ray = ray_spawn(x.hit.point, x.normal, direction, x.hit.scale);
    }
    return radiance;
}
