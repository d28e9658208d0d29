/* mesh.c (bench, chapter 9): the torus knot. See mesh.h. */
#include "mesh.h"

#include "frame.h"

/* The knot's curve at parameter t, in units of `size`, in the plane x = 0. */
static Vec3 knot_point(double t)
{
    const double big = 0.6, small = 0.3;
    double radius = big + small * cos(3.0 * t);
    return vec3(small * sin(3.0 * t), radius * cos(2.0 * t), radius * sin(2.0 * t));
}

/* The tube's point at curve parameter t and angle a around it: a circle in the plane
 * normal to the curve's tangent. */
static Vec3 tube_point(Vec3 centre, double size, double t, double a)
{
    const double tube = 0.1, step = 1e-4;
    Vec3 p = knot_point(t);
    Vec3 tangent = vec3_normalize(vec3_sub(knot_point(t + step), knot_point(t - step)));
    Vec3 side, up;
    vec3_basis(tangent, &side, &up);
    Vec3 around = vec3_add(vec3_scale(side, cos(a)), vec3_scale(up, sin(a)));
    return vec3_add(centre, vec3_scale(vec3_add_scaled(p, around, tube), size));
}

int mesh_add_torus_knot(Scene *scene, int material, Vec3 centre, double size, int segments,
                        int sides)
{
    const double two_pi = 2.0 * PI;
    for (int i = 0; i < segments; i++)
        for (int j = 0; j < sides; j++) {
            double t0 = two_pi * i / segments, t1 = two_pi * (i + 1) / segments;
            double a0 = two_pi * j / sides, a1 = two_pi * (j + 1) / sides;
            Vec3 p00 = tube_point(centre, size, t0, a0), p01 = tube_point(centre, size, t0, a1);
            Vec3 p10 = tube_point(centre, size, t1, a0), p11 = tube_point(centre, size, t1, a1);
            if (scene_add_triangle(scene, triangle_make(p00, p10, p11, material)) < 0 ||
                scene_add_triangle(scene, triangle_make(p00, p11, p01, material)) < 0)
                return -1;
        }
    return 0;
}
