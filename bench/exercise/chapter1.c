/* chapter1.c (bench, chapter 1): chapter 1's exercises and their graders (grading.h).
 *
 * Each grader knows the right answer from the geometry itself: whether a ray meets a
 * sphere follows from its distance to the centre, whether it meets a triangle from the
 * barycentric coordinates of the point it was aimed at, and a reflected or refracted
 * direction must keep its length, stay in the plane of d and n and obey its law. Fixed
 * seeds; tolerances far above rounding and far below any mistake.
 */
#include <math.h>
#include <stdio.h>

#include "camera.h"
#include "grading.h"
#include "mirror.h"
#include "schlick.h"
#include "snell.h"
#include "sphere.h"
#include "triangle.h"

#define TRIES 4000

static int close_to(double a, double b, double tolerance) { return fabs(a - b) <= tolerance; }

static void grade_sphere(Grading *g)
{
    Sphere sphere = {vec3(0.3, -0.2, 0.5), 0.7, 0};
    double r = sphere.radius;
    int hits = 0, misses = 0, inside = 0, behind = 0;
    for (int i = 0; i < TRIES && !g->failed; i++) {
        TestRandom rng = test_random(grading_stream(g, 11), 1, (uint64_t)i);
        int kind = i % 4; /* 0, 1: from outside; 2: from inside; 3: sphere behind */
        double distance =
            kind == 2 ? 0.6 * r * test_uniform(&rng) : 1.5 + 3.0 * test_uniform(&rng);
        Vec3 origin = vec3_add_scaled(sphere.center, random_unit_vector(&rng), distance);
        Vec3 target = vec3_add_scaled(sphere.center, random_unit_vector(&rng),
                                      1.3 * r * test_uniform(&rng));
        Vec3 d = vec3_normalize(vec3_sub(target, origin));
        if (kind == 3)
            d = vec3_neg(d);
        Vec3 to_centre = vec3_sub(sphere.center, origin);
        double b = vec3_dot(d, to_centre);
        double miss2 =
            vec3_dot(to_centre, to_centre) - b * b; /* squared distance of the line */
        double pass = sqrt(fmax(0.0, miss2));
        if (fabs(pass - r) < 1e-6)
            continue;
        double half = sqrt(fmax(0.0, r * r - miss2));
        double near = b - half, far = b + half;
        double expected =
            pass > r ? INFINITY : (near > 1e-9 ? near : (far > 1e-9 ? far : INFINITY));
        Ray ray = {origin, d};
        double t = ASK(g, sphere_intersect(&sphere, ray, 1e-9, INFINITY));
        if (isnan(t)) {
            grading_not_finite(g, t, "t");
            break;
        }
        if (expected == INFINITY && t != INFINITY) {
            if (kind == 3)
                grading_fail(g,
                             "hits a sphere that lies behind the ray's origin (t = %.3f; the "
                             "sphere is at t = %.3f and %.3f): only t in (tmin, tmax) counts",
                             t, near, far);
            else
                grading_fail(
                    g,
                    "hits a ray that passes %.3f from the centre of a sphere of radius "
                    "%.2f (t = %.3f): is the discriminant's sign right?",
                    pass, r, t);
        } else if (expected != INFINITY && t == INFINITY) {
            if (kind == 2)
                grading_fail(g,
                             "a ray starting inside the sphere finds no hit: when the near "
                             "root t = %.3f is behind the origin, the far root t = %.3f is the "
                             "hit",
                             near, far);
            else
                grading_fail(g,
                             "misses a ray that passes %.3f from the centre of a sphere of "
                             "radius %.2f (the hit is at t = %.3f)",
                             pass, r, expected);
        } else if (expected != INFINITY && !close_to(t, expected, 1e-9 * (1.0 + expected))) {
            Vec3 p = vec3_add_scaled(origin, d, t);
            double off = vec3_length(vec3_sub(p, sphere.center)) - r;
            if (close_to(t, far, 1e-9 * (1.0 + far)))
                grading_fail(g,
                             "returns the far side of the sphere, t = %.4f, where the first "
                             "hit is at t = %.4f: the smaller root comes first",
                             t, near);
            else
                grading_fail(g,
                             "t = %.*f where the ray meets the sphere at t = %.*f: the point "
                             "at t is %.3g off the surface (is the direction unit, and are b "
                             "and c as in eq. 20?)",
                             grading_decimals(t, expected), t, grading_decimals(t, expected),
                             expected, off);
        }
        hits += expected != INFINITY && kind != 2;
        misses += expected == INFINITY;
        inside += kind == 2;
        behind += kind == 3;
    }
    grading_note(g,
                 "%d rays hitting from outside, %d missing, %d from inside, %d with the "
                 "sphere behind",
                 hits, misses, inside, behind);
}

