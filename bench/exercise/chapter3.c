/* chapter3.c (bench, chapter 3): chapter 3's exercises and their graders (grading.h).
 *
 * The lamp sampler by the warp test over two lamps in one plane, a 1 x 1 and a 2 x 1
 * (uniform over their area: each of 12 x 4 cells of the 3 x 1 strip holds 1 / 48 of
 * the samples); the pdf in solid angle against d^2 / (A cos beta); the shadow ray by
 * the image of the light it finds at each camera ray's first hit, against the
 * solution's, pixel by pixel; eq. 21 with M shadow rays against the mean of the M
 * shadow rays it draws, at M = 1, 2, 4 and 30. Seeds from GRADE_SEED; the course's level
 * (grading.h).
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "area_light.h"
#include "grading.h"
#include "path.h"
#include "render_check.h"

#define LEVEL grading_level()
#define COLS 12
#define ROWS 4
#define WARP_SAMPLES 200000

/* Two lamps facing down from the plane z = 1: x in [0, 1] and [1, 3], y in [0, 1]. */
static const char lamps[] = "camera 0 0 -1   -1 -1 0   1 -1 0   -1 1 0\n"
                            "material lamp light 1 1 1\n"
                            "material white lambert 0.5 0.5 0.5\n"
                            "quad lamp 0 0 1   0 1 1   1 1 1   1 0 1\n"
                            "quad lamp 1 0 1   1 1 1   3 1 1   3 0 1\n"
                            "quad white -5 -5 -1   5 -5 -1   5 5 -1   -5 5 -1\n";

static void grade_light_sample(Grading *g)
{
    Scene scene;
    if (grading_scene(g, lamps, &scene) != 0)
        return;
    const WarpLabels labels = {"row", "the lamps' far edge, y near 1",
                               "the lamps' near edge, y near 0",
                               "column (1-4: the small lamp, 5-12: the large one)",
                               "off the lamps, or with the wrong normal or emission"};
    Warp warp;
    if (warp_new(g, &warp, ROWS, COLS, 4000, labels) != 0) {
        scene_free(&scene);
        return;
    }
    for (long i = 0; i < WARP_SAMPLES; i++) {
        Rng rng = rng_for_sample(grading_stream(g, 31), 1, (uint64_t)i);
        double u_select = rng_uniform(&rng), u1, u2;
        rng_pair(&rng, &u1, &u2);
        LightSample s = {vec3(0, 0, 0), vec3(0, 0, 0), vec3(0, 0, 0)};
        if (grading_probing(g))
            s = area_light_sample(&scene, u_select, u1, u2);
        s.point = grading_ask_vec3(g, s.point);
        s.normal = grading_ask_vec3(g, s.normal);
        s.emission = grading_ask_vec3(g, s.emission);
        Vec3 p = s.point;
        int on = fabs(p.z - 1.0) < 1e-9 && p.x >= 0.0 && p.x <= 3.0 && p.y >= 0.0 &&
                 p.y <= 1.0 && fabs(s.normal.z + 1.0) < 1e-9 && s.emission.x == 1.0;
        if (!on) {
            warp_add(&warp, i, -1, 0, u_select, u1, NAN, NAN);
            continue;
        }
        int col = (int)(p.x / 3.0 * COLS), row = (int)((1.0 - p.y) * ROWS);
        warp_add(&warp, i, row < ROWS ? row : ROWS - 1, col < COLS ? col : COLS - 1, u_select,
                 u1, p.x / 1.5 - 1.0, (2.0 * p.y - 1.0) / 3.0);
    }
    for (int c = 0; c < ROWS * COLS; c++)
        warp.expected[c] = (double)WARP_SAMPLES / (ROWS * COLS);
    grading_warp(g, &warp, "the two lamps from below", LEVEL, 1,
                 "is the lamp chosen with probability proportional to its area (the running "
                 "sums in light_cumulative) and the point on its triangle at barycentric "
                 "(s (1 - u2), s u2) with s = sqrt(u1) (docs/chapter3.md, section 1)?");
    warp_free(&warp);
    scene_free(&scene);
}

