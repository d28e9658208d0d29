/* ch04_fresnel.c (chapter 4): Fresnel glass and ray depth (report §3.5.1-3.5.2, §4.4; Figure
 * 9).
 *
 * New concepts (lib/): fresnel (the exact reflectance, eqs. 3-5, the labels R_s and R_p
 * corrected), chosen in glass.c by the path settings; Snell's law and Schlick (eqs. 2,
 * 6-7) came in chapter 1. The experiment (docs/chapter4.md): Figure 9, depth 3 against 8,
 * with the report's red square enlarged and each image's mean radiance, where cutting
 * paths short shows; then Schlick against exact Fresnel: (a) their curves, (b) the cost
 * of one evaluation, (c) the room with each, from the same random numbers. No roulette.
 */
#include <stdio.h>

#include "experiment.h"
#include "fresnel.h"
#include "path_direct.h"
#include "schlick.h"
#include "snell.h"

#define GLASS_IOR 1.5
#define TIMING_CALLS 10000000

static const int FIGURE_DEPTH[2] = {3, 8};
enum {
    FULL_DEPTH = 64,
    FRESNEL_DEPTH = 8
};

/* The report's red square: the part of the mirror wall that shows the glass sphere, as
 * fractions of the image's width and height (the sphere's mirror image is centred near
 * (0.40, 0.53)), enlarged CROP_SCALE times. */
static const double CROP_LEFT = 0.32, CROP_TOP = 0.445, CROP_SIDE = 0.16;
enum {
    CROP_SCALE = 3
};

/* The reference for the full rendering equation up to `depth` segments (the reference
 * program keeps its long paths cheap with Russian roulette, chapter 6). */
static void reference_for(const Options *options, const Scene *scene, int depth,
                          FresnelMode fresnel, Reference *reference)
{
    PathSettings estimator = {.max_depth = depth, .fresnel = fresnel};
    experiment_path_reference(options, scene, &estimator, NULL, 0.0, reference);
}

/* Render one panel into a table row; its image and standard error stay in *result. */
static TableRow render_panel(const Options *options, const Scene *scene,
                             const Reference *reference, int depth, FresnelMode fresnel,
                             PixelSampling sampling, const char *name, RenderResult *result)
{
    PathSettings path = {
        .max_depth = depth, .shadow_rays = options->shadow_rays, .fresnel = fresnel};
    char description[64], settings_text[96];
    describe_path(&path, description, sizeof description);
    snprintf(settings_text, sizeof settings_text, "%d spp, %s", options->spp, description);
    RenderSettings settings =
        experiment_render_settings(options, scene, options->spp, sampling, name);
    return experiment_runs(options, scene, &settings, path_direct_radiance, &path, name,
                           settings_text, reference, 1, result);
}

/* Figure 9, its red square enlarged, and each image's mean radiance against the
 * reference's: how much light the bounces beyond the depth limit would have added. */
static void figure9(const Options *options, const Scene *scene)
{
    Reference reference;
    reference_for(options, scene, FULL_DEPTH, options->fresnel, &reference);
    TableRow rows[2];
    Image images[2];
    double means[2], errors[2];
    char crop_captions[2][256];
    for (int i = 0; i < 2; i++) {
        char name[64];
        snprintf(name, sizeof name, "ch04_figure9_depth%d", FIGURE_DEPTH[i]);
        RenderResult result;
        rows[i] = render_panel(options, scene, &reference, FIGURE_DEPTH[i], options->fresnel,
                               PIXEL_SUBPIXELS, name, &result);
        measure_image_mean(&result.image, &result.average_std_error, &means[i], &errors[i]);
        images[i] = result.image;
        image_free(&result.std_error);
        image_free(&result.average_std_error);
        snprintf(crop_captions[i], sizeof crop_captions[i],
                 "the mirror wall showing the glass sphere\ndepth %d, enlarged %d times",
                 FIGURE_DEPTH[i], CROP_SCALE);
    }
    const char *titles[] = {"Figure 9, left", "Figure 9, right"};
    experiment_write_panels(options, "ch04_figure9", images, rows, titles, 2);
    const char *crop_list[] = {crop_captions[0], crop_captions[1]};
    int width = images[0].width, height = images[0].height;
    experiment_write_crops(options, "ch04_figure9_crop", images, crop_list, 2,
                           (int)(CROP_LEFT * width), (int)(CROP_TOP * height),
                           (int)(CROP_SIDE * width + 0.5), CROP_SCALE);
    experiment_write_table(options, "ch04_table", rows, 2);
    printf("mean radiance of the image:\n  full depth (reference) %.5f +- %.5f\n",
           reference.mean, reference.mean_std_error);
    for (int i = 0; i < 2; i++) {
        printf("  depth %d                %.5f +- %.5f   (%+.1f%%, %+.1f standard errors)\n",
               FIGURE_DEPTH[i], means[i], errors[i], 100.0 * (means[i] / reference.mean - 1.0),
               measure_z(means[i], errors[i], reference.mean, reference.mean_std_error));
        image_free(&images[i]);
    }
    measure_reference_free(&reference);
}

