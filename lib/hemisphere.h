/* hemisphere.h (chapter 2): cosine-weighted directions drawn by inverting the CDF
 * (report §3.1, §3.5.3, eqs. 9-12).
 *
 * In the local frame (normal +z) the density p(w) = cos(theta) / pi (eqs. 9-10) splits
 * into p(theta) = 2 cos sin and p(phi) = 1 / (2 pi); their CDFs (eq. 11) P(theta) =
 * sin^2(theta) and P(phi) = phi / (2 pi) inverted (eq. 12) give, from uniform u1, u2,
 *     cos(theta) = sqrt(1 - u1),   sin(theta) = sqrt(u1),   phi = 2 pi u2.
 * With it a Lambertian sample's weight f cos / p is exactly rho (docs/chapter2.md).
 */
#ifndef HEMISPHERE_H
#define HEMISPHERE_H

#include "vec.h"

/* Exercise 2.1: a unit direction with density cos(theta) / pi, from u1, u2 in [0, 1).
 * Its z is sqrt(1 - u1) > 0: never below or exactly on the surface. */
Vec3 hemisphere_sample_cosine(double u1, double u2);

/* Exercise 2.2: the density cos(theta) / pi of a unit local direction; 0 below the surface. */
double hemisphere_pdf_cosine(Vec3 w_local);

#endif
