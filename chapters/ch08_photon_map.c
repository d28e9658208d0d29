/* ch08_photon_map.c (chapter 8): caustics from a photon map, made progressive, on top of chapter 7's
 * final path tracer (beyond the report: its §5 names photon mapping, its reference [9], as
 * the way to caustics and shorter renders).
 *
 * New concepts (lib/): point_grid (points near a place, fast), photon (shooting photons
 * from the lamps, tracing them through mirrors and glass, the caustic map L S+ D),
 * photon_estimate (reflected radiance from the density of photons, and the progressive
 * radius), and path_caustics, chapter 7's final path tracer to which the photon map adds
 * the light that reaches a diffuse surface through mirrors and glass. The bench renders
 * it in independent passes (bench/ppm.h).
 *
 * Why: chapter 7 finds the lamp's light by way of the planar mirror wall with shadow
 * rays to the lamp's image, but the light the glass and mirror spheres focus (light,
 * specular, diffuse: L S+ D) only when a path happens to hit the lamp after them:
 * rarely, and brightly. Photons go the other way and land there in numbers. The paths
 * split: one planar mirror and straight on stays with the images, every other chain of
 * mirrors and glass goes to the map (path_caustics.h), so nothing is counted twice.
 *
 * The experiment:
 *   - the figure: chapter 7's final estimator (Figure 7's: its sub-pixels and stratified
 *     pairs, one shadow ray, bounded roulette, the mirror's images, the sphere guide)
 *     against the same estimator with photon-mapped caustics, at equal time: the photon
 *     version gets as much processor time as chapter 7's took (processor time, all
 *     threads together, so that other programs sharing the machine do not change the
 *     comparison; the wall-clock time is printed too) and renders as many passes as fit,
 *     each continuing the others' samples (PIXEL_PROGRESSIVE: all of them together are
 *     as stratified as chapter 7's sub-pixels and pairs). Captions give the time and the error
 *     against the reference; two more figures enlarge the caustic under the glass sphere
 *     and the lamp's image in the mirror wall;
 *   - a table and a log-log plot of error against time on a quarter-size image, each
 *     setting rendered with SEEDS seeds: chapter 7's final estimator as its samples
 *     double; the photon map as its passes double, with the radius shrinking (alpha =
 *     2/3) and fixed (alpha = 1); and the photon count and initial radius varied. The
 *     error splits into bias and variance. For the K images X_1..X_K of one setting, the
 *     mean over pixels of their sample variance is V, one image's variance. Their average
 *     X has error X - T = b + e (bias b, noise e of variance V / K), and each of two
 *     references R_1, R_2 of independent seeds has R_j - T = n_j. Then
 *         E[(X - R_1)(X - R_2)] = b^2 + V / K,
 *     the references' noise dropping out of the product (n_1 and n_2 are independent of
 *     each other and of e, with mean 0); so bias^2 is the mean of that product minus
 *     V / K, with no estimate of the references' own noise needed. The mean squared
 *     error of one image is bias^2 + V. These are measured without the lamp and its
 *     images in the mirrors and the glass (lamp_mask): their edges' noise is the same
 *     estimator in both and at a quarter size would hide everything else.
 *
 * Photons per pass and the first radius scale with the image: per pass a fixed number of
 * photons per pixel, and the radius in proportion to a pixel's size.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "atomic_file.h"
#include "experiment.h"
#include "path_final.h"
#include "plot.h"
#include "ppm.h"

/* The photon version's settings, for an image 800 pixels wide (they scale: see above);
 * the first radius as a fraction of the view's width at the depth the camera sees
 * (ppm_first_radius: 14.8 in the room, so about 0.05 there). docs/chapter8.md: how they
 * were chosen. */
#define PHOTONS_PER_PIXEL 0.5
#define FIRST_RADIUS_AT_800 0.0034
#define PPM_SPP_PER_PASS 8
#define MAX_PASSES 100000

/* The lamp's images in the mirror wall at the first diffuse vertex only, where the eye
 * sees their light sharp; beyond it the caustic map brings that light too, its blur
 * hidden by the bounce, for less than the images' shadow rays cost. */
#define PHOTON_MIRROR_LIGHT 1

