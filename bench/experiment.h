/* experiment.h (bench, chapter 1): what every chapter program does around its renders.
 *
 * A chapter program is the experiment: which scene, which settings per panel, what is
 * measured, how the figure is laid out. The chores they share live here, and unlike
 * lib/ they may end the program: "PROGRAM: what is wrong" on stderr and exit status 2
 * for bad input, 1 for a failure of the machine (memory, disk), 130 after an
 * interruption. From chapter 2 on, panels are measured against references rendered by
 * build/reference (bench/reference.c) from the final chapter's library and cached in
 * build/references/ (reference_cache.h).
 */
#ifndef EXPERIMENT_H
#define EXPERIMENT_H

#include "cli.h"
#include "renderer.h"
#include "table.h"
#if CHAPTER >= 2
#include "measure.h"
#include "path.h"
#endif
#if CHAPTER >= 4
#include "plot.h"
#endif
#if CHAPTER >= 7
#include "error_estimate.h"
#endif
#if CHAPTER >= 8
#include "bias_variance.h"
#include "ppm.h"
#endif

typedef enum {
    NEEDS_POINT_LIGHT,
    NEEDS_AREA_LIGHT
} LightNeed;

/* Every chapter program's first lines: parse the command line (cli_parse), check that
 * --out can be written (before any time is spent rendering), then read options->scene
 * once (scene_file_read: a pipe or FIFO works) and parse it, or exit
 * with status 2 and the reader's message. Also an error: a scene without the kind of
 * light the chapter needs, or with a material this chapter does not have yet, or a
 * --size whose image does not match the plane (experiment_image_size); a size not given
 * (the default, or --quick's quarter of it) is experiment_width_near of it. Without
 * the figures' font, exit with status 1 (before any rendering), as
 * experiment_write_figure would. At its exit the program then prints its total time. */
void experiment_start(int argc, char **argv, const ProgramInfo *info, LightNeed need,
                      Options *options, Scene *scene);

/* Width from --size, height from the image plane's aspect ratio, rounded (exit 2 if
 * the rounded image's aspect ratio is more than 1% off the plane's). */
void experiment_image_size(const Options *options, const Scene *scene, int *width, int *height);

/* The width nearest `wanted` (the smaller of two as near) whose image is no more than 1%
 * off the image plane's aspect ratio, as experiment_image_size requires: every width a
 * program derives from --size (its quarter-size sweeps, its panels) is chosen by this, so
 * that a --size valid for the image is valid for all of them. */
int experiment_width_near(const Scene *scene, int wanted);

/* Render settings from the options: size, threads, seed, progress. */
#if CHAPTER >= 2
RenderSettings experiment_render_settings(const Options *options, const Scene *scene, int spp,
                                          PixelSampling sampling, const char *label);
#else
RenderSettings experiment_render_settings(const Options *options, const Scene *scene, int spp,
                                          const char *label);
#endif

/* Render, or exit with status 1 when memory runs out. Announces dropped non-finite
 * samples. */
void experiment_render(const Scene *scene, const RenderSettings *settings, Estimator estimate,
                       const void *estimator_settings, RenderResult *result);

/* On stderr, if any: "dropped N non-finite samples of M", naming the render by label. */
void experiment_report_dropped(const char *label, const RenderResult *result);

/* The same with the lesson's own loop (render_serial, renderer.h), on one thread. */
void experiment_render_serial(const Scene *scene, const RenderSettings *settings,
                              Estimator estimate, const void *estimator_settings,
                              RenderResult *result);

/* The path of `file_name` in the output directory, which is created if needed. */
void experiment_path(const Options *options, const char *file_name, char *path, size_t size);

/* The options for a chapter's sweep on a quarter-size image: a quarter of --size (at
 * least 16 pixels, at most --size; experiment_width_near of that), and a reference with twice
 * the samples per pixel (at most 2^20), for an eighth of the cost of the full-size reference.
 * The sweeps' panels have few samples, so its noise stays a small share of their error (at most
 * 4% in `make figures`, chapter 5's sweep). */
Options experiment_quarter_size(const Options *options, const Scene *scene);

/* Exposure of every panel's PNG: radiance 1 is white. */
#define PANEL_EXPOSURE 1.0

/* Write NAME.png and NAME.pfm in the output directory (exit 1 on failure). */
void experiment_write_image(const Options *options, const char *name, const Image *image,
                            double exposure);

/* Write the side-by-side figure NAME.png. Without the figures' font (FONT_PATH), exit
 * with status 1 and a message naming the Debian package that ships it. */
