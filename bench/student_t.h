/* student_t.h (bench, chapter 1): Student's t distribution, for a test whose standard
 * error is itself estimated from a few independent replicates.
 *
 * R independent, normally distributed estimates of one quantity (replicates: each a mean
 * of many samples), of mean m and sample standard deviation s, give
 *     T = (m - exact) / (s / sqrt(R)),
 * which follows Student's t with nu = R - 1 degrees of freedom when m's expectation is
 * exact. Its two-sided tail is the regularised incomplete beta function,
 *     P(|T| > t) = I_x(nu / 2, 1 / 2),   x = nu / (nu + t^2),
 * computed by its continued fraction (modified Lentz). Its tails are heavier than the
 * normal's: at 63 degrees of freedom the two-sided level 2.5e-7 needs |t| > 5.78 where
 * a z-test needs 5.16.
 *
 * The power: when m is off by a bias b, T = (Z + delta) / S with delta = b / (sigma /
 * sqrt(R)), Z standard normal and S = sqrt(chi^2_nu / nu) independent of it (the
 * noncentral t). The test detects the bias with probability
 *     P(T > t_crit) = E_S[Phi(delta - t_crit S)]
 * (the other side's share is negligible), integrated here over S's density. The shift
 * that gives a stated power is larger than t_crit + t_power, the shifted central t
 * that ignores that S scales with delta too: 8.38 against 8.17 at 63 degrees of freedom
 * and the course's level; 7.49 (the normal's) as nu grows.
 */
#ifndef STUDENT_T_H
#define STUDENT_T_H

/* P(|T| > t) for Student's t with `dof` >= 1 degrees of freedom. */
double student_t_tail(double t, int dof);

/* The t with P(|T| > t) = level (0 < level < 1). */
double student_t_critical(double level, int dof);

/* P(T' > critical) for the noncentral t T' of that shift (above). */
double student_t_power(double shift, double critical, int dof);

/* The shift, in standard errors, that a two-sided test at `level` detects with
 * probability `power`. */
double student_t_detectable(double level, double power, int dof);

#endif
