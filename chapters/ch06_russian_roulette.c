/* ch06_russian_roulette.c (chapter 6): Russian roulette (report §2.2, §4.7; Figure 12).
 *
 * New concepts (lib/): roulette (a path survives each diffuse hit with probability alpha,
 * its weight divided by alpha: alpha is the SURVIVAL probability, the report's erratum),
 * path_roulette (the report's path tracer). The experiment (docs/chapter6.md): Figure 12,
 * alpha = 0.01 against 0.5; a sweep of alpha and bounded weights on a quarter-size image,
 * the image's mean staying the reference's while time and variance move. Below alpha =
 * rho^2 of the brightest surface the variance is infinite: such rows are marked, not ranked.
 */
#include <stdio.h>

#include "experiment.h"
#include "path_roulette.h"

/* The last point, 0, is not a constant alpha but roulette with bounded weights. */
static const double SWEEP[] = {0.01, 0.05, 0.1, 0.25, 0.5, 0.75, 0.9, 1.0, 0.0};
enum {
    SWEEP_COUNT = sizeof SWEEP / sizeof SWEEP[0],
    SWEEP_SPP = 16
};

static void settings_text_for(const Options *options, double alpha, char *text, size_t size)
{
    snprintf(text, size, "%d spp, M=%d alpha=%g", options->spp, options->shadow_rays, alpha);
}

/* A sweep point: alpha, or with alpha = 0 bounded weights (roulette.h: survival
 * min(1, max throughput) from the first segment on). Measured at random positions; its
 * image and standard error stay in *result for the image's mean. */
static TableRow measure_alpha(const Options *options, const Scene *scene,
                              const Reference *reference, double alpha, RenderResult *result)
{
    PathSettings path = {
        .max_depth = options->depth, .shadow_rays = options->shadow_rays, .rr_survival = alpha};
    char name[64], settings_text[96];
    if (alpha > 0.0) {
        snprintf(name, sizeof name, "sweep, alpha=%g", alpha);
        settings_text_for(options, alpha, settings_text, sizeof settings_text);
    } else {
        path.rr_throughput = 1;
        snprintf(name, sizeof name, "sweep, bounded weights");
        snprintf(settings_text, sizeof settings_text, "%d spp, M=%d q=min(1, max T)",
                 options->spp, options->shadow_rays);
    }
    RenderSettings settings =
        experiment_render_settings(options, scene, options->spp, PIXEL_RANDOM, name);
    TableRow row = experiment_runs(options, scene, &settings, path_roulette_radiance, &path,
                                   name, settings_text, reference, 0, result);
    row.infinite_variance = experiment_infinite_variance(scene, &path);
    return row;
}

/* Every alpha estimates the same image; the reference program renders it with its own
 * estimator (bench/reference.c): only the depth is taken from here. */
static void reference_for(const Options *options, const Scene *scene, Reference *reference)
{
    PathSettings estimator = {
        .max_depth = options->depth, .shadow_rays = 1, .rr_survival = 0.75};
    experiment_path_reference(options, scene, &estimator, NULL, 0.0, reference);
}

