/* chapter5.c (bench, chapter 5): chapter 5's exercises and their graders (grading.h).
 *
 * A and B against eq. 14 at several roughnesses (a wrong one named: the report's A
 * without "1 -", sigma taken as degrees); the factor against eq. 13 written with the
 * angles themselves (alpha = max, beta = min of theta_i, theta_o), and by the image of
 * a rough sphere lit from the viewer, against the solution's, pixel by pixel. Fixed
 * seeds; significance level 0.01.
 */
#include <math.h>
#include <stdio.h>

#include "grading.h"
#include "oren_nayar.h"
#include "path_direct.h"
#include "render_check.h"

#define LEVEL 0.01

static const double sigmas[] = {0.0, 0.1, 0.25, 0.5, 1.0};
#define SIGMAS (int)(sizeof sigmas / sizeof sigmas[0])

static double right_a(double sigma)
{
    return 1.0 - sigma * sigma / (2.0 * (sigma * sigma + 0.33));
}

static double right_b(double sigma) { return 0.45 * sigma * sigma / (sigma * sigma + 0.09); }

/* One of A and B against its right value at each roughness, naming a known mistake. */
static void grade_coefficient(Grading *g, const char *name, double (*yours)(double),
                              double (*right)(double), const char *missing)
{
    double values[SIGMAS];
    for (int i = 0; i < SIGMAS; i++)
        values[i] = ASK(g, yours(sigmas[i]));
    /* the misprint: 1 - the right value at every roughness (and not 0 everywhere) */
    int misprint = missing != NULL, nonzero = 0;
    for (int i = 0; i < SIGMAS; i++) {
        misprint &= fabs(values[i] - (1.0 - right(sigmas[i]))) <= 1e-12;
        nonzero |= values[i] != 0.0;
    }
    for (int i = 0; i < SIGMAS && !g->failed; i++) {
        double sigma = sigmas[i], got = values[i], want = right(sigma);
        grading_note(g, "%s(%.2f) = %.6f; eq. 14 gives %.6f", name, sigma, got, want);
        if (grading_not_finite(g, got, name) || fabs(got - want) <= 1e-12)
            continue;
        double degrees = sigma * PI / 180.0;
        int decimals = grading_decimals(got, want);
        if (fabs(got - right(degrees)) <= 1e-12)
            grading_fail(g, "%s(%.2f) = %.6f, which is %s of %.2f degrees: sigma is in radians",
                         name, sigma, got, name, sigma);
        else if (misprint && nonzero)
            grading_fail(g, "%s(%.2f) = %.*f where eq. 14 gives %.*f: %s", name, sigma,
                         decimals, got, decimals, want, missing);
        else
            grading_fail(
                g, "%s(%.2f) = %.*f where eq. 14 gives %.*f%s", name, sigma, decimals, got,
                decimals, want,
                sigma == 0.0 ? " (at sigma = 0 the surface is Lambertian: A = 1, B = 0)" : "");
    }
}

static void grade_a(Grading *g)
{
    grade_coefficient(g, "A", oren_nayar_a, right_a,
                      "the report's misprint: A = 1 - sigma^2 / (2 (sigma^2 + 0.33)), so that "
                      "sigma = 0 is Lambert");
}

static void grade_b(Grading *g) { grade_coefficient(g, "B", oren_nayar_b, right_b, NULL); }

/* A unit direction above the surface, from its polar angle and azimuth. */
static Vec3 polar(double theta, double phi)
{
    return vec3(sin(theta) * cos(phi), sin(theta) * sin(phi), cos(theta));
}

