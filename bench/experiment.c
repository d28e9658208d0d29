/* experiment.c (bench, chapter 1): the chores shared by the chapter programs. See experiment.h.
 */
#include "experiment.h"

#include <errno.h>
#include <stdarg.h>
#include <stdlib.h>
#include <stdio.h>
#include <string.h>

#include "directory.h"
#include "figure.h"
#if CHAPTER >= 2
#include "reference_cache.h"
#endif
#include "scene_file.h"
#if CHAPTER >= 7
#include "sphere_guide.h"
#endif
#if CHAPTER >= 8
#include "path_final.h"
#endif

/* The bytes of the scene file as read by experiment_load_scene: the scene is read once
 * (a pipe or a FIFO can be read only once), and these bytes name its references and are
 * handed to the reference program. Program state, set once. */
static char *scene_text;
static size_t scene_length;

/* When the program started its work, for the total time it prints at its end. */
static double start_time;

static void print_total_time(void)
{
    printf("%s: total time %.1f s\n", cli_program, stats_now() - start_time);
}

static void load_font(Font *font)
{
    char error[4400];
    if (font_load(font, FONT_PATH, error, sizeof error) != 0)
        cli_fail(1, "%s", error);
}

/* --out must be a directory we can write a file into: found out now, not after the
 * render. */
static void check_output_directory(const Options *options)
{
    char failed[4096];
    if (directory_writable(options->out, failed, sizeof failed) != 0)
        cli_fail(errno == ENOTDIR || errno == ENAMETOOLONG ? 2 : 1,
                 "--out %s: cannot write in %s: %s", options->out, failed, strerror(errno));
}

/* The triangles that emit: the area lights (listed by the lesson from chapter 3 on). */
static int emitting_triangles(const Scene *scene)
{
    int count = 0;
    for (int i = 0; i < scene->triangle_count; i++)
        count +=
            vec3_max_component(scene->materials[scene->triangles[i].material].emission) > 0.0;
    return count;
}

/* The name of a light material of emission 0 0 0 that a shape is made of, or NULL. */
static const char *dark_light(const Scene *scene)
{
    for (int i = 0; i < scene->triangle_count; i++) {
        const Material *m = &scene->materials[scene->triangles[i].material];
        if (m->kind == MATERIAL_LIGHT && !(vec3_max_component(m->emission) > 0.0))
            return m->name;
    }
    return NULL;
}

void experiment_start(int argc, char **argv, const ProgramInfo *info, LightNeed need,
                      Options *options, Scene *scene)
{
    start_time = stats_now();
    cli_parse(argc, argv, info, options);
    render_install_interrupt(); /* from the start: temporary files are removed on a signal */
    check_output_directory(options);
    char error[4400];
    SceneFileInfo file;
    if (scene_file_read(options->scene, &scene_text, &scene_length, error, sizeof error) != 0 ||
        scene_parse(scene_text, scene_length, options->scene, scene, &file, error,
                    sizeof error) != 0)
        cli_fail(2, "%s", error);
    options->scene_hash = file.hash;
    options->scene_lines = file.line_count;
    if (need == NEEDS_POINT_LIGHT && scene->point_light_count == 0)
        cli_fail(2, "%s:%d: no point_light: %s needs one", options->scene, options->scene_lines,
                 cli_program);
    const char *dark = dark_light(scene);
    int area_lights = emitting_triangles(scene);
    if (need == NEEDS_AREA_LIGHT && area_lights == 0 && dark)
        cli_fail(2,
                 "%s:%d: no area light: material '%s' is a light of emission 0 0 0, which "
                 "emits nothing (%s needs a light with a channel above 0)",
                 options->scene, options->scene_lines, dark, cli_program);
    if (need == NEEDS_AREA_LIGHT && area_lights == 0)
        cli_fail(2,
                 "%s:%d: no area light (a 'light' material on a triangle, quad, box or "
                 "tetrahedron): %s needs one",
                 options->scene, options->scene_lines, cli_program);
    /* The width not given is fitted to the image plane; the one given is checked now,
     * before any file is written, as every width derived from it is fitted. */
    if (!cli_given(options, FLAG_SIZE))
        options->size = experiment_width_near(scene, options->size);
    int width, height;
    experiment_image_size(options, scene, &width, &height);
    /* The figures need the font: say so now rather than after the renders. */
    Font font;
    load_font(&font);
    font_free(&font);
    atexit(print_total_time); /* once the scene is read: from here on, the time is the work */
}

