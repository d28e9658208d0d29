/* chapter5.c (bench, chapter 5): chapter 5's exercises and their graders (grading.h).
 *
 * A and B against eq. 14 at six roughnesses; the factor against eq. 13 written with the
 * angles themselves (alpha = max, beta = min of theta_i, theta_o) at 2,000 random pairs
 * of directions, and its reciprocity (the pair swapped); the BRDF rho / pi times the
 * factor, per channel, reciprocal too, and by the image of a rough sphere lit from the
 * viewer against the solution's, pixel by pixel. Closed forms to 1e-9 and catalogues of
 * known wrong answers (the other term's constant, alpha and beta swapped, sin(beta) for
 * tan(beta), sigma in degrees, ...); the image at the course's level (grading.h).
 */
#include <math.h>
#include <stdio.h>

#include "grading.h"
#include "oren_nayar.h"
#include "path_direct.h"
#include "render_check.h"

#define LEVEL grading_level()
#define PAIRS 2000
#define TOLERANCE 1e-9

static const double sigmas[] = {0.0, 0.1, 0.25, 0.5, 1.0, 2.0};
#define SIGMAS (int)(sizeof sigmas / sizeof sigmas[0])

/* sigma^2 / (sigma^2 + c) */
static double ratio_of(double sigma, double c) { return sigma * sigma / (sigma * sigma + c); }
static double degrees(double sigma) { return sigma * PI / 180.0; }

static double right_a(double sigma) { return 1.0 - 0.5 * ratio_of(sigma, 0.33); }
static double right_b(double sigma) { return 0.45 * ratio_of(sigma, 0.09); }

/* Known wrong A and B, of inputs[0] = sigma. */
static double a_misprint(const double *x) { return 0.5 * ratio_of(x[0], 0.33); }
static double a_degrees(const double *x) { return right_a(degrees(x[0])); }
static double a_other_constant(const double *x) { return 1.0 - 0.5 * ratio_of(x[0], 0.09); }
static double a_with_045(const double *x) { return 1.0 - 0.45 * ratio_of(x[0], 0.33); }
static double a_without_half(const double *x) { return 1.0 - ratio_of(x[0], 0.33); }
static double a_not_squared(const double *x) { return 1.0 - 0.5 * x[0] / (x[0] + 0.33); }
static double a_integer_half(const double *x) { return 1.0 + 0.0 * x[0]; }
static double a_is_b(const double *x) { return right_b(x[0]); }
static double b_other_constant(const double *x) { return 0.45 * ratio_of(x[0], 0.33); }
static double b_degrees(const double *x) { return right_b(degrees(x[0])); }
static double b_with_half(const double *x) { return 0.5 * ratio_of(x[0], 0.09); }
static double b_not_squared(const double *x) { return 0.45 * x[0] / (x[0] + 0.09); }
static double b_one_minus(const double *x) { return 1.0 - 0.45 * ratio_of(x[0], 0.09); }
static double b_is_a(const double *x) { return right_a(x[0]); }

