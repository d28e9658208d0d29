/* fresnel.c (chapter 4): the exact Fresnel reflectance. See fresnel.h. */
#include "fresnel.h"

#include <math.h>

#include "snell.h"

typedef struct {
    double s, p;
} Polarised;

static double squared_ratio(double numerator, double denominator)
{
    double r = numerator / denominator;
    return r * r;
}

/* Exercise 4.1: R_s and R_p at one incidence: 1 and 1 for total internal reflection, 0
 * and 0 with no interface (n_i = n_t, where at grazing incidence both would be 0 / 0). */
static Polarised fresnel_polarised(double cos_i, double n_i, double n_t)
{
    Polarised r = {0.0, 0.0};
    if (n_i == n_t)
        return r;
    cos_i = fmin(1.0, fmax(0.0, cos_i));
    double cos_t = snell_cos_transmitted(cos_i, n_i, n_t);
    if (cos_t < 0.0) {
        r.s = r.p = 1.0;
        return r;
    }
    /* R_s: the formula the report labels R_p, eq. 4. */
    r.s = squared_ratio(n_i * cos_i - n_t * cos_t, n_i * cos_i + n_t * cos_t);
    /* R_p: the formula the report labels R_s, eq. 5. */
    r.p = squared_ratio(n_i * cos_t - n_t * cos_i, n_i * cos_t + n_t * cos_i);
    return r;
}

double fresnel_s(double cos_i, double n_i, double n_t)
{
    return fresnel_polarised(cos_i, n_i, n_t).s;
}

double fresnel_p(double cos_i, double n_i, double n_t)
{
    return fresnel_polarised(cos_i, n_i, n_t).p;
}

/* Exercise 4.2, eq. 3: unpolarised light is half s, half p. */
double fresnel_reflectance(double cos_i, double n_i, double n_t)
{
    Polarised r = fresnel_polarised(cos_i, n_i, n_t);
    return 0.5 * (r.s + r.p);
}

double fresnel_critical_angle(double n_i, double n_t)
{
    return n_i > n_t ? asin(n_t / n_i) : 0.5 * PI;
}
