/* ch03_shadow_rays.c (chapter 3): shadow rays (report §3.7, eq. 21; Figure 11).
 *
 * New concepts (lib/): area_light (uniform sampling of the lights' area, and the direct
 * light of eq. 21 with M shadow rays), path_direct (the path tracer with them). The
 * experiment (docs/chapter3.md): Figure 11, 1 against 30 shadow rays; Figure 8 as the
 * report rendered it, with shadow rays; a sweep of M from 0 (chapter 2's estimator) to 30
 * on a quarter-size image, where more shadow rays stop paying, and what it measured, in
 * words. Every M estimates the same image, so one reference serves them all.
 */
#include <stdio.h>

#include "experiment.h"
#include "path.h"
#include "path_direct.h"

static const int SWEEP[] = {0, 1, 2, 4, 8, 16, 30};
enum {
    SWEEP_COUNT = sizeof SWEEP / sizeof SWEEP[0],
    SWEEP_SPP = 4
};

/* One setting of M as a table row; with `image`, a panel (experiment_path_row). */
static TableRow render_m(const Options *options, const Scene *scene, const Reference *reference,
                         int m, int spp, PixelSampling sampling, const char *name, Image *image)
{
    PathSettings path = {.max_depth = options->depth, .shadow_rays = m};
    char settings_text[96];
    snprintf(settings_text, sizeof settings_text, "%d spp, M=%d depth=%d", spp, m,
             options->depth);
    Estimator estimate = m == 0 ? path_radiance : path_direct_radiance;
    return experiment_path_row(options, scene, estimate, &path, spp, sampling, name,
                               settings_text, reference, image);
}

/* Every M estimates the same image; the reference uses one shadow ray. */
static void reference_for(const Options *options, const Scene *scene, Reference *reference)
{
    PathSettings with_shadow_ray = {.max_depth = options->depth, .shadow_rays = 1};
    experiment_path_reference(options, scene, &with_shadow_ray, NULL, 0.0, reference);
}

/* What the sweep measured, in words computed from it. */
static void print_conclusions(const TableRow sweep[SWEEP_COUNT])
{
    int best = measure_most_efficient(sweep, SWEEP_COUNT);
    if (best >= 0)
        printf("measured: the most efficient setting is M=%d (M=0, chapter 2's estimator, "
               "included).\n",
               SWEEP[best]);
    double ratio = sweep[1].efficiency / sweep[0].efficiency;
    if (ratio > 1.0)
        printf("  one shadow ray reaches the error of M=0 in %.1f times less time.\n", ratio);
    else
        printf(
            "  one shadow ray was not more efficient than M=0 here (efficiency ratio %.2f).\n",
            ratio);
    const TableRow *one = &sweep[1], *most = &sweep[SWEEP_COUNT - 1];
    /* The relative error, because the RMSE of a small image is mostly the edges of the
     * lamp (radiance 25), which no number of shadow rays changes. */
    if (measure_clearly_lower(most, one))
        printf("  M=%d lowered the error of M=1 measurably (relative MSE %.4g +- %.2g against "
               "%.4g +- %.2g), at %.1f times the time.\n",
               SWEEP[SWEEP_COUNT - 1], most->rel_mse, most->rel_mse_spread, one->rel_mse,
               one->rel_mse_spread, most->seconds / one->seconds);
    else
        printf("  M=%d did not lower the error of M=1 measurably (relative MSE %.4g +- %.2g "
               "against %.4g +- %.2g), at %.1f times the time:\n  the error that remains is "
               "not the direct light that shadow rays estimate (it can be the lamp's own\n  "
               "edges seen from the camera, or the lamp seen in a mirror or through glass).\n",
               SWEEP[SWEEP_COUNT - 1], most->rel_mse, most->rel_mse_spread, one->rel_mse,
               one->rel_mse_spread, most->seconds / one->seconds);
}

int main(int argc, char **argv)
{
    ProgramInfo info = {
        "Chapter 3, shadow rays: reproduces the report's Figure 11 (1 vs 30 shadow rays) and\n"
        "sweeps the number of shadow rays M.",
        FLAGS_COMMON | FLAG_SPP | FLAG_DEPTH | FLAG_REFERENCE_SPP | FLAG_RUNS,
        {.scene = "scenes/room.scene",
         .size = 800,
         .spp = 4,
         .depth = 8,
         .seed = 1,
         .out = "build/figures",
         .reference_spp = DEPTH8_REFERENCE_SPP,
         .runs = CLI_RUNS},
    };
    Options options;
    Scene scene;
    experiment_start(argc, argv, &info, NEEDS_AREA_LIGHT, &options, &scene);
    Reference reference;
    reference_for(&options, &scene, &reference);

    TableRow rows[4];
    Image images[4];
    const int figure_m[2] = {1, 30}, figure8_spp[2] = {1, 4};
    const char *titles[] = {"Figure 11, left", "Figure 11, right",
                            "Figure 8, left, as the report: with shadow rays",
                            "Figure 8, right, as the report: with shadow rays"};
    for (int i = 0; i < 2; i++) {
        char name[64];
        snprintf(name, sizeof name, "ch03_figure11_m%d", figure_m[i]);
        rows[i] = render_m(&options, &scene, &reference, figure_m[i], options.spp,
                           PIXEL_SUBPIXELS, name, &images[i]);
    }
    experiment_write_panels(&options, "ch03_figure11", images, rows, titles, 2);
    for (int i = 0; i < 2; i++) {
        char name[64];
        snprintf(name, sizeof name, "ch03_figure8_%dspp", figure8_spp[i]);
        rows[2 + i] = render_m(&options, &scene, &reference, 1, figure8_spp[i], PIXEL_SUBPIXELS,
                               name, &images[2 + i]);
    }
    experiment_write_panels(&options, "ch03_figure8", &images[2], &rows[2], &titles[2], 2);
    experiment_write_table(&options, "ch03_table", rows, 4);
    for (int i = 0; i < 4; i++)
        image_free(&images[i]);
    measure_reference_free(&reference);

    /* The sweep, on a quarter-size image with a reference of its own. */
    Options sweep_options = experiment_quarter_size(&options, &scene);
    reference_for(&sweep_options, &scene, &reference);
    TableRow sweep[SWEEP_COUNT];
    for (int i = 0; i < SWEEP_COUNT; i++) {
        char name[64];
        snprintf(name, sizeof name, "sweep, M=%d", SWEEP[i]);
        sweep[i] = render_m(&sweep_options, &scene, &reference, SWEEP[i], SWEEP_SPP,
                            PIXEL_RANDOM, name, NULL);
    }
    printf("\nsweep of M at %d pixels wide, %d spp each:\n", sweep_options.size, SWEEP_SPP);
    experiment_write_table(&options, "ch03_sweep", sweep, SWEEP_COUNT);
    print_conclusions(sweep);

    measure_reference_free(&reference);
    scene_free(&scene);
    return 0;
}