void experiment_write_figure(const Options *options, const char *name, const Image *panels,
                             const char *const *captions, int count, double exposure);

/* The figure NAME of the `count` images cropped alike: the square of side `side` whose
 * top-left pixel is (left, top), moved inside each image if it pokes out, enlarged
 * `scale` times (image_crop). */
void experiment_write_crops(const Options *options, const char *name, const Image *images,
                            const char *const *captions, int count, int left, int top, int side,
                            int scale);

/* Print the table and write it as NAME.csv. */
void experiment_write_table(const Options *options, const char *name, const TableRow *rows,
                            int count);

/* Write a table of numbers as NAME.csv (table_write_numbers_csv). */
void experiment_write_numbers(const Options *options, const char *name, const char *header,
                              const double *values, int rows, int columns, const int *decimals);

/* A table row with the cost columns of a render filled in and no error measured. */
TableRow experiment_row(const char *panel, const char *settings, const RenderResult *result);

/* Write a render's panel as NAME.png and NAME.pfm, unless an interruption stopped it
 * before every pixel had a sample (the rows not reached would be black); then, if it was
 * interrupted, say what was saved and exit with status 130. */
void experiment_write_panel(const Options *options, const char *name,
                            const RenderResult *result);

/* After a render was interrupted (SIGINT): say what was saved and exit with status 130.
 * `saved` names what was written of it, or is NULL when nothing was. */
void experiment_exit_if_interrupted(const RenderResult *result, const char *saved);

#if CHAPTER >= 4
/* The plot drawn on a width x height image (exit 1 without the font or memory), to show
 * as a panel of a figure (experiment_write_figure). */
Image experiment_plot(const Plot *plot, int width, int height);

/* The plot drawn on a width x height image, written as the figure NAME.png with its
 * caption (exit 1 without the font or memory). */
void experiment_write_plot(const Options *options, const char *name, const Plot *plot,
                           int width, int height, const char *caption);
#endif

#if CHAPTER >= 2
/* Samples per pixel of the full-size references (their default --reference-spp):
 * REFERENCE_SPP for chapters 4-8 (chapter 5 takes twice as many), DEPTH8_REFERENCE_SPP
 * for the depth-8 image of chapters 2 and 3, whose panels are much noisier than it.
 * docs/chapter2.md gives the references' noise and time measured at each setting. */
#define REFERENCE_SPP 128
#define DEPTH8_REFERENCE_SPP 64

/* The reference for the image that the path tracer with settings `path` estimates (its
 * depth and, from chapter 4, its Fresnel mode; shadow rays and roulette do not change the
 * expectation), of the scene as loaded, with the roughness of the material named
 * `rough_material` (or none, NULL) set to `rough_sigma` (chapter 5's sweep), at the
 * options' size and --reference-spp samples per pixel (rounded up to whole batches of
 * sub-pixels, bench/reference.c), with a seed independent of the panels'. Read from the
 * cache, or rendered by the reference program first. Prints a line with its noise. */
void experiment_path_reference(const Options *options, const Scene *scene,
                               const PathSettings *path, const char *rough_material,
                               double rough_sigma, Reference *reference);

/* The path tracer at `spp` samples per pixel as one table row (experiment_runs), marked
 * when its variance is infinite. With `image`, a panel: the first run written as
 * NAME.png/.pfm and kept in *image; without, only measured. */
TableRow experiment_path_row(const Options *options, const Scene *scene, Estimator estimate,
                             const PathSettings *path, int spp, PixelSampling sampling,
                             const char *name, const char *settings_text,
                             const Reference *reference, Image *image);

/* One setting measured over options->runs independent runs (seeds options->seed + k;
 * one run without a reference), combined into one table row (measure_combine_runs):
 * the mean error over the runs and its spread. The first run's render stays in *first;
 * with `write_panel`, its image is written as NAME.png/.pfm. An interruption saves
 * the first run's panel if it was being rendered and has a sample in every pixel, and
 * exits (experiment_exit_if_interrupted). */
TableRow experiment_runs(const Options *options, const Scene *scene,
                         const RenderSettings *settings, Estimator estimate,
                         const void *estimator_settings, const char *name,
                         const char *settings_text, const Reference *reference, int write_panel,
                         RenderResult *first);

#if CHAPTER >= 6
/* Whether the path tracer with these settings has infinite variance in this scene:
 * roulette with alpha <= rho^2 of its brightest diffuse surface. */
int experiment_infinite_variance(const Scene *scene, const PathSettings *path);
#endif

