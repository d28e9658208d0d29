/* test_frame.c (chapter 2): the orthonormal basis around a normal (frame.h).
 *
 * The basis (t, b, n) is where every hemisphere direction is sampled, so it must be
 * orthonormal and right-handed for every unit normal, including the pole n = (0,0,-1)
 * where simpler constructions divide by zero, and normals a hair away from it; and the
 * local-to-world transform a rotation, undone by world-to-local.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include "check.h"
#include "frame.h"

static void assert_vec_close(Vec3 a, Vec3 b, double tol)
{
    assert_close(a.x, b.x, tol);
    assert_close(a.y, b.y, tol);
    assert_close(a.z, b.z, tol);
}

/* Checks that (t, b, n) is orthonormal and right-handed to `tol`. */
static void assert_right_handed_frame(Vec3 n, double tol)
{
    Vec3 t, b;
    vec3_basis(n, &t, &b);
    assert_true(vec3_is_finite(t) && vec3_is_finite(b));
    assert_close(vec3_length(t), 1, tol);
    assert_close(vec3_length(b), 1, tol);
    assert_close(vec3_dot(t, b), 0, tol);
    assert_close(vec3_dot(t, n), 0, tol);
    assert_close(vec3_dot(b, n), 0, tol);
    assert_vec_close(vec3_cross(t, b), n, tol);
}

/* The frame is orthonormal and right-handed (t x b = n) at the axes, at both poles,
 * and for normals within 1e-6 ... 1e-300 of the south pole n = (0,0,-1), where
 * the construction's 1 / (sign + n.z) is closest to dividing by zero. */
static void test_basis_special_normals(void **state)
{
    Vec3 normals[] = {
        vec3(0, 0, 1),
        vec3(0, 0, -1),
        vec3(1, 0, 0),
        vec3(-1, 0, 0),
        vec3(0, 1, 0),
        vec3(0, -1, 0),
        vec3(1, 0, -0.0),
        vec3(0, 1, -0.0),
        vec3_normalize(vec3(1e-6, 1e-6, -1)),
        vec3_normalize(vec3(1e-6, -2e-6, -1)),
        vec3_normalize(vec3(sqrt(2e-12), 0, -1 + 1e-12)),
        vec3_normalize(vec3(3e-9, -4e-9, -1)),
        vec3_normalize(vec3(-1e-160, 1e-160, -1)),
        vec3_normalize(vec3(1e-300, 0, -1)),
        vec3_normalize(vec3(1e-6, 1e-6, 1)),
        vec3_normalize(vec3(1, 1, 1)),
        vec3_normalize(vec3(-1, 1, -1)),
    };
    for (size_t i = 0; i < sizeof normals / sizeof normals[0]; i++)
        assert_right_handed_frame(normals[i], 1e-15);
}

/* 100000 random unit normals, uniform over the sphere (z uniform in [-1,1]), plus as
 * many crowded within 1e-4 of each pole: all give right-handed orthonormal frames. */
static void test_basis_random_normals(void **state)
{
    TestRandom rng = test_random(11, 0, 0);
    for (int i = 0; i < 200000; i++) {
        double z = 2.0 * test_uniform(&rng) - 1.0;
        if (i % 2)
            z = copysign(1.0 - 1e-4 * test_uniform(&rng), z);
        double phi = 2.0 * PI * test_uniform(&rng), s = sqrt(fmax(0.0, 1.0 - z * z));
        assert_right_handed_frame(vec3(s * cos(phi), s * sin(phi), z), 1e-14);
    }
}

/* vec3_from_local takes the local axes to t, b, n, so local coordinates are the
 * dot products with the frame: the transform is a rotation. */
static void test_from_local(void **state)
{
    Vec3 n = vec3_normalize(vec3(0.3, -0.5, 0.8)), t, b;
    vec3_basis(n, &t, &b);
    assert_vec_close(vec3_from_local(vec3(1, 0, 0), t, b, n), t, 0);
    assert_vec_close(vec3_from_local(vec3(0, 1, 0), t, b, n), b, 0);
    assert_vec_close(vec3_from_local(vec3(0, 0, 1), t, b, n), n, 0);
    Vec3 local = vec3(0.36, -0.48, 0.8);
    Vec3 world = vec3_from_local(local, t, b, n);
    assert_close(vec3_length(world), 1, 1e-15);
    assert_close(vec3_dot(world, t), local.x, 1e-15);
    assert_close(vec3_dot(world, b), local.y, 1e-15);
    assert_close(vec3_dot(world, n), local.z, 1e-15);
    assert_vec_close(vec3_to_local(world, t, b, n), local, 1e-15);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_basis_special_normals),
        cmocka_unit_test(test_basis_random_normals),
        cmocka_unit_test(test_from_local),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
