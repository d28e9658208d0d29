/* experiment.c: the chores shared by the chapter programs (chapter 1). See experiment.h. */
#include "experiment.h"

#include <errno.h>
#include <stdlib.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

#include "figure.h"
#include "scene_file.h"

void experiment_load_scene(const Options *options, LightNeed need, Scene *scene)
{
    char error[512];
    if (scene_load(options->scene, scene, error, sizeof error) != 0)
        cli_fail(2, "%s", error);
    if (need == NEEDS_POINT_LIGHT && scene->point_light_count == 0)
        cli_fail(2, "%s:%d: no point_light: %s needs one", scene->source, scene->line_count,
                 cli_program);
    if (need == NEEDS_AREA_LIGHT && scene->light_count == 0)
        cli_fail(2, "%s:%d: no area light (a 'light' material on a triangle, quad, box or "
                    "tetrahedron): %s needs one", scene->source, scene->line_count, cli_program);
}

void experiment_image_size(const Options *options, const Scene *scene, int *width, int *height)
{
    double aspect = camera_aspect(&scene->camera);
    double exact_height = options->size / aspect;
    *width = options->size;
    *height = (int)lround(exact_height);
    if (*height < 1 || *height > 16384 || fabs(*height - exact_height) > 0.01 * *height)
        cli_fail(2, "%s:%d: --size %d gives no image whose aspect ratio matches the image "
                    "plane's (%.4g)", scene->source, scene->line_count, options->size, aspect);
}

RenderSettings experiment_render_settings(const Options *options, const Scene *scene, int spp,
                                          PixelSampling sampling, const char *label)
{
    RenderSettings settings;
    experiment_image_size(options, scene, &settings.width, &settings.height);
    settings.spp = spp;
    settings.sampling = sampling;
    settings.threads = options->threads;
    settings.seed = options->seed;
    settings.progress = !options->quiet;
    settings.label = label;
    return settings;
}

void experiment_render(const Scene *scene, const RenderSettings *settings, Estimator estimate,
                       const void *estimator_settings, RenderResult *result)
{
    render_install_interrupt();
    if (render(scene, settings, estimate, estimator_settings, result) != 0)
        cli_fail(1, "out of memory rendering %d x %d", settings->width, settings->height);
    if (result->nonfinite > 0)
        fprintf(stderr, "%s: %s: dropped %llu non-finite samples of %llu\n", cli_program,
                settings->label, (unsigned long long)result->nonfinite,
                (unsigned long long)result->samples);
}

/* mkdir -p */
static void make_directories(const char *path)
{
    char directory[4096];
    if (snprintf(directory, sizeof directory, "%s", path) >= (int)sizeof directory)
        cli_fail(2, "path too long: %s", path);
    for (char *p = directory + 1;; p++) {
        int end = *p == '\0';
        if (*p == '/' || end) {
            *p = '\0';
            if (mkdir(directory, 0777) != 0 && errno != EEXIST)
                cli_fail(1, "cannot create directory %s: %s", directory, strerror(errno));
            if (end)
                break;
            *p = '/';
        }
    }
}

void experiment_path(const Options *options, const char *file_name, char *path, size_t size)
{
    make_directories(options->out);
    if (snprintf(path, size, "%s/%s", options->out, file_name) >= (int)size)
        cli_fail(2, "--out: path too long");
}

