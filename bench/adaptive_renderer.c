/* adaptive_renderer.c (bench, chapter 10): the passes on every core. See
 * adaptive_renderer.h. */
#include "adaptive_renderer.h"

#include <math.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

typedef struct {
    const Scene *scene;
    const RenderSettings *settings;
    Estimator estimate;
    const void *estimator_settings;
    AdaptivePixel *pixels;
    const int *to_add;
    atomic_int next_row;
} Pass;

typedef struct {
    Pass *pass;
    RayCounts rays;
    uint64_t nonfinite; /* samples dropped */
} Worker;

static void *work(void *argument)
{
    Worker *worker = argument;
    Pass *pass = worker->pass;
    int row;
    while ((row = atomic_fetch_add(&pass->next_row, 1)) < pass->settings->image.height)
        worker->nonfinite += adaptive_sample_rows(
            pass->scene, &pass->settings->image, pass->estimate, pass->estimator_settings,
            pass->pixels, pass->to_add, row, row + 1, &worker->rays);
    return NULL;
}

/* Add the planned samples, rows shared among the threads. */
static void sample_pass(Pass *pass, Worker *workers, pthread_t *threads, int count)
{
    atomic_store(&pass->next_row, 0);
    int started = 1;
    for (int i = 1; i < count; i++)
        if (pthread_create(&threads[i], NULL, work, &workers[i]) == 0)
            started = i + 1;
        else
            break; /* fewer threads: the rows are still all taken */
    work(&workers[0]);
    for (int i = 1; i < started; i++)
        pthread_join(threads[i], NULL);
}

static double mean_of(const double *values, long count)
{
    double sum = 0.0;
    for (long i = 0; i < count; i++)
        sum += values[i];
    return sum / count;
}

/* The kept image, the samples and the error maps from the pixels and the last plan. */
static void finish(const AdaptivePixel *pixels, AdaptiveRule rule, const double *estimate,
                   AdaptiveResult *r)
{
    long count = (long)r->render.image.width * r->render.image.height;
    for (long p = 0; p < count; p++) {
        Vec3 value = adaptive_pixel_value(&pixels[p], rule);
        float *out = &r->render.image.pixels[3 * p];
        out[0] = (float)value.x, out[1] = (float)value.y, out[2] = (float)value.z;
        for (int c = 0; c < 3; c++) {
            r->samples.pixels[3 * p + c] = (float)pixels[p].samples;
            r->error.pixels[3 * p + c] = (float)sqrt(estimate[p]);
        }
        r->render.samples += (uint64_t)pixels[p].samples;
    }
}

int adaptive_renderer_run(const Scene *scene, const RenderSettings *settings,
                          Estimator estimate, const void *estimator_settings,
                          const AdaptiveGoal *goal, AdaptiveResult *result)
{
    int width = settings->image.width, height = settings->image.height;
    long count = (long)width * height;
    AdaptiveResult r = {0};
    r.render.threads = settings->threads > 0 ? settings->threads : render_core_count();
    if (r.render.threads > height)
        r.render.threads = height;
    r.render.image = image_new(width, height);
    r.render.std_error = image_new(width, height);
    r.render.average_std_error = image_new(width, height);
    r.samples = image_new(width, height);
    r.error = image_new(width, height);
    AdaptivePixel *pixels = calloc((size_t)count, sizeof *pixels);
    double *errors = calloc((size_t)count, sizeof *errors);
    int *to_add = calloc((size_t)count, sizeof *to_add);
    Worker *workers = calloc((size_t)r.render.threads, sizeof *workers);
    pthread_t *threads = calloc((size_t)r.render.threads, sizeof *threads);
    int status = -1;
    if (!r.render.image.pixels || !r.render.std_error.pixels ||
        !r.render.average_std_error.pixels || !r.samples.pixels || !r.error.pixels || !pixels ||
        !errors || !to_add || !workers || !threads)
        goto done;

    Pass pass = {scene, settings, estimate, estimator_settings, pixels, to_add, 0};
    for (int i = 0; i < r.render.threads; i++)
        workers[i] = (Worker){&pass, {0, 0, 0}, 0};
    AdaptiveSettings rule = goal->rule;
    if (goal->target_error > 0.0)
        rule.threshold = goal->target_error * goal->target_error;
    double start = stats_now(), cpu_start = stats_cpu_now();
    for (;;) {
        long active = adaptive_plan(&rule, pixels, width, height, errors, to_add);
        if (active < 0)
            goto done;
        r.estimated_rel_rmse = sqrt(mean_of(errors, count));
        int started = r.passes > 0;
        if (active == 0 || render_interrupted() ||
            (started && goal->target_error > 0.0 &&
             r.estimated_rel_rmse <= goal->target_error) ||
            (started && goal->time_limit > 0.0 && stats_now() - start >= goal->time_limit))
            break;
        sample_pass(&pass, workers, threads, r.render.threads);
        r.passes++;
        if (goal->target_error <= 0.0)
            rule.threshold = mean_of(errors, count);
        if (settings->progress && isatty(STDERR_FILENO))
            fprintf(stderr, "\r%s: pass %d, %ld pixels sampled, estimated error %.4f  ",
                    settings->label ? settings->label : "adaptive", r.passes, active,
                    r.estimated_rel_rmse);
    }
    r.render.seconds = stats_now() - start;
    r.cpu_seconds = stats_cpu_now() - cpu_start;
    if (settings->progress && isatty(STDERR_FILENO))
        fprintf(stderr, "\r%*s\r", 79, "");
    for (int i = 0; i < r.render.threads; i++) {
        ray_counts_add(&r.render.rays, workers[i].rays);
        r.render.nonfinite += workers[i].nonfinite;
    }
    r.render.interrupted = render_interrupted();
    finish(pixels, goal->rule.rule, errors, &r);
    status = 0;
done:
    free(pixels);
    free(errors);
    free(to_add);
    free(workers);
    free(threads);
    if (status == 0)
        *result = r;
    else
        adaptive_result_free(&r);
    return status;
}

void adaptive_result_free(AdaptiveResult *result)
{
    render_result_free(&result->render);
    image_free(&result->samples);
    image_free(&result->error);
}
