/* metamorphic.h (bench, chapter 1): metamorphic tests (include after cmocka.h): each
 * case of metamorphic_scenes.h rendered by one chapter, before and after its change, and
 * the two images judged: bit for bit where the arithmetic is exact, else by agreement
 * (each value's z-test, Sidak-corrected; the image means; 4 x 4 blocks' chi-square) or,
 * for a deterministic image, value by value to 1e-2. Every render runs in a child
 * process with a time limit, so a hang or a crash is a verdict, not a stuck test. Each
 * program prints a row per case: case, chapter, judged, verdict, seconds, and the
 * numbers behind the verdict. docs/metamorphic.md derives the tests and their levels.
 */
#ifndef METAMORPHIC_H
#define METAMORPHIC_H

#include <errno.h>
#include <math.h>
#include <poll.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "chi_square.h"
#include "metamorphic_scenes.h"
#include "scene_file.h"

/* Each comparison's significance level; the image means' z at most; a render's time. */
#define METAMORPHIC_LEVEL 1e-4
#define MEAN_SIGMAS 4.0
#define RENDER_SECONDS 30

/* ---- rendering, in a child process ----------------------------------------------- */

/* An image as doubles, with each value's standard error (NULL: the render is exact, a
 * deterministic one), `samples` behind each standard error, and whether its pixels are
 * independent (so that the image mean's standard error follows from theirs). */
typedef struct {
    int width, height, samples, independent;
    double *value, *error;
} Rendering;

/* A chapter's render of a scene (its text, and as read) with a seed: 0, or -1. */
typedef int (*RenderScene)(const char *text, const Scene *scene, uint64_t seed, Rendering *out);

static inline void rendering_free(Rendering *r)
{
    free(r->value);
    free(r->error);
    memset(r, 0, sizeof *r);
}

static inline int write_all(int fd, const void *data, size_t size)
{
    for (size_t done = 0; done < size;) {
        ssize_t n = write(fd, (const char *)data + done, size - done);
        if (n < 0 && errno != EINTR)
            return -1;
        done += n > 0 ? (size_t)n : 0;
    }
    return 0;
}

static inline double now_seconds(void)
{
    struct timespec now;
    clock_gettime(CLOCK_MONOTONIC, &now);
    return now.tv_sec + 1e-9 * now.tv_nsec;
}

/* Read `size` bytes or fail by the deadline. Returns 0, or -1. */
static inline int read_by(int fd, void *data, size_t size, double deadline)
{
    for (size_t done = 0; done < size;) {
        int left = (int)((deadline - now_seconds()) * 1000.0);
        struct pollfd p = {fd, POLLIN, 0};
        if (left <= 0 || poll(&p, 1, left) <= 0)
            return -1;
        ssize_t n = read(fd, (char *)data + done, size - done);
        if (n <= 0)
            return -1;
        done += (size_t)n;
    }
    return 0;
}

/* Read the scene text and render it with `render` in a child process, which sends the
 * image back through a pipe; the child is killed if it has not finished within
 * RENDER_SECONDS. Returns 0; -1 with `why` (the scene refused, the render failed or
 * crashed) or -2 (no answer in time). */
