/* frame.h (chapter 2): the local frame around a surface normal.
 *
 * A direction drawn about a normal (hemisphere.h) is made in local coordinates: x along
 * t, y along b, z along n, where (t, b, n) is a right-handed orthonormal basis built
 * from n alone, by the branchless construction of Duff et al., "Building an Orthonormal
 * Basis, Revisited" (JCGT 2017): exact to rounding for any unit n, n = (0, 0, -1) too.
 */
#ifndef FRAME_H
#define FRAME_H

#include "vec.h"

/* Two unit vectors t, b that with the unit vector n form a right-handed orthonormal
 * basis (t, b, n). */
void vec3_basis(Vec3 n, Vec3 *t, Vec3 *b);

/* A local direction (x along t, y along b, z along n) in world space. */
static inline Vec3 vec3_from_local(Vec3 local, Vec3 t, Vec3 b, Vec3 n)
{
    return vec3(local.x * t.x + local.y * b.x + local.z * n.x,
                local.x * t.y + local.y * b.y + local.z * n.y,
                local.x * t.z + local.y * b.z + local.z * n.z);
}

/* A world direction in the local frame: its components along t, b and n. */
static inline Vec3 vec3_to_local(Vec3 w, Vec3 t, Vec3 b, Vec3 n)
{
    return vec3(vec3_dot(w, t), vec3_dot(w, b), vec3_dot(w, n));
}

#endif
