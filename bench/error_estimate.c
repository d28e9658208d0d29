/* error_estimate.c (bench, chapter 7): the error from the samples' two halves, and the
 * render that stops at a target error or a time limit. See error_estimate.h. */
#include "error_estimate.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const RelativeError NOT_MEASURED = {NAN, NAN};

static int same_size(const Image *a, const Image *b)
{
    return a->width == b->width && a->height == b->height;
}

/* Mean and standard error over pixels of each pixel's channels' terms summed, / 3:
 * the relative MSE over pixels and channels. */
typedef struct {
    double sum, sum_squares;
    long pixels;
} PixelTerms;

static void pixel_terms_add(PixelTerms *terms, double pixel_sum)
{
    terms->sum += pixel_sum;
    terms->sum_squares += pixel_sum * pixel_sum;
    terms->pixels++;
}

static RelativeError pixel_terms_finish(const PixelTerms *terms)
{
    double n = (double)terms->pixels, mean = terms->sum / n;
    double variance = n > 1 ? fmax(terms->sum_squares - n * mean * mean, 0.0) / (n - 1) : 0.0;
    return (RelativeError){mean / 3.0, sqrt(variance / n) / 3.0};
}

RelativeError error_estimate_halves(const Image *a, const Image *b)
{
    if (!same_size(a, b))
        return NOT_MEASURED;
    PixelTerms terms = {0};
    long pixels = (long)a->width * a->height;
    for (long p = 0; p < pixels; p++) {
        double pixel_sum = 0.0;
        for (int c = 0; c < 3; c++) {
            double x = a->pixels[3 * p + c], y = b->pixels[3 * p + c];
            double half_difference = (x - y) / 2.0, mean = (x + y) / 2.0;
            pixel_sum += half_difference * half_difference / (mean * mean + 0.01);
        }
        pixel_terms_add(&terms, pixel_sum);
    }
    return pixel_terms_finish(&terms);
}

double error_allocation_gain(const Image *image, const Image *std_error)
{
    if (!same_size(image, std_error))
        return NAN;
    double sum = 0.0, sum_of_roots = 0.0;
    long pixels = (long)image->width * image->height;
    for (long p = 0; p < pixels; p++) {
        double variance = 0.0;
        for (int c = 0; c < 3; c++) {
            double f = image->pixels[3 * p + c], se = std_error->pixels[3 * p + c];
            variance += se * se / (f * f + 0.01) / 3.0;
        }
        sum += variance;
        sum_of_roots += sqrt(variance);
    }
    if (!(sum > 0.0))
        return NAN;
    double mean_root = sum_of_roots / pixels;
    return sum / pixels / (mean_root * mean_root);
}

RelativeError error_against_reference(const Image *image, const Reference *reference)
{
    if (!same_size(image, &reference->image) || !same_size(image, &reference->std_error))
        return NOT_MEASURED;
    PixelTerms terms = {0};
    long pixels = (long)image->width * image->height;
    for (long p = 0; p < pixels; p++) {
        double pixel_sum = 0.0;
        for (int c = 0; c < 3; c++) {
            double x = image->pixels[3 * p + c], r = reference->image.pixels[3 * p + c];
            double se = reference->std_error.pixels[3 * p + c];
            pixel_sum += ((x - r) * (x - r) - se * se) / (r * r + 0.01);
        }
        pixel_terms_add(&terms, pixel_sum);
    }
    return pixel_terms_finish(&terms);
}

double error_percent(double rel_mse) { return 100.0 * sqrt(fmax(rel_mse, 0.0)); }

double error_percent_std_error(const RelativeError *error)
{
    return error->rel_mse > 0.0 ? 100.0 * error->std_error / (2.0 * sqrt(error->rel_mse)) : NAN;
}

int half_images_begin(HalfImages *halves, int width, int height)
{
    *halves = (HalfImages){{image_new(width, height), image_new(width, height)}, {0, 0}, 0};
    if (halves->sum[0].pixels && halves->sum[1].pixels)
        return 0;
    half_images_free(halves);
    return -1;
}

