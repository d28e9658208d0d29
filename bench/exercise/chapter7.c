/* chapter7.c (bench, chapter 7): chapter 7's exercises and their graders (grading.h).
 *
 * The power heuristic against its closed form (a catalogue of known wrong weights); what
 * its weights read from chapters 2 and 3 against their closed forms; the light at a floor
 * point by MIS against the exact integral over the lamp, and paired with the solution's on
 * the same numbers. The lamp's mirror image (docs/chapter7.md, section 3): each shadow ray
 * against the solution's from the same lamp point (known wrong variants named), then the
 * mean paired; a lamp facing the mirror and one tilted in mid-air. The course's level.
 */
#include <math.h>
#include <stdio.h>

#include "area_light.h"
#include "diffuse.h"
#include "direct_light.h"
#include "grading.h"
#include "hemisphere.h"
#include "lambert.h"
#include "mirror.h"
#include "mirror_light.h"
#include "mis.h"
#include "sphere_guide.h"

#define PAIRS 2000
#define MIS_SAMPLES 1250000
#define MIRROR_RAYS 180000 /* per scene */
#define MIRROR_REFLECTANCE 0.9
#define COUNT(list) (int)(sizeof list / sizeof list[0])

/* The weight's inputs: count_f, pdf_f, count_g, pdf_g. */
static double right_weight(const double *x)
{
    double f = x[0] * x[1], g = x[2] * x[3];
    return f > 0.0 ? f * f / (f * f + g * g) : 0.0;
}
static double weight_balance(const double *x)
{
    double f = x[0] * x[1], g = x[2] * x[3];
    return f > 0.0 ? f / (f + g) : 0.0;
}
static double weight_no_counts(const double *x)
{
    return x[1] > 0.0 ? x[1] * x[1] / (x[1] * x[1] + x[3] * x[3]) : 0.0;
}
static double weight_inverted(const double *x)
{
    double f = x[0] * x[1], g = x[2] * x[3];
    return f > 0.0 ? g * g / (f * f + g * g) : 0.0;
}
static double weight_balance_squared(const double *x)
{
    double w = weight_balance(x);
    return w * w;
}
static double weight_counts_unsquared(const double *x)
{
    double f = x[0] * x[1] * x[1], g = x[2] * x[3] * x[3];
    return x[1] > 0.0 ? f / (f + g) : 0.0;
}
static double weight_counts_swapped(const double *x)
{
    double f = x[2] * x[1], g = x[0] * x[3];
    return f > 0.0 ? f * f / (f * f + g * g) : 0.0;
}
static double weight_ratio_unsquared(const double *x)
{
    double f = x[0] * x[1], g = x[2] * x[3];
    return f > 0.0 ? 1.0 / (1.0 + g * g / f) : 0.0;
}

static const WrongAnswer wrong_weight[] = {
    {"the balance heuristic n_f p_f / (n_f p_f + n_g p_g)",
     "the power heuristic squares both: (n_f p_f)^2 / ((n_f p_f)^2 + (n_g p_g)^2)",
     weight_balance},
    {"p_f^2 / (p_f^2 + p_g^2), without the sample counts",
     "the power heuristic weighs n_f p_f against n_g p_g", weight_no_counts},
    {"(n_g p_g)^2 / ((n_f p_f)^2 + (n_g p_g)^2): the ratio inverted, the other strategy's "
     "weight",
     "strategy f's weight grows with its own density: (n_f p_f)^2 on top", weight_inverted},
    {"the balance heuristic's weight squared, (n_f p_f)^2 / (n_f p_f + n_g p_g)^2",
     "square each term, not the sum: (n_f p_f)^2 / ((n_f p_f)^2 + (n_g p_g)^2)",
     weight_balance_squared},
    {"n_f p_f^2 / (n_f p_f^2 + n_g p_g^2), the counts not squared",
     "the count multiplies the density before squaring: (n_f p_f)^2", weight_counts_unsquared},
    {"(n_g p_f)^2 / ((n_g p_f)^2 + (n_f p_g)^2): the counts swapped",
     "each density goes with its own strategy's count", weight_counts_swapped},
    {"1 / (1 + (n_g p_g)^2 / (n_f p_f)), the ratio's denominator not squared",
     "1 / (1 + r^2) with r = n_g p_g / (n_f p_f)", weight_ratio_unsquared},
};

