/* test_triangle.c (chapter 1): the triangle and Möller-Trumbore intersection (triangle.h,
 * report §3.6.1, eqs. 15-18, chapter 1).
 *
 * Known hits from both sides, misses, rays parallel to the plane, rays through a
 * vertex or along an edge, and watertightness: a ray through the common edge or
 * vertex of neighbouring triangles must hit at least one of them, or the image shows
 * pinholes of background along every diagonal of every quad.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include "check.h"
#include "triangle.h"

static double hit(const Triangle *tri, Ray ray)
{
    return triangle_intersect(tri, ray, 0.0, INFINITY);
}

/* triangle_make: area = |e1 x e2| / 2, unit normal along e1 x e2 (the front side of
 * the scene format), flipped by swapping two vertices; checked by hand and against Heron's
 * formula and perpendicularity for an awkward triangle. */
static void test_make(void **state)
{
    Triangle tri = triangle_make(vec3(0, 0, 0), vec3(2, 0, 0), vec3(0, 3, 0), 7);
    assert_close(tri.area, 3, 0);
    assert_close(tri.normal.z, 1, 0);
    assert_int_equal(tri.material, 7);
    Triangle flipped = triangle_make(vec3(0, 0, 0), vec3(0, 3, 0), vec3(2, 0, 0), 7);
    assert_close(flipped.normal.z, -1, 0);

    Vec3 a = vec3(0.1234, -5.678, 9.1011), b = vec3(-3.21, 0.654, 2.2),
         c = vec3(7.7, 1.5, -0.25);
    Triangle odd = triangle_make(a, b, c, 0);
    double ab = vec3_length(vec3_sub(b, a)), bc = vec3_length(vec3_sub(c, b));
    double ca = vec3_length(vec3_sub(a, c)), s = 0.5 * (ab + bc + ca);
    assert_close(odd.area, sqrt(s * (s - ab) * (s - bc) * (s - ca)), 1e-12 * odd.area);
    assert_close(vec3_length(odd.normal), 1, 1e-15);
    assert_close(vec3_dot(odd.normal, vec3_sub(b, a)), 0, 1e-13);
    assert_close(vec3_dot(odd.normal, vec3_sub(c, a)), 0, 1e-13);
}

/* A ray straight down onto the triangle at height 2 hits at t = 2, from the front and
 * from the back alike (two-sided surfaces), and exactly at the aimed point. */
static void test_hit_both_sides(void **state)
{
    Triangle tri = triangle_make(vec3(0, 0, 2), vec3(4, 0, 2), vec3(0, 4, 2), 0);
    Ray from_front = {vec3(1, 1, 4), vec3(0, 0, -1)};
    Ray from_back = {vec3(1, 1, 0), vec3(0, 0, 1)};
    assert_close(hit(&tri, from_front), 2, 1e-15);
    assert_close(hit(&tri, from_back), 2, 1e-15);
    Vec3 target = point_on_triangle(&tri, 0.2, 0.3);
    Ray oblique = ray_through(vec3(-3, 5, 9), target);
    double t = hit(&tri, oblique);
    assert_close(vec3_length(vec3_sub(ray_at(oblique, t), target)), 0, 1e-14);
    assert_true(isinf(triangle_intersect(&tri, from_front, 0, 1.99)));
    assert_true(isinf(triangle_intersect(&tri, from_front, 2.01, INFINITY)));
}

/* Rays aimed 1e-6 outside each edge and beyond each vertex miss; a ray pointing away
 * from the triangle (hit at negative t) misses. */
static void test_miss(void **state)
{
    Triangle tri = triangle_make(vec3(0, 0, 0), vec3(1, 0, 0), vec3(0, 1, 0), 0);
    Vec3 outside[] = {
        vec3(0.5, -1e-6, 0),   vec3(-1e-6, 0.5, 0),  vec3(0.5 + 1e-6, 0.5 + 1e-6, 0),
        vec3(-1e-6, -1e-6, 0), vec3(1 + 1e-6, 0, 0), vec3(0, 1 + 1e-6, 0)};
    for (int i = 0; i < 6; i++)
        assert_true(isinf(hit(&tri, ray_through(vec3(0.3, 0.2, 1), outside[i]))));
    Ray away = {vec3(0.2, 0.2, 1), vec3(0, 0, 1)};
    assert_true(isinf(hit(&tri, away)));
}

/* Rays parallel to the plane miss, with no NaN: in the plane itself (through the
 * triangle's middle, where Cramer's rule would divide 0 by 0) and just above it. */
