/* image.h (bench, chapter 1): a linear RGB framebuffer and its files.
 *
 * Introduced in chapter 1. Pixels hold linear radiance (float RGB, row 0 at the top).
 *
 * Two outputs, for two readers:
 *   - PFM (Portable Float Map, "PF" header, little-endian, rows stored bottom to top):
 *     the radiance itself, what a program compares (image_read_pfm reads it back);
 *   - PNG (through stb_image_write): what a person looks at, after the tone map
 *         value = clamp(exposure * L, 0, 1), then the sRGB transfer curve
 *         (12.92 v for v <= 0.0031308, else 1.055 v^(1/2.4) - 0.055),
 *     rounded to 8 bits.
 *
 * Files are written whole or not at all: into "PATH.tmp.PID" first, renamed over PATH
 * only when complete.
 */
#ifndef IMAGE_H
#define IMAGE_H

#include <stdint.h>

#include "vec.h"

typedef struct {
    int width, height;
    float *pixels; /* 3 * width * height floats */
} Image;

/* A black image, or one with pixels == NULL when memory runs out. */
Image image_new(int width, int height);
void image_free(Image *image);

static inline Vec3 image_get(const Image *image, int col, int row)
{
    const float *p = image->pixels + 3 * ((long)row * image->width + col);
    return vec3(p[0], p[1], p[2]);
}

static inline void image_set(Image *image, int col, int row, Vec3 value)
{
    float *p = image->pixels + 3 * ((long)row * image->width + col);
    p[0] = (float)value.x;
    p[1] = (float)value.y;
    p[2] = (float)value.z;
}

/* The square of side `side` (at least 1, at most the image's smaller side) whose top-left
 * pixel is (left, top), moved inside the image where it pokes out, each pixel repeated
 * `scale` times across and down: a crop enlarged without blurring. pixels == NULL when
 * memory runs out. */
Image image_crop(const Image *image, int left, int top, int side, int scale);

/* The tone map above, for one channel value, to an 8-bit sRGB code. */
uint8_t image_tonemap(double value, double exposure);

/* Each returns 0, or -1 with errno describing the failure (nothing is left at path). */
int image_write_png(const Image *image, const char *path, double exposure);
int image_write_pfm(const Image *image, const char *path);

/* Reads an RGB PFM ("PF") of either byte order (the sign of the scale: negative is
 * little-endian; its magnitude is not applied). Everything is checked: the magic, each
 * side from 1 to IMAGE_MAX_SIDE, a finite non-zero scale, exactly 12 * width * height
 * bytes of data, every value finite. Returns 0, or -1 with "PATH: what is wrong" in
 * error[error_size] (the image is then empty). */
#define IMAGE_MAX_SIDE (1 << 15)
int image_read_pfm(const char *path, Image *image, char *error, int error_size);

/* The two halves of image_write_png, for figure.c, which tone maps several images into
 * one picture: tone map every pixel into 8-bit RGB rows `stride` bytes apart; write
 * width x height 8-bit RGB pixels (rows 3 * width bytes apart) as a PNG. */
void image_tonemap_rgb8(const Image *image, double exposure, uint8_t *rgb, long stride);
int image_write_rgb8_png(const uint8_t *rgb, int width, int height, const char *path);

#endif
