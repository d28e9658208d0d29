/* chapter8.c (bench, chapter 8): chapter 8's exercises and their graders (grading.h).
 *
 * The density estimate against its closed form on a map the grader lays out (photons from
 * below or on a wall must not count) on a Lambertian and a rough floor, known wrong sums
 * named (section 4). The radius schedule against r_1 sqrt(j^(alpha - 1)), with a catalogue
 * (section 5). Each emitted photon's start, power and direction against the specification,
 * the stored power in a closed room against the flux pi A Le, and the directions by warp
 * tests (about the normal, and against where they left from) and cos(theta)'s mean (2).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "area_light.h"
#include "diffuse.h"
#include "frame.h"
#include "grading.h"
#include "hemisphere.h"
#include "photon_estimate.h"
#include "render_check.h"

#define PHOTONS 4000
#define POWER 0.01
#define LEVEL grading_level()
#define RINGS 10
#define SECTORS 12
#define SHOT 800000 /* cos(theta)'s mean to 0.3 % */
#define COUNT(list) (int)(sizeof list / sizeof list[0])

/* What an estimate sums, for one point and radius: the right sum and the known wrong ones,
 * each of f Phi over photons (red channel), all divided by pi r^2 but where named. */
enum {
    DENSITY_RIGHT,
    DENSITY_NO_BRDF,
    DENSITY_PI_R,
    DENSITY_NO_PI,
    DENSITY_ALL,
    DENSITY_FROM_BEHIND,
    DENSITY_OTHER_SURFACE,
    DENSITY_MEAN,
    DENSITY_WO_TWICE,
    DENSITY_FORMS
};
static const char *const density_words[DENSITY_FORMS] = {
    "",
    "the photons' power summed without the BRDF: each photon's Phi is multiplied by f = "
    "diffuse_brdf(m, n, incoming, wo) before the sum",
    "the sum divided by pi r, not by the disc's area pi r^2",
    "the sum divided by r^2, without pi: the disc's area is pi r^2",
    "every photon within r: those on another surface and those that arrived from behind "
    "are counted: keep those with normal . n >= PHOTON_NORMAL_COS and incoming . n > 0",
    "photons that arrived from behind the surface are counted (keep incoming . n > 0)",
    "photons on another surface are counted (keep normal . n >= PHOTON_NORMAL_COS)",
    "the photons' mean f Phi, where their sum belongs: the density is the flux per area",
    "f evaluated with wo for each photon's incoming direction, f(wo, wo): the photon came "
    "from its own incoming direction",
};

/* The BRDFs the estimate reads through diffuse_brdf (exercises 2.3 and 5.4) at the first
 * photons' directions, against the solution's. Returns 1 when they agree. */
static int brdfs_rechecked(Grading *g, const Material floors[2], const Photon *photons)
{
    Vec3 n = vec3(0, 0, 1), wo = vec3_normalize(vec3(0.2, 0.1, 1.0));
    for (int k = 0; k < 2; k++)
        for (int i = 0; i < 50; i++) {
            if (photons[i].incoming.z <= 0.0)
                continue;
            Vec3 got = ASK_VEC3(g, diffuse_brdf(&floors[k], n, photons[i].incoming, wo));
            if (grading_probing(g))
                continue;
            Vec3 want = diffuse_brdf(&floors[k], n, photons[i].incoming, wo);
            if (vec3_length(vec3_sub(got, want)) <= 1e-9 * vec3_length(want))
                continue;
            return grading_fail(g,
                                "exercise %s (%s), which diffuse_brdf calls for the estimate's "
                                "f, is wrong: f = (%.5f, %.5f, %.5f) where (%.5f, %.5f, %.5f) "
                                "is right (the %s floor)",
                                k == 0 ? "2.3" : "5.4",
                                k == 0 ? "lambert_brdf" : "oren_nayar_brdf", got.x, got.y,
                                got.z, want.x, want.y, want.z, floors[k].name);
        }
    return 1;
}

