/* Chapter 6: Russian roulette (report §2.2, §4.7; Figure 12; SPEC §8.5).
 *
 * New concepts (lib/): roulette (a path survives each diffuse hit with probability
 * alpha, its weight divided by alpha; alpha is the SURVIVAL probability, erratum §8.5).
 *
 * The experiment:
 *   - Figure 12: alpha = 0.01 vs 0.5;
 *   - a sweep of alpha on a smaller image (a quarter of --size): the image's mean
 *     radiance stays the same within its standard error (roulette is unbiased) while
 *     time and variance move; the efficiency column says which alpha is best.
 * With roulette, paths may be long: the depth limit is set high (64) so that it almost
 * never acts and the estimate is of the full rendering equation.
 */
#include <stdio.h>

#include "experiment.h"
#include "path.h"

static const double SWEEP[] = {0.01, 0.05, 0.1, 0.25, 0.5, 0.75, 0.9, 1.0};
enum { SWEEP_COUNT = sizeof SWEEP / sizeof SWEEP[0] };

/* Render one alpha into a table row; its image and standard error stay in *result.
 * A panel (`panel` non-zero) also has its image written. */
static TableRow render_alpha(const Options *options, const Scene *scene,
                             const Reference *reference, double alpha, int panel,
                             const char *name, RenderResult *result)
{
    PathSettings path = {options->shadow_rays, alpha, options->depth, FRESNEL_SCHLICK};
    char settings_text[96];
    snprintf(settings_text, sizeof settings_text, "%d spp, M=%d alpha=%g", options->spp,
             options->shadow_rays, alpha);
    PixelSampling sampling = panel ? PIXEL_SUBPIXELS : PIXEL_RANDOM;
    RenderSettings settings = experiment_render_settings(options, scene, options->spp, sampling, name);
    if (panel)
        return experiment_panel(options, scene, &settings, path_radiance, &path, name,
                                settings_text, reference, result);
    return experiment_measure(scene, &settings, path_radiance, &path, name, settings_text,
                              reference, result);
}

static void reference_for(const Options *options, const Scene *scene, Reference *reference)
{
    PathSettings estimator = {1, 0.5, options->depth, FRESNEL_SCHLICK};
    char description[96];
    path_describe(&estimator, description, sizeof description);
    experiment_reference(options, scene, path_radiance, &estimator, description,
                         options->reference_spp, reference);
}

int main(int argc, char **argv)
{
    ProgramInfo info = {
        "Chapter 6, Russian roulette: reproduces the report's Figure 12 (alpha 0.01 vs 0.5)\n"
        "and sweeps alpha, the survival probability.",
        FLAGS_COMMON | FLAG_SPP | FLAG_SHADOW_RAYS | FLAG_DEPTH | FLAG_REFERENCE_SPP,
        {.scene = "scenes/room.scene", .size = 800, .spp = 4, .shadow_rays = 1, .depth = 64,
         .seed = 1, .out = "build/figures", .reference_spp = 256},
    };
    Options options;
    cli_parse(argc, argv, &info, &options);
    if (options.quick && !cli_given(&options, FLAG_SIZE))
        options.size = 200;

    Scene scene;
    experiment_load_scene(&options, NEEDS_AREA_LIGHT, &scene);
    Reference reference;
    reference_for(&options, &scene, &reference);

    const double figure_alpha[2] = {0.01, 0.5};
    TableRow rows[2];
    Image images[2];
    char captions[2][256];
    for (int i = 0; i < 2; i++) {
        char name[64];
        snprintf(name, sizeof name, "ch06_figure12_alpha%g", figure_alpha[i]);
        RenderResult result;
        rows[i] = render_alpha(&options, &scene, &reference, figure_alpha[i], 1, name, &result);
        experiment_caption(&rows[i], i == 0 ? "Figure 12, left" : "Figure 12, right",
                           captions[i], sizeof captions[i]);
        images[i] = result.image;
        image_free(&result.std_error);
    }
    const char *figure_captions[] = {captions[0], captions[1]};
    experiment_write_figure(&options, "ch06_figure12", images, figure_captions, 2, PANEL_EXPOSURE);
    experiment_write_table(&options, "ch06_table", rows, 2);
    image_free(&images[0]);
    image_free(&images[1]);
    measure_reference_free(&reference);

    Options sweep_options = options;
    sweep_options.size = options.size / 4 > 16 ? options.size / 4 : 16;
    reference_for(&sweep_options, &scene, &reference);
    double reference_mean, reference_error;
    measure_image_mean(&reference.image, &reference.std_error, &reference_mean, &reference_error);
    TableRow sweep[SWEEP_COUNT];
    printf("\nsweep of alpha at %d pixels wide, %d spp each; mean radiance of the image:\n",
           sweep_options.size, options.spp);
    printf("  reference        %.5f +- %.5f\n", reference_mean, reference_error);
    for (int i = 0; i < SWEEP_COUNT; i++) {
        char name[64];
        snprintf(name, sizeof name, "sweep, alpha=%g", SWEEP[i]);
        RenderResult result;
        sweep[i] = render_alpha(&sweep_options, &scene, &reference, SWEEP[i], 0, name, &result);
        double mean, error;
        measure_image_mean(&result.image, &result.std_error, &mean, &error);
        double z = (mean - reference_mean) / sqrt(error * error + reference_error * reference_error);
        printf("  alpha = %-5g    %.5f +- %.5f   (%+.1f standard errors from the reference)\n",
               SWEEP[i], mean, error, z);
        render_result_free(&result);
    }
    experiment_write_table(&options, "ch06_sweep", sweep, SWEEP_COUNT);
    int best = 0;
    for (int i = 1; i < SWEEP_COUNT; i++)
        if (sweep[i].efficiency > sweep[best].efficiency)
            best = i;
    printf("most efficient: alpha = %g\n", SWEEP[best]);

    measure_reference_free(&reference);
    scene_free(&scene);
    return 0;
}