/* The weight against its closed form; the known wrong ones named. Returns 1 when right. */
static int grade_weight_closed_form(Grading *g)
{
    static double x[PAIRS * 4], got[PAIRS], other[PAIRS];
    int wrong = -1, sum_wrong = -1;
    for (int i = 0; i < PAIRS; i++) {
        Rng rng = rng_for_sample(grading_stream(g, 71), 1, (uint64_t)i);
        double *p = x + 4 * i;
        p[0] = 1 + (int)(4 * rng_uniform(&rng)), p[2] = 1 + (int)(4 * rng_uniform(&rng));
        p[1] = i % 10 == 0 ? 0.0 : 5.0 * rng_uniform(&rng), p[3] = 5.0 * rng_uniform(&rng);
        if (i % 50 == 1)
            p[1] = p[3] = 0.0;
        got[i] = ASK(g, mis_power_heuristic((int)p[0], p[1], (int)p[2], p[3]));
        other[i] = ASK(g, mis_power_heuristic((int)p[2], p[3], (int)p[0], p[1]));
        if (grading_not_finite(g, got[i],
                               p[1] == 0.0 && p[3] == 0.0
                                   ? "the weight when both densities are 0"
                                   : "the weight"))
            return 0;
        if (wrong < 0 && !(fabs(got[i] - right_weight(p)) <= 1e-12))
            wrong = i;
        if (sum_wrong < 0 && p[1] > 0.0 && p[3] > 0.0 && fabs(got[i] + other[i] - 1.0) > 1e-9)
            sum_wrong = i;
    }
    grading_note(g, "%d random counts and densities (some 0) against the closed form", PAIRS);
    if (wrong < 0)
        return 1;
    const WrongAnswer *match =
        grading_known_wrong(wrong_weight, COUNT(wrong_weight), x, 4, got, PAIRS);
    if (match)
        return grading_fail_known(g, "weight", match, PAIRS);
    const double *p = x + 4 * wrong;
    double want = right_weight(p);
    int decimals = grading_decimals(got[wrong], want);
    if (sum_wrong >= 0) {
        const double *q = x + 4 * sum_wrong;
        return grading_fail(g,
                            "the weights of the two strategies for one direction sum to "
                            "%.6f, not 1 (counts %g and %g, pdfs %.3f and %.3f), so the "
                            "estimate is biased by that factor there; the first wrong "
                            "weight: %.*f where (n_f p_f)^2 / ((n_f p_f)^2 + (n_g p_g)^2) = "
                            "%.*f",
                            got[sum_wrong] + other[sum_wrong], q[0], q[2], q[1], q[3], decimals,
                            got[wrong], decimals, want);
    }
    return grading_fail(g,
                        "the weight is %.*f for counts %g, %g and pdfs %.3f, %.3f, where "
                        "(n_f p_f)^2 / ((n_f p_f)^2 + (n_g p_g)^2) = %.*f (%s); the two "
                        "weights of a direction still sum to 1",
                        decimals, got[wrong], p[0], p[2], p[1], p[3], decimals, want,
                        p[1] == 0.0 ? "strategy f cannot draw it: 0"
                                    : "the ratio n_g p_g / (n_f p_f) decides it");
}

/* A white floor and a square lamp above it, beside the floor point at the origin. */
static const char mis_scene[] = "camera 0 -3 1   -1 -2 0   1 -2 0   -1 -2 2\n"
                                "material floor lambert 0.5 0.5 0.5\n"
                                "material lamp  light   10 10 10\n"
                                "quad floor -10 -10 0   10 -10 0   10 10 0   -10 10 0\n"
                                "quad lamp 0.2 -0.5 1   0.2 0.5 1   1.2 0.5 1   1.2 -0.5 1\n";
static const Vec3 lamp_corners[4] = {
    {0.2, -0.5, 1}, {0.2, 0.5, 1}, {1.2, 0.5, 1}, {1.2, -0.5, 1}};
#define LAMP_HEIGHT 1.0

/* The integral of cos(theta) over the lamp seen from the origin (normal +z), by
 * Lambert's formula for a polygon: 1/2 sum_i angle(v_i, v_i+1) (z . unit(v_i x v_i+1)). */
