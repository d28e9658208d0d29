/* chapter2.c (bench, chapter 2): chapter 2's exercises and their graders (grading.h).
 *
 * The cosine sampler by the warp test against its exact density (a ring between
 * heights a < b holds b^2 - a^2 of the samples, a sector 1 / 12) and by its moments,
 * each over replicates of stratified inputs (grading.h); its pdf and the
 * Lambert BRDF against their closed forms, the BRDF also through the white furnace
 * it would make (L = Le / (1 - pi f)); the path tracer by its paths against the
 * solution's from the same random numbers (the student's own cosine directions replayed
 * in them) and by its image against the solution's, pixel by pixel. Seeds from
 * GRADE_SEED; the course's level (grading.h).
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "grading.h"
#include "hemisphere.h"
#include "lambert.h"
#include "path.h"
#include "pixel_sampling.h"
#include "render_check.h"

#define LEVEL grading_level()
#define RINGS 10
#define SECTORS 12
/* The cosine sampler's inputs: COSINE_REPLICATES replicates of a jittered grid of
 * COSINE_GRID x COSINE_GRID (u1, u2) (grading_stratify), 1,048,576 samples. */
#define COSINE_GRID 64
#define COSINE_REPLICATES 256
#define WARP_SAMPLES ((long)COSINE_REPLICATES * COSINE_GRID * COSINE_GRID)

/* Sample i of the stream: its (u1, u2), point i of a replicate of `strata`, and the
 * direction the student's sampler makes of them. */
static Vec3 ask_cosine_sample(Grading *g, uint64_t stream, const Strata *strata, long i,
                              double *u1, double *u2)
{
    Rng rng = rng_for_sample(grading_stream(g, stream), 1, (uint64_t)i);
    double u[2];
    rng_pair(&rng, &u[0], &u[1]);
    grading_stratify(strata, i, u);
    *u1 = u[0], *u2 = u[1];
    return ASK_VEC3(g, hemisphere_sample_cosine(*u1, *u2));
}

/* The moments of the density cos(theta) / pi: E z = 2/3, E z^2 = 1/2, E x = E y = E x y
 * = 0, E x^2 = E y^2 = 1/4. */
#define MOMENTS 7
static const char *const moment_names[MOMENTS] = {
    "the mean cos(theta)", "the mean cos^2(theta)", "the mean x",  "the mean x^2",
    "the mean y",          "the mean y^2",          "the mean x y"};
static const double moment_exact[MOMENTS] = {2.0 / 3.0, 0.5, 0.0, 0.25, 0.0, 0.25, 0.0};

static void grade_cosine_sample(Grading *g)
{
    const WarpLabels labels = {"ring", "nearest the pole", "nearest the horizon",
                               "sector around the normal",
                               "below the surface, off the unit sphere or at NaN"};
    const Strata strata = grading_strata(2, (const int[]){COSINE_GRID, COSINE_GRID});
    Warp warp; /* the picture shows the first replicate */
    if (warp_new(g, &warp, RINGS, SECTORS, (int)strata.cells, labels) != 0)
        return;
    static double moments[MOMENTS][COSINE_REPLICATES]; /* each replicate's means */
    memset(moments, 0, sizeof moments);
    long identical = 0;
    for (long i = 0; i < WARP_SAMPLES; i++) {
        double u1, u2;
        Vec3 w = ask_cosine_sample(g, 21, &strata, i, &u1, &u2);
        warp_add_hemisphere(&warp, i, u1, u2, w);
        if (grading_probing(g))
            continue;
        identical += vec3_length(vec3_sub(w, hemisphere_sample_cosine(u1, u2))) <= 1e-12;
        const double values[MOMENTS] = {w.z, w.z * w.z, w.x,      w.x * w.x,
                                        w.y, w.y * w.y, w.x * w.y};
        for (int k = 0; k < MOMENTS; k++)
            moments[k][i / strata.cells] += values[k] / strata.cells;
    }
    const char *hint = "is cos(theta) = sqrt(1 - u1), sin(theta) = sqrt(u1) and phi = 2 pi u2 "
                       "(eq. 12, docs/chapter2.md)?";
    warp_expect_cosine(&warp, WARP_SAMPLES);
    if (!grading_probing(g))
        grading_note(g,
                     "%ld of %ld directions identical to the solution's from the same (u1, u2)",
                     identical, WARP_SAMPLES);
    /* The inputs are stratified, so each cell's count varies less than a multinomial's (a
     * sum of the strata's independent Bernoullis, sum p_i (1 - p_i) <= N p (1 - p)): the
     * warp test is conservative, rejecting a right sampler less often than its level
     * (chi^2 about 25 to 50 on 119 degrees of freedom), and a wrong one's excess stands
     * out of less noise. */
    if (grading_warp(g, &warp, "the hemisphere seen from above", LEVEL, 1, hint) &&
        !grading_probing(g))
        for (int k = 0; k < MOMENTS && !g->failed; k++)
            grading_replicate_test(g, moment_names[k], moments[k], COSINE_REPLICATES,
                                   moment_exact[k], hint);
    warp_free(&warp);
}

/* The pdf at the sampler's own directions (exercise 2.1's): cos(theta) / pi at each, and
 * the solid angle of the cap cos(theta) > 1/2, pi, as the mean of [cos(theta) > 1/2] /
 * pdf, over PDF_REPLICATES replicates of a jittered PDF_GRID x PDF_GRID grid of (u1, u2).
 * The task's sampler maps the cap's rim onto a line between cells (u1 = 3/4), another
 * valid one across cells, each adding noise: a grid finer than 2.1's. */
