/* convergence.c (bench, chapter 7): the convergence plot and what it says. See
 * convergence.h. */
#include "convergence.h"

#include <math.h>

int convergence_plot(ConvergencePlot *p, const TableRow *rows, int count, int steps,
                     const char *const *labels, const Vec3 *colours)
{
    if (count < 1 || count > CONVERGENCE_MAX_SERIES || steps < 1 ||
        steps > CONVERGENCE_MAX_STEPS)
        return -1;
    for (int s = 0; s < count; s++) {
        const TableRow *series = &rows[s * steps];
        for (int k = 0; k < steps; k++) {
            double spread = isnan(series[k].rmse_spread) ? 0.0 : series[k].rmse_spread;
            p->x[s][k] = series[k].seconds;
            p->y[s][k] = series[k].rmse;
            p->low[s][k] = series[k].rmse - spread;
            p->high[s][k] = series[k].rmse + spread;
        }
        p->series[s] = (PlotSeries){.label = labels[s],
                                    .x = p->x[s],
                                    .y = p->y[s],
                                    .y_low = p->low[s],
                                    .y_high = p->high[s],
                                    .count = steps,
                                    .colour = colours[s],
                                    .markers = 1,
                                    .infinite_variance = series[0].infinite_variance};
    }
    const double *x = p->x[count - 1], *y = p->y[count - 1];
    p->x[count][0] = x[0];
    p->x[count][1] = x[steps - 1];
    p->y[count][0] = 2.0 * y[0];
    p->y[count][1] = 2.0 * y[0] * sqrt(x[0] / x[steps - 1]);
    p->series[count] = (PlotSeries){.label = "slope -1/2",
                                    .x = p->x[count],
                                    .y = p->y[count],
                                    .count = 2,
                                    .colour = {0.45, 0.45, 0.45},
                                    .dashed = 1};
    p->plot = (Plot){{"time (s)", PLOT_LOG, 0.0, 0.0, 0.0},
                     {"RMSE", PLOT_LOG, 0.0, 0.0, 0.0},
                     p->series,
                     count + 1,
                     0.0};
    return 0;
}

int convergence_falls(const TableRow *rows, int steps)
{
    for (int k = 1; k < steps; k++)
        if (!(rows[k].rmse < rows[k - 1].rmse))
            return 0;
    return 1;
}

double convergence_slope(const TableRow *rows, int steps)
{
    return log(rows[steps - 1].rmse / rows[0].rmse) /
           log(rows[steps - 1].seconds / rows[0].seconds);
}
