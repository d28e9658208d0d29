/* ch08_photon_map.c (chapter 8): caustics from a photon map, made progressive, on top of
 * chapter 7's final path tracer (beyond the report: its §5 names photon mapping).
 *
 * New concepts (lib/): point_grid, photon (the caustic map L S+ D), photon_estimate
 * (radiance from the photons' density, the progressive radius), path_caustics (chapter 7's
 * final path tracer plus the map); the bench renders it in passes (bench/ppm.h). The
 * experiment (docs/chapter8.md): both at equal processor time, with crops of the caustic
 * under the glass sphere and of the lamp's image in the mirror; then, on a quarter-size
 * image, each setting over SEEDS seeds, the error against time as bias and variance.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "experiment.h"
#include "path_final.h"
#include "view.h"

/* Camera samples per pass of the figure's photon map, and passes at most (its time budget
 * ends them). */
#define PPM_SPP_PER_PASS 8
#define MAX_PASSES 100000

/* The table: seeds per setting, steps of doubling passes (and samples), camera samples
 * per pass; the crops' enlargement. */
enum {
    SEEDS = 4,
    STEPS = 5,
    TABLE_SPP_PER_PASS = 2,
    CROP_SCALE = 5
};

/* The reference: the same image as chapter 7's, shared with it through the cache. */
static void reference_for(const Options *options, const Scene *scene, Reference *reference)
{
    PathSettings estimator = {.max_depth = options->depth, .fresnel = options->fresnel};
    experiment_path_reference(options, scene, &estimator, NULL, 0.0, reference);
}

/* The figure: chapter 7's final estimator, then the photon version in the same
 * processor time; what each bought; and the crops. */
static void equal_time_figure(const Options *options, const Scene *scene,
                              const PathSettings *path, const Reference *reference)
{
    RenderSettings settings = experiment_render_settings(
        options, scene, options->spp, PIXEL_STRATIFIED, "chapter 7's final estimator");
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

    PpmSettings ppm = experiment_photon_settings(
        path, scene, settings.image.width, settings.image.height, PPM_SPP_PER_PASS, MAX_PASSES);
    ppm.cpu_seconds = path_cpu;
    settings.label = "photon map";
    settings.image.sampling = PIXEL_PROGRESSIVE; /* stratified over all passes */
    PpmResult photons;
    experiment_render_ppm(options, "ch08_photon_map", scene, &settings, &ppm, &photons);
    experiment_write_image(options, "ch08_photon_map", &photons.render.image, PANEL_EXPOSURE);
    describe_ppm(&ppm, &photons, text, sizeof text);
    rows[1] = experiment_row("ch08_photon_map", text, &photons.render);
    measure_fill_row(&rows[1], &photons.render.image, reference);

    const char *titles[] = {"chapter 7: final estimator (Figure 7)",
                            "chapter 8: + photon-mapped caustics, equal time"};
    Image images[3] = {reference->image, traced.image, photons.render.image}; /* the crops' */
    experiment_write_panels(options, "ch08_equal_time", &images[1], rows, titles, 2);
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
           "own variance (its noise %.4f): %.4f and %.4f, ratio %.3f\n",
           raw[0], raw[1], raw[1] / raw[0], reference->noise, rows[0].rmse, rows[1].rmse,
           rows[1].rmse / rows[0].rmse);
    printf("efficiency (1 / (rel_mse x seconds)): %.3g and %.3g, ratio %.2f\n",
           rows[0].efficiency, rows[1].efficiency, rows[1].efficiency / rows[0].efficiency);
    double ours[3], theirs[3];
    measure_channel_means(&photons.render.image, ours);
    measure_channel_means(&reference->image, theirs);
    printf("image mean per channel, photon map / reference:");
    for (int c = 0; c < 3; c++) {
        if (theirs[c] > 0.0)
            printf(" %.4f", ours[c] / theirs[c]);
        else
            printf(" - (the reference's mean is %g)", theirs[c]);
    }
    printf("\n");

    char reference_caption[128];
    snprintf(reference_caption, sizeof reference_caption, "reference (path tracer, %.0f spp)",
             reference->spp);
    const char *crop_captions[3] = {reference_caption, "chapter 7: final estimator",
                                    "chapter 8: photon map, equal time"};
    int col, row, width = traced.image.width, height = traced.image.height;
    int side = width / CROP_SCALE;
    if (view_caustic_pixel(scene, width, height, &col, &row))
        experiment_write_crops(options, "ch08_caustic_crop", images, crop_captions, 3,
                               col - side / 2, row - side / 2, side, CROP_SCALE);
    else
        printf("no glass sphere with a surface under it in view: no crop of its caustic\n");
    if (view_mirror_image_pixel(scene, path->mirrors, width, height, &col, &row))
        experiment_write_crops(options, "ch08_mirror_crop", images, crop_captions, 3,
                               col - side / 2, row - side / 2, side, CROP_SCALE);
    else
        printf("no lamp seen in a planar mirror: no crop of its image\n");
    render_result_free(&traced);
    ppm_result_free(&photons);
}

