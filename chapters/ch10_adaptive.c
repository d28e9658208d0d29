/* ch10_adaptive.c (chapter 10): adaptive sampling, rendering to an error rather than to a
 * sample count (beyond the report), on chapter 7's final estimator.
 *
 * New concept (lib/): adaptive (each pixel's error from two half-images of its own samples,
 * the stopping rule, the passes, and the bias of deciding from the samples that are kept);
 * the bench runs the passes on every core until an error or a time is reached
 * (bench/adaptive_renderer.h). The experiment (docs/chapter10.md): the adaptive image at
 * --target-error (or for --time) against chapter 7's uniform samples and chapter 8's photon
 * map in the same processor time, with the maps of samples and of the estimated error; then,
 * on a quarter-size image over SEEDS seeds, the time each takes to reach 5, 2, 1 and 0.5 %.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "adaptive_renderer.h"
#include "experiment.h"
#include "path_final.h"

/* The rule's samples per pass where a pixel is above the threshold, and at most per
 * pixel; without --target-error or --time the figure renders for DEFAULT_SECONDS (with
 * --quick, to QUICK_TARGET): at full size a target of a few per cent takes tens of minutes. */
enum {
    PASS_SAMPLES = 8,
    MAX_SAMPLES = 1 << 16
};
#define DEFAULT_SECONDS 60
#define TEXT(x) #x
#define TEXT_OF(macro) TEXT(macro)
#define QUICK_TARGET 0.05
/* Its references take 16 times chapter 8's samples: the table measures errors down to
 * 0.5 %, which a reference's noise must not hide (the printed ref% says how much it does).
 * --quick, a check that the figure and the table are made, takes QUICK_REFERENCE_FACTOR
 * times: their errors are then measured against a noisier reference (ref% shows it), its
 * noise still taken out. */
#define REFERENCE_SPP_FACTOR 16
#define QUICK_REFERENCE_FACTOR 4

/* The table: seeds, the errors it times, and the ladders each estimator climbs: chapter 7's
 * samples per pixel and chapter 8's passes doubling from FIRST_SPP and 1, until the
 * smallest error is passed or a step takes more than STEP_SECONDS (--quick:
 * QUICK_STEP_SECONDS); chapter 10's targets down to LAST_TARGET, below the smallest error so as
 * to bracket it. */
enum {
    SEEDS = 3,
    QUICK_SEEDS = 2,
    ERRORS = 4,
    LADDER = 24,
    FIRST_SPP = 4,
    TABLE_SPP_PER_PASS = 2
};
static const double TABLE_ERRORS[ERRORS] = {0.05, 0.02, 0.01, 0.005};
#define LAST_TARGET 0.0035
#define STEP_SECONDS 10.0
#define QUICK_STEP_SECONDS 0.25

static AdaptiveSettings rule_from(const Options *options, AdaptiveRule rule)
{
    int min_samples = (options->spp + 3) / 4 * 4; /* whole quarters */
    return (AdaptiveSettings){rule, min_samples, MAX_SAMPLES, PASS_SAMPLES, 0.0};
}

static AdaptiveGoal goal_from(const Options *options, AdaptiveRule rule)
{
    AdaptiveGoal goal = {rule_from(options, rule), options->target_error, options->time_limit};
    if (goal.target_error <= 0.0 && goal.time_limit <= 0.0) {
        if (options->quick)
            goal.target_error = QUICK_TARGET;
        else
            goal.time_limit = DEFAULT_SECONDS;
    }
    return goal;
}

static void render_adaptive(const Scene *scene, const RenderSettings *settings,
                            const PathSettings *path, const AdaptiveGoal *goal,
                            AdaptiveResult *result)
{
    render_install_interrupt();
    if (adaptive_renderer_run(scene, settings, path_final_radiance, path, goal, result) != 0)
        cli_fail(1, "out of memory rendering %d x %d adaptively", settings->image.width,
                 settings->image.height);
    experiment_report_dropped(settings->label, &result->render);
    experiment_exit_if_interrupted(&result->render, NULL);
}

/* The relative MSE of an image against the reference, its noise taken out (measure.h). */
static double measured_rel_mse(const Image *image, const Reference *reference)
{
    ErrorEstimate error;
    if (measure_error_estimate(image, &reference->image, &reference->std_error, &error) != 0)
        cli_fail(1, "an image and its reference differ in size");
    return error.rel_mse;
}

