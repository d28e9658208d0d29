/* ch04_fresnel.c (chapter 4): Fresnel glass and ray depth (report §3.5.1-3.5.2, §4.4; Figure 9).
 *
 * New concepts (lib/): fresnel (the exact Fresnel reflectance, eqs. 3-5, with the
 * labels R_s and R_p corrected), chosen in glass.c by the path settings. The perfect
 * mirror, Snell's law with total internal reflection, and Schlick's approximation
 * (eqs. 2, 6-7) came in chapter 1; the path tracer's glass has used Schlick since
 * chapter 2.
 *
 * The experiment:
 *   - Figure 9: maximum ray depth 3 vs 8, both measured against the full-depth image.
 *     Cutting paths short loses light (a bias) where light needs many specular bounces:
 *     the glass sphere, and the glass sphere seen in the mirror wall (the report's red
 *     square), which a second figure enlarges. At a few samples per pixel the noise
 *     dominates the RMSE, so the image's mean radiance is printed too: there the bias
 *     stands out against its standard error;
 *   - Schlick vs exact Fresnel: (a) both reflectances over the incidence angle, entering
 *     glass (n = 1.5) and leaving it, as a table and a plot; (b) what one evaluation of
 *     each costs; (c) the room rendered with each on a quarter-size image, against a
 *     reference with exact Fresnel: what Schlick saves in time and costs in accuracy.
 *     Rendered with the same random numbers, the two images differ only where Schlick's
 *     reflectance flipped a path's choice between reflecting and refracting: their
 *     difference is what Schlick changes, free of the noise the two share (an upper
 *     bound on its bias, since each flipped choice adds noise of its own).
 * No Russian roulette in the panels (chapter 6). A reference may use any unbiased
 * estimator of its image; the reference program uses roulette (experiment.h).
 */
#include <stdio.h>

#include "atomic_file.h"
#include "experiment.h"
#include "fresnel.h"
#include "path_direct.h"
#include "plot.h"
#include "schlick.h"
#include "snell.h"

#define GLASS_IOR 1.5
#define TIMING_CALLS 10000000

static const int FIGURE_DEPTH[2] = {3, 8};
enum { FULL_DEPTH = 64, FRESNEL_DEPTH = 8 };

/* The report's red square: the part of the mirror wall that shows the glass sphere, as
 * fractions of the image's width and height (the sphere's mirror image is centred near
 * (0.40, 0.53)), enlarged CROP_SCALE times. */
static const double CROP_LEFT = 0.32, CROP_TOP = 0.445, CROP_SIDE = 0.16;
enum { CROP_SCALE = 3 };

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
    PathSettings path = {.max_depth = depth, .shadow_rays = options->shadow_rays, .fresnel = fresnel};
    char description[64], settings_text[96];
    describe_path(&path, description, sizeof description);
    snprintf(settings_text, sizeof settings_text, "%d spp, %s", options->spp, description);
    RenderSettings settings = experiment_render_settings(options, scene, options->spp, sampling, name);
    return experiment_runs(options, scene, &settings, path_direct_radiance, &path, name,
                           settings_text, reference, 1, result);
}

static Image new_image(int width, int height)
{
    Image image = image_new(width, height);
    if (!image.pixels)
        cli_fail(1, "out of memory for a %d x %d image", width, height);
    return image;
}

/* The crop of the red square, each pixel repeated CROP_SCALE times (nearest neighbour). */
static Image crop_enlarged(const Image *image)
{
    int side = (int)(CROP_SIDE * image->width + 0.5);
    int left = (int)(CROP_LEFT * image->width), top = (int)(CROP_TOP * image->height);
    Image crop = new_image(side * CROP_SCALE, side * CROP_SCALE);
    for (int row = 0; row < crop.height; row++)
        for (int col = 0; col < crop.width; col++)
            image_set(&crop, col, row,
                      image_get(image, left + col / CROP_SCALE, top + row / CROP_SCALE));
    return crop;
}