/* The table's settings: seeds per setting, steps of doubling passes (and samples), and
 * camera samples per pass (chapter 7's estimator takes as many per pass of the photon
 * map's). */
enum { SEEDS = 4, STEPS = 5, TABLE_SPP_PER_PASS = 2 };

/* How much the crops are enlarged. */
enum { CROP_SCALE = 5 };

/* The reference: the same image as chapter 7's, shared with it through the cache. */
static void reference_for(const Options *options, const Scene *scene, Reference *reference)
{
    PathSettings estimator = {.max_depth = options->depth, .fresnel = options->fresnel};
    experiment_path_reference(options, scene, &estimator, NULL, 0.0, reference);
}

/* The photon version of chapter 7's final estimator `path` for a width x height image:
 * photons and radius scaled from 800 pixels wide, `spp` camera samples per pass, at most
 * `passes` passes. */
static PpmSettings photon_settings(const PathSettings *path, const Scene *scene, int width,
                                   int height, int spp, int passes)
{
    /* No more photons per pass than a grid takes: a pass then never stores too many. */
    double photons = fmin(PHOTONS_PER_PIXEL * width * height + 0.5, POINT_GRID_MAX_POINTS);
    PpmSettings ppm = {*path, (int)photons,
                       ppm_first_radius(scene, FIRST_RADIUS_AT_800) * 800.0 / width, PPM_ALPHA,
                       spp, passes, 0.0};
    ppm.path.mirror_light = PHOTON_MIRROR_LIGHT;
    return ppm;
}

static void describe_ppm(const PpmSettings *ppm, const PpmResult *result, char *text, size_t size)
{
    char photons[32];
    if (ppm->photons >= 10000)
        snprintf(photons, sizeof photons, "%dk", (ppm->photons + 500) / 1000);
    else
        snprintf(photons, sizeof photons, "%d", ppm->photons);
    snprintf(text, size, "%d x %d spp, M=%d mirror-light@%d, %s photons, r %.3g to %.3g",
             result->passes, ppm->spp, ppm->path.shadow_rays, ppm->path.mirror_light, photons,
             ppm->radius, result->radius);
}

/* Render the photon version, or exit as experiment_render does. Interrupted, the panel
 * `name` (if not NULL) is saved with the passes completed, if there is one. */
static void render_ppm(const Options *options, const char *name, const Scene *scene,
                       const RenderSettings *settings, const PpmSettings *ppm, PpmResult *result)
{
    render_install_interrupt();
    if (ppm_render(scene, settings, ppm, result) != 0)
        cli_fail(1, "out of memory rendering %d x %d with photons", settings->image.width, settings->image.height);
    if (name && result->render.interrupted)
        experiment_write_panel(options, name, &result->render);
    experiment_exit_if_interrupted(&result->render, NULL);
}

/* The mean of each channel over the image. */
static Vec3 channel_means(const Image *image)
{
    double sum[3] = {0, 0, 0};
    long pixels = (long)image->width * image->height;
    for (long i = 0; i < 3 * pixels; i++)
        sum[i % 3] += image->pixels[i];
    return vec3(sum[0] / pixels, sum[1] / pixels, sum[2] / pixels);
}

/* Where the point p is seen, in pixels: where the line from the eye to p crosses the
 * image plane. Returns 0 if that is behind the eye or outside the image. */
static int pixel_of(const Scene *scene, Vec3 p, int width, int height, int *col, int *row)
{
    const Camera *c = &scene->camera;
    Vec3 normal = vec3_cross(c->right, c->up), to_p = vec3_sub(p, c->eye);
    double t = vec3_dot(vec3_sub(c->bottom_left, c->eye), normal) / vec3_dot(to_p, normal);
    if (!(t > 0.0))
        return 0;
    Vec3 q = vec3_sub(vec3_add_scaled(c->eye, to_p, t), c->bottom_left);
    double u = vec3_dot(q, c->right) / vec3_dot(c->right, c->right);
    double v = vec3_dot(q, c->up) / vec3_dot(c->up, c->up);
    *col = (int)(u * width);
    *row = (int)((1.0 - v) * height);
    return *col >= 0 && *col < width && *row >= 0 && *row < height;
}