static void test_parallel(void **state)
{
    Triangle tri = triangle_make(vec3(0, 0, 0), vec3(1, 0, 0), vec3(0, 1, 0), 0);
    Ray in_plane = {vec3(-1, 0.25, 0), vec3(1, 0, 0)};
    Ray above = {vec3(-1, 0.25, 1e-9), vec3(1, 0, 0)};
    Ray diagonal_in_plane = {vec3(-1, -1, 0), vec3_normalize(vec3(1, 1, 0))};
    double t[3] = {hit(&tri, in_plane), hit(&tri, above), hit(&tri, diagonal_in_plane)};
    for (int i = 0; i < 3; i++)
        assert_true(isinf(t[i]) && t[i] > 0);
}

/* Grazing the boundary: rays through each vertex exactly and through points on each
 * edge hit, from many directions. */
static void test_vertex_and_edge(void **state)
{
    TestRandom rng = test_random(5, 0, 0);
    Vec3 a = vec3(0.3, -1.7, 2.2), b = vec3(2.9, 0.4, 1.1), c = vec3(-0.6, 1.3, 3.7);
    Triangle tri = triangle_make(a, b, c, 0);
    Vec3 boundary[] = {a,
                       b,
                       c,
                       point_on_triangle(&tri, 0.5, 0),
                       point_on_triangle(&tri, 0, 0.25),
                       point_on_triangle(&tri, 0.6, 0.4)};
    for (int k = 0; k < 1000; k++)
        for (int i = 0; i < 6; i++) {
            Vec3 origin = vec3_add_scaled(boundary[i], random_unit_vector(&rng), 5.0);
            assert_true(isfinite(hit(&tri, ray_through(origin, boundary[i]))));
        }
}

/* A rotation taking the axes to a random right-handed frame: "awkward" coordinates
 * where no component is a round number. */
typedef struct {
    Vec3 x, y, z;
} Frame;

static Frame random_frame(TestRandom *rng)
{
    Frame f;
    f.z = random_unit_vector(rng);
    test_frame(f.z, &f.x, &f.y);
    return f;
}

static Vec3 place(Frame f, Vec3 origin, double scale, Vec3 local)
{
    return vec3_add_scaled(origin, test_from_frame(local, f.x, f.y, f.z), scale);
}

/* A unit vector at angle acos(cos_theta) from `normal`, on either side of the plane,
 * in a random azimuth. */
static Vec3 at_angle(TestRandom *rng, Vec3 normal, double cos_theta)
{
    Vec3 t, b;
    test_frame(normal, &t, &b);
    double phi = 2.0 * PI * test_uniform(rng), sin_theta = sqrt(1.0 - cos_theta * cos_theta);
    double side = test_uniform(rng) < 0.5 ? -1.0 : 1.0;
    return test_from_frame(vec3(sin_theta * cos(phi), sin_theta * sin(phi), side * cos_theta),
                           t, b, normal);
}

/* Shoots `rays` rays through points from `target`, from 1 to 10^4 times `scale` away:
 * half from uniformly random directions, half grazing the plane of the first triangle
 * (cosine log-uniform between 1e-12 and 1). Returns how many hit none of the triangles. */
static int count_holes(const Triangle *tris, int count, Vec3 (*target)(TestRandom *, void *),
                       void *context, double scale, int rays, TestRandom *rng)
{
    int holes = 0;
    for (int k = 0; k < rays; k++) {
        Vec3 aim = target(rng, context);
        double distance = scale * pow(10.0, 4.0 * test_uniform(rng));
        Vec3 from = k % 2 ? at_angle(rng, tris[0].normal, pow(10.0, -12.0 * test_uniform(rng)))
                          : random_unit_vector(rng);
        Ray ray = ray_through(vec3_add_scaled(aim, from, distance), aim);
        int hit_any = 0;
        for (int i = 0; i < count && !hit_any; i++)
            hit_any = isfinite(hit(&tris[i], ray));
        holes += !hit_any;
    }
    return holes;
}

/* A quad P0 P1 P2 P3 split as the scene format does, into (P0,P1,P2) and (P0,P2,P3). */
typedef struct {
    Vec3 p[4];
    Triangle tri[2];
} Quad;

/* A random point of the shared diagonal P0-P2 as the renderer would compute one
 * (so within rounding, ~1e-16 relative, of the exact segment), or one of its ends. */