static const WrongAnswer wrong_a[] = {
    {"sigma^2 / (2 (sigma^2 + 0.33)), the report's misprint without \"1 -\"",
     "A = 1 - sigma^2 / (2 (sigma^2 + 0.33)), so that sigma = 0 is Lambert (A = 1)",
     a_misprint},
    {"A of sigma taken in degrees (sigma pi / 180)", "sigma is in radians: use it as it comes",
     a_degrees},
    {"1 - sigma^2 / (2 (sigma^2 + 0.09)): B's constant 0.09 in A",
     "A's constant is 0.33, B's 0.09", a_other_constant},
    {"1 - 0.45 sigma^2 / (sigma^2 + 0.33): B's factor 0.45 in A",
     "A halves the ratio: 1 - sigma^2 / (2 (sigma^2 + 0.33))", a_with_045},
    {"1 - sigma^2 / (sigma^2 + 0.33), without the 2 of the denominator",
     "A = 1 - sigma^2 / (2 (sigma^2 + 0.33)) tends to 1/2 for a very rough surface, not 0",
     a_without_half},
    {"1 - sigma / (2 (sigma + 0.33)), sigma not squared", "eq. 14 has sigma^2 in both places",
     a_not_squared},
    {"1 at every roughness (is 1/2 written 1 / 2, which is 0 in C's integer arithmetic?)",
     "A = 1 - sigma^2 / (2 (sigma^2 + 0.33)): 0.5 or 1.0 / 2", a_integer_half},
    {"B's formula 0.45 sigma^2 / (sigma^2 + 0.09)", "A = 1 - sigma^2 / (2 (sigma^2 + 0.33))",
     a_is_b},
};
static const WrongAnswer wrong_b[] = {
    {"0.45 sigma^2 / (sigma^2 + 0.33): A's constant 0.33 in B",
     "B's constant is 0.09, A's 0.33", b_other_constant},
    {"B of sigma taken in degrees (sigma pi / 180)", "sigma is in radians: use it as it comes",
     b_degrees},
    {"0.5 sigma^2 / (sigma^2 + 0.09): 1/2 (A's) for B's factor 0.45",
     "B = 0.45 sigma^2 / (sigma^2 + 0.09)", b_with_half},
    {"0.45 sigma / (sigma + 0.09), sigma not squared", "eq. 14 has sigma^2 in both places",
     b_not_squared},
    {"1 - 0.45 sigma^2 / (sigma^2 + 0.09), with a \"1 -\" that only A has",
     "B = 0.45 sigma^2 / (sigma^2 + 0.09) is 0 for a smooth surface", b_one_minus},
    {"A's formula 1 - sigma^2 / (2 (sigma^2 + 0.33))", "B = 0.45 sigma^2 / (sigma^2 + 0.09)",
     b_is_a},
};
#define COUNT(list) (int)(sizeof list / sizeof list[0])

/* One of A and B against its right value at each roughness: a known wrong answer named,
 * else where it goes wrong and by how much. */
static void grade_coefficient(Grading *g, const char *name, double (*yours)(double),
                              double (*right)(double), const WrongAnswer *known, int count,
                              double smooth)
{
    double got[SIGMAS];
    int wrong = -1;
    for (int i = 0; i < SIGMAS; i++) {
        got[i] = ASK(g, yours(sigmas[i]));
        grading_note(g, "%s(%.2f) = %.9f; eq. 14 gives %.9f", name, sigmas[i], got[i],
                     right(sigmas[i]));
        if (grading_not_finite(g, got[i], name))
            return;
        if (wrong < 0 && !(fabs(got[i] - right(sigmas[i])) <= 1e-12))
            wrong = i;
    }
    if (wrong < 0)
        return;
    const WrongAnswer *match = grading_known_wrong(known, count, sigmas, 1, got, SIGMAS);
    if (match) {
        grading_fail_known(g, name, match, SIGMAS);
        return;
    }
    int zeros = 0;
    for (int i = 0; i < SIGMAS; i++)
        zeros += got[i] == 0.0;
    if (zeros == SIGMAS) {
        grading_fail(g, "%s is 0 at every roughness tried: is anything computed? (eq. 14)",
                     name);
        return;
    }
    double sigma = sigmas[wrong], want = right(sigma);
    int decimals = grading_decimals(got[wrong], want);
    if (sigma == 0.0)
        grading_fail(g,
                     "%s(0) = %.*f where a smooth surface (sigma = 0) is Lambert's: %s = %g "
                     "there (eq. 14)",
                     name, decimals, got[wrong], name, smooth);
    else
        grading_fail(g,
                     "%s(%.2f) = %.*f where eq. 14 gives %.*f (%.6g times that), right up "
                     "to sigma = %.2f: look at how %s grows with sigma^2",
                     name, sigma, decimals, got[wrong], decimals, want, got[wrong] / want,
                     sigmas[wrong - 1], name);
}

static void grade_a(Grading *g)
{
    grade_coefficient(g, "A", oren_nayar_a, right_a, wrong_a, COUNT(wrong_a), 1.0);
}