static void grade_triangle(Grading *g)
{
    int hits = 0, misses = 0;
    for (int i = 0; i < TRIES && !g->failed; i++) {
        TestRandom rng = test_random(grading_stream(g, 12), 1, (uint64_t)i);
        Vec3 v[3];
        for (int k = 0; k < 3; k++)
            v[k] = vec3_scale(random_unit_vector(&rng), 2.0 * test_uniform(&rng) + 0.5);
        Triangle tri = triangle_make(v[0], v[1], v[2], 0);
        if (tri.area < 0.1)
            continue;
        double a = 2.0 * test_uniform(&rng) - 0.5, b = 2.0 * test_uniform(&rng) - 0.5;
        double margin = fmin(fabs(a), fmin(fabs(b), fabs(1.0 - a - b)));
        if (margin < 1e-3)
            continue;
        int inside = a > 0.0 && b > 0.0 && a + b < 1.0;
        Vec3 target = vec3_add_scaled(vec3_add_scaled(tri.v0, tri.e1, a), tri.e2, b);
        Vec3 origin =
            vec3_add_scaled(target, random_unit_vector(&rng), 1.0 + 3.0 * test_uniform(&rng));
        Vec3 to_target = vec3_sub(target, origin);
        double distance = vec3_length(to_target);
        Vec3 d = vec3_scale(to_target, 1.0 / distance);
        if (fabs(vec3_dot(d, tri.normal)) < 0.05)
            continue;
        int away = i % 5 == 4;
        Ray ray = {origin, away ? vec3_neg(d) : d};
        double t = ASK(g, triangle_intersect(&tri, ray, 1e-9, INFINITY));
        if (isnan(t)) {
            grading_not_finite(g, t, "t");
            break;
        }
        double expected = inside && !away ? distance : INFINITY;
        if (expected == INFINITY && t != INFINITY) {
            if (away)
                grading_fail(g,
                             "hits a triangle behind the ray's origin (t = %.3f): only t in "
                             "(tmin, tmax) counts",
                             t);
            else
                grading_fail(g,
                             "hits a ray aimed at (u, v) = (%.2f, %.2f), outside the triangle "
                             "(%s)",
                             a, b,
                             a < 0.0   ? "u < 0"
                             : b < 0.0 ? "v < 0"
                                       : "u + v > 1: is u + v <= 1 tested?");
        } else if (expected != INFINITY && t == INFINITY) {
            grading_fail(g,
                         "misses a ray aimed at (u, v) = (%.2f, %.2f), inside the triangle, "
                         "from %s side",
                         a, b, vec3_dot(d, tri.normal) < 0.0 ? "the front" : "the back");
        } else if (expected != INFINITY && !close_to(t, expected, 1e-9 * (1.0 + expected))) {
            grading_fail(g,
                         "t = %.*f where the triangle is at t = %.*f along the ray (eq. 18: "
                         "t = (e2 . q) / det)",
                         grading_decimals(t, expected), t, grading_decimals(t, expected),
                         expected);
        }
        hits += expected != INFINITY;
        misses += expected == INFINITY;
    }
    grading_note(g,
                 "%d rays that hit a random triangle, %d that miss it or have it behind them",
                 hits, misses);
}

