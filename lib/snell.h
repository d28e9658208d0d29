/* snell.h (chapter 1): refraction by Snell's law, n_i sin(theta_i) = n_t sin(theta_t)
 * (report §3.5.2, eq. 2), and total internal reflection.
 *
 *     t = eta d + (eta cos_i - cos_t) n,   eta = n_i / n_t,   cos_t = sqrt(1 - eta^2 sin_i^2)
 * with n the unit normal on the incident side. From the denser medium there is no real
 * cos_t beyond the critical angle arcsin(n_t / n_i) (erratum: the report inverts the
 * ratio), nor within SNELL_GRAZING_MARGIN of it, where rounding could fall either side.
 */
#ifndef SNELL_H
#define SNELL_H

#include <float.h>

#include "vec.h"

#define SNELL_GRAZING_MARGIN (256 * DBL_EPSILON)

/* Exercise 1.5: refract unit direction d at a surface with unit normal n facing the
 * incident side (d . n <= 0), from index n_i into index n_t. Returns 1 and the unit
 * refracted direction in *t, or 0 for total internal reflection. */
int snell_refract(Vec3 d, Vec3 n, double n_i, double n_t, Vec3 *t);

/* cos(theta_t) for incidence cosine cos_i, or -1 for total internal reflection
 * (only possible for n_i > n_t). */
double snell_cos_transmitted(double cos_i, double n_i, double n_t);

#endif