static inline int render_text(const char *text, RenderScene render, uint64_t seed,
                              Rendering *out, char *why, size_t why_size)
{
    memset(out, 0, sizeof *out);
    int ends[2];
    assert_int_equal(pipe(ends), 0);
    fflush(NULL);
    pid_t child = fork();
    assert_true(child >= 0);
    if (child == 0) { /* a crash ends the child, not a test framework's handler */
        const int crashes[] = {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT};
        for (int i = 0; i < 5; i++)
            signal(crashes[i], SIG_DFL);
        close(ends[0]);
        Scene scene;
        char error[512];
        Rendering r;
        int status =
            scene_parse(text, strlen(text), "scene", &scene, NULL, error, sizeof error);
        if (status != 0) {
            fprintf(stderr, "%s\n", error);
            _exit(3);
        }
        if (render(text, &scene, seed, &r) != 0)
            _exit(4);
        long n = 3L * r.width * r.height;
        int header[4] = {r.width, r.height, r.samples,
                         (r.error != NULL) | (r.independent << 1)};
        if (write_all(ends[1], header, sizeof header) != 0 ||
            write_all(ends[1], r.value, (size_t)n * sizeof *r.value) != 0 ||
            (r.error && write_all(ends[1], r.error, (size_t)n * sizeof *r.error) != 0))
            _exit(5);
        _exit(0);
    }
    close(ends[1]);
    double deadline = now_seconds() + RENDER_SECONDS;
    int header[4], result = -1;
    if (read_by(ends[0], header, sizeof header, deadline) == 0) {
        long n = 3L * header[0] * header[1];
        *out = (Rendering){header[0],
                           header[1],
                           header[2],
                           header[3] >> 1,
                           malloc((size_t)n * sizeof(double)),
                           header[3] & 1 ? malloc((size_t)n * sizeof(double)) : NULL};
        assert_non_null(out->value);
        if (read_by(ends[0], out->value, (size_t)n * sizeof(double), deadline) == 0 &&
            (!out->error ||
             read_by(ends[0], out->error, (size_t)n * sizeof(double), deadline) == 0))
            result = 0;
    }
    int timed_out = result != 0 && now_seconds() >= deadline;
    if (result != 0)
        kill(child, SIGKILL);
    int status;
    while (waitpid(child, &status, 0) < 0 && errno == EINTR)
        ;
    close(ends[0]);
    if (result == 0)
        return 0;
    rendering_free(out);
    if (timed_out) {
        snprintf(why, why_size, "no image within %d s (a hang)", RENDER_SECONDS);
        return -2;
    }
    if (WIFSIGNALED(status))
        snprintf(why, why_size, "the render crashed (signal %d)", WTERMSIG(status));
    else
        snprintf(why, why_size, "%s",
                 WEXITSTATUS(status) == 3 ? "the scene was refused" : "the render failed");
    return -1;
}

/* ---- judging --------------------------------------------------------------------- */

typedef struct {
    int pass;
    char detail[256];
} Verdict;

/* A standard error estimated from n samples makes (a - b) / se Student's t with about
 * n - 1 degrees of freedom, whose tails are heavier than the normal's (with 7, as the
 * reference's batches give, |t| > 4.4 is 100 times likelier): Bailey's transformation
 * turns it into a standard normal z. */
static inline double t_as_z(double t, double nu)
{
    return t * (1.0 - 1.0 / (4.0 * nu)) / sqrt(1.0 + t * t / (2.0 * nu));
}

/* Where the arithmetic is exact: every value (and standard error) the same. */
static inline Verdict judge_bit(const Rendering *a, const Rendering *b, double factor)
{
    long n = 3L * a->width * a->height, differ = 0;
    for (long i = 0; i < n; i++)
        differ += a->value[i] != b->value[i] * factor ||
                  (a->error && a->error[i] != b->error[i] * factor);
    Verdict v = {differ == 0, ""};
    snprintf(v.detail, sizeof v.detail, "%ld of %ld values differ", differ, n);
    return v;
}

/* A deterministic image whose arithmetic changed: at most 1% of its values off by more
 * than 1e-2. A change of rounding moves a few pixel centres across an edge, and paths
 * between the facing mirrors and the mirror ball are chaotic and amplify it, so some
 * values change; a bug (acne, a lost reflection) changes whole surfaces. */
static inline Verdict judge_deterministic(const Rendering *a, const Rendering *b, double factor)
{
    long n = 3L * a->width * a->height, differ = 0;
    double worst = 0.0;
    for (long i = 0; i < n; i++) {
        double x = a->value[i], y = b->value[i] * factor;
        double relative = fabs(x - y) / fmax(fmax(fabs(x), fabs(y)), 1e-300);
        differ += relative > 1e-2;
        worst = fmax(worst, relative);
    }
    Verdict v = {differ <= n / 100, ""};
    snprintf(v.detail, sizeof v.detail,
             "%ld of %ld values off by more than 1e-2 (at most %ld "
             "may be), the largest by %.2g",
             differ, n, n / 100, worst);
    return v;
}

/* The block test: for each BLOCK x BLOCK block of pixels and channel, z of the two
 * block means (their standard errors from the pixels', which are independent); the sum
 * of z^2 over the blocks is chi-square with as many degrees of freedom. It sees a
 * change spread thinly over many pixels, which no single pixel shows. */
