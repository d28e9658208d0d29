/* test_scene.c (chapter 1): ray queries against a whole scene (scene.h, chapter 1).
 *
 * Scenes are built in code with scene_add_*. Beyond "the nearest hit wins" (and of two
 * at the same t, the lower-numbered) this is where rays start on surfaces, so it is where the
 * acne and near-hit cases live: a ray re-launched from a hit point with ray_spawn must never
 * find the surface it left at t ~ 0, must still find a surface a hair away, and a shadow ray
 * between two surface points must not be blocked by either end's own surface. All of it at
 * scene scales from 1e-45 to 1e45.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <float.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "scene.h"
#include "scene_file.h"
#include "whitted_estimator.h"

/* From the smallest to the largest scale the reader takes (scene_file.c: sizes 1e-50
 * to 1e50), through 1e-12, where an absolute ray offset would fail. */
static const double scales[] = {1e-45, 1e-12, 1e-3, 1.0, 1e3, 1e45};
#define SCALE_COUNT (int)(sizeof scales / sizeof scales[0])

/* A random direction on the side of the surface that `normal` points to. */
static Vec3 random_direction_along(TestRandom *rng, Vec3 normal)
{
    Vec3 d = random_unit_vector(rng);
    return vec3_dot(d, normal) < 0 ? vec3_neg(d) : d;
}

/* A uniformly random point of a triangle. */
static Vec3 random_point_on(const Triangle *tri, TestRandom *rng)
{
    double a = sqrt(test_uniform(rng)), b = test_uniform(rng);
    return point_on_triangle(tri, a * (1 - b), a * b);
}

static int add_material(Scene *scene, MaterialKind kind, double emission)
{
    Material m;
    memset(&m, 0, sizeof m);
    m.kind = kind;
    m.reflectance = vec3(0.5, 0.5, 0.5);
    m.emission = vec3(emission, emission, emission);
    return scene_add_material(scene, m);
}

/* The quad P0 P1 P2 P3 as the scene file splits it: (P0,P1,P2) and (P0,P2,P3). */
static void add_quad(Scene *scene, Vec3 p0, Vec3 p1, Vec3 p2, Vec3 p3, int material)
{
    scene_add_triangle(scene, triangle_make(p0, p1, p2, material));
    scene_add_triangle(scene, triangle_make(p0, p2, p3, material));
}

/* A square of half-size `half` centred on `centre`, spanned by unit vectors a, b; its
 * front faces a x b. */
static void add_square(Scene *scene, Vec3 centre, Vec3 a, Vec3 b, double half, int material)
{
    Vec3 lo = vec3_add_scaled(centre, vec3_add(a, b), -half);
    add_quad(scene, lo, vec3_add_scaled(lo, a, 2 * half),
             vec3_add_scaled(lo, vec3_add(a, b), 2 * half), vec3_add_scaled(lo, b, 2 * half),
             material);
}

/* Nearest of several: along +z a sphere (t = 2) in front of two triangles (t = 5, 10)
 * added before it; beside the sphere the nearer triangle wins; the Hit carries the
 * point, the front normal (not flipped towards the ray), material and triangle index. */
static void test_nearest_hit(void **state)
{
    Scene scene;
    scene_init(&scene);
    int grey = add_material(&scene, MATERIAL_LAMBERT, 0);
    int glass = add_material(&scene, MATERIAL_GLASS, 0);
    int lamp = add_material(&scene, MATERIAL_LIGHT, 1);
    scene_add_triangle(&scene,
                       triangle_make(vec3(-9, -9, 10), vec3(9, -9, 10), vec3(0, 9, 10), grey));
    scene_add_triangle(&scene,
                       triangle_make(vec3(-9, -9, 5), vec3(0, 9, 5), vec3(9, -9, 5), lamp));
    Sphere sphere = {vec3(0, 0, 3), 1, glass};
    scene_add_sphere(&scene, sphere);
    assert_int_equal(scene_prepare(&scene), 0);

    Hit hit;
    Ray up = {vec3(0, 0, 0), vec3(0, 0, 1)};
    assert_true(scene_intersect(&scene, up, INFINITY, &hit));
    assert_close(hit.t, 2, 1e-15);
    assert_close(hit.point.z, 2, 1e-15);
    assert_close(hit.normal.z, -1, 1e-15);
    assert_int_equal(hit.material, glass);
    assert_int_equal(hit.triangle, -1);

    Ray beside = {vec3(2, 0, 0), vec3(0, 0, 1)};
    assert_true(scene_intersect(&scene, beside, INFINITY, &hit));
    assert_close(hit.t, 5, 1e-15);
    assert_close(hit.point.x, 2, 1e-15);
    assert_close(hit.normal.z, -1, 1e-15); /* the lamp's front faces down, towards -z */
    assert_int_equal(hit.material, lamp);
    assert_int_equal(hit.triangle, 1);

    Ray down = {vec3(2, 0, 20), vec3(0, 0, -1)};
    assert_true(scene_intersect(&scene, down, INFINITY, &hit));
    assert_close(hit.t, 10, 1e-15);
    assert_close(hit.normal.z, 1, 1e-15);
    assert_int_equal(hit.triangle, 0);

    assert_false(scene_intersect(&scene, up, 1.99, &hit));
    Ray away = {vec3(0, 0, 0), vec3(0, 0, -1)};
    assert_false(scene_intersect(&scene, away, INFINITY, &hit));
    scene_free(&scene);
}