static double efficiency(double rel_mse, double cpu_seconds)
{
    return rel_mse > 0.0 ? 1.0 / (rel_mse * cpu_seconds) : NAN;
}

/* Chapter 7's final estimator at `spp` stratified samples per pixel; its processor time. */
static double render_uniform(const Options *options, const Scene *scene,
                             const PathSettings *path, int spp, RenderResult *result)
{
    RenderSettings settings =
        experiment_render_settings(options, scene, spp, PIXEL_STRATIFIED, "chapter 7, uniform");
    double start = stats_cpu_now();
    experiment_render(scene, &settings, path_final_radiance, path, result);
    experiment_exit_if_interrupted(result, NULL);
    return stats_cpu_now() - start;
}

/* A map (samples or error: the same value in the three channels) scaled so that its
 * largest value is white, for the figure. */
static Image scaled_map(const Image *map, double *largest)
{
    long n = 3L * map->width * map->height;
    *largest = 0.0;
    for (long i = 0; i < n; i++)
        *largest = fmax(*largest, map->pixels[i]);
    Image scaled = image_new(map->width, map->height);
    if (!scaled.pixels)
        cli_fail(1, "out of memory");
    for (long i = 0; i < n; i++)
        scaled.pixels[i] = *largest > 0.0 ? (float)(map->pixels[i] / *largest) : 0.0f;
    return scaled;
}

/* The figure: adaptive (unbiased, then biased) against uniform samples and the photon map
 * in the processor time the unbiased adaptive render took; the maps. */
