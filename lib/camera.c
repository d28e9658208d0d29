/* camera.c (chapter 1): the pixel-to-ray mapping. See camera.h. */
#include "camera.h"

Camera camera_make(Vec3 eye, Vec3 bottom_left, Vec3 bottom_right, Vec3 top_left)
{
    Camera camera = {eye, bottom_left, vec3_sub(bottom_right, bottom_left),
                     vec3_sub(top_left, bottom_left)};
    return camera;
}

Ray camera_ray(const Camera *camera, int width, int height, int col, int row, double u,
               double v)
{
    double x = (col + u) / width;
    double y = 1.0 - (row + v) / height;
    Vec3 on_plane =
        vec3_add_scaled(vec3_add_scaled(camera->bottom_left, camera->right, x), camera->up, y);
    Ray ray = {camera->eye, vec3_normalize(vec3_sub(on_plane, camera->eye))};
    return ray;
}