static void grade_b(Grading *g)
{
    grade_coefficient(g, "B", oren_nayar_b, right_b, wrong_b, COUNT(wrong_b), 0.0);
}

/* A unit direction above the surface, from its polar angle and azimuth. */
static Vec3 polar(double theta, double phi)
{
    return vec3(sin(theta) * cos(phi), sin(theta) * sin(phi), cos(theta));
}

/* The inputs of one factor: sigma, theta_i, theta_o, phi_i, phi_o (and rho's red for the
 * BRDF). The parts of eq. 13 they give. */
#define ARITY 6
typedef struct {
    double a, b, c, alpha, beta; /* c = cos(phi_i - phi_o) */
} Parts;

static Parts parts(const double *x)
{
    Parts p = {right_a(x[0]), right_b(x[0]), cos(x[3] - x[4]), fmax(x[1], x[2]),
               fmin(x[1], x[2])};
    return p;
}

static double right_factor(const double *x)
{
    Parts p = parts(x);
    return p.a + p.b * fmax(0.0, p.c) * sin(p.alpha) * tan(p.beta);
}

static double factor_sin_beta(const double *x)
{
    Parts p = parts(x);
    return p.a + p.b * fmax(0.0, p.c) * sin(p.alpha) * sin(p.beta);
}
static double factor_swapped(const double *x)
{
    Parts p = parts(x);
    return p.a + p.b * fmax(0.0, p.c) * sin(p.beta) * tan(p.alpha);
}
static double factor_incoming_alpha(const double *x)
{
    Parts p = parts(x);
    return p.a + p.b * fmax(0.0, p.c) * sin(x[1]) * tan(x[2]);
}
static double factor_outgoing_alpha(const double *x)
{
    Parts p = parts(x);
    return p.a + p.b * fmax(0.0, p.c) * sin(x[2]) * tan(x[1]);
}
static double factor_no_max(const double *x)
{
    Parts p = parts(x);
    return p.a + p.b * p.c * sin(p.alpha) * tan(p.beta);
}
static double factor_abs(const double *x)
{
    Parts p = parts(x);
    return p.a + p.b * fabs(p.c) * sin(p.alpha) * tan(p.beta);
}
static double factor_a_alone(const double *x) { return parts(x).a; }
static double factor_b_alone(const double *x) { return right_factor(x) - parts(x).a; }
static double factor_a_b_swapped(const double *x)
{
    Parts p = parts(x);
    return p.b + p.a * fmax(0.0, p.c) * sin(p.alpha) * tan(p.beta);
}
static double factor_full_dot(const double *x)
{
    Parts p = parts(x);
    double dot = sin(x[1]) * sin(x[2]) * p.c + cos(x[1]) * cos(x[2]);
    return p.a + p.b * fmax(0.0, dot) / cos(p.beta);
}
static double factor_tan_tan(const double *x)
{
    Parts p = parts(x);
    return p.a + p.b * fmax(0.0, p.c) * tan(p.alpha) * tan(p.beta);
}
static double factor_with_cosine(const double *x) { return right_factor(x) * cos(x[1]); }
static double factor_with_pi(const double *x) { return right_factor(x) / PI; }

