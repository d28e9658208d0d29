/* chi_square.h (bench, chapter 1): Pearson's chi-square goodness-of-fit test, the tool that
 * checks a sampling routine against the density it claims to have.
 *
 * Introduced in chapter 2 (its tests check the cosine-weighted hemisphere; later the
 * area light). Draw N samples, count how many land in each of k bins (observed O_j), and
 * integrate the claimed density over each bin times N (expected E_j). Then
 *     X^2 = sum_j (O_j - E_j)^2 / E_j
 * follows, for large counts, the chi-square distribution with k - 1 degrees of freedom
 * (one fewer than bins, since the counts add up to N). The approximation needs E_j of
 * at least 5, so bins with fewer expected samples are merged with their neighbours in
 * the order given (pbrt and Mitsuba pool sparse cells likewise), and k counts the merged
 * groups. The p-value is the chance that a correct sampler gives a statistic at least
 * this large:
 *     p = Q(a, x),   a = (k - 1) / 2,   x = X^2 / 2,
 * Q the regularised upper incomplete gamma function, computed by its power series when
 * x < a + 1 and by its continued fraction otherwise (both converge fast there). A test
 * rejects the sampler when p is below its stated significance level, e.g. 0.01; a
 * correct sampler is then wrongly rejected in 1 run out of 100, which a fixed seed makes
 * either always or never.
 */
#ifndef CHI_SQUARE_H
#define CHI_SQUARE_H

/* Bins expecting fewer samples than this are merged with their neighbours. */
#define CHI_SQUARE_MIN_EXPECTED 5.0

/* X^2 for `bins` observed against expected counts, after merging bins (in order) until
 * each group expects at least CHI_SQUARE_MIN_EXPECTED; a remainder at the end joins
 * the last group. The degrees of freedom, groups - 1, go to *degrees_of_freedom.
 * A bin with observed samples where none are expected makes X^2 infinite: the sampler
 * produced something impossible. */
double chi_square_statistic(const double *observed, const double *expected, int bins,
                            int *degrees_of_freedom);

/* The probability that a chi-square variable with dof degrees of freedom is at least
 * `statistic`: Q(dof / 2, statistic / 2). 0 for an infinite or NaN statistic (the
 * sampler is broken), 1 when dof < 1 (nothing to test). */
double chi_square_p_value(double statistic, int dof);

#endif