#define PDF_GRID 96
#define PDF_REPLICATES 64
#define PDF_SAMPLES ((long)PDF_REPLICATES * PDF_GRID * PDF_GRID)
static void grade_pdf_at_samples(Grading *g)
{
    const Strata strata = grading_strata(2, (const int[]){PDF_GRID, PDF_GRID});
    double caps[PDF_REPLICATES] = {0}; /* each replicate's mean */
    long wrong = 0;
    Vec3 first = vec3(0, 0, 0);
    double first_pdf = 0.0;
    for (long i = 0; i < PDF_SAMPLES; i++) {
        double u1, u2;
        Vec3 w = ask_cosine_sample(g, 23, &strata, i, &u1, &u2);
        double pdf = ASK(g, hemisphere_pdf_cosine(w));
        if (grading_probing(g))
            continue;
        if (fabs(pdf - fmax(w.z, 0.0) / PI) > 1e-9) {
            if (!wrong++)
                first = w, first_pdf = pdf;
        }
        caps[i / strata.cells] += (w.z > 0.5 && pdf > 0.0 ? 1.0 / pdf : 0.0) / strata.cells;
    }
    if (grading_probing(g))
        return;
    if (wrong) {
        grading_fail(g,
                     "at %ld of the %ld directions the sampler (exercise 2.1) draws, the pdf "
                     "is not cos(theta) / pi: %.6f at cos(theta) = %.4f, where %.6f is right",
                     wrong, PDF_SAMPLES, first_pdf, first.z, fmax(first.z, 0.0) / PI);
        return;
    }
    grading_replicate_test(g,
                           "the solid angle of the cap cos(theta) > 1/2 from the sampler's "
                           "directions, the mean of [cos(theta) > 1/2] / pdf",
                           caps, PDF_REPLICATES, PI,
                           "the pdf must be the density of the sampler's directions in solid "
                           "angle, cos(theta) / pi");
}

static void grade_cosine_pdf(Grading *g)
{
    int checked = 0;
    for (int i = 0; i < 2000 && !g->failed; i++, checked++) {
        TestRandom rng = test_random(grading_stream(g, 22), 1, (uint64_t)i);
        Vec3 w = random_unit_vector(&rng);
        double pdf = ASK(g, hemisphere_pdf_cosine(w)), right = w.z > 0.0 ? w.z / PI : 0.0;
        if (grading_not_finite(g, pdf, "the pdf"))
            break;
        if (w.z <= 0.0 && pdf != 0.0)
            grading_fail(g,
                         "the pdf is %.4f below the surface (z = %.3f), where no sample ever "
                         "goes: it must be 0 there",
                         pdf, w.z);
        else if (w.z > 0.0 && fabs(pdf - right) > 1e-9) {
            double ratio = pdf / right;
            if (fabs(pdf - 1.0 / (2.0 * PI)) < 1e-9)
                grading_fail(g,
                             "the pdf is 1 / (2 pi) = %.4f at every direction: that is the "
                             "uniform hemisphere's; the cosine sampler's grows with cos(theta)",
                             pdf);
            else if (fabs(ratio - PI) < 1e-6)
                grading_fail(
                    g,
                    "the pdf is pi times too large (%.4f at cos(theta) = %.3f where "
                    "cos(theta) / pi = %.4f): a missing 1 / pi; it integrates to pi, not "
                    "1",
                    pdf, w.z, right);
            else
                grading_fail(g,
                             "the pdf is %.*f at cos(theta) = %.3f, where cos(theta) / pi = "
                             "%.*f",
                             grading_decimals(pdf, right), pdf, w.z,
                             grading_decimals(pdf, right), right);
        }
    }
    grading_note(g,
                 "%d random directions over the whole sphere against cos(theta) / pi above "
                 "the surface, 0 below",
                 checked);
    grade_pdf_at_samples(g);
}

static void grade_lambert(Grading *g)
{
    const double rho[3] = {0.5, 0.25, 0.8};
    Vec3 f = ASK_VEC3(g, lambert_brdf(vec3(rho[0], rho[1], rho[2])));
    double got[3] = {f.x, f.y, f.z};
    grading_note(g,
                 "f(rho = (%.2f, %.2f, %.2f)) = (%.4f, %.4f, %.4f); rho / pi = (%.4f, %.4f, "
                 "%.4f)",
                 rho[0], rho[1], rho[2], got[0], got[1], got[2], rho[0] / PI, rho[1] / PI,
                 rho[2] / PI);
    for (int c = 0; c < 3; c++) {
        if (grading_not_finite(g, got[c], "f"))
            return;
        if (fabs(got[c] - rho[c] / PI) <= 1e-12)
            continue;
        /* A box of albedo pi f everywhere, emitting Le = 1: L = Le / (1 - pi f). */
        double albedo = PI * got[c];
        char furnace[200];
        if (albedo >= 1.0)
            snprintf(furnace, sizeof furnace,
                     "a furnace box of rho = %.2f would reflect %.2f of "
                     "what arrives, and its light would grow without bound",
                     rho[c], albedo);
        else
            snprintf(furnace, sizeof furnace,
                     "a furnace box of rho = %.2f emitting 1 gives L = "
                     "%.2f where 1 / (1 - rho) = %.2f is exact",
                     rho[c], 1.0 / (1.0 - albedo), 1.0 / (1.0 - rho[c]));
        int decimals = grading_decimals(got[c], rho[c] / PI);
        grading_fail(g, "f = %.*f for rho = %.2f, where rho / pi = %.*f: %s (%s)", decimals,
                     got[c], rho[c], decimals, rho[c] / PI, furnace,
                     fabs(got[c] - rho[c]) < 1e-12
                         ? "a missing 1 / pi?"
                         : "f cos integrated over the hemisphere must be rho");
        return;
    }
}

static const PathSettings path_settings = {.max_depth = 4};
static const RenderCheck path_check = {
    render_check_room, path_radiance, &path_settings, 24, 64, 2048};

/* A lamp in mid-air, facing down, between a floor and a ceiling, seen from above (its
 * back, and the floor it lights around it), from below (its front) and along the floor
 * at a grazing angle (the floor a little tilted, so that its hit points lie off it by
 * rounding, and a sphere); and the room. */