/* The height of a `width` pixels wide image of the plane's aspect ratio, rounded, or 0 when
 * the rounded image's aspect ratio would be more than 1% off the plane's. */
static int fitting_height(double aspect, int width)
{
    double exact = width / aspect;
    if (!(exact >= 0.5 && exact <= 16384.0))
        return 0;
    int height = (int)lround(exact);
    return fabs(height - exact) <= 0.01 * height ? height : 0;
}

void experiment_image_size(const Options *options, const Scene *scene, int *width, int *height)
{
    double aspect = scene_file_aspect(&scene->camera);
    *width = options->size;
    *height = fitting_height(aspect, options->size);
    if (*height == 0)
        cli_fail(2,
                 "%s:%d: --size %d gives no image whose aspect ratio matches the image "
                 "plane's (%.4g)",
                 options->scene, options->scene_lines, options->size, aspect);
}

int experiment_width_near(const Scene *scene, int wanted)
{
    double aspect = scene_file_aspect(&scene->camera);
    for (int d = 0; d < 16384; d++) {
        if (wanted - d >= 1 && wanted - d <= 16384 && fitting_height(aspect, wanted - d))
            return wanted - d;
        if (wanted + d >= 1 && wanted + d <= 16384 && fitting_height(aspect, wanted + d))
            return wanted + d;
    }
    cli_fail(
        2,
        "no image width from 1 to 16384 pixels matches the image plane's aspect ratio (%.4g)",
        aspect);
    return 0;
}

#if CHAPTER >= 2
RenderSettings experiment_render_settings(const Options *options, const Scene *scene, int spp,
                                          PixelSampling sampling, const char *label)
#else
RenderSettings experiment_render_settings(const Options *options, const Scene *scene, int spp,
                                          const char *label)
#endif
{
    RenderSettings settings = {0};
    experiment_image_size(options, scene, &settings.image.width, &settings.image.height);
    settings.image.spp = spp;
#if CHAPTER >= 2
    settings.image.sampling = sampling;
    settings.image.seed = options->seed;
#endif
    settings.threads = options->threads;
    settings.progress = !options->quiet;
    settings.label = label;
    return settings;
}

void experiment_render(const Scene *scene, const RenderSettings *settings, Estimator estimate,
                       const void *estimator_settings, RenderResult *result)
{
    render_install_interrupt();
    if (render_interrupted())
        cli_fail(130, "interrupted: stopped before rendering %s", settings->label);
    if (render(scene, settings, estimate, estimator_settings, result) != 0)
        cli_fail(1, "out of memory rendering %d x %d", settings->image.width,
                 settings->image.height);
    experiment_report_dropped(settings->label, result);
}

void experiment_report_dropped(const char *label, const RenderResult *result)
{
    if (result->nonfinite > 0)
        fprintf(stderr, "%s: %s: dropped %llu non-finite samples of %llu\n", cli_program, label,
                (unsigned long long)result->nonfinite, (unsigned long long)result->samples);
}

void experiment_render_serial(const Scene *scene, const RenderSettings *settings,
                              Estimator estimate, const void *estimator_settings,
                              RenderResult *result)
{
    if (render_serial(scene, settings, estimate, estimator_settings, result) != 0)
        cli_fail(1, "out of memory rendering %d x %d", settings->image.width,
                 settings->image.height);
}