/* The angles from 0 to 90 degrees every `step` degrees, with the critical angle leaving
 * glass put in its place among them (so that the kink where total internal reflection
 * sets in is sharp); returns how many. */
static int angles_with_critical(double step, double *angles)
{
    double critical = fresnel_critical_angle(GLASS_IOR, 1.0) * 180.0 / PI;
    int count = 0;
    for (int i = 0; i * step <= 90.0; i++) {
        if (count > 0 && critical > angles[count - 1] && critical < i * step)
            angles[count++] = critical;
        angles[count++] = i * step;
    }
    return count;
}

/* Glass's reflectance at `degrees` of incidence: exact and Schlick entering it, then
 * exact and Schlick leaving it. */
static void reflectances(double degrees, double r[4])
{
    double cos_i = cos(degrees * PI / 180.0);
    r[0] = fresnel_reflectance(cos_i, 1.0, GLASS_IOR);
    r[1] = schlick_reflectance(cos_i, 1.0, GLASS_IOR);
    r[2] = fresnel_reflectance(cos_i, GLASS_IOR, 1.0);
    r[3] = schlick_reflectance(cos_i, GLASS_IOR, 1.0);
}

/* (a) The reflectance curves. The table every 5 degrees, printed and as a CSV, with
 * Schlick's difference from exact; the plot every half degree, Schlick's curves dashed. */
static void fresnel_curves(const Options *options)
{
    double angles[200], table[24][7], r[4];
    int count = angles_with_critical(5.0, angles);
    printf("\nglass reflectance R (n = %.1f), Schlick minus exact; the critical angle "
           "leaving glass is %.2f degrees:\n",
           GLASS_IOR, fresnel_critical_angle(GLASS_IOR, 1.0) * 180.0 / PI);
    printf("  angle   entering: exact  Schlick  differ.   leaving: exact  Schlick  differ.\n");
    for (int i = 0; i < count; i++) {
        reflectances(angles[i], r);
        double *t = table[i];
        t[0] = angles[i];
        t[1] = r[0], t[2] = r[1], t[3] = r[1] - r[0];
        t[4] = r[2], t[5] = r[3], t[6] = r[3] - r[2];
        printf("  %5.2f            %.4f   %.4f  %+.4f            %.4f   %.4f  %+.4f\n", t[0],
               t[1], t[2], t[3], t[4], t[5], t[6]);
    }
    const int decimals[7] = {4, 6, 6, 6, 6, 6, 6};
    experiment_write_numbers(
        options, "ch04_fresnel_curve",
        "angle_degrees,entering_exact,entering_schlick,entering_difference,"
        "leaving_exact,leaving_schlick,leaving_difference",
        &table[0][0], count, 7, decimals);

    const char *labels[4] = {"exact, entering glass", "Schlick, entering glass",
                             "exact, leaving glass", "Schlick, leaving glass"};
    const Vec3 colours[4] = {
        {0.8, 0.0, 0.0}, {1.0, 0.5, 0.0}, {0.0, 0.0, 0.9}, {0.0, 0.6, 0.8}};
    double curves[4][200];
    count = angles_with_critical(0.5, angles);
    for (int i = 0; i < count; i++) {
        reflectances(angles[i], r);
        for (int c = 0; c < 4; c++)
            curves[c][i] = r[c];
    }
    PlotSeries series[4];
    for (int c = 0; c < 4; c++)
        series[c] = (PlotSeries){.label = labels[c],
                                 .x = angles,
                                 .y = curves[c],
                                 .count = count,
                                 .colour = colours[c],
                                 .dashed = c % 2};
    Plot plot = {{"angle of incidence (degrees)", PLOT_LINEAR, 0.0, 90.0, 15.0},
                 {"reflectance R", PLOT_LINEAR, 0.0, 1.0, 0.25},
                 series,
                 4,
                 0.0};
    experiment_write_plot(options, "ch04_fresnel_curve", &plot, 800, 450,
                          "glass reflectance R (n = 1.5) against the angle of incidence:\n"
                          "exact Fresnel (solid) and Schlick's approximation (dashed)");
}

