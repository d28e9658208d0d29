/* ppm.c (chapter 8): probabilistic progressive photon mapping, pass by pass.
 * See ppm.h. */
#include "ppm.h"

#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

double ppm_radius(double first_radius, double alpha, int pass)
{
    return first_radius * sqrt(pow((double)pass, alpha - 1.0));
}

/* Two independent 64-bit seeds for pass `pass`: its camera samples and its photons. */
static void pass_seeds(uint64_t seed, int pass, uint64_t *image_seed, uint64_t *photon_seed)
{
    Rng rng = rng_for_sample(seed, 0x70686f746f6eULL /* "photon" */, (uint64_t)pass);
    uint64_t high = rng_next(&rng);
    *image_seed = high << 32 | rng_next(&rng);
    high = rng_next(&rng);
    *photon_seed = high << 32 | rng_next(&rng);
}

/* One pass: a fresh caustic map, then the image with it. */
static int render_pass(const Scene *scene, const RenderSettings *whole,
                       const PpmSettings *settings, int pass, RenderResult *image,
                       RayCounts *photon_rays, int *stored)
{
    uint64_t image_seed, photon_seed;
    pass_seeds(whole->seed, pass, &image_seed, &photon_seed);
    PhotonMapSettings photons = {settings->photons, PHOTON_CAUSTIC, settings->path.fresnel,
                                 photon_seed, whole->threads};
    PhotonMap map;
    if (photon_map_build(&map, scene, &photons, photon_rays) != 0)
        return -1;
    *stored = map.count;
    CausticPathSettings estimator = {settings->path, &map,
                                     ppm_radius(settings->radius, settings->alpha, pass)};
    RenderSettings pass_render = *whole;
    pass_render.spp = settings->spp;
    pass_render.seed = image_seed;
    pass_render.progress = 0;
    int status = render(scene, &pass_render, path_radiance_caustics, &estimator, image);
    photon_map_free(&map);
    return status;
}

/* The mean of the passes and its standard error, from per-pixel sums over passes. */
static void finish(const double *sum, const double *sum_squares, int passes, RenderResult *r)
{
    long values = 3L * r->image.width * r->image.height;
    for (long i = 0; i < values; i++) {
        double mean = passes > 0 ? sum[i] / passes : 0.0, error = 0.0;
        if (passes > 1)
            error = sqrt(fmax(sum_squares[i] - passes * mean * mean, 0.0) / (passes - 1) / passes);
        r->image.pixels[i] = (float)mean;
        r->std_error.pixels[i] = (float)error;
    }
}

/* Another pass, if one is left and the budget allows it: the total time with it (judged
 * by the mean pass so far) ends nearer the budget than without it. */
static int budget_allows(const PpmSettings *s, int done, double cpu_used)
{
    if (done >= s->passes)
        return 0;
    return s->cpu_seconds <= 0.0 || done == 0 || cpu_used + 0.5 * cpu_used / done <= s->cpu_seconds;
}

int ppm_render(const Scene *scene, const RenderSettings *render, const PpmSettings *settings,
               PpmResult *result)
{
    PpmResult r = {0};
    long values = 3L * render->width * render->height;
    r.render.image = image_new(render->width, render->height);
    r.render.std_error = image_new(render->width, render->height);
    double *sum = calloc((size_t)values, sizeof *sum);
    double *sum_squares = calloc((size_t)values, sizeof *sum_squares);
    int status = r.render.image.pixels && r.render.std_error.pixels && sum && sum_squares ? 0 : -1;
    int show = render->progress && isatty(STDERR_FILENO);
    double start = stats_now(), cpu_start = stats_cpu_now();
    long stored = 0;
    while (status == 0 && budget_allows(settings, r.passes, stats_cpu_now() - cpu_start)) {
        RenderResult pass;
        int pass_stored;
        if (render_pass(scene, render, settings, r.passes + 1, &pass, &r.render.rays, &pass_stored) != 0) {
            status = -1;
            break;
        }
        if (pass.interrupted) {
            r.render.interrupted = 1;
            render_result_free(&pass);
            break;
        }
        for (long i = 0; i < values; i++) {
            double v = pass.image.pixels[i];
            sum[i] += v;
            sum_squares[i] += v * v;
        }
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
    }
    if (show)
        fprintf(stderr, "\r%*s\r", 40, "");
    r.render.seconds = stats_now() - start;
    r.cpu_seconds = stats_cpu_now() - cpu_start;
    if (status == 0) {
        finish(sum, sum_squares, r.passes, &r.render);
        r.radius = ppm_radius(settings->radius, settings->alpha, r.passes > 0 ? r.passes : 1);
        r.stored = r.passes > 0 ? (double)stored / r.passes : 0.0;
        *result = r;
    } else {
        ppm_result_free(&r);
    }
    free(sum);
    free(sum_squares);
    return status;
}

void ppm_result_free(PpmResult *result)
{
    render_result_free(&result->render);
}