static void grade_camera(Grading *g)
{
    Vec3 eye = vec3(-1, 0.2, 0.1), bl = vec3(0, 1, -0.8), br = vec3(0.2, -1, -0.8),
         tl = vec3(0, 1, 0.9);
    Camera camera = camera_make(eye, bl, br, tl);
    const int width = 40, height = 30;
    int tried = 0;
    for (int i = 0; i < TRIES && !g->failed; i++, tried++) {
        TestRandom rng = test_random(grading_stream(g, 13), 1, (uint64_t)i);
        int col = (int)(test_uniform(&rng) * width), row = (int)(test_uniform(&rng) * height);
        double u = test_uniform(&rng), v = test_uniform(&rng);
        Ray ray = {vec3(0, 0, 0), vec3(0, 0, 0)};
        if (grading_probing(g))
            ray = camera_ray(&camera, width, height, col, row, u, v);
        ray.origin = grading_ask_vec3(g, ray.origin);
        ray.dir = grading_ask_vec3(g, ray.dir);
        double length = vec3_length(ray.dir);
        if (grading_not_finite(g, length, "the direction's length"))
            break;
        if (vec3_length(vec3_sub(ray.origin, eye)) > 1e-12) {
            grading_fail(g,
                         "the ray starts at (%.3f, %.3f, %.3f), not at the eye (%.3f, %.3f, "
                         "%.3f)",
                         ray.origin.x, ray.origin.y, ray.origin.z, eye.x, eye.y, eye.z);
            break;
        }
        if (!close_to(length, 1.0, 1e-12)) {
            grading_fail(g, "the direction is %.4f long, not 1: normalise it", length);
            break;
        }
        double x = (col + u) / width, y = 1.0 - (row + v) / height;
        Vec3 expected = vec3_normalize(
            vec3_sub(vec3_add_scaled(vec3_add_scaled(bl, camera.right, x), camera.up, y), eye));
        if (vec3_length(vec3_sub(ray.dir, expected)) < 1e-9)
            continue;
        /* Which plane point does it go through? Where the ray meets the image plane. */
        Vec3 normal = vec3_normalize(vec3_cross(camera.right, camera.up));
        double towards = vec3_dot(ray.dir, normal);
        double t = vec3_dot(vec3_sub(bl, eye), normal) / towards;
        if (!(t > 0.0 && isfinite(t))) {
            grading_fail(g,
                         "pixel (%d, %d) at (u, v) = (%.2f, %.2f) sends its ray along (%.3f, "
                         "%.3f, %.3f), %s the image plane; it should go through the plane at "
                         "(%.3f, %.3f) of its width and height, along (%.3f, %.3f, %.3f)",
                         col, row, u, v, ray.dir.x, ray.dir.y, ray.dir.z,
                         fabs(towards) < 1e-12 ? "parallel to" : "away from", x, y, expected.x,
                         expected.y, expected.z);
            break;
        }
        Vec3 rel = vec3_sub(vec3_add_scaled(eye, ray.dir, t), bl);
        double got_x = vec3_dot(rel, camera.right) / vec3_dot(camera.right, camera.right);
        double got_y = vec3_dot(rel, camera.up) / vec3_dot(camera.up, camera.up);
        const char *why = "";
        if (close_to(got_x, x, 1e-6) && close_to(got_y, 1.0 - y, 1e-6))
            why = ": the image is upside down (row 0 is the top: 1 - (row + v) / H)";
        else if (close_to(got_x, 1.0 - x, 1e-6) && close_to(got_y, y, 1e-6))
            why = ": the image is mirrored left to right";
        else if (close_to(got_x, (col + 0.5) / width, 1e-6) ||
                 close_to(got_x, (double)col / width, 1e-6))
            why = ": (u, v), the point within the pixel, is not used";
        grading_fail(g,
                     "pixel (%d, %d) at (u, v) = (%.2f, %.2f) sends its ray through the image "
                     "plane at (%.3f, %.3f) of its width and height, where (%.3f, %.3f) is "
                     "right%s",
                     col, row, u, v, got_x, got_y, x, y, why);
    }
    grading_note(g, "%d rays of a %d x %d image checked against BL + x (BR - BL) + y (TL - BL)",
                 tried, width, height);
}

