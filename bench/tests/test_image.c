/* test_image.c (bench, chapter 1): the framebuffer, its tone map and its PNG and PFM files
 * (image.h, chapter 1).
 *
 * The tone map is checked at its fixed points and for rounding to the nearest code over
 * the whole range; PFM must round-trip bit for bit, read either byte order, and reject
 * every kind of broken file with a message naming it; PNG must be a PNG of the right
 * size whose pixels are the tone-mapped radiance; and a failed write leaves nothing. A
 * crop, enlarged, by hand.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <dirent.h>
#include <errno.h>
#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include <stb_image.h>

#include "image.h"

/* A fresh directory for each test, so that leftovers can be counted. */
static char scratch_dir[64], scratch_file[600];

static int make_scratch(void **state)
{
    strcpy(scratch_dir, "/tmp/test_image_XXXXXX");
    return mkdtemp(scratch_dir) ? 0 : -1;
}

static const char *in_scratch(const char *name)
{
    snprintf(scratch_file, sizeof scratch_file, "%s/%s", scratch_dir, name);
    return scratch_file;
}

/* How many entries the scratch directory holds; with `remove_them`, they go. */
static int scratch_entries(int remove_them)
{
    DIR *dir = opendir(scratch_dir);
    int count = 0;
    for (struct dirent *entry; dir && (entry = readdir(dir));) {
        if (entry->d_name[0] == '.')
            continue;
        count++;
        if (remove_them)
            remove(in_scratch(entry->d_name));
    }
    if (dir)
        closedir(dir);
    return count;
}

static int remove_scratch(void **state)
{
    scratch_entries(1);
    return rmdir(scratch_dir);
}

static unsigned char *read_whole_file(const char *path, long *size)
{
    FILE *file = fopen(path, "rb");
    assert_non_null(file);
    fseek(file, 0, SEEK_END);
    *size = ftell(file);
    rewind(file);
    unsigned char *data = malloc((size_t)*size + 1);
    assert_non_null(data);
    assert_int_equal(fread(data, 1, (size_t)*size, file), (size_t)*size);
    fclose(file);
    return data;
}

static void write_whole_file(const char *path, const void *data, size_t size)
{
    FILE *file = fopen(path, "wb");
    assert_non_null(file);
    assert_int_equal(fwrite(data, 1, size, file), size);
    assert_int_equal(fclose(file), 0);
}

/* A test image whose every channel value differs: value(col, row, channel). */
static Image numbered_image(int width, int height)
{
    Image image = image_new(width, height);
    assert_non_null(image.pixels);
    for (int i = 0; i < 3 * width * height; i++)
        image.pixels[i] = (float)(i + 1) / (float)(3 * width * height);
    return image;
}

/* The tone map at chosen points, each line saying what it shows. */
static void test_tonemap_values(void **state)
{
    const struct {
        double value, exposure;
        int code;
    } cases[] = {
        /* Black is 0, white 255, and linear 0.5 is sRGB 0.735, code 188 (not 128: the
         * curve spends more codes on the dark end, where the eye discerns more). */
        {0.0, 1.0, 0},
        {1.0, 1.0, 255},
        {0.5, 1.0, 188},
        /* The linear segment near black: 12.92 * 0.002 * 255 = 6.6, code 7. */
        {0.002, 1.0, 7},
        /* Exposure multiplies the radiance before anything else. */
        {0.25, 2.0, 188},
        {1.0, 0.5, 188},
        {0.5, 4.0, 255},
        {100.0, 0.0, 0},
        /* Out of range values clamp. */
        {1.5, 1.0, 255},
        {1e30, 1.0, 255},
        {INFINITY, 1.0, 255},
        {-0.5, 1.0, 0},
        {-INFINITY, 1.0, 0},
        /* NaN (a broken sample, or inf * 0) shows as black, not as noise. */
        {NAN, 1.0, 0},
        {0.5, NAN, 0},
        {INFINITY, 0.0, 0},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        int code = image_tonemap(cases[i].value, cases[i].exposure);
        if (code != cases[i].code)
            fail_msg("tone map of %g at exposure %g is %d, expected %d", cases[i].value,
                     cases[i].exposure, code, cases[i].code);
    }
}