/* The photon-mapped image rendered to --target-error or --time: pairs of passes of
 * independent camera samples (stratified within each pass), so that the odd and even
 * passes are independent halves (error_estimate.h). The image is biased (the density
 * estimate's blur), which no estimate from its own samples sees: the error against the
 * reference is printed beside it, and what the two say measured. */
static void photon_map_to_target(const Options *options, const Scene *scene,
                                 const PathSettings *path, const Reference *reference)
{
    RenderSettings settings = experiment_render_settings(options, scene, PPM_SPP_PER_PASS,
                                                         PIXEL_STRATIFIED, "photon map");
    PpmSettings ppm = experiment_photon_settings(
        path, scene, settings.image.width, settings.image.height, PPM_SPP_PER_PASS, MAX_PASSES);
    ppm.target_error = options->target_error;
    ppm.time_limit = options->time_limit;
    PpmResult photons;
    experiment_render_ppm(options, "ch08_photon_map", scene, &settings, &ppm, &photons);
    experiment_write_image(options, "ch08_photon_map", &photons.render.image, PANEL_EXPOSURE);
    char text[192];
    describe_ppm(&ppm, &photons, text, sizeof text);
    TargetSettings target = experiment_target_settings(options, PPM_SPP_PER_PASS, 0);
    experiment_report_target(options, "ch08_photon_map", text, &target, &photons.estimate,
                             photons.stop, photons.passes, &photons.render, reference);
    RelativeError against = error_against_reference(&photons.render.image, reference);
    double estimated = error_percent(photons.estimate.rel_mse),
           measured = error_percent(against.rel_mse),
           spread = error_percent_std_error(&against);
    printf("the photon map is biased (its blur): the estimate from its own passes holds their "
           "variance only. Against the reference %.2f %% +/- %.2f, %s the estimate %.2f %%",
           measured, spread,
           measured - estimated > 2.0 * spread   ? "clearly above"
           : estimated - measured > 2.0 * spread ? "clearly below"
                                                 : "within two standard errors of",
           estimated);
    if (measured - estimated > 2.0 * spread)
        printf(": bias (and what the halves missed) about %.2f %%",
               sqrt(measured * measured - estimated * estimated));
    printf("\n");
    ppm_result_free(&photons);
}

/* The pixels that show the lamp or its images in the mirrors and the glass, and their
 * neighbours: bright in the image without caustics (the photon version with an empty
 * map), which nothing else is. Their noise is the same estimator in both here and, at a
 * quarter size, dominates the RMSE; the bias and variance are measured without them. */
