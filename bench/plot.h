/* plot.h (bench, chapter 4): line plots with numbered axes, error bars and a legend, on linear
 * or log axes.
 *
 * Introduced in chapter 4, for the Fresnel reflectance curves (linear axes); chapter 7
 * adds log axes for its convergence plot (error against time). A presentation file:
 * the figures that say what a setting costs and buys. On a log-log plot an unbiased
 * Monte Carlo estimator of finite variance has its error fall along a line of slope
 * -1/2 (error ~ 1/sqrt(samples) ~ 1/sqrt(time)); a better estimator is the same line
 * lower down, a biased one flattens out at its bias. An estimator of infinite
 * variance (Russian roulette with alpha < rho^2, chapter 6) follows no such line: one
 * run's error is one draw of a heavy-tailed distribution. Its series are drawn dashed
 * with hollow markers and named "(infinite variance)" in the legend, so that they are
 * not read as measurements of a trend.
 *
 * The picture, on white: the data area framed in black, light grey grid lines at the
 * numbered ticks, each axis' title (x under its numbers, y above the data area), each
 * series as an anti-aliased polyline in its colour through its points in order, a
 * marker at each point if asked for, and a vertical error bar from y_low to y_high
 * (with short caps) at every point that has one; the legend in the data area's corner
 * that covers the fewest of the series' pixels.
 *
 * Axes. A range with low < high is shown as given. Otherwise it comes from the data
 * (every point and error bar end that can be drawn): on a log axis from the largest
 * value of the 1-2-5 sequence (..., 0.1, 0.2, 0.5, 1, 2, 5, 10, ...) at or below the
 * smallest value to the smallest one at or above the largest (one step either way when
 * they coincide; 1 to 10 with no data); on a linear axis from the multiples of the
 * tick spacing around the data (0 to 1 with no data). Numbered ticks on a log axis are
 * at the 1-2-5 values when their labels have room, else at decades (every decade, or
 * every 2nd, 3rd, 5th, 10th one, whichever first has room; then with unnumbered
 * ticks at 2 to 9 times each decade); on a linear axis at multiples of `tick`, or, if
 * that is 0, of the smallest 1-2-5 spacing whose labels have room.
 *
 * Points left out. A point is left out (counted in layout->left_out, and the polyline
 * joins its neighbours) when a coordinate is not finite, is <= 0 on a log axis, or
 * lies outside a given range (and, so that every range has finite ends, when it is
 * above 1e300 in size or, on a log axis, below 1e-300). There are at most
 * PLOT_MAX_TICKS numbered ticks per axis (a given spacing finer than that: the first
 * ones). An error bar end that is not finite is no bar; an end
 * <= 0 on a log axis, or beyond the range, is cut off at the frame.
 */
#ifndef PLOT_H
#define PLOT_H

#include "font.h"
#include "image.h"

typedef enum {
    PLOT_LINEAR,
    PLOT_LOG
} PlotScale;

typedef struct {
    const char *title; /* e.g. "time (s)"; NULL for none */
    PlotScale scale;
    double low, high; /* the range shown; low >= high (e.g. both 0): from the data */
    double tick;      /* linear axes: spacing of the numbered ticks; 0: chosen */
} PlotAxis;

typedef struct {
    const char *label;            /* its legend entry; NULL: not in the legend */
    const double *x, *y;          /* count points */
    const double *y_low, *y_high; /* point i's error bar, y_low[i] to y_high[i]; NULL: none */
    int count;
    Vec3 colour; /* linear RGB in [0, 1] */
    int markers; /* a dot at each point (else the line alone) */
    int dashed;
    int infinite_variance; /* dashed, hollow markers, "(infinite variance)" */
} PlotSeries;

typedef struct {
    PlotAxis x, y;
    const PlotSeries *series;
    int series_count;
    double text_size; /* pixels per em; 0: sqrt(width * height) / 32, within [10, 24] */
} Plot;

enum {
    PLOT_MAX_TICKS = 64
};

/* Where things were drawn, for a caption and for tests. Pixel coordinates are of
 * pixel centres (column, row; row 0 at the top). */
typedef struct {
    double x_low, x_high, y_low, y_high;                     /* the ranges shown */
    double left, right, top, bottom;                         /* the frame: data area's edges */
    double x_ticks[PLOT_MAX_TICKS], y_ticks[PLOT_MAX_TICKS]; /* numbered tick values */
    int x_tick_count, y_tick_count;
    int legend[4]; /* the legend's box: left, top, right, bottom
                      (exclusive); all 0 without a legend */
    int left_out;  /* points that could not be drawn */
} PlotLayout;

/* The plot on a width x height image (pixels NULL when memory runs out or a side is
 * not positive). `layout` may be NULL. */
Image plot_draw(const Plot *plot, const Font *font, int width, int height, PlotLayout *layout);

#endif