static void grade_density(Grading *g)
{
    Photon *photons = malloc(PHOTONS * sizeof *photons);
    if (!photons) {
        grading_fail(g, "out of memory");
        return;
    }
    for (int i = 0; i < PHOTONS; i++) {
        Rng rng = rng_for_sample(grading_stream(g, 81), 1, (uint64_t)i);
        Photon *p = &photons[i];
        p->position = vec3(2.0 * rng_uniform(&rng) - 1.0, 2.0 * rng_uniform(&rng) - 1.0, 0.0);
        p->normal = vec3(0, 0, 1);
        p->incoming =
            vec3_normalize(vec3(rng_uniform(&rng) - 0.5, rng_uniform(&rng) - 0.5, 1.0));
        p->power = vec3(POWER, 0.5 * POWER, 2.0 * POWER);
        if (i % 7 == 3)
            p->incoming.z = -p->incoming.z; /* arrived from below: not this side's light */
        if (i % 11 == 5)
            p->normal = vec3(1, 0, 0); /* on a wall through the floor: another surface */
    }
    PhotonMap map;
    if (photon_map_build(&map, photons, PHOTONS, 100000, 0.1) != 0) {
        free(photons);
        grading_fail(g, "out of memory");
        return;
    }
    /* a Lambertian floor, and a rough one, where each photon's f depends on its direction */
    const Material floors[2] = {
        {.name = "Lambertian", .kind = MATERIAL_LAMBERT, .reflectance = vec3(0.5, 0.5, 0.5)},
        {.name = "rough",
         .kind = MATERIAL_OREN_NAYAR,
         .reflectance = vec3(0.6, 0.4, 0.2),
         .sigma = 0.8}};
    const Vec3 points[] = {{0, 0, 0}, {0.3, -0.2, 0}, {-0.5, 0.4, 0}};
    const double radii[] = {0.1, 0.25, 0.4};
    if (!brdfs_rechecked(g, floors, photons)) {
        photon_map_free(&map);
        free(photons);
        return;
    }
    enum {
        ESTIMATES = 6
    };
    Vec3 n = vec3(0, 0, 1), wo = vec3_normalize(vec3(0.2, 0.1, 1.0));
    double forms[ESTIMATES][DENSITY_FORMS];
    Vec3 got[ESTIMATES], want[ESTIMATES];
    int matches[DENSITY_FORMS] = {0}, wrong = -1;
    for (int e = 0; e < ESTIMATES; e++) {
        const Material *m = &floors[e / 3];
        int k = e % 3;
        double r = radii[k], area = PI * r * r;
        double sum[DENSITY_FORMS] = {0};
        Vec3 right = vec3(0, 0, 0);
        int counted = 0;
        for (int i = 0; i < PHOTONS && !grading_probing(g); i++) {
            const Photon *p = &photons[i];
            if (vec3_length(vec3_sub(p->position, points[k])) > r)
                continue;
            Vec3 f = diffuse_brdf(m, n, p->incoming, wo);
            double fp = f.x * p->power.x;
            int here = vec3_dot(p->normal, n) >= PHOTON_NORMAL_COS,
                front = vec3_dot(p->incoming, n) > 0.0;
            sum[DENSITY_ALL] += fp;
            sum[DENSITY_FROM_BEHIND] += here ? fp : 0.0;
            sum[DENSITY_OTHER_SURFACE] += front ? fp : 0.0;
            if (!here || !front)
                continue;
            counted++;
            right = vec3_add(right, vec3_mul(f, p->power));
            sum[DENSITY_RIGHT] += fp;
            sum[DENSITY_NO_BRDF] += p->power.x;
            sum[DENSITY_WO_TWICE] += diffuse_brdf(m, n, wo, wo).x * p->power.x;
        }
        forms[e][DENSITY_RIGHT] = sum[DENSITY_RIGHT] / area;
        forms[e][DENSITY_NO_BRDF] = sum[DENSITY_NO_BRDF] / area;
        forms[e][DENSITY_PI_R] = sum[DENSITY_RIGHT] / (PI * r);
        forms[e][DENSITY_NO_PI] = sum[DENSITY_RIGHT] / (r * r);
        forms[e][DENSITY_ALL] = sum[DENSITY_ALL] / area;
        forms[e][DENSITY_FROM_BEHIND] = sum[DENSITY_FROM_BEHIND] / area;
        forms[e][DENSITY_OTHER_SURFACE] = sum[DENSITY_OTHER_SURFACE] / area;
        forms[e][DENSITY_MEAN] = counted > 0 ? sum[DENSITY_RIGHT] / counted / area : 0.0;
        forms[e][DENSITY_WO_TWICE] = sum[DENSITY_WO_TWICE] / area;
        want[e] = vec3_scale(right, 1.0 / area);
        got[e] = ASK_VEC3(g, photon_estimate_radiance(&map, r, points[k], n, wo, m));
        if (grading_probing(g))
            continue;
        grading_note(g,
                     "%s floor at (%.1f, %.1f), r = %.2f: L = (%.6f, %.6f, %.6f); the sum "
                     "of f Phi over the %d photons that count / (pi r^2) = (%.6f, %.6f, %.6f)",
                     m->name, points[k].x, points[k].y, r, got[e].x, got[e].y, got[e].z,
                     counted, want[e].x, want[e].y, want[e].z);
        if (grading_not_finite(g, got[e].x + got[e].y + got[e].z, "L"))
            break;
        int red_right =
            fabs(got[e].x - forms[e][DENSITY_RIGHT]) <= 1e-9 * forms[e][DENSITY_RIGHT];
        for (int f = 0; f < DENSITY_FORMS; f++)
            matches[f] += red_right || fabs(got[e].x - forms[e][f]) <= 1e-9 * forms[e][f];
        int right_here = fabs(got[e].x - want[e].x) <= 1e-9 * want[e].x &&
                         fabs(got[e].y - want[e].y) <= 1e-9 * want[e].y &&
                         fabs(got[e].z - want[e].z) <= 1e-9 * want[e].z;
        if (!right_here && wrong < 0)
            wrong = e;
    }
    photon_map_free(&map);
    free(photons);
    if (grading_probing(g) || g->failed || wrong < 0)
        return;
    for (int f = 1; f < DENSITY_FORMS; f++)
        if (matches[f] == ESTIMATES) {
            grading_fail(g,
                         "your L is %s (it matches that, or the right value, at each of "
                         "the %d points, radii and floors tried)",
                         density_words[f], ESTIMATES);
            return;
        }
    const Vec3 p = points[wrong % 3];
    double ratio = got[wrong].x / want[wrong].x;
    if (matches[DENSITY_RIGHT] == ESTIMATES)
        grading_fail(g,
                     "L = (%.5f, %.5f, %.5f) where (%.5f, %.5f, %.5f) is right: the red "
                     "channel is, the others not; each channel sums f Phi of its own",
                     got[wrong].x, got[wrong].y, got[wrong].z, want[wrong].x, want[wrong].y,
                     want[wrong].z);
    else if (got[wrong].x == 0.0)
        grading_fail(g,
                     "L = 0 on the %s floor at (%.1f, %.1f) with r = %.2f, where the photons "
                     "within r give %.5f: no photon counted",
                     floors[wrong / 3].name, p.x, p.y, radii[wrong % 3], want[wrong].x);
    else
        grading_fail(
            g,
            "L = %.*f on the %s floor at (%.1f, %.1f) with r = %.2f, where the "
            "photons within r give sum f Phi / (pi r^2) = %.*f (%.6g times that)%s",
            grading_decimals(got[wrong].x, want[wrong].x), got[wrong].x, floors[wrong / 3].name,
            p.x, p.y, radii[wrong % 3], grading_decimals(got[wrong].x, want[wrong].x),
            want[wrong].x, ratio,
            wrong >= 3 && matches[DENSITY_RIGHT] >= 3
                ? ": right on the Lambertian floor, wrong on the rough one, where each "
                  "photon's f depends on its incoming direction"
                : "");
}

