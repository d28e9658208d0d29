/* chapter3.c (bench, chapter 3): chapter 3's exercises and their graders (grading.h).
 *
 * The lamp sampler by the warp test over two lamps in one plane, a 1 x 1 and a 2 x 1
 * (uniform over their area: each of 12 x 4 cells of the 3 x 1 strip holds 1 / 48 of
 * the samples) and by its means, over replicates of stratified inputs; the pdf in solid angle
 * against d^2 / (A cos beta); the shadow ray by the image of the light it finds at each camera
 * ray's first hit, against the solution's, pixel by pixel; eq. 21 with M shadow rays against
 * the mean of the M shadow rays it draws, at M = 1, 2, 4 and 30. Seeds from GRADE_SEED; the
 * course's level (grading.h).
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

static int same(double a, double b) { return fabs(a - b) <= 1e-12 + 1e-9 * fabs(b); }
static int same_vec(Vec3 a, Vec3 b)
{
    return same(a.x, b.x) && same(a.y, b.y) && same(a.z, b.z);
}

/* Two lamps in the plane z = 1, x in [0, 1] and [1, 3], y in [0, 1]: the small one
 * facing down with one colour, the large one facing up with another, so that a sample's
 * normal and emission show which lamp they came from. */
static const char lamps[] = "camera 0 0 -1   -1 -1 0   1 -1 0   -1 1 0\n"
                            "material small light 1 0.5 0.25\n"
                            "material large light 3 2 1\n"
                            "material white lambert 0.5 0.5 0.5\n"
                            "quad small 0 0 1   0 1 1   1 1 1   1 0 1\n"
                            "quad large 1 0 1   3 0 1   3 1 1   1 1 1\n"
                            "quad white -5 -5 -1   5 -5 -1   5 5 -1   -5 5 -1\n";
/* The inputs (u_select, u1, u2): LIGHT_REPLICATES replicates of a jittered grid of
 * 6 x LIGHT_GRID x LIGHT_GRID cells (grading_stratify), 2,973,696 samples. The lamps'
 * triangles hold 1/6, 1/6, 1/3 and 1/3 of their area, so a lamp chosen by u_select with
 * probability proportional to area is the same throughout each of the six slices of
 * u_select, whichever order the triangles are listed in: the choice adds no noise. */
#define LIGHT_GRID 88
#define LIGHT_REPLICATES 64
#define LIGHT_SAMPLES ((long)LIGHT_REPLICATES * 6 * LIGHT_GRID * LIGHT_GRID)
#define LIGHT_WHOLE 100000 /* samples whose normal and emission are checked too */

/* What is measured of each replicate: its mean over the samples of the share on the
 * small lamp (1/3 of the area), y (1/2), x on the small lamp (x where the sample is on
 * it, else 0: 1/3 x 1/2) and x on the large one (2/3 x 2); each exactly unbiased. */
#define LIGHT_MEANS 4
static const char *const light_mean_names[LIGHT_MEANS] = {
    "the share of samples on the small lamp (1 / 3 of the area)", "the mean y",
    "the mean of x on the small lamp, 0 on the large (its share 1 / 3 times its mean x 1 / 2)",
    "the mean of x on the large lamp, 0 on the small (its share 2 / 3 times its mean x 2)"};
static const double light_mean_exact[LIGHT_MEANS] = {1.0 / 3.0, 0.5, 1.0 / 6.0, 4.0 / 3.0};

/* The statistics of the whole sample: where it fell and whether its normal and emission
 * are its lamp's. */
typedef struct {
    long off, wrong_normal, other_normal, wrong_emission, other_emission, identical;
    double means[LIGHT_MEANS][LIGHT_REPLICATES]; /* each replicate's */
} LightTally;

