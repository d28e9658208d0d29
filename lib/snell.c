/* snell.c (chapter 1): Snell's law and total internal reflection. See snell.h. */
#include "snell.h"

double snell_cos_transmitted(double cos_i, double n_i, double n_t)
{
    double eta = n_i / n_t;
    double sin2_t = eta * eta * fmax(0.0, 1.0 - cos_i * cos_i);
    /* Total internal reflection, from the critical angle on (snell.h) */
    if (n_i > n_t && sin2_t >= 1.0 - SNELL_GRAZING_MARGIN)
        return -1.0;
    return sqrt(1.0 - sin2_t);
}

int snell_refract(Vec3 d, Vec3 n, double n_i, double n_t, Vec3 *t)
{
    double cos_i = fmin(1.0, -vec3_dot(d, n));
    double cos_t = snell_cos_transmitted(cos_i, n_i, n_t);
    if (cos_t < 0.0)
        return 0;
    double eta = n_i / n_t;
    *t = vec3_normalize(vec3_add(vec3_scale(d, eta), vec3_scale(n, eta * cos_i - cos_t)));
    return 1;
}