Options experiment_quarter_size(const Options *options, const Scene *scene)
{
    Options quarter = *options;
    quarter.size = experiment_width_near(scene, cli_quarter(options->size, 16));
    quarter.reference_spp = (int)fmin(2.0 * options->reference_spp, 1 << 20);
    return quarter;
}

void experiment_path(const Options *options, const char *file_name, char *path, size_t size)
{
    char failed[4096];
    if (directory_make(options->out, failed, sizeof failed) != 0)
        cli_fail(1, "--out %s: cannot create directory %s: %s", options->out, failed,
                 strerror(errno));
    if (snprintf(path, size, "%s/%s", options->out, file_name) >= (int)size)
        cli_fail(2, "--out: path too long");
}

static void announce(int status, const char *path)
{
    if (status != 0)
        cli_fail(1, "cannot write %s: %s", path, strerror(errno));
    printf("wrote %s\n", path);
    fflush(stdout);
}

void experiment_write_image(const Options *options, const char *name, const Image *image,
                            double exposure)
{
    char file_name[256], path[4400];
    snprintf(file_name, sizeof file_name, "%s.png", name);
    experiment_path(options, file_name, path, sizeof path);
    announce(image_write_png(image, path, exposure), path);
    snprintf(file_name, sizeof file_name, "%s.pfm", name);
    experiment_path(options, file_name, path, sizeof path);
    announce(image_write_pfm(image, path), path);
}

void experiment_write_figure(const Options *options, const char *name, const Image *panels,
                             const char *const *captions, int count, double exposure)
{
    char file_name[256], path[4400];
    snprintf(file_name, sizeof file_name, "%s.png", name);
    experiment_path(options, file_name, path, sizeof path);
    Font font;
    load_font(&font);
    announce(figure_write_png(path, &font, panels, captions, count, exposure), path);
    font_free(&font);
}

#if CHAPTER >= 4
Image experiment_plot(const Plot *plot, int width, int height)
{
    Font font;
    load_font(&font);
    Image image = plot_draw(plot, &font, width, height, NULL);
    font_free(&font);
    if (!image.pixels)
        cli_fail(1, "out of memory for a %d x %d plot", width, height);
    return image;
}

void experiment_write_plot(const Options *options, const char *name, const Plot *plot,
                           int width, int height, const char *caption)
{
    Image image = experiment_plot(plot, width, height);
    experiment_write_figure(options, name, &image, &caption, 1, 1.0);
    image_free(&image);
}
#endif

void experiment_write_crops(const Options *options, const char *name, const Image *images,
                            const char *const *captions, int count, int left, int top, int side,
                            int scale)
{
    Image crops[8] = {{0, 0, NULL}};
    if (count > 8)
        cli_fail(1, "%d crops in one figure (at most 8)", count);
    for (int i = 0; i < count; i++) {
        crops[i] = image_crop(&images[i], left, top, side, scale);
        if (!crops[i].pixels)
            cli_fail(1, "out of memory for a crop");
    }
    experiment_write_figure(options, name, crops, captions, count, PANEL_EXPOSURE);
    for (int i = 0; i < count; i++)
        image_free(&crops[i]);
}

void experiment_write_table(const Options *options, const char *name, const TableRow *rows,
                            int count)
{
    char file_name[256], path[4400];
    table_print(stdout, rows, count);
    snprintf(file_name, sizeof file_name, "%s.csv", name);
    experiment_path(options, file_name, path, sizeof path);
    announce(table_write_csv(path, rows, count), path);
}

void experiment_write_numbers(const Options *options, const char *name, const char *header,
                              const double *values, int rows, int columns, const int *decimals)
{
    char file_name[256], path[4400];
    snprintf(file_name, sizeof file_name, "%s.csv", name);
    experiment_path(options, file_name, path, sizeof path);
    announce(table_write_numbers_csv(path, header, values, rows, columns, decimals), path);
}