int main(int argc, char **argv)
{
    ProgramInfo info = {
        "Chapter 6, Russian roulette: reproduces the report's Figure 12 (alpha 0.01 vs 0.5)\n"
        "and sweeps alpha, the survival probability.",
        FLAGS_COMMON | FLAG_SPP | FLAG_SHADOW_RAYS | FLAG_DEPTH | FLAG_REFERENCE_SPP |
            FLAG_RUNS,
        {.scene = "scenes/room.scene",
         .size = 800,
         .spp = 4,
         .shadow_rays = 1,
         .depth = 64,
         .seed = 1,
         .out = "build/figures",
         .reference_spp = REFERENCE_SPP,
         .runs = CLI_RUNS},
    };
    Options options;
    Scene scene;
    experiment_start(argc, argv, &info, NEEDS_AREA_LIGHT, &options, &scene);
    Reference reference;
    reference_for(&options, &scene, &reference);

    const double figure_alpha[2] = {0.01, 0.5};
    TableRow rows[2];
    Image images[2];
    for (int i = 0; i < 2; i++) {
        char name[64], settings_text[96];
        snprintf(name, sizeof name, "ch06_figure12_alpha%g", figure_alpha[i]);
        settings_text_for(&options, figure_alpha[i], settings_text, sizeof settings_text);
        PathSettings path = {.max_depth = options.depth,
                             .shadow_rays = options.shadow_rays,
                             .rr_survival = figure_alpha[i]};
        rows[i] =
            experiment_path_row(&options, &scene, path_roulette_radiance, &path, options.spp,
                                PIXEL_SUBPIXELS, name, settings_text, &reference, &images[i]);
    }
    const char *titles[] = {"Figure 12, left", "Figure 12, right"};
    experiment_write_panels(&options, "ch06_figure12", images, rows, titles, 2);
    experiment_write_table(&options, "ch06_table", rows, 2);
    image_free(&images[0]);
    image_free(&images[1]);
    measure_reference_free(&reference);

    Options sweep_options = experiment_quarter_size(&options, &scene);
    reference_for(&sweep_options, &scene, &reference);
    double reference_mean = reference.mean, reference_error = reference.mean_std_error;
    TableRow sweep[SWEEP_COUNT];
    sweep_options.spp = SWEEP_SPP;
    printf("\nsweep of alpha at %d pixels wide, %d spp each; mean radiance of the image "
           "(first run):\n",
           sweep_options.size, SWEEP_SPP);
    printf("  reference        %.5f +- %.5f\n", reference_mean, reference_error);
    int finite = 0, finite_far = 0, infinite = 0, infinite_short = 0;
    for (int i = 0; i < SWEEP_COUNT; i++) {
        RenderResult result;
        sweep[i] = measure_alpha(&sweep_options, &scene, &reference, SWEEP[i], &result);
        double mean, error;
        measure_image_mean(&result.image, &result.average_std_error, &mean, &error);
        double z = measure_z(mean, error, reference_mean, reference_error);
        char label[32] = "bounded weights";
        if (SWEEP[i] > 0.0)
            snprintf(label, sizeof label, "alpha = %g", SWEEP[i]);
        printf("  %-16s %.5f +- %.5f   (%+.1f standard errors from the reference)%s\n", label,
               mean, error, z, sweep[i].infinite_variance ? "  inf-var" : "");
        if (sweep[i].infinite_variance) {
            infinite++;
            infinite_short += z < -2.0;
        } else {
            finite++;
            finite_far += fabs(z) > 3.0;
        }
        render_result_free(&result);
    }
    /* What this run measured, counted; not what usually happens. */
    printf("measured: %d of the %d settings of finite variance have a mean more than 3 "
           "standard errors\nfrom the reference; %d of the %d of infinite variance fall short "
           "of it by more than 2\n(their standard errors cannot be trusted: a rare, very "
           "bright path is missing from them).\n",
           finite_far, finite, infinite_short, infinite);
    experiment_write_table(&options, "ch06_sweep", sweep, SWEEP_COUNT);
    int best = measure_most_efficient(sweep, SWEEP_COUNT);
    if (best == SWEEP_COUNT - 1)
        printf("most efficient of the settings of finite variance (the others cannot be "
               "ranked): bounded weights\n");
    else if (best >= 0)
        printf("most efficient of the settings of finite variance (the others cannot be "
               "ranked): alpha = %g\n",
               SWEEP[best]);
    /* Against the best constant alpha of finite variance (alpha = 1 always is). */
    int best_alpha = measure_most_efficient(sweep, SWEEP_COUNT - 1);
    if (best_alpha >= 0)
        printf("bounded weights (q = min(1, max throughput)): %.2f times the efficiency of the "
               "best constant alpha of finite variance (%g)\n",
               sweep[SWEEP_COUNT - 1].efficiency / sweep[best_alpha].efficiency,
               SWEEP[best_alpha]);

    measure_reference_free(&reference);
    scene_free(&scene);
    return 0;
}
