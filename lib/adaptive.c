/* adaptive.c (chapter 10): the error estimate from two half-images, the stopping rule and
 * the passes. See adaptive.h. */
#include "adaptive.h"

#include <math.h>
#include <stdlib.h>

static double channel(Vec3 v, int c) { return c == 0 ? v.x : c == 1 ? v.y : v.z; }

double adaptive_error_estimate(const Vec3 *first, const Vec3 *second, int width, int height,
                               int col, int row)
{
    double sum = 0.0;
    int count = 0;
    for (int y = row - 1; y <= row + 1; y++)
        for (int x = col - 1; x <= col + 1; x++) {
            if (x < 0 || y < 0 || x >= width || y >= height)
                continue;
            long p = (long)y * width + x;
            for (int c = 0; c < 3; c++) {
                double a = channel(first[p], c), b = channel(second[p], c);
                double value = (a + b) / 2.0;
                sum += (a - b) * (a - b) / 4.0 / (value * value + 0.01) / 3.0;
            }
            count++;
        }
    return sum / count;
}

int adaptive_samples_to_add(const AdaptiveSettings *settings, int samples, double estimate)
{
    if (samples < settings->min_samples)
        return settings->min_samples - samples;
    if (estimate <= settings->threshold || samples >= settings->max_samples)
        return 0;
    int left = settings->max_samples - samples;
    return settings->pass_samples < left ? settings->pass_samples : left;
}

/* The finite samples of quarter q: those s < samples with s mod 4 = q, less the dropped. */
static int quarter_finite(const AdaptivePixel *pixel, int q)
{
    return (pixel->samples + 3 - q) / 4 - pixel->dropped[q];
}

/* The mean of the finite samples of quarters q and q + 2 (a half-image: A for q = 0, B for
 * q = 1), or of quarter q alone; 0 without any. */
static Vec3 quarters_mean(const AdaptivePixel *pixel, int q, int both)
{
    int n = quarter_finite(pixel, q) + (both ? quarter_finite(pixel, q + 2) : 0);
    Vec3 sum = both ? vec3_add(pixel->sum[q], pixel->sum[q + 2]) : pixel->sum[q];
    return n > 0 ? vec3_scale(sum, 1.0 / n) : vec3(0, 0, 0);
}

static Vec3 half_mean(const AdaptivePixel *pixel, int q) { return quarters_mean(pixel, q, 1); }

Vec3 adaptive_pixel_value(const AdaptivePixel *pixel, AdaptiveRule rule)
{
    if (rule == ADAPTIVE_UNBIASED)
        return half_mean(pixel, 1);
    return vec3_scale(vec3_add(half_mean(pixel, 0), half_mean(pixel, 1)), 0.5);
}

/* The two independent halves the rule decides from. Biased: A and B, whose
 * ((A - B) / 2)^2 estimates the variance of the kept (A + B) / 2. Unbiased: A's own
 * quarters 0 and 2, whose ((q0 - q2) / 2)^2 estimates Var(A) = Var(B), the kept B's. */
static void decision_halves(const AdaptivePixel *pixel, AdaptiveRule rule, Vec3 *first,
                            Vec3 *second)
{
    if (rule == ADAPTIVE_BIASED) {
        *first = half_mean(pixel, 0);
        *second = half_mean(pixel, 1);
        return;
    }
    *first = quarters_mean(pixel, 0, 0);
    *second = quarters_mean(pixel, 2, 0);
}

long adaptive_plan(const AdaptiveSettings *settings, const AdaptivePixel *pixels, int width,
                   int height, double *estimate, int *to_add)
{
    long count = (long)width * height, active = 0;
    Vec3 *first = malloc(2 * (size_t)count * sizeof *first), *second = first + count;
    if (!first)
        return -1;
    for (long p = 0; p < count; p++)
        decision_halves(&pixels[p], settings->rule, &first[p], &second[p]);
    for (int row = 0; row < height; row++)
        for (int col = 0; col < width; col++)
            estimate[(long)row * width + col] =
                adaptive_error_estimate(first, second, width, height, col, row);
    /* A pixel is sampled when any window it lies in is above the threshold, so that the
     * pixel whose error holds a window up gets samples too. */
    for (int row = 0; row < height; row++)
        for (int col = 0; col < width; col++) {
            double worst = 0.0;
            for (int y = row - 1; y <= row + 1; y++)
                for (int x = col - 1; x <= col + 1; x++)
                    if (x >= 0 && y >= 0 && x < width && y < height)
                        worst = fmax(worst, estimate[(long)y * width + x]);
            long p = (long)row * width + col;
            to_add[p] = adaptive_samples_to_add(settings, pixels[p].samples, worst);
            active += to_add[p] > 0;
        }
    free(first);
    return active;
}

uint64_t adaptive_sample_rows(const Scene *scene, const ImageSettings *image,
                              Estimator estimate, const void *estimator_settings,
                              AdaptivePixel *pixels, const int *to_add, int first_row,
                              int end_row, RayCounts *counts)
{
    uint64_t dropped = 0;
    ImageSettings quarters[4];
    for (int q = 0; q < 4; q++) {
        quarters[q] = *image;
        quarters[q].seed = rng_hash(image->seed * 4 + (uint64_t)q); /* independent */
    }
    for (int row = first_row; row < end_row; row++)
        for (int col = 0; col < image->width; col++) {
            AdaptivePixel *pixel = &pixels[(long)row * image->width + col];
            int end = pixel->samples + to_add[(long)row * image->width + col];
            for (int s = pixel->samples; s < end; s++) {
                Vec3 x = render_sample(scene, &quarters[s % 4], col, row, s / 4, estimate,
                                       estimator_settings, counts);
                if (!vec3_is_finite(x)) {
                    pixel->dropped[s % 4]++;
                    dropped++;
                    continue;
                }
                pixel->sum[s % 4] = vec3_add(pixel->sum[s % 4], x);
            }
            pixel->samples = end;
        }
    return dropped;
}

int adaptive_render(const Scene *scene, const ImageSettings *image, Estimator estimate,
                    const void *estimator_settings, const AdaptiveSettings *settings,
                    AdaptivePixel *pixels, double *error_estimate, RayCounts *counts)
{
    int *to_add = malloc((size_t)image->width * image->height * sizeof *to_add);
    if (!to_add)
        return -1;
    long active;
    while ((active = adaptive_plan(settings, pixels, image->width, image->height,
                                   error_estimate, to_add)) > 0)
        adaptive_sample_rows(scene, image, estimate, estimator_settings, pixels, to_add, 0,
                             image->height, counts);
    free(to_add);
    return active < 0 ? -1 : 0;
}