/* The inverse of the sRGB curve: the linear value whose encoding is e. */
static double srgb_decode(double e)
{
    return e <= 0.04045 ? e / 12.92 : pow((e + 0.055) / 1.055, 2.4);
}

/* Rounding is to the nearest code over the whole range: a value encoding to k/255 maps
 * to k, one encoding just below halfway to the next code still maps to k, and one just
 * above maps to k + 1 (truncation would fail the first and the last). */
static void test_tonemap_rounds_to_nearest(void **state)
{
    for (int k = 0; k < 256; k++) {
        assert_int_equal(image_tonemap(srgb_decode(k / 255.0), 1.0), k);
        if (k < 255) {
            assert_int_equal(image_tonemap(srgb_decode((k + 0.49) / 255.0), 1.0), k);
            assert_int_equal(image_tonemap(srgb_decode((k + 0.51) / 255.0), 1.0), k + 1);
        }
    }
}

/* A new image is black and has the requested size; impossible sizes give no pixels
 * (and no size), and freeing twice is harmless. */
static void test_image_new(void **state)
{
    Image image = image_new(3, 2);
    assert_non_null(image.pixels);
    assert_int_equal(image.width, 3);
    assert_int_equal(image.height, 2);
    for (int i = 0; i < 18; i++)
        assert_true(image.pixels[i] == 0.0f);
    image_set(&image, 2, 1, vec3(0.25, 0.5, 0.75));
    assert_true(image_get(&image, 2, 1).y == 0.5);
    assert_true(image.pixels[3 * (1 * 3 + 2) + 2] == 0.75f); /* row-major, RGB */
    image_free(&image);
    assert_null(image.pixels);
    image_free(&image);

    const int bad[][2] = {{0, 5}, {5, 0}, {-1, 5}, {5, -1}, {INT_MAX, INT_MAX}};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        Image none = image_new(bad[i][0], bad[i][1]);
        assert_null(none.pixels);
        assert_int_equal(none.width, 0);
        assert_int_equal(none.height, 0);
    }
}

/* A crop by hand, on a 4 x 3 image whose pixel (c, r) holds (c, r, 0): the square of side
 * 2 asked at (3, 2) pokes out right and below, so it is moved to (2, 1); enlarged twice,
 * crop pixel (x, y) shows (2 + x / 2, 1 + y / 2). A side larger than the image's smaller
 * side is cut to it, and one below 1 is 1. */
static void test_crop_by_hand(void **state)
{
    Image image = image_new(4, 3);
    assert_non_null(image.pixels);
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 4; c++)
            image_set(&image, c, r, vec3(c, r, 0));
    Image crop = image_crop(&image, 3, 2, 2, 2);
    assert_int_equal(crop.width, 4);
    assert_int_equal(crop.height, 4);
    for (int y = 0; y < 4; y++)
        for (int x = 0; x < 4; x++) {
            Vec3 p = image_get(&crop, x, y);
            assert_true(p.x == 2 + x / 2 && p.y == 1 + y / 2);
        }
    image_free(&crop);
    crop = image_crop(&image, -5, -5, 10, 1);
    assert_int_equal(crop.width, 3);
    assert_true(image_get(&crop, 2, 2).x == 2 && image_get(&crop, 2, 2).y == 2);
    image_free(&crop);
    crop = image_crop(&image, 1, 1, 0, 3);
    assert_int_equal(crop.width, 3);
    assert_true(image_get(&crop, 2, 2).x == 1 && image_get(&crop, 2, 2).y == 1);
    image_free(&crop);
    image_free(&image);
}