static double lamp_projected_solid_angle(void)
{
    double sum = 0.0;
    for (int i = 0; i < 4; i++) {
        Vec3 a = vec3_normalize(lamp_corners[i]), b = vec3_normalize(lamp_corners[(i + 1) % 4]);
        sum += acos(vec3_dot(a, b)) * vec3_normalize(vec3_cross(a, b)).z;
    }
    return 0.5 * fabs(sum);
}

static double pdf_area(const double *x) { return 1.0 / x[2]; }
static double pdf_no_cosine(const double *x) { return x[0] * x[0] / x[2]; }
static double pdf_inverted(const double *x) { return x[2] * x[1] / (x[0] * x[0]); }
static double pdf_not_squared(const double *x) { return x[0] / (x[2] * x[1]); }
static double pdf_right(const double *x) { return x[0] * x[0] / (x[2] * x[1]); }

/* A density towards a lamp point of inputs distance, cos(beta), light area. */
static const WrongAnswer wrong_light_pdf[] = {
    {"1 / A, the density in area measure",
     "MIS compares densities in solid angle: d^2 / (A cos beta)", pdf_area},
    {"d^2 / A, without the cosine at the lamp", "d^2 / (A cos beta)", pdf_no_cosine},
    {"A cos(beta) / d^2, the density inverted", "d^2 / (A cos beta)", pdf_inverted},
    {"d / (A cos beta), the distance not squared", "d^2 / (A cos beta)", pdf_not_squared},
};

/* Exercise 2.3's lambert_brdf, the f of both of the estimate's terms (through
 * diffuse_brdf), against rho / pi at POINTS albedos. Returns 1 when it holds. */
static int lambert_rechecked(Grading *g, int points)
{
    for (int i = 0; i < points; i++) {
        Rng rng = rng_for_sample(grading_stream(g, 73), 4, (uint64_t)i);
        Vec3 rho = vec3(rng_uniform(&rng), rng_uniform(&rng), rng_uniform(&rng));
        Vec3 got = ASK_VEC3(g, lambert_brdf(rho)), want = vec3_scale(rho, 1.0 / PI);
        if (grading_not_finite(g, got.x + got.y + got.z, "lambert_brdf (exercise 2.3)"))
            return 0;
        if (vec3_length(vec3_sub(got, want)) <= 1e-12 * vec3_length(want))
            continue;
        double ratio = vec3_dot(got, want) / vec3_dot(want, want);
        return grading_fail(g,
                            "exercise 2.3 (lambert_brdf), the f that the shadow ray and the "
                            "bounce both read, is wrong: f = (%.5f, %.5f, %.5f) for rho = "
                            "(%.3f, %.3f, %.3f) where rho / pi = (%.5f, %.5f, %.5f), %.4g "
                            "times that%s",
                            got.x, got.y, got.z, rho.x, rho.y, rho.z, want.x, want.y, want.z,
                            ratio, fabs(ratio - PI) < 1e-9 ? ": the 1 / pi is missing" : "");
    }
    return 1;
}

/* Exercise 3.2's area_light_pdf and the pdf of 3.3's shadow rays (what the MIS weights
 * read), 2.2's hemisphere_pdf_cosine (the bounce's density in the weights) and 2.3's
 * lambert_brdf (the f of both terms), each against its closed form. Returns 1 when all
 * hold. */
