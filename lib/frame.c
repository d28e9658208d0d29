/* frame.c (chapter 2): the orthonormal basis around a normal. See frame.h. */
#include "frame.h"

void vec3_basis(Vec3 n, Vec3 *t, Vec3 *b)
{
    double sign = copysign(1.0, n.z);
    double a = -1.0 / (sign + n.z);
    double c = n.x * n.y * a;
    *t = vec3(1.0 + sign * n.x * n.x * a, sign * c, -sign * n.x);
    *b = vec3(c, sign + n.y * n.y * a, -n.y);
}
