/* view.c (bench, chapter 5): where a point of the scene appears in the image. See view.h. */
#include "view.h"

#include <math.h>

int view_position(const Camera *camera, int width, int height, Vec3 p, double *col, double *row)
{
    Vec3 normal = vec3_cross(camera->right, camera->up);
    Vec3 to_point = vec3_sub(p, camera->eye);
    double t = vec3_dot(normal, vec3_sub(camera->bottom_left, camera->eye)) /
               vec3_dot(normal, to_point);
    Vec3 q = vec3_sub(vec3_add_scaled(camera->eye, to_point, t), camera->bottom_left);
    double rr = vec3_dot(camera->right, camera->right), uu = vec3_dot(camera->up, camera->up);
    double ru = vec3_dot(camera->right, camera->up);
    double qr = vec3_dot(q, camera->right), qu = vec3_dot(q, camera->up);
    double determinant = rr * uu - ru * ru;
    double a = (qr * uu - qu * ru) / determinant, b = (qu * rr - qr * ru) / determinant;
    *col = a * width;
    *row = (1.0 - b) * height;
    return t > 0.0;
}

int view_pixel(const Camera *camera, int width, int height, Vec3 p, int *col, int *row)
{
    double x, y;
    if (!view_position(camera, width, height, p, &x, &y) || !(x >= 0.0 && x < width) ||
        !(y >= 0.0 && y < height))
        return 0;
    *col = (int)x;
    *row = (int)y;
    return 1;
}

#if CHAPTER >= 8
/* The lamps' centre, weighted by area. */
static Vec3 lamp_centre(const Scene *scene)
{
    Vec3 lamp = vec3(0, 0, 0);
    for (int k = 0; k < scene->light_count; k++) {
        const Triangle *t = &scene->triangles[scene->light_triangles[k]];
        Vec3 centroid = vec3_add(t->v0, vec3_scale(vec3_add(t->e1, t->e2), 1.0 / 3.0));
        lamp = vec3_add_scaled(lamp, centroid, t->area / scene->light_area);
    }
    return lamp;
}

int view_caustic_pixel(const Scene *scene, int width, int height, int *col, int *row)
{
    Vec3 lamp = lamp_centre(scene);
    for (int i = 0; i < scene->sphere_count; i++) {
        const Sphere *s = &scene->spheres[i];
        if (scene->materials[s->material].kind != MATERIAL_GLASS)
            continue;
        Vec3 d = vec3_normalize(vec3_sub(s->center, lamp));
        Ray beyond = {vec3_add_scaled(s->center, d, 1.0001 * s->radius), d};
        Hit hit;
        return scene_intersect(scene, beyond, INFINITY, &hit) &&
               view_pixel(&scene->camera, width, height, hit.point, col, row);
    }
    return 0;
}

int view_mirror_image_pixel(const Scene *scene, const MirrorPlanes *mirrors, int width,
                            int height, int *col, int *row)
{
    if (mirrors->count == 0)
        return 0;
    const MirrorPlane *plane = &mirrors->planes[0];
    Vec3 lamp = lamp_centre(scene);
    Vec3 image = vec3_add_scaled(lamp, plane->normal,
                                 -2.0 * (vec3_dot(plane->normal, lamp) - plane->offset));
    Ray view = {scene->camera.eye, vec3_normalize(vec3_sub(image, scene->camera.eye))};
    Hit hit;
    return scene_intersect(scene, view, INFINITY, &hit) && hit.triangle >= 0 &&
           scene->materials[hit.material].kind == MATERIAL_MIRROR &&
           view_pixel(&scene->camera, width, height, image, col, row);
}
#endif