static const WrongAnswer wrong_factor[] = {
    {"A + B max(0, cos(phi_i - phi_o)) sin(alpha) sin(beta), sin(beta) where tan(beta) "
     "belongs (the report's misprint)",
     "the term is sin(alpha) tan(beta): max(0, x_i x_o + y_i y_o) / max(z_i, z_o)",
     factor_sin_beta},
    {"A + B max(0, cos(phi_i - phi_o)) sin(beta) tan(alpha): alpha and beta swapped (the "
     "projected dot divided by min(z_i, z_o))",
     "alpha is the larger angle (the smaller z), beta the smaller: divide by max(z_i, z_o)",
     factor_swapped},
    {"A + B max(0, cos(phi_i - phi_o)) sin(theta_i) tan(theta_o): alpha taken as theta_i and "
     "beta as theta_o, which is not reciprocal",
     "alpha = max(theta_i, theta_o), beta = min: divide by max(z_i, z_o)",
     factor_incoming_alpha},
    {"A + B max(0, cos(phi_i - phi_o)) sin(theta_o) tan(theta_i): alpha taken as theta_o and "
     "beta as theta_i, which is not reciprocal",
     "alpha = max(theta_i, theta_o), beta = min: divide by max(z_i, z_o)",
     factor_outgoing_alpha},
    {"A + B cos(phi_i - phi_o) sin(alpha) tan(beta), without max(0, ...)",
     "directions on opposite sides of the normal (cos(phi_i - phi_o) < 0) get A alone: "
     "max(0, x_i x_o + y_i y_o)",
     factor_no_max},
    {"A + B |cos(phi_i - phi_o)| sin(alpha) tan(beta), |...| where max(0, ...) belongs",
     "directions on opposite sides of the normal get A alone: max(0, x_i x_o + y_i y_o)",
     factor_abs},
    {"A alone: the angular term B max(0, cos(phi_i - phi_o)) sin(alpha) tan(beta) is missing",
     "add B max(0, x_i x_o + y_i y_o) / max(z_i, z_o)", factor_a_alone},
    {"the angular term alone, without A", "the factor is A + the angular term", factor_b_alone},
    {"B + A max(0, cos(phi_i - phi_o)) sin(alpha) tan(beta): A and B swapped",
     "A stands alone, B multiplies the angular term", factor_a_b_swapped},
    {"A + B max(0, wi . wo) / max(z_i, z_o): the whole dot product, z_i z_o included",
     "only the parts in the surface's plane: x_i x_o + y_i y_o", factor_full_dot},
    {"A + B max(0, cos(phi_i - phi_o)) tan(alpha) tan(beta)",
     "the term is sin(alpha) tan(beta): max(0, x_i x_o + y_i y_o) / max(z_i, z_o)",
     factor_tan_tan},
    {"the factor times cos(theta_i)",
     "the factor is f / (rho / pi) alone; the rendering equation's cosine is the caller's",
     factor_with_cosine},
    {"the factor divided by pi", "the factor is f / (rho / pi): no 1 / pi in it",
     factor_with_pi},
};

/* PAIRS random inputs (some at normal incidence or grazing, none within 0.001 of the
 * normal but at it, where a trigonometric form may take the term as 0), then swapped:
 * x[k * ARITY ...] = sigma, theta_i, theta_o, phi_i, phi_o, rho's red. */
static void factor_inputs(Grading *g, double *x)
{
    for (int i = 0; i < PAIRS; i++) {
        Rng rng = rng_for_sample(grading_stream(g, 51), 1, (uint64_t)i);
        double *p = x + (long)i * ARITY;
        p[0] = 0.05 + 1.95 * rng_uniform(&rng);
        p[1] = 0.001 + (0.49 * PI - 0.001) * rng_uniform(&rng);
        p[2] = 0.001 + (0.49 * PI - 0.001) * rng_uniform(&rng);
        p[3] = 2.0 * PI * rng_uniform(&rng);
        p[4] = 2.0 * PI * rng_uniform(&rng);
        p[5] = 0.1 + 0.8 * rng_uniform(&rng);
        if (i % 50 == 7)
            p[1 + i % 2] = 0.0; /* normal incidence */
        if (i % 50 == 21)
            p[1 + i % 2] = 0.5 * PI; /* grazing */
        if (i % 50 == 33)
            p[4] = p[3]; /* the same azimuth */
        double *q = x + (long)(PAIRS + i) * ARITY;
        q[0] = p[0], q[1] = p[2], q[2] = p[1], q[3] = p[4], q[4] = p[3], q[5] = p[5];
    }
}

/* Where a factor or BRDF that matches no known wrong answer goes wrong, in words: the
 * worst input, whether it is right where the angular term is 0, and its reciprocity. */