/* Two copies of one square in the plane z = 0, of two materials: every ray down onto it
 * hits both at the same t, and the lower-numbered triangle wins, whichever copy was added
 * first. */
static void test_tie_goes_to_the_lower_number(void **state)
{
    for (int order = 0; order < 2; order++) {
        Scene scene;
        scene_init(&scene);
        int grey = add_material(&scene, MATERIAL_LAMBERT, 0);
        int lamp = add_material(&scene, MATERIAL_LIGHT, 1);
        int first = order == 0 ? grey : lamp, second = order == 0 ? lamp : grey;
        add_square(&scene, vec3(0, 0, 0), vec3(1, 0, 0), vec3(0, 1, 0), 1, first);
        add_square(&scene, vec3(0, 0, 0), vec3(1, 0, 0), vec3(0, 1, 0), 1, second);
        assert_int_equal(scene_prepare(&scene), 0);
        for (int i = 0; i < 1000; i++) {
            TestRandom rng = test_random(31, (uint64_t)order, (uint64_t)i);
            Vec3 target =
                vec3(1.8 * test_uniform(&rng) - 0.9, 1.8 * test_uniform(&rng) - 0.9, 0);
            Vec3 origin =
                vec3_add(target, vec3(test_uniform(&rng) - 0.5, test_uniform(&rng) - 0.5,
                                      1 + test_uniform(&rng)));
            Ray ray = {origin, vec3_normalize(vec3_sub(target, origin))};
            Hit hit;
            assert_true(scene_intersect(&scene, ray, INFINITY, &hit));
            if (hit.triangle > 1 || hit.material != first)
                fail_msg(
                    "order %d, ray %d: triangle %d (material %d) hit, not the first copy's",
                    order, i, hit.triangle, hit.material);
        }
        scene_free(&scene);
    }
}

/* From inside a sphere the hit is its far side and the normal still points out,
 * along the ray. */
static void test_hit_from_inside_sphere(void **state)
{
    Scene scene;
    scene_init(&scene);
    Sphere sphere = {vec3(1, 2, 3), 2, add_material(&scene, MATERIAL_GLASS, 0)};
    scene_add_sphere(&scene, sphere);
    scene_prepare(&scene);
    Hit hit;
    Ray ray = {vec3(1, 2, 4), vec3(0, 0, 1)};
    assert_true(scene_intersect(&scene, ray, INFINITY, &hit));
    assert_close(hit.t, 1, 1e-15);
    assert_close(hit.normal.z, 1, 1e-15);
    scene_free(&scene);
}

/* A triangle-only scene: one large awkwardly oriented square, once off the origin
 * and aimed at uniformly, once through the origin and aimed at points 1e-12 to 1
 * (times the scale, log-uniform) from it -- where an offset relative to |p| alone
 * would fail, because a hit point's rounding error is set by the square's numbers
 * along its normal, not by |p| (ray.h). From 2000 hit points per case, seen from
 * 10 units away on either side, rays spawned into random directions of either
 * hemisphere must hit nothing: the only surface is the plane they left. */