static double reflectance(FresnelMode mode, double cos_i, double n_i, double n_t)
{
    return mode == FRESNEL_EXACT ? fresnel_reflectance(cos_i, n_i, n_t)
                                 : schlick_reflectance(cos_i, n_i, n_t);
}

/* (a) The table: exact and Schlick reflectance every 5 degrees and at the critical
 * angle, entering glass (air -> glass) and leaving it (glass -> air). */
static void fresnel_curve_table(const Options *options)
{
    double critical = snell_critical_angle(GLASS_IOR, 1.0) * 180.0 / PI;
    double angles[20];
    int count = 0;
    for (int degrees = 0; degrees <= 90; degrees += 5) {
        if (critical > degrees - 5 && critical < degrees)
            angles[count++] = critical;
        angles[count++] = degrees;
    }
    char path[4400];
    experiment_path(options, "ch04_fresnel_curve.csv", path, sizeof path);
    AtomicFile file;
    if (atomic_open(&file, path) != 0)
        cli_fail(1, "cannot write %s", path);
    fprintf(file.file, "angle_degrees,entering_exact,entering_schlick,entering_difference,"
                       "leaving_exact,leaving_schlick,leaving_difference\n");
    printf("\nglass reflectance R (n = %.1f), Schlick minus exact; the critical angle "
           "leaving glass is %.2f degrees:\n", GLASS_IOR, critical);
    printf("  angle   entering: exact  Schlick  differ.   leaving: exact  Schlick  differ.\n");
    for (int i = 0; i < count; i++) {
        double cos_i = cos(angles[i] * PI / 180.0);
        double in_exact = fresnel_reflectance(cos_i, 1.0, GLASS_IOR);
        double in_schlick = schlick_reflectance(cos_i, 1.0, GLASS_IOR);
        double out_exact = fresnel_reflectance(cos_i, GLASS_IOR, 1.0);
        double out_schlick = schlick_reflectance(cos_i, GLASS_IOR, 1.0);
        printf("  %5.2f            %.4f   %.4f  %+.4f            %.4f   %.4f  %+.4f\n",
               angles[i], in_exact, in_schlick, in_schlick - in_exact, out_exact,
               out_schlick, out_schlick - out_exact);
        fprintf(file.file, "%.4f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f\n", angles[i], in_exact,
                in_schlick, in_schlick - in_exact, out_exact, out_schlick,
                out_schlick - out_exact);
    }
    if (atomic_close(&file, 0) != 0)
        cli_fail(1, "cannot write %s", path);
    printf("wrote %s\n", path);
}

/* (a) The same curves as a line plot (plot.h): x the incidence angle from 0 to 90
 * degrees, y the reflectance from 0 to 1. Each curve is sampled every half degree and
 * at the critical angle, so the kink where total internal reflection sets in is drawn
 * sharp; Schlick's curves are dashed. */
