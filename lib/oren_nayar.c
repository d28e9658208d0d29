/* oren_nayar.c (chapter 5): the Oren-Nayar BRDF, with the errata of oren_nayar.h. */
#include "oren_nayar.h"

#include <float.h>

#include "lambert.h"

/* sigma^2 / (sigma^2 + c), the shape both coefficients share. sigma^2 is capped at
 * the largest double so that even an infinite sigma gives the limit 1, not inf / inf. */
static double roughness_ratio(double sigma, double c)
{
    double s2 = fmin(sigma * sigma, DBL_MAX);
    return s2 / (s2 + c);
}

/* Exercise 5.1, eq. 14: A with the "1 -" the report leaves out. */
double oren_nayar_a(double sigma) { return 1.0 - 0.5 * roughness_ratio(sigma, 0.33); }

/* Exercise 5.2, eq. 14: B. */
double oren_nayar_b(double sigma) { return 0.45 * roughness_ratio(sigma, 0.09); }

/* Exercise 5.3: eq. 13 divided by rho / pi, with sin(alpha) tan(beta) (not sin(beta)),
 * written as max(0, x_i x_o + y_i y_o) / max(z_i, z_o) (see oren_nayar.h). */
double oren_nayar_factor(double sigma, Vec3 wi, Vec3 wo)
{
    double a = oren_nayar_a(sigma);
    double cos_beta = fmax(0.0, fmax(wi.z, wo.z));
    if (cos_beta == 0.0)
        return a;
    double projected_dot = wi.x * wo.x + wi.y * wo.y;
    return a + oren_nayar_b(sigma) * fmax(0.0, projected_dot) / cos_beta;
}

/* Exercise 5.4, eq. 13: Lambert's rho / pi times the factor, so sigma = 0 is Lambert bit
 * for bit; reciprocal, as the factor is. */
Vec3 oren_nayar_brdf(Vec3 rho, double sigma, Vec3 wi, Vec3 wo)
{
    return vec3_scale(lambert_brdf(rho), oren_nayar_factor(sigma, wi, wo));
}
