/* test_vec.c (chapter 1): vector arithmetic (vec.h): hand-checked values, the cross
 * product's handedness, normalising at any magnitude, non-finite components caught.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include "check.h"
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

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_arithmetic),
        cmocka_unit_test(test_cross),
        cmocka_unit_test(test_normalize),
        cmocka_unit_test(test_is_finite),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
