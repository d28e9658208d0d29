/* scene.h (chapter 1): everything a scene declares, and the ray queries against it.
 *
 * A scene is flat arrays of materials, triangles, spheres and point lights, with no
 * scene graph and no transforms: the scene file's quads, boxes and tetrahedra are split
 * into triangles when it is read. Add the elements (scene_add_*), then call
 * scene_prepare() once before the first query.
 */
#ifndef SCENE_H
#define SCENE_H

#if CHAPTER >= 2
#include "bvh.h"
#endif
#if CHAPTER >= 9
#include "wide_bvh.h"

/* How the ray queries find a hit: chapter 9 measures each. */
typedef enum {
    QUERY_WIDE_TREE,
    QUERY_BINARY_TREE,
    QUERY_EVERY_PRIMITIVE
} QueryMethod;
#endif
#include "camera.h"
#include "material.h"
#include "sphere.h"
#include "triangle.h"

typedef struct {
    Vec3 position;
    Vec3 intensity; /* radiant intensity, W/sr */
} PointLight;

typedef struct {
    Camera camera;
    Material *materials;
    int material_count;
    Triangle *triangles;
    int triangle_count;
    Sphere *spheres;
    int sphere_count;
    PointLight *point_lights;
    int point_light_count;
#if CHAPTER >= 2
    Bvh bvh; /* the tree over all triangles and spheres, built by scene_prepare() */
#endif
#if CHAPTER >= 3
    int *light_triangles;     /* indices of the emitting triangles */
    double *light_cumulative; /* running sum of their areas, for choosing one by area */
    int light_count;
    double light_area; /* total emitting area */
#endif
#if CHAPTER >= 9
    WideBvh wide;      /* the same tree made four-wide */
    QueryMethod query; /* QUERY_WIDE_TREE unless set after scene_prepare() */
#endif
} Scene;

/* What a ray hit. */
typedef struct {
    double t;
    Vec3 point;
    Vec3 normal; /* unit geometric normal of the front side (outward on spheres) */
    int material;
    int triangle; /* index of the triangle hit, or -1 for a sphere */
    double scale; /* the magnitude of the surface's numbers the point came from (ray.h) */
} Hit;

#if CHAPTER >= 2
/* The primitives the hierarchy is built over (bvh.h). */
static inline BvhPrimitives scene_primitives(const Scene *scene)
{
    return (BvhPrimitives){scene->triangles, scene->triangle_count, scene->spheres,
                           scene->sphere_count};
}
#endif

void scene_init(Scene *scene);
void scene_free(Scene *scene);

/* Each returns the new element's index, or -1 when memory runs out. */
int scene_add_material(Scene *scene, Material material);
int scene_add_triangle(Scene *scene, Triangle triangle);
int scene_add_sphere(Scene *scene, Sphere sphere);
int scene_add_point_light(Scene *scene, PointLight light);

/* Build what the queries need. Returns 0, or -1 when memory runs out. */
int scene_prepare(Scene *scene);

/* The nearest hit with t in (0, tmax). Returns 1 and fills *hit, or 0 for a miss. Of
 * primitives hit at the same t, the lower number wins (the triangles are numbered first,
 * then the spheres). */
int scene_intersect(const Scene *scene, Ray ray, double tmax, Hit *hit);

/* Whether anything blocks the segment from surface point `from` (normal from_normal)
 * to point `to` on a surface with normal to_normal; both ends are moved off their
 * surfaces (ray.h), so neither end's own surface blocks. */
int scene_occluded(const Scene *scene, Vec3 from, Vec3 from_normal, Vec3 to, Vec3 to_normal);
#if CHAPTER >= 3

/* The emitting triangles as the area lights: their list, built by scene_prepare() and
 * freed by scene_free() (area_light.c). Returns 0, or -1 when memory runs out. */
int area_lights_list(Scene *scene);
void area_lights_free(Scene *scene);
#endif

#endif