static void fail_factor(Grading *g, const char *what, const double *x, const double *got,
                        const double *want)
{
    int worst = 0, wrong_flat = 0, flat = 0, nonreciprocal = 0;
    for (int k = 0; k < 2 * PAIRS; k++) {
        const double *p = x + (long)k * ARITY;
        double error = fabs(got[k] - want[k]);
        if (error > fabs(got[worst] - want[worst]))
            worst = k;
        int term_zero = cos(p[3] - p[4]) <= 0.0 || p[1] == 0.0 || p[2] == 0.0;
        flat += term_zero;
        wrong_flat += term_zero && error > TOLERANCE * fmax(1.0, fabs(want[k]));
        if (k < PAIRS && fabs(got[k] - got[k + PAIRS]) > TOLERANCE * fmax(1.0, fabs(got[k])))
            nonreciprocal++;
    }
    const double *p = x + (long)worst * ARITY;
    int decimals = grading_decimals(got[worst], want[worst]);
    char where[300];
    if (wrong_flat == 0)
        snprintf(where, sizeof where,
                 "right wherever the angular term is 0 (at all %d inputs with cos(phi_i - "
                 "phi_o) <= 0 or a direction at the normal): the term B max(0, cos(phi_i - "
                 "phi_o)) sin(alpha) tan(beta) is wrong",
                 flat);
    else
        snprintf(where, sizeof where,
                 "wrong also at %d of the %d inputs where the angular term is 0: A itself is "
                 "(oren_nayar_a(sigma))",
                 wrong_flat, flat);
    grading_fail(g,
                 "%s %.*f at sigma = %.2f, theta_i = %.1f, theta_o = %.1f degrees, cos(phi_i "
                 "- phi_o) = %.2f, where eq. 13 gives %.*f (%.6g times that); %s%s",
                 what, decimals, got[worst], p[0], p[1] * 180.0 / PI, p[2] * 180.0 / PI,
                 cos(p[3] - p[4]), decimals, want[worst], got[worst] / want[worst], where,
                 nonreciprocal > 0 ? "; and it is not reciprocal: swapping wi and wo changes "
                                     "it, where f(wi, wo) = f(wo, wi)"
                                   : "");
    grading_note(g, "not reciprocal at %d of %d pairs", nonreciprocal, PAIRS);
}

/* Grade 2 PAIRS values `got` (the pairs, then swapped) against `right` of x: the known
 * wrong answers, else where they go wrong. Returns 1 when all are right. */
static int grade_values(Grading *g, const char *what, const double *x, const double *got,
                        double (*right)(const double *), const WrongAnswer *known, int count)
{
    static double want[2 * PAIRS];
    int wrong = 0;
    for (int k = 0; k < 2 * PAIRS; k++) {
        want[k] = right(x + (long)k * ARITY);
        if (grading_not_finite(g, got[k], what))
            return 0;
        wrong += !(fabs(got[k] - want[k]) <= TOLERANCE * fmax(1.0, fabs(want[k])));
    }
    grading_note(g,
                 "%d random pairs of directions and roughnesses and the same pairs swapped: "
                 "%d values differ from eq. 13 by more than 1e-9",
                 PAIRS, wrong);
    if (wrong == 0)
        return 1;
    const WrongAnswer *match = grading_known_wrong(known, count, x, ARITY, got, 2 * PAIRS);
    if (match)
        return grading_fail_known(g, what, match, 2 * PAIRS);
    fail_factor(g, what, x, got, want);
    return 0;
}

static void grade_factor(Grading *g)
{
    static double x[2 * PAIRS * ARITY], got[2 * PAIRS];
    factor_inputs(g, x);
    for (int k = 0; k < 2 * PAIRS; k++) {
        const double *p = x + (long)k * ARITY;
        got[k] = ASK(g, oren_nayar_factor(p[0], polar(p[1], p[3]), polar(p[2], p[4])));
    }
    if (!g->failed)
        grade_values(g, "factor", x, got, right_factor, wrong_factor, COUNT(wrong_factor));
}

