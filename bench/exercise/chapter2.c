/* chapter2.c (bench, chapter 2): chapter 2's exercises and their graders (grading.h).
 *
 * The cosine sampler by the warp test against its exact density (a ring between
 * heights a < b holds b^2 - a^2 of the samples, a sector 1 / 12); its pdf and the
 * Lambert BRDF against their closed forms, the BRDF also through the white furnace
 * it would make (L = Le / (1 - pi f)); the path tracer by its image against the
 * solution's, pixel by pixel. Seeds from GRADE_SEED; the course's level (grading.h).
 */
#include <math.h>
#include <stdio.h>

#include "grading.h"
#include "hemisphere.h"
#include "lambert.h"
#include "path.h"
#include "render_check.h"

#define LEVEL grading_level()
#define RINGS 10
#define SECTORS 12
#define WARP_SAMPLES 200000

static void grade_cosine_sample(Grading *g)
{
    const WarpLabels labels = {"ring", "nearest the pole", "nearest the horizon",
                               "sector around the normal",
                               "below the surface, off the unit sphere or at NaN"};
    Warp warp;
    if (warp_new(g, &warp, RINGS, SECTORS, 4000, labels) != 0)
        return;
    for (long i = 0; i < WARP_SAMPLES; i++) {
        Rng rng = rng_for_sample(grading_stream(g, 21), 1, (uint64_t)i);
        double u1, u2;
        rng_pair(&rng, &u1, &u2);
        warp_add_hemisphere(&warp, i, u1, u2, ASK_VEC3(g, hemisphere_sample_cosine(u1, u2)));
    }
    warp_expect_cosine(&warp, WARP_SAMPLES);
    grading_warp(g, &warp, "the hemisphere seen from above", LEVEL, 1,
                 "is cos(theta) = sqrt(1 - u1), sin(theta) = sqrt(u1) and phi = 2 pi u2 "
                 "(eq. 12, docs/chapter2.md)?");
    warp_free(&warp);
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

static void grade_path(Grading *g)
{
    grading_render(
        g, &path_check, LEVEL,
        "does a hit on the front of a light add throughput times its emission, does "
        "the path stop at a light or at max_depth, and does the throughput take each "
        "bounce's weight (docs/chapter2.md)?");
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
     "return 0.0;", grade_cosine_pdf, NULL, ""},
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
     "return vec3(0, 0, 0);", grade_path, &path_check, "2.1"},
};
const int exercise_count = sizeof exercises / sizeof exercises[0];