static unsigned char *lamp_mask(const Options *small, const Scene *scene,
                                const PathSettings *path, int *left_out)
{
    PhotonMap empty;
    if (photon_map_build(&empty, NULL, 0, 0, 1.0) != 0)
        cli_fail(1, "out of memory");
    CausticPathSettings without = {*path, &empty, &empty, 1.0};
    Options quiet = *small;
    quiet.quiet = 1;
    RenderSettings settings =
        experiment_render_settings(&quiet, scene, 16, PIXEL_STRATIFIED, "mask");
    RenderResult result;
    experiment_render(scene, &settings, path_caustics_radiance, &without, &result);
    experiment_exit_if_interrupted(&result, NULL);
    unsigned char *lamp = bias_variance_bright_mask(&result.image, 1.0, left_out);
    if (!lamp)
        cli_fail(1, "out of memory");
    render_result_free(&result);
    photon_map_free(&empty);
    return lamp;
}

/* A row of the table: chapter 7's final estimator at `spp` (ppm NULL), or the photon map. */
static SettingError table_row(const Options *small, const Scene *scene,
                              const PathSettings *path, const PpmSettings *ppm, int spp,
                              const Reference references[2], const unsigned char *lamp)
{
    BiasVariance error =
        experiment_seeds(small, scene, path, ppm, spp, SEEDS, references, lamp);
    if (!ppm)
        return (SettingError){"chapter 7 final", spp, 0, 0, 0.0, 0.0, error};
    SettingError row = {"",          ppm->spp,   ppm->photons, ppm->passes,
                        ppm->radius, ppm->alpha, error};
    snprintf(row.estimator, sizeof row.estimator, "photon map a=%.2g", ppm->alpha);
    return row;
}

/* The table and the plot, on a quarter-size image. */
static void error_against_time(const Options *options, const Scene *scene,
                               const PathSettings *path)
{
    Options small = experiment_quarter_size(options, scene);
    /* Two references of independent seeds: the product of an image's errors against the
     * two has the reference's noise taken out in expectation (bias_variance.h). */
    Reference references[2];
    reference_for(&small, scene, &references[0]);
    Options other = small;
    other.seed = small.seed + 1000; /* references use ~seed; the panels seed .. seed + SEEDS */
    printf("a second reference of the same image, of another seed (the table's errors use "
           "both):\n");
    reference_for(&other, scene, &references[1]);
    int width, height, left_out;
    experiment_image_size(&small, scene, &width, &height);
    unsigned char *lamp = lamp_mask(&small, scene, path, &left_out);
    /* The series of the plot: chapter 7's estimator as its samples double, then the photon
     * map as its passes double: at the figure's settings; and with BLUR times the radius
     * (BLUR^2 times the photons in each estimate: far less variance, but a wide blur),
     * shrinking and fixed. Then, at the most passes, the figure's settings with 4 times
     * and a quarter of the photons, and half the radius. */
    enum {
        SERIES = 4,
        EXTRA = 3,
        BLUR = 8,
        ROWS = SERIES * STEPS + EXTRA
    };
    const double series_radius[SERIES] = {0, 1, BLUR, BLUR},
                 series_alpha[SERIES] = {0, PPM_ALPHA, PPM_ALPHA, 1};
    const double photon_factor[EXTRA] = {4.0, 0.25, 1.0},
                 radius_factor[EXTRA] = {1.0, 1.0, 0.5};
    SettingError rows[ROWS];
    double x[SERIES][STEPS], y[SERIES][STEPS];
    for (int s = 0; s < SERIES; s++)
        for (int step = 0; step < STEPS; step++) {
            SettingError *row = &rows[s * STEPS + step];
            PpmSettings ppm = experiment_photon_settings(path, scene, width, height,
                                                         TABLE_SPP_PER_PASS, 1 << step);
            ppm.radius *= series_radius[s];
            ppm.alpha = series_alpha[s];
            *row = table_row(&small, scene, path, s == 0 ? NULL : &ppm,
                             TABLE_SPP_PER_PASS << step, references, lamp);
            x[s][step] = row->error.cpu;
            y[s][step] = row->error.error;
        }
    for (int e = 0; e < EXTRA; e++) {
        PpmSettings ppm = experiment_photon_settings(path, scene, width, height,
                                                     TABLE_SPP_PER_PASS, 1 << (STEPS - 1));
        ppm.photons = (int)(ppm.photons * photon_factor[e] + 0.5);
        ppm.radius *= radius_factor[e];
        rows[SERIES * STEPS + e] =
            table_row(&small, scene, path, &ppm, ppm.spp, references, lamp);
    }
    printf(
        "\nerror against time at %d x %d, %d seeds per setting. rmse: the whole image "
        "(mean, lowest and highest of the seeds); error: without the lamp and its images "
        "(%d pixels of %d) and without the reference's noise, split into bias and variance:\n",
        width, height, SEEDS, left_out, width * height);
    experiment_write_error_table(options, "ch08_error_table", rows, ROWS);

    const Vec3 colours[SERIES] = {
        {0.85, 0.1, 0.1}, {0.1, 0.2, 0.9}, {0.1, 0.6, 0.1}, {0.95, 0.55, 0.0}};
    char labels[SERIES][64];
    snprintf(labels[0], sizeof labels[0], "chapter 7 final, %d to %d spp", TABLE_SPP_PER_PASS,
             TABLE_SPP_PER_PASS << (STEPS - 1));
    snprintf(labels[1], sizeof labels[1], "photon map, 1 to %d passes of %d spp",
             1 << (STEPS - 1), TABLE_SPP_PER_PASS);
    snprintf(labels[2], sizeof labels[2], "%d x the radius, shrinking", BLUR);
    snprintf(labels[3], sizeof labels[3], "%d x the radius, fixed", BLUR);
    PlotSeries series[SERIES];
    for (int s = 0; s < SERIES; s++)
        series[s] = (PlotSeries){.label = labels[s],
                                 .x = x[s],
                                 .y = y[s],
                                 .count = STEPS,
                                 .colour = colours[s],
                                 .markers = 1,
                                 .dashed = s == 3};
    Plot figure = {{"processor time (s)", PLOT_LOG, 0.0, 0.0, 0.0},
                   {"error (no lamp, no reference noise)", PLOT_LOG, 0.0, 0.0, 0.0},
                   series,
                   SERIES,
                   0.0};
    char caption[512];
    snprintf(caption, sizeof caption,
             "error against processor time, log-log, each point the mean of %d seeds; the "
             "shrinking radius's blur (bias) fades, the fixed one's stays",
             SEEDS);
    experiment_write_plot(options, "ch08_error_plot", &figure, 720, 480, caption);
    free(lamp);
    measure_reference_free(&references[0]);
    measure_reference_free(&references[1]);
}

