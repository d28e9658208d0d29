/* triangle.c (chapter 1): a triangle's edges, normal and area. The intersection test is
 * in triangle.h, inline. */
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