/* The lamps' centre, weighted by area. */
static Vec3 lamp_centre(const Scene *scene)
{
    Vec3 lamp = vec3(0, 0, 0);
    for (int k = 0; k < scene->light_count; k++) {
        const Triangle *t = &scene->triangles[scene->light_triangles[k]];
        Vec3 centroid = vec3_add(t->v0, vec3_scale(vec3_add(t->e1, t->e2), 1.0 / 3.0));
        lamp = vec3_add_scaled(lamp, centroid, t->area / scene->light_area);
    }
    return lamp;
}

/* Where the caustic of the first glass sphere is seen: a ball lens focuses the lamp's
 * light on the line from the lamp through its centre, so where that line, beyond the
 * sphere, meets a surface. Returns 0 if the scene has no glass sphere or that point is
 * not in view. */
static int caustic_position(const Scene *scene, int width, int height, int *col, int *row)
{
    Vec3 lamp = lamp_centre(scene);
    for (int i = 0; i < scene->sphere_count; i++) {
        const Sphere *s = &scene->spheres[i];
        if (scene->materials[s->material].kind != MATERIAL_GLASS)
            continue;
        Vec3 d = vec3_normalize(vec3_sub(s->center, lamp));
        Ray beyond = {vec3_add_scaled(s->center, d, 1.0001 * s->radius), d};
        Hit hit;
        if (!scene_intersect(scene, beyond, INFINITY, &hit))
            return 0;
        return pixel_of(scene, hit.point, width, height, col, row);
    }
    return 0;
}

/* Where the lamps' image in the first planar mirror is seen: their centre mirrored in
 * its plane, if the eye sees that point in a mirror. Returns 0 otherwise. */
static int mirror_image_position(const Scene *scene, const MirrorPlanes *mirrors, int width,
                                 int height, int *col, int *row)
{
    if (mirrors->count == 0)
        return 0;
    const MirrorPlane *plane = &mirrors->planes[0];
    Vec3 lamp = lamp_centre(scene);
    Vec3 image = vec3_add_scaled(lamp, plane->normal,
                                 -2.0 * (vec3_dot(plane->normal, lamp) - plane->offset));
    Ray view = {scene->camera.eye, vec3_normalize(vec3_sub(image, scene->camera.eye))};
    Hit hit;
    if (!scene_intersect(scene, view, INFINITY, &hit) || hit.triangle < 0 ||
        scene->materials[hit.material].kind != MATERIAL_MIRROR)
        return 0;
    return pixel_of(scene, image, width, height, col, row);
}

/* A square of side width / CROP_SCALE around (col, row), kept inside the image, each
 * pixel repeated CROP_SCALE times. */
static Image crop_around(const Image *image, int col, int row)
{
    int side = image->width / CROP_SCALE < image->height ? image->width / CROP_SCALE : image->height;
    int left = col - side / 2, top = row - side / 2;
    left = left < 0 ? 0 : left + side > image->width ? image->width - side : left;
    top = top < 0 ? 0 : top + side > image->height ? image->height - side : top;
    Image crop = image_new(side * CROP_SCALE, side * CROP_SCALE);
    if (!crop.pixels)
        cli_fail(1, "out of memory for the crop");
    for (int y = 0; y < crop.height; y++)
        for (int x = 0; x < crop.width; x++)
            image_set(&crop, x, y, image_get(image, left + x / CROP_SCALE, top + y / CROP_SCALE));
    return crop;
}

/* The figure NAME of the three images cropped around (col, row). */
static void write_crops(const Options *options, const char *name, const Image images[3],
                        const char *const captions[3], int col, int row)
{
    Image crops[3];
    for (int i = 0; i < 3; i++)
        crops[i] = crop_around(&images[i], col, row);
    experiment_write_figure(options, name, crops, captions, 3, PANEL_EXPOSURE);
    for (int i = 0; i < 3; i++)
        image_free(&crops[i]);
}

/* The figure: chapter 7's final estimator, then the photon version in the same
 * processor time; and the crops. */