#define MID_AIR                                                                                \
    "material white lambert 0.7 0.5 0.3\n"                                                     \
    "material lamp light 4 3 2\n"                                                              \
    "quad lamp -0.5 -0.5 0   -0.5 0.5 0   0.5 0.5 0   0.5 -0.5 0\n"                            \
    "quad white -5 -5 -1.037   5 -5 -0.983   5 5 -0.961   -5 5 -1.015\n"                       \
    "quad white -5 -5 1   -5 5 1   5 5 1   5 -5 1\n"                                           \
    "sphere white 1.3 0.9 -0.62 0.37\n"

typedef struct {
    const char *scene, *name;
    const char *hint; /* what makes it too bright, or NULL */
} PathView;

static const PathView path_views[] = {
    {render_check_room, "the room", NULL},
    {"camera 0 0 0.8   -0.6 -0.6 0.3   0.6 -0.6 0.3   -0.6 0.6 0.3\n" MID_AIR,
     "a lamp in mid-air seen from above (its back)",
     "a lamp emits from its front only: add its emission where the path arrives on the front "
     "(x.front)"},
    {"camera 0 0 -0.8   -0.6 -0.6 -0.3   0.6 -0.6 -0.3   -0.6 0.6 -0.3\n" MID_AIR,
     "a lamp in mid-air seen from below (its front)", NULL},
    {"camera 0 -4 -0.9   -0.5 -3 -1   0.5 -3 -1   -0.5 -3 -0.7\n" MID_AIR,
     "a floor seen at a grazing angle under a lamp in mid-air", NULL},
};
#define PATH_VIEWS (int)(sizeof path_views / sizeof path_views[0])
#define PATH_GRID 8
#define PATH_SAMPLES 256

/* Exercise 2.4's paths paired through the student's own directions. Another valid cosine
 * sampler than the task's (exercise 2.1: the concentric disk) turns the same (u1, u2)
 * into other directions: the student's paths part from the solution's, and the paired
 * test is left with unpaired noise. So the probe records every call the student's
 * path_radiance makes to hemisphere_sample_cosine, its (u1, u2) and the direction it
 * returned, and the judge replays those directions, in order, in the solution's path from
 * the same random numbers: a right path_radiance then gives the solution's path exactly,
 * whatever valid mapping 2.1 uses, and a wrong one differs only by its mistake. The
 * linker puts __wrap_hemisphere_sample_cosine between the sampler and every call from
 * another object (ld --wrap: the Makefile's grader_wraps), so the lesson holds no hook.
 * A replay holds when every call the solution's path makes asks the (u1, u2) recorded for
 * it, or the two swapped (rng_pair(rng, &u2, &u1): as valid), and every direction is a
 * unit vector above the surface. A call beyond the recorded ones (a path longer than the
 * student's) is the solution's own sampler's: given the path so far, its direction has
 * the same density. */
#define SAMPLER_CALLS 16 /* recorded per path: a right one makes at most max_depth - 1 */

typedef struct {
    double u1, u2;
    Vec3 w;
} SamplerCall;

typedef enum {
    SAMPLER_DIRECT,
    SAMPLER_RECORD,
    SAMPLER_REPLAY
} SamplerMode;

static struct {
    SamplerMode mode;
    SamplerCall calls[SAMPLER_CALLS];
    long count;      /* calls recorded, those beyond SAMPLER_CALLS not kept; or to replay */
    long next;       /* the next call to replay */
    long mismatched; /* replayed calls that asked other (u1, u2) than the recorded */
    long other;      /* replayed directions other than the solution's sampler's */
} sampler;

/* Whether a recorded call asked (u1, u2), in either order. */
static int asked(const SamplerCall *call, double u1, double u2)
{
    return (call->u1 == u1 && call->u2 == u2) || (call->u1 == u2 && call->u2 == u1);
}

Vec3 __real_hemisphere_sample_cosine(double u1, double u2);
Vec3 __wrap_hemisphere_sample_cosine(double u1, double u2);

Vec3 __wrap_hemisphere_sample_cosine(double u1, double u2)
{
    Vec3 w = __real_hemisphere_sample_cosine(u1, u2);
    if (sampler.mode == SAMPLER_RECORD) {
        if (sampler.count < SAMPLER_CALLS)
            sampler.calls[sampler.count] = (SamplerCall){u1, u2, w};
        sampler.count++;
    } else if (sampler.mode == SAMPLER_REPLAY && sampler.next < sampler.count) {
        const SamplerCall *call = &sampler.calls[sampler.next++];
        if (!asked(call, u1, u2)) {
            sampler.mismatched++;
            return w;
        }
        sampler.other += vec3_length(vec3_sub(call->w, w)) > 1e-12;
        return call->w;
    }
    return w;
}

/* The calls recorded in the probe's last path, sent, a count first; in the judge,
 * received for the replay. Returns 1 when they can be replayed: all kept, each direction
 * a unit vector above the surface (as exercise 2.1's warp test wants them). */
static int ask_sampler_calls(Grading *g)
{
    double count = ASK(g, (double)sampler.count);
    long kept = (long)fmin(fmax(count, 0.0), SAMPLER_CALLS);
    int replayable = count == (double)kept;
    for (long k = 0; k < kept; k++) {
        SamplerCall *call = &sampler.calls[k];
        call->u1 = ASK(g, call->u1);
        call->u2 = ASK(g, call->u2);
        call->w = ASK_VEC3(g, call->w);
        replayable &= fabs(vec3_length(call->w) - 1.0) < 1e-6 && call->w.z > 0.0;
    }
    sampler.count = kept;
    return replayable;
}

/* The paired differences of one view: your path minus the solution's from the same
 * random numbers. */
