/* sphere.c (chapter 1): ray-sphere intersection. See sphere.h. */
#include "sphere.h"

double sphere_intersect(const Sphere *sphere, Ray ray, double tmin, double tmax)
{
    Vec3 to_origin = vec3_sub(ray.origin, sphere->center);
    double b = -vec3_dot(to_origin, ray.dir);
    Vec3 closest = vec3_add_scaled(to_origin, ray.dir, b); /* centre to the nearest point */
    double r2 = sphere->radius * sphere->radius;
    double half_chord2 = r2 - vec3_dot(closest, closest);
    if (half_chord2 < 0.0)
        return INFINITY;
    double half_chord = sqrt(half_chord2);
    /* The near root, computed without cancellation: q = b + sign(b) h; roots q and k/q. */
    double k = vec3_dot(to_origin, to_origin) - r2;
    double q = b + copysign(half_chord, b);
    double t0 = q;
    double t1 = q != 0.0 ? k / q : 0.0;
    if (t0 > t1) {
        double swap = t0;
        t0 = t1;
        t1 = swap;
    }
    if (t0 > tmin && t0 < tmax)
        return t0;
    if (t1 > tmin && t1 < tmax)
        return t1;
    return INFINITY;
}

Vec3 sphere_normal(const Sphere *sphere, Vec3 p)
{
    return vec3_normalize(vec3_sub(p, sphere->center));
}
