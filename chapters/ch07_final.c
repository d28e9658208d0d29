/* ch07_final.c (chapter 7): the final image and the benchmarks (report §4.2, §4.8, §5; Figure 7,
 * Table 1).
 *
 * New concepts (lib/): ways to spend the samples where the error is: mis (multiple
 * importance sampling of the lamps), mirror_light (the lamp's image in the mirror wall
 * as a light of its own), direct_light (both, at a diffuse vertex), sphere_guide
 * (bounces aimed at the mirror and glass spheres, for their caustics), sobol (stratified
 * pairs of numbers across a pixel's samples), and path_final, the path tracer with them
 * all; from chapter 6, roulette with bounded weights. The bench renders on every core
 * (--threads), what the report's discussion asks for first: its final image took 311
 * minutes on one thread.
 *
 * The experiment:
 *   - Figure 7: the room with everything on (sub-pixels, shadow rays, glass with
 *     Fresnel reflectance, Russian roulette; Oren-Nayar where a scene uses it), and
 *     with the levers below: one shadow ray, bounded-weight roulette (unless --rr is
 *     given), the mirror's image of the lamp at every diffuse hit, bounces aimed at
 *     the spheres, and the stratified pairs of sobol.h (--strata off: independent
 *     numbers);
 *   - the levers, one by one, at equal samples on a quarter-size image: the report's
 *     estimator of this chapter's old default (M=4, alpha=0.75), then M=1, bounded
 *     weights, mis, the mirror light, the sphere guide and the stratified pairs, each
 *     with its time, error and efficiency.
 *     Where the error is (measured per path): in the room most of it is light found
 *     only by hitting the lamp after a mirror or the glass (caustics), the mirror
 *     wall's share the largest; shadow rays already find the lamp directly well, so
 *     mis, which adds BRDF sampling where light sampling is poor, changes almost
 *     nothing here (the lamp is seen from afar), while the mirror light removes the
 *     mirror wall's share and the sphere guide most of the glass sphere's (at
 *     256 x 256, 64 spp, it halves the squared error that is left);
 *   - Table 1: the report's six settings (samples per pixel, shadow rays, roulette
 *     alpha) at full size, each with its time, rays, error against the reference and
 *     efficiency, beside the minutes the report measured;
 *   - a convergence plot: for the five estimators of Table 1, the error against the
 *     time as the samples double, log-log, on a quarter-size image.
 * Every setting estimates the same image (roulette, shadow rays, mis and the mirror
 * light are unbiased, and the depth limit of 64 is never reached in practice), so one
 * reference serves all.
 *
 * Watch the roulette constant. A surviving path's weight grows by rho / alpha at each
 * diffuse bounce, so its variance is finite only when alpha > rho^2 (tests/test_path.c).
 * The room's white walls have rho^2 = 0.56: Table 1's alpha = 0.25 and 0.01 are below
 * that, their error is dominated by rare very bright samples ("fireflies") and falls
 * slower than 1/sqrt(time) on the convergence plot. The final image uses alpha = 0.75,
 * above the brightest surface's rho^2 = 0.64.
 */
#include <stdio.h>
#include <string.h>

#include "experiment.h"
#include "path_final.h"
#include "path_roulette.h"
#include "plot.h"
#include "sphere_guide.h"

typedef struct {
    int spp, shadow_rays;
    double rr;
    double report_minutes;
} Table1Setting;

static const Table1Setting TABLE1[] = {
    {16, 1, 0.25, 7}, {16, 30, 0.25, 132}, {1, 20, 0.25, 5},
    {4, 20, 0.25, 23}, {4, 20, 0.01, 5},   {4, 20, 0.9, 51},
};
enum { TABLE1_ROWS = sizeof TABLE1 / sizeof TABLE1[0] };

/* The convergence plot's estimators: Table 1's, once each, with their colours. */
static const struct {
    int shadow_rays;
    double rr;
    const char *colour_name;
    Vec3 colour;
} ESTIMATORS[] = {
    {1, 0.25, "red", {0.85, 0.1, 0.1}},   {30, 0.25, "green", {0.1, 0.6, 0.1}},
    {20, 0.25, "blue", {0.1, 0.2, 0.9}},  {20, 0.01, "orange", {0.95, 0.55, 0.0}},
    {20, 0.9, "purple", {0.6, 0.1, 0.7}},
};
enum { ESTIMATOR_COUNT = sizeof ESTIMATORS / sizeof ESTIMATORS[0], CONVERGENCE_STEPS = 5 };

