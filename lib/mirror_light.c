/* mirror_light.c (chapter 7): the lamps' images in planar mirrors. See mirror_light.h. */
#include "mirror_light.h"

#include <stdlib.h>

#include "diffuse.h"
#include "mirror.h"

/* A triangle lies in a plane when their normals are parallel (either orientation) and
 * its v0 has the plane's offset, both to the rounding of the numbers compared: the sine
 * of the angle between the normals, and the offsets against the largest term n_i v_i of
 * the dot products that gave them. Nothing absolute: the room scaled by 2^-40 keeps its
 * planes apart as the room does (docs/chapter7.md). */
#define PLANE_TOLERANCE 1e-12

/* The largest term of n . v, what the rounding of the dot product is relative to. */
static double largest_term(Vec3 n, Vec3 v) { return vec3_max_abs(vec3_mul(n, v)); }

static int in_plane(const MirrorPlane *plane, const Triangle *triangle)
{
    double offset = vec3_dot(plane->normal, triangle->v0);
    double terms = max2(plane->largest_term, largest_term(plane->normal, triangle->v0));
    return vec3_length(vec3_cross(plane->normal, triangle->normal)) < PLANE_TOLERANCE &&
           fabs(offset - plane->offset) <= PLANE_TOLERANCE * terms;
}

static int is_mirror_triangle(const Scene *scene, int triangle)
{
    return scene->materials[scene->triangles[triangle].material].kind == MATERIAL_MIRROR;
}

int mirror_light_find_planes(const Scene *scene, MirrorPlanes *mirrors)
{
    mirrors->planes = NULL;
    mirrors->count = 0;
    int mirror_triangles = 0;
    for (int i = 0; i < scene->triangle_count; i++)
        mirror_triangles += is_mirror_triangle(scene, i);
    if (mirror_triangles == 0)
        return 0;
    mirrors->planes = malloc((size_t)mirror_triangles * sizeof *mirrors->planes);
    if (!mirrors->planes)
        return -1;
    for (int i = 0; i < scene->triangle_count; i++) {
        const Triangle *triangle = &scene->triangles[i];
        if (!is_mirror_triangle(scene, i))
            continue;
        int known = 0;
        for (int p = 0; p < mirrors->count && !known; p++)
            known = in_plane(&mirrors->planes[p], triangle);
        if (!known) {
            MirrorPlane plane = {triangle->normal, vec3_dot(triangle->normal, triangle->v0),
                                 largest_term(triangle->normal, triangle->v0)};
            mirrors->planes[mirrors->count++] = plane;
        }
    }
    return 0;
}

void mirror_planes_free(MirrorPlanes *mirrors)
{
    free(mirrors->planes);
    mirrors->planes = NULL;
    mirrors->count = 0;
}

ShadowRay mirror_light_shadow_ray(const Scene *scene, const MirrorPlane *plane, Vec3 x, Vec3 n,
                                  Vec3 wo, const Material *m, Rng *rng, RayCounts *counts)
{
    ShadowRay ray = {vec3(0, 0, 0), vec3(0, 0, 0), 0.0};
    double u_select = rng_uniform(rng), u1, u2;
    rng_pair(rng, &u1, &u2);
    LightSample light = area_light_sample(scene, u_select, u1, u2);
    double height_x = vec3_dot(plane->normal, x) - plane->offset;
    double height_y = vec3_dot(plane->normal, light.point) - plane->offset;
    if (height_x * height_y <= 0.0)
        return ray; /* not on the same side: no way from one to the other by this plane */
    Vec3 image = vec3_add_scaled(light.point, plane->normal, -2.0 * height_y);
    Vec3 image_normal = mirror_reflect(light.normal, plane->normal);
    Vec3 to_image = vec3_sub(image, x);
    double distance = vec3_length(to_image);
    Vec3 wi = vec3_scale(to_image, 1.0 / distance);
    double cos_alpha = vec3_dot(n, wi), cos_beta = -vec3_dot(image_normal, wi);
    if (cos_alpha <= 0.0 || cos_beta <= 0.0)
        return ray;
    counts->shadow++;
    Hit hit;
    /* The segment to the image, offset at x as scene_occluded offsets its ends. */
    Ray to_mirror = ray_spawn(x, n, wi, max2(vec3_max_abs(x), vec3_max_abs(image)));
    if (!scene_intersect(scene, to_mirror, distance, &hit) || hit.triangle < 0)
        return ray;
    const Material *mirror = &scene->materials[hit.material];
    if (mirror->kind != MATERIAL_MIRROR || !in_plane(plane, &scene->triangles[hit.triangle]))
        return ray; /* blocked before the mirror, or missed its polygon */
    counts->shadow++;
    if (scene_occluded(scene, hit.point, hit.normal, light.point, light.normal))
        return ray;
    Vec3 f = vec3_mul(diffuse_brdf(m, n, wi, wo), mirror->reflectance);
    ray.value = vec3_scale(vec3_mul(light.emission, f),
                           scene->light_area * cos_alpha * cos_beta / (distance * distance));
    ray.wi = wi;
    ray.pdf = area_light_pdf(scene, distance, cos_beta);
    return ray;
}