static void test_no_acne_on_triangles(void **state)
{
    TestRandom rng = test_random(31, 0, 0);
    for (int i = 0; i < SCALE_COUNT; i++)
        for (int near_origin = 0; near_origin < 2; near_origin++) {
            double s = scales[i];
            Scene scene;
            scene_init(&scene);
            Vec3 n = vec3_normalize(vec3(0.3, -0.4, 0.87)), a, b;
            test_frame(n, &a, &b);
            Vec3 centre = near_origin ? vec3(0, 0, 0) : vec3(1.7 * s, -3.1 * s, 2.3 * s);
            add_square(&scene, centre, a, b, 5 * s, add_material(&scene, MATERIAL_LAMBERT, 0));
            scene_prepare(&scene);
            for (int k = 0; k < 2000; k++) {
                double r = s * pow(10.0, -12.0 * test_uniform(&rng)),
                       phi = 2 * PI * test_uniform(&rng);
                Vec3 target = near_origin ? vec3_add(vec3_scale(a, r * cos(phi)),
                                                     vec3_scale(b, r * sin(phi)))
                                          : random_point_on(&scene.triangles[k % 2], &rng);
                Vec3 eye = vec3_add_scaled(centre, random_unit_vector(&rng), 10 * s);
                Hit hit, again;
                assert_true(scene_intersect(&scene, ray_through(eye, target), INFINITY, &hit));
                Vec3 dir =
                    random_direction_along(&rng, test_uniform(&rng) < 0.5 ? n : vec3_neg(n));
                if (scene_intersect(&scene, ray_spawn(hit.point, hit.normal, dir, hit.scale),
                                    INFINITY, &again))
                    fail_msg("scale %g: self-hit at t = %g, %g from the origin", s, again.t,
                             vec3_length(hit.point));
            }
            scene_free(&scene);
        }
}

/* A sphere, hit from outside and from inside, 2000 times per scale. Spawned outwards
 * (as a reflection from the outside would be) a ray meets nothing; spawned inwards (a
 * refraction) it meets the far side, at least half the chord 2 r cos(theta) away, never
 * the near side at t ~ 0. */
static void test_no_acne_on_spheres(void **state)
{
    TestRandom rng = test_random(32, 0, 0);
    for (int i = 0; i < SCALE_COUNT; i++) {
        double s = scales[i];
        Scene scene;
        scene_init(&scene);
        Sphere sphere = {vec3(-2.3 * s, 1.9 * s, 0.7 * s), 1.3 * s,
                         add_material(&scene, MATERIAL_GLASS, 0)};
        scene_add_sphere(&scene, sphere);
        scene_prepare(&scene);
        for (int k = 0; k < 2000; k++) {
            double start_distance = (k % 2 ? 5.0 : 0.9 * test_uniform(&rng)) * sphere.radius;
            Vec3 start =
                vec3_add_scaled(sphere.center, random_unit_vector(&rng), start_distance);
            Ray first = {start, random_unit_vector(&rng)};
            Hit hit, again;
            if (!scene_intersect(&scene, first, INFINITY, &hit))
                continue;
            Vec3 out = random_direction_along(&rng, hit.normal);
            if (scene_intersect(&scene, ray_spawn(hit.point, hit.normal, out, hit.scale),
                                INFINITY, &again))
                fail_msg("scale %g: outward ray hit the sphere at t = %g", s, again.t);
            Vec3 in = random_direction_along(&rng, vec3_neg(hit.normal));
            double cos_theta = -vec3_dot(in, hit.normal);
            assert_true(scene_intersect(&scene, ray_spawn(hit.point, hit.normal, in, hit.scale),
                                        INFINITY, &again));
            if (!(again.t > sphere.radius * cos_theta))
                fail_msg("scale %g: inward ray hit at t = %g, chord %g", s, again.t,
                         2 * sphere.radius * cos_theta);
        }
        scene_free(&scene);
    }
}

/* A sphere hit's scale (Hit.scale) holds the numbers behind its point's error: the point,
 * C + r n, lies off the sphere by a few ulps of the centre's coordinates and the radius
 * together. A small sphere far from the origin shows why the centre counts: there the
 * error is ulps of |C|, up to a million times r (measured in long double). From r = 1e-9
 * to 1e3, centres 0 to 1e9 away (at most a million radii), 200 hits each. */