static void equal_time_figure(const Options *options, const Scene *scene, const PathSettings *path,
                              const Reference *reference)
{
    RenderSettings settings = experiment_render_settings(options, scene, options->spp,
                                                         PIXEL_STRATIFIED, "chapter 7's final estimator");
    char description[128], text[192];
    describe_path(path, description, sizeof description);
    snprintf(text, sizeof text, "%d spp, %s strata", options->spp, description);
    RenderResult traced;
    double cpu_start = stats_cpu_now();
    experiment_render(scene, &settings, path_final_radiance, path, &traced);
    double path_cpu = stats_cpu_now() - cpu_start;
    experiment_write_panel(options, "ch08_path", &traced);
    TableRow rows[2];
    rows[0] = experiment_row("ch08_path", text, &traced);
    measure_fill_row(&rows[0], &traced.image, reference);

    PpmSettings ppm = photon_settings(path, scene, settings.image.width, settings.image.height,
                                      PPM_SPP_PER_PASS, MAX_PASSES);
    ppm.cpu_seconds = path_cpu;
    settings.label = "photon map";
    settings.image.sampling = PIXEL_PROGRESSIVE; /* stratified over all passes */
    PpmResult photons;
    render_ppm(options, "ch08_photon_map", scene, &settings, &ppm, &photons);
    experiment_write_image(options, "ch08_photon_map", &photons.render.image, PANEL_EXPOSURE);
    describe_ppm(&ppm, &photons, text, sizeof text);
    rows[1] = experiment_row("ch08_photon_map", text, &photons.render);
    measure_fill_row(&rows[1], &photons.render.image, reference);

    char captions[2][320];
    experiment_caption(&rows[0], "chapter 7: final estimator (Figure 7)", captions[0], sizeof captions[0]);
    experiment_caption(&rows[1], "chapter 8: + photon-mapped caustics, equal time",
                       captions[1], sizeof captions[1]);
    const char *caption_list[] = {captions[0], captions[1]};
    Image panels[2] = {traced.image, photons.render.image};
    experiment_write_figure(options, "ch08_equal_time", panels, caption_list, 2, PANEL_EXPOSURE);
    experiment_write_table(options, "ch08_equal_time", rows, 2);

    /* The rows' RMSE has the reference's variance removed (measure.h); the raw one too. */
    double raw[2], unused;
    measure_error(&traced.image, &reference->image, &raw[0], &unused);
    measure_error(&photons.render.image, &reference->image, &raw[1], &unused);
    printf("\nequal time: processor time %.1f s (chapter 7) and %.1f s (photon map: passes %d, "
           "photons per pass %d, stored per pass %.0f); wall clock %.1f s and %.1f s\n",
           path_cpu, photons.cpu_seconds, photons.passes, ppm.photons, photons.stored,
           rows[0].seconds, rows[1].seconds);
    printf("RMSE against the reference: %.4f and %.4f, ratio %.3f; without the reference's "
           "own variance (its noise %.4f): %.4f and %.4f, ratio %.3f\n", raw[0], raw[1],
           raw[1] / raw[0], reference->noise, rows[0].rmse, rows[1].rmse,
           rows[1].rmse / rows[0].rmse);
    printf("efficiency (1 / (rel_mse x seconds)): %.3g and %.3g, ratio %.2f\n", rows[0].efficiency,
           rows[1].efficiency, rows[1].efficiency / rows[0].efficiency);
    Vec3 ref_mean = channel_means(&reference->image), mean = channel_means(&photons.render.image);
    const double ours[3] = {mean.x, mean.y, mean.z}, theirs[3] = {ref_mean.x, ref_mean.y, ref_mean.z};
    printf("image mean per channel, photon map / reference:");
    for (int c = 0; c < 3; c++) {
        if (theirs[c] > 0.0)
            printf(" %.4f", ours[c] / theirs[c]);
        else
            printf(" - (the reference's mean is %g)", theirs[c]);
    }
    printf("\n");

    const Image crop_sources[3] = {reference->image, traced.image, photons.render.image};
    char reference_caption[128];
    snprintf(reference_caption, sizeof reference_caption, "reference (path tracer, %.0f spp)",
             reference->spp);
    const char *crop_captions[3] = {reference_caption, "chapter 7: final estimator",
                                    "chapter 8: photon map, equal time"};
    int col, row, width = traced.image.width, height = traced.image.height;
    if (caustic_position(scene, width, height, &col, &row))
        write_crops(options, "ch08_caustic_crop", crop_sources, crop_captions, col, row);
    else
        printf("no glass sphere with a surface under it in view: no crop of its caustic\n");
    if (mirror_image_position(scene, path->mirrors, width, height, &col, &row))
        write_crops(options, "ch08_mirror_crop", crop_sources, crop_captions, col, row);
    else
        printf("no lamp seen in a planar mirror: no crop of its image\n");
    render_result_free(&traced);
    ppm_result_free(&photons);
}

