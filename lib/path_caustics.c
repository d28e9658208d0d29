/* path_caustics.c (chapter 8): the final path tracer with caustics from a photon map. See
 * path_caustics.h. */
#include "path_caustics.h"

#include "direct_light.h"
#include "photon_estimate.h"
#include "roulette.h"
#include "sphere_guide.h"

/* How much of the emission a path hits it adds: all (no other estimator finds that
 * light), the share mis leaves to the bounce (the shadow rays or the images found the
 * rest), or none (a photon map's). */
typedef enum {
    EMISSION_ALL,
    EMISSION_SHARE,
    EMISSION_NONE
} Emission;

Vec3 path_caustics_radiance(const Scene *scene, Ray ray, Rng *rng, const void *settings,
                            RayCounts *counts)
{
    const CausticPathSettings *c = settings;
    const PathSettings *s = &c->path;
    Vec3 radiance = vec3(0, 0, 0), throughput = vec3(1, 1, 1);
    Emission emission = EMISSION_ALL;
    /* Since the last diffuse vertex: its segment, whether it sampled the mirror images,
     * the density of the bounce it drew, and the distance travelled since. */
    int diffuse_vertices = 0, diffuse_segment = -1, images = 0;
    double bounce_pdf = 0.0, travelled = 0.0;
    Vertex x;
    for (int segment = 1; path_vertex(scene, ray, &x); segment++) {
        if (x.front && material_emits(x.material) && emission != EMISSION_NONE) {
            double share =
                emission == EMISSION_ALL ? 1.0
                : s->mis ? direct_light_hit_weight(scene, s, bounce_pdf, travelled + x.hit.t,
                                                   vec3_dot(x.wo, x.hit.normal))
                         : 0.0;
            radiance = vec3_add(radiance,
                                vec3_mul(throughput, vec3_scale(x.material->emission, share)));
        }
        if (x.material->kind == MATERIAL_LIGHT || segment >= s->max_depth)
            break;
        Vec3 direction, weight;
        if (material_is_diffuse(x.material)) {
            if (s->shadow_rays > 0) {
                images = s->mirrors && diffuse_vertices < s->mirror_light &&
                         segment + 2 <= s->max_depth;
                Vec3 direct = direct_light(scene, &x, images, s, rng, counts);
                radiance = vec3_add(radiance, vec3_mul(throughput, direct));
            }
            /* L M D from the images where this vertex sampled them, else from the map.
             * The disc's reachable area where the camera sees it; after a diffuse
             * bounce, pi r^2 (the bounce blurs an edge more than the kernel does). */
            const PhotonMap *map = images ? c->split : c->caustics;
            Vec3 caustic = diffuse_vertices == 0
                               ? photon_estimate_reachable(scene, map, c->radius, &x)
                               : photon_estimate_radiance(map, c->radius, x.hit.point, x.normal,
                                                          x.wo, x.material);
            radiance = vec3_add(radiance, vec3_mul(throughput, caustic));
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
            /* After a diffuse vertex, mirrors and glass bring a map's light (L S+ D),
             * but for one planar mirror straight on (L M D) where the images were
             * sampled: theirs, shared by mis with this path. */
            int planar_mirror = x.material->kind == MATERIAL_MIRROR && x.hit.triangle >= 0;
            if (diffuse_vertices == 0)
                emission = EMISSION_ALL;
            else if (planar_mirror && images && diffuse_segment == segment - 1)
                emission = EMISSION_SHARE;
            else
                emission = EMISSION_NONE;
            travelled += x.hit.t; /* unfolded at mirrors */
        }
        throughput = vec3_mul(throughput, weight);
        counts->bounce++;
        ray = ray_spawn(x.hit.point, x.normal, direction, x.hit.scale);
    }
    return radiance;
}
