/* chapter8.c (bench, chapter 8): chapter 8's exercises and their graders (grading.h).
 *
 * The density estimate against its closed form on a map the grader lays out: photons
 * of known power on the floor z = 0, some arriving from below or lying on a wall
 * (which must not count), at three points and radii (docs/chapter8.md, section 4). The
 * radius schedule against r_1 sqrt(j^(alpha - 1)) (section 5). Photon emission by the
 * total power of the photons stored in a closed room against the lamp's flux pi A Le,
 * and their directions by the warp test about the lamp's normal (section 2).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "area_light.h"
#include "frame.h"
#include "grading.h"
#include "photon_estimate.h"
#include "render_check.h"

#define PHOTONS 4000
#define POWER 0.01
#define LEVEL 0.01
#define RINGS 10
#define SECTORS 12
#define SHOT 100000

static void grade_density(Grading *g)
{
    Photon *photons = malloc(PHOTONS * sizeof *photons);
    if (!photons) {
        grading_fail(g, "out of memory");
        return;
    }
    for (int i = 0; i < PHOTONS; i++) {
        Rng rng = rng_for_sample(81, 1, (uint64_t)i);
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
    Material floor = {
        .name = "floor", .kind = MATERIAL_LAMBERT, .reflectance = vec3(0.5, 0.5, 0.5)};
    const Vec3 points[] = {{0, 0, 0}, {0.3, -0.2, 0}, {-0.5, 0.4, 0}};
    const double radii[] = {0.1, 0.25, 0.4};
    Vec3 n = vec3(0, 0, 1), wo = vec3_normalize(vec3(0.2, 0.1, 1.0));
    for (int k = 0; k < 3 && !g->failed; k++) {
        double r = radii[k], all = 0.0, counted = 0.0, from_below = 0.0, other_surface = 0.0;
        for (int i = 0; i < PHOTONS; i++) {
            const Photon *p = &photons[i];
            if (vec3_length(vec3_sub(p->position, points[k])) > r)
                continue;
            all += p->power.x;
            if (vec3_dot(p->normal, n) < PHOTON_NORMAL_COS) {
                other_surface += vec3_dot(p->incoming, n) > 0.0 ? p->power.x : 0.0;
                continue;
            }
            if (vec3_dot(p->incoming, n) <= 0.0) {
                from_below += p->power.x;
                continue;
            }
            counted += p->power.x;
        }
        double want = 0.5 / PI * counted / (PI * r * r);
        Vec3 got = ASK_VEC3(g, photon_estimate_radiance(&map, r, points[k], n, wo, &floor));
        grading_note(g,
                     "at (%.1f, %.1f) with r = %.2f: L = %.5f (red); (rho / pi) Phi / (pi r^2) "
                     "= %.5f from %.3f W of %.3f W within r",
                     points[k].x, points[k].y, r, got.x, want, counted, all);
        if (grading_not_finite(g, got.x, "L"))
            break;
        if (fabs(got.x - want) <= 1e-9 * want && fabs(got.y - 0.5 * want) <= 1e-9 * want &&
            fabs(got.z - 2.0 * want) <= 1e-9 * want)
            continue;
        double ratio = got.x / want;
        double scale = 0.5 / PI / (PI * r * r);
        if (fabs(got.x - want) <= 1e-9 * want) {
            grading_fail(g,
                         "L = (%.5f, %.5f, %.5f) where (%.5f, %.5f, %.5f) is right: the red "
                         "channel is, the others not; each channel sums f Phi of its own "
                         "(the photons carry (%.3f, %.3f, %.3f) W)",
                         got.x, got.y, got.z, want, 0.5 * want, 2.0 * want, POWER, 0.5 * POWER,
                         2.0 * POWER);
            break;
        }
        if (fabs(got.x - scale * all) <= 1e-9 * want ||
            fabs(got.x - scale * (counted + from_below)) <= 1e-9 * want ||
            fabs(got.x - scale * (counted + other_surface)) <= 1e-9 * want)
            grading_fail(g,
                         "L = %.5f where %.5f is right: photons on another surface or arriving "
                         "from behind are counted (keep those with normal . n >= "
                         "PHOTON_NORMAL_COS and incoming . n > 0)",
                         got.x, want);
        else if (fabs(ratio - r) <= 1e-6 * r)
            grading_fail(
                g,
                "L = %.5f where %.5f is right: divided by pi r, not by the disc's area "
                "pi r^2",
                got.x, want);
        else if (fabs(ratio - PI) <= 1e-6 || fabs(ratio - 2.0 / PI) <= 1e-6 ||
                 fabs(ratio - 2.0) <= 1e-6)
            grading_fail(
                g,
                "L = %.5f is %.3f times the right %.5f: is the sum of f Phi (f = rho / "
                "pi, diffuse_brdf) divided by pi r^2?",
                got.x, ratio, want);
        else if (got.x == 0.0)
            grading_fail(g,
                         "L = 0 at (%.1f, %.1f) with r = %.2f, where the photons within r "
                         "give (rho / pi) Phi / (pi r^2) = %.5f: no photon counted",
                         points[k].x, points[k].y, r, want);
        else
            grading_fail(g,
                         "L = %.*f at (%.1f, %.1f) with r = %.2f, where the photons within r "
                         "give (rho / pi) Phi / (pi r^2) = %.*f (%.10g times that)",
                         grading_decimals(got.x, want), got.x, points[k].x, points[k].y, r,
                         grading_decimals(got.x, want), want, ratio);
    }
    photon_map_free(&map);
    free(photons);
}

static void grade_radius(Grading *g)
{
    const double first = 0.2, alphas[] = {2.0 / 3.0, 0.5, 0.9};
    for (int a = 0; a < 3 && !g->failed; a++) {
        double alpha = alphas[a];
        for (int j = 1; j <= 1000 && !g->failed; j = j < 10 ? j + 1 : j * 10) {
            double got = ASK(g, ppm_radius(first, alpha, j)),
                   want = first * sqrt(pow(j, alpha - 1.0));
            if (grading_not_finite(g, got, "the radius") || fabs(got - want) <= 1e-12 * want)
                continue;
            if (j > 1 && got > first)
                grading_fail(
                    g,
                    "pass %d's radius is %.4f, larger than the first pass's %.2f: the "
                    "radius must shrink (the exponent alpha - 1 < 0), or the bias never "
                    "goes away",
                    j, got, first);
            else if (fabs(got - first * pow(j, alpha - 1.0)) <= 1e-12 * want)
                grading_fail(
                    g,
                    "pass %d's radius is %.5f where r_1 sqrt(j^(alpha - 1)) = %.5f: the "
                    "square root is missing, so the radius shrinks too fast and the "
                    "variance no longer averages away",
                    j, got, want);
            else
                grading_fail(
                    g,
                    "pass %d's radius at alpha = %.2f is %.*f, where r_1 sqrt(j^(alpha "
                    "- 1)) = %.*f",
                    j, alpha, grading_decimals(got, want), got, grading_decimals(got, want),
                    want);
        }
        double r_10 = ASK(g, ppm_radius(first, alpha, 10));
        double r_1000 = ASK(g, ppm_radius(first, alpha, 1000));
        grading_note(g, "alpha = %.2f: r_1 = %.2f, r_10 = %.4f, r_1000 = %.4f", alpha, first,
                     r_10, r_1000);
    }
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

/* Each photon's start against the lamp point its first three numbers give; the total
 * power of those the closed room stores against the flux. Returns 1 when both hold. */