/* What R(d) = d + k (d . n) n with k other than -2 does wrong. */
static void name_mirror_factor(Grading *g, double k, double dn, double length)
{
    if (fabs(k) <= 1e-9)
        grading_fail(g, "R(d) = d: the direction goes on through the mirror; its normal part "
                        "must turn round: R(d) = d - 2 (d . n) n");
    else if (fabs(k - 2.0) <= 1e-9)
        grading_fail(
            g,
            "R(d) = d + 2 (d . n) n: the sign is wrong, so the normal part is "
            "doubled, not turned round (R . n = %.4f where -d . n = %.4f): R(d) = d - 2 "
            "(d . n) n",
            3.0 * dn, -dn);
    else
        grading_fail(g,
                     "R(d) = d %c %.4g (d . n) n, %.4f long for a unit d: the factor of (d . "
                     "n) n should be 2, subtracted: R(d) = d - 2 (d . n) n",
                     k < 0.0 ? '-' : '+', fabs(k), length);
}

static void grade_mirror(Grading *g)
{
    int i;
    for (i = 0; i < TRIES && !g->failed; i++) {
        TestRandom rng = test_random(grading_stream(g, 14), 1, (uint64_t)i);
        Vec3 n = random_unit_vector(&rng), d = random_unit_vector(&rng);
        Vec3 r = ASK_VEC3(g, mirror_reflect(d, n));
        double length = vec3_length(r), dn = vec3_dot(d, n);
        if (grading_not_finite(g, length, "the reflected direction's length"))
            break;
        if (vec3_length(vec3_sub(r, vec3_add_scaled(d, n, -2.0 * dn))) <= 1e-12)
            continue;
        /* Is R(d) = d + k (d . n) n for another factor k? */
        double k = fabs(dn) > 0.05 ? vec3_dot(vec3_sub(r, d), n) / dn : NAN;
        if (isfinite(k) && vec3_length(vec3_sub(r, vec3_add_scaled(d, n, k * dn))) <= 1e-9)
            name_mirror_factor(g, k, dn, length);
        else if (!close_to(length, 1.0, 1e-12))
            grading_fail(g,
                         "R(d) is %.*f long for a unit d: a reflection keeps the length (d - "
                         "2 (d . n) n)",
                         grading_decimals(length, 1.0), length);
        else if (!close_to(vec3_dot(r, n), -dn, 1e-12))
            grading_fail(g,
                         "R . n = %.4f where -d . n = %.4f: the reflection leaves at another "
                         "angle than it arrived",
                         vec3_dot(r, n), -dn);
        else if (!close_to(vec3_dot(vec3_cross(d, n), r), 0.0, 1e-12))
            grading_fail(g, "R(d) leaves the plane of d and n");
        else
            grading_fail(g, "R(d) = (%.3f, %.3f, %.3f) is not d - 2 (d . n) n", r.x, r.y, r.z);
    }
    grading_note(g, "%d random unit directions and normals, either side", i);
}

/* Known wrong refractions: the inputs d (3), n (3), n_i, n_t and the component asked. */
static double refracted(const double *in, double eta, double cos_i_sign, double cos_t_sign)
{
    Vec3 d = vec3(in[0], in[1], in[2]), n = vec3(in[3], in[4], in[5]);
    double cos_i = -vec3_dot(d, n), sin2_t = eta * eta * (1.0 - cos_i * cos_i);
    if (sin2_t > 1.0)
        return NAN;
    Vec3 t = vec3_normalize(
        vec3_add(vec3_scale(d, eta),
                 vec3_scale(n, eta * cos_i_sign * cos_i + cos_t_sign * sqrt(1.0 - sin2_t))));
    return in[8] == 0.0 ? t.x : in[8] == 1.0 ? t.y : t.z;
}
static double snell_cos_sign(const double *in)
{
    return refracted(in, in[6] / in[7], -1.0, -1.0);
}
static double snell_swapped(const double *in)
{
    return refracted(in, in[7] / in[6], 1.0, -1.0);
}
static double snell_plus_cos_t(const double *in)
{
    return refracted(in, in[6] / in[7], 1.0, 1.0);
}

