/* plot.h (chapter 4): a log-log line plot, drawn with the project's own image code.
 *
 * Introduced in chapter 7, for its convergence plot (RMSE against seconds). On a
 * log-log plot an unbiased Monte Carlo estimator's error falls along a line of slope
 * -1/2 (error ~ 1/sqrt(samples) ~ 1/sqrt(time)); a better estimator is the same line
 * lower down, and a biased one flattens out at its bias.
 *
 * The axes span whole decades that contain every point; a grey line marks each decade,
 * black lines the axes themselves (the lowest decade of each).
 * Each series is a polyline in its colour with a dot at each point. The plot carries
 * no text: the caption beside it (figure.h) names the axes, their decades and the
 * series' colours.
 */
#ifndef PLOT_H
#define PLOT_H

#include "image.h"

typedef struct {
    const double *x, *y; /* points with a zero, negative or non-finite value are left out */
    int count;
    Vec3 colour;         /* linear RGB in [0, 1] */
} PlotSeries;

/* The plot on a width x height image (pixels NULL when memory runs out). The decades
 * spanned go to decades[] = {x_low, x_high, y_low, y_high}, as powers of ten. */
Image plot_log_log(const PlotSeries *series, int count, int width, int height, int decades[4]);

#endif
