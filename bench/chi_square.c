/* chi_square.c (bench, chapter 1): Pearson's chi-square statistic and its p-value.
 * See chi_square.h. */
#include "chi_square.h"

#include <math.h>

/* Both expansions below stop when a step changes the result by less than this
 * fraction, or after this many steps (enough for thousands of degrees of freedom). */
#define GAMMA_EPSILON 1e-15
#define GAMMA_MAX_STEPS 100000
/* Stands in for 0 in a continued-fraction denominator. */
#define GAMMA_TINY 1e-300

/* One group's share of X^2. */
static double pearson_term(double observed, double expected)
{
    double d = observed - expected;
    return d * d / expected;
}

double chi_square_statistic(const double *observed, const double *expected, int bins,
                            int *degrees_of_freedom)
{
    double statistic = 0.0;
    int groups = 0;
    double o = 0.0, e = 0.0;           /* the group being filled */
    double last_o = 0.0, last_e = 0.0; /* the last full group; its term waits in case the
                                          remainder at the end has to join it */
    for (int j = 0; j < bins; j++) {
        if (expected[j] <= 0.0 && observed[j] > 0.0) {
            *degrees_of_freedom = bins - 1;
            return INFINITY;
        }
        o += observed[j];
        e += expected[j];
        if (e >= CHI_SQUARE_MIN_EXPECTED) {
            if (groups > 0)
                statistic += pearson_term(last_o, last_e);
            last_o = o;
            last_e = e;
            groups++;
            o = e = 0.0;
        }
    }
    last_o += o;
    last_e += e;
    if (last_e > 0.0)
        statistic += pearson_term(last_o, last_e);
    *degrees_of_freedom = groups > 0 ? groups - 1 : 0;
    return statistic;
}

/* e^-x x^a / Gamma(a), the factor both expansions share (in logarithms, as x^a and
 * Gamma(a) overflow long before their ratio does). */
static double gamma_prefactor(double a, double x) { return exp(a * log(x) - x - lgamma(a)); }

/* The regularised lower incomplete gamma function by its power series,
 *     P(a, x) = e^-x x^a / Gamma(a) * sum_{n >= 0} x^n / (a (a + 1) ... (a + n)),
 * whose terms shrink quickly once a + n > x. */
static double gamma_p_series(double a, double x)
{
    double term = 1.0 / a, sum = term;
    for (int n = 1; n < GAMMA_MAX_STEPS && term > sum * GAMMA_EPSILON; n++) {
        term *= x / (a + n);
        sum += term;
    }
    return gamma_prefactor(a, x) * sum;
}

/* The regularised upper incomplete gamma function by its continued fraction,
 *     Q(a, x) = e^-x x^a / Gamma(a) / g,
 *     g = b_0 + c_1 / (b_1 + c_2 / (b_2 + ...)),
 *     b_n = x + 1 - a + 2n,   c_n = -n (n - a),
 * evaluated front to back by the modified Lentz method: g is the product of the ratios
 * g_n / g_(n-1) = C_n D_n, with C_n and D_n updated by
 *     C_n = b_n + c_n / C_(n-1),   D_n = 1 / (b_n + c_n D_(n-1)),
 * converging fast when x > a + 1. */
static double gamma_q_continued_fraction(double a, double x)
{
    double b = x + 1.0 - a;
    double g = b, c = b, d = 0.0;
    for (int n = 1; n < GAMMA_MAX_STEPS; n++) {
        double c_n = -n * (n - a);
        b += 2.0;
        c = b + c_n / c;
        d = b + c_n * d;
        if (fabs(c) < GAMMA_TINY)
            c = GAMMA_TINY;
        if (fabs(d) < GAMMA_TINY)
            d = GAMMA_TINY;
        d = 1.0 / d;
        double ratio = c * d;
        g *= ratio;
        if (fabs(ratio - 1.0) < GAMMA_EPSILON)
            break;
    }
    return gamma_prefactor(a, x) / g;
}

double chi_square_p_value(double statistic, int dof)
{
    if (!(statistic < INFINITY))
        return 0.0;
    if (dof < 1 || statistic <= 0.0)
        return 1.0;
    double a = 0.5 * dof, x = 0.5 * statistic;
    return x < a + 1.0 ? 1.0 - gamma_p_series(a, x) : gamma_q_continued_fraction(a, x);
}
