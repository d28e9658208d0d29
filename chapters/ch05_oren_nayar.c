/* ch05_oren_nayar.c (chapter 5): the Oren-Nayar reflector (report §3.5.4, §4.5; Figure 10).
 *
 * New concepts (lib/): oren_nayar (eqs. 13-14 with their corrections:
 * A = 1 - sigma^2 / (2 (sigma^2 + 0.33)), and tan(beta) where the report has sin(beta)).
 * The experiment (docs/chapter5.md), on scenes/oren_nayar.scene, a rough sphere beside a
 * Lambertian one lit from the viewer: Figure 10; a sweep of sigma on a quarter-size image;
 * and the number that says "flat", each sphere's brightness at 80% of its radius over
 * that at its centre, on the references, beside eq. 13's for a light at the eye.
 */
#include <stdio.h>

#include "experiment.h"
#include "oren_nayar.h"
#include "path_direct.h"
#include "scene_file.h"
#include "view.h"

static const double SIGMAS[] = {0.0, 0.25, 0.5, 1.0};
enum {
    SIGMA_COUNT = sizeof SIGMAS / sizeof SIGMAS[0]
};
#define RIM_FRACTION 0.8

/* The reference for the scene with the roughness of `rough` set to `sigma`. */
static void reference_for(const Options *options, const Scene *scene, double sigma,
                          Reference *reference)
{
    PathSettings path = {.max_depth = options->depth, .shadow_rays = options->shadow_rays};
    experiment_path_reference(options, scene, &path, "rough", sigma, reference);
}

/* Render one panel into a table row; its image stays in *image. */
static TableRow render_panel(const Options *options, const Scene *scene,
                             const Reference *reference, double sigma, PixelSampling sampling,
                             const char *name, Image *image)
{
    PathSettings path = {.max_depth = options->depth, .shadow_rays = options->shadow_rays};
    char settings_text[96];
    snprintf(settings_text, sizeof settings_text, "%d spp, M=%d depth=%d, sigma=%g",
             options->spp, options->shadow_rays, options->depth, sigma);
    return experiment_path_row(options, scene, path_direct_radiance, &path, options->spp,
                               sampling, name, settings_text, reference, image);
}

typedef struct {
    double value, error; /* a brightness or a ratio, and its standard error */
} Measured;

/* The reference's brightness (the mean of the channels) within `half` pixels of (col, row). */
static Measured brightness(const Reference *reference, double col, double row, int half)
{
    Measured m;
    measure_window_mean(&reference->image, &reference->std_error, (int)col, (int)row, half,
                        &m.value, &m.error);
    return m;
}

/* Brightness at RIM_FRACTION of the sphere's radius, left and right of its centre
 * (averaged), over the brightness at its centre. The rim points are found by
 * projecting the centre moved sideways, perpendicular to the line of sight. */
static Measured rim_to_centre(const Scene *scene, const Reference *reference,
                              const Sphere *sphere)
{
    const Camera *camera = &scene->camera;
    int width = reference->image.width, height = reference->image.height;
    Vec3 sight = vec3_normalize(vec3_sub(sphere->center, camera->eye));
    Vec3 sideways = vec3_sub(camera->right, vec3_scale(sight, vec3_dot(camera->right, sight)));
    Vec3 offset = vec3_scale(vec3_normalize(sideways), RIM_FRACTION * sphere->radius);
    double col, row, left_col, left_row, right_col, right_row;
    view_position(camera, width, height, sphere->center, &col, &row);
    view_position(camera, width, height, vec3_sub(sphere->center, offset), &left_col,
                  &left_row);
    view_position(camera, width, height, vec3_add(sphere->center, offset), &right_col,
                  &right_row);
    double radius_pixels = fabs(right_col - left_col) / (2.0 * RIM_FRACTION);
    int half = (int)(radius_pixels / 10.0); /* a window small beside the sphere */
    Measured centre = brightness(reference, col, row, half);
    Measured left = brightness(reference, left_col, left_row, half);
    Measured right = brightness(reference, right_col, right_row, half);
    Measured rim = {(left.value + right.value) / 2.0, hypot(left.error, right.error) / 2.0};
    double ratio = rim.value / centre.value;
    return (Measured){ratio, ratio * hypot(rim.error / rim.value, centre.error / centre.value)};
}

/* Eq. 13 with the light at the eye: both directions at theta from the normal, in the
 * same plane, so the ratio to the centre (theta = 0) is cos theta (A + B sin theta
 * tan theta) / A. */
static double eye_lit_ratio(double sigma)
{
    double sin_theta = RIM_FRACTION, cos_theta = sqrt(1.0 - sin_theta * sin_theta);
    double a = oren_nayar_a(sigma), b = oren_nayar_b(sigma);
    return cos_theta * (a + b * sin_theta * (sin_theta / cos_theta)) / a;
}

/* The first sphere of material `rough` and the first Lambertian sphere, to compare;
 * exit 2 when the scene lacks either. */
