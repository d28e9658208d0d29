/* test_ray.c (chapter 1): the ray x(t) = o + t d (report eq. 20) and starting a ray on a
 * surface (ray.h, chapter 1).
 *
 * ray_spawn must move the origin to the side the new ray travels into, straight
 * along the normal, by an offset relative to the scene's scale and to the point's
 * coordinates, whichever is larger -- never an absolute one, which at scale 1e-12 is
 * larger than the scene -- and that survives rounding: the moved
 * point really differs from p. Whether that offset prevents acne without skipping
 * near surfaces is tested on whole scenes in test_scene.c.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <float.h>

#include "check.h"
#include "ray.h"

/* ray_at steps t along the unit direction: t is a distance. */
static void test_ray_at(void **state)
{
    Ray ray = {vec3(1, 2, 3), vec3(0, 0.6, -0.8)};
    Vec3 p = ray_at(ray, 5);
    assert_close(p.x, 1, 0);
    assert_close(p.y, 5, 1e-15);
    assert_close(p.z, -1, 1e-15);
    assert_close(vec3_length(vec3_sub(ray_at(ray, 2.5), ray.origin)), 2.5, 1e-15);
    Vec3 o = ray_at(ray, 0);
    assert_true(o.x == 1 && o.y == 2 && o.z == 3);
}

/* For scene scales 1e-45, 1e-12, 1 and 1e40, points of size 1e-3 to 10 times the
 * scale, random normals of either orientation and random directions: the spawned
 * origin lies on the side of the new direction, moved along the normal only, by
 * RAY_OFFSET * max(scale, max |p_i|) -- the scale's share near the origin, the
 * point's beyond the scale -- and by at least 10^5 ulps of p, so rounding cannot undo
 * it. The direction is unchanged. */
static void test_spawn(void **state)
{
    TestRandom rng = test_random(8, 0, 0);
    const double scales[] = {1e-45, 1e-12, 1.0, 1e40}, sizes[] = {1e-3, 1.0, 10.0};
    for (int j = 0; j < 4; j++)
        for (int i = 0; i < 3; i++)
            for (int k = 0; k < 3000; k++) {
                double scale = scales[j];
                Vec3 p = vec3_scale(random_unit_vector(&rng), sizes[i] * scale);
                Vec3 n = random_unit_vector(&rng), dir = random_unit_vector(&rng);
                Ray ray = ray_spawn(p, n, dir, scale);
                Vec3 moved = vec3_sub(ray.origin, p);
                double offset = vec3_length(moved);
                double expected = RAY_OFFSET * fmax(scale, vec3_max_abs(p));
                double rounding = 4 * DBL_EPSILON * vec3_max_abs(p); /* of `moved` itself */
                assert_true(vec3_dot(moved, n) * vec3_dot(dir, n) > 0);
                assert_close(offset, expected, rounding);
                assert_close(fabs(vec3_dot(moved, n)), offset, rounding);
                assert_true(offset > 1e5 * DBL_EPSILON * vec3_max_abs(p));
                assert_true(ray.dir.x == dir.x && ray.dir.y == dir.y && ray.dir.z == dir.z);
            }
}

/* In a room the size of 1e-12 the offset is 1e-22-ish, far inside the room: the old
 * absolute floor (1e-10) was a hundred times the room. */
static void test_offset_follows_scale(void **state)
{
    Vec3 p = vec3(3e-12, -4e-12, 2e-12), n = vec3(0, 0, 1);
    Ray ray = ray_spawn(p, n, vec3(0, 0, 1), 13e-12);
    assert_close(ray.origin.z - p.z, RAY_OFFSET * 13e-12, 4 * DBL_EPSILON * 2e-12);
    assert_true(ray.origin.z - p.z < 1e-9 * 13e-12);
}

/* The side is chosen by the new direction, not by the normal's orientation: flipping
 * n gives the same origin. A direction exactly in the tangent plane still moves off. */
static void test_spawn_side(void **state)
{
    Vec3 p = vec3(3, -4, 2), n = vec3(0, 0, 1);
    Vec3 up = vec3_normalize(vec3(1, 1, 1)), down = vec3_normalize(vec3(1, 1, -1));
    Ray a = ray_spawn(p, n, up, 5), b = ray_spawn(p, vec3_neg(n), up, 5);
    assert_true(a.origin.z > p.z && a.origin.z == b.origin.z);
    Ray c = ray_spawn(p, n, down, 5), d = ray_spawn(p, vec3_neg(n), down, 5);
    assert_true(c.origin.z < p.z && c.origin.z == d.origin.z);
    Ray tangent = ray_spawn(p, n, vec3(1, 0, 0), 5);
    assert_true(tangent.origin.z != p.z);
}

/* ray_offset_origin makes the same move towards any vector, unnormalised too (a
 * shadow ray's span to its target, an area light), and matches ray_spawn. */
static void test_offset_origin(void **state)
{
    Vec3 p = vec3(3, -4, 2), n = vec3(0, 0, 1);
    Vec3 below = ray_offset_origin(p, n, vec3(0.1, 0.2, -7e5), 5);
    Vec3 above = ray_offset_origin(p, n, vec3(-5e-9, 0, 3e-9), 5);
    assert_close(below.z, p.z - RAY_OFFSET * 5, 1e-15);
    assert_close(above.z, p.z + RAY_OFFSET * 5, 1e-15);
    assert_true(below.x == p.x && below.y == p.y);
    Ray spawned = ray_spawn(p, n, vec3_normalize(vec3(0.1, 0.2, -7e5)), 5);
    assert_true(spawned.origin.z == below.z);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_ray_at),
        cmocka_unit_test(test_spawn),
        cmocka_unit_test(test_offset_follows_scale),
        cmocka_unit_test(test_spawn_side),
        cmocka_unit_test(test_offset_origin),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