static const WrongAnswer wrong_snell[] = {
    {"eta d + (eta cos_i - cos_t) n with cos_i = d . n, the sign of cos(theta_i) dropped",
     "d points into the surface, so cos_i = -d . n is the positive cosine (eq. 2)",
     snell_cos_sign},
    {"the refraction with n_i and n_t swapped (eta = n_t / n_i)",
     "eta = n_i / n_t, the incident medium's index over the transmitted one's", snell_swapped},
    {"eta d + (eta cos_i + cos_t) n, cos_t added where it is subtracted",
     "t = eta d + (eta cos_i - cos_t) n: the transmitted ray goes on into the surface, "
     "against n",
     snell_plus_cos_t},
};

static void grade_snell(Grading *g)
{
    const double indices[4][2] = {{1.0, 1.5}, {1.5, 1.0}, {1.0, 1.33}, {1.6, 1.2}};
    int refracted_count = 0, reflected = 0;
    static double in[TRIES * 3 * 9], got[TRIES * 3];
    int wrong = 0;
    for (int i = 0; i < TRIES; i++) {
        TestRandom rng = test_random(grading_stream(g, 15), 1, (uint64_t)i);
        double n_i = indices[i % 4][0], n_t = indices[i % 4][1];
        Vec3 n = random_unit_vector(&rng), d = random_unit_vector(&rng);
        if (vec3_dot(d, n) > 0.0)
            d = vec3_neg(d);
        double cos_i = -vec3_dot(d, n), sin_i = sqrt(fmax(0.0, 1.0 - cos_i * cos_i));
        double sin_t = n_i / n_t * sin_i;
        if (fabs(sin_t - 1.0) < 1e-6 || cos_i < 1e-6)
            continue;
        double degrees = acos(cos_i) * 180.0 / PI;
        double critical = n_i > n_t ? asin(n_t / n_i) * 180.0 / PI : 90.0;
        Vec3 t = vec3(NAN, NAN, NAN);
        int ok = ASK(g, snell_refract(d, n, n_i, n_t, &t)) != 0.0;
        t = grading_ask_vec3(g, t);
        if (sin_t > 1.0) {
            reflected++;
            if (ok)
                grading_fail(g,
                             "no total internal reflection at %.1f degrees from index %.2f "
                             "into %.2f, beyond the critical angle arcsin(n_t / n_i) = %.1f "
                             "degrees (sin(theta_t) would be %.2f)",
                             degrees, n_i, n_t, critical, sin_t);
            continue;
        }
        refracted_count++;
        if (!ok) {
            if (n_i < n_t)
                grading_fail(
                    g,
                    "reports total internal reflection at %.1f degrees from index "
                    "%.2f into %.2f, entering the denser medium, where it cannot happen",
                    degrees, n_i, n_t);
            else
                grading_fail(g,
                             "reports total internal reflection at %.1f degrees from index "
                             "%.2f into %.2f, below the critical angle %.1f degrees",
                             degrees, n_i, n_t, critical);
            continue;
        }
        double length = vec3_length(t);
        if (grading_not_finite(g, length, "the refracted direction's length"))
            continue;
        /* The right direction, by eq. 2; a wrong one goes to the catalogue first. */
        double eta = n_i / n_t, cos_t = sqrt(1.0 - sin_t * sin_t);
        Vec3 right =
            vec3_normalize(vec3_add(vec3_scale(d, eta), vec3_scale(n, eta * cos_i - cos_t)));
        if (vec3_length(vec3_sub(t, right)) <= 1e-9)
            continue;
        const double components[3] = {t.x, t.y, t.z};
        for (int c = 0; c < 3 && wrong < TRIES * 3; c++) {
            double *x = in + (long)wrong * 9;
            x[0] = d.x, x[1] = d.y, x[2] = d.z, x[3] = n.x, x[4] = n.y, x[5] = n.z;
            x[6] = n_i, x[7] = n_t, x[8] = c;
            got[wrong++] = components[c];
        }
        double cos_got = -vec3_dot(t, n) / length;
        double got_sin_t = sqrt(fmax(0.0, 1.0 - cos_got * cos_got));
        if (!close_to(length, 1.0, 1e-9))
            grading_fail(g, "the refracted direction is %.4f long, not 1", length);
        else if (cos_got <= 0.0)
            grading_fail(g,
                         "the refracted ray turns back to the incident side (t . n = %.3f > 0)",
                         -cos_got);
        else if (!close_to(vec3_dot(vec3_cross(d, n), t), 0.0, 1e-9))
            grading_fail(g, "the refracted ray leaves the plane of d and n");
        else if (sin_i > 0.05 && !close_to(got_sin_t / sin_i, n_i / n_t, 1e-6))
            grading_fail(
                g,
                "sin(theta_t) / sin(theta_i) = %.*f from index %.2f into %.2f, where "
                "Snell's law gives n_i / n_t = %.*f%s",
                grading_decimals(got_sin_t / sin_i, n_i / n_t), got_sin_t / sin_i, n_i, n_t,
                grading_decimals(got_sin_t / sin_i, n_i / n_t), n_i / n_t,
                close_to(got_sin_t / sin_i, n_t / n_i, 1e-6) ? ": the ratio is inverted" : "");
        else
            grading_fail(g,
                         "the refracted direction (%.6f, %.6f, %.6f) at %.1f degrees from "
                         "index %.2f into %.2f is %.3g off eq. 2's (%.6f, %.6f, %.6f)",
                         t.x, t.y, t.z, degrees, n_i, n_t, vec3_length(vec3_sub(t, right)),
                         right.x, right.y, right.z);
    }
    /* A failure with the catalogue's cause, where it knows one. */
    if (g->failed && wrong >= 6 && !grading_probing(g)) {
        /* every refracted input wrong in the same known way: that is the verdict */
        const WrongAnswer *known = grading_known_wrong(
            wrong_snell, (int)(sizeof wrong_snell / sizeof *wrong_snell), in, 9, got, wrong);
        if (known) {
            g->failed = 0;
            grading_fail_known(g, "refracted direction", known, wrong / 3);
        }
    }
    grading_note(g,
                 "%d refractions and %d total internal reflections at indices 1 / 1.5, 1.5 / "
                 "1, 1 / 1.33 and 1.6 / 1.2",
                 refracted_count, reflected);
}