static void find_spheres(const Options *options, const Scene *scene, int rough,
                         const Sphere **rough_sphere, const Sphere **lambert_sphere)
{
    *rough_sphere = *lambert_sphere = NULL;
    for (int i = 0; i < scene->sphere_count; i++) {
        const Sphere *s = &scene->spheres[i];
        if (!*rough_sphere && s->material == rough)
            *rough_sphere = s;
        if (!*lambert_sphere && scene->materials[s->material].kind == MATERIAL_LAMBERT)
            *lambert_sphere = s;
    }
    if (!*rough_sphere || !*lambert_sphere)
        cli_fail(2,
                 "%s:%d: no sphere of material 'rough', or no Lambertian sphere: %s "
                 "compares the two",
                 options->scene, options->scene_lines, cli_program);
}

int main(int argc, char **argv)
{
    /* Twice the other chapters' reference samples: this image's noise is in its paths,
     * not at its edges, so the reference's sub-pixels gain nothing here. */
    ProgramInfo info = {
        "Chapter 5, the Oren-Nayar reflector: reproduces the report's Figure 10 (a rough\n"
        "sphere beside a Lambertian one) and sweeps the roughness sigma.",
        FLAGS_COMMON | FLAG_SPP | FLAG_SHADOW_RAYS | FLAG_REFERENCE_SPP | FLAG_RUNS,
        {.scene = "scenes/oren_nayar.scene",
         .size = 800,
         .spp = 16,
         .shadow_rays = 4,
         .depth = 8,
         .seed = 1,
         .out = "build/figures",
         .reference_spp = 2 * REFERENCE_SPP,
         .runs = CLI_RUNS},
    };
    Options options;
    Scene scene;
    experiment_start(argc, argv, &info, NEEDS_AREA_LIGHT, &options, &scene);
    int rough = scene_file_material(&scene, "rough");
    if (rough < 0 || scene.materials[rough].kind != MATERIAL_OREN_NAYAR)
        cli_fail(2, "%s:%d: no oren_nayar material named 'rough': %s sweeps its sigma",
                 options.scene, options.scene_lines, cli_program);
    const Sphere *rough_sphere, *lambert_sphere;
    find_spheres(&options, &scene, rough, &rough_sphere, &lambert_sphere);

    /* Figure 10: the scene as it is. */
    double file_sigma = scene.materials[rough].sigma;
    Reference reference;
    reference_for(&options, &scene, file_sigma, &reference);
    Image image;
    TableRow row = render_panel(&options, &scene, &reference, file_sigma, PIXEL_SUBPIXELS,
                                "ch05_rough_and_lambert", &image);
    const char *figure_title[] = {"Figure 10: Oren-Nayar | Lambert"};
    experiment_write_panels(&options, "ch05_figure10", &image, &row, figure_title, 1);
    experiment_write_table(&options, "ch05_table", &row, 1);
    image_free(&image);
    measure_reference_free(&reference);

    /* The sweep of sigma, each against its own reference, on a quarter-size image. */
    Options sweep_options = experiment_quarter_size(&options, &scene);
    TableRow rows[SIGMA_COUNT];
    Image images[SIGMA_COUNT];
    char titles[SIGMA_COUNT][64];
    const char *title_list[SIGMA_COUNT];
    Measured rough_ratio[SIGMA_COUNT], lambert_ratio[SIGMA_COUNT];
    for (int i = 0; i < SIGMA_COUNT; i++) {
        scene.materials[rough].sigma = SIGMAS[i];
        reference_for(&sweep_options, &scene, SIGMAS[i], &reference);
        char name[64];
        snprintf(name, sizeof name, "ch05_sigma%g", SIGMAS[i]);
        snprintf(titles[i], sizeof titles[i], "sigma = %g rad", SIGMAS[i]);
        title_list[i] = titles[i];
        rows[i] = render_panel(&sweep_options, &scene, &reference, SIGMAS[i], PIXEL_RANDOM,
                               name, &images[i]);
        rough_ratio[i] = rim_to_centre(&scene, &reference, rough_sphere);
        lambert_ratio[i] = rim_to_centre(&scene, &reference, lambert_sphere);
        measure_reference_free(&reference);
    }
    experiment_write_panels(&options, "ch05_sigma_sweep", images, rows, title_list,
                            SIGMA_COUNT);
    printf("\nsweep of sigma at %d pixels wide:\n", sweep_options.size);
    experiment_write_table(&options, "ch05_sigma_sweep", rows, SIGMA_COUNT);

    printf("\nbrightness at %.0f%% of the radius over the brightness at the centre (on the "
           "references):\n  sigma    rough sphere        Lambertian sphere   eq. 13, light at "
           "the eye\n",
           100.0 * RIM_FRACTION);
    for (int i = 0; i < SIGMA_COUNT; i++) {
        printf("  %-5g    %.3f +- %.3f     %.3f +- %.3f       %.3f\n", SIGMAS[i],
               rough_ratio[i].value, rough_ratio[i].error, lambert_ratio[i].value,
               lambert_ratio[i].error, eye_lit_ratio(SIGMAS[i]));
        image_free(&images[i]);
    }

    scene_free(&scene);
    return 0;
}
