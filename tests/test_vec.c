/* test_vec.c (chapter 1): vector arithmetic and the orthonormal basis (vec.h, chapter 1).
 *
 * The basis (t, b, n) is where every hemisphere direction is sampled, so it must be
 * orthonormal and right-handed for every unit normal, including the pole n = (0,0,-1)
 * where simpler constructions divide by zero, and normals a hair away from it.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include "check.h"
#include "rng.h"
#include "vec.h"

static void assert_vec_close(Vec3 a, Vec3 b, double tol)
{
    assert_close(a.x, b.x, tol);
    assert_close(a.y, b.y, tol);
    assert_close(a.z, b.z, tol);
}

/* Arithmetic on hand-checked values. */
static void test_arithmetic(void **state)
{
    Vec3 a = vec3(1, 2, 3), b = vec3(-4, 5, 0.5);
    assert_vec_close(vec3_add(a, b), vec3(-3, 7, 3.5), 0);
    assert_vec_close(vec3_sub(a, b), vec3(5, -3, 2.5), 0);
    assert_vec_close(vec3_scale(a, -2), vec3(-2, -4, -6), 0);
    assert_vec_close(vec3_mul(a, b), vec3(-4, 10, 1.5), 0);
    assert_vec_close(vec3_neg(a), vec3(-1, -2, -3), 0);
    assert_vec_close(vec3_add_scaled(a, b, 2), vec3(-7, 12, 4), 0);
    assert_close(vec3_dot(a, b), 7.5, 0);
    assert_close(vec3_length(vec3(3, 4, 12)), 13, 0);
    assert_close(vec3_max_abs(vec3(1, -7, 3)), 7, 0);
    assert_close(vec3_max_component(vec3(1, -7, 3)), 3, 0);
    assert_close(vec3_average(vec3(1, 2, 6)), 3, 0);
}

/* The cross product is right-handed (x * y = z), anti-commutative, and perpendicular
 * to both factors. */
static void test_cross(void **state)
{
    assert_vec_close(vec3_cross(vec3(1, 0, 0), vec3(0, 1, 0)), vec3(0, 0, 1), 0);
    assert_vec_close(vec3_cross(vec3(0, 1, 0), vec3(0, 0, 1)), vec3(1, 0, 0), 0);
    assert_vec_close(vec3_cross(vec3(0, 0, 1), vec3(1, 0, 0)), vec3(0, 1, 0), 0);
    Vec3 a = vec3(1, 2, 3), b = vec3(-4, 5, 0.5);
    Vec3 c = vec3_cross(a, b);
    assert_vec_close(c, vec3_neg(vec3_cross(b, a)), 0);
    assert_close(vec3_dot(c, a), 0, 1e-12);
    assert_close(vec3_dot(c, b), 0, 1e-12);
}

/* Normalising gives unit length at any magnitude, from 1e-150 to 1e150. */
static void test_normalize(void **state)
{
    for (double scale = 1e-150; scale < 1e151; scale *= 1e10) {
        Vec3 n = vec3_normalize(vec3(3 * scale, -4 * scale, 12 * scale));
        assert_close(vec3_length(n), 1, 1e-15);
        assert_close(n.y, -4.0 / 13.0, 1e-15);
    }
}

/* NaN and infinity in any component are caught. */
static void test_is_finite(void **state)
{
    assert_true(vec3_is_finite(vec3(1e308, -1e-308, 0)));
    assert_false(vec3_is_finite(vec3(NAN, 0, 0)));
    assert_false(vec3_is_finite(vec3(0, INFINITY, 0)));
    assert_false(vec3_is_finite(vec3(0, 0, -INFINITY)));
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
        vec3(0, 0, 1), vec3(0, 0, -1), vec3(1, 0, 0), vec3(-1, 0, 0),
        vec3(0, 1, 0), vec3(0, -1, 0), vec3(1, 0, -0.0), vec3(0, 1, -0.0),
        vec3_normalize(vec3(1e-6, 1e-6, -1)), vec3_normalize(vec3(1e-6, -2e-6, -1)),
        vec3_normalize(vec3(sqrt(2e-12), 0, -1 + 1e-12)),
        vec3_normalize(vec3(3e-9, -4e-9, -1)), vec3_normalize(vec3(-1e-160, 1e-160, -1)),
        vec3_normalize(vec3(1e-300, 0, -1)), vec3_normalize(vec3(1e-6, 1e-6, 1)),
        vec3_normalize(vec3(1, 1, 1)), vec3_normalize(vec3(-1, 1, -1)),
    };
    for (size_t i = 0; i < sizeof normals / sizeof normals[0]; i++)
        assert_right_handed_frame(normals[i], 1e-15);
}

/* 100000 random unit normals, uniform over the sphere (z uniform in [-1,1]), plus as
 * many crowded within 1e-4 of each pole: all give right-handed orthonormal frames. */
static void test_basis_random_normals(void **state)
{
    Rng rng = rng_for_sample(11, 0, 0);
    for (int i = 0; i < 200000; i++) {
        double z = 2.0 * rng_uniform(&rng) - 1.0;
        if (i % 2)
            z = copysign(1.0 - 1e-4 * rng_uniform(&rng), z);
        double phi = 2.0 * PI * rng_uniform(&rng), s = sqrt(fmax(0.0, 1.0 - z * z));
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
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_arithmetic),
        cmocka_unit_test(test_cross),
        cmocka_unit_test(test_normalize),
        cmocka_unit_test(test_is_finite),
        cmocka_unit_test(test_basis_special_normals),
        cmocka_unit_test(test_basis_random_normals),
        cmocka_unit_test(test_from_local),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