static void grade_light_sample(Grading *g)
{
    Scene scene;
    if (grading_scene(g, lamps, &scene) != 0)
        return;
    const WarpLabels labels = {
        "row", "the lamps' far edge, y near 1", "the lamps' near edge, y near 0",
        "column (1-4: the small lamp, 5-12: the large one)", "off the lamps"};
    Warp warp;
    if (warp_new(g, &warp, ROWS, COLS, 4000, labels) != 0) {
        scene_free(&scene);
        return;
    }
    const Vec3 normal_of[2] = {{0, 0, -1}, {0, 0, 1}};
    const Vec3 emission_of[2] = {{1, 0.5, 0.25}, {3, 2, 1}};
    const Strata strata = grading_strata(3, (const int[]){6, LIGHT_GRID, LIGHT_GRID});
    static LightTally t;
    memset(&t, 0, sizeof t);
    for (long i = 0; i < LIGHT_SAMPLES; i++) {
        Rng rng = rng_for_sample(grading_stream(g, 31), 1, (uint64_t)i);
        double u[3];
        u[0] = rng_uniform(&rng);
        rng_pair(&rng, &u[1], &u[2]);
        grading_stratify(&strata, i, u);
        double u_select = u[0], u1 = u[1], u2 = u[2];
        LightSample s = {vec3(0, 0, 0), vec3(0, 0, 0), vec3(0, 0, 0)};
        if (grading_probing(g))
            s = area_light_sample(&scene, u_select, u1, u2);
        int whole = i < LIGHT_WHOLE;
        s.point = grading_ask_vec3(g, s.point);
        if (whole) {
            s.normal = grading_ask_vec3(g, s.normal);
            s.emission = grading_ask_vec3(g, s.emission);
        }
        if (grading_probing(g))
            continue;
        LightSample right = area_light_sample(&scene, u_select, u1, u2);
        t.identical += whole && same_vec(s.point, right.point) &&
                       same_vec(s.normal, right.normal) && same_vec(s.emission, right.emission);
        Vec3 p = s.point;
        if (!(fabs(p.z - 1.0) < 1e-9 && p.x >= 0.0 && p.x <= 3.0 && p.y >= 0.0 && p.y <= 1.0)) {
            t.off++;
            warp_add(&warp, i, -1, 0, u_select, u1, NAN, NAN);
            continue;
        }
        int lamp = p.x > 1.0;
        if (whole && !same_vec(s.normal, normal_of[lamp])) {
            t.wrong_normal++;
            t.other_normal += same_vec(s.normal, normal_of[!lamp]);
        }
        if (whole && !same_vec(s.emission, emission_of[lamp])) {
            t.wrong_emission++;
            t.other_emission += same_vec(s.emission, emission_of[!lamp]);
        }
        const double values[LIGHT_MEANS] = {!lamp, p.y, lamp ? 0.0 : p.x, lamp ? p.x : 0.0};
        for (int k = 0; k < LIGHT_MEANS; k++)
            t.means[k][i / strata.cells] += values[k] / strata.cells;
        int col = (int)(p.x / 3.0 * COLS), row = (int)((1.0 - p.y) * ROWS);
        warp_add(&warp, i, row < ROWS ? row : ROWS - 1, col < COLS ? col : COLS - 1, u_select,
                 u1, p.x / 1.5 - 1.0, (2.0 * p.y - 1.0) / 3.0);
    }
    scene_free(&scene);
    if (grading_probing(g)) {
        warp_free(&warp);
        return;
    }
    grading_note(g,
                 "%ld samples, their points and, of the first %ld, their normals and "
                 "emissions: %ld of those identical to the solution's from the same numbers; "
                 "%ld off the lamps, %ld with another normal, %ld with another emission than "
                 "their lamp's",
                 (long)LIGHT_SAMPLES, (long)LIGHT_WHOLE, t.identical, t.off, t.wrong_normal,
                 t.wrong_emission);
    const char *hint = "is the lamp chosen with probability proportional to its area (the "
                       "running sums in light_cumulative) and the point on its triangle at "
                       "barycentric (s (1 - u2), s u2) with s = sqrt(u1) (docs/chapter3.md, "
                       "section 1)?";
    if (t.wrong_normal)
        grading_fail(g,
                     "the normal is not the normal of the lamp the point lies on in %ld of %ld "
                     "samples%s: the normal and the emission are those of the triangle the "
                     "point was drawn on",
                     t.wrong_normal, (long)LIGHT_WHOLE,
                     t.other_normal == t.wrong_normal ? " (it is the other lamp's)" : "");
    else if (t.wrong_emission)
        grading_fail(g,
                     "the emission is not that of the lamp the point lies on in %ld of %ld "
                     "samples%s: the emission is the material's of the triangle the point "
                     "was drawn on",
                     t.wrong_emission, (long)LIGHT_WHOLE,
                     t.other_emission == t.wrong_emission ? " (it is the other lamp's)" : "");
    if (g->failed) {
        warp_free(&warp);
        return;
    }
    for (int c = 0; c < ROWS * COLS; c++)
        warp.expected[c] = (double)LIGHT_SAMPLES / (ROWS * COLS);
    /* conservative on stratified inputs (chapter 2's grade_cosine_sample) */
    if (grading_warp(g, &warp, "the two lamps from below", LEVEL, 1, hint))
        for (int k = 0; k < LIGHT_MEANS && !g->failed; k++)
            grading_replicate_test(g, light_mean_names[k], t.means[k], LIGHT_REPLICATES,
                                   light_mean_exact[k], hint);
    warp_free(&warp);
}

/* The pdf's inputs: d, cos(beta) and A. */
static double pdf_no_cos(const double *in) { return in[0] * in[0] / in[2]; }
static double pdf_area(const double *in) { return 1.0 / in[2]; }
static double pdf_inverse(const double *in) { return in[2] * in[1] / (in[0] * in[0]); }
static double pdf_d(const double *in) { return in[0] / (in[2] * in[1]); }
static double pdf_cos_up(const double *in) { return in[0] * in[0] * in[1] / in[2]; }
static double pdf_no_area(const double *in) { return in[0] * in[0] / in[1]; }
static double pdf_degrees(const double *in)
{
    return in[0] * in[0] / (in[2] * cos(in[1])); /* cos(beta) taken for an angle */
}

