/* camera.h (chapter 1): rays from the eye through the image plane (report §3.3, §4.1, Figure 6).
 *
 * Introduced in chapter 1. The scene file gives the eye and three corners of the image
 * plane (SPEC §4). Pixel (col, row) of a W x H image, row 0 at the top, covers
 *     BL + (col + u) / W * (BR - BL) + (1 - (row + v) / H) * (TL - BL),   u, v in [0, 1),
 * and a camera ray runs from the eye through one such point.
 *
 * Where in the pixel (report §3.3.1, supersampling):
 *   - PIXEL_CENTRE: u = v = 1/2, one ray per pixel (Whitted, chapter 1);
 *   - PIXEL_SUBPIXELS: sample i of n goes to the centre of sub-pixel i of an evenly
 *     spaced grid (the report's "sub pixels", chapter 2);
 *   - PIXEL_RANDOM: u, v uniform in [0, 1) ("ray randomization", chapter 2).
 */
#ifndef CAMERA_H
#define CAMERA_H

#include "ray.h"
#include "rng.h"

typedef struct {
    Vec3 eye;
    Vec3 bottom_left;
    Vec3 right; /* BR - BL: the image plane's full width */
    Vec3 up;    /* TL - BL: the image plane's full height */
} Camera;

typedef enum { PIXEL_CENTRE, PIXEL_SUBPIXELS, PIXEL_RANDOM } PixelSampling;

Camera camera_make(Vec3 eye, Vec3 bottom_left, Vec3 bottom_right, Vec3 top_left);

/* The image plane's width over its height: a W x H image must have W / H equal to it. */
double camera_aspect(const Camera *camera);

/* The unit-direction ray through position (u, v) in [0,1)^2 of pixel (col, row). */
Ray camera_ray(const Camera *camera, int width, int height, int col, int row, double u, double v);

/* Position (u, v) of sample `sample` out of `samples` in a pixel. Sub-pixels: a grid of
 * ceil(sqrt(n)) columns and as many rows as needed (n = 4 gives 2 x 2, n = 16 gives
 * 4 x 4); when n is not a perfect square the last row is only partly filled. */
void camera_pixel_position(PixelSampling sampling, int sample, int samples, Rng *rng,
                           double *u, double *v);

#endif