static void test_sphere_scale_bounds_its_error(void **state)
{
    TestRandom rng = test_random(34, 0, 0);
    const double radii[] = {1e-9, 1e-3, 1.0, 1e3}, distances[] = {0.0, 1.0, 1e3, 1e6, 1e9};
    double worst = 0.0;
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 5 && distances[j] <= 1e6 * radii[i]; j++) {
            Scene scene;
            scene_init(&scene);
            Sphere sphere = {vec3_scale(vec3(0.6, -0.48, 0.64), distances[j]), radii[i],
                             add_material(&scene, MATERIAL_LAMBERT, 0)};
            scene_add_sphere(&scene, sphere);
            scene_prepare(&scene);
            for (int k = 0; k < 200; k++) {
                Vec3 eye =
                    vec3_add_scaled(sphere.center, random_unit_vector(&rng), 3 * sphere.radius);
                Vec3 target = vec3_add_scaled(sphere.center, random_unit_vector(&rng),
                                              0.5 * sphere.radius);
                Hit hit;
                assert_true(scene_intersect(&scene, ray_through(eye, target), INFINITY, &hit));
                long double dx = (long double)hit.point.x - sphere.center.x,
                            dy = (long double)hit.point.y - sphere.center.y,
                            dz = (long double)hit.point.z - sphere.center.z;
                double off = (double)fabsl(sqrtl(dx * dx + dy * dy + dz * dz) - sphere.radius);
                if (!(off <= 4 * DBL_EPSILON * hit.scale))
                    fail_msg("r %g at %g from the origin: the point is %g off the sphere, "
                             "%.3g ulps of its scale %g",
                             radii[i], distances[j], off, off / (DBL_EPSILON * hit.scale),
                             hit.scale);
                worst = fmax(worst, off / (DBL_EPSILON * hit.scale));
            }
            scene_free(&scene);
        }
    print_message("    at most %.2f ulps of the hit's scale off the sphere\n", worst);
}

/* No missed near hit: two parallel squares 1e-6 * scale apart (awkwardly oriented).
 * From 2000 hit points on the lower one, a ray spawned towards the upper one finds it
 * (not the lower one, not nothing) at t = gap / cos(theta), and the other way round.
 * Every ray is within 60 degrees of the normal: a more grazing eye ray can pass the
 * near square's edge and reach the far one first. */
static void test_near_parallel_planes(void **state)
{
    TestRandom rng = test_random(33, 0, 0);
    for (int i = 0; i < SCALE_COUNT; i++) {
        double s = scales[i], gap = 1e-6 * s;
        Scene scene;
        scene_init(&scene);
        Vec3 n = vec3_normalize(vec3(-0.2, 0.9, 0.4)), a, b;
        test_frame(n, &a, &b);
        Vec3 centre = vec3(0.6 * s, 2.2 * s, -1.4 * s);
        int m = add_material(&scene, MATERIAL_LAMBERT, 0);
        add_square(&scene, centre, a, b, s, m);                          /* triangles 0, 1 */
        add_square(&scene, vec3_add_scaled(centre, n, gap), a, b, s, m); /* triangles 2, 3 */
        scene_prepare(&scene);
        for (int k = 0; k < 2000; k++) {
            int up = k % 2;
            Vec3 side = up ? vec3_neg(n) : vec3_scale(n, 2);
            Vec3 target = random_point_on(&scene.triangles[k % 4], &rng);
            target = vec3_add_scaled(target, n, up ? 0.0 : gap);
            Vec3 from; /* within 60 degrees of the normal, so the eye ray meets the near
                          square's plane inside it */
            do
                from = random_direction_along(&rng, side);
            while (fabs(vec3_dot(from, n)) < 0.5);
            Vec3 eye = vec3_add_scaled(target, from, 0.5 * s);
            Hit hit, near;
            assert_true(scene_intersect(&scene, ray_through(eye, target), INFINITY, &hit));
            /* Towards the other plane, at most 60 degrees from its normal so the hit
             * stays inside the squares. */
            Vec3 towards = up ? n : vec3_neg(n), dir;
            do
                dir = random_direction_along(&rng, towards);
            while (vec3_dot(dir, towards) < 0.5);
            int found = scene_intersect(
                &scene, ray_spawn(hit.point, hit.normal, dir, hit.scale), INFINITY, &near);
            if (!found || (near.triangle >= 2) != up)
                fail_msg("scale %g: missed the plane %g away (found %d, triangle %d)", s, gap,
                         found, found ? near.triangle : -1);
            /* t is the gap along the ray, less the start's offset (ray.h) */
            double expected = gap / vec3_dot(dir, towards);
            assert_close(near.t, expected, 0.2 * expected);
        }
        scene_free(&scene);
    }
}

/* No missed near hit in a corner: a floor and a wall meeting at a right angle. From
 * floor points 1e-6 * scale from the wall, rays towards the wall find the wall. */
