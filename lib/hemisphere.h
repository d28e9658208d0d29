/* hemisphere.h (chapter 2): cosine-weighted directions on the hemisphere, drawn by inverting the
 * CDF (report §3.1, §3.5.3, eqs. 9-12).
 *
 * Introduced in chapter 2. Directions are in the local frame: the normal is +z, theta
 * is measured from it and phi around it (cos theta = w.z, phi = atan2(w.y, w.x)).
 * The density over solid angle
 *     p(w) = cos(theta) / pi
 * is non-negative (eq. 9) and integrates to 1 over the hemisphere (eq. 10). With
 * dw = sin(theta) dtheta dphi the density of (theta, phi) is cos(theta) sin(theta) / pi,
 * the product of a density of theta alone and a uniform density of phi:
 *     p(theta) = 2 cos(theta) sin(theta),   p(phi) = 1 / (2 pi).
 * Their CDFs (eq. 11) are
 *     P(theta) = sin^2(theta),              P(phi) = phi / (2 pi),
 * and inverting each one (eq. 12) turns uniform u1, u2 in [0, 1) into
 *     sin^2(theta) = u1, i.e. cos(theta) = sqrt(1 - u1),   phi = 2 pi u2.
 * No trigonometry is needed for theta: sin(theta) = sqrt(u1).
 *
 * Why this density: f cos(theta) / p is constant for a Lambertian surface (lambert.h),
 * so every sample carries the weight rho and the only noise left is in the incoming
 * radiance. Oren-Nayar surfaces are sampled the same way (oren_nayar.h).
 */
#ifndef HEMISPHERE_H
#define HEMISPHERE_H

#include "vec.h"

/* A unit direction with density cos(theta) / pi, from u1, u2 in [0, 1).
 * Its z is sqrt(1 - u1) > 0: never below or exactly on the surface. */
Vec3 hemisphere_sample_cosine(double u1, double u2);

/* The density cos(theta) / pi of a unit local direction; 0 below the surface. */
double hemisphere_pdf_cosine(Vec3 w_local);

#endif
