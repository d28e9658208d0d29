/* plot.c (chapter 4): drawing the log-log plot. See plot.h. */
#include "plot.h"

#define MARGIN 12

/* A square dot of half-size `radius` at (x, y), clipped to the image. */
static void dot(Image *image, double x, double y, int radius, Vec3 colour)
{
    for (int row = (int)y - radius; row <= (int)y + radius; row++)
        for (int col = (int)x - radius; col <= (int)x + radius; col++)
            if (col >= 0 && row >= 0 && col < image->width && row < image->height)
                image_set(image, col, row, colour);
}

/* A line from (x0, y0) to (x1, y1), two pixels thick, by stepping one pixel at a time
 * along its longer extent. */
static void line(Image *image, double x0, double y0, double x1, double y1, Vec3 colour)
{
    int steps = (int)ceil(fmax(fabs(x1 - x0), fabs(y1 - y0))) + 1;
    for (int i = 0; i <= steps; i++) {
        double f = (double)i / steps;
        dot(image, x0 + f * (x1 - x0), y0 + f * (y1 - y0), 1, colour);
    }
}

/* Whether a point can be drawn on log axes: both coordinates positive and finite
 * (a perfect RMSE of 0, say, cannot). Others are left out. */
static int drawable(double x, double y)
{
    return x > 0.0 && y > 0.0 && isfinite(x) && isfinite(y);
}

Image plot_log_log(const PlotSeries *series, int count, int width, int height, int decades[4])
{
    double low[2] = {INFINITY, INFINITY}, high[2] = {-INFINITY, -INFINITY};
    for (int s = 0; s < count; s++)
        for (int i = 0; i < series[s].count; i++) {
            if (!drawable(series[s].x[i], series[s].y[i]))
                continue;
            double v[2] = {log10(series[s].x[i]), log10(series[s].y[i])};
            for (int axis = 0; axis < 2; axis++) {
                low[axis] = fmin(low[axis], v[axis]);
                high[axis] = fmax(high[axis], v[axis]);
            }
        }
    for (int axis = 0; axis < 2; axis++) {
        decades[2 * axis] = isfinite(low[axis]) ? (int)floor(low[axis]) : 0;
        decades[2 * axis + 1] = isfinite(high[axis]) ? (int)ceil(high[axis]) : 1;
        if (decades[2 * axis + 1] == decades[2 * axis])
            decades[2 * axis + 1]++;
    }
    Image image = image_new(width, height);
    if (!image.pixels)
        return image;
    for (long i = 0; i < 3L * width * height; i++)
        image.pixels[i] = 1.0f;
    double plot_width = width - 2 * MARGIN, plot_height = height - 2 * MARGIN;
    double x_span = decades[1] - decades[0], y_span = decades[3] - decades[2];
    Vec3 grey = vec3(0.7, 0.7, 0.7), black = vec3(0, 0, 0);
    for (int d = 0; d <= (int)x_span; d++) {
        double x = MARGIN + plot_width * d / x_span;
        line(&image, x, MARGIN, x, height - MARGIN, d == 0 ? black : grey);
    }
    for (int d = 0; d <= (int)y_span; d++) {
        double y = height - MARGIN - plot_height * d / y_span;
        line(&image, MARGIN, y, width - MARGIN, y, d == 0 ? black : grey);
    }
    for (int s = 0; s < count; s++) {
        double previous_x = 0, previous_y = 0;
        int drawn = 0;
        for (int i = 0; i < series[s].count; i++) {
            if (!drawable(series[s].x[i], series[s].y[i]))
                continue;
            double x = MARGIN + plot_width * (log10(series[s].x[i]) - decades[0]) / x_span;
            double y = height - MARGIN - plot_height * (log10(series[s].y[i]) - decades[2]) / y_span;
            if (drawn++ > 0)
                line(&image, previous_x, previous_y, x, y, series[s].colour);
            dot(&image, x, y, 3, series[s].colour);
            previous_x = x;
            previous_y = y;
        }
    }
    return image;
}