static void assert_round_trip(const Image *image)
{
    const char *path = in_scratch("round_trip.pfm");
    assert_int_equal(image_write_pfm(image, path), 0);
    Image back;
    char error[256] = "";
    assert_int_equal(image_read_pfm(path, &back, error, sizeof error), 0);
    assert_string_equal(error, "");
    assert_int_equal(back.width, image->width);
    assert_int_equal(back.height, image->height);
    assert_memory_equal(back.pixels, image->pixels,
                        3 * sizeof(float) * (size_t)image->width * (size_t)image->height);
    image_free(&back);
}

/* PFM keeps the radiance bit for bit: odd sizes (so that a row/column mix-up shows),
 * and values from denormal to huge, negative and negative zero. */
static void test_pfm_round_trip_is_bit_exact(void **state)
{
    const int sizes[][2] = {{3, 5}, {1, 1}, {7, 2}, {1, 4}};
    for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; s++) {
        Image image = numbered_image(sizes[s][0], sizes[s][1]);
        assert_round_trip(&image);
        image_free(&image);
    }
    const float extremes[] = {1e-30f, 1e30f, FLT_MAX, FLT_MIN,    1e-40f /* denormal */,
                              -1.5f,  -0.0f, 0.1f,    1.0f / 3.0f};
    Image image = image_new(3, 3);
    memcpy(image.pixels, extremes, sizeof extremes);
    assert_round_trip(&image);
    image_free(&image);
}

/* The file is the documented format: the exact header, then little-endian floats with
 * the bottom row first, and nothing else; nothing but the file is left in the directory. */
static void test_pfm_layout(void **state)
{
    Image image = numbered_image(3, 5);
    const char *path = in_scratch("layout.pfm");
    assert_int_equal(image_write_pfm(&image, path), 0);
    long size;
    unsigned char *data = read_whole_file(path, &size);
    const char header[] = "PF\n3 5\n-1.0\n";
    assert_memory_equal(data, header, strlen(header));
    assert_int_equal(size, (long)strlen(header) + 3 * 5 * 12);
    const unsigned char *first = data + strlen(header);
    uint32_t bits = (uint32_t)first[0] | (uint32_t)first[1] << 8 | (uint32_t)first[2] << 16 |
                    (uint32_t)first[3] << 24;
    float value;
    memcpy(&value, &bits, sizeof value);
    assert_true(value == (float)image_get(&image, 0, 4).x); /* bottom-left pixel, red */
    assert_int_equal(scratch_entries(0), 1);
    free(data);
    image_free(&image);
}

/* A positive scale means big-endian data; the reader turns the bytes round and still
 * puts the first stored row at the bottom. */
static void test_pfm_reads_big_endian(void **state)
{
    const char header[] = "PF\n1 2\n1.0\n";
    const float stored[6] = {1.0f, 2.0f, 3.0f, -0.5f, 1e-30f, 6.25f}; /* bottom, top */
    unsigned char data[sizeof header - 1 + 24];
    memcpy(data, header, sizeof header - 1);
    for (int i = 0; i < 6; i++) {
        uint32_t bits;
        memcpy(&bits, &stored[i], sizeof bits);
        for (int b = 0; b < 4; b++)
            data[sizeof header - 1 + 4 * i + b] = (unsigned char)(bits >> (24 - 8 * b));
    }
    const char *path = in_scratch("big_endian.pfm");
    write_whole_file(path, data, sizeof data);
    Image image;
    char error[256] = "";
    assert_int_equal(image_read_pfm(path, &image, error, sizeof error), 0);
    assert_int_equal(image.width, 1);
    assert_int_equal(image.height, 2);
    const float expected[6] = {-0.5f, 1e-30f, 6.25f, 1.0f, 2.0f, 3.0f}; /* top row first */
    assert_memory_equal(image.pixels, expected, sizeof expected);
    image_free(&image);
}

/* Every broken file is refused with "PATH: what is wrong" and an empty image: the
 * message names the path and contains the given words. */