TableRow experiment_row(const char *panel, const char *settings, const RenderResult *result)
{
    TableRow row = {0};
    snprintf(row.panel, sizeof row.panel, "%s", panel);
    snprintf(row.settings, sizeof row.settings, "%s", settings);
    row.spp = render_samples_per_pixel(result);
    row.seconds = result->seconds;
    row.threads = result->threads;
    row.rays = result->rays;
    row.rmse = row.rel_mse = row.efficiency = row.rmse_spread = row.rel_mse_spread = NAN;
    row.reference_share = NAN;
    row.nonfinite = result->nonfinite;
    row.runs = 1;
    return row;
}

void experiment_write_panel(const Options *options, const char *name,
                            const RenderResult *result)
{
    int written = !result->interrupted || render_samples_per_pixel(result) >= 1.0;
    if (written)
        experiment_write_image(options, name, &result->image, PANEL_EXPOSURE);
    experiment_exit_if_interrupted(result, written ? name : NULL);
}

void experiment_exit_if_interrupted(const RenderResult *result, const char *saved)
{
    if (!result->interrupted)
        return;
    if (saved)
        fprintf(stderr, "%s: interrupted: saved %s after %.2f samples per pixel\n", cli_program,
                saved, render_samples_per_pixel(result));
    else
        fprintf(stderr, "%s: interrupted after %.2f samples per pixel; nothing saved of it\n",
                cli_program, render_samples_per_pixel(result));
    exit(130);
}

#if CHAPTER >= 2
void experiment_path_reference(const Options *options, const Scene *scene,
                               const PathSettings *path, const char *rough_material,
                               double rough_sigma, Reference *reference)
{
    int width, height;
    experiment_image_size(options, scene, &width, &height);
#if CHAPTER >= 4
    int exact = path->fresnel == FRESNEL_EXACT;
#else
    int exact = 0;
#endif
    char size[32], spp[32], depth[32], seed[32], sigma[128];
    snprintf(size, sizeof size, "%d", options->size);
    snprintf(spp, sizeof spp, "%d", options->reference_spp);
    snprintf(depth, sizeof depth, "%d", path->max_depth);
    snprintf(seed, sizeof seed, "%llu", (unsigned long long)~options->seed);
    snprintf(sigma, sizeof sigma, "%s=%.17g", rough_material ? rough_material : "",
             rough_sigma);
    /* The key: the scene's bytes and the settings (the cache adds the program's). */
    ReferenceIdentity identity = {0, options->scene_hash, ""};
    measure_reference_settings(&identity, options->size, options->reference_spp,
                               path->max_depth, exact ? "exact" : "schlick", ~options->seed,
                               sigma);
    identity.key =
        measure_hash(options->scene_hash, identity.settings, strlen(identity.settings));
    char *arguments[] = {
        "--scene", "/dev/stdin", "--name",          (char *)options->scene,
        "--size",  size,         "--reference-spp", spp,
        "--depth", depth,        "--fresnel",       exact ? "exact" : "schlick",
        "--seed",  seed,         "--sigma",         sigma,
        "--quiet"};
    int count = sizeof arguments / sizeof *arguments - (options->quiet ? 0 : 1);
    reference_cache_get(arguments, count, scene_text, scene_length, &identity, width, height,
                        reference);
    char description[160];
    snprintf(description, sizeof description, "depth=%d %s%s%s", path->max_depth,
             exact ? "exact" : "schlick", rough_material ? ", sigma=" : "",
             rough_material ? sigma + strlen(rough_material) + 1 : "");
    printf("reference: %s, %.0f spp, %s %.1f s; its own standard error (RMS) %.5f\n",
           description, reference->spp,
           reference->cached ? "cached, rendered in" : "rendered in", reference->seconds,
           reference->noise);
}

/* One run: render, write the panel if asked (and every pixel has a sample), exit if
 * interrupted, and measure. */
