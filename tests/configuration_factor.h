/* configuration_factor.h (chapter 3): direct light from a rectangle, in closed form.
 * Shared by the tests of eq. 21 (test_area_light.c, chapter 3) and of the photon
 * density estimate (test_photon_estimate.c, chapter 8).
 *
 * The configuration factor from a point on a plane to a parallel a x b rectangle at
 * height h, the point right under one of its corners, is
 *     F = 1/(2 pi) [ A/sqrt(1+A^2) atan(B/sqrt(1+A^2)) + B/sqrt(1+B^2) atan(A/sqrt(1+B^2)) ],
 * A = a/h, B = b/h; a Lambertian point there with reflectance rho under a lamp of
 * radiance Le reflects L = rho Le F (its irradiance is pi Le F).
 * For a point anywhere, split the rectangle at the point's projection into pieces that
 * each have a corner above it: with G(u, v) the corner form for [0, u] x [0, v], odd in
 * u and in v (a piece on the other side counts negatively), the rectangle
 * [x0, x1] x [y0, y1] gives G(x1, y1) - G(x0, y1) - G(x1, y0) + G(x0, y0), all
 * coordinates relative to the point.
 */
#ifndef CONFIGURATION_FACTOR_H
#define CONFIGURATION_FACTOR_H

#include <math.h>

#include "vec.h"

static inline double configuration_factor(double a, double b, double h)
{
    double A = a / h, B = b / h, sa = sqrt(1 + A * A), sb = sqrt(1 + B * B);
    return (A / sa * atan(B / sa) + B / sb * atan(A / sb)) / (2.0 * PI);
}

static inline double configuration_factor_corner_signed(double u, double v, double h)
{
    double sign = (u < 0) != (v < 0) ? -1.0 : 1.0;
    return sign * configuration_factor(fabs(u), fabs(v), h);
}

/* The point (x, y) on the plane, the rectangle [0, a] x [0, b] at height h above it. */
static inline double configuration_factor_at(double x, double y, double a, double b, double h)
{
    return configuration_factor_corner_signed(a - x, b - y, h) -
           configuration_factor_corner_signed(-x, b - y, h) -
           configuration_factor_corner_signed(a - x, -y, h) +
           configuration_factor_corner_signed(-x, -y, h);
}

#endif
