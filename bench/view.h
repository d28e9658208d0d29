/* view.h (bench, chapter 5): where a point of the scene appears in the image, for the
 * measurements and crops the chapters place by the scene (chapter 5: a sphere's centre and
 * rim; chapter 8: the caustic under the glass sphere, the lamps' image in the mirror).
 *
 * The line from the eye to p crosses the image plane at BL + a (BR - BL) + b (TL - BL);
 * camera.h maps that point to col = a W, row = (1 - b) H. a and b solve the 2 x 2 system
 * of its dot products with the plane's two sides, which need not be perpendicular.
 */
#ifndef VIEW_H
#define VIEW_H

#include "scene.h"
#if CHAPTER >= 8
#include "mirror_light.h"
#endif

/* Where p appears in a width x height image, as a continuous position: pixel (c, r)
 * covers [c, c + 1) x [r, r + 1). Returns 1 if p is in front of the eye, else 0 (the
 * position is then where the line through p crosses the plane behind the eye, or
 * undefined when it never does). */
int view_position(const Camera *camera, int width, int height, Vec3 p, double *col,
                  double *row);

/* The pixel where p appears: 1 if p is in front of the eye and inside the image. */
int view_pixel(const Camera *camera, int width, int height, Vec3 p, int *col, int *row);

#if CHAPTER >= 8
/* The pixel where the caustic of the scene's first glass sphere is seen: a ball lens
 * focuses the lamps' light on the line from their centre (weighted by area) through its
 * own, so where that line, beyond the sphere, meets a surface. 0 if there is no glass
 * sphere, no surface there, or it is out of view. */
int view_caustic_pixel(const Scene *scene, int width, int height, int *col, int *row);

/* The pixel where the lamps' image in the first planar mirror is seen: their centre
 * mirrored in the mirror's plane, if the eye sees that point in a mirror. 0 otherwise. */
int view_mirror_image_pixel(const Scene *scene, const MirrorPlanes *mirrors, int width,
                            int height, int *col, int *row);
#endif

#endif
