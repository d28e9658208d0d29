/* chapter7.c (bench, chapter 7): chapter 7's exercises and their graders (grading.h).
 *
 * The power heuristic against its closed form, and its two weights for one direction
 * summing to one. The lamp's mirror image (docs/chapter7.md, section 3) by what a
 * mirror does: light at a point on the floor through a mirror of reflectance 0.9 is
 * 0.9 times the direct light from the lamp's reflection with no mirror, so the mean of
 * the student's shadow rays to the image is compared with 0.9 times the mean of
 * chapter 3's shadow rays to a lamp put where the image is (200,000 each, fixed seeds,
 * significance level 0.01: |z| <= 2.58).
 */
#include <math.h>
#include <stdio.h>

#include "area_light.h"
#include "grading.h"
#include "mirror_light.h"
#include "mis.h"

#define SHADOW_RAYS 200000
#define Z_LEVEL 2.58
#define MIRROR_REFLECTANCE 0.9

static double right_weight(int cf, double pf, int cg, double pg)
{
    double f = cf * pf, g = cg * pg;
    return f > 0.0 ? f * f / (f * f + g * g) : 0.0;
}

static void grade_power(Grading *g)
{
    int checked = 0;
    for (int i = 0; i < 2000 && !g->failed; i++, checked++) {
        Rng rng = rng_for_sample(71, 1, (uint64_t)i);
        int cf = 1 + (int)(4 * rng_uniform(&rng)), cg = 1 + (int)(4 * rng_uniform(&rng));
        double pf = i % 10 == 0 ? 0.0 : 5.0 * rng_uniform(&rng), pg = 5.0 * rng_uniform(&rng);
        if (i % 50 == 1)
            pf = pg = 0.0;
        double wf = ASK(g, mis_power_heuristic(cf, pf, cg, pg));
        double wg = ASK(g, mis_power_heuristic(cg, pg, cf, pf));
        double want = right_weight(cf, pf, cg, pg);
        if (grading_not_finite(g, wf,
                               pf == 0.0 && pg == 0.0 ? "the weight when both densities are 0"
                                                      : "the weight"))
            break;
        if (fabs(wf - want) <= 1e-12)
            continue;
        double f = cf * pf, h = cg * pg;
        if (pf > 0.0 && pg > 0.0 && fabs(wf + wg - 1.0) > 1e-9)
            grading_fail(
                g,
                "the weights of the two strategies for one direction sum to %.4f, not "
                "1 (counts %d and %d, pdfs %.3f and %.3f): the estimate would be biased",
                wf + wg, cf, cg, pf, pg);
        else if (fabs(wf - f / (f + h)) <= 1e-12)
            grading_fail(g,
                         "the weight is %.4f, the balance heuristic's n_f p_f / (n_f p_f + "
                         "n_g p_g); the power heuristic squares both: %.4f",
                         wf, want);
        else if (fabs(wf - pf * pf / (pf * pf + pg * pg)) <= 1e-12)
            grading_fail(g,
                         "the weight is %.4f, without the sample counts (%d and %d): the power "
                         "heuristic weighs n_f p_f against n_g p_g, giving %.4f",
                         wf, cf, cg, want);
        else
            grading_fail(g,
                         "the weight is %.*f for counts %d, %d and pdfs %.3f, %.3f, where "
                         "(n_f p_f)^2 / ((n_f p_f)^2 + (n_g p_g)^2) = %.*f",
                         grading_decimals(wf, want), wf, cf, cg, pf, pg,
                         grading_decimals(wf, want), want);
    }
    grading_note(g, "%d random counts and densities (some 0) against the closed form", checked);
}

/* The mirror at z = 2 above a floor point at the origin, the lamp at z = 1 facing it. */
static const char with_mirror[] =
    "camera 0 0 -1   -1 -1 0   1 -1 0   -1 1 0\n"
    "material mirror mirror 0.9 0.9 0.9\n"
    "material lamp light 10 10 10\n"
    "quad mirror -10 -10 2   10 -10 2   10 10 2   -10 10 2\n"
    "quad lamp 1.25 -0.25 1   1.75 -0.25 1   1.75 0.25 1   1.25 0.25 1\n";
/* The lamp's reflection in that mirror, at z = 3 facing down, and no mirror. */
static const char image_only[] =
    "camera 0 0 -1   -1 -1 0   1 -1 0   -1 1 0\n"
    "material lamp light 10 10 10\n"
    "quad lamp 1.25 -0.25 3   1.25 0.25 3   1.75 0.25 3   1.75 -0.25 3\n";

typedef struct {
    double mean, se;
} Mean;