static int grade_densities_read(Grading *g, const Scene *scene)
{
    enum {
        POINTS = 200
    };
    if (!lambert_rechecked(g, POINTS))
        return 0;
    double x[3 * POINTS], got[POINTS];
    double area = scene->light_area;
    for (int i = 0; i < POINTS; i++) {
        Rng rng = rng_for_sample(grading_stream(g, 73), 1, (uint64_t)i);
        x[3 * i] = 0.2 + 3.0 * rng_uniform(&rng);
        x[3 * i + 1] = 0.05 + 0.95 * rng_uniform(&rng);
        x[3 * i + 2] = area;
        got[i] = ASK(g, area_light_pdf(scene, x[3 * i], x[3 * i + 1]));
        if (grading_not_finite(g, got[i], "area_light_pdf (exercise 3.2)"))
            return 0;
    }
    const char *blame = "exercise 3.2 (area_light_pdf), whose density the MIS weights read, is "
                        "wrong";
    for (int i = 0; i < POINTS; i++) {
        if (fabs(got[i] - pdf_right(x + 3 * i)) <= 1e-9 * pdf_right(x + 3 * i))
            continue;
        const WrongAnswer *match =
            grading_known_wrong(wrong_light_pdf, COUNT(wrong_light_pdf), x, 3, got, POINTS);
        if (match)
            return grading_fail(g, "%s: it equals %s (at %d inputs): %s", blame, match->wrong,
                                POINTS, match->right);
        return grading_fail(g,
                            "%s: %.6g at d = %.3f, cos(beta) = %.3f where d^2 / (A cos beta) "
                            "= %.6g (%.6g times that)",
                            blame, got[i], x[3 * i], x[3 * i + 1], pdf_right(x + 3 * i),
                            got[i] / pdf_right(x + 3 * i));
    }
    /* the shadow ray's own pdf, at the floor point below the lamp */
    Vec3 origin = vec3(0, 0, 0), up = vec3(0, 0, 1);
    Material floor = {
        .name = "floor", .kind = MATERIAL_LAMBERT, .reflectance = vec3(0.5, 0.5, 0.5)};
    RayCounts counts = {0};
    double ray_x[3 * POINTS], ray_pdf[POINTS];
    int lit = 0;
    for (int i = 0; i < POINTS; i++) {
        Rng rng = rng_for_sample(grading_stream(g, 73), 2, (uint64_t)i);
        ShadowRay ray = {vec3(0, 0, 0), vec3(0, 0, 0), 0.0};
        if (grading_probing(g))
            ray = area_light_shadow_ray(scene, origin, up, up, &floor, &rng, &counts);
        ray.value = grading_ask_vec3(g, ray.value);
        ray.wi = grading_ask_vec3(g, ray.wi);
        ray.pdf = grading_ask(g, ray.pdf);
        if (!(ray.value.y > 0.0) || !(ray.wi.z > 0.0))
            continue;
        double d = LAMP_HEIGHT / ray.wi.z;
        ray_x[3 * lit] = d, ray_x[3 * lit + 1] = ray.wi.z, ray_x[3 * lit + 2] = area;
        ray_pdf[lit++] = ray.pdf;
    }
    for (int i = 0; i < lit; i++) {
        double want = pdf_right(ray_x + 3 * i);
        if (fabs(ray_pdf[i] - want) <= 1e-6 * want)
            continue;
        const WrongAnswer *match = grading_known_wrong(wrong_light_pdf, COUNT(wrong_light_pdf),
                                                       ray_x, 3, ray_pdf, lit);
        return grading_fail(
            g,
            "exercise 3.3 (area_light_shadow_ray) returns shadow rays whose pdf the MIS "
            "weights "
            "read wrong: %.6g for a ray of length %.3f at cos(beta) = %.3f where "
            "area_light_pdf gives d^2 / (A cos beta) = %.6g%s%s",
            ray_pdf[i], ray_x[3 * i], ray_x[3 * i + 1], want, match ? ": it is " : "",
            match ? match->wrong : "");
    }
    /* the bounce's density, cos(theta) / pi */
    for (int i = 0; i < POINTS; i++) {
        Rng rng = rng_for_sample(grading_stream(g, 73), 3, (uint64_t)i);
        double z = i % 20 == 0 ? -0.3 : rng_uniform(&rng), s = sqrt(fmax(0.0, 1.0 - z * z));
        Vec3 w = vec3(s, 0.0, z);
        double got_pdf = ASK(g, hemisphere_pdf_cosine(w)), want = z > 0.0 ? z / PI : 0.0;
        if (grading_not_finite(g, got_pdf, "hemisphere_pdf_cosine (exercise 2.2)"))
            return 0;
        if (!(fabs(got_pdf - want) <= 1e-9 * fmax(want, 1e-3)))
            return grading_fail(
                g,
                "exercise 2.2 (hemisphere_pdf_cosine), the bounce's density "
                "that the MIS weights read, is wrong: %.6g at cos(theta) = %.3f "
                "where cos(theta) / pi = %.6g",
                got_pdf, z, want);
    }
    grading_note(g,
                 "what the weights read: area_light_pdf at %d inputs, %d shadow rays' pdf, "
                 "hemisphere_pdf_cosine at %d directions, lambert_brdf at %d albedos: all "
                 "right",
                 POINTS, lit, POINTS, POINTS);
    return 1;
}