/* The radius's inputs: r_1, alpha, j. */
static double radius_right(const double *x) { return x[0] * sqrt(pow(x[2], x[1] - 1.0)); }
static double radius_growing(const double *x) { return x[0] * sqrt(pow(x[2], 1.0 - x[1])); }
static double radius_no_root(const double *x) { return x[0] * pow(x[2], x[1] - 1.0); }
static double radius_alpha(const double *x) { return x[0] * sqrt(pow(x[2], x[1])); }
static double radius_no_alpha(const double *x) { return x[0] / sqrt(x[2]); }
static double radius_from_zero(const double *x)
{
    return x[0] * sqrt(pow(x[2] + 1.0, x[1] - 1.0));
}
static double radius_squared(const double *x) { return x[0] * x[0] * pow(x[2], x[1] - 1.0); }

static const WrongAnswer wrong_radius[] = {
    {"r_1 sqrt(j^(1 - alpha)), which grows: the radius must shrink (the exponent alpha - 1 < "
     "0), or the bias never goes away",
     "r_j = r_1 sqrt(j^(alpha - 1))", radius_growing},
    {"r_1 j^(alpha - 1): the square root is missing, so the radius shrinks too fast and the "
     "variance no longer averages away",
     "r_j = r_1 sqrt(j^(alpha - 1)): the power law holds for r_j^2", radius_no_root},
    {"r_1 sqrt(j^alpha), which grows: the exponent is alpha - 1",
     "r_j = r_1 sqrt(j^(alpha - 1))", radius_alpha},
    {"r_1 / sqrt(j), alpha left out", "r_j = r_1 sqrt(j^(alpha - 1))", radius_no_alpha},
    {"r_1 sqrt((j + 1)^(alpha - 1)): the passes counted from 0",
     "pass j = 1 has the first radius r_1: sqrt(j^(alpha - 1))", radius_from_zero},
    {"r_1^2 j^(alpha - 1), the squared radius", "r_j itself: r_1 sqrt(j^(alpha - 1))",
     radius_squared},
};