typedef struct {
    long samples, differ, darker, bounces_differ;
    long unlike_deeper,
        unlike_shallower; /* paths unlike the solution's with max_depth + 1, - 1 */
    long unreplayed;      /* paths whose calls of the sampler could not be replayed */
    long replayed_other;  /* directions replayed that the solution's sampler would not give */
    double yours, solution, difference, difference2;
} PathPairs;

#define VIEW_PATHS (PATH_GRID * PATH_GRID * PATH_SAMPLES)

/* Path `index` of a view, through a random point of pixel index / PATH_SAMPLES of a
 * PATH_GRID^2 grid: its camera ray, and its generator in *rng. */
static Ray path_start(const Grading *g, const Scene *scene, int view, int index, Rng *rng)
{
    int pixel = index / PATH_SAMPLES, k = index % PATH_SAMPLES;
    TestRandom where = test_random(grading_stream(g, 24), (uint64_t)view, (uint64_t)index);
    double u = test_uniform(&where), v = test_uniform(&where);
    *rng = rng_for_sample(grading_stream(g, 25), (uint64_t)(view * 4096 + pixel), (uint64_t)k);
    return camera_ray(&scene->camera, PATH_GRID, PATH_GRID, pixel % PATH_GRID,
                      pixel / PATH_GRID, u, v);
}

/* The solution's path from the generator rng with max_depth + `more` segments, the
 * recorded directions replayed when `replay`: its radiance summed over the channels, and
 * its bounces in *bounces. */
static double solution_path(const Scene *scene, Ray ray, Rng rng, int more, int replay,
                            long *bounces)
{
    PathSettings settings = path_settings;
    settings.max_depth += more;
    RayCounts counts = {0};
    sampler.mode = replay ? SAMPLER_REPLAY : SAMPLER_DIRECT;
    sampler.next = 0;
    Vec3 radiance = path_radiance(scene, ray, &rng, &settings, &counts);
    sampler.mode = SAMPLER_DIRECT;
    *bounces = (long)counts.bounce;
    return radiance.x + radiance.y + radiance.z;
}

/* Whether a path's radiance a differs from the solution's b beyond rounding. */
static int radiance_differs(double a, double b) { return fabs(a - b) > 1e-12 + 1e-9 * fabs(b); }

/* Your path's radiance a (summed over the channels) against the solution's b. */
static void pair_add(PathPairs *pairs, double a, double b, int bounces_differ)
{
    pairs->samples++;
    pairs->yours += a;
    pairs->solution += b;
    pairs->difference += a - b;
    pairs->difference2 += (a - b) * (a - b);
    int differs = radiance_differs(a, b);
    pairs->differ += differs;
    pairs->darker += differs && a < b;
    pairs->bounces_differ += bounces_differ;
}

/* Whether the radiance a differs from the solution's path with max_depth + `more`. */
static int unlike_path(const Scene *scene, Ray ray, Rng rng, int more, int replay, double a)
{
    long bounces;
    return radiance_differs(a, solution_path(scene, ray, rng, more, replay, &bounces));
}

/* Your paths' radiance and bounces, kept for a second pairing (paired_unreplayed). */
static double view_yours[VIEW_PATHS], view_bounces[VIEW_PATHS];

/* One view's paths, each paired with the solution's path from the same random numbers
 * that takes your sampler's directions. */
static void path_pairs(Grading *g, const Scene *scene, int view, PathPairs *pairs)
{
    for (int i = 0; i < VIEW_PATHS; i++) {
        Rng rng;
        Ray ray = path_start(g, scene, view, i, &rng);
        RayCounts counts = {0};
        Vec3 got = vec3(0, 0, 0);
        sampler.count = 0;
        if (grading_probing(g)) {
            Rng mine = rng;
            sampler.mode = SAMPLER_RECORD;
            got = path_radiance(scene, ray, &mine, &path_settings, &counts);
            sampler.mode = SAMPLER_DIRECT;
        }
        got = ASK_VEC3(g, got);
        double bounces = ASK(g, (double)counts.bounce);
        int replay = ask_sampler_calls(g);
        if (grading_not_finite(g, got.x + got.y + got.z, "the radiance"))
            break;
        if (grading_probing(g))
            continue;
        double a = got.x + got.y + got.z;
        long right_bounces;
        sampler.mismatched = sampler.other = 0;
        double b = solution_path(scene, ray, rng, 0, replay, &right_bounces);
        pairs->unreplayed += !replay || sampler.mismatched > 0;
        pairs->replayed_other += sampler.other;
        pair_add(pairs, a, b, bounces != (double)right_bounces);
        view_yours[i] = a, view_bounces[i] = bounces;
        pairs->unlike_deeper += unlike_path(scene, ray, rng, 1, replay, a);
        pairs->unlike_shallower += unlike_path(scene, ray, rng, -1, replay, a);
    }
}

/* The pairs again against the solution's own paths, where some of yours could not be
 * replayed: unpaired where your directions differ from its sampler's. */
static void paired_unreplayed(const Grading *g, const Scene *scene, int view, PathPairs *pairs)
{
    PathPairs own = {.unlike_deeper = pairs->unlike_deeper,
                     .unlike_shallower = pairs->unlike_shallower,
                     .unreplayed = pairs->unreplayed};
    for (long i = 0; i < pairs->samples; i++) {
        Rng rng;
        Ray ray = path_start(g, scene, view, (int)i, &rng);
        long bounces;
        double b = solution_path(scene, ray, rng, 0, 0, &bounces);
        pair_add(&own, view_yours[i], b, view_bounces[i] != (double)bounces);
    }
    *pairs = own;
}

/* One view's pairs (path_pairs), against the solution's own paths when yours cannot be
 * replayed (paired_unreplayed). */
static void view_pairs(Grading *g, int view, PathPairs *pairs)
{
    memset(pairs, 0, sizeof *pairs);
    Scene scene;
    if (grading_scene(g, path_views[view].scene, &scene) != 0)
        return;
    path_pairs(g, &scene, view, pairs);
    if (!grading_probing(g) && !g->failed && pairs->unreplayed > 0)
        paired_unreplayed(g, &scene, view, pairs);
    scene_free(&scene);
}

