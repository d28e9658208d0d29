/* ppm.c (bench, chapter 8): progressive photon mapping, pass by pass. See ppm.h. */
#include "ppm.h"

#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* One thread's share: photons [first, end), stored into its own growing array. The
 * thread works on its own copy of its Worker and writes it back at the end, so that
 * two threads never update counters in one cache line. */
typedef struct {
    const Scene *scene;
    const PhotonMapSettings *settings;
    int first, end;
    Photon *photons;
    int count, capacity;
    RayCounts rays;
    int failed;
} Worker;

static void shoot_share(Worker *w)
{
    for (int k = w->first; k < w->end; k++) {
        Photon photon;
        if (!photon_shoot(w->scene, w->settings, k, &photon, &w->rays))
            continue;
        if (w->count == w->capacity) {
            int capacity = w->capacity ? 2 * w->capacity : 1024;
            Photon *grown = realloc(w->photons, (size_t)capacity * sizeof *grown);
            if (!grown) {
                w->failed = 1;
                return;
            }
            w->photons = grown;
            w->capacity = capacity;
        }
        w->photons[w->count++] = photon;
    }
}

static void *shoot_thread(void *argument)
{
    Worker *shared = argument, own = *shared;
    shoot_share(&own);
    *shared = own;
    return NULL;
}

/* The workers' photons, in the order they were shot, made into the map. */
static int gather(PhotonMap *map, const Worker *workers, int threads, int emitted,
                  double radius)
{
    int count = 0;
    for (int i = 0; i < threads; i++)
        count += workers[i].count;
    Photon *shot = malloc((size_t)(count > 0 ? count : 1) * sizeof *shot);
    if (!shot)
        return -1;
    for (int i = 0, at = 0; i < threads; at += workers[i].count, i++)
        if (workers[i].count > 0)
            memcpy(shot + at, workers[i].photons, (size_t)workers[i].count * sizeof *shot);
    int status = photon_map_build(map, shot, count, emitted, radius);
    free(shot);
    return status;
}

int ppm_photon_map(PhotonMap *map, const Scene *scene, const PhotonMapSettings *settings,
                   double radius, int threads, RayCounts *counts)
{
    memset(map, 0, sizeof *map);
    if (threads <= 0)
        threads = render_core_count();
    if (threads > settings->emitted)
        threads = settings->emitted > 0 ? settings->emitted : 1;
    Worker *workers = calloc((size_t)threads, sizeof *workers);
    pthread_t *ids = calloc((size_t)threads, sizeof *ids);
    int status = workers && ids ? 0 : -1;
    for (int i = 0; status == 0 && i < threads; i++)
        workers[i] = (Worker){scene,
                              settings,
                              (int)((long)settings->emitted * i / threads),
                              (int)((long)settings->emitted * (i + 1) / threads),
                              NULL,
                              0,
                              0,
                              {0, 0, 0},
                              0};
    int started = 1;
    for (int i = 1; status == 0 && i < threads; i++) {
        if (pthread_create(&ids[i], NULL, shoot_thread, &workers[i]) != 0)
            break; /* the rest are shot below, on this thread */
        started = i + 1;
    }
    if (status == 0) {
        shoot_thread(&workers[0]);
        for (int i = 1; i < started; i++)
            pthread_join(ids[i], NULL);
        for (int i = started; i < threads; i++)
            shoot_thread(&workers[i]);
    }
    for (int i = 0; status == 0 && i < threads; i++) {
        status = workers[i].failed ? -1 : 0;
        ray_counts_add(counts, workers[i].rays);
    }
    if (status == 0)
        status = gather(map, workers, threads, settings->emitted, radius);
    for (int i = 0; workers && i < threads; i++)
        free(workers[i].photons);
    free(workers);
    free(ids);
    return status;
}

void ppm_pass_seeds(uint64_t seed, int pass, uint64_t *image_seed, uint64_t *photon_seed)
{
    Rng rng = rng_for_sample(seed, 0x70686f746f6eULL /* "photon" */, (uint64_t)pass);
    uint64_t high = rng_next(&rng);
    *image_seed = high << 32 | rng_next(&rng);
    high = rng_next(&rng);
    *photon_seed = high << 32 | rng_next(&rng);
}

/* One pass: fresh maps, then the image with them. Both maps are of the same photons
 * (one seed): the split map keeps those of the caustic map that did not come by one
 * planar mirror alone. */
