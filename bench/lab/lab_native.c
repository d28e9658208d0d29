/* lab_native.c (bench, chapter 8): the lab's renderer as a native program, for its
 * tests and its benchmark (build/lab/lab-native).
 *
 *   lab-native SCENE SETTINGS record COL ROW FIRST COUNT   the paths the inspector shows,
 *                                                          as the page's JSON
 *   lab-native SCENE SETTINGS render OUT.pfm               the image the page renders
 *   lab-native SCENE SETTINGS speed SECONDS                rays per second on one thread
 *
 * SETTINGS are the page's (lab.h, docs/lab.md), e.g. "chapter=2 size=64 spp=8". The
 * image is rendered as the page renders it: the steps of each pixel in order, averaged
 * by Welford's update (renderer.h), on one thread; chapter 10's passes as the page takes
 * them (lab_adaptive_plan, then lab_adaptive_band over the bands). Errors: "lab-native: what is
 * wrong" on stderr, exit status 2 (bad input) or 1.
 */
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "lab.h"
#include "renderer.h"
#include "scene_file.h"
#include "stats.h"

enum {
    BAND = 16
};

static void fail(int status, const char *message)
{
    fprintf(stderr, "lab-native: %s\n", message);
    exit(status);
}

static Lab *open_lab(const char *path, const char *settings)
{
    Lab *lab = lab_new();
    char *text, error[4400];
    size_t length;
    if (!lab)
        fail(1, "out of memory");
    if (scene_file_read(path, &text, &length, error, sizeof error) != 0)
        fail(2, error);
    if (length > 1u << 30 || lab_load_scene(lab, text, (int)length, path) != 0 ||
        lab_configure(lab, settings) != 0)
        fail(2, lab_error(lab));
    free(text);
    return lab;
}

/* A whole number from 0 to INT_MAX, or exit. */
static int whole(const char *text)
{
    char *end;
    errno = 0;
    long long n = strtoll(text, &end, 10);
    if (*text < '0' || *text > '9' || *end != '\0' || errno != 0 || n > INT_MAX) {
        fprintf(stderr, "lab-native: expected a whole number from 0 to %d, got '%s'\n", INT_MAX,
                text);
        exit(2);
    }
    return (int)n;
}

/* Every step of the band starting at row0 (BAND rows at most), into the pixels' sums. */
static double render_band(Lab *lab, int row0, int step, double *out, PixelSum *pixels)
{
    int width = lab_width(lab),
        rows = lab_height(lab) - row0 < BAND ? lab_height(lab) - row0 : BAND;
    if (lab_render_band(lab, step, row0, rows, out) != 0)
        fail(1, lab_error(lab));
    for (long i = 0; i < (long)rows * width; i++) {
        Vec3 value = vec3(out[3 * i], out[3 * i + 1], out[3 * i + 2]);
        if (vec3_is_finite(value))
            pixel_sum_add(&pixels[(long)row0 * width + i], value);
    }
    return lab_rays(lab, 0) + lab_rays(lab, 1) + lab_rays(lab, 2) + lab_rays(lab, 3);
}

/* Render every step, in order, over all bands; returns the rays traced. */
static double render_all(Lab *lab, PixelSum *pixels, double *out)
{
    double rays = 0.0;
    for (int step = 0; step < lab_steps(lab); step++)
        for (int row0 = 0; row0 < lab_height(lab); row0 += BAND)
            rays += render_band(lab, row0, step, out, pixels);
    return rays;
}

/* Chapter 10's passes, planned and sampled band by band, into result->image; returns the
 * rays traced. */
