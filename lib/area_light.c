/* area_light.c (chapter 3): uniform area-light sampling and eq. 21. See area_light.h. */
#include "area_light.h"

#include <stdlib.h>

#include "diffuse.h"

void area_lights_free(Scene *scene)
{
    free(scene->light_triangles);
    free(scene->light_cumulative);
    scene->light_triangles = NULL;
    scene->light_cumulative = NULL;
    scene->light_count = 0;
    scene->light_area = 0.0;
}

/* The emitting triangles, with the running sum of their areas. */
int area_lights_list(Scene *scene)
{
    area_lights_free(scene);
    int emitting = 0;
    for (int i = 0; i < scene->triangle_count; i++)
        emitting += material_emits(&scene->materials[scene->triangles[i].material]);
    if (emitting == 0)
        return 0;
    scene->light_triangles = malloc((size_t)emitting * sizeof *scene->light_triangles);
    scene->light_cumulative = malloc((size_t)emitting * sizeof *scene->light_cumulative);
    if (!scene->light_triangles || !scene->light_cumulative)
        return -1;
    for (int i = 0; i < scene->triangle_count; i++) {
        if (!material_emits(&scene->materials[scene->triangles[i].material]))
            continue;
        scene->light_area += scene->triangles[i].area;
        scene->light_triangles[scene->light_count] = i;
        scene->light_cumulative[scene->light_count] = scene->light_area;
        scene->light_count++;
    }
    return 0;
}

LightSample area_light_sample(const Scene *scene, double u_select, double u1, double u2)
{
    /* The first light whose running area sum exceeds u_select * A. */
    double target = u_select * scene->light_area;
    int low = 0, high = scene->light_count - 1;
    while (low < high) {
        int middle = (low + high) / 2;
        if (scene->light_cumulative[middle] > target)
            high = middle;
        else
            low = middle + 1;
    }
    const Triangle *triangle = &scene->triangles[scene->light_triangles[low]];
    double s = sqrt(u1);
    LightSample sample;
    sample.point = triangle_point(triangle, s * (1.0 - u2), s * u2);
    sample.normal = triangle->normal;
    sample.emission = scene->materials[triangle->material].emission;
    return sample;
}

ShadowRay area_light_shadow_ray(const Scene *scene, Vec3 x, Vec3 n, Vec3 wo, const Material *m,
                                Rng *rng, RayCounts *counts)
{
    ShadowRay ray = {.value = vec3(0, 0, 0)};
    double u_select = rng_uniform(rng), u1, u2;
    rng_pair(rng, &u1, &u2);
    LightSample light = area_light_sample(scene, u_select, u1, u2);
    Vec3 to_light = vec3_sub(light.point, x);
    double distance2 = vec3_dot(to_light, to_light);
    Vec3 wi = vec3_scale(to_light, 1.0 / sqrt(distance2));
    double cos_alpha = vec3_dot(n, wi);
    double cos_beta = -vec3_dot(light.normal, wi);
    if (cos_alpha <= 0.0 || cos_beta <= 0.0)
        return ray;
    counts->shadow++;
    if (scene_occluded(scene, x, n, light.point, light.normal))
        return ray;
    Vec3 f = diffuse_brdf(m, n, wi, wo);
    ray.value = vec3_scale(vec3_mul(light.emission, f),
                           scene->light_area * cos_alpha * cos_beta / distance2);
    ray.wi = wi;
    ray.pdf = area_light_pdf(scene, sqrt(distance2), cos_beta);
    return ray;
}

Vec3 area_light_direct(const Scene *scene, Vec3 x, Vec3 n, Vec3 wo, const Material *m,
                       int shadow_rays, Rng *rng, RayCounts *counts)
{
    Vec3 sum = vec3(0, 0, 0);
    for (int k = 0; k < shadow_rays; k++)
        sum = vec3_add(sum, area_light_shadow_ray(scene, x, n, wo, m, rng, counts).value);
    return vec3_scale(sum, 1.0 / shadow_rays);
}

double area_light_pdf(const Scene *scene, double distance, double cos_beta)
{
    return distance * distance / (scene->light_area * cos_beta);
}