static TableRow one_run(const Options *options, const Scene *scene,
                        const RenderSettings *settings, Estimator estimate,
                        const void *estimator_settings, const char *name,
                        const char *settings_text, const Reference *reference, int write_panel,
                        RenderResult *result)
{
    experiment_render(scene, settings, estimate, estimator_settings, result);
    if (write_panel)
        experiment_write_panel(options, name, result);
    experiment_exit_if_interrupted(result, NULL);
    TableRow row = experiment_row(name, settings_text, result);
    if (reference)
        measure_fill_row(&row, &result->image, reference);
    return row;
}

TableRow experiment_runs(const Options *options, const Scene *scene,
                         const RenderSettings *settings, Estimator estimate,
                         const void *estimator_settings, const char *name,
                         const char *settings_text, const Reference *reference, int write_panel,
                         RenderResult *first)
{
    int runs = reference && options->runs > 1 ? options->runs : 1;
    TableRow rows[CLI_RUNS_MAX];
    rows[0] = one_run(options, scene, settings, estimate, estimator_settings, name,
                      settings_text, reference, write_panel, first);
    for (int k = 1; k < runs; k++) {
        RenderSettings again = *settings;
        again.image.seed = settings->image.seed + (uint64_t)k;
        char label[160];
        snprintf(label, sizeof label, "%s, run %d of %d", settings->label, k + 1, runs);
        again.label = label;
        RenderResult result;
        rows[k] = one_run(options, scene, &again, estimate, estimator_settings, name,
                          settings_text, reference, 0, &result);
        render_result_free(&result);
    }
    TableRow combined;
    if (measure_combine_runs(rows, runs, &combined) != 0)
        cli_fail(1, "out of memory");
    return combined;
}

#if CHAPTER >= 6
/* The largest reflectance (any channel) of the scene's diffuse materials. */
static double largest_diffuse_reflectance(const Scene *scene)
{
    double largest = 0.0;
    for (int i = 0; i < scene->material_count; i++)
        if (material_is_diffuse(&scene->materials[i]))
            largest = fmax(largest, vec3_max_component(scene->materials[i].reflectance));
    return largest;
}

int experiment_infinite_variance(const Scene *scene, const PathSettings *path)
{
    return measure_roulette_variance_infinite(path->rr_survival > 0.0 ? path->rr_survival : 1.0,
                                              largest_diffuse_reflectance(scene));
}
#endif

TableRow experiment_path_row(const Options *options, const Scene *scene, Estimator estimate,
                             const PathSettings *path, int spp, PixelSampling sampling,
                             const char *name, const char *settings_text,
                             const Reference *reference, Image *image)
{
    RenderSettings settings = experiment_render_settings(options, scene, spp, sampling, name);
    RenderResult result;
    TableRow row = experiment_runs(options, scene, &settings, estimate, path, name,
                                   settings_text, reference, image != NULL, &result);
#if CHAPTER >= 6
    row.infinite_variance = experiment_infinite_variance(scene, path);
#endif
    image_free(&result.std_error);
    image_free(&result.average_std_error);
    if (image)
        *image = result.image;
    else
        image_free(&result.image);
    return row;
}

#if CHAPTER >= 7
PathSettings experiment_final_estimator(const Options *options, const MirrorPlanes *mirrors)
{
    PathSettings path = {.max_depth = options->depth,
                         .shadow_rays = options->shadow_rays,
                         .fresnel = options->fresnel,
                         .mirror_light = options->depth,
                         .mirrors = mirrors,
                         .sphere_guide = SPHERE_GUIDE_STRENGTH};
    if (cli_given(options, FLAG_RR))
        path.rr_survival = options->rr;
    else
        path.rr_throughput = 1;
    return path;
}

int experiment_to_target(const Options *options)
{
    return options->target_error > 0.0 || options->time_limit > 0.0;
}

TargetSettings experiment_target_settings(const Options *options, int first_spp, int grow)
{
    return (TargetSettings){options->target_error, options->time_limit, first_spp, grow, 0};
}