/* Every setting estimates the same image; the reference program renders it with its
 * own estimator (bench/reference.c): only the depth and Fresnel mode are taken from
 * here. */
static void reference_for(const Options *options, const Scene *scene, Reference *reference)
{
    PathSettings estimator = {.max_depth = options->depth, .fresnel = options->fresnel};
    experiment_path_reference(options, scene, &estimator, NULL, 0.0, reference);
}

/* The final estimator with these settings as a table row; with `image`, a panel
 * (experiment_path_row). */
static TableRow render_path(const Options *options, const Scene *scene, const Reference *reference,
                            const PathSettings *path, int spp, const char *name, const char *note,
                            Image *image)
{
    char description[128], settings_text[192];
    describe_path(path, description, sizeof description);
    snprintf(settings_text, sizeof settings_text, "%d spp, %s%s", spp, description, note);
    PixelSampling sampling = options->strata ? PIXEL_STRATIFIED : PIXEL_SUBPIXELS;
    return experiment_path_row(options, scene, path_final_radiance, path, spp, sampling, name,
                               settings_text, reference,
                               image);
}

/* One of the report's settings (M shadow rays, constant alpha) as a table row. */
static TableRow render_setting(const Options *options, const Scene *scene,
                               const Reference *reference, int spp, int shadow_rays, double rr,
                               const char *name, const char *note, Image *image)
{
    PathSettings path = {.max_depth = options->depth, .shadow_rays = shadow_rays, .fresnel = options->fresnel, .rr_survival = rr};
    char settings_text[96];
    snprintf(settings_text, sizeof settings_text, "%d spp, M=%d, rr=%g%s", spp, shadow_rays, rr, note);
    return experiment_path_row(options, scene, path_roulette_radiance, &path, spp, PIXEL_SUBPIXELS,
                               name, settings_text,
                               reference, image);
}

static void final_image(const Options *options, const Scene *scene, const Reference *reference,
                        const MirrorPlanes *mirrors)
{
    Image image;
    PathSettings path = experiment_final_estimator(options, mirrors);
    TableRow row = render_path(options, scene, reference, &path, options->spp, "ch07_figure7",
                               options->strata ? " strata" : "", &image);
    char caption[512];
    experiment_caption(&row, options->strata
                                 ? "Figure 7: final image, with chapter 7's levers (bounded-weight"
                                   " roulette, the mirror's image of the lamp, the sphere guide,"
                                   " stratified pairs)"
                                 : "Figure 7: final image, with chapter 7's levers (bounded-weight"
                                   " roulette, the mirror's image of the lamp, the sphere guide)",
                       caption, sizeof caption);
    const char *captions[] = {caption};
    experiment_write_figure(options, "ch07_figure7_captioned", &image, captions, 1, PANEL_EXPOSURE);
    experiment_write_table(options, "ch07_figure7", &row, 1);
    image_free(&image);
}

static void table1(const Options *options, const Scene *scene, const Reference *reference)
{
    TableRow rows[TABLE1_ROWS];
    for (int i = 0; i < TABLE1_ROWS; i++) {
        char name[48], note[48];
        snprintf(name, sizeof name, "Table 1, row %d", i + 1);
        snprintf(note, sizeof note, " (report: %g min)", TABLE1[i].report_minutes);
        rows[i] = render_setting(options, scene, reference, TABLE1[i].spp, TABLE1[i].shadow_rays,
                                 TABLE1[i].rr, name, note, NULL);
    }
    printf("\nTable 1 of the report, measured here:\n");
    experiment_write_table(options, "ch07_table1", rows, TABLE1_ROWS);
    printf("\n%-28s %12s %12s %10s\n", "setting", "report (s)", "here (s)", "speed-up");
    for (int i = 0; i < TABLE1_ROWS; i++) {
        char setting[48];
        snprintf(setting, sizeof setting, "%d spp, M=%d, rr=%g", TABLE1[i].spp,
                 TABLE1[i].shadow_rays, TABLE1[i].rr);
        printf("%-28s %12.0f %12.2f %10.0f\n", setting, 60.0 * TABLE1[i].report_minutes,
               rows[i].seconds, 60.0 * TABLE1[i].report_minutes / rows[i].seconds);
    }
}

/* The levers one by one, at equal samples on a quarter-size image, against its own
 * reference: each row adds one to the row before, from the report's estimator of
 * this chapter's old default; the last row is the final image's estimator. */
