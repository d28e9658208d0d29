/* vec.c (chapter 1): the orthonormal basis around a normal, by the branchless
 * construction of Duff et al., "Building an Orthonormal Basis, Revisited" (JCGT 2017):
 * exact to rounding for any unit n, n = (0, 0, -1) included.
 */
#include "vec.h"

void vec3_basis(Vec3 n, Vec3 *t, Vec3 *b)
{
    double sign = copysign(1.0, n.z);
    double a = -1.0 / (sign + n.z);
    double c = n.x * n.y * a;
    *t = vec3(1.0 + sign * n.x * n.x * a, sign * c, -sign * n.x);
    *b = vec3(c, sign + n.y * n.y * a, -n.y);
}