static void grade_radius(Grading *g)
{
    const double first = 0.2, alphas[] = {2.0 / 3.0, 0.5, 0.9};
    const int passes[] = {1, 2, 3, 5, 10, 100, 1000, 100000};
    enum {
        PASSES = sizeof passes / sizeof passes[0],
        POINTS = 3 * PASSES
    };
    double x[3 * POINTS], got[POINTS];
    int wrong = -1;
    for (int k = 0; k < POINTS; k++) {
        double *p = x + 3 * k;
        p[0] = first, p[1] = alphas[k / PASSES], p[2] = passes[k % PASSES];
        got[k] = ASK(g, ppm_radius(first, p[1], (int)p[2]));
        if (grading_not_finite(g, got[k], "the radius"))
            return;
        if (wrong < 0 && !(fabs(got[k] - radius_right(p)) <= 1e-12 * radius_right(p)))
            wrong = k;
    }
    for (int a = 0; a < 3; a++)
        grading_note(g,
                     "alpha = %.2f: r_1 = %.2f, r_10 = %.6f (right: %.6f), r_1000 = %.6f "
                     "(right: %.6f)",
                     alphas[a], first, got[a * PASSES + 4],
                     radius_right(x + 3 * (a * PASSES + 4)), got[a * PASSES + 6],
                     radius_right(x + 3 * (a * PASSES + 6)));
    if (wrong < 0)
        return;
    const WrongAnswer *match =
        grading_known_wrong(wrong_radius, COUNT(wrong_radius), x, 3, got, POINTS);
    if (match) {
        grading_fail_known(g, "radius", match, POINTS);
        return;
    }
    const double *p = x + 3 * wrong;
    double want = radius_right(p);
    if (p[2] > 1 && got[wrong] > first)
        grading_fail(g,
                     "pass %g's radius is %.4f, larger than the first pass's %.2f: the radius "
                     "must shrink (the exponent alpha - 1 < 0), or the bias never goes away",
                     p[2], got[wrong], first);
    else
        grading_fail(g,
                     "pass %g's radius at alpha = %.2f is %.*f, where r_1 sqrt(j^(alpha - 1)) "
                     "= %.*f (%.6g times that)%s",
                     p[2], p[1], grading_decimals(got[wrong], want), got[wrong],
                     grading_decimals(got[wrong], want), want, got[wrong] / want,
                     p[2] == 1 ? ": the first pass has the first radius r_1" : "");
}

/* The lamps' flux pi sum A_i Le_i (green channel). */
static double lamp_flux(const Scene *scene)
{
    double flux = 0.0;
    for (int i = 0; i < scene->light_count; i++) {
        const Triangle *t = &scene->triangles[scene->light_triangles[i]];
        flux += PI * t->area * scene->materials[t->material].emission.y;
    }
    return flux;
}