/* What the pairing of a view took of your directions, when not the solution's own. */
static void note_replay(Grading *g, int view, const PathPairs *p)
{
    if (p->unreplayed > 0)
        grading_note(g,
                     "%s: in %ld of %ld paths your calls of the cosine sampler (exercise 2.1) "
                     "could not be replayed in the solution's path (it asked other (u1, u2), "
                     "or a direction was no unit vector above the surface): compared with the "
                     "solution's own paths instead, unpaired where your directions differ",
                     path_views[view].name, p->unreplayed, p->samples);
    else if (p->replayed_other > 0)
        grading_note(g,
                     "%s: the solution's paths took your sampler's directions (exercise 2.1), "
                     "%ld of them other than its own sampler's from the same (u1, u2)",
                     path_views[view].name, p->replayed_other);
}

/* The paths against the solution's, view by view: a paired z-test of the mean radiance at
 * the course's level, exact where the random numbers are used as the solution uses them,
 * whatever valid mapping the sampler of 2.1 is (its directions replayed). */
static void grade_path_pairs(Grading *g)
{
    PathPairs pairs[PATH_VIEWS];
    double z[PATH_VIEWS];
    int worst = -1;
    for (int view = 0; view < PATH_VIEWS && !g->failed; view++) {
        PathPairs *p = &pairs[view];
        view_pairs(g, view, p);
        if (grading_probing(g) || g->failed || p->samples < 2)
            continue;
        long n = p->samples;
        double mean = p->difference / n;
        double se = sqrt(fmax(0.0, p->difference2 / n - mean * mean) / (n - 1));
        z[view] = se > 0.0 ? mean / se : (fabs(mean) <= 1e-12 ? 0.0 : INFINITY);
        grading_note(g,
                     "%s: %ld paths, %ld differ from the solution's from the same random "
                     "numbers; mean radiance %.5f, the solution's %.5f (%+.3f%%, paired z = "
                     "%+.1f; a bias of %.2g detected at power %.2f)",
                     path_views[view].name, n, p->differ, p->yours / (3.0 * n),
                     p->solution / (3.0 * n),
                     p->solution != 0.0 ? 100.0 * (p->yours / p->solution - 1.0) : 0.0, z[view],
                     grading_detectable(se) / 3.0, GRADING_POWER);
        note_replay(g, view, p);
        if (fabs(z[view]) > grading_z(grading_level()) &&
            (worst < 0 || fabs(z[view]) > fabs(z[worst])))
            worst = view;
    }
    if (grading_probing(g) || g->failed)
        return;
    if (worst >= 0) {
        const PathPairs *p = &pairs[worst];
        long n = p->samples;
        double relative = p->solution != 0.0 ? p->yours / p->solution - 1.0 : 0.0;
        const char *hint = relative > 0.0 && path_views[worst].hint
                               ? path_views[worst].hint
                               : "does the path add throughput times the emission on the front "
                                 "of a surface, stop at a light or at max_depth, take each "
                                 "bounce's weight and start each bounce ray off its surface "
                                 "(ray_spawn)?";
        if (p->unlike_deeper == 0)
            hint = "every path equals the solution's with max_depth + 1 segments: the path "
                   "makes one segment too many (stop when segment >= s->max_depth, the camera "
                   "ray being the first)";
        else if (p->unlike_shallower == 0)
            hint = "every path equals the solution's with max_depth - 1 segments: the path "
                   "stops one segment early (the camera ray is segment 1)";
        else if (p->darker >= 0.9 * p->differ && p->differ < n / 4)
            hint =
                "only a few paths differ, nearly all darker: light lost on the way, as when a "
                "bounce ray started exactly on its surface hits that surface again (acne): "
                "ray_spawn(x.hit.point, x.normal, direction, x.hit.scale) moves it off";
        grading_fail(g,
                     "in %s your paths are %.2f%% too %s (mean %.5f where the solution's "
                     "paths from the same random numbers give %.5f; %ld of %ld differ, %ld of "
                     "them darker; paired z = %+.1f): %s",
                     path_views[worst].name, 100.0 * fabs(relative),
                     relative < 0.0 ? "dark" : "bright", p->yours / (3.0 * n),
                     p->solution / (3.0 * n), p->differ, n, p->darker, z[worst], hint);
        return;
    }
    for (int view = 0; view < PATH_VIEWS; view++)
        if (pairs[view].bounces_differ > 0 && pairs[view].differ == 0) {
            grading_fail(g,
                         "in %s the radiance is right but counts->bounce differs from the "
                         "solution's in %ld of %ld paths: count each bounce once "
                         "(counts->bounce++), the camera ray not",
                         path_views[view].name, pairs[view].bounces_differ,
                         pairs[view].samples);
            return;
        }
}

static void grade_path(Grading *g)
{
    grade_path_pairs(g);
    grading_render(
        g, &path_check, LEVEL,
        "does a hit on the front of a light add throughput times its emission, does "
        "the path stop at a light or at max_depth, and does the throughput take each "
        "bounce's weight (docs/chapter2.md)?");
}

/* The sub-pixel counts tried: squares, rows of unequal length, primes, 1; 179 cells. */
static const int subpixel_counts[] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 12, 16, 17, 25, 64};
#define SUBPIXEL_COUNTS (int)(sizeof subpixel_counts / sizeof subpixel_counts[0])
#define SUBPIXEL_CELLS 179
/* Each cell's trials: a replicate, their generators' first two numbers stratified on a
 * JITTER_GRID x JITTER_GRID grid (cell_generators). */
#define JITTER_GRID 16
#define PIXEL_TRIALS (JITTER_GRID * JITTER_GRID)
#define JITTER_CELLS 4