/* Schlick's R (eqs. 6-7) with (1 - cos theta) to `power`: theta the transmitted angle
 * leaving the denser medium when `transmitted` (1 beyond the critical angle), else the
 * incidence angle; R0 squared when `squared`. 0 with no interface. */
static double schlick(double cos_i, double n_i, double n_t, int power, int transmitted,
                      int squared)
{
    if (n_i == n_t)
        return 0.0;
    double cos_theta = cos_i;
    if (n_i > n_t && transmitted) {
        double sin2_t = (n_i / n_t) * (n_i / n_t) * (1.0 - cos_i * cos_i);
        if (sin2_t >= 1.0)
            return 1.0;
        cos_theta = sqrt(1.0 - sin2_t);
    }
    double r0 = (n_i - n_t) / (n_i + n_t);
    r0 = squared ? r0 * r0 : r0;
    return r0 + (1.0 - r0) * pow(1.0 - cos_theta, power);
}

/* The power other than 5 of (1 - cos theta) that R matches at this incidence, or 0. */
static int schlick_wrong_power(double r, double cos_i, double n_i, double n_t)
{
    for (int power = 1; power <= 6; power++)
        if (power != 5 && close_to(r, schlick(cos_i, n_i, n_t, power, 1, 1), 1e-12))
            return power;
    return 0;
}