/* One MIS estimate of the light at x (green): a weighted shadow ray and a weighted bounce,
 * as the final path tracer combines them (direct_light, direct_light_hit_weight). */
static double mis_estimate(const Scene *scene, const Vertex *x, const PathSettings *settings,
                           Rng *rng)
{
    RayCounts counts = {0};
    Vec3 direction, direct = direct_light(scene, x, 0, settings, rng, &counts);
    double bounce_pdf, estimate = direct.y;
    Vec3 weight = sphere_guide_bounce(scene, x, 0.0, rng, &direction, &bounce_pdf);
    Vertex y;
    if (path_vertex(scene, ray_spawn(x->hit.point, x->normal, direction, x->hit.scale), &y) &&
        y.front && material_emits(y.material))
        estimate += weight.y * y.material->emission.y *
                    direct_light_hit_weight(scene, settings, bounce_pdf, y.hit.t,
                                            vec3_dot(y.wo, y.hit.normal));
    return estimate;
}

/* The light at the floor point by MIS, a shadow ray and a bounce each weighted
 * (direct_light and direct_light_hit_weight, as the final path tracer combines them),
 * against the exact (rho / pi) Le times the lamp's projected solid angle, and paired with
 * the solution's estimate on the same random numbers. */
static void grade_mis_estimate(Grading *g, const Scene *scene)
{
    PathSettings settings = {.max_depth = 3, .shadow_rays = 1, .mis = 1};
    Vertex x;
    Ray down = {vec3(0, 0, 1e-3), vec3(0, 0, -1)};
    if (!path_vertex(scene, down, &x)) {
        grading_fail(g, "the floor point is not found");
        return;
    }
    double exact = 0.5 / PI * 10.0 * lamp_projected_solid_angle();
    double sum = 0.0, sum2 = 0.0, dsum = 0.0, dsum2 = 0.0;
    for (long i = 0; i < MIS_SAMPLES; i++) {
        Rng rng = rng_for_sample(grading_stream(g, 74), 1, (uint64_t)i), again = rng;
        double estimate = grading_probing(g) ? mis_estimate(scene, &x, &settings, &rng) : 0.0;
        estimate = ASK(g, estimate);
        if (grading_not_finite(g, estimate, "the MIS estimate"))
            return;
        sum += estimate;
        sum2 += estimate * estimate;
        if (grading_probing(g))
            continue;
        double solution = mis_estimate(scene, &x, &settings, &again); /* the solution's */
        dsum += estimate - solution;
        dsum2 += (estimate - solution) * (estimate - solution);
    }
    if (grading_probing(g))
        return;
    double n = MIS_SAMPLES, mean = sum / n, se = sqrt(fmax(0.0, sum2 / n - mean * mean) / n);
    double dmean = dsum / n, dse = sqrt(fmax(0.0, dsum2 / n - dmean * dmean) / n);
    double z = se > 0.0 ? (mean - exact) / se : (mean == exact ? 0.0 : INFINITY);
    double dz = dse > 0.0 ? dmean / dse : (dmean == 0.0 ? 0.0 : INFINITY);
    double limit = grading_z(grading_level());
    grading_note(g,
                 "MIS at the floor point: %.6f +- %.2g where the exact (rho / pi) Le times the "
                 "lamp's projected solid angle is %.6f (z = %+.1f); yours minus the solution's "
                 "on the same numbers: %.3g +- %.2g (z = %+.1f); limit |z| <= %.2f; detectable "
                 "bias %.2g%% (paired: %.2g%%)",
                 mean, se, exact, z, dmean, dse, dz, limit,
                 100.0 * grading_detectable(se) / exact,
                 100.0 * grading_detectable(dse) / exact);
    if (fabs(z) > limit || fabs(dz) > limit)
        grading_fail(g,
                     "the light at a floor point by MIS (a shadow ray and a bounce, each "
                     "weighted) is %.4f times the exact %.5f (z = %.1f): the weights of the "
                     "two ways to one direction must sum to 1, both computed from densities in "
                     "solid angle (area_light_pdf's d^2 / (A cos beta) and the bounce's "
                     "cos / pi)",
                     mean / exact, exact, fabs(z) > limit ? z : dz);
}

