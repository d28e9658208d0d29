/* vec.h (chapter 1): three-component vectors, for points, directions and RGB colours.
 *
 * Doubles throughout: the renderer must work on scenes scaled far up and down, where
 * floats would lose the offsets that keep new rays off their surface (ray.h). Every
 * function is small and inline.
 */
#ifndef VEC_H
#define VEC_H

#include <math.h>

#define PI 3.14159265358979323846

typedef struct {
    double x, y, z;
} Vec3;

static inline Vec3 vec3(double x, double y, double z)
{
    Vec3 v = {x, y, z};
    return v;
}
static inline Vec3 vec3_add(Vec3 a, Vec3 b) { return vec3(a.x + b.x, a.y + b.y, a.z + b.z); }
static inline Vec3 vec3_sub(Vec3 a, Vec3 b) { return vec3(a.x - b.x, a.y - b.y, a.z - b.z); }
static inline Vec3 vec3_scale(Vec3 a, double s) { return vec3(a.x * s, a.y * s, a.z * s); }
/* Component-wise product: how a colour filters a colour. */
static inline Vec3 vec3_mul(Vec3 a, Vec3 b) { return vec3(a.x * b.x, a.y * b.y, a.z * b.z); }
static inline Vec3 vec3_neg(Vec3 a) { return vec3(-a.x, -a.y, -a.z); }
static inline double vec3_dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static inline Vec3 vec3_cross(Vec3 a, Vec3 b)
{
    return vec3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
static inline double vec3_length(Vec3 a) { return sqrt(vec3_dot(a, a)); }
static inline Vec3 vec3_normalize(Vec3 a) { return vec3_scale(a, 1.0 / vec3_length(a)); }
/* a + s * b, the step along a ray. */
static inline Vec3 vec3_add_scaled(Vec3 a, Vec3 b, double s)
{
    return vec3(a.x + s * b.x, a.y + s * b.y, a.z + s * b.z);
}
/* The larger of two numbers, written out: fmax() must honour NaN rules and is a library
 * call in the renderer's inner loops. */
static inline double max2(double a, double b) { return a > b ? a : b; }
#if CHAPTER >= 2
/* The smaller of two numbers, written out as max2 is. */
static inline double min2(double a, double b) { return a < b ? a : b; }
#endif
static inline double vec3_max_abs(Vec3 a)
{
    return max2(fabs(a.x), max2(fabs(a.y), fabs(a.z)));
}
static inline double vec3_max_component(Vec3 a) { return max2(a.x, max2(a.y, a.z)); }
static inline double vec3_average(Vec3 a) { return (a.x + a.y + a.z) / 3.0; }
static inline int vec3_is_finite(Vec3 a)
{
    return isfinite(a.x) && isfinite(a.y) && isfinite(a.z);
}

#endif
