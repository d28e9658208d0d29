/* scene.c: the scene's arrays and the ray queries against them (chapter 1).
 * See scene.h. Every query tests every primitive: the room has 36 triangles and
 * 2 spheres, and a student can see at a glance that nothing is missed. */
#include "scene.h"

#include <stdlib.h>
#include <string.h>

void scene_init(Scene *scene)
{
    memset(scene, 0, sizeof *scene);
}

void scene_free(Scene *scene)
{
    free(scene->materials);
    free(scene->triangles);
    free(scene->spheres);
    free(scene->point_lights);
    free(scene->light_triangles);
    free(scene->light_cumulative);
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
    return append((void **)&scene->materials, &scene->material_count, &material, sizeof material);
}

int scene_add_triangle(Scene *scene, Triangle triangle)
{
    return append((void **)&scene->triangles, &scene->triangle_count, &triangle, sizeof triangle);
}

int scene_add_sphere(Scene *scene, Sphere sphere)
{
    return append((void **)&scene->spheres, &scene->sphere_count, &sphere, sizeof sphere);
}

int scene_add_point_light(Scene *scene, PointLight light)
{
    return append((void **)&scene->point_lights, &scene->point_light_count, &light, sizeof light);
}

int scene_find_material(const Scene *scene, const char *name)
{
    for (int i = 0; i < scene->material_count; i++)
        if (strcmp(scene->materials[i].name, name) == 0)
            return i;
    return -1;
}

int scene_prepare(Scene *scene)
{
    free(scene->light_triangles);
    free(scene->light_cumulative);
    scene->light_triangles = NULL;
    scene->light_cumulative = NULL;
    scene->light_count = 0;
    scene->light_area = 0.0;
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

int scene_intersect(const Scene *scene, Ray ray, double tmax, Hit *hit)
{
    int nearest_triangle = -1, nearest_sphere = -1;
    for (int i = 0; i < scene->triangle_count; i++) {
        double t = triangle_intersect(&scene->triangles[i], ray, 0.0, tmax);
        if (t < tmax) {
            tmax = t;
            nearest_triangle = i;
        }
    }
    for (int i = 0; i < scene->sphere_count; i++) {
        double t = sphere_intersect(&scene->spheres[i], ray, 0.0, tmax);
        if (t < tmax) {
            tmax = t;
            nearest_sphere = i;
        }
    }
    if (nearest_triangle < 0 && nearest_sphere < 0)
        return 0;
    hit->t = tmax;
    hit->point = ray_at(ray, tmax);
    if (nearest_sphere >= 0) {
        const Sphere *sphere = &scene->spheres[nearest_sphere];
        hit->normal = sphere_normal(sphere, hit->point);
        hit->material = sphere->material;
        hit->triangle = -1;
    } else {
        const Triangle *triangle = &scene->triangles[nearest_triangle];
        hit->normal = triangle->normal;
        hit->material = triangle->material;
        hit->triangle = nearest_triangle;
    }
    return 1;
}

int scene_occluded(const Scene *scene, Vec3 from, Vec3 from_normal, Vec3 to, Vec3 to_normal)
{
    Vec3 start = ray_offset_origin(from, from_normal, vec3_sub(to, from));
    Vec3 end = ray_offset_origin(to, to_normal, vec3_sub(from, to));
    Vec3 span = vec3_sub(end, start);
    double distance = vec3_length(span);
    Ray ray = {start, vec3_scale(span, 1.0 / distance)};
    for (int i = 0; i < scene->triangle_count; i++)
        if (triangle_intersect(&scene->triangles[i], ray, 0.0, distance) < distance)
            return 1;
    for (int i = 0; i < scene->sphere_count; i++)
        if (sphere_intersect(&scene->spheres[i], ray, 0.0, distance) < distance)
            return 1;
    return 0;
}
