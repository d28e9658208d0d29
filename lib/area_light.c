/* area_light.c (chapter 3): uniform area-light sampling and eq. 21. See area_light.h. */
#include "area_light.h"

#include "diffuse.h"

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

Vec3 area_light_direct(const Scene *scene, Vec3 x, Vec3 n, Vec3 wo, const Material *m,
                       int shadow_rays, Rng *rng, RayCounts *counts)
{
    Vec3 sum = vec3(0, 0, 0);
    for (int k = 0; k < shadow_rays; k++) {
        double u_select = rng_uniform(rng), u1 = rng_uniform(rng), u2 = rng_uniform(rng);
        LightSample light = area_light_sample(scene, u_select, u1, u2);
        Vec3 to_light = vec3_sub(light.point, x);
        double distance2 = vec3_dot(to_light, to_light);
        Vec3 wi = vec3_scale(to_light, 1.0 / sqrt(distance2));
        double cos_alpha = vec3_dot(n, wi);
        double cos_beta = -vec3_dot(light.normal, wi);
        if (cos_alpha <= 0.0 || cos_beta <= 0.0)
            continue;
        counts->shadow++;
        if (scene_occluded(scene, x, n, light.point, light.normal))
            continue;
        Vec3 f = diffuse_brdf(m, n, wi, wo);
        sum = vec3_add(sum, vec3_scale(vec3_mul(light.emission, f), cos_alpha * cos_beta / distance2));
    }
    return vec3_scale(sum, scene->light_area / shadow_rays);
}