static void grade_light_pdf(Grading *g)
{
    Scene scene;
    if (grading_scene(g, lamps, &scene) != 0)
        return;
    double area = scene.light_area;
    int checked = 0;
    for (int i = 0; i < 200 && !g->failed; i++, checked++) {
        Rng rng = rng_for_sample(grading_stream(g, 32), 1, (uint64_t)i);
        double d = 0.2 + 3.0 * rng_uniform(&rng), cos_beta = 0.05 + 0.95 * rng_uniform(&rng);
        double pdf = ASK(g, area_light_pdf(&scene, d, cos_beta)),
               right = d * d / (area * cos_beta);
        if (grading_not_finite(g, pdf, "the pdf"))
            break;
        if (fabs(pdf - right) <= 1e-9 * right)
            continue;
        if (fabs(pdf - d * d / area) <= 1e-9 * right)
            grading_fail(g,
                         "the pdf is %.4f at distance %.2f and cos(beta) = %.2f, where d^2 / "
                         "(A cos beta) = %.4f: the cosine at the lamp is missing (a lamp seen "
                         "edge-on covers a smaller solid angle)",
                         pdf, d, cos_beta, right);
        else if (fabs(pdf - 1.0 / area) <= 1e-9 * right)
            grading_fail(g,
                         "the pdf is 1 / A = %.4f, the density per unit area, where the "
                         "density in solid angle d^2 / (A cos beta) = %.4f is asked for",
                         pdf, right);
        else
            grading_fail(g,
                         "the pdf is %.*f at distance %.2f and cos(beta) = %.2f, where d^2 / "
                         "(A cos beta) = %.*f (A = %.1f)",
                         grading_decimals(pdf, right), pdf, d, cos_beta,
                         grading_decimals(pdf, right), right, area);
    }
    grading_note(g,
                 "%d distances and angles at lamps of total area %.1f against d^2 / (A cos "
                 "beta)",
                 checked, area);
    scene_free(&scene);
}

/* The light at a camera ray's first hit from one shadow ray (eq. 21 with M = 1), or the
 * lamp's own where the ray sees one: the shadow ray alone, without the path tracer's
 * bounces or area_light_direct. */
static Vec3 first_hit_direct(const Scene *scene, Ray ray, Rng *rng, const void *settings,
                             RayCounts *counts)
{
    Vertex x;
    if (!path_vertex(scene, ray, &x))
        return vec3(0, 0, 0);
    if (!material_is_diffuse(x.material))
        return x.front ? x.material->emission : vec3(0, 0, 0);
    return area_light_shadow_ray(scene, x.hit.point, x.normal, x.wo, x.material, rng, counts)
        .value;
}

static const RenderCheck direct_check = {
    render_check_room, first_hit_direct, NULL, 24, 32, 1024};

static void grade_shadow_ray(Grading *g)
{
    grading_render(
        g, &direct_check, LEVEL,
        "is the value Le f cos(alpha) cos(beta) A / d^2 (eq. 21), 0 when the lamp or "
        "the surface faces away or the shadow ray is blocked (docs/chapter3.md, "
        "section 2)?");
}

/* Points of the room (render_check_room) lit by its lamp, with their normals: on the floor
 * in front of the sphere, on the floor in its half-shadow, on the red wall. */
static const Vec3 room_points[][2] = {{{0.3, -0.8, -1.5}, {0, 0, 1}},
                                      {{0.95, 0.3, -1.5}, {0, 0, 1}},
                                      {{-1.49, -0.5, 0.2}, {1, 0, 0}}};
static const char *const room_point_names[] = {"the floor",
                                               "the floor in the sphere's "
                                               "half-shadow",
                                               "the red wall"};
#define ROOM_POINTS 3
#define DIRECT_TRIALS 50
#define MOST_RAYS 30
/* A trial's inputs for the catalogue: M, then the values of M + 1 shadow rays drawn in
 * turn from the trial's generator (one channel). */
#define DIRECT_ARITY (MOST_RAYS + 2)

