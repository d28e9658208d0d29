/* path_direct.c (chapter 3): the path tracer with M shadow rays. See path_direct.h. */
#include "path_direct.h"

#include "area_light.h"

Vec3 path_direct_radiance(const Scene *scene, Ray ray, Rng *rng, const void *settings,
                          RayCounts *counts)
{
    const PathSettings *s = settings;
    Vec3 radiance = vec3(0, 0, 0), throughput = vec3(1, 1, 1);
    int add_emission = 1; /* camera ray, after a mirror or glass, or M = 0 */
    Vertex x;
    for (int segment = 1; path_vertex(scene, ray, &x); segment++) {
        if (x.front && add_emission)
            radiance = vec3_add(radiance, vec3_mul(throughput, x.material->emission));
        if (x.material->kind == MATERIAL_LIGHT || segment >= s->max_depth)
            break;
        Vec3 direction, weight;
        if (material_is_diffuse(x.material)) {
            if (s->shadow_rays > 0) {
                Vec3 direct = area_light_direct(scene, x.hit.point, x.normal, x.wo, x.material,
                                                s->shadow_rays, rng, counts);
                radiance = vec3_add(radiance, vec3_mul(throughput, direct));
            }
            add_emission = s->shadow_rays == 0;
            weight = path_diffuse_bounce(&x, rng, &direction);
        } else {
            weight = path_specular(&x, ray.dir, s, rng, &direction);
            add_emission = 1;
        }
        throughput = vec3_mul(throughput, weight);
        counts->bounce++;
        ray = ray_spawn(x.hit.point, x.normal, direction, x.hit.scale);
    }
    return radiance;
}
