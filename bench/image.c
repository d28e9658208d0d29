/* image.c (bench, chapter 1): the linear RGB framebuffer, its tone map, and its PNG and PFM
 * files (chapter 1). See image.h.
 *
 * The report shows its results (section 4) as 8-bit pictures but does not say how
 * radiance becomes a pixel; the tone map here is the usual one: exposure, clamp, the
 * sRGB transfer curve. PFM keeps the radiance itself so that programs can compare it.
 */
#include "image.h"

#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <stb_image_write.h>

#include "atomic_file.h"

Image image_new(int width, int height)
{
    Image image = {0, 0, NULL};
    if (width <= 0 || height <= 0 ||
        (size_t)width > SIZE_MAX / (3 * sizeof(float)) / (size_t)height)
        return image;
    image.pixels = calloc(3 * (size_t)width * (size_t)height, sizeof(float));
    if (image.pixels) {
        image.width = width;
        image.height = height;
    }
    return image;
}

void image_free(Image *image)
{
    free(image->pixels);
    *image = (Image){0, 0, NULL};
}

/* value clamped to [low, high]. */
static int clamp_int(int value, int low, int high)
{
    return value < low ? low : value > high ? high : value;
}

Image image_crop(const Image *image, int left, int top, int side, int scale)
{
    side = clamp_int(side, 1, image->width < image->height ? image->width : image->height);
    left = clamp_int(left, 0, image->width - side);
    top = clamp_int(top, 0, image->height - side);
    Image crop = image_new(side * scale, side * scale);
    for (int y = 0; y < crop.height; y++)
        for (int x = 0; x < crop.width; x++)
            image_set(&crop, x, y, image_get(image, left + x / scale, top + y / scale));
    return crop;
}

/* The tone map: v = clamp(exposure * L, 0, 1) (NaN counts as 0), then the sRGB curve,
 * rounded to the nearest of the 256 codes. */
uint8_t image_tonemap(double value, double exposure)
{
    double v = exposure * value;
    if (!(v > 0.0))
        return 0;
    if (v >= 1.0)
        return 255;
    double encoded = v <= 0.0031308 ? 12.92 * v : 1.055 * pow(v, 1.0 / 2.4) - 0.055;
    return (uint8_t)(255.0 * encoded + 0.5);
}

void image_tonemap_rgb8(const Image *image, double exposure, uint8_t *rgb, long stride)
{
    for (int row = 0; row < image->height; row++) {
        const float *in = image->pixels + 3 * (long)row * image->width;
        uint8_t *out = rgb + row * stride;
        for (long i = 0; i < 3L * image->width; i++)
            out[i] = image_tonemap(in[i], exposure);
    }
}

/* stb_image_write hands over the encoded PNG through this callback; a short write shows
 * up as the stream's error flag, which atomic_close checks. */
static void write_to_file(void *file, void *data, int size)
{
    fwrite(data, 1, (size_t)size, file);
}

int image_write_rgb8_png(const uint8_t *rgb, int width, int height, const char *path)
{
    if (width <= 0 || height <= 0 || width > INT_MAX / 3) {
        errno = EINVAL;
        return -1;
    }
    AtomicFile out;
    if (atomic_open(&out, path) != 0)
        return -1;
    errno = 0;
    int encoded =
        stbi_write_png_to_func(write_to_file, out.file, width, height, 3, rgb, 3 * width);
    if (!encoded && errno == 0)
        errno = ENOMEM; /* the encoder fails only when it runs out of memory */
    return atomic_close(&out, !encoded);
}

int image_write_png(const Image *image, const char *path, double exposure)
{
    if (!image->pixels || image->width > INT_MAX / 3) {
        errno = EINVAL;
        return -1;
    }
    uint8_t *rgb = malloc(3 * (size_t)image->width * (size_t)image->height);
    if (!rgb) {
        errno = ENOMEM;
        return -1;
    }
    image_tonemap_rgb8(image, exposure, rgb, 3L * image->width);
    int status = image_write_rgb8_png(rgb, image->width, image->height, path);
    int saved_errno = errno;
    free(rgb);
    errno = saved_errno;
    return status;
}

/* PFM stores 32-bit IEEE floats; these fix the byte order whatever the machine's is. */
static void float_to_little_endian(float value, unsigned char bytes[4])
{
    uint32_t bits;
    memcpy(&bits, &value, sizeof bits);
    for (int i = 0; i < 4; i++)
        bytes[i] = (unsigned char)(bits >> (8 * i));
}

static float float_from_bytes(const unsigned char bytes[4], int big_endian)
{
    uint32_t bits = 0;
    for (int i = 0; i < 4; i++)
        bits |= (uint32_t)bytes[big_endian ? 3 - i : i] << (8 * i);
    float value;
    memcpy(&value, &bits, sizeof value);
    return value;
}

int image_write_pfm(const Image *image, const char *path)
{
    if (!image->pixels) {
        errno = EINVAL;
        return -1;
    }
    size_t row_bytes = 12 * (size_t)image->width;
    unsigned char *row_data = malloc(row_bytes);
    AtomicFile out;
    if (!row_data || atomic_open(&out, path) != 0) {
        int saved_errno = row_data ? errno : ENOMEM;
        free(row_data);
        errno = saved_errno;
        return -1;
    }
    /* A negative scale means little-endian; rows go from the bottom of the image up. */
    fprintf(out.file, "PF\n%d %d\n-1.0\n", image->width, image->height);
    for (int row = image->height - 1; row >= 0; row--) {
        const float *in = image->pixels + 3 * (long)row * image->width;
        for (size_t i = 0; i < 3 * (size_t)image->width; i++)
            float_to_little_endian(in[i], row_data + 4 * i);
        fwrite(row_data, 1, row_bytes, out.file);
    }
    free(row_data);
    return atomic_close(&out, 0);
}