static Vec3 on_diagonal(TestRandom *rng, void *context)
{
    const Quad *q = context;
    double s = test_uniform(rng);
    if (s < 0.05)
        return q->p[0];
    if (s > 0.95)
        return q->p[2];
    return vec3_add_scaled(q->p[0], vec3_sub(q->p[2], q->p[0]), s);
}

/* Watertight diagonal: for an irregular quad at scales 1e-3, 1 and 1e3, placed with
 * axis-aligned and with awkward rotated and offset coordinates, 10^5 rays per case
 * through points of the shared diagonal and its end vertices all hit, however far
 * and however grazing. (With a fixed slack of 1e-12, about 1 in 1000 went through.) */
static void test_watertight_quad(void **state)
{
    TestRandom rng = test_random(2024, 0, 0);
    const double scales[] = {1e-3, 1.0, 1e3};
    Vec3 corners[4] = {vec3(0, 0, 0), vec3(1.3, -0.2, 0), vec3(1.1, 0.9, 0),
                       vec3(-0.1, 0.7, 0)};
    for (int i = 0; i < 3; i++)
        for (int awkward = 0; awkward < 2; awkward++) {
            double s = scales[i];
            Frame f = {vec3(1, 0, 0), vec3(0, 1, 0), vec3(0, 0, 1)};
            Vec3 origin = vec3(0, 0, 0);
            if (awkward) {
                f = random_frame(&rng);
                origin = vec3(3.14159265 * s, -2.71828183 * s, 1.41421356 * s);
            }
            Quad q;
            for (int c = 0; c < 4; c++)
                q.p[c] = place(f, origin, s, corners[c]);
            q.tri[0] = triangle_make(q.p[0], q.p[1], q.p[2], 0);
            q.tri[1] = triangle_make(q.p[0], q.p[2], q.p[3], 0);
            int holes = count_holes(q.tri, 2, on_diagonal, &q, s, 100000, &rng);
            if (holes)
                fail_msg("scale %g, %s: %d of 100000 rays through the diagonal missed", s,
                         awkward ? "rotated" : "axis-aligned", holes);
        }
}

/* A fan of six triangles around a centre vertex, each listing the vertices in its own
 * order, so the shared spokes are e1 in one triangle and e2 (or the far edge) in the
 * next. */
typedef struct {
    Vec3 centre, rim[6];
    Triangle tri[6];
} Fan;

static Vec3 on_spoke(TestRandom *rng, void *context)
{
    const Fan *fan = context;
    int spoke = (int)(6 * test_uniform(rng));
    double s = test_uniform(rng);
    return s < 0.1 ? fan->centre
                   : vec3_add_scaled(fan->centre, vec3_sub(fan->rim[spoke], fan->centre), s);
}

/* Watertight fan: 10^5 rays per scale through the shared centre vertex and the
 * shared spokes of six triangles of irregular shape all hit. */
static void test_watertight_fan(void **state)
{
    TestRandom rng = test_random(2025, 0, 0);
    const double scales[] = {1e-3, 1.0, 1e3};
    for (int i = 0; i < 3; i++) {
        double s = scales[i];
        Frame f = random_frame(&rng);
        Fan fan;
        fan.centre = vec3(-7.3 * s, 0.37 * s, 5.9 * s);
        for (int k = 0; k < 6; k++) {
            double angle = k * PI / 3 + 0.3 * test_uniform(&rng),
                   radius = 0.5 + test_uniform(&rng);
            fan.rim[k] =
                place(f, fan.centre, s, vec3(radius * cos(angle), radius * sin(angle), 0));
        }
        for (int k = 0; k < 6; k++) {
            Vec3 a = fan.centre, b = fan.rim[k], c = fan.rim[(k + 1) % 6];
            fan.tri[k] = k % 3 == 0   ? triangle_make(a, b, c, 0)
                         : k % 3 == 1 ? triangle_make(b, c, a, 0)
                                      : triangle_make(c, a, b, 0);
        }
        int holes = count_holes(fan.tri, 6, on_spoke, &fan, s, 100000, &rng);
        if (holes)
            fail_msg("scale %g: %d of 100000 rays through the spokes missed", s, holes);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_make),
        cmocka_unit_test(test_hit_both_sides),
        cmocka_unit_test(test_miss),
        cmocka_unit_test(test_parallel),
        cmocka_unit_test(test_vertex_and_edge),
        cmocka_unit_test(test_watertight_quad),
        cmocka_unit_test(test_watertight_fan),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
