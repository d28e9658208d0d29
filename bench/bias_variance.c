/* bias_variance.c (bench, chapter 8): bias and variance from images of several seeds. See
 * bias_variance.h. */
#include "bias_variance.h"

#include <math.h>
#include <stdlib.h>

#include "atomic_file.h"
#include "measure.h"

int seed_images_begin(SeedImages *s, int width, int height, const unsigned char *left_out)
{
    long values = 3L * width * height;
    *s = (SeedImages){calloc((size_t)values, sizeof *s->sum),
                      calloc((size_t)values, sizeof *s->sum_squares),
                      left_out,
                      values,
                      0,
                      0.0,
                      INFINITY,
                      0.0,
                      0.0,
                      0.0};
    if (s->sum && s->sum_squares)
        return 0;
    free(s->sum);
    free(s->sum_squares);
    return -1;
}

void seed_images_add(SeedImages *s, const Image *image, double seconds, double cpu,
                     const Image *reference)
{
    double rmse, rel_mse;
    measure_error(image, reference, &rmse, &rel_mse);
    for (long i = 0; i < s->values; i++) {
        s->sum[i] += image->pixels[i];
        s->sum_squares[i] += (double)image->pixels[i] * image->pixels[i];
    }
    s->count++;
    s->rmse_sum += rmse;
    s->rmse_low = fmin(s->rmse_low, rmse);
    s->rmse_high = fmax(s->rmse_high, rmse);
    s->seconds += seconds;
    s->cpu += cpu;
}

void seed_images_finish(SeedImages *s, const Image *reference_1, const Image *reference_2,
                        BiasVariance *result)
{
    double cross = 0.0, variance = 0.0;
    int k = s->count;
    long used = 0;
    for (long i = 0; i < s->values; i++) {
        if (s->left_out && s->left_out[i / 3])
            continue;
        double mean = s->sum[i] / k;
        cross += (mean - reference_1->pixels[i]) * (mean - reference_2->pixels[i]);
        variance += fmax(s->sum_squares[i] - k * mean * mean, 0.0) / (k - 1);
        used++;
    }
    result->variance = used > 0 ? variance / used : NAN;
    result->bias2 = used > 0 ? cross / used - result->variance / k : NAN;
    result->error = sqrt(fmax(result->bias2, 0.0) + result->variance);
    result->rmse = s->rmse_sum / k;
    result->rmse_low = s->rmse_low;
    result->rmse_high = s->rmse_high;
    result->seconds = s->seconds / k;
    result->cpu = s->cpu / k;
    free(s->sum);
    free(s->sum_squares);
    s->sum = s->sum_squares = NULL;
}

unsigned char *bias_variance_bright_mask(const Image *image, double threshold, int *marked)
{
    int w = image->width, h = image->height;
    unsigned char *mask = calloc((size_t)w * h, 1);
    if (!mask)
        return NULL;
    *marked = 0;
    for (int row = 0; row < h; row++)
        for (int col = 0; col < w; col++) {
            int bright = 0;
            for (int dy = -1; dy <= 1; dy++)
                for (int dx = -1; dx <= 1; dx++) {
                    int x = col + dx, y = row + dy;
                    if (x >= 0 && y >= 0 && x < w && y < h)
                        bright |= vec3_max_component(image_get(image, x, y)) > threshold;
                }
            mask[row * w + col] = (unsigned char)bright;
            *marked += bright;
        }
    return mask;
}

/* The shares of bias^2 and of the variance in the mean squared error. */
static double bias_share(const BiasVariance *e)
{
    double total = fmax(e->bias2, 0.0) + e->variance;
    return total > 0.0 ? fmax(e->bias2, 0.0) / total : 0.0;
}

void bias_variance_print(FILE *out, const SettingError *rows, int count)
{
    fprintf(out, "%-18s %4s %8s %7s %5s %6s %8s %7s %8s %17s %8s %10s %10s %5s %5s\n",
            "estimator", "spp", "photons", "radius", "alpha", "passes", "seconds", "cpu",
            "rmse", "(lowest-highest)", "error", "bias^2", "variance", "bias", "var.");
    for (int i = 0; i < count; i++) {
        const SettingError *r = &rows[i];
        const BiasVariance *e = &r->error;
        fprintf(out,
                "%-18s %4d %8d %7.4f %5.2f %6d %8.3f %7.3f %8.5f (%7.5f-%7.5f) %8.5f "
                "%10.3e %10.3e %4.0f%% %4.0f%%\n",
                r->estimator, r->spp, r->photons, r->radius, r->alpha, r->passes, e->seconds,
                e->cpu, e->rmse, e->rmse_low, e->rmse_high, e->error, e->bias2, e->variance,
                100 * bias_share(e), 100 * (1.0 - bias_share(e)));
    }
}

int bias_variance_write_csv(const char *path, const SettingError *rows, int count)
{
    AtomicFile file;
    if (atomic_open(&file, path) != 0)
        return -1;
    fprintf(file.file, "estimator,spp_per_pass,photons_per_pass,first_radius,alpha,passes,"
                       "seconds,cpu_seconds,rmse,rmse_lowest,rmse_highest,error,bias_squared,"
                       "variance,bias_share,variance_share\n");
    for (int i = 0; i < count; i++) {
        const SettingError *r = &rows[i];
        const BiasVariance *e = &r->error;
        fprintf(file.file,
                "%s,%d,%d,%.6g,%.6g,%d,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,"
                "%.6g\n",
                r->estimator, r->spp, r->photons, r->radius, r->alpha, r->passes, e->seconds,
                e->cpu, e->rmse, e->rmse_low, e->rmse_high, e->error, e->bias2, e->variance,
                bias_share(e), 1.0 - bias_share(e));
    }
    return atomic_close(&file, 0);
}