/* Another known mistake R matches at this incidence, in words, or "". */
static const char *schlick_mistake(double r, double cos_i, double n_i, double n_t)
{
    if (n_i > n_t && close_to(r, schlick(cos_i, n_i, n_t, 5, 0, 1), 1e-12))
        return ": leaving the denser medium (n_i > n_t), theta must be the transmitted angle, "
               "cos theta = snell_cos_transmitted(cos_i, n_i, n_t) (erratum 4); with the "
               "incidence angle R jumps to 1 at the critical angle";
    if (close_to(r, schlick(cos_i, n_i, n_t, 5, 1, 0), 1e-12))
        return ": R0 is (n_i - n_t) / (n_i + n_t) squared (eq. 7)";
    return "";
}

/* Where one pair of indices is furthest from Schlick's R: the failure it makes. */
static void fail_schlick(Grading *g, double n_i, double n_t, int degrees, double got)
{
    static const char *const ordinals[] = {"",       "first", "second", "third",
                                           "fourth", "fifth", "sixth"};
    double cos_i = cos(degrees * PI / 180.0), want = schlick(cos_i, n_i, n_t, 5, 1, 1);
    double sin2_t = (n_i / n_t) * (n_i / n_t) * (1.0 - cos_i * cos_i);
    int decimals = grading_decimals(got, want);
    int power = schlick_wrong_power(got, cos_i, n_i, n_t);
    char where[160];
    snprintf(where, sizeof where, "R = %.*f at %d degrees from index %.2f into %.2f", decimals,
             got, degrees, n_i, n_t);
    if (n_i == n_t)
        grading_fail(g,
                     "%s: with n_i = n_t there is no interface and nothing is reflected, R = "
                     "0 (eq. 6 alone would still give (1 - cos theta)^5)",
                     where);
    else if (sin2_t > 1.0)
        grading_fail(g,
                     "%s, beyond the critical angle %.1f degrees: with no transmitted ray all "
                     "is reflected, R = 1 (total internal reflection)",
                     where, asin(n_t / n_i) * 180.0 / PI);
    else if (power)
        grading_fail(g,
                     "%s is R0 + (1 - R0) (1 - cos theta) to the %s power, where Schlick's "
                     "approximation takes the fifth: %.*f (eq. 6)",
                     where, ordinals[power], decimals, want);
    else
        grading_fail(g, "%s, where R0 + (1 - R0) (1 - cos theta)^5 = %.*f (R0 = %.4f)%s", where,
                     decimals, want, pow((n_i - n_t) / (n_i + n_t), 2.0),
                     schlick_mistake(got, cos_i, n_i, n_t));
}

static void grade_schlick(Grading *g)
{
    static const double pairs[][2] = {
        {1.0, 1.5}, {1.5, 1.0}, {1.0, 1.33}, {1.6, 1.2}, {1.4, 1.4}};
    int checked = 0;
    for (int k = 0; k < 5 && !g->failed; k++) {
        double n_i = pairs[k][0], n_t = pairs[k][1], worst = 0.0, worst_got = 0.0;
        int worst_degrees = -1;
        for (int a = 0; a < 90; a++, checked++) {
            double cos_i = cos(a * PI / 180.0);
            double sin2_t = (n_i / n_t) * (n_i / n_t) * (1.0 - cos_i * cos_i);
            if (fabs(sin2_t - 1.0) < 1e-6)
                continue; /* at the critical angle itself either answer rounds right */
            double got = ASK(g, schlick_reflectance(cos_i, n_i, n_t));
            double off = fabs(got - schlick(cos_i, n_i, n_t, 5, 1, 1));
            if (grading_not_finite(g, got, "R"))
                return;
            if (off > worst) {
                worst = off;
                worst_got = got;
                worst_degrees = a;
            }
        }
        /* The incidence furthest off shows the mistake best. */
        if (worst > 1e-12)
            fail_schlick(g, n_i, n_t, worst_degrees, worst_got);
    }
    grading_note(g,
                 "%d incidences (every degree from 0 to 89 at n_i / n_t = 1 / 1.5, 1.5 / 1, 1 "
                 "/ 1.33, 1.6 / 1.2, 1.4 / 1.4) against R0 + (1 - R0) (1 - cos theta)^5, theta "
                 "the transmitted angle leaving the denser medium",
                 checked);
}

