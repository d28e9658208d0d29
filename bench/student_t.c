/* student_t.c (bench, chapter 1): Student's t tail, its critical values and the shift a
 * test detects. See student_t.h. */
#include "student_t.h"

#include <math.h>

/* The continued fraction stops when a step changes it by less than this fraction, or
 * after this many steps (a few hundred suffice for thousands of degrees of freedom). */
#define BETA_EPSILON 1e-15
#define BETA_MAX_STEPS 100000
/* Stands in for 0 in a continued-fraction denominator. */
#define BETA_TINY 1e-300
/* The power's integral over S: this many midpoints, over 12 of S's standard deviations
 * (about 1 / sqrt(2 nu)) and more on either side of 1. */
#define POWER_STEPS 1024

/* The continued fraction's coefficient d_j of I_x(a, b):
 *     d_(2m+1) = -(a + m)(a + b + m) x / ((a + 2m)(a + 2m + 1)),
 *     d_(2m) = m (b - m) x / ((a + 2m - 1)(a + 2m)). */
static double beta_coefficient(double a, double b, double x, int j)
{
    int m = j / 2;
    if (j % 2)
        return -(a + m) * (a + b + m) * x / ((a + 2 * m) * (a + 2 * m + 1));
    return m * (b - m) * x / ((a + 2 * m - 1) * (a + 2 * m));
}

/* The regularised incomplete beta function by its continued fraction,
 *     I_x(a, b) = x^a y^b / (a B(a, b)) / (1 + d_1 / (1 + d_2 / (1 + ...))),   y = 1 - x,
 * the fraction evaluated front to back by the modified Lentz method (its value the
 * product of the ratios C_j D_j, with C_j = 1 + d_j / C_(j-1) and D_j = 1 / (1 + d_j
 * D_(j-1))); it converges fast for x < (a + 1) / (a + b + 2). y is passed apart, so that
 * a y near 0 keeps its digits. */
static double beta_continued_fraction(double a, double b, double x, double y)
{
    double fraction = 1.0, c = 1.0, d = 0.0;
    for (int j = 1; j < BETA_MAX_STEPS; j++) {
        double coefficient = beta_coefficient(a, b, x, j);
        c = 1.0 + coefficient / c;
        d = 1.0 + coefficient * d;
        c = fabs(c) < BETA_TINY ? BETA_TINY : c;
        d = 1.0 / (fabs(d) < BETA_TINY ? BETA_TINY : d);
        fraction *= c * d;
        if (fabs(c * d - 1.0) < BETA_EPSILON)
            break;
    }
    double log_front = a * log(x) + b * log(y) + lgamma(a + b) - lgamma(a) - lgamma(b);
    return exp(log_front) / (a * fraction);
}

/* I_x(a, b), y = 1 - x: the continued fraction where it converges fast, else through
 * I_x(a, b) = 1 - I_y(b, a). */
static double regularised_beta(double a, double b, double x, double y)
{
    if (x <= 0.0)
        return 0.0;
    if (y <= 0.0)
        return 1.0;
    if (x < (a + 1.0) / (a + b + 2.0))
        return beta_continued_fraction(a, b, x, y);
    return 1.0 - beta_continued_fraction(b, a, y, x);
}

double student_t_tail(double t, int dof)
{
    double t2 = t * t, nu = dof;
    if (isinf(t2))
        return 0.0;
    return regularised_beta(0.5 * nu, 0.5, nu / (nu + t2), t2 / (nu + t2));
}

double student_t_critical(double level, int dof)
{
    double low = 0.0, high = 1.0;
    while (student_t_tail(high, dof) > level)
        low = high, high *= 2.0;
    for (int i = 0; i < 200; i++) {
        double middle = 0.5 * (low + high);
        if (student_t_tail(middle, dof) > level)
            low = middle;
        else
            high = middle;
    }
    return 0.5 * (low + high);
}

/* The density of S = sqrt(chi^2_nu / nu) at s > 0:
 *     2 (nu / 2)^(nu / 2) / Gamma(nu / 2) s^(nu - 1) e^(-nu s^2 / 2). */
static double scale_density(double s, double nu)
{
    return exp(log(2.0) + 0.5 * nu * log(0.5 * nu) - lgamma(0.5 * nu) + (nu - 1.0) * log(s) -
               0.5 * nu * s * s);
}

double student_t_power(double shift, double critical, int dof)
{
    double nu = dof, reach = 12.0 / sqrt(nu);
    double low = fmax(0.0, 1.0 - reach), step = (1.0 + reach - low) / POWER_STEPS;
    double power = 0.0;
    for (int i = 0; i < POWER_STEPS; i++) {
        double s = low + (i + 0.5) * step;
        /* Phi(shift - critical s), the normal's distribution function */
        power += scale_density(s, nu) * 0.5 * erfc((critical * s - shift) / sqrt(2.0));
    }
    return power * step;
}

double student_t_detectable(double level, double power, int dof)
{
    double critical = student_t_critical(level, dof);
    double low = critical, high = critical + 1.0;
    while (student_t_power(high, critical, dof) < power)
        low = high, high += 1.0;
    for (int i = 0; i < 60; i++) {
        double middle = 0.5 * (low + high);
        if (student_t_power(middle, critical, dof) < power)
            low = middle;
        else
            high = middle;
    }
    return 0.5 * (low + high);
}