static void equal_time_figure(const Options *options, const Scene *scene,
                              const PathSettings *path, const Reference *reference)
{
    enum {
        PANELS = 4
    };
    AdaptiveGoal goal = goal_from(options, ADAPTIVE_UNBIASED);
    RenderSettings settings = experiment_render_settings(options, scene, 0, PIXEL_PROGRESSIVE,
                                                         "chapter 10, adaptive");
    AdaptiveResult adaptive, biased;
    render_adaptive(scene, &settings, path, &goal, &adaptive);
    double budget = adaptive.cpu_seconds;
    AdaptiveGoal biased_goal = goal_from(options, ADAPTIVE_BIASED);
    settings.label = "chapter 10, biased rule";
    render_adaptive(scene, &settings, path, &biased_goal, &biased);

    /* Chapter 7 at the samples per pixel that take the same processor time, judged by a
     * render of FIRST_SPP. */
    RenderResult trial, uniform;
    Options quiet = *options;
    quiet.quiet = 1;
    double trial_cpu = render_uniform(&quiet, scene, path, FIRST_SPP, &trial);
    render_result_free(&trial);
    int spp = (int)fmax(1.0, round(FIRST_SPP * budget / trial_cpu));
    double uniform_cpu = render_uniform(options, scene, path, spp, &uniform);

    PpmSettings ppm = experiment_photon_settings(path, scene, settings.image.width,
                                                 settings.image.height, 8, 100000);
    ppm.cpu_seconds = budget;
    settings.label = "chapter 8, photon map";
    settings.image.sampling = PIXEL_PROGRESSIVE;
    PpmResult photons;
    experiment_render_ppm(options, "ch10_photon_map", scene, &settings, &ppm, &photons);

    const RenderResult *renders[PANELS] = {&uniform, &photons.render, &adaptive.render,
                                           &biased.render};
    const double cpu[PANELS] = {uniform_cpu, photons.cpu_seconds, adaptive.cpu_seconds,
                                biased.cpu_seconds};
    const char *names[PANELS] = {"ch10_uniform", "ch10_photon_map", "ch10_adaptive",
                                 "ch10_adaptive_biased"};
    const char *titles[PANELS] = {
        "chapter 7: uniform samples, equal time", "chapter 8: photon map, equal time",
        "chapter 10: adaptive (unbiased rule)", "chapter 10: adaptive, biased rule"};
    char texts[PANELS][96];
    snprintf(texts[0], sizeof texts[0], "%d spp stratified", spp);
    describe_ppm(&ppm, &photons, texts[1], sizeof texts[1]);
    const AdaptiveResult *runs[2] = {&adaptive, &biased};
    for (int i = 0; i < 2; i++)
        snprintf(texts[2 + i], sizeof texts[2 + i], "%s %.3g%s, min %d spp, %d passes",
                 goal.target_error > 0.0 ? "target" : "for",
                 goal.target_error > 0.0 ? goal.target_error : goal.time_limit,
                 goal.target_error > 0.0 ? "" : " s", goal.rule.min_samples, runs[i]->passes);
    TableRow rows[PANELS];
    Image images[PANELS];
    double rel_mse[PANELS];
    for (int i = 0; i < PANELS; i++) {
        experiment_write_image(options, names[i], &renders[i]->image, PANEL_EXPOSURE);
        rows[i] = experiment_row(names[i], texts[i], renders[i]);
        measure_fill_row(&rows[i], &renders[i]->image, reference);
        images[i] = renders[i]->image;
        rel_mse[i] = measured_rel_mse(&renders[i]->image, reference);
    }
    experiment_write_panels(options, "ch10_equal_time", images, rows, titles, PANELS);
    experiment_write_table(options, "ch10_equal_time", rows, PANELS);

    double most_samples, largest_error;
    Image maps[2] = {scaled_map(&adaptive.samples, &most_samples),
                     scaled_map(&adaptive.error, &largest_error)};
    experiment_write_image(options, "ch10_samples", &adaptive.samples, 1.0 / most_samples);
    experiment_write_image(options, "ch10_error", &adaptive.error, 1.0 / largest_error);
    char captions[2][160];
    snprintf(captions[0], sizeof captions[0],
             "samples per pixel (white: %.0f; mean %.1f, uniform: %d)", most_samples,
             render_samples_per_pixel(&adaptive.render), spp);
    snprintf(captions[1], sizeof captions[1],
             "estimated relative RMSE per pixel (white: %.3f; image: %.4f)", largest_error,
             adaptive.estimated_rel_rmse);
    const char *map_captions[2] = {captions[0], captions[1]};
    experiment_write_figure(options, "ch10_maps", maps, map_captions, 2, 1.0);
    image_free(&maps[0]);
    image_free(&maps[1]);

    printf("\nequal processor time: %.1f s (chapter 7: %.1f s, chapter 8: %.1f s, biased "
           "rule: %.1f s)\n",
           budget, uniform_cpu, photons.cpu_seconds, biased.cpu_seconds);
    for (int i = 0; i < 2; i++)
        printf("%s: relative RMSE estimated from its samples %.4f, measured against the "
               "reference %.4f (ratio %.2f)\n",
               titles[2 + i], runs[i]->estimated_rel_rmse, sqrt(fmax(rel_mse[2 + i], 0.0)),
               runs[i]->estimated_rel_rmse / sqrt(fmax(rel_mse[2 + i], 0.0)));
    printf("efficiency 1 / (rel_mse x processor seconds):");
    for (int i = 0; i < PANELS; i++)
        printf(" %s %.3g;", names[i] + 5, efficiency(rel_mse[i], cpu[i]));
    printf("\nratio chapter 10 / chapter 8: %.2f; chapter 10 / chapter 7: %.2f\n",
           efficiency(rel_mse[2], cpu[2]) / efficiency(rel_mse[1], cpu[1]),
           efficiency(rel_mse[2], cpu[2]) / efficiency(rel_mse[0], cpu[0]));
    /* What an oracle allocating the same samples among the pixels could buy at most. */
    double gain_uniform = error_allocation_gain(&uniform.image, &uniform.std_error),
           gain_photons =
               error_allocation_gain(&photons.render.image, &photons.render.std_error);
    printf(
        "the most any allocation of the samples among the pixels could buy (each pixel's "
        "variance known, nothing spent to learn it, every sample kept): x %.2f on chapter "
        "7's estimator, x %.2f on chapter 8's (from its %d passes' spread); at best %.2f and "
        "%.2f times chapter 8's efficiency\n",
        gain_uniform, gain_photons, photons.passes,
        gain_uniform * efficiency(rel_mse[0], cpu[0]) / efficiency(rel_mse[1], cpu[1]),
        gain_photons);
    render_result_free(&uniform);
    ppm_result_free(&photons);
    adaptive_result_free(&adaptive);
    adaptive_result_free(&biased);
}

/* The processor time at which a ladder's error (falling as its time grows) reaches
 * `error`: between the two steps around it, interpolated on log-log axes; beyond the
 * ladder, from its nearest step with error^2 in proportion to 1 / time (*extrapolated
 * set). */