/* "PATH: what is wrong" into error[size]; returns -1 for the caller to return. */
static int read_failure(char *error, int size, const char *path, const char *format, ...)
{
    if (error && size > 0) {
        int used = snprintf(error, (size_t)size, "%s: ", path);
        if (used >= 0 && used < size) {
            va_list args;
            va_start(args, format);
            vsnprintf(error + used, (size_t)(size - used), format, args);
            va_end(args);
        }
    }
    return -1;
}

/* The next header field: skips white space, reads up to the next white space character
 * and consumes it (after the scale, that one character is all that separates the header
 * from the data). A field longer than the buffer, or none at all, reads as "". */
static void read_field(FILE *file, char *field, size_t size)
{
    int c;
    do
        c = fgetc(file);
    while (c == ' ' || c == '\t' || c == '\n' || c == '\r');
    size_t length = 0;
    for (; c != EOF && c != ' ' && c != '\t' && c != '\n' && c != '\r'; c = fgetc(file)) {
        if (length + 1 >= size) {
            field[0] = '\0';
            return;
        }
        field[length++] = (char)c;
    }
    field[length] = '\0';
}

/* A side length: a whole decimal number from 1 to IMAGE_MAX_SIDE, or 0 when it is not. */
static int parse_side(const char *field)
{
    char *end;
    errno = 0;
    long value = strtol(field, &end, 10);
    if (end == field || *end != '\0' || errno != 0 || value < 1 || value > IMAGE_MAX_SIDE)
        return 0;
    return (int)value;
}

/* The number of bytes from the current position to the end, or -1 when the file cannot
 * tell (a pipe); then the reads themselves find a short file. */
static long bytes_remaining(FILE *file)
{
    long here = ftell(file);
    if (here < 0 || fseek(file, 0, SEEK_END) != 0)
        return -1;
    long end = ftell(file);
    if (fseek(file, here, SEEK_SET) != 0 || end < here)
        return -1;
    return end - here;
}

/* Reads the header and data of an open PFM file into *image (which starts empty). */
static int read_pfm(FILE *file, const char *path, Image *image, char *error, int size)
{
    char magic[8], width_field[16], height_field[16], scale_field[64];
    read_field(file, magic, sizeof magic);
    if (ferror(file))
        return read_failure(error, size, path, "cannot read: %s", strerror(errno));
    if (strcmp(magic, "Pf") == 0)
        return read_failure(error, size, path,
                            "grey-scale PFM ('Pf'); only RGB ('PF') is read");
    if (strcmp(magic, "PF") != 0)
        return read_failure(error, size, path,
                            "not an RGB PFM file (it does not start with 'PF')");
    read_field(file, width_field, sizeof width_field);
    read_field(file, height_field, sizeof height_field);
    read_field(file, scale_field, sizeof scale_field);
    int width = parse_side(width_field), height = parse_side(height_field);
    if (!width)
        return read_failure(error, size, path, "the width is not a whole number from 1 to %d",
                            IMAGE_MAX_SIDE);
    if (!height)
        return read_failure(error, size, path, "the height is not a whole number from 1 to %d",
                            IMAGE_MAX_SIDE);
    char *end;
    double scale = strtod(scale_field, &end);
    if (end == scale_field || *end != '\0' || !isfinite(scale) || scale == 0.0)
        return read_failure(
            error, size, path,
            "the scale is not a finite non-zero number (its sign gives the byte order)");
    int big_endian = scale > 0.0;

    size_t row_bytes = 12 * (size_t)width;
    long expected = (long)row_bytes * height, found = bytes_remaining(file);
    if (found >= 0 && found != expected)
        return read_failure(error, size, path,
                            "%d x %d pixels need %ld bytes of data, the file has %ld", width,
                            height, expected, found);
    *image = image_new(width, height);
    unsigned char *row_data = malloc(row_bytes);
    if (!image->pixels || !row_data) {
        free(row_data);
        return read_failure(error, size, path, "out of memory for %d x %d pixels", width,
                            height);
    }
    int status = 0;
    for (int row = height - 1; row >= 0 && status == 0; row--) {
        size_t got = fread(row_data, 1, row_bytes, file);
        if (got != row_bytes) {
            status =
                ferror(file)
                    ? read_failure(error, size, path, "cannot read: %s", strerror(errno))
                    : read_failure(error, size, path,
                                   "%d x %d pixels need %ld bytes of data, the file ends early",
                                   width, height, expected);
            break;
        }
        float *out = image->pixels + 3 * (long)row * width;
        for (int i = 0; i < 3 * width && status == 0; i++) {
            out[i] = float_from_bytes(row_data + 4 * i, big_endian);
            if (!isfinite(out[i]))
                status =
                    read_failure(error, size, path, "pixel (%d, %d) is not finite", i / 3, row);
        }
    }
    if (status == 0 && fgetc(file) != EOF)
        status = read_failure(error, size, path, "data continues past the %ld bytes of pixels",
                              expected);
    free(row_data);
    return status;
}

int image_read_pfm(const char *path, Image *image, char *error, int error_size)
{
    *image = (Image){0, 0, NULL};
    FILE *file = fopen(path, "rb");
    if (!file)
        return read_failure(error, error_size, path, "cannot open: %s", strerror(errno));
    int status = read_pfm(file, path, image, error, error_size);
    fclose(file);
    if (status != 0)
        image_free(image);
    return status;
}
