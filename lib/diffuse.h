/* diffuse.h (chapter 2): the diffuse materials' BRDF and sampling, in world space.
 *
 * A diffuse surface is sampled by the cosine-weighted hemisphere (hemisphere.h) around
 * its normal, under which a Lambertian direction carries the weight f cos / pdf = rho
 * exactly (eq. 8). The BRDFs themselves work in the local frame, normal +z; this file
 * moves directions into it.
 */
#ifndef DIFFUSE_H
#define DIFFUSE_H

#include "material.h"
#if CHAPTER >= 5
#include "oren_nayar.h"
#endif

/* f(wi, wo) at a surface with unit normal n facing wo; wi and wo are unit directions
 * away from the surface. */
Vec3 diffuse_brdf(const Material *m, Vec3 n, Vec3 wi, Vec3 wo);

/* Draw wi from the cosine-weighted hemisphere around n with u1, u2 in [0, 1); returns
 * the weight f cos / pdf. */
Vec3 diffuse_sample(const Material *m, Vec3 n, Vec3 wo, double u1, double u2, Vec3 *wi);

/* The density in solid angle with which diffuse_sample draws wi: cos / pi above the
 * surface, 0 below it. */
double diffuse_pdf(Vec3 n, Vec3 wi);

#endif
