/* camera.c (chapter 1): the pixel-to-ray mapping of SPEC §4. See camera.h. */
#include "camera.h"

Camera camera_make(Vec3 eye, Vec3 bottom_left, Vec3 bottom_right, Vec3 top_left)
{
    Camera camera = {eye, bottom_left, vec3_sub(bottom_right, bottom_left),
                     vec3_sub(top_left, bottom_left)};
    return camera;
}

double camera_aspect(const Camera *camera)
{
    return vec3_length(camera->right) / vec3_length(camera->up);
}

Ray camera_ray(const Camera *camera, int width, int height, int col, int row, double u, double v)
{
    double x = (col + u) / width;
    double y = 1.0 - (row + v) / height;
    Vec3 on_plane = vec3_add_scaled(vec3_add_scaled(camera->bottom_left, camera->right, x),
                                    camera->up, y);
    Ray ray = {camera->eye, vec3_normalize(vec3_sub(on_plane, camera->eye))};
    return ray;
}

void camera_pixel_position(PixelSampling sampling, int sample, int samples, Rng *rng,
                           double *u, double *v)
{
    if (sampling == PIXEL_RANDOM) {
        *u = rng_uniform(rng);
        *v = rng_uniform(rng);
    } else if (sampling == PIXEL_SUBPIXELS) {
        int columns = (int)ceil(sqrt((double)samples));
        int rows = (samples + columns - 1) / columns;
        *u = (sample % columns + 0.5) / columns;
        *v = (sample / columns + 0.5) / rows;
    } else {
        *u = 0.5;
        *v = 0.5;
    }
}