static void test_corner(void **state)
{
    TestRandom rng = test_random(34, 0, 0);
    for (int i = 0; i < SCALE_COUNT; i++) {
        double s = scales[i], d = 1e-6 * s;
        Scene scene;
        scene_init(&scene);
        int m = add_material(&scene, MATERIAL_LAMBERT, 0);
        Vec3 o = vec3(3 * s, -2 * s, 5 * s);
        /* floor z = o.z over x in [o.x, o.x + s]; wall x = o.x over z in [o.z, o.z + s] */
        add_quad(&scene, o, vec3_add(o, vec3(s, 0, 0)), vec3_add(o, vec3(s, s, 0)),
                 vec3_add(o, vec3(0, s, 0)), m);
        add_quad(&scene, o, vec3_add(o, vec3(0, s, 0)), vec3_add(o, vec3(0, s, s)),
                 vec3_add(o, vec3(0, 0, s)), m);
        scene_prepare(&scene);
        for (int k = 0; k < 2000; k++) {
            Vec3 target = vec3_add(o, vec3(d, (0.25 + 0.5 * test_uniform(&rng)) * s, 0));
            Hit hit, wall;
            assert_true(scene_intersect(
                &scene, ray_through(vec3_add(target, vec3(0.3 * s, 0, s)), target), INFINITY,
                &hit));
            assert_true(hit.triangle < 2);
            /* towards the wall (-x), rising at most 45 degrees above the floor */
            double rise = test_uniform(&rng), swing = test_uniform(&rng) - 0.5;
            Vec3 dir = vec3_normalize(vec3(-1, swing, rise));
            assert_true(scene_intersect(
                &scene, ray_spawn(hit.point, hit.normal, dir, hit.scale), INFINITY, &wall));
            if (wall.triangle < 2)
                fail_msg("scale %g: hit the floor again at t = %g", s, wall.t);
        }
        scene_free(&scene);
    }
}

/* Shadow rays, at each scale: a floor and a light square above it, without and with
 * a blocker exactly half-way. Between 2000 random points of the floor and of the
 * light: never occluded by the end points' own surfaces; always by the blocker. */
static void test_occluded(void **state)
{
    TestRandom rng = test_random(35, 0, 0);
    for (int i = 0; i < SCALE_COUNT; i++)
        for (int blocked = 0; blocked < 2; blocked++) {
            double s = scales[i];
            Scene scene;
            scene_init(&scene);
            int white = add_material(&scene, MATERIAL_LAMBERT, 0);
            int lamp = add_material(&scene, MATERIAL_LIGHT, 10);
            Vec3 x = vec3(1, 0, 0), y = vec3(0, 1, 0), base = vec3(0.7 * s, -0.3 * s, 1.1 * s);
            add_square(&scene, base, x, y, s, white); /* floor, up */
            add_square(&scene, vec3_add(base, vec3(0, 0, 2 * s)), y, x, s,
                       lamp); /* light, down */
            if (blocked)
                add_square(&scene, vec3_add(base, vec3(0, 0, s)), x, y, 3 * s, white);
            scene_prepare(&scene);
            for (int k = 0; k < 2000; k++) {
                Vec3 from = random_point_on(&scene.triangles[k % 2], &rng);
                Vec3 to = random_point_on(&scene.triangles[2 + k % 2], &rng);
                int occluded = scene_occluded(&scene, from, scene.triangles[0].normal, to,
                                              scene.triangles[2].normal);
                if (occluded != blocked)
                    fail_msg("scale %g, blocker %d: occluded = %d", s, blocked, occluded);
            }
            scene_free(&scene);
        }
}

/* Shadow rays to a sphere's surface: a point on the side facing us is visible, one on
 * the far side is hidden by the sphere itself; a sphere in between hides; points on
 * the floor under the sphere's shadow and beside it. */
static void test_occluded_by_spheres(void **state)
{
    for (int i = 0; i < SCALE_COUNT; i++) {
        double s = scales[i];
        Scene scene;
        scene_init(&scene);
        Sphere sphere = {vec3(0, 0, 3 * s), s, add_material(&scene, MATERIAL_LAMBERT, 0)};
        scene_add_sphere(&scene, sphere);
        scene_prepare(&scene);
        Vec3 floor_up = vec3(0, 0, 1);
        Vec3 under = vec3(0, 0, 0), beside = vec3(3 * s, 0, 0), above = vec3(0, 0, 6 * s);
        Vec3 near_side = vec3(0, 0, 2 * s), far_side = vec3(0, 0, 4 * s);
        assert_false(scene_occluded(&scene, under, floor_up, near_side, vec3(0, 0, -1)));
        assert_true(scene_occluded(&scene, under, floor_up, far_side, vec3(0, 0, 1)));
        assert_true(scene_occluded(&scene, under, floor_up, above, floor_up));
        assert_false(scene_occluded(&scene, beside, floor_up, vec3(3 * s, 0, 6 * s), floor_up));
        scene_free(&scene);
    }
}