static void test_pfm_rejects_broken_files(void **state)
{
    const struct {
        const char *header;
        long data_bytes; /* zero bytes of pixel data after the header */
        const char *words;
    } cases[] = {
        {"P6\n1 1\n255\n", 3, "PF"},          /* a PPM, not a PFM */
        {"Pf\n1 1\n-1.0\n", 4, "grey-scale"}, /* one channel */
        {"", 0, "PF"},                        /* empty file */
        {"PF\n-3 5\n-1.0\n", 180, "width"},
        {"PF\n0 5\n-1.0\n", 0, "width"},
        {"PF\n3 0\n-1.0\n", 0, "height"},
        {"PF\n3 x\n-1.0\n", 180, "height"},
        {"PF\n32769 1\n-1.0\n", 0, "width"}, /* one more than the cap */
        {"PF\n1 100000\n-1.0\n", 0, "height"},
        {"PF\n99999999999999999999 1\n-1.0\n", 0, "width"},
        {"PF\n1 1\n0.0\n", 12, "scale"},
        {"PF\n1 1\nnan\n", 12, "scale"},
        {"PF\n1 1\n-inf\n", 12, "scale"},
        {"PF\n1 1\n", 0, "scale"},           /* the header stops short */
        {"PF\n2 1\n-1.0\n", 23, "24 bytes"}, /* truncated by one byte */
        {"PF\n2 1\n-1.0\n", 25, "24 bytes"}, /* one byte too many */
        {"PF\n1 1\n-1.0\n", 0, "12 bytes"},  /* no data at all */
    };
    const char *path = in_scratch("broken.pfm");
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        size_t header_bytes = strlen(cases[i].header);
        unsigned char data[256] = {0};
        memcpy(data, cases[i].header, header_bytes);
        write_whole_file(path, data, header_bytes + (size_t)cases[i].data_bytes);
        Image image = {7, 7, NULL};
        char error[256] = "";
        assert_int_equal(image_read_pfm(path, &image, error, sizeof error), -1);
        assert_null(image.pixels);
        assert_int_equal(image.width, 0);
        assert_int_equal(strncmp(error, path, strlen(path)), 0);
        assert_non_null(strstr(error, cases[i].words));
    }
}

/* A pixel value that is not finite (here +inf, little-endian) is refused too: a
 * reference with one would poison every error measured against it. */
static void test_pfm_rejects_non_finite_pixels(void **state)
{
    const char header[] = "PF\n1 1\n-1.0\n";
    unsigned char data[sizeof header - 1 + 12] = {0};
    memcpy(data, header, sizeof header - 1);
    const unsigned char infinity[4] = {0x00, 0x00, 0x80, 0x7f};
    memcpy(data + sizeof header - 1 + 4, infinity, 4); /* green channel */
    const char *path = in_scratch("infinite.pfm");
    write_whole_file(path, data, sizeof data);
    Image image;
    char error[256] = "";
    assert_int_equal(image_read_pfm(path, &image, error, sizeof error), -1);
    assert_null(image.pixels);
    assert_non_null(strstr(error, "pixel (0, 0) is not finite"));
}

/* A missing file is an error naming the file and the reason; a tiny error buffer is
 * cut short, never overrun. */
static void test_pfm_missing_file(void **state)
{
    const char *path = in_scratch("does_not_exist.pfm");
    Image image;
    char error[256] = "";
    assert_int_equal(image_read_pfm(path, &image, error, sizeof error), -1);
    assert_null(image.pixels);
    assert_int_equal(strncmp(error, path, strlen(path)), 0);
    assert_non_null(strstr(error, strerror(ENOENT)));
    char tiny[8];
    assert_int_equal(image_read_pfm(path, &image, tiny, sizeof tiny), -1);
    assert_int_equal(strlen(tiny), sizeof tiny - 1);
}

/* The PNG starts with the PNG signature and its IHDR chunk gives the size, 8 bits per
 * channel, RGB; decoded, every pixel is the tone map of the radiance. */