static double mean_of(const double *in, int count)
{
    double sum = 0.0;
    for (int k = 0; k < count; k++)
        sum += in[1 + k];
    return sum / in[0];
}

static double direct_right(const double *in) { return mean_of(in, (int)in[0]); }
static double direct_sum(const double *in) { return mean_of(in, (int)in[0]) * in[0]; }
static double direct_one_more(const double *in) { return mean_of(in, (int)in[0] + 1); }
static double direct_one_fewer(const double *in) { return mean_of(in, (int)in[0] - 1); }
static double direct_first(const double *in) { return in[1]; }
static double direct_last(const double *in) { return in[(int)in[0]]; }
static double direct_over_more(const double *in)
{
    return mean_of(in, (int)in[0] + 1) * in[0] / (in[0] + 1.0);
}
static double direct_integer(const double *in) { return in[0] > 1.0 ? 0.0 : in[1]; }
/* The sum kept in a float, then divided by M in double or in float. */
static double direct_float(const double *in)
{
    float sum = 0.0f;
    for (int k = 0; k < (int)in[0]; k++)
        sum = (float)((double)sum + in[1 + k]); /* sum += value, sum a float */
    return sum / in[0];
}
static double direct_float_divided(const double *in)
{
    float sum = 0.0f;
    for (int k = 0; k < (int)in[0]; k++)
        sum = (float)((double)sum + in[1 + k]); /* sum += value, sum a float */
    return (double)(sum / (float)in[0]);
}

static double direct_rounded(const double *in) { return (float)direct_right(in); }

static const WrongAnswer wrong_direct[] = {
    {"the sum of the M shadow rays, not divided by M",
     "eq. 21 takes their mean, (1 / M) times the sum: with M rays the light is M times too "
     "bright",
     direct_sum},
    {"the sum of M + 1 shadow rays divided by M (the loop runs once too often: k <= M)",
     "eq. 21 takes M shadow rays, for (k = 0; k < M; k++), and divides their sum by M",
     direct_one_more},
    {"the sum of M - 1 shadow rays divided by M (the loop runs once too few: k from 1 to "
     "M - 1)",
     "eq. 21 takes M shadow rays, for (k = 0; k < M; k++), and divides their sum by M",
     direct_one_fewer},
    {"the sum of M + 1 shadow rays divided by M + 1 where M were asked for",
     "shadow_rays is M: for (k = 0; k < M; k++)", direct_over_more},
    {"(1 / M) times the sum with 1 / M computed in whole numbers: 0 for M > 1",
     "1 / M divides two ints; 1.0 / M does not", direct_integer},
    {"the first shadow ray's value alone", "eq. 21 averages all M of them", direct_first},
    {"the last shadow ray's value alone (the sum overwritten, = where += belongs)",
     "eq. 21 adds all M of them, sum += value, then divides by M", direct_last},
    {"the sum kept in a float, then divided by M",
     "a float keeps 7 digits: the sum and the light lose the rest; keep it in a double (a "
     "Vec3)",
     direct_float},
    {"the sum kept in a float and divided by M in float",
     "a float keeps 7 digits: keep the sum and the mean in doubles (a Vec3)",
     direct_float_divided},
    {"the mean of the M shadow rays rounded to a float on the way",
     "a float keeps 7 digits: keep the sum and the mean in doubles (a Vec3)", direct_rounded},
};
#define WRONG_DIRECT (int)(sizeof wrong_direct / sizeof wrong_direct[0])

/* L_D with M shadow rays at the room's points, DIRECT_TRIALS times each, against the
 * M + 1 shadow rays drawn again from the same generator: each trial's inputs (M and the
 * terms of one channel) and L_D in that channel, for every channel, into in[] and got[];
 * the number of trials where L_D is not the mean of M. Returns -1 after failing on a
 * NaN. */