typedef struct {
    long tried, identical, outside, other_cell, neighbour, swapped, draws_wrong;
    int n, s, cell; /* the first misplaced sample: sample s of n in cell `cell` */
    double u, v;
    double jitter[JITTER_CELLS * JITTER_CELLS + 1];
    double means[2][SUBPIXEL_CELLS]; /* each cell's mean ju and jv, a replicate's */
} PixelTally;

/* Which cell of n holds (u, v), or -1. */
static int cell_of(double u, double v, int n)
{
    for (int k = 0; k < n; k++) {
        double u0, v0, w, h;
        pixel_stratum_bounds(k, n, &u0, &v0, &w, &h);
        if (u >= u0 && u < u0 + w && v >= v0 && v < v0 + h)
            return k;
    }
    return -1;
}

/* Sample s of n, cell `replicate` of those tried, drawn from rng, at (u, v); the
 * generator's next number after it was `next`. */
static void tally_subpixel(PixelTally *t, int replicate, int n, int s, Rng rng, double u,
                           double v, double next)
{
    double u0, v0, w, h, right_u, right_v;
    pixel_stratum_bounds(s, n, &u0, &v0, &w, &h);
    pixel_position(PIXEL_SUBPIXELS, s, n, &rng, &right_u, &right_v);
    t->tried++;
    t->identical += fabs(u - right_u) <= 1e-12 && fabs(v - right_v) <= 1e-12;
    t->draws_wrong += next != rng_uniform(&rng);
    if (!(u >= 0.0 && u < 1.0 && v >= 0.0 && v < 1.0)) {
        if (!t->outside++ && !t->other_cell)
            t->n = n, t->s = s, t->cell = -1, t->u = u, t->v = v;
        return;
    }
    if (!(u >= u0 && u < u0 + w && v >= v0 && v < v0 + h)) {
        int k = cell_of(u, v, n);
        if (!t->other_cell++ && !t->outside)
            t->n = n, t->s = s, t->cell = k, t->u = u, t->v = v;
        t->neighbour += k == s - 1 || k == s + 1;
        t->swapped += v >= u0 && v < u0 + w && u >= v0 && u < v0 + h;
        return;
    }
    double ju = (u - u0) / w, jv = (v - v0) / h;
    int cu = (int)(ju * JITTER_CELLS), cv = (int)(jv * JITTER_CELLS);
    t->jitter[(cv < JITTER_CELLS ? cv : JITTER_CELLS - 1) * JITTER_CELLS +
              (cu < JITTER_CELLS ? cu : JITTER_CELLS - 1)] += 1.0;
    t->means[0][replicate] += ju / PIXEL_TRIALS;
    t->means[1][replicate] += jv / PIXEL_TRIALS;
}

/* The generators of the trials of one cell, `cell` of the cells tried: for each of the
 * JITTER_GRID x JITTER_GRID squares of [0, 1)^2, the first generator of the cell's
 * stream whose first two numbers fall in it. Those two numbers, uniform within their
 * square and independent, are a replicate of stratified inputs (grading.h) for any
 * jitter made of them: its mean over the trials is unbiased and far less noisy than
 * over as many independent generators. */
static void cell_generators(Grading *g, int cell, Rng *trials)
{
    char taken[PIXEL_TRIALS] = {0};
    for (int j = 0, filled = 0; filled < PIXEL_TRIALS; j++) {
        Rng rng = rng_for_sample(grading_stream(g, 26), (uint64_t)cell, (uint64_t)j);
        Rng look = rng;
        int row = (int)(rng_uniform(&look) * JITTER_GRID);
        int square = row * JITTER_GRID + (int)(rng_uniform(&look) * JITTER_GRID);
        if (!taken[square]) {
            taken[square] = 1;
            trials[square] = rng;
            filled++;
        }
    }
}