static double time_to_reach(const double *seconds, const double *errors, int steps,
                            double error, int *extrapolated)
{
    for (int k = 1; k < steps; k++)
        if (errors[k - 1] > error && errors[k] <= error) {
            double t =
                (log(errors[k - 1]) - log(error)) / (log(errors[k - 1]) - log(errors[k]));
            return exp(log(seconds[k - 1]) + t * (log(seconds[k]) - log(seconds[k - 1])));
        }
    *extrapolated = 1;
    int nearest = errors[0] <= error ? 0 : steps - 1;
    double ratio = errors[nearest] / error;
    return seconds[nearest] * ratio * ratio;
}

/* One estimator's ladder at one seed: each step's processor time and measured relative
 * RMSE. estimator 0: chapter 7, 1: chapter 8, 2: chapter 10. Returns the steps. */
static int climb(int estimator, const Options *small, const Scene *scene,
                 const PathSettings *path, const Reference *reference, double *seconds,
                 double *errors)
{
    double step_limit = small->quick ? QUICK_STEP_SECONDS : STEP_SECONDS;
    int steps = 0, width, height;
    experiment_image_size(small, scene, &width, &height);
    for (int k = 0; k < LADDER; k++) {
        Image *image;
        RenderResult uniform;
        PpmResult photons;
        AdaptiveResult adaptive;
        if (estimator == 0) {
            seconds[k] = render_uniform(small, scene, path, FIRST_SPP << k, &uniform);
            image = &uniform.image;
        } else if (estimator == 1) {
            RenderSettings settings =
                experiment_render_settings(small, scene, 0, PIXEL_PROGRESSIVE, "photon map");
            PpmSettings ppm = experiment_photon_settings(path, scene, width, height,
                                                         TABLE_SPP_PER_PASS, 1 << k);
            experiment_render_ppm(small, NULL, scene, &settings, &ppm, &photons);
            seconds[k] = photons.cpu_seconds;
            image = &photons.render.image;
        } else {
            AdaptiveGoal goal = {rule_from(small, ADAPTIVE_UNBIASED),
                                 TABLE_ERRORS[0] * pow(LAST_TARGET / TABLE_ERRORS[0],
                                                       (double)k / (ERRORS - 1) * 0.75),
                                 0.0};
            RenderSettings settings =
                experiment_render_settings(small, scene, 0, PIXEL_PROGRESSIVE, "adaptive");
            render_adaptive(scene, &settings, path, &goal, &adaptive);
            seconds[k] = adaptive.cpu_seconds;
            image = &adaptive.render.image;
        }
        errors[k] = sqrt(fmax(measured_rel_mse(image, reference), 1e-12));
        if (estimator == 0)
            render_result_free(&uniform);
        else if (estimator == 1)
            ppm_result_free(&photons);
        else
            adaptive_result_free(&adaptive);
        steps = k + 1;
        if (errors[k] < TABLE_ERRORS[ERRORS - 1] * 0.9 || seconds[k] > step_limit)
            break;
    }
    return steps;
}

/* The table: per estimator and error, the mean time to reach it over the seeds and its
 * standard error; the ratio of chapter 8's to chapter 10's (their efficiency ratio). */
