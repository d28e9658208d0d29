/* path.c (chapter 2): the path tracer that finds light by hitting it, and the helpers
 * every path tracer shares. See path.h. */
#include "path.h"

#include "diffuse.h"
#include "glass.h"
#include "mirror.h"

int path_vertex(const Scene *scene, Ray ray, Vertex *x)
{
    if (!scene_intersect(scene, ray, INFINITY, &x->hit))
        return 0;
    x->material = &scene->materials[x->hit.material];
    x->front = vec3_dot(ray.dir, x->hit.normal) < 0.0;
    x->normal = x->front ? x->hit.normal : vec3_neg(x->hit.normal);
    x->wo = vec3_neg(ray.dir);
    return 1;
}

Vec3 path_diffuse_bounce(const Vertex *x, Rng *rng, Vec3 *direction)
{
    double u1, u2;
    rng_pair(rng, &u1, &u2);
    return diffuse_sample(x->material, x->normal, x->wo, u1, u2, direction);
}

Vec3 path_specular(const Vertex *x, Vec3 d, const PathSettings *settings, Rng *rng,
                   Vec3 *direction)
{
    if (x->material->kind == MATERIAL_MIRROR) {
        *direction = mirror_reflect(d, x->normal);
        return x->material->reflectance;
    }
    *direction = glass_scatter(d, x->normal, x->front, x->material->ior, settings, rng);
    return vec3(1, 1, 1);
}

/* Eq. 1 sampled along one path: each vertex adds the emission it shows the path,
 * weighted by the throughput so far; an emitter reflects nothing and ends it. */
Vec3 path_radiance(const Scene *scene, Ray ray, Rng *rng, const void *settings,
                   RayCounts *counts)
{
    const PathSettings *s = settings;
    Vec3 radiance = vec3(0, 0, 0), throughput = vec3(1, 1, 1);
    Vertex x;
    for (int segment = 1; path_vertex(scene, ray, &x); segment++) {
        if (x.front)
            radiance = vec3_add(radiance, vec3_mul(throughput, x.material->emission));
        if (x.material->kind == MATERIAL_LIGHT || segment >= s->max_depth)
            break;
        Vec3 direction;
        Vec3 weight = material_is_diffuse(x.material)
                          ? path_diffuse_bounce(&x, rng, &direction)
                          : path_specular(&x, ray.dir, s, rng, &direction);
        throughput = vec3_mul(throughput, weight);
        counts->bounce++;
        ray = ray_spawn(x.hit.point, x.normal, direction, x.hit.scale);
    }
    return radiance;
}
