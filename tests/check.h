/* check.h (chapter 1): small helpers shared by the geometry tests (include after cmocka.h).
 *
 * assert_close compares doubles and, unlike cmocka's float-only assert_float_equal,
 * prints both values at full precision when it fails. The random directions are
 * uniform over the unit sphere: z = cos(theta) uniform in [-1, 1] (Archimedes' hat-box
 * theorem) and phi uniform in [0, 2 pi).
 */
#ifndef CHECK_H
#define CHECK_H

#include "ray.h"
#include "rng.h"

#define assert_close(a, b, tol) \
    do { \
        double a_ = (a), b_ = (b); \
        if (!(fabs(a_ - b_) <= (tol))) \
            fail_msg("%s = %.17g, expected %.17g within %.3g", #a, a_, b_, (double)(tol)); \
    } while (0)

static inline Vec3 random_unit_vector(Rng *rng)
{
    double z = 2.0 * rng_uniform(rng) - 1.0, phi = 2.0 * PI * rng_uniform(rng);
    double s = sqrt(fmax(0.0, 1.0 - z * z));
    return vec3(s * cos(phi), s * sin(phi), z);
}

/* The ray from `origin` through `target`. */
static inline Ray ray_through(Vec3 origin, Vec3 target)
{
    Ray ray = {origin, vec3_normalize(vec3_sub(target, origin))};
    return ray;
}

#endif
