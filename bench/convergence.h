/* convergence.h (bench, chapter 7): error against time as the samples double, for the
 * convergence plot and what it says.
 *
 * A setting measured at doubling samples is a series of table rows. Its plot is the
 * RMSE (the runs' mean) against the time, log-log, each point with a bar of one standard
 * deviation of the runs either side, beside a guide of slope -1/2: the error of an
 * estimator of finite variance falls as 1 / sqrt(time). What it says: whether the error
 * fell at every doubling, and the series' log-log slope from its first row to its last.
 */
#ifndef CONVERGENCE_H
#define CONVERGENCE_H

#include "plot.h"
#include "table.h"

enum {
    CONVERGENCE_MAX_SERIES = 8,
    CONVERGENCE_MAX_STEPS = 16
};

/* The plot and the points it shows (the guide is the series after the settings'). */
typedef struct {
    double x[CONVERGENCE_MAX_SERIES + 1][CONVERGENCE_MAX_STEPS];
    double y[CONVERGENCE_MAX_SERIES + 1][CONVERGENCE_MAX_STEPS];
    double low[CONVERGENCE_MAX_SERIES][CONVERGENCE_MAX_STEPS];
    double high[CONVERGENCE_MAX_SERIES][CONVERGENCE_MAX_STEPS];
    PlotSeries series[CONVERGENCE_MAX_SERIES + 1];
    Plot plot;
} ConvergencePlot;

/* The plot of `count` settings of `steps` rows each, setting s's rows at rows[s * steps]
 * on, with their labels and colours: time (s) against RMSE, a setting dashed as of
 * infinite variance when its first row is; then the guide of slope -1/2 over the last
 * setting's times, from twice its first error, so that both lines show. Returns 0, or
 * -1 for more settings or steps than it holds. */
int convergence_plot(ConvergencePlot *plot, const TableRow *rows, int count, int steps,
                     const char *const *labels, const Vec3 *colours);

/* Whether the RMSE fell from each of the `steps` rows to the next. */
int convergence_falls(const TableRow *rows, int steps);

/* The log-log slope of the RMSE against the time from the first row to the last. */
double convergence_slope(const TableRow *rows, int steps);

#endif
