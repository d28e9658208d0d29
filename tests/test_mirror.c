/* test_mirror.c (chapter 1): the perfect mirror's reflection R(d) = d - 2 (d . n) n (mirror.h,
 * report §3.5.1, chapter 1).
 *
 * The law of reflection is geometry, so each property is checked for many random unit
 * directions d and normals n (fixed seed) to rounding (a few 1e-15 on unit vectors): the
 * length is kept, the angle of reflection equals the angle of incidence, the reflected
 * ray lies in the plane of incidence (spanned by d and n), either orientation of n gives
 * the same result, and reflecting twice undoes the reflection. Then the two extremes:
 * normal incidence (straight back) and grazing incidence (no change).
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include "check.h"
#include "mirror.h"

#define PAIRS 100000
#define ROUNDING 1e-15

static double distance(Vec3 a, Vec3 b) { return vec3_length(vec3_sub(a, b)); }

/* A worked example: a ray going down at 45 degrees onto the floor (n = +y) leaves going
 * up at 45 degrees, keeping its forward component. */
static void test_example_by_hand(void **state)
{
    Vec3 d = vec3_normalize(vec3(1, -1, 0));
    Vec3 r = mirror_reflect(d, vec3(0, 1, 0));
    assert_close(distance(r, vec3_normalize(vec3(1, 1, 0))), 0.0, ROUNDING);
}

/* Reflection is an isometry: |R(d)| = |d|, for unit and non-unit d alike (a mirror
 * neither creates nor loses length, so a unit ray direction stays unit). */
static void test_keeps_length(void **state)
{
    TestRandom rng = test_random(1, 0, 0);
    for (int i = 0; i < PAIRS; i++) {
        Vec3 n = random_unit_vector(&rng);
        Vec3 d = vec3_scale(random_unit_vector(&rng), 0.01 + 10.0 * test_uniform(&rng));
        assert_close(vec3_length(mirror_reflect(d, n)), vec3_length(d),
                     4 * ROUNDING * vec3_length(d));
    }
}

/* Angle in = angle out: the normal component flips sign, R . n = -(d . n), and the
 * tangential component d - (d . n) n is unchanged; the reflected direction lies in the
 * plane of incidence: R . (d x n) = 0. */
static void test_angle_in_equals_angle_out_in_plane_of_incidence(void **state)
{
    TestRandom rng = test_random(2, 0, 0);
    for (int i = 0; i < PAIRS; i++) {
        Vec3 n = random_unit_vector(&rng), d = random_unit_vector(&rng);
        Vec3 r = mirror_reflect(d, n);
        assert_close(vec3_dot(r, n), -vec3_dot(d, n), ROUNDING);
        Vec3 tangential_in = vec3_add_scaled(d, n, -vec3_dot(d, n));
        Vec3 tangential_out = vec3_add_scaled(r, n, -vec3_dot(r, n));
        assert_close(distance(tangential_out, tangential_in), 0.0, 2 * ROUNDING);
        assert_close(vec3_dot(r, vec3_cross(d, n)), 0.0, 2 * ROUNDING);
    }
}

/* The formula does not care which way n points: R(d, -n) = R(d, n), bit for bit
 * (negating n negates d . n exactly, and the two negations cancel). So a mirror needs
 * no front side, and the renderer may pass either normal. */
static void test_independent_of_normal_orientation(void **state)
{
    TestRandom rng = test_random(3, 0, 0);
    for (int i = 0; i < PAIRS; i++) {
        Vec3 n = random_unit_vector(&rng), d = random_unit_vector(&rng);
        Vec3 a = mirror_reflect(d, n), b = mirror_reflect(d, vec3_neg(n));
        assert_true(a.x == b.x && a.y == b.y && a.z == b.z);
    }
}

/* Reflection is its own inverse: R(R(d)) = d (the light path through a mirror can be
 * walked backwards, which is why tracing from the eye is legitimate). */
static void test_reflecting_twice_gives_d_back(void **state)
{
    TestRandom rng = test_random(4, 0, 0);
    for (int i = 0; i < PAIRS; i++) {
        Vec3 n = random_unit_vector(&rng), d = random_unit_vector(&rng);
        assert_close(distance(mirror_reflect(mirror_reflect(d, n), n), d), 0.0, 4 * ROUNDING);
    }
}

/* Normal incidence sends the ray straight back, R(-n) = n (exactly); grazing incidence
 * (d perpendicular to n) leaves it unchanged, R(d) = d (exactly, since d . n = 0). */
static void test_normal_and_grazing_incidence(void **state)
{
    const Vec3 normals[] = {vec3(0, 0, 1), vec3(1, 0, 0), vec3(0, -1, 0)};
    for (int k = 0; k < 3; k++) {
        Vec3 n = normals[k];
        Vec3 back = mirror_reflect(vec3_neg(n), n);
        assert_true(back.x == n.x && back.y == n.y && back.z == n.z);
        Vec3 along = vec3(n.y, n.z, n.x); /* perpendicular to n */
        Vec3 r = mirror_reflect(along, n);
        assert_true(r.x == along.x && r.y == along.y && r.z == along.z);
    }
    /* For random normals both hold to rounding. */
    TestRandom rng = test_random(5, 0, 0);
    for (int i = 0; i < PAIRS; i++) {
        Vec3 n = random_unit_vector(&rng);
        assert_close(distance(mirror_reflect(vec3_neg(n), n), n), 0.0, 2 * ROUNDING);
        Vec3 t, b;
        test_frame(n, &t, &b);
        assert_close(distance(mirror_reflect(t, n), t), 0.0, 2 * ROUNDING);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_example_by_hand),
        cmocka_unit_test(test_keeps_length),
        cmocka_unit_test(test_angle_in_equals_angle_out_in_plane_of_incidence),
        cmocka_unit_test(test_independent_of_normal_orientation),
        cmocka_unit_test(test_reflecting_twice_gives_d_back),
        cmocka_unit_test(test_normal_and_grazing_incidence),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