static void grade_power(Grading *g)
{
    if (!grade_weight_closed_form(g))
        return;
    Scene scene;
    if (grading_scene(g, mis_scene, &scene) != 0)
        return;
    if (grade_densities_read(g, &scene))
        grade_mis_estimate(g, &scene);
    scene_free(&scene);
}

/* The mirror at z = 2 above the floor; a lamp below it facing it (the floor point at the
 * origin sees its image straight up), or tilted 75 degrees towards +x, in mid-air (the
 * floor point at x = 3 sees its image up and back, and the real lamp's own normal faces
 * that way too, less steeply). */
static const char mirror_facing[] =
    "camera 0 0 -1   -1 -1 0   1 -1 0   -1 1 0\n"
    "material mirror mirror 0.9 0.9 0.9\n"
    "material lamp light 10 10 10\n"
    "quad mirror -10 -10 2   10 -10 2   10 10 2   -10 10 2\n"
    "quad lamp 1.25 -0.25 1   1.75 -0.25 1   1.75 0.25 1   1.25 0.25 1\n";
static const char mirror_tilted[] =
    "camera 0 0 -1   -1 -1 0   1 -1 0   -1 1 0\n"
    "material mirror mirror 0.9 0.9 0.9\n"
    "material lamp light 10 10 10\n"
    "quad mirror -10 -10 2   10 -10 2   10 10 2   -10 10 2\n"
    "quad lamp 1.4353 -0.25 1.2415   1.5647 -0.25 0.7585   1.5647 0.25 0.7585   "
    "1.4353 0.25 1.2415\n";

/* One shadow ray's value (green) done right, and as the known mistakes do it. */
enum {
    RIGHT,
    REAL_NORMAL,
    REAL_NORMAL_ABS,
    NO_REFLECTANCE,
    REAL_DISTANCE,
    NO_COS_ALPHA,
    VARIANTS
};
static const char *const variant_words[VARIANTS] = {
    "",
    "cos(beta) taken at the real lamp's normal n_y, where the image's normal "
    "mirror_reflect(n_y, n_plane) belongs (the lamp point's reflection and the mirror hit "
    "are right)",
    "|cos(beta)| taken at the real lamp's normal n_y, where the image's normal "
    "mirror_reflect(n_y, n_plane) belongs (the lamp point's reflection and the mirror hit "
    "are right)",
    "the light without the mirror's reflectance R (0.9): multiply f by R",
    "the light with d the distance to the real lamp point, where the path's length is the "
    "distance to its image y'",
    "the light without cos(alpha) at the floor point",
};

/* The solution's ray and the variants' values from the lamp point the same numbers give. */
static void mirror_variants(const Scene *scene, const MirrorPlane *plane, Vec3 x, Rng rng,
                            ShadowRay *right, double *values)
{
    Vec3 n = vec3(0, 0, 1);
    Material floor = {
        .name = "floor", .kind = MATERIAL_LAMBERT, .reflectance = vec3(0.5, 0.5, 0.5)};
    RayCounts counts = {0};
    Rng again = rng;
    *right = mirror_light_shadow_ray(scene, plane, x, n, n, &floor, &again, &counts);
    double u_select = rng_uniform(&rng), u1, u2;
    rng_pair(&rng, &u1, &u2);
    LightSample y = area_light_sample(scene, u_select, u1, u2);
    for (int v = 0; v < VARIANTS; v++)
        values[v] = 0.0;
    values[RIGHT] = right->value.y;
    if (!(right->value.y > 0.0))
        return;
    Vec3 wi = right->wi;
    Vec3 image = vec3_add_scaled(y.point, plane->normal,
                                 -2.0 * (vec3_dot(plane->normal, y.point) - plane->offset));
    double cos_image = -vec3_dot(mirror_reflect(y.normal, plane->normal), wi);
    double cos_real = -vec3_dot(y.normal, wi);
    double d_image = vec3_length(vec3_sub(image, x)),
           d_real = vec3_length(vec3_sub(y.point, x));
    values[REAL_NORMAL] = cos_real > 0.0 ? right->value.y * cos_real / cos_image : 0.0;
    values[REAL_NORMAL_ABS] = right->value.y * fabs(cos_real) / cos_image;
    values[NO_REFLECTANCE] = right->value.y / MIRROR_REFLECTANCE;
    values[REAL_DISTANCE] = right->value.y * d_image * d_image / (d_real * d_real);
    values[NO_COS_ALPHA] = right->value.y / vec3_dot(n, wi);
}