static void grade_factor_closed_form(Grading *g)
{
    int checked = 0;
    for (int i = 0; i < 2000 && !g->failed; i++, checked++) {
        Rng rng = rng_for_sample(51, 1, (uint64_t)i);
        double sigma = 0.05 + 0.95 * rng_uniform(&rng);
        double ti = 0.5 * PI * 0.98 * rng_uniform(&rng),
               to = 0.5 * PI * 0.98 * rng_uniform(&rng);
        double pi_ = 2.0 * PI * rng_uniform(&rng), po = 2.0 * PI * rng_uniform(&rng);
        double alpha = fmax(ti, to), beta = fmin(ti, to);
        double want =
            right_a(sigma) + right_b(sigma) * fmax(0.0, cos(pi_ - po)) * sin(alpha) * tan(beta);
        double got = ASK(g, oren_nayar_factor(sigma, polar(ti, pi_), polar(to, po)));
        if (grading_not_finite(g, got, "the factor") || fabs(got - want) <= 1e-9)
            continue;
        double with_sin =
            right_a(sigma) + right_b(sigma) * fmax(0.0, cos(pi_ - po)) * sin(alpha) * sin(beta);
        grading_fail(g,
                     "the factor is %.*f at sigma = %.2f, theta_i = %.1f, theta_o = %.1f "
                     "degrees, cos(phi_i - phi_o) = %.2f, where eq. 13 gives %.*f%s",
                     grading_decimals(got, want), got, sigma, ti * 180.0 / PI, to * 180.0 / PI,
                     cos(pi_ - po), grading_decimals(got, want), want,
                     fabs(got - with_sin) <= 1e-9 ? ": sin(beta) where tan(beta) belongs (the "
                                                    "report's misprint)"
                                                  : "");
    }
    grading_note(g,
                 "%d random pairs of directions and roughnesses against A + B max(0, "
                 "cos(phi_i - phi_o)) sin(alpha) tan(beta)",
                 checked);
}

/* A rough sphere (sigma = 1) in a dark room, lit from just above the eye. */
static const char rough_sphere[] =
    "camera 0 0 0   1 0.2 -0.2   1 -0.2 -0.2   1 0.2 0.2\n"
    "material wall  lambert    0.3 0.3 0.3\n"
    "material rough oren_nayar 0.8 0.8 0.8 1.0\n"
    "material lamp  light      120 120 120\n"
    "box wall -2 -5 -1   10 5 5\n"
    "sphere rough 6 0 0 1\n"
    "quad lamp 0 -0.6 0.5   0 0.6 0.5   0 0.6 1.0   0 -0.6 1.0\n";

static const PathSettings direct_settings = {.max_depth = 2, .shadow_rays = 1};
static const RenderCheck rough_check = {
    rough_sphere, path_direct_radiance, &direct_settings, 24, 32, 1024};

static void grade_factor(Grading *g)
{
    grade_factor_closed_form(g);
    if (!g->failed)
        grading_render(g, &rough_check, LEVEL,
                       "is the factor A + B max(0, x_i x_o + y_i y_o) / max(z_i, z_o) (docs/"
                       "chapter5.md, section 2)?");
}

const Exercise exercises[] = {
    {"5.1", "oren_nayar_a",
     "Return Oren-Nayar's A = 1 - sigma^2 / (2 (sigma^2 + 0.33)) (eq. 14, corrected: the "
     "report leaves out the \"1 -\"), sigma the roughness in radians. See docs/chapter5.md, "
     "section 1.",
     "return 0.0;", grade_a, NULL, ""},
    {"5.2", "oren_nayar_b",
     "Return Oren-Nayar's B = 0.45 sigma^2 / (sigma^2 + 0.09) (eq. 14), sigma in radians. See "
     "docs/chapter5.md, section 1.",
     "return 0.0;", grade_b, NULL, ""},
    {"5.3", "oren_nayar_factor",
     "Return f / (rho / pi) = A + B max(0, cos(phi_i - phi_o)) sin(alpha) tan(beta) (eq. 13, "
     "with tan(beta), not the report's sin(beta)) for unit local directions wi, wo, alpha = "
     "max(theta_i, theta_o), beta = min, without trigonometry: max(0, x_i x_o + y_i y_o) / "
     "max(z_i, z_o) (A alone when that maximum is 0). See docs/chapter5.md, section 2.",
     "return 0.0;", grade_factor, &rough_check, "5.1 5.2"},
};
const int exercise_count = sizeof exercises / sizeof exercises[0];