static int photons_check(Grading *g, const Scene *scene, Warp *warp)
{
    double stored = 0.0, least = INFINITY, most = 0.0;
    RayCounts counts = {0};
    for (long k = 0; k < SHOT; k++) {
        Rng rng = rng_for_sample(83, 1, (uint64_t)k);
        double u[5];
        for (int i = 0; i < 5; i++)
            u[i] = rng_uniform(&rng);
        PhotonRay photon = {{vec3(0, 0, 0), vec3(0, 0, 0)}, vec3(0, 0, 0)};
        if (grading_probing(g))
            photon = photon_emit(scene, SHOT, u[0], u[1], u[2], u[3], u[4]);
        photon.ray.origin = grading_ask_vec3(g, photon.ray.origin);
        photon.ray.dir = grading_ask_vec3(g, photon.ray.dir);
        photon.power = grading_ask_vec3(g, photon.power);
        if (grading_probing(g))
            continue;
        /* the oracle: the lamp point of the solution's area_light_sample */
        LightSample y = area_light_sample(scene, u[0], u[1], u[2]);
        Vec3 o = photon.ray.origin;
        if (grading_not_finite(g, vec3_length(o) + photon.power.y, "a photon's start or power"))
            return 0;
        if (vec3_length(vec3_sub(o, y.point)) > 1e-6)
            return grading_fail(
                g,
                "photon %ld starts at (%.3f, %.3f, %.3f), where "
                "area_light_sample(scene, u_select, u1, u2) puts its lamp point "
                "at (%.3f, %.3f, %.3f)",
                k, o.x, o.y, o.z, y.point.x, y.point.y, y.point.z);
        Vec3 t, b, d = photon.ray.dir;
        vec3_basis(y.normal, &t, &b);
        Vec3 local = vec3(vec3_dot(d, t), vec3_dot(d, b), vec3_dot(d, y.normal));
        warp_add_hemisphere(warp, k, u[3], u[4], local);
        least = fmin(least, photon.power.y);
        most = fmax(most, photon.power.y);
        Photon landed;
        if (photon_trace(scene, photon, PHOTON_DIRECT, FRESNEL_EXACT, &rng, &landed, &counts))
            stored += landed.power.y;
    }
    if (grading_probing(g))
        return 1;
    double flux = lamp_flux(scene);
    grading_note(g,
                 "%d photons shot from a lamp of flux pi A Le = %.4f W (green) into a closed "
                 "room; those stored carry %.4f W, each %.4g to %.4g W",
                 SHOT, flux, stored, least, most);
    if (most > least * (1.0 + 1e-9))
        return grading_fail(g,
                            "photons of one lamp carry from %.4g to %.4g W: the cosine of "
                            "Le cos(theta) cancels that of the density cos(theta) / pi, so "
                            "every photon carries the same pi A Le / N",
                            least, most);
    if (fabs(stored - flux) > 1e-6 * flux) {
        fail_flux(g, stored, flux);
        return 0;
    }
    return 1;
}

static void grade_emit(Grading *g)
{
    Scene scene;
    if (grading_scene(g, render_check_room, &scene) != 0)
        return;
    const WarpLabels labels = {"ring", "nearest the lamp's normal", "nearest the lamp's plane",
                               "sector around the normal",
                               "behind the lamp, off the unit sphere or at NaN"};
    Warp warp;
    if (warp_new(g, &warp, RINGS, SECTORS, 4000, labels) != 0) {
        scene_free(&scene);
        return;
    }
    if (photons_check(g, &scene, &warp) && !grading_probing(g)) {
        warp_expect_cosine(&warp, SHOT);
        grading_warp(g, &warp, "the photons' directions seen from the lamp", LEVEL, 1,
                     "is the direction hemisphere_sample_cosine(u3, u4) in the frame of the "
                     "lamp's front normal (vec3_basis, vec3_from_local)?");
    }
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
