/* render_check.c (bench, chapter 2): an estimator's image against the solution's. See
 * render_check.h. */
#include "render_check.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "figure.h"
#include "font.h"
#include "measure.h"
#include "renderer.h"
#include "scene_file.h"

#define ZOOM 12

const char render_check_room[] =
    "camera  0 -3.2 0   -1 -2 -1   1 -2 -1   -1 -2 1\n"
    "material white lambert 0.7 0.7 0.7\n"
    "material red   lambert 0.7 0.15 0.15\n"
    "material green lambert 0.15 0.7 0.15\n"
    "material lamp  light   4 4 4\n"
    "box white -1.5 -3.5 -1.5   1.5 1.5 1.5\n"
    "quad red   -1.49 -3.5 -1.5   -1.49 1.5 -1.5   -1.49 1.5 1.5   -1.49 -3.5 1.5\n"
    "quad green  1.49 -3.5 -1.5    1.49 -3.5 1.5   1.49 1.5 1.5    1.49 1.5 -1.5\n"
    "quad lamp  -1 -1 1.49   -1 1 1.49   1 1 1.49   1 -1 1.49\n"
    "sphere white 0.3 0 -0.9 0.6\n";

static int load_scene(const RenderCheck *check, Scene *scene, char *error, size_t size)
{
    return scene_parse(check->scene, strlen(check->scene), "exercise.scene", scene, NULL, error,
                       size);
}

static int render_at(const RenderCheck *check, const Scene *scene, int spp, uint64_t seed,
                     RenderResult *result)
{
    int height = (int)lround(check->width / scene_file_aspect(&scene->camera));
    RenderSettings settings = {
        {check->width, height, spp, PIXEL_RANDOM, seed}, 0, 0, "exercise"};
    return render(scene, &settings, check->estimate, check->settings, result);
}

static void reference_paths(const char *folder, const char *id, char *image, char *se,
                            size_t size)
{
    snprintf(image, size, "%s/exercise-%s-reference.pfm", folder, id);
    snprintf(se, size, "%s/exercise-%s-reference-se.pfm", folder, id);
}

int render_check_reference(const Exercise *e, const char *folder, char *error, size_t size)
{
    Scene scene;
    if (load_scene(e->render, &scene, error, size) != 0)
        return -1;
    RenderResult result;
    int status = render_at(e->render, &scene, e->render->reference_spp, 2, &result);
    scene_free(&scene);
    if (status != 0) {
        snprintf(error, size, "out of memory");
        return -1;
    }
    char image_path[1024], se_path[1024];
    reference_paths(folder, e->id, image_path, se_path, sizeof image_path);
    status = image_write_pfm(&result.image, image_path) == 0 &&
                     image_write_pfm(&result.std_error, se_path) == 0
                 ? 0
                 : -1;
    if (status != 0)
        snprintf(error, size, "cannot write %s", image_path);
    render_result_free(&result);
    return status;
}

/* The image enlarged ZOOM times, pixels as squares. */
static Image zoomed(const Image *image)
{
    Image big = image_new(image->width * ZOOM, image->height * ZOOM);
    for (int row = 0; big.pixels && row < big.height; row++)
        for (int col = 0; col < big.width; col++)
            image_set(&big, col, row, image_get(image, col / ZOOM, row / ZOOM));
    return big;
}

static void write_zmap_picture(Grading *g, const Image *yours, const Image *reference,
                               const Image *zmap, double exposure, const char *verdict)
{
    Image panels[3] = {zoomed(yours), zoomed(reference), zoomed(zmap)};
    /* figure.c tone maps every panel alike; the z-map's colours are made for exposure 1 */
    for (long i = 0; panels[2].pixels && i < 3L * panels[2].width * panels[2].height; i++)
        panels[2].pixels[i] = (float)(panels[2].pixels[i] / exposure);
    char error[256], path[1024], zcaption[512];
    snprintf(zcaption, sizeof zcaption,
             "z = (yours - reference) / sigma:\nred brighter, blue "
             "darker, yellow fails\n%s",
             verdict);
    const char *captions[3] = {"yours", "the solution's reference", zcaption};
    snprintf(path, sizeof path, "%s/exercise-%s-zmap.png", g->out, g->id);
    Font font;
    if (!panels[0].pixels || !panels[1].pixels || !panels[2].pixels)
        grading_note(g, "no picture: out of memory");
    else if (font_load(&font, FONT_PATH, error, sizeof error) != 0)
        grading_note(g, "no picture: %s", error);
    else {
        if (figure_write_png(path, &font, panels, captions, 3, exposure) == 0)
            grading_note(g, "picture: %s", path);
        else
            grading_note(g, "no picture: %s could not be written (%s)", path, strerror(errno));
        font_free(&font);
    }
    for (int i = 0; i < 3; i++)
        image_free(&panels[i]);
}

typedef struct {
    int tests, failing_pixels;
    double level, smallest_p, z;
    int col, row;
} PixelTest;