/* `in` scaled by s, into a new prepared scene: triangles from their stored corners, so
 * that the copy with s = 1 is the reference the scaled copies are compared with (point
 * lights keep their intensity). */
static void scale_scene(const Scene *in, double s, Scene *out)
{
    scene_init(out);
    for (int i = 0; i < in->material_count; i++)
        scene_add_material(out, in->materials[i]);
    for (int i = 0; i < in->triangle_count; i++) {
        const Triangle *t = &in->triangles[i];
        scene_add_triangle(
            out, triangle_make(vec3_scale(t->v0, s), vec3_scale(vec3_add(t->v0, t->e1), s),
                               vec3_scale(vec3_add(t->v0, t->e2), s), t->material));
    }
    for (int i = 0; i < in->sphere_count; i++) {
        Sphere sphere = in->spheres[i];
        sphere.center = vec3_scale(sphere.center, s);
        sphere.radius *= s;
        scene_add_sphere(out, sphere);
    }
    for (int i = 0; i < in->point_light_count; i++) {
        PointLight light = in->point_lights[i];
        light.position = vec3_scale(light.position, s);
        scene_add_point_light(out, light);
    }
    const Camera *c = &in->camera;
    out->camera = camera_make(vec3_scale(c->eye, s), vec3_scale(c->bottom_left, s),
                              vec3_scale(vec3_add(c->bottom_left, c->right), s),
                              vec3_scale(vec3_add(c->bottom_left, c->up), s));
    assert_int_equal(scene_prepare(out), 0);
}

/* The room scaled by 2^-40 (about 1e-12, where an absolute ray offset jumped through
 * the walls and left half the pixels black) and by 2^130 (about
 * 1e39). Scaling by a power of two is exact, and so is every query computed from it,
 * the ray offset included (it is relative to the scene's scale, ray.h): from every
 * pixel of a 32 x 32 view, the camera ray and then four bounces in random directions
 * (the same in every copy) hit the same primitives at the same t, times the scale, as
 * in the room itself. */
static void test_scaled_room(void **state)
{
    Scene room, reference;
    char error[512];
    if (scene_load("scenes/room.scene", &room, error, sizeof error) != 0)
        fail_msg("%s", error);
    scale_scene(&room, 1.0, &reference);
    const int exponents[] = {-40, 130};
    for (int e = 0; e < 2; e++) {
        double s = ldexp(1.0, exponents[e]);
        Scene scaled;
        scale_scene(&room, s, &scaled);
        for (int pixel = 0; pixel < 32 * 32; pixel++) {
            Ray a = camera_ray(&reference.camera, 32, 32, pixel % 32, pixel / 32, 0.5, 0.5);
            Ray b = camera_ray(&scaled.camera, 32, 32, pixel % 32, pixel / 32, 0.5, 0.5);
            TestRandom rng = test_random(36, (uint64_t)pixel, 0);
            for (int bounce = 0; bounce < 5; bounce++) {
                Hit hit_a, hit_b;
                int found_a = scene_intersect(&reference, a, INFINITY, &hit_a);
                int found_b = scene_intersect(&scaled, b, INFINITY, &hit_b);
                assert_int_equal(found_a, found_b);
                if (!found_a)
                    break;
                if (hit_a.triangle != hit_b.triangle || hit_a.material != hit_b.material ||
                    hit_b.t != hit_a.t * s)
                    fail_msg("scale 2^%d, pixel %d, bounce %d: triangle %d at t = %g "
                             "instead of triangle %d at t = %g",
                             exponents[e], pixel, bounce, hit_b.triangle, hit_b.t / s,
                             hit_a.triangle, hit_a.t);
                Vec3 towards =
                    vec3_dot(a.dir, hit_a.normal) < 0 ? hit_a.normal : vec3_neg(hit_a.normal);
                Vec3 dir = random_direction_along(&rng, towards);
                a = ray_spawn(hit_a.point, hit_a.normal, dir, hit_a.scale);
                b = ray_spawn(hit_b.point, hit_b.normal, dir, hit_b.scale);
            }
        }
        scene_free(&scaled);
    }
    scene_free(&reference);
    scene_free(&room);
}