typedef struct {
    long rays, differ, matches[VARIANTS], dark; /* dark: yours 0 where the right one is not */
    long dark_real_faces_away;                  /* ... and the real lamp's normal faces away */
    long wrong_pdf, wrong_wi;
    double sum, sum2, dsum, dsum2, right_sum;
} MirrorTally;

static int close_value(double a, double b)
{
    return fabs(a - b) <= 1e-9 * fmax(fabs(b), 1e-12);
}

/* The student's rays in one scene, each against the solution's from the same numbers. */
static int mirror_rays(Grading *g, const char *text, Vec3 x, uint64_t stream, MirrorTally *t)
{
    Scene scene;
    if (grading_scene(g, text, &scene) != 0)
        return 0;
    MirrorPlanes planes = {NULL, 0};
    if (mirror_light_find_planes(&scene, &planes) != 0 || planes.count != 1) {
        mirror_planes_free(&planes);
        scene_free(&scene);
        return grading_fail(g, "the scene's mirror plane is not found");
    }
    Vec3 n = vec3(0, 0, 1);
    Material floor = {
        .name = "floor", .kind = MATERIAL_LAMBERT, .reflectance = vec3(0.5, 0.5, 0.5)};
    RayCounts counts = {0};
    for (long i = 0; i < MIRROR_RAYS; i++) {
        Rng rng = rng_for_sample(grading_stream(g, 72), stream, (uint64_t)i), again = rng;
        ShadowRay yours = {vec3(0, 0, 0), vec3(0, 0, 0), 0.0};
        if (grading_probing(g))
            yours = mirror_light_shadow_ray(&scene, &planes.planes[0], x, n, n, &floor, &rng,
                                            &counts);
        yours.value = grading_ask_vec3(g, yours.value);
        yours.wi = grading_ask_vec3(g, yours.wi);
        yours.pdf = grading_ask(g, yours.pdf);
        if (grading_not_finite(g, yours.value.y, "a shadow ray's value"))
            break;
        if (grading_probing(g))
            continue;
        ShadowRay right;
        double values[VARIANTS];
        mirror_variants(&scene, &planes.planes[0], x, again, &right, values);
        double v = yours.value.y;
        t->rays++;
        t->sum += v;
        t->sum2 += v * v;
        t->dsum += v - values[RIGHT];
        t->dsum2 += (v - values[RIGHT]) * (v - values[RIGHT]);
        t->right_sum += values[RIGHT];
        for (int k = 0; k < VARIANTS; k++)
            t->matches[k] += close_value(v, values[k]);
        t->differ += !close_value(v, values[RIGHT]);
        if (v == 0.0 && values[RIGHT] > 0.0) {
            t->dark++;
            t->dark_real_faces_away += values[REAL_NORMAL] == 0.0;
        }
        if (v > 0.0 && values[RIGHT] > 0.0) {
            t->wrong_wi += vec3_length(vec3_sub(yours.wi, right.wi)) > 1e-9;
            t->wrong_pdf += !close_value(yours.pdf, right.pdf);
        }
    }
    mirror_planes_free(&planes);
    scene_free(&scene);
    return !g->failed;
}