/* The per-pixel z-test, filling the z-map: each pixel's colour from its channel of
 * largest |z|. */
static PixelTest pixel_test(const RenderResult *yours, const Image *reference, const Image *se,
                            double spp_ratio, double level, Image *zmap)
{
    PixelTest t = {0, 0, level, 1.0, 0.0, -1, -1};
    long pixels = (long)reference->width * reference->height;
    for (long i = 0; i < 3 * pixels; i++) {
        double sb = se->pixels[i], sa = fmax(yours->std_error.pixels[i], sb * spp_ratio);
        double difference = (double)yours->image.pixels[i] - reference->pixels[i];
        if (sa == 0.0 && sb == 0.0 && difference == 0.0)
            continue;
        t.tests++;
    }
    t.level = t.tests > 0 ? -expm1(log1p(-level) / t.tests) : level;
    for (long p = 0; p < pixels; p++) {
        double largest = 0.0, smallest_p = 1.0;
        for (int c = 0; c < 3; c++) {
            long i = 3 * p + c;
            double sb = se->pixels[i], sa = fmax(yours->std_error.pixels[i], sb * spp_ratio);
            double difference = (double)yours->image.pixels[i] - reference->pixels[i];
            double spread = sqrt(sa * sa + sb * sb);
            double z = spread > 0.0
                           ? difference / spread
                           : (difference == 0.0 ? 0.0 : copysign(INFINITY, difference));
            double pvalue = erfc(fabs(z) / sqrt(2.0));
            if (fabs(z) > fabs(largest))
                largest = z;
            smallest_p = fmin(smallest_p, pvalue);
            if (pvalue < t.smallest_p) {
                t.smallest_p = pvalue;
                t.z = z;
                t.col = (int)(p % reference->width);
                t.row = (int)(p / reference->width);
            }
        }
        double v = fmin(1.0, fabs(largest) / 5.0);
        Vec3 colour = largest > 0 ? vec3(v, 0.1 * v, 0.1 * v) : vec3(0.1 * v, 0.3 * v, v);
        if (smallest_p < t.level) {
            t.failing_pixels++;
            colour = vec3(1.0, 0.9, 0.1);
        }
        image_set(zmap, (int)(p % reference->width), (int)(p / reference->width), colour);
    }
    return t;
}

/* A count the probe sends, as a whole number the judge can hold. */
static uint64_t ask_count(Grading *g, uint64_t count)
{
    double value = grading_ask(g, (double)count);
    return value >= 0.0 && value < 1e18 ? (uint64_t)value : 0;
}

/* Whether every pixel value is finite, and every standard error also >= 0. */
static int finite_render(const RenderResult *r)
{
    for (long i = 0; i < 3L * r->image.width * r->image.height; i++) {
        float se = r->std_error.pixels[i], average = r->average_std_error.pixels[i];
        if (!isfinite(r->image.pixels[i]) || !isfinite(se) || se < 0.0f || !isfinite(average) ||
            average < 0.0f)
            return 0;
    }
    return 1;
}

/* The probe renders with the student's code and sends the result; the judge receives it
 * (size, pixels, standard errors, sample counts). Returns 0, or -1 after failing. */
static int ask_render(Grading *g, const RenderCheck *check, RenderResult *yours)
{
    memset(yours, 0, sizeof *yours);
    Scene scene;
    char error[512];
    if (load_scene(check, &scene, error, sizeof error) != 0) {
        grading_fail(g, "the exercise's scene does not load: %s", error);
        return -1;
    }
    int status = grading_probing(g)
                     ? render_at(check, &scene, check->spp, grading_stream(g, 1), yours)
                     : 0;
    int width = check->width, height = (int)lround(width / scene_file_aspect(&scene.camera));
    scene_free(&scene);
    if (grading_ask(g, status) != 0.0) {
        grading_fail(g, "out of memory while rendering");
        return -1;
    }
    double width_got = grading_ask(g, yours->image.width);
    double height_got = grading_ask(g, yours->image.height);
    if (width_got != width || height_got != height) {
        grading_fail(g, "the render is %g x %g pixels, where %d x %d were asked for", width_got,
                     height_got, width, height);
        return -1;
    }
    if (!grading_probing(g)) {
        yours->image = image_new(width, height);
        yours->std_error = image_new(width, height);
        yours->average_std_error = image_new(width, height);
    }
    if (!yours->image.pixels || !yours->std_error.pixels || !yours->average_std_error.pixels) {
        render_result_free(yours);
        grading_fail(g, "out of memory");
        return -1;
    }
    long values = 3L * width * height;
    grading_ask_floats(g, yours->image.pixels, values);
    grading_ask_floats(g, yours->std_error.pixels, values);
    grading_ask_floats(g, yours->average_std_error.pixels, values);
    yours->samples = ask_count(g, yours->samples);
    yours->nonfinite = ask_count(g, yours->nonfinite);
    if (!g->failed && !finite_render(yours))
        grading_fail(g, "the render's pixels are not all finite numbers, nor its standard "
                        "errors all >= 0");
    if (!g->failed)
        return 0;
    render_result_free(yours);
    return -1;
}

