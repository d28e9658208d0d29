/* scene.c (chapter 1): the scene's arrays and the ray queries against them.
 * See scene.h. The queries go through the bounding volume hierarchy (bvh.h),
 * which finds the same hit as testing every primitive, only sooner. */
#include "scene.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#if CHAPTER >= 7
#include "mirror_light.h"
#endif

void scene_init(Scene *scene)
{
    memset(scene, 0, sizeof *scene);
}

void scene_free(Scene *scene)
{
    free(scene->source);
    free(scene->materials);
    free(scene->material_table);
    free(scene->triangles);
    free(scene->spheres);
    free(scene->point_lights);
    free(scene->light_triangles);
    free(scene->light_cumulative);
    bvh_free(&scene->bvh);
#if CHAPTER >= 7
    free(scene->mirror_planes);
#endif
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

uint64_t scene_hash(uint64_t hash, const void *data, size_t size)
{
    const unsigned char *bytes = data;
    for (size_t i = 0; i < size; i++) {
        hash ^= bytes[i];
        hash *= 0x100000001b3ULL; /* the 64-bit FNV prime */
    }
    return hash;
}

/* Linear probing from the name's hash: the slot holding the material called `name`, or
 * the empty slot where it would go. The table is never full, so there is one. Adds the
 * names compared to *comparisons. */
static size_t probe(const Scene *scene, const char *name, int *comparisons)
{
    size_t mask = (size_t)scene->material_table_size - 1;
    size_t slot = (size_t)scene_hash(SCENE_HASH_START, name, strlen(name)) & mask;
    for (;; slot = (slot + 1) & mask) {
        int index = scene->material_table[slot];
        if (index < 0)
            return slot;
        (*comparisons)++;
        if (strcmp(scene->materials[index].name, name) == 0)
            return slot;
    }
}

/* List material `index` in the table under its name, unless a material of that name is
 * there already (then lookups find the first, as a scan would). */
static void list_material(Scene *scene, int index)
{
    int comparisons = 0;
    size_t slot = probe(scene, scene->materials[index].name, &comparisons);
    if (scene->material_table[slot] < 0)
        scene->material_table[slot] = index;
}

/* A table twice the size (at least 16 slots) listing every material. */
static int grow_material_table(Scene *scene)
{
    int size = scene->material_table_size ? 2 * scene->material_table_size : 16;
    int *table = malloc((size_t)size * sizeof *table);
    if (!table)
        return -1;
    for (int i = 0; i < size; i++)
        table[i] = -1;
    free(scene->material_table);
    scene->material_table = table;
    scene->material_table_size = size;
    for (int i = 0; i < scene->material_count; i++)
        list_material(scene, i);
    return 0;
}

int scene_add_material(Scene *scene, Material material)
{
    int index = append((void **)&scene->materials, &scene->material_count, &material,
                       sizeof material);
    if (index < 0)
        return -1;
    if (2 * (long)scene->material_count > scene->material_table_size) {
        if (grow_material_table(scene) != 0) {
            scene->material_count--;
            return -1;
        }
    } else {
        list_material(scene, index);
    }
    return index;
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
    int comparisons = 0;
    return scene->material_table_size ? scene->material_table[probe(scene, name, &comparisons)]
                                      : -1;
}

int scene_material_comparisons(const Scene *scene, const char *name)
{
    int comparisons = 0;
    if (scene->material_table_size)
        probe(scene, name, &comparisons);
    return comparisons;
}

static BvhPrimitives primitives_of(const Scene *scene)
{
    BvhPrimitives p = {scene->triangles, scene->triangle_count, scene->spheres, scene->sphere_count};
    return p;
}

static double max_abs_of(double scale, Vec3 p)
{
    return fmax(scale, vec3_max_abs(p));
}

/* The largest magnitude of any coordinate: of the geometry, the point lights and the
 * camera (a hit point's rounding error is relative to the ray's origin too). */
static double scale_of(const Scene *scene)
{
    double scale = 0.0;
    for (int i = 0; i < scene->triangle_count; i++) {
        const Triangle *t = &scene->triangles[i];
        scale = max_abs_of(scale, t->v0);
        scale = max_abs_of(scale, vec3_add(t->v0, t->e1));
        scale = max_abs_of(scale, vec3_add(t->v0, t->e2));
    }
    for (int i = 0; i < scene->sphere_count; i++)
        scale = fmax(scale, vec3_max_abs(scene->spheres[i].center) + scene->spheres[i].radius);
    for (int i = 0; i < scene->point_light_count; i++)
        scale = max_abs_of(scale, scene->point_lights[i].position);
    if (scene->has_camera) {
        const Camera *c = &scene->camera;
        Vec3 corners[4] = {c->bottom_left, vec3_add(c->bottom_left, c->right),
                           vec3_add(c->bottom_left, c->up),
                           vec3_add(vec3_add(c->bottom_left, c->right), c->up)};
        scale = max_abs_of(scale, c->eye);
        for (int i = 0; i < 4; i++)
            scale = max_abs_of(scale, corners[i]);
    }
    return scale;
}

int scene_prepare(Scene *scene)
{
    scene->scale = scale_of(scene);
    bvh_free(&scene->bvh);
    if (bvh_build(&scene->bvh, primitives_of(scene)) != 0)
        return -1;
#if CHAPTER >= 7
    if (mirror_light_find_planes(scene) != 0)
        return -1;
#endif
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
    int primitive = bvh_intersect(&scene->bvh, primitives_of(scene), ray, &tmax);
    if (primitive < 0)
        return 0;
    hit->t = tmax;
    hit->point = ray_at(ray, tmax);
    if (primitive >= scene->triangle_count) {
        const Sphere *sphere = &scene->spheres[primitive - scene->triangle_count];
        hit->normal = sphere_normal(sphere, hit->point);
        hit->material = sphere->material;
        hit->triangle = -1;
    } else {
        const Triangle *triangle = &scene->triangles[primitive];
        hit->normal = triangle->normal;
        hit->material = triangle->material;
        hit->triangle = primitive;
    }
    return 1;
}

int scene_occluded(const Scene *scene, Vec3 from, Vec3 from_normal, Vec3 to, Vec3 to_normal)
{
    Vec3 start = ray_offset_origin(from, from_normal, vec3_sub(to, from), scene->scale);
    Vec3 end = ray_offset_origin(to, to_normal, vec3_sub(from, to), scene->scale);
    Vec3 span = vec3_sub(end, start);
    double distance = vec3_length(span);
    Ray ray = {start, vec3_scale(span, 1.0 / distance)};
    return bvh_occluded(&scene->bvh, primitives_of(scene), ray, distance);
}