/* One setting of the table: K images with different seeds, reduced to its errors. */
typedef struct {
    char estimator[24];
    int spp, photons, passes;  /* spp per pass for the photon map */
    double radius, alpha;      /* first radius; 0 for the path tracer */
    double seconds, cpu;       /* wall-clock and processor time, means over the seeds */
    double rmse, rmse_low, rmse_high;  /* mean, lowest and highest over the seeds */
    double error;              /* sqrt(bias^2 + variance): without the reference's noise */
    double bias2, variance;    /* per pixel and channel, means */
} Measurement;

/* Accumulates the K images of a setting; `lamp` marks the values left out of the
 * bias and variance (lamp_mask). */
typedef struct {
    double *sum, *sum_squares;
    const unsigned char *lamp;
    long values;
    int count;
    double rmse_sum, rmse_low, rmse_high, seconds, cpu;
} SeedImages;

static void seeds_begin(SeedImages *s, long values, const unsigned char *lamp)
{
    s->sum = calloc((size_t)values, sizeof *s->sum);
    s->sum_squares = calloc((size_t)values, sizeof *s->sum_squares);
    if (!s->sum || !s->sum_squares)
        cli_fail(1, "out of memory for the table");
    s->lamp = lamp;
    s->values = values;
    s->count = 0;
    s->rmse_sum = s->seconds = s->cpu = 0.0;
    s->rmse_low = INFINITY;
    s->rmse_high = 0.0;
}

static void seeds_add(SeedImages *s, const Image *image, double seconds, double cpu,
                      const Reference *reference)
{
    double rmse, rel_mse;
    measure_error(image, &reference->image, &rmse, &rel_mse);
    for (long i = 0; i < s->values; i++) {
        s->sum[i] += image->pixels[i];
        s->sum_squares[i] += (double)image->pixels[i] * image->pixels[i];
    }
    s->count++;
    s->rmse_sum += rmse;
    s->rmse_low = fmin(s->rmse_low, rmse);
    s->rmse_high = fmax(s->rmse_high, rmse);
    s->seconds += seconds;
    s->cpu += cpu;
}

/* Bias^2 and variance from the seeds (see the top of the file), and free them. */
static void seeds_finish(SeedImages *s, const Reference references[2], Measurement *m)
{
    double cross = 0.0, variance = 0.0;
    int k = s->count;
    long used = 0;
    for (long i = 0; i < s->values; i++) {
        if (s->lamp[i / 3])
            continue;
        double mean = s->sum[i] / k;
        cross += (mean - references[0].image.pixels[i]) * (mean - references[1].image.pixels[i]);
        variance += fmax(s->sum_squares[i] - k * mean * mean, 0.0) / (k - 1);
        used++;
    }
    m->variance = variance / used;
    m->bias2 = cross / used - m->variance / k;
    m->error = sqrt(fmax(m->bias2, 0.0) + m->variance);
    m->rmse = s->rmse_sum / k;
    m->rmse_low = s->rmse_low;
    m->rmse_high = s->rmse_high;
    m->seconds = s->seconds / k;
    m->cpu = s->cpu / k;
    free(s->sum);
    free(s->sum_squares);
}

/* The render settings of seed k of a setting (quiet: there are many). */
static RenderSettings seeded_settings(const Options *small, const Scene *scene, int k, int spp)
{
    Options seeded = *small;
    seeded.seed = small->seed + (uint64_t)k;
    seeded.quiet = 1;
    return experiment_render_settings(&seeded, scene, spp, PIXEL_STRATIFIED, "table");
}

