/* oren_nayar.h (chapter 5): the Oren-Nayar reflector for rough diffuse surfaces (report
 * §3.5.4, eqs. 13-14).
 *
 *     f = rho / pi (A + B max(0, cos(phi_i - phi_o)) sin(alpha) tan(beta))      (13)
 *     A = 1 - sigma^2 / (2 (sigma^2 + 0.33)),  B = 0.45 sigma^2 / (sigma^2 + 0.09)  (14)
 * alpha = max(theta_i, theta_o), beta = min. Errata: the report prints A without the
 * "1 -" and sin(beta) for tan(beta); corrected, sigma = 0 is Lambert. The angular term
 * is max(0, x_i x_o + y_i y_o) / max(z_i, z_o), with no trigonometry. Sampled by the
 * cosine-weighted hemisphere, a direction carries f cos / pdf = rho * oren_nayar_factor.
 * The model reflects up to 1.5% more than it receives at grazing angles (docs/chapter5.md).
 */
#ifndef OREN_NAYAR_H
#define OREN_NAYAR_H

#include "vec.h"

/* Eq. 14, corrected. */
double oren_nayar_a(double sigma);
double oren_nayar_b(double sigma);

/* f / (rho / pi) = A + B max(0, cos(phi_i - phi_o)) sin(alpha) tan(beta), for unit
 * local directions wi, wo (z >= 0; a z below 0 from rounding counts as grazing). */
double oren_nayar_factor(double sigma, Vec3 wi, Vec3 wo);

/* Eq. 13: the BRDF for reflectance rho and roughness sigma >= 0 (radians). */
Vec3 oren_nayar_brdf(Vec3 rho, double sigma, Vec3 wi, Vec3 wo);

#endif
