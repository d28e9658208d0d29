/* diffuse.h (chapter 2): the diffuse materials' BRDF and sampling in world space.
 *
 * Introduced in chapter 2. Lambertian (eq. 8) and Oren-Nayar (eqs. 13-14) surfaces are
 * both sampled with the cosine-weighted hemisphere (hemisphere.h, pdf cos/pi), so a
 * sampled direction carries the weight
 *     f cos / pdf = rho                      (Lambert)
 *                 = rho * oren_nayar_factor  (Oren-Nayar).
 * The BRDFs themselves work in the local frame with the normal as +z (lambert.h,
 * oren_nayar.h); this file moves directions into and out of that frame.
 */
#ifndef DIFFUSE_H
#define DIFFUSE_H

#include "material.h"

/* f(wi, wo) for a Lambert or Oren-Nayar material at a surface with unit normal n
 * (facing wo); wi and wo are unit directions away from the surface. */
Vec3 diffuse_brdf(const Material *m, Vec3 n, Vec3 wi, Vec3 wo);

/* Sample wi by the cosine-weighted hemisphere around n; returns the weight
 * f cos / pdf and the direction in *wi. */
Vec3 diffuse_sample(const Material *m, Vec3 n, Vec3 wo, double u1, double u2, Vec3 *wi);

#if CHAPTER >= 7
/* The density in solid angle with which diffuse_sample draws wi: cos / pi (hemisphere.h),
 * 0 below the surface. Multiple importance sampling (mis.h) needs it. */
double diffuse_pdf(Vec3 n, Vec3 wi);
#endif

#endif
