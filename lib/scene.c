/* scene.c (chapter 1): the scene's arrays and the ray queries. See scene.h. */
#include "scene.h"

#include <stdlib.h>
#include <string.h>

#if CHAPTER >= 9
#include "query_method.h" /* the queries as scene->query says */
#elif CHAPTER >= 2
/* The queries go through the tree (bvh.h), built over every primitive. */
static int queries_prepare(Scene *scene)
{
    return bvh_build(&scene->bvh, scene_primitives(scene));
}
static void queries_free(Scene *scene) { bvh_free(&scene->bvh); }
static int queries_nearest(const Scene *scene, Ray ray, double *tmax)
{
    return bvh_intersect(&scene->bvh, scene_primitives(scene), ray, tmax);
}
static int queries_any(const Scene *scene, Ray ray, double tmax)
{
    return bvh_occluded(&scene->bvh, scene_primitives(scene), ray, tmax);
}
#else
/* The queries test every primitive, in increasing number (scene.h): nothing is built. */
static int queries_prepare(Scene *scene) { return 0; }
static void queries_free(Scene *scene) {}
static int queries_nearest(const Scene *scene, Ray ray, double *tmax)
{
    int nearest = -1, n = scene->triangle_count;
    for (int i = 0; i < n + scene->sphere_count; i++) {
        double t = i < n ? triangle_intersect(&scene->triangles[i], ray, 0.0, *tmax)
                         : sphere_intersect(&scene->spheres[i - n], ray, 0.0, *tmax);
        if (t < *tmax) {
            *tmax = t;
            nearest = i;
        }
    }
    return nearest;
}
static int queries_any(const Scene *scene, Ray ray, double tmax)
{
    return queries_nearest(scene, ray, &tmax) >= 0;
}
#endif

void scene_init(Scene *scene) { memset(scene, 0, sizeof *scene); }

void scene_free(Scene *scene)
{
    free(scene->materials);
    free(scene->triangles);
    free(scene->spheres);
    free(scene->point_lights);
#if CHAPTER >= 3
    area_lights_free(scene);
#endif
    queries_free(scene);
    scene_init(scene);
}

/* Append one element of `size` bytes to a growable array, doubling its capacity when
 * the count reaches a power of two. Returns the new index, or -1. */
static int append(void **array, int *count, const void *element, size_t size)
{
    int n = *count;
    if ((n & (n - 1)) == 0) {
        size_t capacity = n == 0 ? 1 : 2 * (size_t)n;
        void *grown = realloc(*array, capacity * size);
        if (!grown)
            return -1;
        *array = grown;
    }
    memcpy((char *)*array + (size_t)n * size, element, size);
    *count = n + 1;
    return n;
}

int scene_add_material(Scene *scene, Material material)
{
    return append((void **)&scene->materials, &scene->material_count, &material,
                  sizeof material);
}

int scene_add_triangle(Scene *scene, Triangle triangle)
{
    return append((void **)&scene->triangles, &scene->triangle_count, &triangle,
                  sizeof triangle);
}

int scene_add_sphere(Scene *scene, Sphere sphere)
{
    return append((void **)&scene->spheres, &scene->sphere_count, &sphere, sizeof sphere);
}

int scene_add_point_light(Scene *scene, PointLight light)
{
    return append((void **)&scene->point_lights, &scene->point_light_count, &light,
                  sizeof light);
}

int scene_prepare(Scene *scene)
{
    queries_free(scene);
#if CHAPTER >= 3
    if (area_lights_list(scene) != 0)
        return -1;
#endif
    return queries_prepare(scene);
}

int scene_intersect(const Scene *scene, Ray ray, double tmax, Hit *hit)
{
    int primitive = queries_nearest(scene, ray, &tmax);
    if (primitive < 0)
        return 0;
    hit->t = tmax;
    /* o + t d, put back on the surface from the surface's own numbers (ray.h). */
    Vec3 p = ray_at(ray, tmax);
    if (primitive >= scene->triangle_count) {
        const Sphere *sphere = &scene->spheres[primitive - scene->triangle_count];
        hit->normal = sphere_normal(sphere, p);
        hit->point = vec3_add_scaled(sphere->center, hit->normal, sphere->radius);
        hit->material = sphere->material;
        hit->triangle = -1;
        hit->scale = vec3_max_abs(sphere->center) + sphere->radius;
    } else {
        const Triangle *triangle = &scene->triangles[primitive];
        Vec3 n = triangle->normal;
        Vec3 s = vec3_sub(p, triangle->v0); /* from the triangle's corner to p */
        hit->normal = n;
        hit->point = vec3_add_scaled(p, n, -vec3_dot(s, n));
        hit->material = triangle->material;
        hit->triangle = primitive;
        hit->scale = fabs(n.x * s.x) + fabs(n.y * s.y) + fabs(n.z * s.z);
    }
    return 1;
}

int scene_occluded(const Scene *scene, Vec3 from, Vec3 from_normal, Vec3 to, Vec3 to_normal)
{
    double scale = max2(vec3_max_abs(from), vec3_max_abs(to));
    Vec3 start = ray_offset_origin(from, from_normal, vec3_sub(to, from), scale);
    Vec3 end = ray_offset_origin(to, to_normal, vec3_sub(from, to), scale);
    Vec3 span = vec3_sub(end, start);
    double distance = vec3_length(span);
    Ray ray = {start, vec3_scale(span, 1.0 / distance)};
    return queries_any(scene, ray, distance);
}
