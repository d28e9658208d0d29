/* camera.h (chapter 1): rays from the eye through the image plane (report §3.3, §4.1).
 *
 * The scene gives the eye and three corners of the image plane; the camera ray of point
 * (u, v) in [0, 1)^2 of pixel (col, row) of a W x H image, row 0 at the top, runs from the
 * eye through BL + (col + u) / W (BR - BL) + (1 - (row + v) / H) (TL - BL).
 */
#ifndef CAMERA_H
#define CAMERA_H

#include "ray.h"

typedef struct {
    Vec3 eye;
    Vec3 bottom_left;
    Vec3 right; /* BR - BL: the image plane's full width */
    Vec3 up;    /* TL - BL: the image plane's full height */
} Camera;

Camera camera_make(Vec3 eye, Vec3 bottom_left, Vec3 bottom_right, Vec3 top_left);

/* Exercise 1.3: the unit-direction ray through point (u, v) of pixel (col, row). */
Ray camera_ray(const Camera *camera, int width, int height, int col, int row, double u,
               double v);

#endif