/* What a total power `stored` of the photons, other than the flux, does wrong. */
static void fail_flux(Grading *g, double stored, double flux)
{
    double ratio = stored / flux;
    char count[32];
    grading_count(SHOT, count, sizeof count);
    if (fabs(ratio - SHOT) <= 1e-6 * SHOT)
        grading_fail(g,
                     "the %s photons stored carry %.4g W, %s times the lamp's flux pi A Le = "
                     "%.4f W: each photon's power is not divided by the number of photons (pi "
                     "A Le / N)",
                     count, stored, count, flux);
    else if (fabs(ratio - 1.0 / PI) <= 1e-6)
        grading_fail(g,
                     "the photons stored carry %.4f W, 1 / pi of the lamp's flux pi A Le = "
                     "%.4f W: a lamp of radiance Le emits pi Le per unit area (the cosine "
                     "integrated over the hemisphere)",
                     stored, flux);
    else
        grading_fail(g,
                     "the photons stored carry %.*f W where the lamp emits pi A Le = %.*f W "
                     "(%.4g times that): each of the N photons carries pi A Le(y) / N, A = "
                     "scene->light_area",
                     grading_decimals(stored, flux), stored, grading_decimals(stored, flux),
                     flux, ratio);
}

/* What the photons of one check add up to. */
typedef struct {
    double stored, least, most, cos_sum, cos_sum2;
    long exact_directions;
} Emitted;

/* Each photon's start against the lamp point its first three numbers give, its power
 * against pi A Le / N, its direction against hemisphere_sample_cosine(u3, u4) in the
 * lamp's frame (a method drawing otherwise is held to the histograms and cos(theta)'s
 * mean); the total power of those the closed room stores against the flux. Returns 1
 * when all hold. */