enum {
    BLOCK = 4
};

static inline double block_chi_square_p(const Rendering *a, const Rendering *b, double factor)
{
    double sum_z2 = 0.0;
    int dof = 0;
    for (int by = 0; by + BLOCK <= a->height; by += BLOCK)
        for (int bx = 0; bx + BLOCK <= a->width; bx += BLOCK)
            for (int c = 0; c < 3; c++) {
                double difference = 0.0, variance = 0.0;
                for (int y = by; y < by + BLOCK; y++)
                    for (int x = bx; x < bx + BLOCK; x++) {
                        long i = 3L * ((long)y * a->width + x) + c;
                        double eb = b->error[i] * factor;
                        difference += a->value[i] - b->value[i] * factor;
                        variance += a->error[i] * a->error[i] + eb * eb;
                    }
                if (variance > 0.0) {
                    sum_z2 += difference * difference / variance;
                    dof++;
                }
            }
    return dof > 0 ? chi_square_p_value(sum_z2, dof) : 1.0;
}

/* Two Monte Carlo images of one expectation: each value's z (t_as_z), the smallest
 * two-sided p against Sidak's 1 - (1 - LEVEL)^(1 / N) over the N values, as
 * tests/agreement.h; where the pixels are independent, also the image means within
 * MEAN_SIGMAS standard errors and the blocks' chi-square above LEVEL. */
static inline Verdict judge_statistical(const Rendering *a, const Rendering *b, double factor)
{
    long n = 3L * a->width * a->height;
    double nu = fmin(a->samples, b->samples) - 1.0;
    double smallest_p = 1.0, worst_z = 0.0, sum_a = 0.0, sum_b = 0.0, var_a = 0.0, var_b = 0.0;
    long tests = 0, at = -1;
    for (long i = 0; i < n; i++) {
        double x = a->value[i], y = b->value[i] * factor;
        double ea = a->error[i], eb = b->error[i] * factor;
        sum_a += x;
        sum_b += y;
        var_a += ea * ea;
        var_b += eb * eb;
        double spread = sqrt(ea * ea + eb * eb);
        if (spread == 0.0 && x == y)
            continue;
        tests++;
        double z = spread > 0.0 ? t_as_z((x - y) / spread, nu) : INFINITY;
        double p = erfc(fabs(z) / sqrt(2.0));
        if (p < smallest_p || at < 0) {
            smallest_p = p;
            worst_z = z;
            at = i;
        }
    }
    double level = tests > 0 ? -expm1(log1p(-METAMORPHIC_LEVEL) / tests) : METAMORPHIC_LEVEL;
    int independent = a->independent && b->independent;
    double mean_z = var_a + var_b > 0.0 ? (sum_a - sum_b) / sqrt(var_a + var_b)
                                        : (sum_a == sum_b ? 0.0 : INFINITY);
    double blocks_p = independent ? block_chi_square_p(a, b, factor) : 1.0;
    Verdict v = {smallest_p >= level && (!independent || fabs(mean_z) <= MEAN_SIGMAS) &&
                     blocks_p >= METAMORPHIC_LEVEL,
                 ""};
    if (independent)
        snprintf(v.detail, sizeof v.detail,
                 "means %.5f and %.5f (z %+.2f); blocks p %.2g; "
                 "smallest p %.2g (z %+.2f at pixel %ld,%ld), Sidak level %.2g over %ld values",
                 sum_a / n, sum_b / n, mean_z, blocks_p, smallest_p, worst_z, at / 3 % a->width,
                 at / 3 / a->width, level, tests);
    else
        snprintf(
            v.detail, sizeof v.detail,
            "smallest p %.2g (z %+.2f at pixel %ld,%ld), Sidak level "
            "%.2g over %ld values (means %.5f and %.5f, not judged: the pixels share photons)",
            smallest_p, worst_z, at / 3 % a->width, at / 3 / a->width, level, tests, sum_a / n,
            sum_b / n);
    return v;
}

