/* camera.h (chapter 1): rays from the eye through the image plane (report §3.3, §4.1, Figure 6).
 *
 * Introduced in chapter 1. The scene file gives the eye and three corners of the image
 * plane (SPEC §4). Pixel (col, row) of a W x H image, row 0 at the top, covers
 *     BL + (col + u) / W * (BR - BL) + (1 - (row + v) / H) * (TL - BL),   u, v in [0, 1),
 * and a camera ray runs from the eye through one such point.
 *
 * Where in the pixel (report §3.3.1, supersampling):
 *   - PIXEL_CENTRE: u = v = 1/2, one ray per pixel (Whitted, chapter 1);
 *   - PIXEL_RANDOM: u, v uniform in [0, 1) ("ray randomization", chapter 2);
 *   - PIXEL_SUBPIXELS: the report's "sub pixels", stratified and jittered (chapter 2);
 *   - PIXEL_STRATIFIED: sub-pixels, and the numbers the estimator draws in pairs
 *     stratified across the pixel's samples as well (chapter 7; sobol.h, render.c).
 *
 * Sub-pixels (chapter 2). The pixel is cut into n = samples strata of equal area 1/n,
 * for any n: r = round(sqrt(n)) rows, row k holding c_k = floor((k+1) n / r) -
 * floor(k n / r) cells (the n cells shared out as evenly as the rows allow) and c_k / n
 * of the pixel's height, so each cell is (1 / c_k) x (c_k / n), nearly square; n = 16
 * gives the 4 x 4 grid, n = 5 a row of 2 cells above a row of 3. Cells are numbered
 * row by row from the top-left. A sample goes to a uniformly random point of its cell
 * ("jittered"): placed at the cell's centre instead, it would estimate the image at n
 * fixed points, a quadrature with an aliasing bias at every edge; jittered, its expected
 * value is the cell's average, and n of them average to the pixel's.
 *
 * The order of the cells, and a render stopped early: one stopped (SIGINT) after k < n
 * samples per pixel must still be unbiased. No fixed order can make every prefix cover
 * the pixel evenly: k cells of area 1/n cover only k/n of it, and visiting them top row
 * first samples only the top strip of every pixel. (Counting only whole passes over the
 * n cells would be unbiased too, but with n = spp a stopped render would keep nothing.)
 * What does make every prefix unbiased is
 * that each sample on its own is uniform over the pixel. So each pixel starts its visit
 * at its own random cell s, uniform in [0, n) (camera_first_stratum), and sample i goes
 * to cell
 *     sigma((s + i) mod n),   sigma(j) = j g mod n,
 * g the integer nearest n / phi (phi the golden ratio) that shares no factor with n, so
 * that sigma is a permutation. Sample i is then in a uniformly random cell, jittered
 * within it: uniform over the pixel, whatever i, so the mean of any first k samples is
 * unbiased, and the n samples together take one cell each (stratified). The golden-ratio
 * stride only spreads the cells a prefix visits (consecutive samples land about 0.62 of
 * the pixel's height apart), so that a stopped render is not noisier than it need be;
 * any permutation would keep the prefixes unbiased.
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

typedef enum {
    PIXEL_CENTRE,
    PIXEL_SUBPIXELS,
    PIXEL_RANDOM,
#if CHAPTER >= 7
    PIXEL_STRATIFIED /* sub-pixels, and the estimator's pairs of numbers too (sobol.h) */
#endif
} PixelSampling;

/* Whether the samples are placed on sub-pixels (PIXEL_SUBPIXELS, PIXEL_STRATIFIED). */
int camera_uses_subpixels(PixelSampling sampling);

Camera camera_make(Vec3 eye, Vec3 bottom_left, Vec3 bottom_right, Vec3 top_left);

/* The image plane's width over its height: a W x H image must have W / H equal to it. */
double camera_aspect(const Camera *camera);

/* The unit-direction ray through position (u, v) in [0,1)^2 of pixel (col, row). */
Ray camera_ray(const Camera *camera, int width, int height, int col, int row, double u, double v);

/* The cell a pixel's visit of its `samples` strata starts at: uniform in [0, samples),
 * drawn from pixel_rng, a generator of the pixel's own, the same for all its samples
 * (render.c uses rng_for_sample(seed, pixel, RENDER_PIXEL_STREAM)). 0 when samples = 1,
 * without drawing. */
int camera_first_stratum(Rng *pixel_rng, int samples);

/* Position (u, v) of sample `sample` out of `samples` in a pixel. rng is the sample's
 * own generator: PIXEL_RANDOM draws u then v from it, PIXEL_SUBPIXELS the jitter within
 * the cell (u then v); PIXEL_CENTRE draws nothing (rng may be NULL). first_stratum
 * (camera_first_stratum) is used by PIXEL_SUBPIXELS only. */
void camera_pixel_position(PixelSampling sampling, int sample, int samples, int first_stratum,
                           Rng *rng, double *u, double *v);

/* The cell (0 <= cell < samples) of sub-pixel sample `sample`, as described above. */
int camera_stratum(int sample, int samples, int first_stratum);

/* Where cell `cell` of `samples` lies: u in [u0, u0 + width), v in [v0, v0 + height). */
void camera_stratum_bounds(int cell, int samples, double *u0, double *v0, double *width,
                           double *height);

#endif