void experiment_reference(const Options *options, const Scene *scene, Estimator estimate,
                          const void *estimator_settings, const char *description, int spp,
                          Reference *reference)
{
    RenderSettings settings =
        experiment_render_settings(options, scene, spp, PIXEL_RANDOM, "reference");
    settings.seed = ~options->seed; /* independent of every panel's samples */
    char key_text[512];
    int length = snprintf(key_text, sizeof key_text, "%s|%dx%d|spp %d|seed %llu", description,
                          settings.width, settings.height, spp,
                          (unsigned long long)settings.seed);
    uint64_t scene_hash = measure_hash_file(MEASURE_HASH_START, options->scene);
    if (scene_hash == 0)
        cli_fail(1, "cannot read %s again to name its reference: %s", options->scene,
                 strerror(errno));
    uint64_t key = measure_hash(scene_hash, key_text, (size_t)length);
    make_directories(REFERENCE_DIRECTORY);
    if (measure_load_reference(REFERENCE_DIRECTORY, key, reference) != 0) {
        RenderResult result;
        experiment_render(scene, &settings, estimate, estimator_settings, &result);
        if (result.interrupted)
            cli_fail(130, "interrupted while rendering the reference; nothing was cached");
        *reference = (Reference){result.image, result.std_error, measure_rms(&result.std_error),
                                 render_samples_per_pixel(&result), result.seconds, 0};
        image_free(&result.average_std_error);
        if (measure_save_reference(REFERENCE_DIRECTORY, key, reference) != 0)
            cli_fail(1, "cannot write the reference into %s: %s", REFERENCE_DIRECTORY,
                     strerror(errno));
    }
    printf("reference: %s, %.0f spp, %s %.1f s; its own standard error (RMS) %.5f\n",
           description, reference->spp, reference->cached ? "cached, rendered in" : "rendered in",
           reference->seconds, reference->noise);
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
    announce(figure_write_png(path, panels, captions, count, exposure), path);
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

TableRow experiment_row(const char *panel, const char *settings, const RenderResult *result)
{
    TableRow row = {0};
    snprintf(row.panel, sizeof row.panel, "%s", panel);
    snprintf(row.settings, sizeof row.settings, "%s", settings);
    row.spp = render_samples_per_pixel(result);
    row.seconds = result->seconds;
    row.threads = result->threads;
    row.rays = result->rays;
    row.rmse = row.rel_mse = row.efficiency = NAN;
    row.nonfinite = result->nonfinite;
    return row;
}

static TableRow measured_row(const char *name, const char *settings_text,
                             const RenderResult *result, const Reference *reference)
{
    TableRow row = experiment_row(name, settings_text, result);
    if (reference)
        measure_fill_row(&row, &result->image, reference);
    return row;
}

TableRow experiment_measure(const Scene *scene, const RenderSettings *settings,
                            Estimator estimate, const void *estimator_settings,
                            const char *name, const char *settings_text,
                            const Reference *reference, RenderResult *result)
{
    experiment_render(scene, settings, estimate, estimator_settings, result);
    experiment_exit_if_interrupted(result);
    return measured_row(name, settings_text, result, reference);
}

TableRow experiment_panel(const Options *options, const Scene *scene,
                          const RenderSettings *settings, Estimator estimate,
                          const void *estimator_settings, const char *name,
                          const char *settings_text, const Reference *reference,
                          RenderResult *result)
{
    experiment_render(scene, settings, estimate, estimator_settings, result);
    experiment_write_image(options, name, &result->image, PANEL_EXPOSURE);
    experiment_exit_if_interrupted(result);
    return measured_row(name, settings_text, result, reference);
}

void experiment_path_reference(const Options *options, const Scene *scene,
                               const PathSettings *path, Reference *reference)
{
    char description[96];
    path_describe(path, description, sizeof description);
    experiment_reference(options, scene, path_radiance, path, description,
                         options->reference_spp, reference);
}

TableRow experiment_path_row(const Options *options, const Scene *scene,
                             const PathSettings *path, int spp, PixelSampling sampling,
                             const char *name, const char *settings_text,
                             const Reference *reference, Image *image)
{
    RenderSettings settings = experiment_render_settings(options, scene, spp, sampling, name);
    RenderResult result;
    TableRow row = image ? experiment_panel(options, scene, &settings, path_radiance, path, name,
                                            settings_text, reference, &result)
                         : experiment_measure(scene, &settings, path_radiance, path, name,
                                              settings_text, reference, &result);
    image_free(&result.std_error);
    image_free(&result.average_std_error);
    if (image)
        *image = result.image;
    else
        image_free(&result.image);
    return row;
}

void experiment_caption(const TableRow *row, const char *title, char *caption, size_t size)
{
    if (isnan(row->rmse))
        snprintf(caption, size, "%s\n%s\n%.2f s", title, row->settings, row->seconds);
    else
        snprintf(caption, size, "%s\n%s\n%.2f s, RMSE %.4f", title, row->settings,
                 row->seconds, row->rmse);
}

void experiment_exit_if_interrupted(const RenderResult *result)
{
    if (!result->interrupted)
        return;
    fprintf(stderr, "%s: interrupted: saved the image after %.2f samples per pixel\n",
            cli_program, render_samples_per_pixel(result));
    exit(130);
}
