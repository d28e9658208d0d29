/* ch07_final.c (chapter 7): the final image and the benchmarks (report §4.2, §4.8, §5;
 * Figure 7, Table 1).
 *
 * New concepts (lib/): mis, mirror_light (the lamp's image in the mirror wall as a light),
 * direct_light (both, at a diffuse vertex), sphere_guide (bounces aimed at the spheres),
 * sobol (stratified pairs across a pixel's samples), path_final (all of them, roulette with
 * bounded weights). The experiment (docs/chapter7.md): Figure 7 with every lever on; the
 * levers one by one on a quarter-size image; Table 1 beside the report's minutes; the
 * convergence plot of Table 1's estimators. Every setting estimates one image.
 */
#include <stdio.h>

#include "convergence.h"
#include "experiment.h"
#include "path_final.h"
#include "path_roulette.h"
#include "sphere_guide.h"

static const struct {
    int spp, shadow_rays;
    double rr, report_minutes;
} TABLE1[] = {
    {16, 1, 0.25, 7},  {16, 30, 0.25, 132}, {1, 20, 0.25, 5},
    {4, 20, 0.25, 23}, {4, 20, 0.01, 5},    {4, 20, 0.9, 51},
};
enum {
    TABLE1_ROWS = sizeof TABLE1 / sizeof TABLE1[0]
};

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
enum {
    ESTIMATOR_COUNT = sizeof ESTIMATORS / sizeof ESTIMATORS[0],
    CONVERGENCE_STEPS = 5
};

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
static TableRow render_path(const Options *options, const Scene *scene,
                            const Reference *reference, const PathSettings *path, int spp,
                            const char *name, const char *note, Image *image)
{
    char description[128], settings_text[192];
    describe_path(path, description, sizeof description);
    snprintf(settings_text, sizeof settings_text, "%d spp, %s%s", spp, description, note);
    PixelSampling sampling = options->strata ? PIXEL_STRATIFIED : PIXEL_SUBPIXELS;
    return experiment_path_row(options, scene, path_final_radiance, path, spp, sampling, name,
                               settings_text, reference, image);
}

/* One of the report's settings (M shadow rays, constant alpha) as a table row. */
static TableRow render_setting(const Options *options, const Scene *scene,
                               const Reference *reference, int spp, int shadow_rays, double rr,
                               const char *name, const char *note, Image *image)
{
    PathSettings path = {.max_depth = options->depth,
                         .shadow_rays = shadow_rays,
                         .fresnel = options->fresnel,
                         .rr_survival = rr};
    char settings_text[96];
    snprintf(settings_text, sizeof settings_text, "%d spp, M=%d, rr=%g%s", spp, shadow_rays, rr,
             note);
    return experiment_path_row(options, scene, path_roulette_radiance, &path, spp,
                               PIXEL_SUBPIXELS, name, settings_text, reference, image);
}

static void final_image(const Options *options, const Scene *scene, const Reference *reference,
                        const MirrorPlanes *mirrors)
{
    Image image;
    PathSettings path = experiment_final_estimator(options, mirrors);
    TableRow row = render_path(options, scene, reference, &path, options->spp, "ch07_figure7",
                               options->strata ? " strata" : "", &image);
    char title[256];
    snprintf(title, sizeof title,
             "Figure 7: final image, with chapter 7's levers (bounded-weight "
             "roulette, the mirror's image of the lamp, the sphere guide%s)",
             options->strata ? ", stratified pairs" : "");
    const char *titles[] = {title};
    experiment_write_panels(options, "ch07_figure7_captioned", &image, &row, titles, 1);
    experiment_write_table(options, "ch07_figure7", &row, 1);
    image_free(&image);
}

/* Figure 7's image rendered to --target-error or --time instead of --spp. */
static void final_image_to_target(const Options *options, const Scene *scene,
                                  const Reference *reference, const MirrorPlanes *mirrors)
{
    PathSettings path = experiment_final_estimator(options, mirrors);
    PixelSampling sampling = options->strata ? PIXEL_STRATIFIED : PIXEL_SUBPIXELS;
    RenderSettings settings =
        experiment_render_settings(options, scene, TARGET_FIRST_SPP, sampling, "Figure 7");
    char description[128], text[192];
    describe_path(&path, description, sizeof description);
    snprintf(text, sizeof text, "to target, %s%s", description,
             options->strata ? " strata" : "");
    experiment_render_to_target(options, scene, &settings, path_final_radiance, &path,
                                "ch07_figure7", text, reference);
}