static void test_png_is_the_tone_mapped_image(void **state)
{
    Image image = numbered_image(5, 3);
    const double exposure = 2.0;
    const char *path = in_scratch("image.png");
    assert_int_equal(image_write_png(&image, path, exposure), 0);
    long size;
    unsigned char *data = read_whole_file(path, &size);
    const unsigned char signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    const unsigned char ihdr[8] = {0, 0, 0, 13, 'I', 'H', 'D', 'R'};
    assert_true(size > 33);
    assert_memory_equal(data, signature, 8);
    assert_memory_equal(data + 8, ihdr, 8);
    const unsigned char size_and_format[10] = {0, 0, 0, 5, 0, 0, 0, 3, 8 /* bits */,
                                               2 /* RGB */};
    assert_memory_equal(data + 16, size_and_format, 10);
    free(data);

    int width, height, channels;
    unsigned char *decoded = stbi_load(path, &width, &height, &channels, 3);
    assert_non_null(decoded);
    for (int i = 0; i < 3 * 5 * 3; i++)
        assert_int_equal(decoded[i], image_tonemap(image.pixels[i], exposure));
    stbi_image_free(decoded);
    assert_int_equal(scratch_entries(0), 1);
    image_free(&image);
}

/* Both writers refuse `image` at `path` with `expected` errno, and afterwards the
 * scratch directory holds `entries` entries: no file and no temporary file appeared. */
static void assert_writes_fail(const Image *image, const char *path, int expected, int entries)
{
    errno = 0;
    assert_int_equal(image_write_png(image, path, 1.0), -1);
    assert_int_equal(errno, expected);
    errno = 0;
    assert_int_equal(image_write_pfm(image, path), -1);
    assert_int_equal(errno, expected);
    assert_int_equal(scratch_entries(0), entries);
}

/* Writing into a directory that does not exist fails with ENOENT and creates nothing. */
static void test_write_into_missing_directory(void **state)
{
    Image image = numbered_image(4, 4);
    assert_writes_fail(&image, in_scratch("missing/image"), ENOENT, 0);
    image_free(&image);
}

/* When the last step fails after the whole file was written (PATH is a directory, so
 * the rename is refused with EISDIR), the temporary file is removed and the directory
 * stays as it was. */
static void test_failed_rename_leaves_nothing(void **state)
{
    Image image = numbered_image(4, 4);
    assert_int_equal(mkdir(in_scratch("taken"), 0700), 0);
    assert_writes_fail(&image, in_scratch("taken"), EISDIR, 1);
    struct stat info;
    assert_int_equal(stat(in_scratch("taken"), &info), 0);
    assert_true(S_ISDIR(info.st_mode));
    image_free(&image);
}

/* An image without pixels (image_new failed) is refused with EINVAL, writing nothing. */
static void test_write_without_pixels(void **state)
{
    Image none = image_new(0, 0);
    assert_writes_fail(&none, in_scratch("none"), EINVAL, 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_tonemap_values),
        cmocka_unit_test(test_tonemap_rounds_to_nearest),
        cmocka_unit_test(test_image_new),
        cmocka_unit_test(test_crop_by_hand),
        cmocka_unit_test_setup_teardown(test_pfm_round_trip_is_bit_exact, make_scratch,
                                        remove_scratch),
        cmocka_unit_test_setup_teardown(test_pfm_layout, make_scratch, remove_scratch),
        cmocka_unit_test_setup_teardown(test_pfm_reads_big_endian, make_scratch,
                                        remove_scratch),
        cmocka_unit_test_setup_teardown(test_pfm_rejects_broken_files, make_scratch,
                                        remove_scratch),
        cmocka_unit_test_setup_teardown(test_pfm_rejects_non_finite_pixels, make_scratch,
                                        remove_scratch),
        cmocka_unit_test_setup_teardown(test_pfm_missing_file, make_scratch, remove_scratch),
        cmocka_unit_test_setup_teardown(test_png_is_the_tone_mapped_image, make_scratch,
                                        remove_scratch),
        cmocka_unit_test_setup_teardown(test_write_into_missing_directory, make_scratch,
                                        remove_scratch),
        cmocka_unit_test_setup_teardown(test_failed_rename_leaves_nothing, make_scratch,
                                        remove_scratch),
        cmocka_unit_test_setup_teardown(test_write_without_pixels, make_scratch,
                                        remove_scratch),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