#define LEVER_SPP 16
#define LEVER_STEPS 8
static void levers(const Options *options, const Scene *scene, const MirrorPlanes *mirrors)
{
    Options small = *options, stratified;
    small.size = cli_quarter(options->size, 16);
    small.strata = 0;
    stratified = small;
    stratified.strata = 1;
    Reference reference;
    reference_for(&small, scene, &reference);
    PathSettings steps[LEVER_STEPS];
    const char *names[LEVER_STEPS] = {"report: M=4, alpha=0.75", "M=1", "+ bounded weights",
                                      "+ mis", "+ mirror light", "without mis",
                                      "+ sphere guide", "final: + stratified pairs"};
    steps[0] = (PathSettings){.max_depth = small.depth, .shadow_rays = 4, .fresnel = small.fresnel,
                              .rr_survival = 0.75};
    steps[1] = steps[0];
    steps[1].shadow_rays = 1;
    steps[2] = steps[1];
    steps[2].rr_throughput = 1;
    steps[3] = steps[2];
    steps[3].mis = 1;
    steps[4] = steps[3];
    steps[4].mirror_light = small.depth;
    steps[4].mirrors = mirrors;
    steps[5] = steps[4];
    steps[5].mis = 0;
    steps[6] = steps[5];
    steps[6].sphere_guide = SPHERE_GUIDE_STRENGTH;
    steps[7] = steps[6];
    TableRow rows[LEVER_STEPS];
    for (int i = 0; i < LEVER_STEPS; i++) {
        int last = i == LEVER_STEPS - 1;
        rows[i] = render_path(last ? &stratified : &small, scene, &reference, &steps[i], LEVER_SPP,
                              names[i], last ? " strata" : "", NULL);
    }
    printf("\nthe levers at %d pixels wide, %d spp each (efficiency = 1 / (rel_mse * seconds)):\n",
           small.size, LEVER_SPP);
    experiment_write_table(options, "ch07_levers", rows, LEVER_STEPS);
    printf("final estimator: %.2f times the efficiency of the report's (row 1); the stratified"
           " pairs alone: %.2f times\n",
           rows[LEVER_STEPS - 1].efficiency / rows[0].efficiency,
           rows[LEVER_STEPS - 1].efficiency / rows[LEVER_STEPS - 2].efficiency);
    printf("the sphere guide alone: %.2f times the efficiency of the row before it\n",
           rows[LEVER_STEPS - 2].efficiency / rows[LEVER_STEPS - 3].efficiency);
    measure_reference_free(&reference);
}

