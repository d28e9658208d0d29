/* renderer.c (bench, chapter 1): the pixel loop on threads, with progress and
 * interruption. See renderer.h. */
#include "renderer.h"

#include <errno.h>
#include <pthread.h>
#include <signal.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/wait.h>
#include <unistd.h>

#include "atomic_file.h"
#include "sample_order.h"

typedef struct {
    const Scene *scene;
    const RenderSettings *settings;
    Estimator estimate;
    const void *estimator_settings;
    PixelSum *pixels;
    SampleOrder order; /* which sample each pass takes of each pixel */
    int first_sample, pass;
    atomic_int next_row;
    atomic_long rows_done; /* over all passes, for the progress display */
    double start_time;
} Job;

typedef struct {
    Job *job;
    int index;
    RayCounts rays;
    uint64_t samples, nonfinite;
} Worker;

static volatile sig_atomic_t interrupt_requested = 0;

/* A program started to render for this one (render_forward_signals), while it runs; and
 * whether signals that end this program wait for render_end_deferred, and which came. */
static volatile sig_atomic_t child_pid = 0;
static volatile sig_atomic_t deferring = 0;
static volatile sig_atomic_t deferred_signal = 0;

/* End the program as the signal would: first remove the temporary files being written
 * (atomic_file.h), then raise it again with its default action, so the program dies of
 * it as it would have. */
static void end_program(int signal_number)
{
    atomic_remove_temporaries();
    signal(signal_number, SIG_DFL);
    raise(signal_number); /* delivered when the handler returns, or at once */
}

/* The one signal path. The first SIGINT asks a running render to stop early (it saves
 * what it has). SIGTERM, SIGHUP and a second SIGINT end the program. While a child
 * renders for it, each is passed on to the child (a second ending one as SIGKILL: the
 * child did not end), and an ending one waits until the child has ended and what both
 * wrote is cleaned up. */
static void on_signal(int signal_number)
{
    int first_interrupt = signal_number == SIGINT && !interrupt_requested;
    if (first_interrupt)
        interrupt_requested = 1;
    if (child_pid > 0)
        kill(child_pid, deferred_signal && !first_interrupt ? SIGKILL : signal_number);
    if (first_interrupt)
        return;
    if (deferring)
        deferred_signal = signal_number;
    else
        end_program(signal_number);
}

static const int handled[] = {SIGINT, SIGTERM, SIGHUP};

void render_install_interrupt(void)
{
    struct sigaction action = {0};
    action.sa_handler = on_signal;
    sigemptyset(&action.sa_mask);
    for (int i = 0; i < 3; i++)
        sigaddset(&action.sa_mask, handled[i]); /* one at a time */
    for (int i = 0; i < 3; i++)
        sigaction(handled[i], &action, NULL);
}

void render_hold_signals(int hold)
{
    sigset_t set;
    sigemptyset(&set);
    for (int i = 0; i < 3; i++)
        sigaddset(&set, handled[i]);
    pthread_sigmask(hold ? SIG_BLOCK : SIG_UNBLOCK, &set, NULL);
}

void render_forward_signals(pid_t child)
{
    deferring = 1;
    child_pid = child;
    if (child > 0 && interrupt_requested)
        kill(child, SIGINT);
}