static void time_table(const Options *options, const Scene *scene, const PathSettings *path)
{
    Options small = experiment_quarter_size(options, scene);
    small.quiet = 1;
    Reference reference;
    PathSettings expectation = {.max_depth = path->max_depth, .fresnel = path->fresnel};
    experiment_path_reference(&small, scene, &expectation, NULL, 0.0, &reference);
    int seeds = options->quick ? QUICK_SEEDS : SEEDS, extrapolated[3][ERRORS] = {{0}};
    double times[3][ERRORS][SEEDS];
    for (int e = 0; e < 3; e++)
        for (int s = 0; s < seeds; s++) {
            double seconds[LADDER], errors[LADDER];
            small.seed = options->seed + (uint64_t)s;
            int steps = climb(e, &small, scene, path, &reference, seconds, errors);
            for (int k = 0; k < ERRORS; k++)
                times[e][k][s] =
                    time_to_reach(seconds, errors, steps, TABLE_ERRORS[k], &extrapolated[e][k]);
        }
    int width, height;
    experiment_image_size(&small, scene, &width, &height);
    printf("\nprocessor seconds to reach each relative RMSE (against the reference, its noise "
           "%.4f taken out) at %d x %d, mean +- standard error over %d seeds:\n",
           reference.noise, width, height, seeds);
    printf("%-8s %-20s %-20s %-20s %s\n", "rel_rmse", "chapter 7", "chapter 8", "chapter 10",
           "ch8 / ch10 (efficiency ratio)");
    enum {
        COLUMNS = 9
    };
    double values[ERRORS * COLUMNS];
    for (int k = 0; k < ERRORS; k++) {
        RunSummary summary[3];
        for (int e = 0; e < 3; e++)
            if (measure_summarise_runs(times[e][k], seeds, &summary[e]) != 0)
                cli_fail(1, "out of memory");
        double ratio = summary[1].mean / summary[2].mean;
        double ratio_error = ratio * hypot(summary[1].std_error / summary[1].mean,
                                           summary[2].std_error / summary[2].mean);
        printf("%-8.3f", TABLE_ERRORS[k]);
        for (int e = 0; e < 3; e++)
            printf(" %8.3g +- %-8.2g%c", summary[e].mean, summary[e].std_error,
                   extrapolated[e][k] ? '*' : ' ');
        printf(" %.2f +- %.2f\n", ratio, ratio_error);
        double row[COLUMNS] = {
            TABLE_ERRORS[k],      summary[0].mean, summary[0].std_error, summary[1].mean,
            summary[1].std_error, summary[2].mean, summary[2].std_error, ratio,
            ratio_error};
        for (int c = 0; c < COLUMNS; c++)
            values[k * COLUMNS + c] = row[c];
    }
    int any = 0;
    for (int e = 0; e < 3; e++)
        for (int k = 0; k < ERRORS; k++)
            any |= extrapolated[e][k];
    if (any)
        printf("*: at some seed extrapolated beyond its ladder (rel_mse in proportion to 1 / "
               "time)\n");
    const int decimals[COLUMNS] = {3, 3, 3, 3, 3, 3, 3, 2, 2};
    experiment_write_numbers(options, "ch10_time_table",
                             "rel_rmse,ch07_seconds,ch07_se,ch08_seconds,ch08_se,ch10_seconds,"
                             "ch10_se,ch08_over_ch10,ratio_se",
                             values, ERRORS, COLUMNS, decimals);
    measure_reference_free(&reference);
}

int main(int argc, char **argv)
{
    ProgramInfo info = {
        "Chapter 10, adaptive sampling: each pixel's error estimated from two half-images of\n"
        "its own samples, more samples only where it is above the threshold, until the\n"
        "image's estimated relative RMSE reaches --target-error or --time runs out; against\n"
        "chapter 7's uniform samples and chapter 8's photon map at equal processor time, and\n"
        "the time each takes to reach 5, 2, 1 and 0.5 %. --spp: the minimum samples per "
        "pixel.\n"
        "Without either, the figure renders for " TEXT_OF(
            DEFAULT_SECONDS) " s (--quick: to 5 %). --quick's reference\n"
                             "takes a quarter of the default's samples unless --reference-spp "
                             "is given.",
        FLAGS_COMMON | FLAG_SPP | FLAG_SHADOW_RAYS | FLAG_RR | FLAG_DEPTH | FLAG_FRESNEL |
            FLAG_REFERENCE_SPP | FLAG_TARGET_ERROR | FLAG_TIME,
        {.scene = "scenes/room.scene",
         .size = 256,
         .spp = 16,
         .shadow_rays = 1,
         .rr = 0.75,
         .depth = 64,
         .fresnel = FRESNEL_EXACT,
         .seed = 1,
         .out = "build/figures",
         .reference_spp = REFERENCE_SPP_FACTOR * REFERENCE_SPP},
    };
    Options options;
    Scene scene;
    experiment_start(argc, argv, &info, NEEDS_AREA_LIGHT, &options, &scene);
    if (options.quick && !cli_given(&options, FLAG_REFERENCE_SPP))
        options.reference_spp = QUICK_REFERENCE_FACTOR * REFERENCE_SPP;
    MirrorPlanes mirrors;
    if (mirror_light_find_planes(&scene, &mirrors) != 0)
        cli_fail(1, "out of memory");
    PathSettings path = experiment_final_estimator(&options, &mirrors);
    Reference reference;
    PathSettings expectation = {.max_depth = path.max_depth, .fresnel = path.fresnel};
    experiment_path_reference(&options, &scene, &expectation, NULL, 0.0, &reference);
    equal_time_figure(&options, &scene, &path, &reference);
    measure_reference_free(&reference);
    time_table(&options, &scene, &path);
    mirror_planes_free(&mirrors);
    scene_free(&scene);
    return 0;
}
