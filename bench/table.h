/* table.h (bench, chapter 1): one row per rendered panel: what it cost and what it bought.
 *
 * Introduced in chapter 1 (cost columns); chapter 2 fills the error columns from a
 * reference image (measure.h). Printed as an aligned table on stdout and written as a
 * CSV beside the figure. Columns:
 *   panel, settings    which panel and its settings
 *   spp                samples per pixel actually taken
 *   seconds, threads   wall-clock time of the render, and threads used
 *   camera/bounce/shadow rays, Mrays/s   rays traced and their rate
 *   rmse               root mean square error against the reference, over all pixels
 *                      and channels
 *   rel_mse            mean over pixels and channels of (x - ref)^2 / (ref^2 + 0.01)
 *   efficiency         1 / (rel_mse * seconds): higher is better; doubling the samples
 *                      of an unbiased estimator halves rel_mse and doubles the time, so
 *                      efficiency compares estimators independently of sample count
 *   nonfinite          samples dropped for being NaN or infinite
 * An error column is "-" (empty in the CSV) when no reference was used, and "<ref" when
 * the error is within the reference's own noise: measure.h takes that noise out of the
 * squared error, and what is left is then not above 0 (the CSV keeps the estimate, which
 * may be negative, for means over many rows).
 */
#ifndef TABLE_H
#define TABLE_H

#include <stdio.h>

#include "stats.h"

/* What the table prints for an error within the reference's own noise. */
#define TABLE_WITHIN_REFERENCE_NOISE "<ref"

typedef struct {
    char panel[48];
    char settings[96];
    double spp;
    double seconds;
    int threads;
    RayCounts rays;
    double rmse, rel_mse, efficiency; /* NaN when not measured */
    unsigned long long nonfinite;
    /* Measured over several independent runs (chapter 2 on): rmse and rel_mse are then
     * the means over the runs, seconds the mean time of one run, and efficiency
     * 1 / (mean rel_mse x mean seconds). */
    int runs;               /* 0 or 1: a single run */
    double rmse_spread;     /* standard deviation of the runs' RMSE; NaN for one */
    double rel_mse_spread;  /* and of their relative MSE */
    double reference_share; /* of the raw MSE, what the reference's noise makes */
    int infinite_variance;  /* the estimator's variance is infinite: its error
                               cannot be pinned down by any number of runs */
} TableRow;

/* Printed under a table that has a row marked infinite_variance. */
#define TABLE_INFINITE_VARIANCE_NOTE                                                           \
    "inf-var: roulette with alpha <= rho^2 has infinite variance (chapter 6): its error "      \
    "over runs does not settle, so it cannot be pinned down or ranked."

void table_print(FILE *out, const TableRow *rows, int count);

/* Write the rows as CSV through an atomic file. Returns 0, or -1 with errno set. */
int table_write_csv(const char *path, const TableRow *rows, int count);

/* A table of numbers as CSV through an atomic file: the header line, then `rows` lines of
 * `columns` values (values[r * columns + c]), column c with decimals[c] decimals.
 * Returns 0, or -1 with errno set. */
int table_write_numbers_csv(const char *path, const char *header, const double *values,
                            int rows, int columns, const int *decimals);

/* Mrays/s of a row. */
double table_mrays_per_second(const TableRow *row);

#endif