void experiment_render_to_target(const Options *options, const Scene *scene,
                                 const RenderSettings *settings, Estimator estimate,
                                 const void *estimator_settings, const char *name,
                                 const char *settings_text, const Reference *reference)
{
    TargetSettings target = experiment_target_settings(options, TARGET_FIRST_SPP, 1);
    TargetResult result;
    render_install_interrupt();
    if (render_to_target(scene, settings, estimate, estimator_settings, &target, &result) != 0)
        cli_fail(1, "out of memory rendering %d x %d", settings->image.width,
                 settings->image.height);
    if (result.render.nonfinite > 0)
        fprintf(stderr, "%s: %s: dropped %llu non-finite samples of %llu\n", cli_program,
                settings->label, (unsigned long long)result.render.nonfinite,
                (unsigned long long)result.render.samples);
    if (!result.render.interrupted || result.passes >= 2)
        experiment_write_image(options, name, &result.render.image, PANEL_EXPOSURE);
    experiment_exit_if_interrupted(&result.render, result.passes >= 2 ? name : NULL);
    experiment_report_target(options, name, settings_text, &target, &result.estimate,
                             result.stop, result.passes, &result.render, reference);
    render_result_free(&result.render);
}

void experiment_report_target(const Options *options, const char *name,
                              const char *settings_text, const TargetSettings *target,
                              const RelativeError *estimate, TargetStop stop, int passes,
                              const RenderResult *render, const Reference *reference)
{
    RelativeError against = {NAN, NAN};
    if (reference)
        against = error_against_reference(&render->image, reference);
    char line[512];
    target_describe(target, estimate, reference ? &against : NULL, stop, render->seconds,
                    render_samples_per_pixel(render), (double)ray_counts_total(render->rays),
                    passes, line, sizeof line);
    printf("%s\n", line);
    TableRow row = experiment_row(name, settings_text, render);
    if (reference)
        measure_fill_row(&row, &render->image, reference);
    char table[256];
    snprintf(table, sizeof table, "%s_target", name);
    experiment_write_table(options, table, &row, 1);
}
#endif

#if CHAPTER >= 8
PpmSettings experiment_photon_settings(const PathSettings *path, const Scene *scene, int width,
                                       int height, int spp, int passes)
{
    /* No more photons per pass than a grid takes: a pass then never stores too many. */
    double photons =
        fmin(EXPERIMENT_PHOTONS_PER_PIXEL * width * height + 0.5, POINT_GRID_MAX_POINTS);
    PpmSettings ppm = {*path,
                       (int)photons,
                       ppm_first_radius(scene, PPM_FIRST_RADIUS_AT_800) * 800.0 / width,
                       PPM_ALPHA,
                       spp,
                       passes,
                       0.0,
                       0.0,
                       0.0};
    ppm.path.mirror_light = 1;
    return ppm;
}

void experiment_render_ppm(const Options *options, const char *name, const Scene *scene,
                           const RenderSettings *settings, const PpmSettings *ppm,
                           PpmResult *result)
{
    render_install_interrupt();
    if (ppm_render(scene, settings, ppm, result) != 0)
        cli_fail(1, "out of memory rendering %d x %d with photons", settings->image.width,
                 settings->image.height);
    if (name && result->render.interrupted)
        experiment_write_panel(options, name, &result->render);
    experiment_exit_if_interrupted(&result->render, NULL);
}