int main(int argc, char **argv)
{
    ProgramInfo info = {
        "Chapter 8, caustics from a photon map: chapter 7's final estimator against the same\n"
        "estimator with progressive photon-mapped caustics at equal time, and their error\n"
        "against time. Both use roulette with bounded weights unless --rr is given. With\n"
        "--target-error or --time it renders the photon-mapped image alone, in pairs of\n"
        "passes, to that error (estimated from its passes: its variance, not its bias) or\n"
        "for that time, and prints what it cost and its error against the reference.",
        FLAGS_COMMON | FLAG_SPP | FLAG_SHADOW_RAYS | FLAG_RR | FLAG_DEPTH | FLAG_FRESNEL |
            FLAG_REFERENCE_SPP | FLAG_TARGET_ERROR | FLAG_TIME,
        {.scene = "scenes/room.scene",
         .size = 800,
         .spp = 64,
         .shadow_rays = 1,
         .rr = 0.75,
         .depth = 64,
         .seed = 1,
         .out = "build/figures",
         .reference_spp = REFERENCE_SPP},
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
    if (experiment_to_target(&options)) {
        photon_map_to_target(&options, &scene, &path, &reference);
        measure_reference_free(&reference);
        mirror_planes_free(&mirrors);
        scene_free(&scene);
        return 0;
    }
    equal_time_figure(&options, &scene, &path, &reference);
    measure_reference_free(&reference);
    error_against_time(&options, &scene, &path);
    mirror_planes_free(&mirrors);
    scene_free(&scene);
    return 0;
}
