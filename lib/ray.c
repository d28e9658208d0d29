/* ray.c (chapter 1): starting new rays off the surface. See ray.h. */
#include "ray.h"

Vec3 ray_offset_origin(Vec3 p, Vec3 n, Vec3 towards, double scale)
{
    double offset = RAY_OFFSET * fmax(scale, vec3_max_abs(p));
    if (vec3_dot(n, towards) < 0.0)
        offset = -offset;
    return vec3_add_scaled(p, n, offset);
}

Ray ray_spawn(Vec3 p, Vec3 n, Vec3 dir, double scale)
{
    Ray ray = {ray_offset_origin(p, n, dir, scale), dir};
    return ray;
}