static inline Verdict judge(const Rendering *a, const Rendering *b, Judged judged,
                            double factor)
{
    if (a->width != b->width || a->height != b->height) {
        Verdict v = {0, "the images differ in size"};
        return v;
    }
    if (judged == JUDGED_BIT)
        return judge_bit(a, b, factor);
    return a->error && b->error ? judge_statistical(a, b, factor)
                                : judge_deterministic(a, b, factor);
}

/* ---- the cases, run ---------------------------------------------------------------- */

typedef struct {
    const char *chapter; /* what renders, for the table */
    RenderScene render;
    int point_lights;  /* the scenes lit by point lights (chapter 1) */
    int hashes_points; /* hashes the bits of points, so a power of two scaling is not
                          exact: judged by agreement */
} Renderer;

/* The text of `c`'s scene, its base change applied, then (`changed`) its changes. */
static inline char *case_text(const Case *c, int point_lights, int changed)
{
    SceneText scene;
    base_scene(c->scene, point_lights, &scene);
    apply_change(&scene, c->base);
    for (int i = 0; changed && i < 2; i++)
        apply_change(&scene, c->changed[i]);
    return scene_text_write(&scene);
}

/* Bases are shared by the cases that start from the same scene: kept here. */
typedef struct {
    SceneKind scene;
    Change base;
    Rendering image;
    int status;
    char why[160];
} BaseImage;

static inline const BaseImage *base_image(const Case *c, const Renderer *r, BaseImage *cache,
                                          int *cached)
{
    for (int i = 0; i < *cached; i++)
        if (cache[i].scene == c->scene && cache[i].base.kind == c->base.kind &&
            cache[i].base.amount == c->base.amount)
            return &cache[i];
    BaseImage *b = &cache[(*cached)++];
    b->scene = c->scene;
    b->base = c->base;
    char *text = case_text(c, r->point_lights, 0);
    b->status = render_text(text, r->render, 1, &b->image, b->why, sizeof b->why);
    free(text);
    return b;
}

/* Run every case with renderer r, print a row for each and a table at the end; fail
 * the test if any case fails. */
static inline void run_cases(const Renderer *r)
{
    static BaseImage cache[CASE_COUNT];
    int cached = 0, failures = 0;
    char rows[CASE_COUNT][128];
    for (int k = 0; k < CASE_COUNT; k++) {
        const Case *c = &CASES[k];
        double start = now_seconds();
        const BaseImage *base = base_image(c, r, cache, &cached);
        Judged judged = c->judged;
        if (r->hashes_points && c->changed[0].kind == CHANGE_SCALE)
            judged = JUDGED_AGREE;
        Verdict v = {0, ""};
        Rendering changed = {0};
        char *text = case_text(c, r->point_lights, 1);
        if (base->status != 0)
            snprintf(v.detail, sizeof v.detail, "the scene itself: %s", base->why);
        else if (render_text(text, r->render, judged == JUDGED_BIT ? 1 : 2, &changed, v.detail,
                             sizeof v.detail) == 0)
            v = judge(&base->image, &changed, judged, radiance_factor(c, r->point_lights));
        free(text);
        rendering_free(&changed);
        double seconds = now_seconds() - start;
        const char *verdict = v.pass ? (judged == JUDGED_BIT ? "same" : "agree")
                                     : (judged == JUDGED_BIT ? "DIFFERENT" : "DISAGREE");
        if (strstr(v.detail, "hang"))
            verdict = "HANG";
        if (strstr(v.detail, "crashed"))
            verdict = "CRASH";
        failures += !v.pass;
        snprintf(rows[k], sizeof rows[k], "%-28s %-10s %-6s %-10s %7.2f", c->name, r->chapter,
                 judged == JUDGED_BIT ? "bit" : "agree", verdict, seconds);
        print_message("    %s\n        %s\n", rows[k], v.detail);
    }
    print_message("\n    %-28s %-10s %-6s %-10s %7s\n", "case", "chapter", "judged", "verdict",
                  "seconds");
    for (int k = 0; k < CASE_COUNT; k++)
        print_message("    %s\n", rows[k]);
    for (int i = 0; i < cached; i++)
        rendering_free(&cache[i].image);
    if (failures)
        fail_msg("%d of %d cases failed", failures, CASE_COUNT);
}

#endif