static const WrongAnswer wrong_pdf[] = {
    {"d^2 / A: the cosine at the lamp is missing",
     "a lamp seen edge-on covers a smaller solid angle: d^2 / (A cos beta)", pdf_no_cos},
    {"1 / A, the density per unit area",
     "the density in solid angle is asked for: dA = d^2 dw / cos(beta) turns 1 / A into d^2 "
     "/ (A cos beta)",
     pdf_area},
    {"A cos(beta) / d^2, the inverse of the density",
     "the density in solid angle is d^2 / (A cos beta), large for a small or distant lamp",
     pdf_inverse},
    {"d / (A cos beta): d where d^2 belongs",
     "the solid angle falls as 1 / d^2: d^2 / (A cos beta)", pdf_d},
    {"d^2 cos(beta) / A: the cosine multiplies where it divides", "d^2 / (A cos beta)",
     pdf_cos_up},
    {"d^2 / cos(beta): the area A is missing",
     "A = scene->light_area, the lamps' total area: d^2 / (A cos beta)", pdf_no_area},
    {"d^2 / (A cos(cos beta)): the cosine taken of the cosine",
     "cos_beta is already the cosine: d^2 / (A cos_beta)", pdf_degrees},
};
#define PDF_POINTS 200

static void grade_light_pdf(Grading *g)
{
    Scene scene;
    if (grading_scene(g, lamps, &scene) != 0)
        return;
    double area = scene.light_area, in[3 * PDF_POINTS], got[PDF_POINTS];
    double wrong_in[3 * PDF_POINTS], wrong_got[PDF_POINTS];
    int wrong = 0, first = -1;
    for (int i = 0; i < PDF_POINTS; i++) {
        Rng rng = rng_for_sample(grading_stream(g, 32), 1, (uint64_t)i);
        double d = 0.2 + 3.0 * rng_uniform(&rng), cos_beta = 0.05 + 0.95 * rng_uniform(&rng);
        in[3 * i] = d, in[3 * i + 1] = cos_beta, in[3 * i + 2] = area;
        got[i] = ASK(g, area_light_pdf(&scene, d, cos_beta));
        if (grading_not_finite(g, got[i], "the pdf")) {
            scene_free(&scene);
            return;
        }
        double right = d * d / (area * cos_beta);
        if (fabs(got[i] - right) <= 1e-9 * right)
            continue;
        memcpy(wrong_in + 3 * wrong, in + 3 * i, sizeof(double) * 3);
        wrong_got[wrong++] = got[i];
        first = first < 0 ? i : first;
    }
    scene_free(&scene);
    grading_note(g,
                 "%d distances and angles at lamps of total area %.1f against d^2 / (A cos "
                 "beta): %d wrong",
                 PDF_POINTS, area, wrong);
    if (wrong == 0)
        return;
    const WrongAnswer *known =
        grading_known_wrong(wrong_pdf, (int)(sizeof wrong_pdf / sizeof wrong_pdf[0]), wrong_in,
                            3, wrong_got, wrong);
    if (known) {
        grading_fail_known(g, "pdf", known, wrong);
        return;
    }
    /* How the ratio to the right pdf goes with d and cos(beta). */
    double low = INFINITY, high = -INFINITY;
    for (int k = 0; k < wrong; k++) {
        const double *x = wrong_in + 3 * k;
        double ratio = wrong_got[k] / (x[0] * x[0] / (x[2] * x[1]));
        low = fmin(low, ratio), high = fmax(high, ratio);
    }
    double d = in[3 * first], cos_beta = in[3 * first + 1], right = d * d / (area * cos_beta);
    int decimals = grading_decimals(got[first], right);
    grading_fail(
        g,
        "the pdf is %.*f at distance %.2f and cos(beta) = %.2f, where d^2 / (A cos "
        "beta) = %.*f (A = %.1f); wrong at %d of %d inputs, %s",
        decimals, got[first], d, cos_beta, decimals, right, area, wrong, PDF_POINTS,
        high - low <= 1e-9 * fabs(high)
            ? "by one constant factor at all (look at the constants)"
            : "by a ratio that changes with d and cos(beta) (look at how each enters)");
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

/* A lamp in mid-air, facing down, between a floor and a ceiling: the floor sees its
 * front, the ceiling its back (from which nothing comes). */
static const char mid_air[] = "camera 0 -3 0   -1 -2 -1   1 -2 -1   -1 -2 1\n"
                              "material white lambert 0.7 0.5 0.3\n"
                              "material lamp light 4 3 2\n"
                              "quad lamp -0.5 -0.5 0   -0.5 0.5 0   0.5 0.5 0   0.5 -0.5 0\n"
                              "quad white -5 -5 -1   5 -5 -1   5 5 -1   -5 5 -1\n"
                              "quad white -5 -5 1   -5 5 1   5 5 1   5 -5 1\n";

/* Where the shadow rays start: the first hits of rays from `from` towards `to`, as a
 * path's vertex is found (a hit point off its surface by a few ulps, the normal facing
 * the ray): on the room's floor, walls and sphere (near its rim too, grazing the
 * lamp's light), and under and over the lamp in mid-air, near it and far (grazing). */
typedef struct {
    const char *scene, *where;
    Vec3 from, to;
} ShadowStart;

static const ShadowStart shadow_starts[] = {
    {render_check_room, "the room's floor", {0, -3, 0}, {0.3, -0.8, -1.5}},
    {render_check_room,
     "the room's floor in the sphere's half-shadow",
     {0, -3, 0},
     {0.95, 0.3, -1.5}},
    {render_check_room, "the room's red wall", {0, -3, 0}, {-1.5, -0.5, 0.2}},
    {render_check_room, "the top of the room's sphere", {0, -3, 1}, {0.3, 0, -0.3}},
    {render_check_room,
     "the rim of the room's sphere, grazing the lamp's light",
     {0, -3, -0.9},
     {0.9, 0, -0.85}},
    {render_check_room,
     "the room's floor far from the lamp, at a grazing angle",
     {0, -3, 0},
     {1.4, -3.3, -1.5}},
    {mid_air, "the floor under the lamp in mid-air", {0, -3, -0.5}, {0.2, 0.1, -1}},
    {mid_air, "the floor far from the lamp in mid-air, grazing", {0, -3, -0.5}, {4.5, 0.3, -1}},
    {mid_air,
     "the ceiling over the lamp in mid-air (which sees its back)",
     {0, -3, 0.5},
     {0.1, -0.2, 1}},
    {mid_air, "the ceiling far from the lamp in mid-air", {0, -3, 0.5}, {3.5, 2, 1}},
};
#define SHADOW_STARTS (int)(sizeof shadow_starts / sizeof shadow_starts[0])
#define SHADOW_TRIALS 800

/* Why the solution's shadow ray is 0, or what it finds. */
enum {
    LIT,
    BELOW_SURFACE,
    LAMP_BACK,
    BLOCKED,
    KINDS
};

typedef struct {
    int trials, wrong[KINDS], student_zero[KINDS], student_lit[KINDS];
    int wi_wrong, wi_reversed, wi_not_unit, pdf_wrong, value_wrong, other_point;
    int unreplayed;     /* trials whose lamp call could not be replayed (lamp_call_valid) */
    int replayed_other; /* replayed lamp points other than the solution's own */
    double sum_student, sum_right, sum_difference, sum_difference2;
    const char *first_value;
    double ratio_low, ratio_high, got, want;
    int unlike[8]; /* lit values wrong that the catalogue's entry does not match */
} ShadowTally;

/* Known wrong values of a lit shadow ray, from the right one and its geometry. */
static const struct {
    const char *wrong, *right;
} value_mistakes[] = {
    {"Le f cos(alpha) A / d^2: the cosine at the lamp, cos(beta), is missing",
     "a lamp seen edge-on covers a smaller solid angle: times cos(beta) = -n_y . wi"},
    {"Le f cos(beta) A / d^2: the cosine at x, cos(alpha), is missing",
     "light arriving at a slant spreads over more area: times cos(alpha) = n . wi"},
    {"Le f cos(alpha) cos(beta) A / d: d where d^2 belongs",
     "the solid angle falls as 1 / d^2"},
    {"Le f cos(alpha) cos(beta) / d^2: the factor A, 1 / the density 1 / A, is missing",
     "a point drawn with density 1 / A is weighted by A = scene->light_area"},
    {"Le rho cos(alpha) cos(beta) A / d^2: rho where f = rho / pi belongs",
     "f is diffuse_brdf(m, n, wi, wo), rho / pi for a Lambertian surface"},
    {"the right value divided by pi once more", "f = rho / pi has one pi, in diffuse_brdf"},
    {"Le f cos(alpha) cos(beta) A^2 / d^2: A twice", "one factor A (eq. 21)"},
};
#define VALUE_MISTAKES (int)(sizeof value_mistakes / sizeof value_mistakes[0])

static void tally_init(ShadowTally *t)
{
    memset(t, 0, sizeof *t);
    t->ratio_low = INFINITY;
    t->ratio_high = -INFINITY;
}

/* Exercise 3.3's shadow rays paired through the student's own lamp points. Another order
 * of the random numbers (u1, u2 drawn before u_select; rng_pair's two swapped) or another
 * valid mapping of exercise 3.1 (the folded square) turns the same numbers into other lamp
 * points: the student's shadow rays part from the solution's, and only their means could
 * be compared. The linker's --wrap cannot reach area_light_sample here: it redirects calls
 * from other objects only, and area_light_shadow_ray calls it within area_light.c. So the
 * probe finds the call: the first three numbers of the trial's generator in the order
 * (one of six, the same at every trial of a start) whose lamp point, from the student's
 * area_light_sample, lies along every lit ray's wi; and that point. The judge checks the
 * call (lamp_call_valid) and replays the point in the solution's shadow ray: it hands the
 * solution the numbers the task's mapping turns into that point (task_numbers), through
 * __wrap_rng_uniform and __wrap_rng_pair (calls from area_light.c to rng.c, which --wrap
 * does reach: the Makefile's grader_wraps). A right shadow ray then gives the solution's
 * exactly, and a wrong one differs only by its mistake; a trial whose call fails the
 * check is compared with the solution's own shadow ray from the same numbers. */
typedef struct {
    double u[3]; /* (u_select, u1, u2), as the student's shadow ray passed them */
    LightSample y;
} LampCall;

/* The numbers the generator hands out while the judge replays a lamp point. */
static struct {
    int replaying;
    double numbers[3];
    int drawn; /* numbers asked for, the generator's own beyond the three */
} lamp_numbers;

double __real_rng_uniform(Rng *rng);
double __wrap_rng_uniform(Rng *rng);
void __real_rng_pair(Rng *rng, double *u, double *v);
void __wrap_rng_pair(Rng *rng, double *u, double *v);

/* The next number to replay, else the generator's own. */
static double replayed_number(Rng *rng)
{
    int k = lamp_numbers.drawn++;
    return k < 3 ? lamp_numbers.numbers[k] : __real_rng_uniform(rng);
}

double __wrap_rng_uniform(Rng *rng)
{
    return lamp_numbers.replaying ? replayed_number(rng) : __real_rng_uniform(rng);
}

void __wrap_rng_pair(Rng *rng, double *u, double *v)
{
    if (!lamp_numbers.replaying) {
        __real_rng_pair(rng, u, v);
        return;
    }
    *u = replayed_number(rng);
    *v = replayed_number(rng);
}

/* The first three numbers of the generator rng: those a shadow ray draws. */
static void first_numbers(Rng rng, double g[3])
{
    for (int k = 0; k < 3; k++)
        g[k] = __real_rng_uniform(&rng);
}

/* The six orders of three numbers. */
static const int orders[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2},
                                 {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
#define ORDERS 6

/* The call of area_light_sample from generator rng's numbers in order o (the probe's). */
static LampCall lamp_call(const Scene *scene, Rng rng, int o)
{
    double g[3];
    first_numbers(rng, g);
    LampCall c = {.u = {g[orders[o][0]], g[orders[o][1]], g[orders[o][2]]}};
    c.y = area_light_sample(scene, c.u[0], c.u[1], c.u[2]);
    return c;
}

static int ray_lit(ShadowRay r)
{
    return r.value.x != 0.0 || r.value.y != 0.0 || r.value.z != 0.0;
}

/* The order of the numbers behind the probe's shadow rays `got` from x: the one whose
 * lamp points lie along every lit ray's wi; `previous` where none is lit; -1 if none
 * fits. */
static int student_order(const Scene *scene, Vec3 x, const ShadowRay *got, const Rng *rngs,
                         int trials, int previous)
{
    int lit = 0;
    for (int o = 0; o < ORDERS; o++) {
        int along = 0;
        lit = 0;
        for (int t = 0; t < trials; t++) {
            if (!ray_lit(got[t]))
                continue;
            lit++;
            LampCall c = lamp_call(scene, rngs[t], o);
            Vec3 to = vec3_normalize(vec3_sub(c.y.point, x));
            along += vec3_length(vec3_sub(to, got[t].wi)) <= 1e-6;
        }
        if (lit > 0 && along == lit)
            return o;
    }
    return lit == 0 ? previous : -1;
}

/* The barycentric coordinates (b1, b2) of the point v0 + d in the plane of triangle t:
 * d = b1 e1 + b2 e2. */
static void barycentric(const Triangle *t, Vec3 d, double *b1, double *b2)
{
    double d11 = vec3_dot(t->e1, t->e1), d12 = vec3_dot(t->e1, t->e2);
    double d22 = vec3_dot(t->e2, t->e2), p1 = vec3_dot(d, t->e1), p2 = vec3_dot(d, t->e2);
    double det = d11 * d22 - d12 * d12;
    *b1 = (d22 * p1 - d12 * p2) / det;
    *b2 = (d11 * p2 - d12 * p1) / det;
}

/* The lamp (its place in scene->light_triangles) that y lies on, within 1e-6 of its plane
 * and inside it, with its normal and emission, and y's barycentric coordinates there; -1
 * if none. */
static int lamp_of(const Scene *scene, const LightSample *y, double *b1, double *b2)
{
    for (int i = 0; i < scene->light_count; i++) {
        const Triangle *t = &scene->triangles[scene->light_triangles[i]];
        Vec3 d = vec3_sub(y->point, t->v0);
        if (fabs(vec3_dot(d, t->normal)) > 1e-6)
            continue;
        barycentric(t, d, b1, b2);
        if (*b1 >= -1e-9 && *b2 >= -1e-9 && *b1 + *b2 <= 1.0 + 1e-9 &&
            same_vec(y->normal, t->normal) &&
            same_vec(y->emission, scene->materials[t->material].emission))
            return i;
    }
    return -1;
}

/* The inverse of the task's mapping (area_light.h): the numbers (u_select, u1, u2) from
 * which it draws the point (b1, b2) of lamp i, u_select amid the lamp's share of A. */
static void task_numbers(const Scene *scene, int i, double b1, double b2, double u[3])
{
    double below = i > 0 ? scene->light_cumulative[i - 1] : 0.0;
    u[0] = 0.5 * (below + scene->light_cumulative[i]) / scene->light_area;
    double s = fmin(fmax(b1 + b2, 0.0), 1.0);
    u[1] = s * s;
    u[2] = s > 0.0 ? fmin(fmax(b2 / s, 0.0), 1.0) : 0.0;
}

/* Whether call c can be replayed from the generator rng: its numbers the generator's
 * first three in some order, its point on a lamp with the lamp's normal and emission.
 * Then the numbers the task's mapping draws its point from, in u. */
static int lamp_call_valid(const Scene *scene, Rng rng, const LampCall *c, double u[3])
{
    double g[3], b1, b2;
    first_numbers(rng, g);
    int drawn = 0;
    for (int o = 0; o < ORDERS; o++)
        drawn |= c->u[0] == g[orders[o][0]] && c->u[1] == g[orders[o][1]] &&
                 c->u[2] == g[orders[o][2]];
    int lamp = drawn ? lamp_of(scene, &c->y, &b1, &b2) : -1;
    if (lamp < 0)
        return 0;
    task_numbers(scene, lamp, b1, b2, u);
    return 1;
}

/* The lamp call behind the probe's shadow ray (order: its numbers' order, -1 if not
 * found), sent, a count first; in the judge, received. Returns 1 when the judge can
 * replay it, with the numbers to hand the solution in u. */
static int ask_lamp_call(Grading *g, const Scene *scene, Rng rng, int order, double u[3])
{
    double count = ASK(g, order >= 0 ? 1.0 : 0.0);
    if (count != 1.0)
        return 0;
    LampCall c = {.u = {0}};
    if (grading_probing(g))
        c = lamp_call(scene, rng, order);
    for (int k = 0; k < 3; k++)
        c.u[k] = ASK(g, c.u[k]);
    c.y.point = ASK_VEC3(g, c.y.point);
    c.y.normal = ASK_VEC3(g, c.y.normal);
    c.y.emission = ASK_VEC3(g, c.y.emission);
    return !grading_probing(g) && lamp_call_valid(scene, rng, &c, u);
}

/* The solution's shadow ray from x with the generator `rng`, its numbers replaced by
 * `replay` unless NULL, and why it is what it is. Returns 0 in *replayed when a replay
 * did not draw exactly the three numbers. */
static ShadowRay solution_shadow_ray(const Scene *scene, Vec3 x, Vec3 n, const Material *m,
                                     Rng rng, const double *replay, int *replayed, int *kind,
                                     double *cos_beta, double *distance)
{
    double u[3];
    first_numbers(rng, u);
    for (int k = 0; replay && k < 3; k++)
        u[k] = replay[k];
    RayCounts counts = {0};
    lamp_numbers.replaying = replay != NULL;
    memcpy(lamp_numbers.numbers, u, sizeof u);
    lamp_numbers.drawn = 0;
    ShadowRay right = area_light_shadow_ray(scene, x, n, n, m, &rng, &counts);
    lamp_numbers.replaying = 0;
    *replayed = !replay || lamp_numbers.drawn == 3;
    LightSample y = area_light_sample(scene, u[0], u[1], u[2]);
    Vec3 to = vec3_sub(y.point, x);
    *distance = vec3_length(to);
    Vec3 wi = vec3_scale(to, 1.0 / *distance);
    *cos_beta = -vec3_dot(y.normal, wi);
    *kind = vec3_dot(n, wi) <= 0.0                           ? BELOW_SURFACE
            : *cos_beta <= 0.0                               ? LAMP_BACK
            : scene_occluded(scene, x, n, y.point, y.normal) ? BLOCKED
                                                             : LIT;
    return right;
}

/* The solution's shadow ray paired with the student's: replayed at the student's lamp
 * point when `replay` (its numbers) is not NULL and the replay holds, else from the
 * trial's own numbers. */
static ShadowRay paired_shadow_ray(ShadowTally *t, const Scene *scene, Vec3 x, Vec3 n,
                                   const Material *m, Rng rng, const double *replay, int *kind,
                                   double *cos_beta, double *distance)
{
    int replayed;
    if (replay) {
        ShadowRay right = solution_shadow_ray(scene, x, n, m, rng, replay, &replayed, kind,
                                              cos_beta, distance);
        if (replayed) {
            double own[3];
            first_numbers(rng, own);
            t->replayed_other +=
                !same_vec(area_light_sample(scene, own[0], own[1], own[2]).point,
                          area_light_sample(scene, replay[0], replay[1], replay[2]).point);
            return right;
        }
    }
    t->unreplayed++;
    return solution_shadow_ray(scene, x, n, m, rng, NULL, &replayed, kind, cos_beta, distance);
}

/* The judge's comparison of one trial with the solution's. */
static void tally_trial(ShadowTally *t, const Scene *scene, Vec3 x, Vec3 n, const Material *m,
                        Rng rng, ShadowRay got, const double *replay)
{
    int kind;
    double cos_beta, distance;
    ShadowRay right =
        paired_shadow_ray(t, scene, x, n, m, rng, replay, &kind, &cos_beta, &distance);
    t->trials++;
    t->sum_student += got.value.y;
    t->sum_right += right.value.y;
    double difference = got.value.y - right.value.y;
    t->sum_difference += difference;
    t->sum_difference2 += difference * difference;
    int zero = got.value.x == 0.0 && got.value.y == 0.0 && got.value.z == 0.0;
    if (!same_vec(got.value, right.value)) {
        t->wrong[kind]++;
        t->student_zero[kind] += zero;
        t->student_lit[kind] += !zero;
        if (kind == LIT && !zero) {
            double ratio = got.value.y / right.value.y;
            t->ratio_low = fmin(t->ratio_low, ratio);
            t->ratio_high = fmax(t->ratio_high, ratio);
            if (!t->value_wrong++)
                t->got = got.value.y, t->want = right.value.y;
            double cos_alpha = vec3_dot(n, right.wi), area = scene->light_area;
            const double candidates[VALUE_MISTAKES] = {
                1.0 / cos_beta, 1.0 / cos_alpha, distance, 1.0 / area, PI, 1.0 / PI, area};
            for (int c = 0; c < VALUE_MISTAKES; c++)
                t->unlike[c] += !same(got.value.y, right.value.y * candidates[c]);
        }
    }
    if (kind != LIT || zero)
        return;
    if (!same_vec(got.wi, right.wi)) {
        t->wi_wrong++;
        t->wi_reversed += same_vec(vec3_neg(got.wi), right.wi);
        t->wi_not_unit += fabs(vec3_length(got.wi) - 1.0) > 1e-9;
        t->other_point += fabs(vec3_length(got.wi) - 1.0) <= 1e-9 &&
                          vec3_length(vec3_sub(got.wi, right.wi)) > 1e-6 &&
                          !same_vec(vec3_neg(got.wi), right.wi);
    }
    if (!same(got.pdf, right.pdf) && same_vec(got.wi, right.wi))
        t->pdf_wrong++;
}

/* The verdict from one start's tally; returns 1 when it failed. */
static int shadow_verdict(Grading *g, const ShadowTally *t, const char *where)
{
    int n = t->trials;
    if (t->other_point > n / 10) {
        /* Another order of the random numbers: only the means can be compared. */
        double mean = t->sum_difference / n;
        double se = sqrt(fmax(0.0, t->sum_difference2 / n - mean * mean) / (n - 1));
        double z = se > 0.0 ? mean / se : (mean == 0.0 ? 0.0 : INFINITY);
        grading_note(g,
                     "%s: your lamp points differ from those the solution draws from the same "
                     "numbers (rng_uniform, then rng_pair, for area_light_sample); the means "
                     "compared: %.5f and %.5f (z = %+.1f, detectable bias %.2g)",
                     where, t->sum_student / n, t->sum_right / n, z, grading_detectable(se));
        if (fabs(z) > grading_z(grading_level()))
            return grading_fail(g,
                                "at %s the mean of your shadow rays is %.5f where the "
                                "solution's is %.5f (z = %+.1f over %d trials, drawn in "
                                "another order than the task's): eq. 21's term is Le f "
                                "cos(alpha) cos(beta) A / d^2",
                                where, t->sum_student / n, t->sum_right / n, z, n),
                   1;
        return 0;
    }
    if (t->student_lit[LAMP_BACK])
        return grading_fail(g,
                            "light from the back of the lamp: at %s, where the lamp turns its "
                            "back (cos(beta) = -n_y . wi <= 0), your value is not 0 in %d of "
                            "%d trials: a lamp emits from its front only",
                            where, t->student_lit[LAMP_BACK], n),
               1;
    if (t->student_lit[BELOW_SURFACE])
        return grading_fail(g,
                            "light from below the surface: at %s, for lamp points behind the "
                            "surface (cos(alpha) = n . wi <= 0) your value is not 0 in %d of "
                            "%d trials",
                            where, t->student_lit[BELOW_SURFACE], n),
               1;
    if (t->student_lit[BLOCKED])
        return grading_fail(g,
                            "light through the scene: at %s, %d of %d shadow rays that "
                            "something blocks still bring light (scene_occluded(scene, x, n, "
                            "y, n_y) says whether the segment is blocked)",
                            where, t->student_lit[BLOCKED], n),
               1;
    if (t->student_zero[LIT])
        return grading_fail(g,
                            "too dark: at %s, %d of %d lamp points in plain sight give 0, as "
                            "if blocked: a shadow ray started exactly at x hits x's own "
                            "surface (acne; worst at grazing angles): scene_occluded(scene, x, "
                            "n, y, n_y) moves both ends off their surfaces",
                            where, t->student_zero[LIT], n),
               1;
    for (int c = 0; t->value_wrong && c < VALUE_MISTAKES; c++)
        if (t->unlike[c] == 0)
            return grading_fail(g,
                                "your value equals %s, at each of the %d lit shadow rays from "
                                "%s where it is wrong (to 1e-9): %s",
                                value_mistakes[c].wrong, t->value_wrong, where,
                                value_mistakes[c].right),
                   1;
    if (t->value_wrong) {
        char shape[200];
        if (t->ratio_high - t->ratio_low <= 1e-9 * fabs(t->ratio_high))
            snprintf(shape, sizeof shape,
                     "%.6g times the right value at every one: a constant factor (A = %s? pi "
                     "in f = rho / pi?)",
                     t->ratio_high, "scene->light_area");
        else
            snprintf(shape, sizeof shape,
                     "between %.4g and %.4g times the right value: a factor that changes with "
                     "the lamp point (cos(alpha), cos(beta), d^2?)",
                     t->ratio_low, t->ratio_high);
        return grading_fail(g,
                            "at %s, the value of %d of %d lit shadow rays is wrong (%.6g where "
                            "Le f cos(alpha) cos(beta) A / d^2 = %.6g), %s",
                            where, t->value_wrong, n, t->got, t->want, shape),
               1;
    }
    if (t->wi_wrong)
        return grading_fail(g,
                            "at %s, wi is wrong in %d of %d lit shadow rays%s: wi is the unit "
                            "direction from x to the lamp point",
                            where, t->wi_wrong, n,
                            t->wi_reversed == t->wi_wrong ? " (it points from the lamp to x)"
                            : t->wi_not_unit              ? " (not of unit length)"
                                                          : ""),
               1;
    if (t->pdf_wrong)
        return grading_fail(g,
                            "at %s, the pdf is wrong in %d of %d lit shadow rays: it is "
                            "area_light_pdf(scene, d, cos(beta)), d^2 / (A cos beta), the "
                            "density of wi in solid angle that multiple importance sampling "
                            "reads (chapter 7)",
                            where, t->pdf_wrong, n),
               1;
    return 0;
}

/* Trial t's generator at start k. */
static Rng trial_rng(const Grading *g, int k, int t)
{
    return rng_for_sample(grading_stream(g, 33), (uint64_t)k, (uint64_t)t);
}

/* The student's shadow rays at the start in hand, made in the probe. */
static ShadowRay probe_rays[SHADOW_TRIALS];

/* In the probe, the student's shadow rays at start k, from x, into probe_rays; returns the
 * order of their numbers (student_order, `previous` where none is lit); -1 in the judge. */
static int probe_shadow_rays(Grading *g, const Scene *scene, int k, Vec3 x, Vec3 n,
                             const Material *m, int previous)
{
    if (!grading_probing(g))
        return -1;
    static Rng rngs[SHADOW_TRIALS];
    RayCounts counts = {0};
    for (int t = 0; t < SHADOW_TRIALS; t++) {
        rngs[t] = trial_rng(g, k, t);
        Rng mine = rngs[t];
        probe_rays[t] = area_light_shadow_ray(scene, x, n, n, m, &mine, &counts);
    }
    return student_order(scene, x, probe_rays, rngs, SHADOW_TRIALS, previous);
}

/* What the pairing at a start took of your lamp points, when not the solution's own. */
static void note_lamp_replay(Grading *g, const ShadowTally *t, const char *where)
{
    if (t->unreplayed > 0)
        grading_note(g,
                     "%s: in %d of %d trials your call of area_light_sample (exercise 3.1) "
                     "could not be found or replayed (its numbers not the trial's first three "
                     "in some order, or its point not on a lamp with its normal and "
                     "emission): compared with the solution's own shadow rays from the same "
                     "numbers instead",
                     where, t->unreplayed, t->trials);
    else if (t->replayed_other > 0)
        grading_note(g,
                     "%s: %d of %d of your lamp points are not the solution's from the same "
                     "numbers (another order of the numbers, or another mapping of exercise "
                     "3.1): the solution's shadow ray replayed at your points",
                     where, t->replayed_other, t->trials);
}

/* Every field of the shadow ray (value, wi, pdf) against the solution's at your lamp point
 * (replayed) at each start: exact, whatever order of the numbers or valid mapping of
 * exercise 3.1 gives the points. */
static void grade_shadow_ray_paired(Grading *g)
{
    Material white = {
        .name = "white", .kind = MATERIAL_LAMBERT, .reflectance = vec3(0.7, 0.5, 0.3)};
    int trials = 0, order = -1;
    for (int k = 0; k < SHADOW_STARTS && !g->failed; k++) {
        const ShadowStart *start = &shadow_starts[k];
        Scene scene;
        if (grading_scene(g, start->scene, &scene) != 0)
            return;
        Ray ray = {start->from, vec3_normalize(vec3_sub(start->to, start->from))};
        Hit hit = {0};
        int found = grading_probing(g) ? scene_intersect(&scene, ray, INFINITY, &hit) : 0;
        found = ASK(g, found) != 0.0;
        Vec3 x = ASK_VEC3(g, hit.point), normal = ASK_VEC3(g, hit.normal);
        if (!found) {
            scene_free(&scene);
            grading_fail(
                g, "the grader's ray towards %s found nothing: has scene_intersect changed?",
                start->where);
            return;
        }
        Vec3 n = vec3_dot(normal, ray.dir) < 0.0 ? normal : vec3_neg(normal);
        ShadowTally tally;
        tally_init(&tally);
        order = probe_shadow_rays(g, &scene, k, x, n, &white, order);
        for (int t = 0; t < SHADOW_TRIALS; t++) {
            Rng rng = trial_rng(g, k, t);
            ShadowRay got = grading_probing(g) ? probe_rays[t] : (ShadowRay){.pdf = 0.0};
            got.value = ASK_VEC3(g, got.value);
            got.wi = ASK_VEC3(g, got.wi);
            got.pdf = ASK(g, got.pdf);
            double replay[3];
            int replayable = ask_lamp_call(g, &scene, rng, order, replay);
            if (grading_not_finite(g, got.value.x + got.value.y + got.value.z, "the value") ||
                (!grading_probing(g) && !(got.value.x == 0.0 && got.value.y == 0.0) &&
                 grading_not_finite(g, got.pdf, "the pdf")))
                break;
            if (!grading_probing(g))
                tally_trial(&tally, &scene, x, n, &white, rng, got, replayable ? replay : NULL);
        }
        scene_free(&scene);
        trials += tally.trials;
        if (!grading_probing(g) && !g->failed) {
            grading_note(g, "%s: %d trials, your mean %.5f, the solution's %.5f", start->where,
                         tally.trials, tally.sum_student / SHADOW_TRIALS,
                         tally.sum_right / SHADOW_TRIALS);
            note_lamp_replay(g, &tally, start->where);
            shadow_verdict(g, &tally, start->where);
        }
    }
    grading_note(g,
                 "%d shadow rays (value, wi and pdf) against the solution's at the same lamp "
                 "points (yours, replayed) at %d points of two scenes",
                 trials, SHADOW_STARTS);
}

static void grade_shadow_ray(Grading *g)
{
    grade_shadow_ray_paired(g);
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