static volatile double timing_sink; /* keeps the timed calls from being optimised away */

/* (b) Nanoseconds per call of `function`, over TIMING_CALLS calls that sweep the
 * incidence cosine over [0, 1], alternately entering and leaving glass. */
static double ns_per_call(double (*function)(double, double, double))
{
    double sum = 0.0;
    double start = stats_now();
    for (int i = 0; i < TIMING_CALLS; i++) {
        double cos_i = ((i / 2) % 1000 + 0.5) / 1000.0;
        sum += i % 2 ? function(cos_i, GLASS_IOR, 1.0) : function(cos_i, 1.0, GLASS_IOR);
    }
    double seconds = stats_now() - start;
    timing_sink = sum;
    return seconds * 1e9 / TIMING_CALLS;
}

/* (b) and (c): what Schlick saves in time and costs in accuracy, the room rendered with
 * each on a quarter-size image against a reference with exact Fresnel. */
static void schlick_against_exact(const Options *options, const Scene *scene)
{
    double schlick_ns = ns_per_call(schlick_reflectance);
    double exact_ns = ns_per_call(fresnel_reflectance);
    printf("\none evaluation (%d calls each): Schlick %.1f ns, exact Fresnel %.1f ns\n",
           TIMING_CALLS, schlick_ns, exact_ns);
    Options small = experiment_quarter_size(options, scene);
    Reference reference;
    reference_for(&small, scene, FRESNEL_DEPTH, FRESNEL_EXACT, &reference);
    TableRow rows[2];
    RenderResult renders[2];
    rows[0] = render_panel(&small, scene, &reference, FRESNEL_DEPTH, FRESNEL_SCHLICK,
                           PIXEL_RANDOM, "ch04_room_schlick", &renders[0]);
    rows[1] = render_panel(&small, scene, &reference, FRESNEL_DEPTH, FRESNEL_EXACT,
                           PIXEL_RANDOM, "ch04_room_exact", &renders[1]);
    printf("\nthe room at %d pixels wide with each, against exact Fresnel:\n", small.size);
    experiment_write_table(options, "ch04_fresnel_table", rows, 2);
    /* The same random numbers in both: their difference is what Schlick changes. */
    double difference, unused;
    measure_error(&renders[0].image, &renders[1].image, &difference, &unused);
    printf("Schlick: %.1f ns per call against %.1f exact; the room took %.2f s against %.2f s "
           "(%+.1f%%); its image differs from exact Fresnel's by RMSE %.5f (in %.2f%% of the "
           "pixels) where the noise makes %.4f.\n",
           schlick_ns, exact_ns, rows[0].seconds, rows[1].seconds,
           100.0 * (rows[0].seconds / rows[1].seconds - 1.0), difference,
           100.0 * measure_changed_fraction(&renders[0].image, &renders[1].image),
           rows[1].rmse);
    render_result_free(&renders[0]);
    render_result_free(&renders[1]);
    measure_reference_free(&reference);
}

int main(int argc, char **argv)
{
    ProgramInfo info = {
        "Chapter 4, Fresnel glass and ray depth: reproduces the report's Figure 9 (depth 3\n"
        "vs 8) and compares Schlick's approximation with the exact Fresnel equations.",
        FLAGS_COMMON | FLAG_SPP | FLAG_SHADOW_RAYS | FLAG_FRESNEL | FLAG_REFERENCE_SPP |
            FLAG_RUNS,
        {.scene = "scenes/room.scene",
         .size = 800,
         .spp = 4,
         .shadow_rays = 1,
         .seed = 1,
         .out = "build/figures",
         .fresnel = FRESNEL_SCHLICK,
         .reference_spp = REFERENCE_SPP,
         .runs = CLI_RUNS},
    };
    Options options;
    Scene scene;
    experiment_start(argc, argv, &info, NEEDS_AREA_LIGHT, &options, &scene);
    figure9(&options, &scene);
    fresnel_curves(&options);
    schlick_against_exact(&options, &scene);
    scene_free(&scene);
    return 0;
}