#if CHAPTER >= 7
/* Chapter 7's final estimator (Figure 7): M = --shadow-rays, bounded-weight roulette
 * (or --rr's constant alpha if given), the mirrors' images of the lamps at every diffuse
 * hit, bounces aimed at the spheres; no mis, which in the room changes nothing
 * measurable (chapter 7's levers table) for about 2% more work. */
PathSettings experiment_final_estimator(const Options *options, const MirrorPlanes *mirrors);

/* Samples per pixel of each of the first two passes of a render to --target-error or
 * --time (error_estimate.h); each later pair adds an eighth of the samples so far. */
#define TARGET_FIRST_SPP 4

/* Whether --target-error or --time was given: then the program renders its main image
 * to them and skips the rest of its figure (docs/running.md). */
int experiment_to_target(const Options *options);

/* The options' target: --target-error, --time, first passes of `first_spp`, growing
 * (grow) or all alike. */
TargetSettings experiment_target_settings(const Options *options, int first_spp, int grow);

/* Render the main image NAME to the options' target (render_to_target), write it as
 * NAME.png/.pfm (an interruption: what it has, then exit), then report (below). */
void experiment_render_to_target(const Options *options, const Scene *scene,
                                 const RenderSettings *settings, Estimator estimate,
                                 const void *estimator_settings, const char *name,
                                 const char *settings_text, const Reference *reference);

/* Print the line of a render to a target (target_describe), with its error measured
 * against `reference` (NULL: none), and write it as a table row NAME_target.csv. */
void experiment_report_target(const Options *options, const char *name,
                              const char *settings_text, const TargetSettings *target,
                              const RelativeError *estimate, TargetStop stop, int passes,
                              const RenderResult *render, const Reference *reference);
#endif

#if CHAPTER >= 8
/* Render with photons (ppm_render), or exit as experiment_render does. Interrupted, the
 * panel NAME (if not NULL) is saved with the passes completed, if there is one, and the
 * program exits (experiment_write_panel). */
void experiment_render_ppm(const Options *options, const char *name, const Scene *scene,
                           const RenderSettings *settings, const PpmSettings *ppm,
                           PpmResult *result);

/* One setting rendered with `seeds` seeds (options->seed + k, quietly) and its error split
 * into bias and variance against the two references (bias_variance.h), without the
 * pixels marked in left_out: chapter 7's final estimator `path` at `spp` samples per
 * pixel on stratified sub-pixels and pairs (ppm NULL), or the photon map `ppm`, its
 * passes continuing one another's samples. */
BiasVariance experiment_seeds(const Options *options, const Scene *scene,
                              const PathSettings *path, const PpmSettings *ppm, int spp,
                              int seeds, const Reference references[2],
                              const unsigned char *left_out);

/* Chapter 8's photon version of chapter 7's final estimator `path` for a width x height
 * image, `spp` camera samples per pass, at most `passes` passes, no time budget: per pass
 * EXPERIMENT_PHOTONS_PER_PIXEL photons a pixel (at most a grid's worth), a first radius in
 * proportion to a pixel's size (PPM_FIRST_RADIUS_AT_800), the lamp's images in the mirror
 * at the first diffuse vertex only (beyond it the map brings that light).
 * docs/chapter8.md: how they were chosen. */
#define EXPERIMENT_PHOTONS_PER_PIXEL 0.5
PpmSettings experiment_photon_settings(const PathSettings *path, const Scene *scene, int width,
                                       int height, int spp, int passes);

/* Print the table of settings and their errors (bias_variance.h) and write it as NAME.csv. */
void experiment_write_error_table(const Options *options, const char *name,
                                  const SettingError *rows, int count);

/* The photon map's settings and what it rendered as text, e.g. "12 x 8 spp, M=1
 * mirror-light@1, 320k photons, r 0.05 to 0.012". */
void describe_ppm(const PpmSettings *ppm, const PpmResult *result, char *text, size_t size);
#endif

/* The settings as text for tables and captions, e.g. "depth=16 M=1 schlick rr=0.25". */
void describe_path(const PathSettings *settings, char *text, int size);

/* A figure caption from a table row: its settings, then time and error. */
void experiment_caption(const TableRow *row, const char *title, char *caption, size_t size);

/* The figure NAME of `count` panels (at most 8), each captioned by its title and its
 * table row (experiment_caption). */
void experiment_write_panels(const Options *options, const char *name, const Image *images,
                             const TableRow *rows, const char *const *titles, int count);
#endif /* CHAPTER >= 2 */

#endif