static double render_adaptive(Lab *lab, RenderResult *result)
{
    long count = (long)lab_width(lab) * lab_height(lab);
    double *sums = calloc((size_t)count, LAB_PIXEL_STATE * sizeof *sums),
           *estimate = malloc((size_t)count * sizeof *estimate),
           *values = malloc((size_t)count * 3 * sizeof *values), rays = 0.0;
    int *samples = calloc((size_t)count, sizeof *samples),
        *to_add = malloc((size_t)count * sizeof *to_add);
    if (!sums || !estimate || !values || !samples || !to_add)
        fail(1, "out of memory");
    long active;
    for (int pass = 0;
         (active = lab_adaptive_plan(lab, pass, sums, samples, estimate, to_add)) > 0; pass++)
        for (int row0 = 0; row0 < lab_height(lab); row0 += BAND) {
            int rows = lab_height(lab) - row0 < BAND ? lab_height(lab) - row0 : BAND;
            long first = (long)row0 * lab_width(lab);
            if (lab_adaptive_band(lab, row0, rows, sums + LAB_PIXEL_STATE * first,
                                  samples + first, to_add + first, values + 3 * first) != 0)
                fail(1, lab_error(lab));
            rays += lab_rays(lab, 0) + lab_rays(lab, 1) + lab_rays(lab, 2);
        }
    if (active < 0)
        fail(1, lab_error(lab));
    for (long i = 0; i < 3 * count; i++)
        result->image.pixels[i] = (float)values[i];
    free(sums);
    free(estimate);
    free(values);
    free(samples);
    free(to_add);
    return rays;
}

static void render_command(Lab *lab, const char *path)
{
    int width = lab_width(lab), height = lab_height(lab);
    PixelSum *pixels = calloc((size_t)width * height, sizeof *pixels);
    double *out = malloc(3 * sizeof *out * BAND * (size_t)width);
    RenderResult result = {0};
    result.image = image_new(width, height);
    result.std_error = image_new(width, height);
    result.average_std_error = image_new(width, height);
    if (!pixels || !out || !result.image.pixels || !result.std_error.pixels ||
        !result.average_std_error.pixels)
        fail(1, "out of memory");
    double start = stats_now(), rays;
    if (strstr(lab_settings(lab), "\"chapter\":10,")) {
        rays = render_adaptive(lab, &result);
    } else {
        rays = render_all(lab, pixels, out);
        pixel_sums_finish(pixels, &result);
    }
    if (image_write_pfm(&result.image, path) != 0)
        fail(1, "cannot write the image");
    printf("wrote %s: %d steps, %.0f rays in %.2f s\n", path, lab_steps(lab), rays,
           stats_now() - start);
    render_result_free(&result);
    free(pixels);
    free(out);
}

/* Rays per second on this thread: whole renders until `seconds` have passed; per second
 * of wall time and per second of this process's processor time (what other programs on
 * a shared machine do not change). */
static void speed_command(Lab *lab, double seconds)
{
    int width = lab_width(lab), height = lab_height(lab);
    PixelSum *pixels = calloc((size_t)width * height, sizeof *pixels);
    double *out = malloc(3 * sizeof *out * BAND * (size_t)width);
    if (!pixels || !out)
        fail(1, "out of memory");
    double start = stats_now(), cpu_start = stats_cpu_now(), rays = 0.0, elapsed;
    int renders = 0;
    do {
        rays += render_all(lab, pixels, out);
        renders++;
        elapsed = stats_now() - start;
    } while (elapsed < seconds);
    double cpu = stats_cpu_now() - cpu_start;
    printf("rays %.0f seconds %.3f cpu_seconds %.3f renders %d rays_per_second %.0f "
           "rays_per_cpu_second %.0f\n",
           rays, elapsed, cpu, renders, rays / elapsed, rays / cpu);
    free(pixels);
    free(out);
}

int main(int argc, char **argv)
{
    if (argc < 4)
        fail(2,
             "usage: lab-native SCENE SETTINGS record COL ROW FIRST COUNT | render OUT.pfm | "
             "speed SECONDS");
    Lab *lab = open_lab(argv[1], argv[2]);
    const char *command = argv[3];
    if (strcmp(command, "record") == 0 && argc == 8) {
        const char *json =
            lab_record(lab, whole(argv[4]), whole(argv[5]), whole(argv[6]), whole(argv[7]));
        if (!json)
            fail(2, lab_error(lab));
        puts(json);
    } else if (strcmp(command, "render") == 0 && argc == 5) {
        render_command(lab, argv[4]);
    } else if (strcmp(command, "speed") == 0 && argc == 5) {
        speed_command(lab, (double)whole(argv[4]));
    } else {
        fail(2, "expected record COL ROW FIRST COUNT, render OUT.pfm or speed SECONDS");
    }
    lab_free(lab);
    return 0;
}