/* A unit sphere far outside the closed room, where no ray can reach it, changes nothing:
 * every pixel of the room's Whitted image is the same bit for bit with the sphere 1e3 to
 * 1e49 away. An offset relative to the whole scene's extent (rather than to the hit
 * point and its surface) moves every new ray by up to 1e39 and turns the room black. */
static void test_far_object_changes_nothing(void **state)
{
    enum {
        SIDE = 24
    };
    const double distances[] = {1e3, 1e9, 1e12, 1e20, 1e40, 1e49};
    WhittedSettings whitted = {10};
    ImageSettings image = {.width = SIDE, .height = SIDE, .spp = 1};
    Scene room;
    char error[512];
    if (scene_load("scenes/room_whitted.scene", &room, error, sizeof error) != 0)
        fail_msg("%s", error);
    static Vec3 alone[SIDE * SIDE];
    RayCounts counts = {0, 0, 0};
    for (int i = 0; i < SIDE * SIDE; i++)
        alone[i] = render_sample(&room, &image, i % SIDE, i / SIDE, 0, whitted_estimate,
                                 &whitted, &counts);
    for (int k = 0; k < (int)(sizeof distances / sizeof distances[0]); k++) {
        Scene far;
        scale_scene(&room, 1.0, &far);
        assert_true(scene_add_sphere(&far, (Sphere){vec3(distances[k], 0, 0), 1.0, 0}) >= 0);
        assert_int_equal(scene_prepare(&far), 0);
        int differ = 0;
        for (int i = 0; i < SIDE * SIDE; i++) {
            Vec3 v = render_sample(&far, &image, i % SIDE, i / SIDE, 0, whitted_estimate,
                                   &whitted, &counts);
            differ += v.x != alone[i].x || v.y != alone[i].y || v.z != alone[i].z;
        }
        print_message("    sphere %g away: %d of %d pixels differ\n", distances[k], differ,
                      SIDE * SIDE);
        assert_int_equal(differ, 0);
        scene_free(&far);
    }
    scene_free(&room);
}

/* However far the ray came from, its hit point is put back on the surface (scene.h),
 * so what starts there behaves as from a near camera: a floor with a wall standing on
 * it and a ball beside, seen from 1e3, 1e8 and 1e11 away (the pulled-back cameras of
 * the metamorphic tests), 400 points of each per distance. From the floor: a shadow ray
 * to a lamp above is not blocked by the floor (acne, where the point kept the rounding
 * of an origin 1e8 away), and a ray spawned towards the wall meets it (it started 10
 * units up when the offset grew with the origin, and a mirror floor's reflections
 * vanished). From the ball: outwards nothing, inwards its far side, and from its lit
 * side the lamp, unblocked. */
static void test_far_camera(void **state)
{
    TestRandom rng = test_random(37, 0, 0);
    const double distances[] = {1e3, 1e8, 1e11};
    Scene scene;
    scene_init(&scene);
    int m = add_material(&scene, MATERIAL_LAMBERT, 0);
    add_square(&scene, vec3(0.7, -0.3, 0), vec3(1, 0, 0), vec3(0, 1, 0), 5, m);  /* 0, 1 */
    add_square(&scene, vec3(0.31, -0.3, 1), vec3(0, 1, 0), vec3(0, 0, 1), 1, m); /* 2, 3 */
    Sphere ball = {vec3(2.9, 1.7, 0.8), 0.75, m};
    scene_add_sphere(&scene, ball);
    assert_int_equal(scene_prepare(&scene), 0);
    Vec3 lamp = vec3(1.5, -0.2, 3.9), down = vec3(0, 0, -1);
    for (int i = 0; i < 3; i++)
        for (int k = 0; k < 800; k++) {
            int on_ball = k % 2;
            Vec3 target =
                on_ball ? vec3_add_scaled(ball.center, random_unit_vector(&rng), ball.radius)
                        : vec3(0.35 + test_uniform(&rng), -1.0 + 1.4 * test_uniform(&rng), 0);
            Vec3 away = on_ball ? vec3_normalize(vec3_sub(target, ball.center)) : vec3(0, 0, 1);
            Vec3 eye =
                vec3_add_scaled(target, random_direction_along(&rng, away), distances[i]);
            Hit hit, next;
            if (!scene_intersect(&scene, ray_through(eye, target), INFINITY, &hit) ||
                (on_ball ? hit.triangle >= 0 : hit.triangle < 0 || hit.triangle > 1))
                continue; /* something else is in the way */
            int lit = vec3_dot(vec3_sub(lamp, hit.point), hit.normal) > 0;
            if (lit && scene_occluded(&scene, hit.point, hit.normal, lamp, down))
                fail_msg("camera %g away: the %s shadows itself (acne)", distances[i],
                         on_ball ? "ball" : "floor");
            if (!on_ball) {
                Vec3 dir = vec3_normalize(
                    vec3(-1, 0.2 * test_uniform(&rng), 0.3 * test_uniform(&rng)));
                if (!scene_intersect(&scene, ray_spawn(hit.point, hit.normal, dir, hit.scale),
                                     INFINITY, &next) ||
                    next.triangle < 2)
                    fail_msg("camera %g away: from the floor, the wall was missed",
                             distances[i]);
                continue;
            }
            Vec3 out = random_direction_along(&rng, hit.normal), in = vec3_neg(out);
            if (scene_intersect(&scene, ray_spawn(hit.point, hit.normal, out, hit.scale),
                                INFINITY, &next) &&
                next.triangle < 0)
                fail_msg("camera %g away: an outward ray hit the ball again", distances[i]);
            if (!scene_intersect(&scene, ray_spawn(hit.point, hit.normal, in, hit.scale),
                                 INFINITY, &next) ||
                next.triangle >= 0 ||
                !(next.t > ball.radius * vec3_dot(in, vec3_neg(hit.normal))))
                fail_msg("camera %g away: an inward ray missed the ball's far side",
                         distances[i]);
        }
    scene_free(&scene);
}