/* The BRDF's red channel (rho's red x[5]), and known wrong ones. */
static double right_brdf(const double *x) { return x[5] / PI * right_factor(x); }
static double brdf_without_pi(const double *x) { return x[5] * right_factor(x); }
static double brdf_without_rho(const double *x) { return right_factor(x) / PI; }
static double brdf_lambert(const double *x) { return x[5] / PI; }
static double brdf_pi_twice(const double *x) { return right_brdf(x) / PI; }
static double brdf_with_cosine(const double *x) { return right_brdf(x) * cos(x[1]); }
static double brdf_incoming_twice(const double *x)
{
    double y[ARITY] = {x[0], x[1], x[1], x[3], x[3], x[5]};
    return right_brdf(y);
}
static double brdf_outgoing_twice(const double *x)
{
    double y[ARITY] = {x[0], x[2], x[2], x[4], x[4], x[5]};
    return right_brdf(y);
}

static const WrongAnswer wrong_brdf[] = {
    {"rho times the factor, without 1 / pi", "f = rho / pi times the factor (lambert_brdf)",
     brdf_without_pi},
    {"the factor / pi, without rho", "f = rho / pi times the factor: each channel its own rho",
     brdf_without_rho},
    {"Lambert's rho / pi: the factor is left out", "f = rho / pi times oren_nayar_factor",
     brdf_lambert},
    {"rho / pi^2 times the factor: 1 / pi taken twice", "lambert_brdf(rho) is already rho / pi",
     brdf_pi_twice},
    {"f times cos(theta_i)",
     "the BRDF is f alone; the rendering equation's cosine is the caller's", brdf_with_cosine},
    {"f(wi, wi): wi passed for wo as well",
     "wi is the direction to the light, wo to the viewer: oren_nayar_factor(sigma, wi, wo)",
     brdf_incoming_twice},
    {"f(wo, wo): wo passed for wi as well",
     "wi is the direction to the light, wo to the viewer: oren_nayar_factor(sigma, wi, wo)",
     brdf_outgoing_twice},
};

static void grade_brdf_closed_form(Grading *g)
{
    static double x[2 * PAIRS * ARITY], got[2 * PAIRS];
    factor_inputs(g, x);
    int channels_wrong = 0;
    for (int k = 0; k < 2 * PAIRS; k++) {
        const double *p = x + (long)k * ARITY;
        Vec3 rho = vec3(p[5], 0.5 * p[5], 0.25 + 0.5 * p[5]);
        Vec3 f = ASK_VEC3(g, oren_nayar_brdf(rho, p[0], polar(p[1], p[3]), polar(p[2], p[4])));
        got[k] = f.x;
        double scale = f.x / rho.x;
        channels_wrong += !(fabs(f.y - scale * rho.y) <= TOLERANCE * fmax(1.0, fabs(f.x)) &&
                            fabs(f.z - scale * rho.z) <= TOLERANCE * fmax(1.0, fabs(f.x)));
    }
    if (g->failed || !grade_values(g, "BRDF's red channel", x, got, right_brdf, wrong_brdf,
                                   COUNT(wrong_brdf)))
        return;
    if (channels_wrong > 0)
        grading_fail(g,
                     "the red channel is right but not the green and blue at %d of %d inputs: "
                     "each channel is its own rho times the same factor / pi (rho = (r, r / 2, "
                     "1/4 + r / 2) here)",
                     channels_wrong, 2 * PAIRS);
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

static void grade_brdf(Grading *g)
{
    grade_brdf_closed_form(g);
    if (!g->failed)
        grading_render(g, &rough_check, LEVEL,
                       "is f = lambert_brdf(rho) times oren_nayar_factor(sigma, wi, wo) (docs/"
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
     "return 0.0;", grade_factor, NULL, "5.1 5.2"},
    {"5.4", "oren_nayar_brdf",
     "Return eq. 13's BRDF f(wi, wo) for reflectance rho and roughness sigma, wi the unit "
     "local direction to the light and wo to the viewer: Lambert's rho / pi (lambert_brdf) "
     "times oren_nayar_factor(sigma, wi, wo), each channel its own rho. It must be "
     "reciprocal, f(wi, wo) = f(wo, wi). See docs/chapter5.md, section 2.",
     "return vec3(0, 0, 0);", grade_brdf, &rough_check, "5.3"},
};
const int exercise_count = sizeof exercises / sizeof exercises[0];