static int photons_check(Grading *g, const Scene *scene, Warp *warp, Warp *joint, Emitted *e)
{
    RayCounts counts = {0};
    e->least = INFINITY;
    for (long k = 0; k < SHOT; k++) {
        Rng rng = rng_for_sample(grading_stream(g, 83), 1, (uint64_t)k);
        double u[5];
        for (int i = 0; i < 5; i++)
            u[i] = rng_uniform(&rng);
        PhotonRay photon = {{vec3(0, 0, 0), vec3(0, 0, 0)}, vec3(0, 0, 0)};
        if (grading_probing(g))
            photon = photon_emit(scene, SHOT, u[0], u[1], u[2], u[3], u[4]);
        /* the lamp point the student's own area_light_sample (chapter 3) gives */
        Vec3 own = ASK_VEC3(g, area_light_sample(scene, u[0], u[1], u[2]).point);
        photon.ray.origin = grading_ask_vec3(g, photon.ray.origin);
        photon.ray.dir = grading_ask_vec3(g, photon.ray.dir);
        photon.power = grading_ask_vec3(g, photon.power);
        if (grading_probing(g))
            continue;
        /* the oracle: the lamp point of the solution's area_light_sample */
        LightSample y = area_light_sample(scene, u[0], u[1], u[2]);
        Vec3 o = photon.ray.origin;
        if (grading_not_finite(g, vec3_length(o) + vec3_length(photon.ray.dir) + photon.power.y,
                               "a photon's start, direction or power"))
            return 0;
        if (vec3_length(vec3_sub(o, own)) > 1e-6)
            return grading_fail(
                g,
                "photon %ld starts at (%.3f, %.3f, %.3f), where "
                "area_light_sample(scene, u_select, u1, u2) puts its lamp point "
                "at (%.3f, %.3f, %.3f)",
                k, o.x, o.y, o.z, own.x, own.y, own.z);
        if (!(fabs(own.z - y.point.z) <= 1e-9) || !(fabs(own.x) <= 1.0 + 1e-9) ||
            !(fabs(own.y) <= 1.0 + 1e-9))
            return grading_fail(g,
                                "exercise 3.1 (area_light_sample), which photon_emit calls, "
                                "puts lamp point %ld at (%.3f, %.3f, %.3f), off the lamp (the "
                                "square |x|, |y| <= 1 at z = %.2f)",
                                k, own.x, own.y, own.z, y.point.z);
        double share = PI * scene->light_area / SHOT;
        Vec3 right_power = vec3_scale(y.emission, share);
        if (fabs(photon.power.x / right_power.x - photon.power.y / right_power.y) > 1e-9 ||
            fabs(photon.power.z / right_power.z - photon.power.y / right_power.y) > 1e-9)
            return grading_fail(g,
                                "photon %ld carries (%.4g, %.4g, %.4g) W from a lamp of "
                                "radiance (%g, %g, %g): each channel is pi A Le / N of its own",
                                k, photon.power.x, photon.power.y, photon.power.z, y.emission.x,
                                y.emission.y, y.emission.z);
        double ratio = photon.power.y / right_power.y;
        e->least = fmin(e->least, ratio);
        e->most = fmax(e->most, ratio);
        Vec3 t, b, d = photon.ray.dir;
        vec3_basis(y.normal, &t, &b);
        Vec3 specified = vec3_from_local(hemisphere_sample_cosine(u[3], u[4]), t, b, y.normal);
        e->exact_directions += vec3_length(vec3_sub(d, specified)) <= 1e-9;
        Vec3 local = vec3(vec3_dot(d, t), vec3_dot(d, b), vec3_dot(d, y.normal));
        warp_add_hemisphere(warp, k, u[3], u[4], local);
        e->cos_sum += local.z;
        e->cos_sum2 += local.z * local.z;
        /* the direction's ring against where on the lamp it left from (x from -1 to 1) */
        int ring = (int)((1.0 - local.z) * joint->rows),
            col = (int)((o.x + 1.0) * 0.5 * joint->cols);
        if (local.z > 0.0 && local.z <= 1.0 + 1e-9)
            warp_add(joint, k, ring < joint->rows ? ring : joint->rows - 1,
                     col < 0 ? 0 : (col < joint->cols ? col : joint->cols - 1), u[1], u[3], o.x,
                     local.z);
        else
            warp_add(joint, k, -1, 0, u[1], u[3], NAN, NAN);
        Photon landed;
        if (photon_trace(scene, photon, PHOTON_DIRECT, FRESNEL_EXACT, &rng, &landed, &counts))
            e->stored += landed.power.y;
    }
    if (grading_probing(g))
        return 1;
    double flux = lamp_flux(scene);
    grading_note(g,
                 "%d photons shot from a lamp of flux pi A Le = %.4f W (green) into a closed "
                 "room; those stored carry %.4f W; each photon %.10g to %.10g times pi A Le / "
                 "N; %ld directions exactly hemisphere_sample_cosine(u3, u4) in the lamp's "
                 "frame",
                 SHOT, flux, e->stored, e->least, e->most, e->exact_directions);
    if (e->most > e->least * (1.0 + 1e-9))
        return grading_fail(
            g,
            "photons of one lamp carry from %.4g to %.4g times pi A Le / N: "
            "the cosine of Le cos(theta) cancels that of the density cos(theta) "
            "/ pi, so every photon carries the same pi A Le / N",
            e->least, e->most);
    if (fabs(e->least - 1.0) > 1e-9) {
        fail_flux(g, e->least * flux, flux);
        return 0;
    }
    if (fabs(e->stored - flux) > 1e-6 * flux) {
        fail_flux(g, e->stored, flux);
        return 0;
    }
    return 1;
}

/* cos(theta)'s mean against 2/3, the cosine-weighted hemisphere's. Returns 1 when it holds. */
static int cosine_mean(Grading *g, const Emitted *e)
{
    double mean = e->cos_sum / SHOT;
    double se = sqrt(fmax(0.0, e->cos_sum2 / SHOT - mean * mean) / SHOT);
    double z = se > 0.0 ? (mean - 2.0 / 3.0) / se : (mean == 2.0 / 3.0 ? 0.0 : INFINITY);
    grading_note(g,
                 "mean cos(theta) of the directions %.6f +- %.2g, 2/3 expected (z = %+.1f, "
                 "limit %.2f; detectable bias %.2g%%)",
                 mean, se, z, grading_z(LEVEL), 100.0 * grading_detectable(se) / (2.0 / 3.0));
    if (fabs(z) <= grading_z(LEVEL))
        return 1;
    return grading_fail(g,
                        "the photons' directions have a mean cos(theta) of %.5f about the "
                        "lamp's normal, where the cosine-weighted hemisphere's is 2/3 (%.4f "
                        "times that): %s",
                        mean, mean * 1.5,
                        mean > 2.0 / 3.0 ? "too many leave near the normal"
                                         : "too many leave near the lamp's plane");
}