static void grade_pixel_position(Grading *g)
{
    static PixelTally t;
    memset(&t, 0, sizeof t);
    static Rng trials[PIXEL_TRIALS];
    for (int c = 0, cell = 0; c < SUBPIXEL_COUNTS; c++) {
        int n = subpixel_counts[c];
        for (int s = 0; s < n; s++, cell++) {
            cell_generators(g, cell, trials);
            for (int k = 0; k < PIXEL_TRIALS; k++) {
                Rng mine = trials[k];
                double u = 0.0, v = 0.0;
                if (grading_probing(g))
                    pixel_position(PIXEL_SUBPIXELS, s, n, &mine, &u, &v);
                u = ASK(g, u);
                v = ASK(g, v);
                double next = ASK(g, rng_uniform(&mine));
                if (grading_not_finite(g, u + v, "u + v"))
                    return;
                if (!grading_probing(g))
                    tally_subpixel(&t, cell, n, s, trials[k], u, v, next);
            }
        }
    }
    /* The other two ways: a uniform point (u, then v) and the centre. */
    long random_wrong = 0, centre_wrong = 0;
    for (int k = 0; k < 256; k++) {
        Rng rng = rng_for_sample(grading_stream(g, 27), 1, (uint64_t)k), mine = rng;
        double u = 0.0, v = 0.0, cu = 0.0, cv = 0.0;
        if (grading_probing(g)) {
            pixel_position(PIXEL_RANDOM, 0, 16, &mine, &u, &v);
            pixel_position(PIXEL_CENTRE, 0, 1, NULL, &cu, &cv);
        }
        u = ASK(g, u), v = ASK(g, v), cu = ASK(g, cu), cv = ASK(g, cv);
        if (grading_probing(g))
            continue;
        double first = rng_uniform(&rng), second = rng_uniform(&rng);
        random_wrong += u != first || v != second;
        centre_wrong += cu != 0.5 || cv != 0.5;
    }
    if (grading_probing(g))
        return;
    grading_note(g,
                 "%ld sub-pixel samples (n = 1 to 64 cells, each cell %d times): %ld identical "
                 "to the solution's from the same numbers, %ld outside the pixel, %ld in "
                 "another cell than their own",
                 t.tried, PIXEL_TRIALS, t.identical, t.outside, t.other_cell);
    if (t.outside)
        grading_fail(g,
                     "%ld of %ld sub-pixel samples fall outside the pixel: sample %d of %d at "
                     "(u, v) = (%.4f, %.4f), where u and v must lie in [0, 1): is a row's "
                     "width 1 / columns and its height columns / n?",
                     t.outside, t.tried, t.s, t.n, t.u, t.v);
    else if (t.other_cell) {
        double u0, v0, w, h;
        pixel_stratum_bounds(t.s, t.n, &u0, &v0, &w, &h);
        const char *why = t.swapped == t.other_cell ? ": u and v are swapped"
                          : t.neighbour == t.other_cell
                              ? ": each falls into the cell next to its own, an off-by-one"
                              : "";
        grading_fail(g,
                     "%ld of %ld sub-pixel samples fall into another cell than their own: "
                     "sample %d of %d at (u, v) = (%.4f, %.4f) is in cell %d, where its cell "
                     "is u in [%.4f, %.4f), v in [%.4f, %.4f)%s (each of the n samples takes "
                     "one cell: the row's first cell and its number of columns from "
                     "stratum_row)",
                     t.other_cell, t.tried, t.s, t.n, t.u, t.v, t.cell, u0, u0 + w, v0, v0 + h,
                     why);
    } else if (t.draws_wrong)
        grading_fail(g,
                     "after %ld of %ld sub-pixel samples the generator is not where two draws "
                     "leave it: the jitter takes two numbers, u's then v's, no more, no fewer",
                     t.draws_wrong, t.tried);
    else if (random_wrong)
        grading_fail(g,
                     "PIXEL_RANDOM: (u, v) is not the sample's first two numbers, u then v, in "
                     "%ld of 256 samples",
                     random_wrong);
    else if (centre_wrong)
        grading_fail(g, "PIXEL_CENTRE: (u, v) is not (0.5, 0.5), the pixel's centre");
    if (g->failed || t.identical == t.tried)
        return;
    /* Another jitter than the task's: uniform within the cell. */
    Warp warp;
    const WarpLabels labels = {"row of the cell", "its bottom", "its top", "column of the cell",
                               "nowhere"};
    if (warp_new(g, &warp, JITTER_CELLS, JITTER_CELLS, 0, labels) != 0)
        return;
    for (int c = 0; c < JITTER_CELLS * JITTER_CELLS; c++) {
        warp.observed[c] = t.jitter[c];
        warp.expected[c] = (double)t.tried / (JITTER_CELLS * JITTER_CELLS);
    }
    const char *hint = "the jitter is uniform within the cell: u0 + ju w, v0 + jv h";
    /* conservative on stratified inputs (grade_cosine_sample) */
    if (grading_warp(g, &warp, "the jitter within the cells", LEVEL, 1, hint) &&
        grading_replicate_test(g, "the mean jitter across the cell", t.means[0], SUBPIXEL_CELLS,
                               0.5, hint))
        grading_replicate_test(g, "the mean jitter up the cell", t.means[1], SUBPIXEL_CELLS,
                               0.5, hint);
    warp_free(&warp);
}

/* Rays at two triangles and two spheres, from outside and inside, hitting front and back:
 * the vertex against the solution's path_vertex. */
static const char vertex_scene[] = "camera 0 -3 0   -1 -2 -1   1 -2 -1   -1 -2 1\n"
                                   "material white lambert 0.7 0.7 0.7\n"
                                   "material red lambert 0.7 0.1 0.1\n"
                                   "quad white -1 -1 0   1 -1 0.2   1 1 0.1   -1 1 -0.1\n"
                                   "sphere red 0.4 0.3 0.9 0.5\n"
                                   "sphere white -0.6 -0.2 -0.8 0.6\n";
#define VERTEX_RAYS 4000