void half_images_add(HalfImages *halves, const Image *pass, double samples)
{
    Image *sum = &halves->sum[halves->passes % 2];
    long values = 3L * sum->width * sum->height;
    for (long i = 0; i < values; i++)
        sum->pixels[i] += (float)(samples * pass->pixels[i]);
    halves->samples[halves->passes % 2] += samples;
    halves->passes++;
}

/* Half h's mean into image. */
static void half_mean(const HalfImages *halves, int h, Image *image)
{
    long values = 3L * image->width * image->height;
    for (long i = 0; i < values; i++)
        image->pixels[i] = (float)(halves->sum[h].pixels[i] / halves->samples[h]);
}

RelativeError half_images_estimate(const HalfImages *halves)
{
    if (halves->samples[0] <= 0.0 || halves->samples[1] <= 0.0)
        return NOT_MEASURED;
    Image a = image_new(halves->sum[0].width, halves->sum[0].height),
          b = image_new(halves->sum[0].width, halves->sum[0].height);
    RelativeError estimate = NOT_MEASURED;
    if (a.pixels && b.pixels) {
        half_mean(halves, 0, &a);
        half_mean(halves, 1, &b);
        estimate = error_estimate_halves(&a, &b);
    }
    image_free(&a);
    image_free(&b);
    return estimate;
}

void half_images_mean(const HalfImages *halves, Image *image)
{
    double samples = halves->samples[0] + halves->samples[1];
    long values = 3L * image->width * image->height;
    for (long i = 0; i < values; i++)
        image->pixels[i] =
            (float)((halves->sum[0].pixels[i] + halves->sum[1].pixels[i]) / samples);
}

void half_images_free(HalfImages *halves)
{
    image_free(&halves->sum[0]);
    image_free(&halves->sum[1]);
}

int target_should_stop(const TargetSettings *target, const RelativeError *estimate, int passes,
                       double seconds, double spp, int *next_spp, TargetStop *stop)
{
    if (target->target_error > 0.0 &&
        sqrt(estimate->rel_mse) <= target->target_error) { /* NaN: not yet */
        *stop = TARGET_REACHED;
        return 1;
    }
    if (target->max_passes > 0 && passes + 2 > target->max_passes) {
        *stop = TARGET_MOST_PASSES;
        return 1;
    }
    int wanted = target->first_spp;
    if (target->grow && (int)(spp / 16.0) > wanted)
        wanted = (int)(spp / 16.0); /* a pair of them: an eighth of the samples so far */
    if (target->time_limit > 0.0 && spp > 0.0) {
        double per_sample = seconds / spp, left = target->time_limit - seconds;
        double fits = floor(left / (2.0 * per_sample));
        if (fits < wanted)
            wanted = target->grow ? (int)fmax(fits, 0.0) : 0;
        if (wanted < 1) {
            *stop = TARGET_TIME_UP;
            return 1;
        }
    }
    *next_spp = wanted;
    return 0;
}

const char *target_stop_name(TargetStop stop)
{
    switch (stop) {
    case TARGET_REACHED:
        return "reached";
    case TARGET_TIME_UP:
        return "time up";
    case TARGET_MOST_PASSES:
        return "most passes done";
    default:
        return "interrupted";
    }
}

/* The spread of alike passes as each pixel's standard error, or else |A - B| / 2. */
static void standard_errors(const HalfImages *halves, const PixelSum *passes, int alike,
                            RenderResult *r)
{
    if (alike) { /* the passes' mean it writes is the halves' */
        pixel_sums_finish(passes, r);
        return;
    }
    long pixels = (long)r->image.width * r->image.height;
    for (long p = 0; p < pixels; p++) {
        double grey = 0.0;
        for (int c = 0; c < 3; c++) {
            double a = halves->sum[0].pixels[3 * p + c] / halves->samples[0];
            double b = halves->sum[1].pixels[3 * p + c] / halves->samples[1];
            r->std_error.pixels[3 * p + c] = (float)(fabs(a - b) / 2.0);
            grey += (a - b) / 6.0;
        }
        for (int c = 0; c < 3; c++)
            r->average_std_error.pixels[3 * p + c] = (float)fabs(grey);
    }
}