int grading_render(Grading *g, const RenderCheck *check, double level, const char *hint)
{
    RenderResult yours;
    if (ask_render(g, check, &yours) != 0)
        return 0;
    if (grading_probing(g)) {
        render_result_free(&yours);
        return 1;
    }
    char error[512], image_path[1024], se_path[1024];
    reference_paths(g->references, g->id, image_path, se_path, sizeof image_path);
    Image reference = {0, 0, NULL}, se = {0, 0, NULL};
    int ok = 0;
    if (image_read_pfm(image_path, &reference, error, sizeof error) != 0 ||
        image_read_pfm(se_path, &se, error, sizeof error) != 0) {
        grading_fail(g,
                     "no reference to compare with (%s): check through make "
                     "check-exercise-chapterN, which renders it",
                     error);
        goto free_reference;
    }
    if (yours.image.width != reference.width || yours.image.height != reference.height) {
        grading_fail(g, "the reference has another size: render it again");
        goto free_reference;
    }
    grading_note(g, "rendered %d x %d pixels at %d samples per pixel; reference at %d",
                 reference.width, reference.height, check->spp, check->reference_spp);
    if (yours.nonfinite > 0) {
        char count[32];
        grading_fail(g,
                     "%s of %s samples were NaN or infinite (a 0 / 0, the sqrt of a negative "
                     "number, a division by a zero pdf?): %s",
                     grading_count((double)yours.nonfinite, count, sizeof count),
                     grading_count((double)yours.samples, error, sizeof error), hint);
        goto free_reference;
    }
    double mean, mean_se, ref_mean, ref_se;
    measure_image_mean(&yours.image, &yours.average_std_error, &mean, &mean_se);
    measure_image_mean(&reference, &se, &ref_mean, &ref_se);
    Image zmap = image_new(reference.width, reference.height);
    if (!zmap.pixels) {
        grading_fail(g, "out of memory");
        goto free_reference;
    }
    /* Under the hypothesis that the student's estimator is the solution's, a pixel's
     * standard error is the reference's times sqrt(reference_spp / spp): a pixel whose
     * few samples all missed the light does not claim to be exact. */
    double spp_ratio = sqrt((double)check->reference_spp / check->spp);
    PixelTest t = pixel_test(&yours, &reference, &se, spp_ratio, level, &zmap);
    double combined = sqrt(mean_se * mean_se + ref_se * ref_se);
    double mean_z = (mean - ref_mean) / combined;
    double share =
        t.tests > 0 ? (double)t.failing_pixels / (reference.width * reference.height) : 0.0;
    char ptext[32], verdict[200];
    grading_p(t.smallest_p, ptext, sizeof ptext);
    grading_note(g, "image mean %.5f +- %.5f, the reference's %.5f +- %.5f (z = %+.1f)", mean,
                 mean_se, ref_mean, ref_se, mean_z);
    grading_note(g,
                 "per-pixel z-test: %d values, smallest %s (z = %+.1f at pixel %d,%d), Sidak "
                 "level %.2g; %d pixels of %d fail",
                 t.tests, ptext, t.z, t.col, t.row, t.level, t.failing_pixels,
                 reference.width * reference.height);
    /* the image means: within 4 standard errors, or the z of the level when it is larger */
    double mean_limit = fmax(4.0, grading_z(level));
    ok = t.smallest_p >= t.level && fabs(mean_z) <= mean_limit;
    snprintf(verdict, sizeof verdict, "%d of %d pixels fail; mean %+.1f%%: %s",
             t.failing_pixels, reference.width * reference.height,
             ref_mean > 0 ? 100.0 * (mean / ref_mean - 1.0) : 0.0, ok ? "agree" : "DISAGREE");
    double exposure = ref_mean > 0.0 ? 0.35 / ref_mean : 1.0;
    write_zmap_picture(g, &yours.image, &reference, &zmap, exposure, verdict);
    image_free(&zmap);
    if (!ok) {
        char brightness[200];
        if (mean == 0.0)
            snprintf(brightness, sizeof brightness, "the image is black");
        else if (fabs(mean_z) > mean_limit)
            snprintf(
                brightness, sizeof brightness,
                "the image is %.0f%% too %s (mean %.4f where the reference has %.4f +- %.4f)",
                100.0 * fabs(mean / ref_mean - 1.0), mean > ref_mean ? "bright" : "dark", mean,
                ref_mean, ref_se);
        else
            snprintf(brightness, sizeof brightness,
                     "the image's mean is right, but not its "
                     "pixels");
        grading_fail(g,
                     "%s; the per-pixel z-test fails at %.0f%% of pixels (%s, level %.2g): "
                     "see exercise-%s-zmap.png: %s",
                     brightness, 100.0 * share, ptext, t.level, g->id, hint);
    }
free_reference:
    render_result_free(&yours);
    image_free(&reference);
    image_free(&se);
    return ok;
}