static void measure_path(const Options *small, const Scene *scene, const PathSettings *path,
                         const Reference references[2], const unsigned char *lamp, int spp,
                         Measurement *m)
{
    *m = (Measurement){"chapter 7 final", spp, 0, 0, 0.0, 0.0, 0, 0, 0, 0, 0, 0, 0, 0};
    SeedImages seeds;
    seeds_begin(&seeds, 3L * references[0].image.width * references[0].image.height, lamp);
    for (int k = 0; k < SEEDS; k++) {
        RenderSettings settings = seeded_settings(small, scene, k, spp);
        RenderResult result;
        double cpu = stats_cpu_now();
        experiment_render(scene, &settings, path_final_radiance, path, &result);
        cpu = stats_cpu_now() - cpu;
        experiment_exit_if_interrupted(&result, NULL);
        seeds_add(&seeds, &result.image, result.seconds, cpu, &references[0]);
        render_result_free(&result);
    }
    seeds_finish(&seeds, references, m);
}

static void measure_photons(const Options *small, const Scene *scene, const Reference references[2],
                            const unsigned char *lamp, const PpmSettings *ppm, Measurement *m)
{
    *m = (Measurement){"", ppm->spp, ppm->photons, ppm->passes, ppm->radius, ppm->alpha,
                       0, 0, 0, 0, 0, 0, 0, 0};
    snprintf(m->estimator, sizeof m->estimator, "photon map a=%.2g", ppm->alpha);
    SeedImages seeds;
    seeds_begin(&seeds, 3L * references[0].image.width * references[0].image.height, lamp);
    for (int k = 0; k < SEEDS; k++) {
        RenderSettings settings = seeded_settings(small, scene, k, ppm->spp);
        settings.image.sampling = PIXEL_PROGRESSIVE;
        PpmResult result;
        render_ppm(small, NULL, scene, &settings, ppm, &result);
        seeds_add(&seeds, &result.render.image, result.render.seconds, result.cpu_seconds,
                  &references[0]);
        ppm_result_free(&result);
    }
    seeds_finish(&seeds, references, m);
}

static void print_measurements(const Measurement *rows, int count, FILE *out, int csv)
{
    if (csv)
        fprintf(out, "estimator,spp_per_pass,photons_per_pass,first_radius,alpha,passes,seconds,cpu_seconds,"
                     "rmse,rmse_lowest,rmse_highest,error,bias_squared,variance,bias_share,"
                     "variance_share\n");
    else
        fprintf(out, "%-18s %4s %8s %7s %5s %6s %8s %7s %8s %17s %8s %10s %10s %5s %5s\n", "estimator",
                "spp", "photons", "radius", "alpha", "passes", "seconds", "cpu", "rmse", "(lowest-highest)",
                "error", "bias^2", "variance", "bias", "var.");
    for (int i = 0; i < count; i++) {
        const Measurement *m = &rows[i];
        double total = fmax(m->bias2, 0.0) + m->variance;
        double bias_share = total > 0.0 ? fmax(m->bias2, 0.0) / total : 0.0;
        if (csv)
            fprintf(out, "%s,%d,%d,%.6g,%.6g,%d,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g\n",
                    m->estimator, m->spp, m->photons, m->radius, m->alpha, m->passes, m->seconds, m->cpu,
                    m->rmse, m->rmse_low, m->rmse_high, m->error, m->bias2, m->variance,
                    bias_share, 1.0 - bias_share);
        else
            fprintf(out, "%-18s %4d %8d %7.4f %5.2f %6d %8.3f %7.3f %8.5f (%7.5f-%7.5f) %8.5f %10.3e "
                    "%10.3e %4.0f%% %4.0f%%\n", m->estimator, m->spp, m->photons, m->radius, m->alpha,
                    m->passes, m->seconds, m->cpu, m->rmse, m->rmse_low, m->rmse_high, m->error, m->bias2,
                    m->variance, 100 * bias_share, 100 * (1.0 - bias_share));
    }
}

static void write_measurements(const Options *options, const Measurement *rows, int count)
{
    print_measurements(rows, count, stdout, 0);
    char path[4400];
    experiment_path(options, "ch08_error_table.csv", path, sizeof path);
    AtomicFile file;
    if (atomic_open(&file, path) != 0)
        cli_fail(1, "cannot write %s", path);
    print_measurements(rows, count, file.file, 1);
    if (atomic_close(&file, 0) != 0)
        cli_fail(1, "cannot write %s", path);
    printf("wrote %s\n", path);
}