static int render_pass(const Scene *scene, const RenderSettings *whole,
                       const PpmSettings *settings, int pass, RenderResult *image,
                       RayCounts *photon_rays, int *stored)
{
    uint64_t image_seed, photon_seed;
    ppm_pass_seeds(whole->image.seed, pass, &image_seed, &photon_seed);
    PhotonMapSettings photons = {settings->photons, PHOTON_CAUSTIC, settings->path.fresnel,
                                 photon_seed};
    PhotonMapSettings split_photons = photons;
    split_photons.paths = PHOTON_SPLIT;
    PhotonMap caustics, split;
    double radius = ppm_radius(settings->radius, settings->alpha, pass);
    /* As many threads as the render takes: no more than its rows. */
    int threads = whole->threads > whole->image.height ? whole->image.height : whole->threads;
    if (ppm_photon_map(&caustics, scene, &photons, radius, threads, photon_rays) != 0)
        return -1;
    if (ppm_photon_map(&split, scene, &split_photons, radius, threads, photon_rays) != 0) {
        photon_map_free(&caustics);
        return -1;
    }
    *stored = caustics.count;
    CausticPathSettings estimator = {settings->path, &split, &caustics, radius};
    RenderSettings pass_render = *whole;
    pass_render.image.spp = settings->spp;
    pass_render.progress = 0;
    /* Progressive sampling continues one sequence per pixel over the passes; the
     * others take independent samples in every pass. */
    int progressive = whole->image.sampling == PIXEL_PROGRESSIVE;
    if (!progressive)
        pass_render.image.seed = image_seed;
    int status = render_from(scene, &pass_render, progressive ? (pass - 1) * settings->spp : 0,
                             path_caustics_radiance, &estimator, image);
    photon_map_free(&caustics);
    photon_map_free(&split);
    return status;
}

int ppm_budget_allows(const PpmSettings *s, int done, double cpu_used)
{
    if (done >= s->passes)
        return 0;
    return s->cpu_seconds <= 0.0 || done == 0 ||
           cpu_used + 0.5 * cpu_used / done <= s->cpu_seconds;
}

int ppm_render(const Scene *scene, const RenderSettings *render, const PpmSettings *settings,
               PpmResult *result)
{
    PpmResult r = {0};
    int width = render->image.width, height = render->image.height;
    r.render.image = image_new(width, height);
    r.render.std_error = image_new(width, height);
    r.render.average_std_error = image_new(width, height);
    /* Each pixel's passes, summed as the renderer sums a pixel's samples: the mean of the
     * independent pass images and its standard error. */
    PixelSum *passes = calloc((size_t)width * height, sizeof *passes);
    int status = r.render.image.pixels && r.render.std_error.pixels &&
                         r.render.average_std_error.pixels && passes
                     ? 0
                     : -1;
    int show = render->progress && isatty(STDERR_FILENO);
    double start = stats_now(), cpu_start = stats_cpu_now();
    long stored = 0;
    /* With a target or a time limit, the passes go in pairs, in turn into two halves. */
    TargetSettings target = {settings->target_error, settings->time_limit, settings->spp, 0,
                             settings->passes};
    int in_pairs = target.target_error > 0.0 || target.time_limit > 0.0;
    HalfImages halves = {{{0, 0, NULL}, {0, 0, NULL}}, {0, 0}, 0};
    if (in_pairs && status == 0 && half_images_begin(&halves, width, height) != 0)
        status = -1;
    r.estimate = (RelativeError){NAN, NAN};
    r.stop = TARGET_MOST_PASSES;
    while (status == 0 && ppm_budget_allows(settings, r.passes, stats_cpu_now() - cpu_start)) {
        RenderResult pass;
        int pass_stored;
        if (render_pass(scene, render, settings, r.passes + 1, &pass, &r.render.rays,
                        &pass_stored) != 0) {
            status = -1;
            break;
        }
        if (pass.interrupted) {
            r.render.interrupted = 1;
            r.stop = TARGET_INTERRUPTED;
            render_result_free(&pass);
            break;
        }
        if (in_pairs)
            half_images_add(&halves, &pass.image, settings->spp);
        for (int row = 0; row < height; row++)
            for (int col = 0; col < width; col++)
                pixel_sum_add(&passes[(long)row * width + col],
                              image_get(&pass.image, col, row));
        r.passes++;
        stored += pass_stored;
        r.render.threads = pass.threads;
        r.render.samples += pass.samples;
        r.render.nonfinite += pass.nonfinite;
        ray_counts_add(&r.render.rays, pass.rays);
        render_result_free(&pass);
        if (show)
            fprintf(stderr, "\r%s: pass %d, %.1f s   ", render->label ? render->label : "ppm",
                    r.passes, stats_now() - start);
        int next_spp;
        if (in_pairs && r.passes % 2 == 0) {
            r.estimate = half_images_estimate(&halves);
            if (target_should_stop(&target, &r.estimate, r.passes, stats_now() - start,
                                   (double)r.passes * settings->spp, &next_spp, &r.stop))
                break;
        }
    }
    half_images_free(&halves);
    if (show)
        fprintf(stderr, "\r%*s\r", 40, "");
    r.render.seconds = stats_now() - start;
    r.cpu_seconds = stats_cpu_now() - cpu_start;
    if (status == 0) {
        pixel_sums_finish(passes, &r.render);
        r.radius = ppm_radius(settings->radius, settings->alpha, r.passes > 0 ? r.passes : 1);
        r.stored = r.passes > 0 ? (double)stored / r.passes : 0.0;
        *result = r;
    } else {
        ppm_result_free(&r);
    }
    free(passes);
    return status;
}

void ppm_result_free(PpmResult *result) { render_result_free(&result->render); }
