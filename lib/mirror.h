/* mirror.h (chapter 1): the perfect mirror (report §3.5.1, Figure 4).
 *
 * Its BRDF is a Dirac delta around the mirror direction R(d) = d - 2 (d . n) n, so the
 * reflected radiance is the mirror's reflectance times the radiance arriving from R(d).
 * The formula is the same for either orientation of the unit normal n.
 */
#ifndef MIRROR_H
#define MIRROR_H

#include "vec.h"

/* Exercise 1.4: the mirror direction R(d) of direction d at the unit normal n. */
static inline Vec3 mirror_reflect(Vec3 d, Vec3 n)
{
    return vec3_add_scaled(d, n, -2.0 * vec3_dot(d, n));
}

#endif
