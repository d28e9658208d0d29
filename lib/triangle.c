/* triangle.c (chapter 1): Möller-Trumbore ray-triangle intersection. See triangle.h. */
#include "triangle.h"

Triangle triangle_make(Vec3 v0, Vec3 v1, Vec3 v2, int material)
{
    Triangle tri;
    tri.v0 = v0;
    tri.e1 = vec3_sub(v1, v0);
    tri.e2 = vec3_sub(v2, v0);
    Vec3 cross = vec3_cross(tri.e1, tri.e2);
    double twice_area = vec3_length(cross);
    tri.area = 0.5 * twice_area;
    tri.normal = twice_area > 0.0 ? vec3_scale(cross, 1.0 / twice_area) : vec3(0, 0, 0);
    tri.longest_edge = max2(vec3_max_abs(tri.e1), vec3_max_abs(tri.e2));
    tri.material = material;
    return tri;
}

double triangle_intersect(const Triangle *tri, Ray ray, double tmin, double tmax)
{
    Vec3 p = vec3_cross(ray.dir, tri->e2);
    double det = vec3_dot(tri->e1, p);
    /* det = -d . (e1 x e2) = -2 area cos(angle to normal); relative to 2 area it is the
     * cosine of the incidence angle, and a ray within ~1e-14 of parallel misses. */
    if (fabs(det) <= 1e-14 * 2.0 * tri->area)
        return INFINITY;
    double inv_det = 1.0 / det;
    Vec3 s = vec3_sub(ray.origin, tri->v0);
    /* Rounding error bound of u and v (triangle.h): accepting down to -slack closes
     * shared edges. */
    double edge = tri->longest_edge;
    double slack = TRIANGLE_EDGE_SLACK * (vec3_max_abs(s) + edge) * edge * fabs(inv_det);
    double u = vec3_dot(s, p) * inv_det;
    if (u < -slack || u > 1.0 + slack)
        return INFINITY;
    Vec3 q = vec3_cross(s, tri->e1);
    double v = vec3_dot(ray.dir, q) * inv_det;
    if (v < -slack || u + v > 1.0 + slack)
        return INFINITY;
    double t = vec3_dot(tri->e2, q) * inv_det;
    return (t > tmin && t < tmax) ? t : INFINITY;
}

Vec3 triangle_point(const Triangle *tri, double u, double v)
{
    return vec3_add_scaled(vec3_add_scaled(tri->v0, tri->e1, u), tri->e2, v);
}