const Exercise exercises[] = {
    {"1.1", "sphere_intersect",
     "Return the smallest t in (tmin, tmax) at which the ray o + t d (d of unit length) meets "
     "the sphere |x - c| = r, or INFINITY when there is none. Substituting the ray gives t^2 - "
     "2 b t + c = 0 with b = d . (c - o) and c = |o - c|^2 - r^2 (eqs. 19-20): try the smaller "
     "root first, then the larger (a ray that starts inside). See docs/chapter1.md, section 3.",
     "return INFINITY;", grade_sphere, NULL, ""},
    {"1.2", "triangle_intersect",
     "Moller-Trumbore: solve [-d, e1, e2] (t, u, v) = o - v0 (eq. 18) by Cramer's rule with p "
     "= d x e2, det = e1 . p, s = o - v0, q = s x e1: u = (s . p) / det, v = (d . q) / det, t "
     "= (e2 . q) / det. The ray meets the triangle where u >= 0, v >= 0, u + v <= 1 (eq. 16) "
     "and tmin < t < tmax; return t, else INFINITY (also when det is about 0: the ray is "
     "parallel). See docs/chapter1.md, section 4.",
     "return INFINITY;", grade_triangle, NULL, ""},
    {"1.3", "camera_ray",
     "The ray from the eye through the point BL + (col + u) / W (BR - BL) + (1 - (row + v) / "
     "H) (TL - BL) of the image plane (camera.h: right = BR - BL, up = TL - BL; row 0 is the "
     "top), with a unit direction. See docs/chapter1.md, section 2.",
     "Ray ray = {camera->eye, vec3(0, 0, 1)};\nreturn ray;", grade_camera, NULL, ""},
    {"1.4", "mirror_reflect",
     "The mirror direction R(d) = d - 2 (d . n) n of the direction d at a surface of unit "
     "normal n (either orientation). See docs/chapter1.md, section 8.",
     "return d;", grade_mirror, NULL, ""},
    {"1.5", "snell_refract",
     "Refract d by Snell's law n_i sin(theta_i) = n_t sin(theta_t) (eq. 2): with eta = n_i / "
     "n_t and cos_i = -d . n, cos_t = snell_cos_transmitted(cos_i, n_i, n_t) (-1: total "
     "internal reflection, return 0); else *t = eta d + (eta cos_i - cos_t) n, normalised, "
     "and return 1. See docs/chapter1.md, section 9.",
     "return 0;", grade_snell, NULL, ""},
    {"1.6", "schlick_reflectance",
     "Return Schlick's reflectance R = R0 + (1 - R0) (1 - cos theta)^5 with R0 = ((n_i - n_t) "
     "/ (n_i + n_t))^2 (eqs. 6-7) at incidence cosine cos_i from index n_i into n_t: 0 when "
     "n_i = n_t (no interface); theta is the incidence angle entering the denser medium, and "
     "leaving it (n_i > n_t) the transmitted angle, cos theta = snell_cos_transmitted(cos_i, "
     "n_i, n_t), with R = 1 when that is -1 (total internal reflection; erratum 4). See "
     "docs/chapter1.md, section 9.",
     "return 0.0;", grade_schlick, NULL, ""},
};
const int exercise_count = sizeof exercises / sizeof exercises[0];
