/* scene.h (chapter 1): everything a scene declares, and the ray queries against it.
 *
 * Flat arrays of materials, triangles (quads, boxes and tetrahedra are split into
 * triangles when read), spheres and point lights; no scene graph, no transforms. Add
 * the elements (scene_add_*), then call scene_prepare() once before the first query:
 * it lists the emitting triangles as the area lights and builds the bounding volume
 * hierarchy (bvh.h) through which every query goes.
 */
#ifndef SCENE_H
#define SCENE_H

#include "bvh.h"
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
    /* Built by scene_prepare(): */
    int *light_triangles;     /* indices of the emitting triangles */
    double *light_cumulative; /* running sum of their areas, for choosing one by area */
    int light_count;
    double light_area;        /* total emitting area */
    Bvh bvh;                  /* over all triangles and spheres */
} Scene;

/* What a ray hit. */
typedef struct {
    double t;
    Vec3 point;
    Vec3 normal;  /* unit geometric normal of the front side (outward on spheres) */
    int material;
    int triangle; /* index of the triangle hit, or -1 for a sphere */
    double scale; /* what the point's error along the normal is relative to besides its
                     own coordinates: the surface's numbers (ray.h) */
} Hit;

void scene_init(Scene *scene);
void scene_free(Scene *scene);

/* Each returns the new element's index, or -1 when memory runs out. */
int scene_add_material(Scene *scene, Material material);
int scene_add_triangle(Scene *scene, Triangle triangle);
int scene_add_sphere(Scene *scene, Sphere sphere);
int scene_add_point_light(Scene *scene, PointLight light);

/* Build the light list and the hierarchy. Returns 0, or -1 when memory runs out. */
int scene_prepare(Scene *scene);

/* The nearest hit with t in (0, tmax). Returns 1 and fills *hit, or 0 for a miss. */
int scene_intersect(const Scene *scene, Ray ray, double tmax, Hit *hit);

/* Whether anything blocks the segment from surface point `from` (normal from_normal)
 * to point `to` on a surface with normal to_normal. Both ends are moved off their
 * surfaces by the segment's largest coordinate (ray.h), so neither end's own surface
 * blocks. */
int scene_occluded(const Scene *scene, Vec3 from, Vec3 from_normal, Vec3 to, Vec3 to_normal);

#endif