int render_wait_for_child(void)
{
    pid_t child = child_pid;
    siginfo_t info;
    /* Wait without reaping, so that the id still names the child whenever the handler
     * passes a signal on; then stop passing them on, and reap it. */
    while (waitid(P_PID, (id_t)child, &info, WEXITED | WNOWAIT) != 0)
        if (errno != EINTR)
            return -1;
    child_pid = 0;
    int status;
    while (waitpid(child, &status, 0) < 0)
        if (errno != EINTR)
            return -1;
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

void render_end_deferred(void)
{
    deferring = 0;
    if (deferred_signal)
        end_program(deferred_signal);
}

int render_interrupted(void) { return interrupt_requested != 0; }

int render_core_count(void)
{
    long cores = sysconf(_SC_NPROCESSORS_ONLN);
    return cores > 0 ? (int)cores : 1;
}

static void show_progress(Job *job)
{
    const RenderSettings *s = job->settings;
    double fraction =
        (double)atomic_load(&job->rows_done) / ((double)s->image.spp * s->image.height);
    double elapsed = stats_now() - job->start_time;
    fprintf(stderr, "\r%s: %3.0f%%  sample %d/%d  %.1f s elapsed, about %.0f s left   ",
            s->label ? s->label : "render", 100.0 * fraction, job->pass + 1, s->image.spp,
            elapsed, fraction > 0.0 ? elapsed * (1.0 - fraction) / fraction : 0.0);
}

void pixel_sum_add(PixelSum *pixel, Vec3 radiance)
{
    double value[4] = {radiance.x, radiance.y, radiance.z, vec3_average(radiance)};
    double n = ++pixel->finite;
    for (int c = 0; c < 4; c++) {
        double delta = value[c] - pixel->mean[c];
        pixel->mean[c] += delta / n;
        pixel->m2[c] += delta * (value[c] - pixel->mean[c]);
    }
}

/* Take sample `pass` of every pixel in one row. The row's counts are kept in locals and
 * added to the worker's at its end: the workers' structs sit side by side in one
 * array, and two threads incrementing counters in one cache line would make it travel
 * between their cores at every ray. */
static void render_row(Worker *worker, int row)
{
    Job *job = worker->job;
    const ImageSettings *image = &job->settings->image;
    RayCounts rays = {0, 0, 0};
    uint64_t samples = 0, nonfinite = 0;
    for (int col = 0; col < image->width; col++) {
        int sample =
            job->first_sample +
            sample_order_sample(&job->order, (uint64_t)row * image->width + col, job->pass);
        Vec3 radiance = render_sample(job->scene, image, col, row, sample, job->estimate,
                                      job->estimator_settings, &rays);
        samples++;
        if (!vec3_is_finite(radiance)) {
            nonfinite++;
            continue;
        }
        pixel_sum_add(&job->pixels[(long)row * image->width + col], radiance);
    }
    ray_counts_add(&worker->rays, rays);
    worker->samples += samples;
    worker->nonfinite += nonfinite;
}

static void *work(void *argument)
{
    Worker *worker = argument;
    Job *job = worker->job;
    int show = worker->index == 0 && job->settings->progress && isatty(STDERR_FILENO);
    double last_shown = 0.0;
    for (;;) {
        if (render_interrupted())
            break;
        int row = atomic_fetch_add(&job->next_row, 1);
        if (row >= job->settings->image.height)
            break;
        render_row(worker, row);
        atomic_fetch_add(&job->rows_done, 1);
        if (show && stats_now() - last_shown > 0.25) {
            last_shown = stats_now();
            show_progress(job);
        }
    }
    return NULL;
}

void pixel_sums_finish(const PixelSum *pixels, RenderResult *result)
{
    for (int row = 0; row < result->image.height; row++) {
        for (int col = 0; col < result->image.width; col++) {
            const PixelSum *p = &pixels[(long)row * result->image.width + col];
            double n = p->finite, e[4] = {0, 0, 0, 0};
            for (int c = 0; c < 4 && n > 1; c++)
                e[c] = sqrt(p->m2[c] / (n - 1) / n);
            image_set(&result->image, col, row, vec3(p->mean[0], p->mean[1], p->mean[2]));
            image_set(&result->std_error, col, row, vec3(e[0], e[1], e[2]));
            image_set(&result->average_std_error, col, row, vec3(e[3], e[3], e[3]));
        }
    }
}

int render(const Scene *scene, const RenderSettings *settings, Estimator estimate,
           const void *estimator_settings, RenderResult *result)
{
    return render_from(scene, settings, 0, estimate, estimator_settings, result);
}

int render_from(const Scene *scene, const RenderSettings *settings, int first_sample,
                Estimator estimate, const void *estimator_settings, RenderResult *result)
{
    RenderResult r = {0};
    r.threads = settings->threads > 0 ? settings->threads : render_core_count();
    if (r.threads > settings->image.height)
        r.threads = settings->image.height;
    r.image = image_new(settings->image.width, settings->image.height);
    r.std_error = image_new(settings->image.width, settings->image.height);
    r.average_std_error = image_new(settings->image.width, settings->image.height);
    PixelSum *pixels =
        calloc((size_t)settings->image.width * settings->image.height, sizeof *pixels);
    Worker *workers = calloc((size_t)r.threads, sizeof *workers);
    pthread_t *threads = calloc((size_t)r.threads, sizeof *threads);
    if (!r.image.pixels || !r.std_error.pixels || !r.average_std_error.pixels || !pixels ||
        !workers || !threads) {
        free(pixels);
        free(workers);
        free(threads);
        render_result_free(&r);
        return -1;
    }

    Job job = {.scene = scene,
               .settings = settings,
               .estimate = estimate,
               .estimator_settings = estimator_settings,
               .pixels = pixels,
               .order = sample_order_make(&settings->image),
               .first_sample = first_sample,
               .start_time = stats_now()};
    for (int i = 0; i < r.threads; i++)
        workers[i] = (Worker){&job, i, {0, 0, 0}, 0, 0};
    for (job.pass = 0; job.pass < settings->image.spp && !render_interrupted(); job.pass++) {
        atomic_store(&job.next_row, 0);
        int started = 1;
        for (int i = 1; i < r.threads; i++)
            if (pthread_create(&threads[i], NULL, work, &workers[i]) == 0)
                started = i + 1;
            else
                break; /* fewer threads this pass: the rows are still all taken */
        work(&workers[0]);
        for (int i = 1; i < started; i++)
            pthread_join(threads[i], NULL);
    }
    r.seconds = stats_now() - job.start_time;
    if (settings->progress && isatty(STDERR_FILENO))
        fprintf(stderr, "\r%*s\r", 79, "");

    for (int i = 0; i < r.threads; i++) {
        ray_counts_add(&r.rays, workers[i].rays);
        r.samples += workers[i].samples;
        r.nonfinite += workers[i].nonfinite;
    }
    r.interrupted = render_interrupted();
    pixel_sums_finish(pixels, &r);
    free(pixels);
    free(workers);
    free(threads);
    *result = r;
    return 0;
}

int render_serial(const Scene *scene, const RenderSettings *settings, Estimator estimate,
                  const void *estimator_settings, RenderResult *result)
{
    const ImageSettings *image = &settings->image;
    RenderResult r = {.threads = 1};
    r.image = image_new(image->width, image->height);
    r.std_error = image_new(image->width, image->height);
    r.average_std_error = image_new(image->width, image->height);
    Vec3 *pixels = malloc((size_t)image->width * image->height * sizeof *pixels);
    if (!r.image.pixels || !r.std_error.pixels || !r.average_std_error.pixels || !pixels) {
        free(pixels);
        render_result_free(&r);
        return -1;
    }
    double start = stats_now();
    render_image(scene, image, estimate, estimator_settings, pixels, &r.rays);
    r.seconds = stats_now() - start;
    r.samples = (uint64_t)image->width * image->height * image->spp;
    for (int row = 0; row < image->height; row++)
        for (int col = 0; col < image->width; col++)
            image_set(&r.image, col, row, pixels[(long)row * image->width + col]);
    free(pixels);
    *result = r;
    return 0;
}

void render_result_free(RenderResult *result)
{
    image_free(&result->image);
    image_free(&result->std_error);
    image_free(&result->average_std_error);
}

double render_samples_per_pixel(const RenderResult *result)
{
    return (double)result->samples / ((double)result->image.width * result->image.height);
}
