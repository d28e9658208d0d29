/* oren_nayar.h (chapter 5): the Oren-Nayar reflector for rough diffuse surfaces (report §3.5.4,
 * eqs. 13-14).
 *
 * Introduced in chapter 5. The surface is modelled as V-shaped grooves of Lambertian
 * facets whose slopes are Gaussian with standard deviation sigma (radians): the
 * roughness. Rough surfaces send more light back towards the light than Lambert's law
 * says, and look flatter. With theta and phi the polar and azimuthal angles of wi and
 * wo in the local frame (normal +z),
 *     f(wi, wo) = rho / pi (A + B max(0, cos(phi_i - phi_o)) sin(alpha) tan(beta))  (13)
 *     A = 1 - sigma^2 / (2 (sigma^2 + 0.33)),   B = 0.45 sigma^2 / (sigma^2 + 0.09)  (14)
 *     alpha = max(theta_i, theta_o),   beta = min(theta_i, theta_o).
 * Errata (SPEC §8.1): the report prints A without the "1 -" and sin(beta) for tan(beta).
 * With the corrections sigma = 0 gives A = 1, B = 0: exactly Lambert (lambert.h).
 *
 * No trigonometric calls are needed. For unit vectors sin(theta) is the length of the
 * projection onto the surface (x, y), so
 *     sin(theta_i) sin(theta_o) cos(phi_i - phi_o) = x_i x_o + y_i y_o,
 * and since tan(beta) = sin(beta) / cos(beta) with cos(beta) = max(cos theta_i,
 * cos theta_o), the angular term is
 *     max(0, cos(phi_i - phi_o)) sin(alpha) tan(beta)
 *         = max(0, x_i x_o + y_i y_o) / max(z_i, z_o).
 * This stays finite at normal incidence (the projection is 0, and so is the term,
 * without dividing by its length) and is symmetric in wi and wo (reciprocity). Only when
 * both directions graze the surface (z_i = z_o = 0) is tan(beta) infinite; there the
 * term is dropped, which changes nothing where it matters, because wherever the BRDF is
 * used it is multiplied by cos(theta_i) = 0.
 *
 * Energy: the model is qualitative, not exactly energy conserving. A white surface's
 * directional albedo (the integral of f cos(theta_i) over wi, rho = 1) rises from A at
 * normal viewing to A + B / 2 at grazing; that is below 1 for sigma >= 0.33 rad but
 * above it for smoother surfaces, by at most 1.5% (sigma = 0.2). A white-furnace test of
 * a renderer must therefore not expect an Oren-Nayar room to give Le / (1 - rho).
 *
 * Sampling: the path tracer draws wi from the cosine-weighted hemisphere (hemisphere.h,
 * pdf cos(theta_i) / pi), so a sample carries the weight
 *     f cos(theta_i) / pdf = rho * oren_nayar_factor(sigma, wi, wo).
 */
#ifndef OREN_NAYAR_H
#define OREN_NAYAR_H

#include "vec.h"

/* Eq. 14, corrected (SPEC §8.1). */
double oren_nayar_a(double sigma);
double oren_nayar_b(double sigma);

/* f / (rho / pi) = A + B max(0, cos(phi_i - phi_o)) sin(alpha) tan(beta), for unit
 * local directions wi, wo (z >= 0; a z below 0 from rounding counts as grazing). */
double oren_nayar_factor(double sigma, Vec3 wi, Vec3 wo);

/* Eq. 13: the BRDF for reflectance rho and roughness sigma >= 0 (radians). */
Vec3 oren_nayar_brdf(Vec3 rho, double sigma, Vec3 wi, Vec3 wo);

#endif
