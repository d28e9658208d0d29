/* chapter3.c (bench, chapter 3): chapter 3's exercises and their graders (grading.h).
 *
 * The lamp sampler by the warp test over two lamps in one plane, a 1 x 1 and a 2 x 1
 * (uniform over their area: each of 12 x 4 cells of the 3 x 1 strip holds 1 / 48 of
 * the samples); the pdf in solid angle against d^2 / (A cos beta); the shadow ray
 * (eq. 21) by the direct-light path tracer's image against the solution's, pixel by
 * pixel. Fixed seeds; significance level 0.01.
 */
#include <math.h>
#include <stdio.h>

#include "area_light.h"
#include "grading.h"
#include "path_direct.h"
#include "render_check.h"

#define LEVEL 0.01
#define COLS 12
#define ROWS 4
#define WARP_SAMPLES 200000

/* Two lamps facing down from the plane z = 1: x in [0, 1] and [1, 3], y in [0, 1]. */
static const char lamps[] =
    "camera 0 0 -1   -1 -1 0   1 -1 0   -1 1 0\n"
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
        Rng rng = rng_for_sample(31, 1, (uint64_t)i);
        double u_select = rng_uniform(&rng), u1, u2;
        rng_pair(&rng, &u1, &u2);
        LightSample s = {vec3(0, 0, 0), vec3(0, 0, 0), vec3(0, 0, 0)};
        if (grading_probing(g))
            s = area_light_sample(&scene, u_select, u1, u2);
        s.point = grading_ask_vec3(g, s.point);
        s.normal = grading_ask_vec3(g, s.normal);
        s.emission = grading_ask_vec3(g, s.emission);
        Vec3 p = s.point;
        int on = fabs(p.z - 1.0) < 1e-9 && p.x >= 0.0 && p.x <= 3.0 && p.y >= 0.0 && p.y <= 1.0 &&
                 fabs(s.normal.z + 1.0) < 1e-9 && s.emission.x == 1.0;
        if (!on) {
            warp_add(&warp, i, -1, 0, u_select, u1, NAN, NAN);
            continue;
        }
        int col = (int)(p.x / 3.0 * COLS), row = (int)((1.0 - p.y) * ROWS);
        warp_add(&warp, i, row < ROWS ? row : ROWS - 1, col < COLS ? col : COLS - 1, u_select, u1,
                 p.x / 1.5 - 1.0, (2.0 * p.y - 1.0) / 3.0);
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
        Rng rng = rng_for_sample(32, 1, (uint64_t)i);
        double d = 0.2 + 3.0 * rng_uniform(&rng), cos_beta = 0.05 + 0.95 * rng_uniform(&rng);
        double pdf = ASK(g, area_light_pdf(&scene, d, cos_beta)), right = d * d / (area * cos_beta);
        if (grading_not_finite(g, pdf, "the pdf"))
            break;
        if (fabs(pdf - right) <= 1e-9 * right)
            continue;
        if (fabs(pdf - d * d / area) <= 1e-9 * right)
            grading_fail(g, "the pdf is %.4f at distance %.2f and cos(beta) = %.2f, where d^2 / "
                         "(A cos beta) = %.4f: the cosine at the lamp is missing (a lamp seen "
                         "edge-on covers a smaller solid angle)", pdf, d, cos_beta, right);
        else if (fabs(pdf - 1.0 / area) <= 1e-9 * right)
            grading_fail(g, "the pdf is 1 / A = %.4f, the density per unit area, where the "
                         "density in solid angle d^2 / (A cos beta) = %.4f is asked for", pdf,
                         right);
        else
            grading_fail(g, "the pdf is %.4f at distance %.2f and cos(beta) = %.2f, where d^2 / "
                         "(A cos beta) = %.4f (A = %.1f)", pdf, d, cos_beta, right, area);
    }
    grading_note(g, "%d distances and angles at lamps of total area %.1f against d^2 / (A cos "
                 "beta)", checked, area);
    scene_free(&scene);
}

static const PathSettings direct_settings = {.max_depth = 3, .shadow_rays = 1};
static const RenderCheck direct_check = {render_check_room, path_direct_radiance,
                                         &direct_settings, 24, 32, 1024};

static void grade_shadow_ray(Grading *g)
{
    grading_render(g, &direct_check, LEVEL,
                   "is the value Le f cos(alpha) cos(beta) A / d^2 (eq. 21), 0 when the lamp or "
                   "the surface faces away or the shadow ray is blocked (docs/chapter3.md, "
                   "section 2)?");
}

const Exercise exercises[] = {
    {"3.1", "area_light_sample",
     "Return a point uniformly distributed over all the lamps' area (density 1 / "
     "scene->light_area), with its lamp's normal and emission: choose the lamp triangle "
     "scene->light_triangles[i] by u_select with probability proportional to its area (the "
     "first i with scene->light_cumulative[i] > u_select * scene->light_area), then the point "
     "triangle_point(t, s (1 - u2), s u2) with s = sqrt(u1). See docs/chapter3.md, section 1.",
     "LightSample sample = {vec3(0, 0, 0), vec3(0, 0, 1), vec3(0, 0, 0)};\nreturn sample;",
     grade_light_sample, NULL},
    {"3.2", "area_light_pdf",
     "Return the density in solid angle of the direction to a lamp point drawn by area, a "
     "distance d away, whose normal makes the angle beta with the way back: dA = d^2 dw / "
     "cos(beta) turns the density 1 / A (A = scene->light_area) into d^2 / (A cos beta). See "
     "docs/chapter3.md, section 2.",
     "return 0.0;", grade_light_pdf, NULL},
    {"3.3", "area_light_shadow_ray",
     "One term of eq. 21 at the diffuse point x (normal n facing the viewer, direction wo, "
     "material m): draw a lamp point y (area_light_sample, from rng_uniform and rng_pair), "
     "and with wi the unit direction to it, d its distance, cos(alpha) = n . wi and cos(beta) "
     "= -n_y . wi, return zero value when either is <= 0 or the segment is blocked "
     "(scene_occluded; count counts->shadow), else value = Le f cos(alpha) cos(beta) A / d^2 "
     "(f = diffuse_brdf), wi and pdf = area_light_pdf. See docs/chapter3.md, section 2.",
     "ShadowRay ray = {.value = vec3(0, 0, 0)};\nreturn ray;", grade_shadow_ray, &direct_check},
};
const int exercise_count = sizeof exercises / sizeof exercises[0];