/* The pixels that show the lamp or its images in the mirrors and the glass, and their
 * neighbours: bright in the image without caustics (the photon version with an empty
 * map), which nothing else is. Their noise is the same estimator in both here and, at a
 * quarter size, dominates the RMSE; the bias and variance are measured without them.
 * Returns the mask (1: left out), one byte per pixel. */
static unsigned char *lamp_mask(const Options *small, const Scene *scene, const PathSettings *path,
                                int *left_out)
{
    PhotonMap empty;
    if (photon_map_build(&empty, NULL, 0, 0, 1.0) != 0)
        cli_fail(1, "out of memory");
    CausticPathSettings without = {*path, &empty, &empty, 1.0};
    Options quiet = *small;
    quiet.quiet = 1;
    RenderSettings settings = experiment_render_settings(&quiet, scene, 16, PIXEL_STRATIFIED, "mask");
    RenderResult result;
    experiment_render(scene, &settings, path_caustics_radiance, &without, &result);
    experiment_exit_if_interrupted(&result, NULL);
    int w = settings.image.width, h = settings.image.height;
    unsigned char *lamp = calloc((size_t)w * h, 1);
    if (!lamp)
        cli_fail(1, "out of memory");
    *left_out = 0;
    for (int row = 0; row < h; row++)
        for (int col = 0; col < w; col++) {
            int bright = 0;
            for (int dy = -1; dy <= 1; dy++)
                for (int dx = -1; dx <= 1; dx++) {
                    int x = col + dx, y = row + dy;
                    if (x >= 0 && y >= 0 && x < w && y < h)
                        bright |= vec3_max_component(image_get(&result.image, x, y)) > 1.0;
                }
            lamp[row * w + col] = (unsigned char)bright;
            *left_out += bright;
        }
    render_result_free(&result);
    photon_map_free(&empty);
    return lamp;
}