static Mean mean_of(double sum, double sum2, long n)
{
    Mean m = {sum / n, 0.0};
    m.se = sqrt(fmax(0.0, sum2 / n - m.mean * m.mean) / n);
    return m;
}

static void grade_mirror_light(Grading *g)
{
    Scene mirror_scene, image_scene;
    if (grading_scene(g, with_mirror, &mirror_scene) != 0)
        return;
    if (grading_scene(g, image_only, &image_scene) != 0) {
        scene_free(&mirror_scene);
        return;
    }
    MirrorPlanes planes = {NULL, 0};
    if (mirror_light_find_planes(&mirror_scene, &planes) != 0 || planes.count != 1) {
        grading_fail(g, "the scene's mirror plane is not found");
        goto done;
    }
    Material floor = {
        .name = "floor", .kind = MATERIAL_LAMBERT, .reflectance = vec3(0.5, 0.5, 0.5)};
    Vec3 x = vec3(0, 0, 0), n = vec3(0, 0, 1), wo = vec3(0, 0, 1);
    double sum[2] = {0, 0}, sum2[2] = {0, 0};
    long wrong_pdf = 0;
    RayCounts counts = {0};
    for (long i = 0; i < SHADOW_RAYS; i++) {
        Rng rng = rng_for_sample(72, 1, (uint64_t)i), rng2 = rng_for_sample(72, 2, (uint64_t)i);
        ShadowRay yours = {vec3(0, 0, 0), vec3(0, 0, 0), 0.0};
        if (grading_probing(g))
            yours = mirror_light_shadow_ray(&mirror_scene, &planes.planes[0], x, n, wo, &floor,
                                            &rng, &counts);
        yours.value = grading_ask_vec3(g, yours.value);
        yours.wi = grading_ask_vec3(g, yours.wi);
        yours.pdf = grading_ask(g, yours.pdf);
        if (grading_not_finite(g, yours.value.y, "a shadow ray's value"))
            goto done;
        sum[0] += yours.value.y;
        sum2[0] += yours.value.y * yours.value.y;
        if (!grading_probing(g)) { /* the oracle: the solution's shadow ray to the image */
            ShadowRay image =
                area_light_shadow_ray(&image_scene, x, n, wo, &floor, &rng2, &counts);
            sum[1] += image.value.y;
            sum2[1] += image.value.y * image.value.y;
        }
        if (yours.value.y > 0.0) {
            Vec3 to_image = vec3_sub(vec3_add_scaled(x, yours.wi, 3.0 / yours.wi.z), x);
            double d = vec3_length(to_image), cos_beta = yours.wi.z;
            double pdf = d * d / (image_scene.light_area * cos_beta);
            wrong_pdf += !(fabs(yours.pdf - pdf) <= 1e-6 * pdf);
        }
    }
    Mean a = mean_of(sum[0], sum2[0], SHADOW_RAYS), b = mean_of(sum[1], sum2[1], SHADOW_RAYS);
    double want = MIRROR_REFLECTANCE * b.mean, want_se = MIRROR_REFLECTANCE * b.se;
    double z = (a.mean - want) / sqrt(a.se * a.se + want_se * want_se);
    grading_note(g,
                 "light at the floor point through the mirror: %.5f +- %.2g; 0.9 times the "
                 "direct light from the lamp's image: %.5f +- %.2g (z = %+.1f)",
                 a.mean, a.se, want, want_se, z);
    if (fabs(z) > Z_LEVEL) {
        double ratio = a.mean / want;
        if (a.mean == 0.0)
            grading_fail(
                g,
                "no light reaches the floor through the mirror (0 where %.4f is "
                "right): is the lamp point reflected in the plane (y' = y - 2 h n, h its "
                "height above the plane), and is the first hit towards the image the "
                "mirror?",
                want);
        else if (fabs(ratio - 1.0 / MIRROR_REFLECTANCE) < 0.03)
            grading_fail(g,
                         "%.1f%% too much light through the mirror: the mirror's reflectance "
                         "(0.9) is missing",
                         100.0 * (ratio - 1.0));
        else
            grading_fail(
                g,
                "the light through the mirror is %.3f times the right %.4f (z = %.1f): "
                "is the value Le f R cos(alpha) cos(beta) A / d^2, with d the distance "
                "to the image and beta at the image's normal (docs/chapter7.md, section "
                "3)?",
                ratio, want, z);
    } else if (wrong_pdf > 0)
        grading_fail(g,
                     "%ld shadow rays carry a pdf other than d^2 / (A cos beta) at the image "
                     "(area_light_pdf): MIS would weigh them wrongly",
                     wrong_pdf);
done:
    mirror_planes_free(&planes);
    scene_free(&mirror_scene);
    scene_free(&image_scene);
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
