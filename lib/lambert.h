/* lambert.h (chapter 2): the Lambertian reflector (report §3.5.3, eq. 8).
 *
 * Introduced in chapter 2. An ideal diffuse surface reflects the same radiance in every
 * direction, whatever the light's direction, so its BRDF is a constant:
 *     f(wi, wo) = rho / pi                                   (eq. 8)
 * with rho in [0, 1] the reflectance (per colour channel). The 1/pi is what makes the
 * directional albedo, the integral of f cos(theta_i) over the hemisphere, equal rho:
 *     integral of cos(theta) dw over the hemisphere = pi,
 * so a white surface (rho = 1) reflects all the light it receives and no more.
 * The surface is sampled with cosine-weighted directions (hemisphere.h), under which
 * every sample's weight f cos / pdf is exactly rho.
 */
#ifndef LAMBERT_H
#define LAMBERT_H

#include "vec.h"

/* Eq. 8: the BRDF rho / pi, the same for every pair of directions. */
Vec3 lambert_brdf(Vec3 rho);

#endif