/* The table and the plot, on a quarter-size image. */
static void error_against_time(const Options *options, const Scene *scene, const PathSettings *path)
{
    Options small = experiment_quarter_size(options);
    /* Two references of independent seeds: the product of an image's errors against the
     * two has the reference's noise taken out in expectation (see the top). */
    Reference references[2];
    reference_for(&small, scene, &references[0]);
    Options other = small;
    other.seed = small.seed + 1000; /* references use ~seed; the panels seed .. seed + SEEDS */
    printf("a second reference of the same image, of another seed (the table's errors use both):\n");
    reference_for(&other, scene, &references[1]);
    int width, height;
    experiment_image_size(&small, scene, &width, &height);
    int left_out;
    unsigned char *lamp = lamp_mask(&small, scene, path, &left_out);
    /* The series of the plot: chapter 7's estimator as its samples double, then the photon
     * map as its passes double: at the figure's settings; and with BLUR times the radius
     * (BLUR^2 times the photons in each estimate: far less variance, but a wide blur),
     * shrinking and fixed. */
    enum { SERIES = 4, EXTRA = 3, BLUR = 8 };
    const double series_radius[SERIES] = {0, 1, BLUR, BLUR}, series_alpha[SERIES] = {0, PPM_ALPHA, PPM_ALPHA, 1};
    Measurement rows[SERIES * STEPS + EXTRA];
    double x[SERIES][STEPS], y[SERIES][STEPS];
    for (int s = 0; s < SERIES; s++)
        for (int step = 0; step < STEPS; step++) {
            Measurement *row = &rows[s * STEPS + step];
            if (s == 0) {
                measure_path(&small, scene, path, references, lamp, TABLE_SPP_PER_PASS << step, row);
            } else {
                PpmSettings ppm = photon_settings(path, scene, width, height, TABLE_SPP_PER_PASS,
                                                  1 << step);
                ppm.radius *= series_radius[s];
                ppm.alpha = series_alpha[s];
                measure_photons(&small, scene, references, lamp, &ppm, row);
            }
            x[s][step] = row->cpu;
            y[s][step] = row->error;
        }
    /* At the most passes, the figure's settings with 4 times and a quarter of the
     * photons, and half the radius. */
    const double photon_factor[EXTRA] = {4.0, 0.25, 1.0}, radius_factor[EXTRA] = {1.0, 1.0, 0.5};
    for (int e = 0; e < EXTRA; e++) {
        PpmSettings ppm = photon_settings(path, scene, width, height, TABLE_SPP_PER_PASS,
                                          1 << (STEPS - 1));
        ppm.photons = (int)(ppm.photons * photon_factor[e] + 0.5);
        ppm.radius *= radius_factor[e];
        measure_photons(&small, scene, references, lamp, &ppm, &rows[SERIES * STEPS + e]);
    }
    printf("\nerror against time at %d x %d, %d seeds per setting. rmse: the whole image "
           "(mean, lowest and highest of the seeds); error: without the lamp and its images "
           "(%d pixels of %d) and without the reference's noise, split into bias and variance:\n",
           width, height, SEEDS, left_out, width * height);
    write_measurements(options, rows, SERIES * STEPS + EXTRA);

    const Vec3 colours[SERIES] = {{0.85, 0.1, 0.1}, {0.1, 0.2, 0.9}, {0.1, 0.6, 0.1}, {0.95, 0.55, 0.0}};
    char labels[SERIES][64];
    snprintf(labels[0], sizeof labels[0], "chapter 7 final, %d to %d spp", TABLE_SPP_PER_PASS,
             TABLE_SPP_PER_PASS << (STEPS - 1));
    snprintf(labels[1], sizeof labels[1], "photon map, 1 to %d passes of %d spp", 1 << (STEPS - 1),
             TABLE_SPP_PER_PASS);
    snprintf(labels[2], sizeof labels[2], "%d x the radius, shrinking", BLUR);
    snprintf(labels[3], sizeof labels[3], "%d x the radius, fixed", BLUR);
    PlotSeries series[SERIES];
    for (int s = 0; s < SERIES; s++)
        series[s] = (PlotSeries){.label = labels[s], .x = x[s], .y = y[s], .count = STEPS,
                                 .colour = colours[s], .markers = 1, .dashed = s == 3};
    Plot figure = {{"processor time (s)", PLOT_LOG, 0.0, 0.0, 0.0},
                   {"error (no lamp, no reference noise)", PLOT_LOG, 0.0, 0.0, 0.0},
                   series, SERIES, 0.0};
    Image plot = experiment_plot(&figure, 720, 480);
    char caption[512];
    snprintf(caption, sizeof caption,
             "error against processor time, log-log, each point the mean of %d seeds; the "
             "shrinking radius's blur (bias) fades, the fixed one's stays", SEEDS);
    const char *captions[] = {caption};
    experiment_write_figure(options, "ch08_error_plot", &plot, captions, 1, 1.0);
    image_free(&plot);
    free(lamp);
    measure_reference_free(&references[0]);
    measure_reference_free(&references[1]);
}

int main(int argc, char **argv)
{
    ProgramInfo info = {
        "Chapter 8, caustics from a photon map: chapter 7's final estimator against the same\n"
        "estimator with progressive photon-mapped caustics at equal time, and their error against\n"
        "time. Both use roulette with bounded weights unless --rr is given.",
        FLAGS_COMMON | FLAG_SPP | FLAG_SHADOW_RAYS | FLAG_RR | FLAG_DEPTH | FLAG_FRESNEL |
            FLAG_REFERENCE_SPP,
        {.scene = "scenes/room.scene", .size = 800, .spp = 64, .shadow_rays = 1, .rr = 0.75,
         .depth = 64, .seed = 1, .out = "build/figures", .reference_spp = REFERENCE_SPP},
    };
    Options options;
    Scene scene;
    experiment_start(argc, argv, &info, NEEDS_AREA_LIGHT, &options, &scene);
    MirrorPlanes mirrors;
    if (mirror_light_find_planes(&scene, &mirrors) != 0)
        cli_fail(1, "out of memory");
    PathSettings path = experiment_final_estimator(&options, &mirrors);
    Reference reference;
    reference_for(&options, &scene, &reference);
    equal_time_figure(&options, &scene, &path, &reference);
    measure_reference_free(&reference);
    error_against_time(&options, &scene, &path);
    mirror_planes_free(&mirrors);
    scene_free(&scene);
    return 0;
}
