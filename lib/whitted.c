/* whitted.c (chapter 1): the Whitted ray tree. See whitted.h. */
#include "whitted.h"

#include "mirror.h"
#include "schlick.h"
#include "snell.h"

/* Hard-shadowed Lambertian shading by the point lights at point p, normal n facing the
 * viewer. */
static Vec3 point_lights_direct(const Scene *scene, Vec3 p, Vec3 n, Vec3 rho, RayCounts *counts)
{
    Vec3 sum = vec3(0, 0, 0);
    for (int i = 0; i < scene->point_light_count; i++) {
        const PointLight *light = &scene->point_lights[i];
        Vec3 to_light = vec3_sub(light->position, p);
        double distance2 = vec3_dot(to_light, to_light);
        double cos_theta = vec3_dot(n, to_light) / sqrt(distance2);
        if (cos_theta <= 0.0)
            continue;
        counts->shadow++;
        if (scene_occluded(scene, p, n, light->position, vec3(0, 0, 0)))
            continue;
        sum = vec3_add(sum, vec3_scale(light->intensity, cos_theta / distance2));
    }
    return vec3_mul(vec3_scale(rho, 1.0 / PI), sum);
}

static Vec3 trace(const Scene *scene, Ray ray, int depth, int max_depth, RayCounts *counts)
{
    Hit hit;
    if (!scene_intersect(scene, ray, INFINITY, &hit))
        return vec3(0, 0, 0);
    const Material *m = &scene->materials[hit.material];
    int front = vec3_dot(ray.dir, hit.normal) < 0.0;
    Vec3 n = front ? hit.normal : vec3_neg(hit.normal); /* facing the incoming ray */
    Vec3 radiance = front ? m->emission : vec3(0, 0, 0);

    if (material_is_diffuse(m))
        return vec3_add(radiance,
                        point_lights_direct(scene, hit.point, n, m->reflectance, counts));
    if (depth >= max_depth || (m->kind != MATERIAL_MIRROR && m->kind != MATERIAL_GLASS))
        return radiance;

    Ray reflected = ray_spawn(hit.point, n, mirror_reflect(ray.dir, n), hit.scale);
    counts->bounce++;
    if (m->kind == MATERIAL_MIRROR) {
        Vec3 incoming = trace(scene, reflected, depth + 1, max_depth, counts);
        return vec3_add(radiance, vec3_mul(m->reflectance, incoming));
    }
    double n_i = front ? 1.0 : m->ior, n_t = front ? m->ior : 1.0;
    double reflectance = schlick_reflectance(-vec3_dot(ray.dir, n), n_i, n_t);
    Vec3 refracted_dir;
    Vec3 sum = vec3_scale(trace(scene, reflected, depth + 1, max_depth, counts), reflectance);
    if (reflectance < 1.0 && snell_refract(ray.dir, n, n_i, n_t, &refracted_dir)) {
        counts->bounce++;
        Ray refracted = ray_spawn(hit.point, n, refracted_dir, hit.scale);
        Vec3 transmitted = trace(scene, refracted, depth + 1, max_depth, counts);
        sum = vec3_add(sum, vec3_scale(transmitted, 1.0 - reflectance));
    }
    return vec3_add(radiance, sum);
}

Vec3 whitted_radiance(const Scene *scene, Ray ray, const void *settings, RayCounts *counts)
{
    const WhittedSettings *s = settings;
    return trace(scene, ray, 1, s->max_depth, counts);
}