static void grade_vertex(Grading *g)
{
    Scene scene;
    if (grading_scene(g, vertex_scene, &scene) != 0)
        return;
    long found_wrong = 0, front_wrong = 0, normal_wrong = 0, never_flipped = 0,
         flipped_wrong = 0, wo_wrong = 0, wo_along = 0, material_wrong = 0, point_wrong = 0,
         backs = 0, hits = 0;
    for (int i = 0; i < VERTEX_RAYS; i++) {
        TestRandom r = test_random(grading_stream(g, 28), 1, (uint64_t)i);
        Vec3 origin = vec3_scale(random_unit_vector(&r), 0.2 + 2.5 * test_uniform(&r));
        Vec3 target = vec3_scale(random_unit_vector(&r), 0.8 * test_uniform(&r));
        Ray ray = {origin, vec3_normalize(vec3_sub(target, origin))};
        Vertex x;
        memset(&x, 0, sizeof x);
        x.material = scene.materials;
        int found = grading_probing(g) ? path_vertex(&scene, ray, &x) : 0;
        found = ASK(g, found) != 0.0;
        double front = ASK(g, x.front);
        Vec3 normal = ASK_VEC3(g, x.normal), wo = ASK_VEC3(g, x.wo),
             point = ASK_VEC3(g, x.hit.point);
        double material = ASK(g, (double)(x.material - scene.materials));
        if (grading_probing(g))
            continue;
        Vertex right;
        int right_found = path_vertex(&scene, ray, &right);
        if (found != right_found) {
            found_wrong++;
            continue;
        }
        if (!found)
            continue;
        hits++;
        backs += !right.front;
        front_wrong += (front != 0.0) != right.front;
        if (vec3_length(vec3_sub(point, right.hit.point)) > 1e-9)
            point_wrong++;
        if (vec3_length(vec3_sub(normal, right.normal)) > 1e-9) {
            normal_wrong++;
            never_flipped += vec3_length(vec3_sub(normal, right.hit.normal)) <= 1e-9;
            flipped_wrong += vec3_length(vec3_add(normal, right.normal)) <= 1e-9;
        }
        if (vec3_length(vec3_sub(wo, right.wo)) > 1e-9) {
            wo_wrong++;
            wo_along += vec3_length(vec3_sub(wo, ray.dir)) <= 1e-9;
        }
        material_wrong += material != (double)(right.material - scene.materials);
    }
    scene_free(&scene);
    if (grading_probing(g))
        return;
    grading_note(g, "%d rays: %ld hits, %ld of them on the back of their surface", VERTEX_RAYS,
                 hits, backs);
    if (found_wrong)
        grading_fail(g,
                     "%ld of %d rays find a surface where the solution's path_vertex does not, "
                     "or none where it does: the vertex is the first hit, scene_intersect",
                     found_wrong, VERTEX_RAYS);
    else if (point_wrong)
        grading_fail(g, "the hit point is not the first hit's in %ld of %ld hits", point_wrong,
                     hits);
    else if (front_wrong)
        grading_fail(g,
                     "x.front is wrong in %ld of %ld hits%s: the ray arrives on the front when "
                     "it travels against the surface's normal, d . n < 0",
                     front_wrong, hits, front_wrong == hits ? " (in all: inverted)" : "");
    else if (normal_wrong)
        grading_fail(g,
                     "x.normal does not face the ray in %ld of %ld hits (%ld on the back of "
                     "their surface)%s: the shading normal faces the side the ray came from, "
                     "hit.normal on the front and -hit.normal on the back",
                     normal_wrong, hits, backs,
                     never_flipped == normal_wrong
                         ? ": it is hit.normal, never turned, so a surface seen from its back "
                           "is shaded as if lit from the other side"
                     : flipped_wrong == normal_wrong ? ": it is turned the wrong way"
                                                     : "");
    else if (wo_wrong)
        grading_fail(g, "x.wo is wrong in %ld of %ld hits%s: wo = -d, back along the ray",
                     wo_wrong, hits, wo_along == wo_wrong ? " (it is d, along the ray)" : "");
    else if (material_wrong)
        grading_fail(g, "x.material is not the hit surface's in %ld of %ld hits",
                     material_wrong, hits);
}

const Exercise exercises[] = {
    {"2.1", "hemisphere_sample_cosine",
     "Return a unit direction (local frame, z the normal) with density cos(theta) / pi, from "
     "u1, u2 in [0, 1): invert the CDFs P(theta) = sin^2(theta) and P(phi) = phi / (2 pi) (eq. "
     "12), so sin(theta) = sqrt(u1), cos(theta) = sqrt(1 - u1), phi = 2 pi u2. See "
     "docs/chapter2.md, section 2.",
     "return vec3(0, 0, 1);", grade_cosine_sample, NULL, ""},
    {"2.2", "hemisphere_pdf_cosine",
     "Return the density in solid angle of the cosine sampler at the unit local direction "
     "w_local: cos(theta) / pi (cos(theta) = w_local.z) above the surface, 0 below. See "
     "docs/chapter2.md, section 2.",
     "return 0.0;", grade_cosine_pdf, NULL, "2.1"},
    {"2.3", "lambert_brdf",
     "Return the Lambertian BRDF of reflectance rho, f = rho / pi (eq. 8): the same for every "
     "pair of directions, so that f cos(theta) integrated over the hemisphere is rho. See "
     "docs/chapter2.md, section 1.",
     "return vec3(0, 0, 0);", grade_lambert, NULL, ""},
    {"2.4", "path_radiance",
     "The path tracer (eq. 1): from the camera ray, find each vertex (path_vertex); on the "
     "front of a surface add throughput times its emission; stop at a light or after "
     "s->max_depth segments (s = settings, a PathSettings); else bounce (path_diffuse_bounce "
     "at a diffuse surface, path_specular otherwise), multiply the throughput by the weight "
     "it returns, count the bounce (counts->bounce) and spawn the next ray with ray_spawn. "
     "See docs/chapter2.md, section 3.",
     "return vec3(0, 0, 0);", grade_path, &path_check, "2.1 2.5 2.6"},
    {"2.5", "pixel_position",
     "Where sample `sample` of `samples` looks within its pixel, (u, v) in [0, 1)^2. "
     "PIXEL_RANDOM: u = rng_uniform(rng), then v = rng_uniform(rng). PIXEL_SUBPIXELS: the n = "
     "samples cells lie in r = round(sqrt(n)) rows, row k holding cells floor(k n / r) to "
     "floor((k + 1) n / r) - 1 (stratum_row gives a cell's row's first cell and its number of "
     "columns); cell m = sample of a row with `columns` cells starting at `first` is u in "
     "[(m - first) / columns, (m - first + 1) / columns), v in [first / n, (first + columns) "
     "/ n); take the jitter ju = rng_uniform(rng), then jv = rng_uniform(rng), and return the "
     "point at (ju, jv) of the cell. PIXEL_CENTRE: (0.5, 0.5), drawing nothing. See "
     "docs/chapter2.md, section 5.",
     "(void)sampling;\n(void)sample;\n(void)samples;\n(void)rng;\n*u = 0.5;\n*v = 0.5;",
     grade_pixel_position, NULL, ""},
    {"2.6", "path_vertex",
     "Find the first surface along the ray (scene_intersect(scene, ray, INFINITY, &x->hit); "
     "return 0 when there is none); then fill the vertex: its material "
     "(&scene->materials[x->hit.material]), whether the ray arrived on the front (d . n < 0 "
     "for the hit's geometric normal n), the normal turned to face the ray (n on the front, "
     "-n on the back: the side the ray came from is the side that is shaded and from which "
     "new rays leave) and wo = -d. Return 1. See docs/chapter2.md, section 3.",
     "(void)scene;\n(void)ray;\n(void)x;\nreturn 0;", grade_vertex, NULL, ""},
};
const int exercise_count = sizeof exercises / sizeof exercises[0];