static Image fresnel_plot(void)
{
    enum { STEPS = 180, POINTS = STEPS + 2 };
    const struct {
        FresnelMode mode;
        double n_i, n_t;
        const char *label;
        Vec3 colour;
    } curves[] = {
        {FRESNEL_EXACT, 1.0, GLASS_IOR, "exact, entering glass", {0.8, 0.0, 0.0}},
        {FRESNEL_SCHLICK, 1.0, GLASS_IOR, "Schlick, entering glass", {1.0, 0.5, 0.0}},
        {FRESNEL_EXACT, GLASS_IOR, 1.0, "exact, leaving glass", {0.0, 0.0, 0.9}},
        {FRESNEL_SCHLICK, GLASS_IOR, 1.0, "Schlick, leaving glass", {0.0, 0.6, 0.8}},
    };
    enum { CURVES = sizeof curves / sizeof curves[0] };
    double critical = snell_critical_angle(GLASS_IOR, 1.0) * 180.0 / PI;
    double angles[POINTS], r[CURVES][POINTS];
    int count = 0;
    for (int i = 0; i <= STEPS; i++) {
        double degrees = 90.0 * i / STEPS;
        if (count > 0 && critical > angles[count - 1] && critical < degrees)
            angles[count++] = critical;
        angles[count++] = degrees;
    }
    PlotSeries series[CURVES];
    for (int c = 0; c < CURVES; c++) {
        for (int i = 0; i < count; i++)
            r[c][i] = reflectance(curves[c].mode, cos(angles[i] * PI / 180.0), curves[c].n_i,
                                  curves[c].n_t);
        series[c] = (PlotSeries){.label = curves[c].label, .x = angles, .y = r[c], .count = count,
                                 .colour = curves[c].colour, .dashed = curves[c].mode == FRESNEL_SCHLICK};
    }
    Plot plot = {{"angle of incidence (degrees)", PLOT_LINEAR, 0.0, 90.0, 15.0},
                 {"reflectance R", PLOT_LINEAR, 0.0, 1.0, 0.25}, series, CURVES, 0.0};
    Image image = experiment_plot(&plot, 800, 450);
    return image;
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

/* The fraction of pixels that differ between two images of the same size. */
static double changed_fraction(const Image *a, const Image *b)
{
    long pixels = (long)a->width * a->height, changed = 0;
    for (long i = 0; i < pixels; i++)
        changed += a->pixels[3 * i] != b->pixels[3 * i] || a->pixels[3 * i + 1] != b->pixels[3 * i + 1] ||
                   a->pixels[3 * i + 2] != b->pixels[3 * i + 2];
    return (double)changed / pixels;
}

int main(int argc, char **argv)
{
    ProgramInfo info = {
        "Chapter 4, Fresnel glass and ray depth: reproduces the report's Figure 9 (depth 3\n"
        "vs 8) and compares Schlick's approximation with the exact Fresnel equations.",
        FLAGS_COMMON | FLAG_SPP | FLAG_SHADOW_RAYS | FLAG_FRESNEL | FLAG_REFERENCE_SPP | FLAG_RUNS,
        {.scene = "scenes/room.scene", .size = 800, .spp = 4, .shadow_rays = 1, .seed = 1,
         .out = "build/figures", .fresnel = FRESNEL_SCHLICK, .reference_spp = REFERENCE_SPP, .runs = CLI_RUNS},
    };
    Options options;
    Scene scene;
    experiment_start(argc, argv, &info, NEEDS_AREA_LIGHT, &options, &scene);
    Reference reference;
    reference_for(&options, &scene, FULL_DEPTH, options.fresnel, &reference);

    /* Figure 9, and its red square enlarged; the mean radiance says how much light the
     * bounces beyond the depth limit would have added. */
    double reference_mean = reference.mean, reference_error = reference.mean_std_error;
    TableRow rows[2];
    Image images[2], crops[2];
    double means[2], errors[2];
    char captions[2][256], crop_captions[2][256];
    for (int i = 0; i < 2; i++) {
        char name[64];
        snprintf(name, sizeof name, "ch04_figure9_depth%d", FIGURE_DEPTH[i]);
        RenderResult result;
        rows[i] = render_panel(&options, &scene, &reference, FIGURE_DEPTH[i], options.fresnel,
                               PIXEL_SUBPIXELS, name, &result);
        measure_image_mean(&result.image, &result.average_std_error, &means[i], &errors[i]);
        images[i] = result.image;
        image_free(&result.std_error);
        image_free(&result.average_std_error);
        experiment_caption(&rows[i], i == 0 ? "Figure 9, left" : "Figure 9, right",
                           captions[i], sizeof captions[i]);
        crops[i] = crop_enlarged(&images[i]);
        snprintf(crop_captions[i], sizeof crop_captions[i],
                 "the mirror wall showing the glass sphere\ndepth %d, enlarged %d times",
                 FIGURE_DEPTH[i], CROP_SCALE);
    }
    const char *figure_captions[] = {captions[0], captions[1]};
    const char *crop_figure_captions[] = {crop_captions[0], crop_captions[1]};
    experiment_write_figure(&options, "ch04_figure9", images, figure_captions, 2, PANEL_EXPOSURE);
    experiment_write_figure(&options, "ch04_figure9_crop", crops, crop_figure_captions, 2,
                            PANEL_EXPOSURE);
    experiment_write_table(&options, "ch04_table", rows, 2);
    printf("mean radiance of the image:\n  full depth (reference) %.5f +- %.5f\n",
           reference_mean, reference_error);
    for (int i = 0; i < 2; i++) {
        double z = (means[i] - reference_mean) /
                   sqrt(errors[i] * errors[i] + reference_error * reference_error);
        printf("  depth %d                %.5f +- %.5f   (%+.1f%%, %+.1f standard errors)\n",
               FIGURE_DEPTH[i], means[i], errors[i], 100.0 * (means[i] / reference_mean - 1.0), z);
        image_free(&images[i]);
        image_free(&crops[i]);
    }
    measure_reference_free(&reference);

    /* (a) The reflectance curves. */
    fresnel_curve_table(&options);
    Image plot = fresnel_plot();
    const char *plot_caption[] = {
        "glass reflectance R (n = 1.5) against the angle of incidence:\n"
        "exact Fresnel (solid) and Schlick's approximation (dashed)"};
    experiment_write_figure(&options, "ch04_fresnel_curve", &plot, plot_caption, 1, 1.0);
    image_free(&plot);

    /* (b) The cost of one evaluation. */
    double schlick_ns = ns_per_call(schlick_reflectance);
    double exact_ns = ns_per_call(fresnel_reflectance);
    printf("\none evaluation (%d calls each): Schlick %.1f ns, exact Fresnel %.1f ns\n",
           TIMING_CALLS, schlick_ns, exact_ns);

    /* (c) The room with each, against the exact reference, on a quarter-size image. */
    Options sweep_options = experiment_quarter_size(&options);
    reference_for(&sweep_options, &scene, FRESNEL_DEPTH, FRESNEL_EXACT, &reference);
    const FresnelMode modes[2] = {FRESNEL_SCHLICK, FRESNEL_EXACT};
    TableRow fresnel_rows[2];
    RenderResult renders[2];
    for (int i = 0; i < 2; i++)
        fresnel_rows[i] = render_panel(&sweep_options, &scene, &reference, FRESNEL_DEPTH,
                                       modes[i], PIXEL_RANDOM,
                                       i == 0 ? "ch04_room_schlick" : "ch04_room_exact",
                                       &renders[i]);
    printf("\nthe room at %d pixels wide with each, against exact Fresnel:\n", sweep_options.size);
    experiment_write_table(&options, "ch04_fresnel_table", fresnel_rows, 2);
    /* The same random numbers in both: their difference is what Schlick changes. */
    double difference, unused;
    measure_error(&renders[0].image, &renders[1].image, &difference, &unused);
    const TableRow *schlick = &fresnel_rows[0], *exact = &fresnel_rows[1];
    printf("Schlick: %.1f ns per call against %.1f exact; the room took %.2f s against %.2f s "
           "(%+.1f%%); its image differs from exact Fresnel's by RMSE %.5f (in %.2f%% of the "
           "pixels) where the noise makes %.4f.\n",
           schlick_ns, exact_ns, schlick->seconds, exact->seconds,
           100.0 * (schlick->seconds / exact->seconds - 1.0), difference,
           100.0 * changed_fraction(&renders[0].image, &renders[1].image), exact->rmse);
    render_result_free(&renders[0]);
    render_result_free(&renders[1]);

    measure_reference_free(&reference);
    scene_free(&scene);
    return 0;
}