static int direct_trials(Grading *g, const Scene *scene, int m, double *in, double *got,
                         int *first_wrong)
{
    Material white = {
        .name = "white", .kind = MATERIAL_LAMBERT, .reflectance = vec3(0.7, 0.5, 0.3)};
    RayCounts counts = {0};
    int wrong = 0;
    *first_wrong = -1;
    for (int p = 0; p < ROOM_POINTS; p++)
        for (int t = 0; t < DIRECT_TRIALS; t++) {
            Vec3 x = room_points[p][0], n = room_points[p][1];
            Rng rng = rng_for_sample(grading_stream(g, 34), (uint64_t)m,
                                     (uint64_t)(p * DIRECT_TRIALS + t));
            Rng again = rng;
            Vec3 direct =
                ASK_VEC3(g, area_light_direct(scene, x, n, n, &white, m, &rng, &counts));
            int trial = p * DIRECT_TRIALS + t;
            double *row[3];
            for (int c = 0; c < 3; c++) {
                row[c] = in + (long)(3 * trial + c) * DIRECT_ARITY;
                row[c][0] = m;
            }
            for (int k = 0; k <= m; k++) {
                Vec3 v = ASK_VEC3(
                    g, area_light_shadow_ray(scene, x, n, n, &white, &again, &counts).value);
                row[0][1 + k] = v.x, row[1][1 + k] = v.y, row[2][1 + k] = v.z;
            }
            got[3 * trial] = direct.x, got[3 * trial + 1] = direct.y,
                    got[3 * trial + 2] = direct.z;
            for (int c = 0; c < 3; c++) {
                if (grading_not_finite(g, got[3 * trial + c], "L_D"))
                    return -1;
                double right = direct_right(row[c]);
                if (fabs(got[3 * trial + c] - right) > 1e-12 + 1e-9 * fabs(right)) {
                    wrong++;
                    if (*first_wrong < 0)
                        *first_wrong = 3 * trial + c;
                }
            }
        }
    return wrong;
}

#define DIRECT_VALUES (3 * ROOM_POINTS * DIRECT_TRIALS)

static void grade_direct(Grading *g)
{
    Scene scene;
    if (grading_scene(g, render_check_room, &scene) != 0)
        return;
    static const int shadow_rays[] = {1, 2, 4, 30};
    static double in[4 * DIRECT_VALUES * DIRECT_ARITY], got[4 * DIRECT_VALUES];
    static double wrong_in[4 * DIRECT_VALUES * DIRECT_ARITY], wrong_got[4 * DIRECT_VALUES];
    int wrong = 0, first[4];
    for (int k = 0; k < 4; k++) {
        int found = direct_trials(g, &scene, shadow_rays[k],
                                  in + (long)k * DIRECT_VALUES * DIRECT_ARITY,
                                  got + k * DIRECT_VALUES, &first[k]);
        if (found < 0) {
            scene_free(&scene);
            return;
        }
        grading_note(g, "M = %d: L_D is the mean of its M shadow rays in %d of %d values",
                     shadow_rays[k], DIRECT_VALUES - found, DIRECT_VALUES);
        wrong += found;
    }
    scene_free(&scene);
    if (wrong == 0)
        return;
    /* The catalogue, at every value that is not the mean of M. */
    int count = 0;
    for (int i = 0; i < 4 * DIRECT_VALUES; i++) {
        const double *row = in + (long)i * DIRECT_ARITY;
        double right = direct_right(row);
        if (fabs(got[i] - right) <= 1e-12 + 1e-9 * fabs(right))
            continue;
        memcpy(wrong_in + (long)count * DIRECT_ARITY, row, sizeof(double) * DIRECT_ARITY);
        wrong_got[count++] = got[i];
    }
    const WrongAnswer *known = grading_known_wrong(wrong_direct, WRONG_DIRECT, wrong_in,
                                                   DIRECT_ARITY, wrong_got, count);
    if (known) {
        grading_fail_known(g, "L_D", known, count);
        return;
    }
    /* Right to a float's 7 digits, and no more: a float on the way. */
    double largest = 0.0;
    for (int q = 0; q < count; q++) {
        double right = direct_right(wrong_in + (long)q * DIRECT_ARITY);
        largest = fmax(largest, fabs(wrong_got[q] - right) / fmax(fabs(right), 1e-300));
    }
    if (largest <= 4e-6) {
        grading_fail(g,
                     "L_D agrees with the mean of its M shadow rays to about 7 digits only (at "
                     "%d of %d values it differs, by %.2g relative at most, where rounding in "
                     "doubles stays within 1e-9): a sum or a mean kept in a float on the way; "
                     "keep them in doubles (a Vec3)",
                     count, 4 * DIRECT_VALUES, largest);
        return;
    }
    for (int k = 0; k < 4; k++) {
        if (first[k] < 0)
            continue;
        int i = first[k], trial = i / 3;
        const double *row = in + ((long)k * DIRECT_VALUES + i) * DIRECT_ARITY;
        double value = got[k * DIRECT_VALUES + i], right = direct_right(row);
        int decimals = grading_decimals(value, right);
        grading_fail(
            g,
            "with M = %d on %s (channel %d), L_D = %.*f where the mean of the M shadow "
            "rays area_light_shadow_ray draws in turn from the same generator is "
            "%.*f (a ratio of %.6g; their sum %.6g; %d of the %d values at M = 1, 2, "
            "4, 30 differ): matches no known mistake; look at how the M values are "
            "drawn, summed and divided (eq. 21)",
            shadow_rays[k], room_point_names[trial / DIRECT_TRIALS], i % 3, decimals, value,
            decimals, right, right != 0.0 ? value / right : NAN, direct_sum(row), wrong,
            4 * DIRECT_VALUES);
        return;
    }
}

