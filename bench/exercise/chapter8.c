/* chapter8.c (bench, chapter 8): chapter 8's exercises and their graders (grading.h).
 *
 * The density estimate against its closed form on a map the grader lays out: photons
 * of known power on the floor z = 0, some arriving from below or lying on a wall
 * (which must not count), at three points and radii; a Lambertian floor's radiance is
 * then (rho / pi) times the power of the photons that count within r, over pi r^2
 * (docs/chapter8.md, section 4). The radius schedule against r_1 sqrt(j^(alpha - 1)):
 * it shrinks, and slowly enough (section 5).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "grading.h"
#include "photon_estimate.h"

#define PHOTONS 4000
#define POWER 0.01

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
        p->incoming = vec3_normalize(vec3(rng_uniform(&rng) - 0.5, rng_uniform(&rng) - 0.5, 1.0));
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
    Material floor = {.name = "floor", .kind = MATERIAL_LAMBERT, .reflectance = vec3(0.5, 0.5, 0.5)};
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
        grading_note(g, "at (%.1f, %.1f) with r = %.2f: L = %.5f (red); (rho / pi) Phi / (pi r^2) "
                     "= %.5f from %.3f W of %.3f W within r", points[k].x, points[k].y, r, got.x,
                     want, counted, all);
        if (grading_not_finite(g, got.x, "L"))
            break;
        if (fabs(got.x - want) <= 1e-9 * want && fabs(got.y - 0.5 * want) <= 1e-9 * want &&
            fabs(got.z - 2.0 * want) <= 1e-9 * want)
            continue;
        double ratio = got.x / want;
        double scale = 0.5 / PI / (PI * r * r);
        if (fabs(got.x - scale * all) <= 1e-9 * want ||
            fabs(got.x - scale * (counted + from_below)) <= 1e-9 * want ||
            fabs(got.x - scale * (counted + other_surface)) <= 1e-9 * want)
            grading_fail(g, "L = %.5f where %.5f is right: photons on another surface or arriving "
                         "from behind are counted (keep those with normal . n >= "
                         "PHOTON_NORMAL_COS and incoming . n > 0)", got.x, want);
        else if (fabs(ratio - r) <= 1e-6 * r)
            grading_fail(g, "L = %.5f where %.5f is right: divided by pi r, not by the disc's area "
                         "pi r^2", got.x, want);
        else if (fabs(ratio - PI) <= 1e-6 || fabs(ratio - 2.0 / PI) <= 1e-6 || fabs(ratio - 2.0) <= 1e-6)
            grading_fail(g, "L = %.5f is %.3f times the right %.5f: is the sum of f Phi (f = rho / "
                         "pi, diffuse_brdf) divided by pi r^2?", got.x, ratio, want);
        else
            grading_fail(g, "L = %.5f at (%.1f, %.1f) with r = %.2f, where the photons within r "
                         "give (rho / pi) Phi / (pi r^2) = %.5f (%.3f times that)", got.x,
                         points[k].x, points[k].y, r, want, ratio);
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
            double got = ASK(g, ppm_radius(first, alpha, j)), want = first * sqrt(pow(j, alpha - 1.0));
            if (grading_not_finite(g, got, "the radius") || fabs(got - want) <= 1e-12 * want)
                continue;
            if (j > 1 && got > first)
                grading_fail(g, "pass %d's radius is %.4f, larger than the first pass's %.2f: the "
                             "radius must shrink (the exponent alpha - 1 < 0), or the bias never "
                             "goes away", j, got, first);
            else if (fabs(got - first * pow(j, alpha - 1.0)) <= 1e-12 * want)
                grading_fail(g, "pass %d's radius is %.5f where r_1 sqrt(j^(alpha - 1)) = %.5f: the "
                             "square root is missing, so the radius shrinks too fast and the "
                             "variance no longer averages away", j, got, want);
            else
                grading_fail(g, "pass %d's radius at alpha = %.2f is %.5f, where r_1 sqrt(j^(alpha "
                             "- 1)) = %.5f", j, alpha, got, want);
        }
        double r_10 = ASK(g, ppm_radius(first, alpha, 10));
        double r_1000 = ASK(g, ppm_radius(first, alpha, 1000));
        grading_note(g, "alpha = %.2f: r_1 = %.2f, r_10 = %.4f, r_1000 = %.4f", alpha, first, r_10,
                     r_1000);
    }
}

const Exercise exercises[] = {
    {"8.1", "photon_estimate_radiance",
     "Return L(x, wo) from the photons of `map` within `radius` of x (point_grid_query_radius on "
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
};
const int exercise_count = sizeof exercises / sizeof exercises[0];