/* A floor quad 2e12 wide under a ceiling 1 above: rays from between them hit the floor
 * near the origin and, spawned upwards, must meet the ceiling at t = 1 / cos(theta). The
 * offset of a point follows the numbers that place it on the floor along the normal (its
 * height, -5), not the floor's far corners: scaled by them, the rays started 100 units up,
 * above the ceiling, and the room with its floor extended far beyond the walls lost its
 * bounced light. */
static void test_huge_floor(void **state)
{
    TestRandom rng = test_random(38, 0, 0);
    Scene scene;
    scene_init(&scene);
    int m = add_material(&scene, MATERIAL_LAMBERT, 0);
    add_quad(&scene, vec3(-1e12, -1e12, -5), vec3(1e12, -1e12, -5), vec3(1e12, 1e12, -5),
             vec3(-1e12, 1e12, -5), m);
    add_square(&scene, vec3(0.5, 0.5, -4), vec3(1, 0, 0), vec3(0, 1, 0), 20, m);
    assert_int_equal(scene_prepare(&scene), 0);
    for (int k = 0; k < 2000; k++) {
        Vec3 target = vec3(3 * test_uniform(&rng) - 1, 3 * test_uniform(&rng) - 1, -5);
        Vec3 eye = vec3_add_scaled(target, random_direction_along(&rng, vec3(0, 0, 1)), 0.9);
        Hit hit, ceiling;
        assert_true(scene_intersect(&scene, ray_through(eye, target), INFINITY, &hit));
        assert_true(hit.triangle < 2);
        Vec3 dir;
        do
            dir = random_direction_along(&rng, vec3(0, 0, 1));
        while (dir.z < 0.5);
        if (!scene_intersect(&scene, ray_spawn(hit.point, hit.normal, dir, hit.scale), INFINITY,
                             &ceiling) ||
            ceiling.triangle < 2)
            fail_msg("from the floor at (%g, %g), up: the ceiling was missed", hit.point.x,
                     hit.point.y);
        assert_close(ceiling.t, 1.0 / dir.z, 1e-9);
    }
    scene_free(&scene);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_nearest_hit),
        cmocka_unit_test(test_tie_goes_to_the_lower_number),
        cmocka_unit_test(test_hit_from_inside_sphere),
        cmocka_unit_test(test_no_acne_on_triangles),
        cmocka_unit_test(test_no_acne_on_spheres),
        cmocka_unit_test(test_sphere_scale_bounds_its_error),
        cmocka_unit_test(test_near_parallel_planes),
        cmocka_unit_test(test_corner),
        cmocka_unit_test(test_occluded),
        cmocka_unit_test(test_occluded_by_spheres),
        cmocka_unit_test(test_scaled_room),
        cmocka_unit_test(test_far_object_changes_nothing),
        cmocka_unit_test(test_far_camera),
        cmocka_unit_test(test_huge_floor),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