static void table1(const Options *options, const Scene *scene, const Reference *reference)
{
    TableRow rows[TABLE1_ROWS];
    for (int i = 0; i < TABLE1_ROWS; i++) {
        char name[48], note[48];
        snprintf(name, sizeof name, "Table 1, row %d", i + 1);
        snprintf(note, sizeof note, " (report: %g min)", TABLE1[i].report_minutes);
        rows[i] = render_setting(options, scene, reference, TABLE1[i].spp,
                                 TABLE1[i].shadow_rays, TABLE1[i].rr, name, note, NULL);
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
    small.size = experiment_width_near(scene, cli_quarter(options->size, 16));
    small.strata = 0;
    stratified = small;
    stratified.strata = 1;
    Reference reference;
    reference_for(&small, scene, &reference);
    PathSettings steps[LEVER_STEPS];
    const char *names[LEVER_STEPS] = {"report: M=4, alpha=0.75", "M=1",
                                      "+ bounded weights",       "+ mis",
                                      "+ mirror light",          "without mis",
                                      "+ sphere guide",          "final: + stratified pairs"};
    steps[0] = (PathSettings){.max_depth = small.depth,
                              .shadow_rays = 4,
                              .fresnel = small.fresnel,
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
        rows[i] = render_path(last ? &stratified : &small, scene, &reference, &steps[i],
                              LEVER_SPP, names[i], last ? " strata" : "", NULL);
    }
    printf(
        "\nthe levers at %d pixels wide, %d spp each (efficiency = 1 / (rel_mse * seconds)):\n",
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

/* Error against time as the samples double, for each estimator; its table, what it
 * measured, and the plot. */
static void convergence(const Options *options, const Scene *scene)
{
    Options small = experiment_quarter_size(options, scene);
    Reference reference;
    reference_for(&small, scene, &reference);
    TableRow rows[ESTIMATOR_COUNT * CONVERGENCE_STEPS];
    char labels[ESTIMATOR_COUNT][48];
    const char *label_list[ESTIMATOR_COUNT];
    Vec3 colours[ESTIMATOR_COUNT];
    for (int e = 0; e < ESTIMATOR_COUNT; e++) {
        for (int step = 0; step < CONVERGENCE_STEPS; step++) {
            char name[64];
            snprintf(name, sizeof name, "%s, %d spp", ESTIMATORS[e].colour_name, 1 << step);
            rows[e * CONVERGENCE_STEPS + step] =
                render_setting(&small, scene, &reference, 1 << step, ESTIMATORS[e].shadow_rays,
                               ESTIMATORS[e].rr, name, "", NULL);
        }
        snprintf(labels[e], sizeof labels[e], "M=%d, rr=%g", ESTIMATORS[e].shadow_rays,
                 ESTIMATORS[e].rr);
        label_list[e] = labels[e];
        colours[e] = ESTIMATORS[e].colour;
    }
    printf("\nconvergence at %d pixels wide, 1 to %d spp:\n", small.size,
           1 << (CONVERGENCE_STEPS - 1));
    experiment_write_table(options, "ch07_convergence", rows,
                           ESTIMATOR_COUNT * CONVERGENCE_STEPS);
    printf("measured: does the mean RMSE fall at every doubling, and its log-log slope "
           "against time\n(an estimator of finite variance follows -1/2):\n");
    for (int e = 0; e < ESTIMATOR_COUNT; e++) {
        const TableRow *series = &rows[e * CONVERGENCE_STEPS];
        printf("  %-14s %-30s slope %+.2f%s\n", labels[e],
               convergence_falls(series, CONVERGENCE_STEPS)
                   ? "falls at every doubling,"
                   : "does not fall at every doubling,",
               convergence_slope(series, CONVERGENCE_STEPS),
               series[0].infinite_variance ? "   (infinite variance)" : "");
    }
    ConvergencePlot plot;
    convergence_plot(&plot, rows, ESTIMATOR_COUNT, CONVERGENCE_STEPS, label_list, colours);
    char caption[256];
    snprintf(caption, sizeof caption,
             "RMSE against render time as the samples double, 1 to %d spp, %d pixels wide; "
             "each point the mean of %d runs, its bar their standard deviation",
             1 << (CONVERGENCE_STEPS - 1), small.size, small.runs);
    experiment_write_plot(options, "ch07_convergence", &plot.plot, 720, 480, caption);
    measure_reference_free(&reference);
}

int main(int argc, char **argv)
{
    ProgramInfo info = {
        "Chapter 7, the final image and the benchmarks: reproduces the report's Figure 7 and\n"
        "Table 1 (with times, errors and efficiency), measures the variance levers one by\n"
        "one, and plots error against time. Figure 7 uses roulette with bounded weights\n"
        "unless --rr is given. With --target-error or --time it renders Figure 7's image\n"
        "alone, in passes, to that error or for that time, and prints what it cost.",
        FLAGS_COMMON | FLAG_SPP | FLAG_SHADOW_RAYS | FLAG_RR | FLAG_DEPTH | FLAG_FRESNEL |
            FLAG_REFERENCE_SPP | FLAG_RUNS | FLAG_STRATA | FLAG_TARGET_ERROR | FLAG_TIME,
        {.scene = "scenes/room.scene",
         .size = 800,
         .spp = 64,
         .shadow_rays = 1,
         .rr = 0.75,
         .depth = 64,
         .seed = 1,
         .out = "build/figures",
         .reference_spp = REFERENCE_SPP,
         .runs = CLI_RUNS,
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
    if (experiment_to_target(&options)) {
        final_image_to_target(&options, &scene, &reference, &mirrors);
        measure_reference_free(&reference);
        mirror_planes_free(&mirrors);
        scene_free(&scene);
        return 0;
    }
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