static void grade_mirror_light(Grading *g)
{
    MirrorTally t = {0};
    if (!mirror_rays(g, mirror_facing, vec3(0, 0, 0), 1, &t) ||
        !mirror_rays(g, mirror_tilted, vec3(3, 0, 0), 2, &t) || grading_probing(g))
        return;
    double n = (double)t.rays, mean = t.sum / n, right = t.right_sum / n;
    double dmean = t.dsum / n, dse = sqrt(fmax(0.0, t.dsum2 / n - dmean * dmean) / n);
    double dz = dse > 0.0 ? dmean / dse : (dmean == 0.0 ? 0.0 : INFINITY);
    grading_note(g,
                 "%ld shadow rays to the lamps' images (a lamp facing the mirror, one tilted "
                 "beside it): mean light %.6f, the solution's from the same lamp points "
                 "%.6f; %ld rays differ from it; paired difference %.3g +- %.2g (z = %+.1f, "
                 "limit %.2f); detectable bias %.2g%% paired, %.2g%% for rays drawn otherwise",
                 t.rays, mean, right, t.differ, dmean, dse, dz, grading_z(grading_level()),
                 100.0 * grading_detectable(dse) / right,
                 100.0 *
                     grading_detectable(sqrt(2.0 * fmax(0.0, t.sum2 / n - mean * mean) / n)) /
                     right);
    for (int k = 1; k < VARIANTS && t.differ > 0; k++)
        if (t.matches[k] == t.rays) {
            grading_fail(g,
                         "each of your %ld shadow rays carries %s (it matches that at every "
                         "ray, to 1e-9)",
                         t.rays, variant_words[k]);
            return;
        }
    if (fabs(dz) > grading_z(grading_level())) {
        if (t.dark > 0 && t.dark_real_faces_away == t.dark && t.wrong_wi == 0)
            grading_fail(g,
                         "%ld shadow rays that reach the image carry no light in yours, each "
                         "where the real lamp's normal faces away from the ray: the image's "
                         "normal is mirror_reflect(n_y, n_plane); the rays that do carry light "
                         "aim at the image as they should",
                         t.dark);
        else if (mean == 0.0)
            grading_fail(g,
                         "no light reaches the floor through the mirror (0 where %.4f is "
                         "right): is the lamp point reflected in the plane (y' = y - 2 h n, h "
                         "its height above the plane), and is the first hit towards the image "
                         "the mirror?",
                         right);
        else
            grading_fail(g,
                         "the light through the mirror is %.4f times the right %.5f (z = %.1f; "
                         "%ld of %ld rays dark where they should carry light): is the value "
                         "Le f R cos(alpha) cos(beta) A / d^2, with d the distance to the "
                         "image and beta at the image's normal (docs/chapter7.md, section 3)?",
                         mean / right, right, dz, t.dark, t.rays);
    } else if (t.wrong_pdf > 0)
        grading_fail(g,
                     "%ld shadow rays carry a pdf other than d^2 / (A cos beta) at the image "
                     "(area_light_pdf with the distance to the image and its cosine): MIS "
                     "would weigh them wrongly",
                     t.wrong_pdf);
}

const Exercise exercises[] = {
    {"7.1", "mis_power_heuristic",
     "Return the power heuristic's weight of strategy f (count_f samples of density pdf_f) "
     "against strategy g for one direction: (count_f pdf_f)^2 / ((count_f pdf_f)^2 + (count_g "
     "pdf_g)^2), 0 when count_f pdf_f is 0; the two strategies' weights sum to one. See "
     "docs/chapter7.md, section 2.",
     "return 0.0;", grade_power, NULL, ""},
    {"7.2", "mirror_light_shadow_ray",
     "One shadow ray at the diffuse point x to the image of a lamp point y "
     "(area_light_sample) in `plane`: with h_x, h_y the heights of x and y above the plane "
     "(zero value unless on the same side), the image y' = y - 2 h_y n_plane, its normal "
     "mirror_reflect(n_y, n_plane); with wi the unit direction to y', d its distance and the "
     "cosines at x and y' both > 0, the first hit towards y' (scene_intersect) must be a "
     "mirror triangle in this plane and the way from it to y unblocked (scene_occluded); "
     "then value = Le f R cos(alpha) cos(beta) A / d^2 (R the mirror's reflectance), wi, "
     "and pdf = area_light_pdf(scene, d, cos(beta)). See docs/chapter7.md, section 3.",
     "ShadowRay ray = {vec3(0, 0, 0), vec3(0, 0, 0), 0.0};\nreturn ray;", grade_mirror_light,
     NULL, ""},
};
const int exercise_count = sizeof exercises / sizeof exercises[0];