int render_to_target(const Scene *scene, const RenderSettings *settings, Estimator estimate,
                     const void *estimator_settings, const TargetSettings *target,
                     TargetResult *result)
{
    if (!(target->target_error > 0.0 || target->time_limit > 0.0 || target->max_passes > 0) ||
        target->first_spp < 1)
        return -1;
    int width = settings->image.width, height = settings->image.height;
    TargetResult t = {.estimate = NOT_MEASURED};
    HalfImages halves;
    PixelSum *passes =
        calloc((size_t)width * height, sizeof *passes); /* of the passes' means */
    if (!passes || half_images_begin(&halves, width, height) != 0) {
        free(passes);
        return -1;
    }
    RenderSettings pass = *settings;
    char label[160];
    pass.label = label;
    pass.image.spp = target->first_spp;
    double start = stats_now();
    int alike = 1, status = 0;
    for (;;) {
        t.passes++;
        pass.image.seed = rng_hash(settings->image.seed ^ rng_hash((uint64_t)t.passes));
        snprintf(label, sizeof label, "%s, pass %d",
                 settings->label ? settings->label : "render", t.passes);
        RenderResult one;
        if (render(scene, &pass, estimate, estimator_settings, &one) != 0) {
            status = -1;
            break;
        }
        t.render.threads = one.threads;
        ray_counts_add(&t.render.rays, one.rays);
        t.render.samples += one.samples;
        t.render.nonfinite += one.nonfinite;
        if (one.interrupted) {
            render_result_free(&one);
            t.passes--;
            t.render.interrupted = 1;
            t.stop = TARGET_INTERRUPTED;
            break;
        }
        half_images_add(&halves, &one.image, pass.image.spp);
        for (long p = 0; p < (long)width * height; p++) {
            const float *x = one.image.pixels + 3 * p;
            pixel_sum_add(&passes[p], vec3(x[0], x[1], x[2]));
        }
        render_result_free(&one);
        if (t.passes % 2 == 1)
            continue;
        t.estimate = half_images_estimate(&halves);
        double spp = halves.samples[0] + halves.samples[1];
        int next_spp;
        if (target_should_stop(target, &t.estimate, t.passes, stats_now() - start, spp,
                               &next_spp, &t.stop))
            break;
        alike = alike && next_spp == pass.image.spp;
        pass.image.spp = next_spp;
    }
    if (status == 0 && halves.passes >= 2) {
        t.render.image = image_new(width, height);
        t.render.std_error = image_new(width, height);
        t.render.average_std_error = image_new(width, height);
        if (t.render.image.pixels && t.render.std_error.pixels &&
            t.render.average_std_error.pixels) {
            half_images_mean(&halves, &t.render.image);
            standard_errors(&halves, passes, alike, &t.render);
        } else {
            render_result_free(&t.render);
            status = -1;
        }
    } else if (status == 0) { /* interrupted in the first pair: nothing to show */
        t.render.image = image_new(width, height);
        t.render.std_error = image_new(width, height);
        t.render.average_std_error = image_new(width, height);
    }
    t.render.seconds = stats_now() - start;
    half_images_free(&halves);
    free(passes);
    if (status == 0)
        *result = t;
    return status;
}

void target_describe(const TargetSettings *target, const RelativeError *estimate,
                     const RelativeError *against, TargetStop stop, double seconds, double spp,
                     double rays, int passes, char *text, size_t size)
{
    char aim[64], measured[128];
    if (target->target_error > 0.0)
        snprintf(aim, sizeof aim, "target %.2f %%", 100.0 * target->target_error);
    else
        snprintf(aim, sizeof aim, "time %.1f s", target->time_limit);
    if (against)
        snprintf(measured, sizeof measured, " / %.2f %% +/- %.2f (against the reference)",
                 error_percent(against->rel_mse), error_percent_std_error(against));
    else
        snprintf(measured, sizeof measured, " (no reference)");
    snprintf(text, size,
             "%s: %s %.2f %% (estimated)%s in %.1f s, %.0f spp, %.3g rays, %d passes", aim,
             stop == TARGET_REACHED ? "reached" : "stopped at",
             error_percent(estimate->rel_mse), measured, seconds, spp, rays, passes);
    if (stop != TARGET_REACHED)
        snprintf(text + strlen(text), size - strlen(text), " (%s)", target_stop_name(stop));
}
