/* lambert.h (chapter 2): the Lambertian reflector (report §3.5.3, eq. 8).
 *
 * An ideal diffuse surface reflects the same radiance in every direction, so its BRDF
 * is the constant f = rho / pi, rho in [0, 1] per colour channel. The 1/pi makes the
 * albedo, the integral of f cos(theta) over the hemisphere, equal rho: a white surface
 * reflects all the light it receives and no more.
 */
#ifndef LAMBERT_H
#define LAMBERT_H

#include "vec.h"

/* Exercise 2.3, eq. 8: the BRDF rho / pi, the same for every pair of directions. */
Vec3 lambert_brdf(Vec3 rho);

#endif