/* Error against time as the samples double, for each estimator; CSV and plot. */
static void convergence(const Options *options, const Scene *scene)
{
    Options small = experiment_quarter_size(options);
    Reference reference;
    reference_for(&small, scene, &reference);
    double seconds[ESTIMATOR_COUNT][CONVERGENCE_STEPS], rmse[ESTIMATOR_COUNT][CONVERGENCE_STEPS];
    double low[ESTIMATOR_COUNT][CONVERGENCE_STEPS], high[ESTIMATOR_COUNT][CONVERGENCE_STEPS];
    TableRow rows[ESTIMATOR_COUNT * CONVERGENCE_STEPS];
    PlotSeries series[ESTIMATOR_COUNT + 1];
    char labels[ESTIMATOR_COUNT][48];
    for (int e = 0; e < ESTIMATOR_COUNT; e++) {
        for (int step = 0; step < CONVERGENCE_STEPS; step++) {
            char name[64];
            snprintf(name, sizeof name, "%s, %d spp", ESTIMATORS[e].colour_name, 1 << step);
            TableRow *row = &rows[e * CONVERGENCE_STEPS + step];
            *row = render_setting(&small, scene, &reference, 1 << step, ESTIMATORS[e].shadow_rays,
                                  ESTIMATORS[e].rr, name, "", NULL);
            seconds[e][step] = row->seconds;
            rmse[e][step] = row->rmse;
            /* The error bar: one standard deviation of the runs' RMSE either side. */
            double spread = isnan(row->rmse_spread) ? 0.0 : row->rmse_spread;
            low[e][step] = row->rmse - spread;
            high[e][step] = row->rmse + spread;
        }
        snprintf(labels[e], sizeof labels[e], "M=%d, rr=%g", ESTIMATORS[e].shadow_rays,
                 ESTIMATORS[e].rr);
        series[e] = (PlotSeries){.label = labels[e], .x = seconds[e], .y = rmse[e],
                                 .y_low = low[e], .y_high = high[e], .count = CONVERGENCE_STEPS,
                                 .colour = ESTIMATORS[e].colour, .markers = 1,
                                 .infinite_variance = rows[e * CONVERGENCE_STEPS].infinite_variance};
    }
    printf("\nconvergence at %d pixels wide, 1 to %d spp:\n", small.size, 1 << (CONVERGENCE_STEPS - 1));
    experiment_write_table(options, "ch07_convergence", rows, ESTIMATOR_COUNT * CONVERGENCE_STEPS);
    printf("measured: does the mean RMSE fall at every doubling, and its log-log slope "
           "against time\n(an estimator of finite variance follows -1/2):\n");
    for (int e = 0; e < ESTIMATOR_COUNT; e++) {
        int falls = 1;
        for (int step = 1; step < CONVERGENCE_STEPS; step++)
            falls = falls && rmse[e][step] < rmse[e][step - 1];
        double slope = log(rmse[e][CONVERGENCE_STEPS - 1] / rmse[e][0]) /
                       log(seconds[e][CONVERGENCE_STEPS - 1] / seconds[e][0]);
        printf("  %-14s %-30s slope %+.2f%s\n", labels[e],
               falls ? "falls at every doubling," : "does not fall at every doubling,", slope,
               series[e].infinite_variance ? "   (infinite variance)" : "");
    }

    /* A guide of slope -1/2 (error ~ 1/sqrt(time), what an estimator of finite variance
     * follows) over the last estimator's times, twice its first error so that both
     * lines show: compare slopes. */
    const int last = ESTIMATOR_COUNT - 1, final_step = CONVERGENCE_STEPS - 1;
    double guide_x[2] = {seconds[last][0], seconds[last][final_step]};
    double guide_y[2] = {2.0 * rmse[last][0], 2.0 * rmse[last][0] * sqrt(guide_x[0] / guide_x[1])};
    series[ESTIMATOR_COUNT] = (PlotSeries){.label = "slope -1/2", .x = guide_x, .y = guide_y,
                                           .count = 2, .colour = {0.45, 0.45, 0.45}, .dashed = 1};
    Plot plot = {{"time (s)", PLOT_LOG, 0.0, 0.0, 0.0}, {"RMSE", PLOT_LOG, 0.0, 0.0, 0.0},
                 series, ESTIMATOR_COUNT + 1, 0.0};
    Image image = experiment_plot(&plot, 720, 480);
    char caption[256];
    snprintf(caption, sizeof caption,
             "RMSE against render time as the samples double, 1 to %d spp, %d pixels wide; "
             "each point the mean of %d runs, its bar their standard deviation",
             1 << (CONVERGENCE_STEPS - 1), small.size, small.runs);
    const char *captions[] = {caption};
    experiment_write_figure(options, "ch07_convergence", &image, captions, 1, 1.0);
    image_free(&image);
    measure_reference_free(&reference);
}

int main(int argc, char **argv)
{
    ProgramInfo info = {
        "Chapter 7, the final image and the benchmarks: reproduces the report's Figure 7 and\n"
        "Table 1 (with times, errors and efficiency), measures the variance levers one by\n"
        "one, and plots error against time. Figure 7 uses roulette with bounded weights\n"
        "unless --rr is given.",
        FLAGS_COMMON | FLAG_SPP | FLAG_SHADOW_RAYS | FLAG_RR | FLAG_DEPTH | FLAG_FRESNEL |
            FLAG_REFERENCE_SPP | FLAG_RUNS | FLAG_STRATA,
        {.scene = "scenes/room.scene", .size = 800, .spp = 64, .shadow_rays = 1, .rr = 0.75,
         .depth = 64, .seed = 1, .out = "build/figures", .reference_spp = REFERENCE_SPP, .runs = CLI_RUNS,
         .strata = 1},
    };
    Options options;
    Scene scene;
    experiment_start(argc, argv, &info, NEEDS_AREA_LIGHT, &options, &scene);
    MirrorPlanes mirrors;
    if (mirror_light_find_planes(&scene, &mirrors) != 0)
        cli_fail(1, "out of memory");
    Reference reference;
    reference_for(&options, &scene, &reference);
    final_image(&options, &scene, &reference, &mirrors);
    Options report = options; /* the report's estimators: independent numbers */
    report.strata = 0;
    table1(&report, &scene, &reference);
    measure_reference_free(&reference);
    levers(&options, &scene, &mirrors);
    convergence(&report, &scene);
    mirror_planes_free(&mirrors);
    scene_free(&scene);
    return 0;
}