BiasVariance experiment_seeds(const Options *options, const Scene *scene,
                              const PathSettings *path, const PpmSettings *ppm, int spp,
                              int seeds, const Reference references[2],
                              const unsigned char *left_out)
{
    const Image *reference = &references[0].image;
    SeedImages images;
    if (seed_images_begin(&images, reference->width, reference->height, left_out) != 0)
        cli_fail(1, "out of memory for the table");
    for (int k = 0; k < seeds; k++) {
        Options seeded = *options;
        seeded.seed = options->seed + (uint64_t)k;
        seeded.quiet = 1;
        RenderSettings settings = experiment_render_settings(
            &seeded, scene, spp, ppm ? PIXEL_PROGRESSIVE : PIXEL_STRATIFIED, "table");
        if (ppm) {
            PpmResult result;
            experiment_render_ppm(options, NULL, scene, &settings, ppm, &result);
            seed_images_add(&images, &result.render.image, result.render.seconds,
                            result.cpu_seconds, reference);
            ppm_result_free(&result);
        } else {
            RenderResult result;
            double cpu = stats_cpu_now();
            experiment_render(scene, &settings, path_final_radiance, path, &result);
            cpu = stats_cpu_now() - cpu;
            experiment_exit_if_interrupted(&result, NULL);
            seed_images_add(&images, &result.image, result.seconds, cpu, reference);
            render_result_free(&result);
        }
    }
    BiasVariance error;
    seed_images_finish(&images, reference, &references[1].image, &error);
    return error;
}

void experiment_write_error_table(const Options *options, const char *name,
                                  const SettingError *rows, int count)
{
    char file_name[256], path[4400];
    bias_variance_print(stdout, rows, count);
    snprintf(file_name, sizeof file_name, "%s.csv", name);
    experiment_path(options, file_name, path, sizeof path);
    announce(bias_variance_write_csv(path, rows, count), path);
}

void describe_ppm(const PpmSettings *ppm, const PpmResult *result, char *text, size_t size)
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
#endif

void experiment_caption(const TableRow *row, const char *title, char *caption, size_t size)
{
    if (isnan(row->rmse))
        snprintf(caption, size, "%s\n%s\n%.2f s", title, row->settings, row->seconds);
    else
        snprintf(caption, size, "%s\n%s\n%.2f s, RMSE %.4f", title, row->settings, row->seconds,
                 row->rmse);
}

void experiment_write_panels(const Options *options, const char *name, const Image *images,
                             const TableRow *rows, const char *const *titles, int count)
{
    char captions[8][512];
    const char *list[8];
    if (count > 8)
        cli_fail(1, "%d panels in one figure (at most 8)", count);
    for (int i = 0; i < count; i++) {
        experiment_caption(&rows[i], titles[i], captions[i], sizeof captions[i]);
        list[i] = captions[i];
    }
    experiment_write_figure(options, name, images, list, count, PANEL_EXPOSURE);
}
#endif /* CHAPTER >= 2 */

#if CHAPTER >= 2
/* Append printf-style text at text[*used], never past text[size - 1]. */
static void append(char *text, int size, int *used, const char *format, ...)
{
    if (*used >= size - 1)
        return;
    va_list args;
    va_start(args, format);
    int n = vsnprintf(text + *used, (size_t)(size - *used), format, args);
    va_end(args);
    *used = n < 0 ? size : *used + n;
}

void describe_path(const PathSettings *s, char *text, int size)
{
    int used = 0;
    text[0] = '\0';
    append(text, size, &used, "depth=%d", s->max_depth);
#if CHAPTER >= 3
    append(text, size, &used, " M=%d", s->shadow_rays);
#endif
#if CHAPTER >= 4
    append(text, size, &used, " %s", s->fresnel == FRESNEL_EXACT ? "exact" : "schlick");
#endif
#if CHAPTER >= 6
    if (s->rr_throughput > 0)
        append(text, size, &used, " rr=throughput@%d", s->rr_throughput);
    else
        append(text, size, &used, " rr=%g", s->rr_survival > 0.0 ? s->rr_survival : 1.0);
#endif
#if CHAPTER >= 7
    if (s->mis)
        append(text, size, &used, " mis");
    if (s->mirror_light > 0)
        append(text, size, &used, " mirror-light@%d", s->mirror_light);
    if (s->sphere_guide > 0.0)
        append(text, size, &used, " sphere-guide=%g", s->sphere_guide);
#endif
}
#endif
