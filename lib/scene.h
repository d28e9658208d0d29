/* scene.h (chapter 1): everything a scene file declares, and the ray queries against it.
 *
 * Introduced in chapter 1. Flat arrays of materials, triangles (quads, boxes and
 * tetrahedra are split into triangles when read), spheres and point lights; the
 * triangles whose material emits are listed once more as the area lights (chapter 3
 * samples them, area_light.c). "Model only what a scene requires": no scene graph,
 * no instancing, no transforms.
 *
 * Building a scene: scene_file.c reads one from text; tests may also call the
 * scene_add_* functions directly. Either way, call scene_prepare() once before the
 * first query: it builds the light list and the bounding volume hierarchy (bvh.h)
 * through which every ray query goes (and, from chapter 7, the list of planar mirrors,
 * mirror_light.h).
 */
#ifndef SCENE_H
#define SCENE_H

#include <stddef.h>
#include <stdint.h>

#include "bvh.h"
#include "camera.h"
#include "material.h"
#include "sphere.h"
#include "triangle.h"

typedef struct {
    Vec3 position;
    Vec3 intensity; /* radiant intensity, W/sr */
} PointLight;

#if CHAPTER >= 7
/* A plane n . p = offset holding mirror triangles (mirror_light.h). */
typedef struct {
    Vec3 normal;
    double offset;
} MirrorPlane;
#endif

typedef struct {
    char *source;         /* file name the scene came from, for error messages (owned) */
    uint64_t source_hash; /* scene_hash of the file's bytes, as read (scene_file.h) */
    int line_count;       /* its number of lines: where "missing X" errors point */
    int has_camera;
    Camera camera;
    Material *materials;
    int material_count;
    /* The materials by name: an open-addressing hash table of material indices (-1:
     * empty), at most half full, so a lookup compares a name or two however many
     * materials there are (100,000 materials took 33 s to read with a linear scan). */
    int *material_table;
    int material_table_size; /* a power of two, or 0 */
    Triangle *triangles;
    int triangle_count;
    Sphere *spheres;
    int sphere_count;
    PointLight *point_lights;
    int point_light_count;
    /* Built by scene_prepare(): */
    int *light_triangles;     /* indices of emitting triangles */
    double *light_cumulative; /* running sum of their areas, for choosing one by area */
    int light_count;
    double light_area;        /* total emitting area */
    double scale;             /* the largest coordinate magnitude: the ray offset's (ray.h) */
    Bvh bvh;                  /* over all triangles and spheres */
#if CHAPTER >= 7
    MirrorPlane *mirror_planes; /* the distinct planes of the mirror triangles */
    int mirror_plane_count;
#endif
} Scene;

/* What a ray hit. */
typedef struct {
    double t;
    Vec3 point;
    Vec3 normal;  /* unit geometric normal of the front side (outward on spheres) */
    int material;
    int triangle; /* index of the triangle hit, or -1 for a sphere */
} Hit;

void scene_init(Scene *scene);
void scene_free(Scene *scene);

/* Each returns the new element's index, or -1 when memory runs out. */
int scene_add_material(Scene *scene, Material material);
int scene_add_triangle(Scene *scene, Triangle triangle);
int scene_add_sphere(Scene *scene, Sphere sphere);
int scene_add_point_light(Scene *scene, PointLight light);

/* Index of the material called `name`, or -1. */
int scene_find_material(const Scene *scene, const char *name);

/* How many material names scene_find_material compares to look up `name`: the cost of
 * a lookup, which the hash table keeps near 1 (tests/test_scene.c). */
int scene_material_comparisons(const Scene *scene, const char *name);

/* FNV-1a, 64 bits (Fowler, Noll, Vo), over `size` bytes continuing from `hash`; start
 * with SCENE_HASH_START. It names materials in the table and the scene's bytes. */
#define SCENE_HASH_START 0xcbf29ce484222325ULL
uint64_t scene_hash(uint64_t hash, const void *data, size_t size);

/* Build the light list, the hierarchy and the scale. Returns 0, or -1 when memory runs
 * out. */
int scene_prepare(Scene *scene);

/* The nearest hit with t in (0, tmax). Returns 1 and fills *hit, or 0 for a miss. */
int scene_intersect(const Scene *scene, Ray ray, double tmax, Hit *hit);

/* Whether anything blocks the segment from surface point `from` (normal from_normal)
 * to point `to` on a surface with normal to_normal. Both ends are offset off their
 * surfaces (ray.h), so neither end point's own surface blocks. */
int scene_occluded(const Scene *scene, Vec3 from, Vec3 from_normal, Vec3 to, Vec3 to_normal);

#endif
