/* snell.h (chapter 1): refraction by Snell's law and total internal reflection (report §3.5.2,
 * eq. 2, Figure 5).
 *
 * Introduced in chapter 1. Snell's law n_i sin(theta_i) = n_t sin(theta_t) (eq. 2) fixes
 * the refracted direction in the plane of incidence:
 *     t = eta d + (eta cos_i - cos_t) n,   eta = n_i / n_t,
 *     cos_i = -d . n,   cos_t = sqrt(1 - eta^2 (1 - cos_i^2)),
 * with n the unit normal on the incident side. When eta^2 (1 - cos_i^2) > 1 there is no
 * real cos_t: total internal reflection, which can only happen going from the denser
 * medium (n_i > n_t), beyond the critical angle
 *     theta_c = arcsin(n_t / n_i).
 * Erratum (SPEC §8.2): the report writes arcsin(n_i / n_refr), whose argument exceeds 1
 * exactly when total internal reflection is possible.
 *
 * At the critical angle itself theta_t = 90 degrees and the Fresnel reflectance is 1:
 * no light is transmitted, so that angle belongs to total internal reflection. But an
 * incidence direction built at the critical angle is rounded, and puts
 * eta^2 sin^2(theta_i) up to a few dozen ulps either side of 1; we therefore call it
 * total internal reflection from 1 - SNELL_GRAZING_MARGIN on, which otherwise only
 * drops transmitted rays within 2.4e-7 rad of the surface.
 */
#ifndef SNELL_H
#define SNELL_H

#include <float.h>

#include "vec.h"

#define SNELL_GRAZING_MARGIN (256 * DBL_EPSILON)

/* Refract unit direction d at a surface with unit normal n facing the incident side
 * (d . n <= 0), from index n_i into index n_t. Returns 1 and the unit refracted
 * direction in *t, or 0 for total internal reflection. */
int snell_refract(Vec3 d, Vec3 n, double n_i, double n_t, Vec3 *t);

/* cos(theta_t) for incidence cosine cos_i, or -1 for total internal reflection
 * (only possible for n_i > n_t). */
double snell_cos_transmitted(double cos_i, double n_i, double n_t);

/* The critical angle in radians for n_i > n_t (SPEC §8.2); pi/2 when n_i <= n_t. */
double snell_critical_angle(double n_i, double n_t);

#endif