static void grade_emit(Grading *g)
{
    Scene scene;
    if (grading_scene(g, render_check_room, &scene) != 0)
        return;
    const WarpLabels labels = {"ring", "nearest the lamp's normal", "nearest the lamp's plane",
                               "sector around the normal",
                               "behind the lamp, off the unit sphere or at NaN"};
    const WarpLabels joint_labels = {"ring", "nearest the lamp's normal",
                                     "nearest the lamp's plane",
                                     "quarter of the lamp (by x) the photon left from",
                                     "behind the lamp, off the unit sphere or at NaN"};
    Warp warp, joint;
    Emitted e = {0};
    if (warp_new(g, &warp, RINGS, SECTORS, 4000, labels) != 0) {
        scene_free(&scene);
        return;
    }
    if (warp_new(g, &joint, 5, 4, 4000, joint_labels) != 0) {
        warp_free(&warp);
        scene_free(&scene);
        return;
    }
    if (photons_check(g, &scene, &warp, &joint, &e) && !grading_probing(g)) {
        warp_expect_cosine(&warp, SHOT);
        for (int r = 0; r < joint.rows; r++) {
            double top = 1.0 - (double)r / joint.rows,
                   bottom = 1.0 - (double)(r + 1) / joint.rows;
            for (int c = 0; c < joint.cols; c++)
                joint.expected[r * joint.cols + c] =
                    (double)SHOT * (top * top - bottom * bottom) / joint.cols;
        }
        if (grading_warp(g, &warp, "the photons' directions seen from the lamp", LEVEL, 1,
                         "is the direction hemisphere_sample_cosine(u3, u4) in the frame of "
                         "the lamp's front normal (vec3_basis, vec3_from_local)?") &&
            cosine_mean(g, &e))
            grading_warp(g, &joint,
                         "the photons' directions against where on the lamp they left from",
                         LEVEL, 1,
                         "are the direction's numbers u3, u4 other than the point's u1, u2 "
                         "(the direction must not depend on where it starts), and are the lamp "
                         "points uniform over its area (area_light_sample, exercise 3.1)?");
    }
    warp_free(&joint);
    warp_free(&warp);
    scene_free(&scene);
}

const Exercise exercises[] = {
    {"8.1", "photon_estimate_radiance",
     "Return L(x, wo) from the photons of `map` within `radius` of x (point_grid_query_radius "
     "on "
     "map->grid with a visit function): the sum of f Phi (f = diffuse_brdf(m, n, incoming, "
     "wo), Phi the photon's power) over the photons on this surface (normal . n >= "
     "PHOTON_NORMAL_COS) that arrived on its side (incoming . n > 0), divided by the disc's "
     "area pi r^2. See docs/chapter8.md, section 4.",
     "return vec3(0, 0, 0);", grade_density, NULL, ""},
    {"8.2", "ppm_radius",
     "Return pass j's radius in progressive photon mapping, r_j = r_1 sqrt(j^(alpha - 1)) "
     "with 0 < alpha < 1 (r_1 = first_radius), so that both the bias and the variance go to "
     "zero. See docs/chapter8.md, section 5.",
     "return first_radius;", grade_radius, NULL, ""},
    {"8.3", "photon_emit",
     "A photon leaving the lamps, one of emitted = N shot in all: it starts at y = "
     "area_light_sample(scene, u_select, u1, u2).point with the lamp's front normal n_y, "
     "goes in the direction hemisphere_sample_cosine(u3, u4) taken in the frame of n_y "
     "(vec3_basis, vec3_from_local), as the ray ray_spawn(y, n_y, direction, "
     "vec3_max_abs(y)), and carries the power pi A Le(y) / N (A = scene->light_area): the "
     "lamps' flux pi A Le shared by the N photons. See docs/chapter8.md, section 2.",
     "PhotonRay photon = {{vec3(0, 0, 0), vec3(0, 0, 1)}, vec3(0, 0, 0)};\nreturn photon;",
     grade_emit, NULL, ""},
};
const int exercise_count = sizeof exercises / sizeof exercises[0];