const Exercise exercises[] = {
    {"3.1", "area_light_sample",
     "Return a point uniformly distributed over all the lamps' area (density 1 / "
     "scene->light_area), with its lamp's normal and emission: choose the lamp triangle "
     "scene->light_triangles[i] by u_select with probability proportional to its area (the "
     "first i with scene->light_cumulative[i] > u_select * scene->light_area), then the point "
     "triangle_point(t, s (1 - u2), s u2) with s = sqrt(u1). See docs/chapter3.md, section 1.",
     "LightSample sample = {vec3(0, 0, 0), vec3(0, 0, 1), vec3(0, 0, 0)};\nreturn sample;",
     grade_light_sample, NULL, ""},
    {"3.2", "area_light_pdf",
     "Return the density in solid angle of the direction to a lamp point drawn by area, a "
     "distance d away, whose normal makes the angle beta with the way back: dA = d^2 dw / "
     "cos(beta) turns the density 1 / A (A = scene->light_area) into d^2 / (A cos beta). See "
     "docs/chapter3.md, section 2.",
     "return 0.0;", grade_light_pdf, NULL, ""},
    {"3.3", "area_light_shadow_ray",
     "One term of eq. 21 at the diffuse point x (normal n facing the viewer, direction wo, "
     "material m): draw a lamp point y (area_light_sample, from rng_uniform and rng_pair), "
     "and with wi the unit direction to it, d its distance, cos(alpha) = n . wi and cos(beta) "
     "= -n_y . wi, return zero value when either is <= 0 or the segment is blocked "
     "(scene_occluded; count counts->shadow), else value = Le f cos(alpha) cos(beta) A / d^2 "
     "(f = diffuse_brdf), wi and pdf = area_light_pdf. See docs/chapter3.md, section 2.",
     "ShadowRay ray = {.value = vec3(0, 0, 0)};\nreturn ray;", grade_shadow_ray, &direct_check,
     "3.1"},
    {"3.4", "area_light_direct",
     "Eq. 21 with M = shadow_rays >= 1: the mean of M shadow rays, (1 / M) times the sum of "
     "the values of M calls of area_light_shadow_ray(scene, x, n, wo, m, rng, counts), each "
     "drawing its own lamp point from rng. Each term's mean is L_D, so their mean is too, "
     "with 1 / M of one term's variance. See docs/chapter3.md, section 2.",
     "return vec3(0, 0, 0);", grade_direct, NULL, "3.3"},
};
const int exercise_count = sizeof exercises / sizeof exercises[0];
