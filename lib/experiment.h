/* experiment.h: what every chapter program does around its renders.
 *
 * Introduced in chapter 1. A chapter file is the experiment: which scene, which settings
 * per panel, what is measured, how the figure is laid out. The chores they all share
 * live here: loading the scene (errors as "PROGRAM: FILE:LINE: what is wrong", exit 2),
 * choosing the image size, rendering with a progress line, writing each panel as PNG
 * and PFM, the figure and the table (each file announced as "wrote PATH"), and an
 * interrupted render (SIGINT) saved as far as it got.
 */
#ifndef EXPERIMENT_H
#define EXPERIMENT_H

#include "cli.h"
#include "measure.h"
#include "path.h"
#include "plot.h"
#include "render.h"
#include "table.h"

typedef enum { NEEDS_POINT_LIGHT, NEEDS_AREA_LIGHT } LightNeed;

/* Load options->scene, or exit with status 2 and the reader's message. Also an error:
 * a scene without the kind of light the chapter needs. Without the figures' font,
 * exit with status 1 (before any rendering) as experiment_write_figure does. */
void experiment_load_scene(const Options *options, LightNeed need, Scene *scene);

/* Width from --size, height from the image plane's aspect ratio, rounded (exit 2 if
 * the rounded image's aspect ratio is more than 1% off the plane's). */
void experiment_image_size(const Options *options, const Scene *scene, int *width, int *height);

/* Render settings from the options: size, threads, seed, progress. */
RenderSettings experiment_render_settings(const Options *options, const Scene *scene, int spp,
                                          PixelSampling sampling, const char *label);

/* Render, or exit with status 1 when memory runs out. Announces dropped non-finite
 * samples. */
void experiment_render(const Scene *scene, const RenderSettings *settings, Estimator estimate,
                       const void *estimator_settings, RenderResult *result);

/* The path of `file_name` in the output directory, which is created if needed. */
void experiment_path(const Options *options, const char *file_name, char *path, size_t size);

/* Exposure of every panel's PNG: radiance 1 is white. */
#define PANEL_EXPOSURE 1.0

/* Where references are cached (measure.h). */
#define REFERENCE_DIRECTORY "build/references"

/* The reference for this scene and estimator at `spp` samples per pixel of random
 * positions, with a seed independent of the panels': read from the cache, or rendered
 * now and cached. `description` must name every setting that changes its expectation.
 * Prints a line with its noise. */
void experiment_reference(const Options *options, const Scene *scene, Estimator estimate,
                          const void *estimator_settings, const char *description, int spp,
                          Reference *reference);

/* experiment_reference for the path tracer with these settings (they describe it). */
void experiment_path_reference(const Options *options, const Scene *scene,
                               const PathSettings *path, Reference *reference);

/* The path tracer at `spp` samples per pixel as one table row. With `image`, a panel:
 * written as NAME.png/.pfm and kept in *image; without, only measured. */
TableRow experiment_path_row(const Options *options, const Scene *scene,
                             const PathSettings *path, int spp, PixelSampling sampling,
                             const char *name, const char *settings_text,
                             const Reference *reference, Image *image);

/* Write NAME.png and NAME.pfm in the output directory (exit 1 on failure). */
void experiment_write_image(const Options *options, const char *name, const Image *image,
                            double exposure);

/* Write the side-by-side figure NAME.png. Without the figures' font (FONT_PATH), exit
 * with status 1 and a message naming the Debian package that ships it. */
void experiment_write_figure(const Options *options, const char *name, const Image *panels,
                             const char *const *captions, int count, double exposure);

/* The plot drawn on a width x height image (exit 1 without the font or memory); show
 * it with experiment_write_figure. */
Image experiment_plot(const Plot *plot, int width, int height);

/* Print the table and write it as NAME.csv. */
void experiment_write_table(const Options *options, const char *name, const TableRow *rows,
                            int count);

/* A table row with the cost columns of a render filled in and no error measured. */
TableRow experiment_row(const char *panel, const char *settings, const RenderResult *result);

/* One measurement: render, and return its table row (labelled `name`) with the error
 * columns filled when a reference is given (else NULL). The rendered image stays in
 * *result. An interrupted render exits the program (experiment_exit_if_interrupted). */
TableRow experiment_measure(const Scene *scene, const RenderSettings *settings,
                            Estimator estimate, const void *estimator_settings,
                            const char *name, const char *settings_text,
                            const Reference *reference, RenderResult *result);

/* One panel of a figure: experiment_measure, and the image written as NAME.png/.pfm
 * (also when interrupted, before the program exits). */
TableRow experiment_panel(const Options *options, const Scene *scene,
                          const RenderSettings *settings, Estimator estimate,
                          const void *estimator_settings, const char *name,
                          const char *settings_text, const Reference *reference,
                          RenderResult *result);

/* A figure caption from a table row: its settings, then time and error. */
void experiment_caption(const TableRow *row, const char *title, char *caption, size_t size);

/* After an interrupted render has been saved: say so and exit with status 130. */
void experiment_exit_if_interrupted(const RenderResult *result);

#endif
