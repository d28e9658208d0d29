/* plot.c (bench, chapter 4): drawing the line plots. Log axes come in chapter 7. See plot.h.
 *
 * Lines, markers and error bars are anti-aliased the simplest way: a pixel's coverage
 * is how far its centre lies inside the shape's edge, clamped to [0, 1] (for a line of
 * width w at distance d from the segment, w / 2 + 1/2 - d), and it is blended as the
 * text is (font.h). The layout is computed from the font's sizes: first the rows (the
 * titles and the x axis' numbers), then the y axis' ticks and so the width of its
 * numbers, then the x axis' ticks.
 */
#include "plot.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const Vec3 WHITE = {1, 1, 1}, BLACK = {0, 0, 0};
static const Vec3 GRID = {0.75, 0.75, 0.75}, LEGEND_BORDER = {0.5, 0.5, 0.5};
static const double DASH_PERIOD = 10.0, DASH_ON = 6.0; /* pixels along the line */

typedef struct {
    int left, top, right, bottom; /* right and bottom exclusive */
} Box;

/* One axis as drawn: its range, its numbered ticks, and whether log decades get
 * unnumbered ticks at 2 to 9 times each. */
typedef struct {
    PlotScale scale;
    double low, high, step; /* step: linear tick spacing */
    double ticks[PLOT_MAX_TICKS];
    int tick_count, minor_ticks;
} Axis;

/* ---- values and their place on an axis ---- */

/* Finite and at most 1e300 in size, and on a log axis at least 1e-300 (so that the
 * 1-2-5 values around it are finite and non-zero too). */
static int drawable(PlotScale scale, double v)
{
    return isfinite(v) && fabs(v) <= 1e300 && (scale == PLOT_LINEAR || v >= 1e-300);
}

static int range_given(const PlotAxis *axis)
{
    return axis->low < axis->high && drawable(axis->scale, axis->low) &&
           drawable(axis->scale, axis->high);
}

/* Whether v is drawable and within the axis' given range (if any), allowing for
 * rounding at the range's ends. */
static int within(const PlotAxis *axis, double v)
{
    if (!drawable(axis->scale, v))
        return 0;
    if (!range_given(axis))
        return 1;
    double slack = 1e-9 * (axis->high - axis->low);
    return v >= axis->low - slack && v <= axis->high + slack;
}

static int point_shown(const Plot *plot, const PlotSeries *series, int i)
{
    return within(&plot->x, series->x[i]) && within(&plot->y, series->y[i]);
}

/* Where v lies on the axis: 0 at its low end, 1 at its high end. */
static double fraction(const Axis *axis, double v)
{
    if (axis->scale == PLOT_LOG)
        return (log10(v) - log10(axis->low)) / (log10(axis->high) - log10(axis->low));
    return (v - axis->low) / (axis->high - axis->low);
}

/* The smallest and largest values of the shown points (for y, their error bars' ends
 * too), or 0 when there are none. */
static int data_extent(const Plot *plot, int vertical, double *min, double *max)
{
    const PlotAxis *axis = vertical ? &plot->y : &plot->x;
    *min = INFINITY;
    *max = -INFINITY;
    for (int s = 0; s < plot->series_count; s++) {
        const PlotSeries *series = &plot->series[s];
        for (int i = 0; i < series->count; i++) {
            if (!point_shown(plot, series, i))
                continue;
            double v[3] = {vertical ? series->y[i] : series->x[i], NAN, NAN};
            if (vertical && series->y_low && series->y_high) {
                v[1] = series->y_low[i];
                v[2] = series->y_high[i];
            }
            for (int k = 0; k < 3; k++)
                if (within(axis, v[k])) {
                    *min = fmin(*min, v[k]);
                    *max = fmax(*max, v[k]);
                }
        }
    }
    return *min <= *max;
}

/* ---- ranges and ticks ---- */

/* The 1-2-5 sequence: value n is (1, 2 or 5 for n mod 3 = 0, 1, 2) * 10^floor(n / 3). */
static double one_two_five(int n)
{
    int decade = n >= 0 ? n / 3 : -((2 - n) / 3);
    int m = n - 3 * decade;
    return (m == 0 ? 1.0 : m == 1 ? 2.0 : 5.0) * pow(10.0, decade);
}

static int one_two_five_at_or_below(double v)
{
    int n = 3 * (int)floor(log10(v)) + 2;
    while (one_two_five(n) > v * (1 + 1e-9))
        n--;
    return n;
}

static int one_two_five_at_or_above(double v)
{
    int n = 3 * (int)floor(log10(v));
    while (one_two_five(n) < v * (1 - 1e-9))
        n++;
    return n;
}

/* The number's text: on a log axis plain decimals from 0.0001 to 100000, else like
 * "2e-6"; on a linear axis with as many decimals as the tick spacing needs. */
static void tick_label(const Axis *axis, double v, char *text, size_t size)
{
    if (axis->scale == PLOT_LOG) {
        int decade = (int)floor(log10(v) + 1e-9);
        if (decade >= -4 && decade <= 5)
            snprintf(text, size, "%.*f", decade < 0 ? -decade : 0, v);
        else
            snprintf(text, size, "%.0fe%d", v / pow(10.0, decade), decade);
        return;
    }
    int decimals = 0;
    for (double scaled = axis->step;
         decimals < 9 && fabs(scaled - round(scaled)) > 1e-6 * scaled; scaled *= 10.0)
        decimals++;
    snprintf(text, size, "%.*f", decimals, fabs(v) < 1e-9 * axis->step ? 0.0 : v);
}

typedef struct {
    const Font *font;
    double size, pixels; /* text size; the axis' length in pixels */
    int vertical;
} TickRoom;

/* Whether the axis' numbers fit: neighbouring ticks are far enough apart for their
 * labels (widths plus an em across, 1.3 lines up). */
static int labels_fit(const Axis *axis, const TickRoom *room)
{
    if (axis->tick_count < 2)
        return 0;
    double previous_extent = 0.0;
    for (int i = 0; i < axis->tick_count; i++) {
        char text[32];
        tick_label(axis, axis->ticks[i], text, sizeof text);
        double extent =
            room->vertical
                ? 1.3 * font_line_height(room->font, room->size)
                : font_width(room->font, text, strlen(text), room->size) + room->size;
        if (i > 0) {
            double gap = room->pixels *
                         (fraction(axis, axis->ticks[i]) - fraction(axis, axis->ticks[i - 1]));
            if (gap < 0.5 * (extent + previous_extent))
                return 0;
        }
        previous_extent = extent;
    }
    return 1;
}

/* Log ticks: every 1-2-5 value in range (every_decades 0), or the decades whose
 * exponent is a multiple of every_decades. Keeps the first PLOT_MAX_TICKS and returns
 * how many there are. */
static int log_ticks(Axis *axis, int every_decades)
{
    int total = 0;
    axis->minor_ticks = every_decades > 0;
    int first = one_two_five_at_or_above(axis->low),
        last = one_two_five_at_or_below(axis->high);
    for (int n = first; n <= last; n++) {
        int decade = n >= 0 ? n / 3 : -((2 - n) / 3);
        if (every_decades == 0 || (n - 3 * decade == 0 && decade % every_decades == 0)) {
            if (total < PLOT_MAX_TICKS)
                axis->ticks[total] = one_two_five(n);
            total++;
        }
    }
    axis->tick_count = total < PLOT_MAX_TICKS ? total : PLOT_MAX_TICKS;
    return total;
}

static void choose_log_axis(const PlotAxis *given, int have_data, double min, double max,
                            const TickRoom *room, Axis *axis)
{
    if (range_given(given)) {
        axis->low = given->low;
        axis->high = given->high;
    } else if (have_data) {
        int low = one_two_five_at_or_below(min), high = one_two_five_at_or_above(max);
        if (low == high) {
            low--;
            high++;
        }
        axis->low = one_two_five(low);
        axis->high = one_two_five(high);
    } else {
        axis->low = 1.0;
        axis->high = 10.0;
    }
    static const int EVERY[] = {0, 1, 2, 3, 5, 10, 20, 50};
    int best = 0; /* the sparsest whole set with two ticks, if none fits */
    for (size_t k = 0; k < sizeof EVERY / sizeof EVERY[0]; k++) {
        int total = log_ticks(axis, EVERY[k]);
        if (total <= PLOT_MAX_TICKS && labels_fit(axis, room))
            return;
        if (total >= 2 && total <= PLOT_MAX_TICKS)
            best = EVERY[k];
    }
    log_ticks(axis, best);
}

/* Linear ticks at the multiples of the step within the range. Keeps the first
 * PLOT_MAX_TICKS and returns how many there are. */
static double linear_ticks(Axis *axis)
{
    axis->minor_ticks = 0;
    double first = ceil(axis->low / axis->step - 1e-9);
    double total = floor(axis->high / axis->step + 1e-9) - first + 1;
    axis->tick_count = total < PLOT_MAX_TICKS ? (int)total : PLOT_MAX_TICKS;
    for (int i = 0; i < axis->tick_count; i++)
        axis->ticks[i] = (first + i) * axis->step;
    return total;
}

/* The range for one step: as given, or the step's multiples around the data. */
static void linear_range(const PlotAxis *given, double min, double max, Axis *axis)
{
    if (range_given(given)) {
        axis->low = given->low;
        axis->high = given->high;
        return;
    }
    axis->low = floor(min / axis->step + 1e-9) * axis->step;
    axis->high = ceil(max / axis->step - 1e-9) * axis->step;
    if (axis->high <= axis->low)
        axis->high = axis->low + axis->step;
}

static void choose_linear_axis(const PlotAxis *given, int have_data, double min, double max,
                               const TickRoom *room, Axis *axis)
{
    if (!have_data) {
        min = 0.0;
        max = 1.0;
    }
    if (given->tick > 0.0) {
        axis->step = given->tick;
        linear_range(given, min, max, axis);
        linear_ticks(axis);
        return;
    }
    double span = range_given(given) ? given->high - given->low
                  : max > min        ? max - min
                  : min != 0.0       ? fabs(min)
                                     : 1.0;
    for (int n = one_two_five_at_or_below(span / 100.0);; n++) {
        axis->step = one_two_five(n);
        linear_range(given, min, max, axis);
        double total = linear_ticks(axis);
        if ((total <= PLOT_MAX_TICKS && labels_fit(axis, room)) || axis->step >= span)
            return;
    }
}

static void choose_axis(const Plot *plot, int vertical, const TickRoom *room, Axis *axis)
{
    const PlotAxis *given = vertical ? &plot->y : &plot->x;
    double min, max;
    int have_data = data_extent(plot, vertical, &min, &max);
    axis->scale = given->scale;
    axis->step = 0.0;
    if (given->scale == PLOT_LOG)
        choose_log_axis(given, have_data, min, max, room, axis);
    else
        choose_linear_axis(given, have_data, min, max, room, axis);
}

/* ---- drawing ---- */

static Box clip_to_image(Box box, const Image *image)
{
    Box clipped = {box.left > 0 ? box.left : 0, box.top > 0 ? box.top : 0,
                   box.right < image->width ? box.right : image->width,
                   box.bottom < image->height ? box.bottom : image->height};
    return clipped;
}

static void fill(Image *image, Box box, Vec3 colour)
{
    box = clip_to_image(box, image);
    for (int row = box.top; row < box.bottom; row++)
        for (int col = box.left; col < box.right; col++)
            image_set(image, col, row, colour);
}

/* A line of `width` pixels from (x0, y0) to (x1, y1) with round ends, drawn inside
 * `clip`; dashed, it is on where its distance along the polyline, starting at
 * `phase`, is within DASH_ON of a multiple of DASH_PERIOD. */
static void stroke(Image *image, Box clip, double x0, double y0, double x1, double y1,
                   double width, Vec3 colour, int dashed, double phase)
{
    double dx = x1 - x0, dy = y1 - y0, length2 = dx * dx + dy * dy, r = 0.5 * width;
    Box box = {(int)floor(fmin(x0, x1) - r - 1), (int)floor(fmin(y0, y1) - r - 1),
               (int)ceil(fmax(x0, x1) + r + 2), (int)ceil(fmax(y0, y1) + r + 2)};
    box = clip_to_image(box, image);
    box.left = box.left > clip.left ? box.left : clip.left;
    box.top = box.top > clip.top ? box.top : clip.top;
    box.right = box.right < clip.right ? box.right : clip.right;
    box.bottom = box.bottom < clip.bottom ? box.bottom : clip.bottom;
    for (int row = box.top; row < box.bottom; row++)
        for (int col = box.left; col < box.right; col++) {
            double t = length2 > 0.0 ? ((col - x0) * dx + (row - y0) * dy) / length2 : 0.0;
            t = t < 0.0 ? 0.0 : t > 1.0 ? 1.0 : t;
            double d = hypot(col - (x0 + t * dx), row - (y0 + t * dy));
            double a = fmin(1.0, r + 0.5 - d);
            if (a <= 0.0 || (dashed && fmod(phase + t * sqrt(length2), DASH_PERIOD) >= DASH_ON))
                continue;
            font_blend(image, col, row, colour, a);
        }
}

/* A disc of radius r at (x, y), or with `hollow` a white disc inside a ring of width
 * `ring`. */
static void marker(Image *image, Box clip, double x, double y, double r, double ring,
                   Vec3 colour, int hollow)
{
    stroke(image, clip, x, y, x, y, 2.0 * r, hollow ? WHITE : colour, 0, 0.0);
    if (!hollow)
        return;
    Box box = {(int)floor(x - r - 1), (int)floor(y - r - 1), (int)ceil(x + r + 2),
               (int)ceil(y + r + 2)};
    box = clip_to_image(box, image);
    for (int row = box.top; row < box.bottom; row++)
        for (int col = box.left; col < box.right; col++) {
            double d = fabs(hypot(col - x, row - y) - (r - 0.5 * ring));
            double a = fmin(1.0, 0.5 * ring + 0.5 - d);
            if (a > 0.0 && col >= clip.left && col < clip.right && row >= clip.top &&
                row < clip.bottom)
                font_blend(image, col, row, colour, a);
        }
}

/* Sizes of everything, from the text size. */
typedef struct {
    const Font *font;
    double size, line, ascent, pad;  /* text size, line pitch, ascent, padding (em / 2) */
    double line_width, marker, tick; /* pixels */
    Box clip;                        /* where series may draw: the frame and a margin */
} Style;

static double pixel_x(const Axis *axis, const PlotLayout *layout, double v)
{
    return layout->left + fraction(axis, v) * (layout->right - layout->left);
}

static double pixel_y(const Axis *axis, const PlotLayout *layout, double v)
{
    return layout->bottom - fraction(axis, v) * (layout->bottom - layout->top);
}

static void draw_text(Image *image, const Style *style, const char *text, double x, double top)
{
    font_draw(image, style->font, text, strlen(text), x, top + style->ascent, style->size,
              BLACK);
}

static double text_width(const Style *style, const char *text)
{
    return font_width(style->font, text, strlen(text), style->size);
}

/* Grid lines and tick marks (outside the frame), numbers, minor ticks on log decades. */
static void draw_ticks(Image *image, const Style *style, const Axis *axis,
                       const PlotLayout *layout, int vertical)
{
    for (int i = 0; i < axis->tick_count; i++) {
        char text[32];
        tick_label(axis, axis->ticks[i], text, sizeof text);
        double width = text_width(style, text);
        if (vertical) {
            int y = (int)lround(pixel_y(axis, layout, axis->ticks[i]));
            fill(image, (Box){(int)layout->left + 1, y, (int)layout->right, y + 1}, GRID);
            fill(image, (Box){(int)(layout->left - style->tick), y, (int)layout->left, y + 1},
                 BLACK);
            draw_text(image, style, text,
                      layout->left - style->tick - 0.3 * style->size - width,
                      y - 0.5 * style->line);
        } else {
            int x = (int)lround(pixel_x(axis, layout, axis->ticks[i]));
            fill(image, (Box){x, (int)layout->top, x + 1, (int)layout->bottom}, GRID);
            fill(image,
                 (Box){x, (int)layout->bottom + 1, x + 1,
                       (int)(layout->bottom + 1 + style->tick)},
                 BLACK);
            draw_text(image, style, text, x - 0.5 * width,
                      layout->bottom + style->tick + 0.2 * style->pad);
        }
    }
    if (!axis->minor_ticks)
        return;
    for (double decade = pow(10.0, floor(log10(axis->low))); decade < axis->high;
         decade *= 10.0)
        for (int m = 2; m <= 9; m++) {
            double v = m * decade;
            if (v < axis->low || v > axis->high)
                continue;
            double half = 0.5 * style->tick;
            if (vertical) {
                int y = (int)lround(pixel_y(axis, layout, v));
                fill(image, (Box){(int)(layout->left - half), y, (int)layout->left, y + 1},
                     BLACK);
            } else {
                int x = (int)lround(pixel_x(axis, layout, v));
                fill(image,
                     (Box){x, (int)layout->bottom + 1, x + 1, (int)(layout->bottom + 1 + half)},
                     BLACK);
            }
        }
}

static void draw_frame(Image *image, const PlotLayout *layout)
{
    int left = (int)layout->left, right = (int)layout->right;
    int top = (int)layout->top, bottom = (int)layout->bottom;
    fill(image, (Box){left, top, right + 1, top + 1}, BLACK);
    fill(image, (Box){left, bottom, right + 1, bottom + 1}, BLACK);
    fill(image, (Box){left, top, left + 1, bottom + 1}, BLACK);
    fill(image, (Box){right, top, right + 1, bottom + 1}, BLACK);
}

/* One series: error bars, then the polyline through its shown points, then markers. */
static void draw_series(Image *image, const Style *style, const Plot *plot,
                        const PlotSeries *series, const Axis *x_axis, const Axis *y_axis,
                        const PlotLayout *layout)
{
    int dashed = series->dashed || series->infinite_variance;
    double previous_x = 0.0, previous_y = 0.0, phase = 0.0;
    int drawn = 0;
    for (int i = 0; i < series->count; i++) {
        if (!point_shown(plot, series, i))
            continue;
        double x = pixel_x(x_axis, layout, series->x[i]),
               y = pixel_y(y_axis, layout, series->y[i]);
        if (series->y_low && series->y_high && isfinite(series->y_low[i]) &&
            isfinite(series->y_high[i])) {
            double low = series->y_low[i], high = series->y_high[i];
            double y_low =
                drawable(y_axis->scale, low) ? pixel_y(y_axis, layout, low) : layout->bottom;
            double y_high =
                drawable(y_axis->scale, high) ? pixel_y(y_axis, layout, high) : layout->bottom;
            y_low = fmax(layout->top, fmin(layout->bottom, y_low));
            y_high = fmax(layout->top, fmin(layout->bottom, y_high));
            double cap = style->marker, bar = style->line_width;
            stroke(image, style->clip, x, y_low, x, y_high, bar, series->colour, 0, 0.0);
            stroke(image, style->clip, x - cap, y_low, x + cap, y_low, bar, series->colour, 0,
                   0.0);
            stroke(image, style->clip, x - cap, y_high, x + cap, y_high, bar, series->colour, 0,
                   0.0);
        }
        if (drawn++ > 0) {
            stroke(image, style->clip, previous_x, previous_y, x, y, style->line_width,
                   series->colour, dashed, phase);
            phase += hypot(x - previous_x, y - previous_y);
        }
        previous_x = x;
        previous_y = y;
    }
    if (!series->markers)
        return;
    for (int i = 0; i < series->count; i++)
        if (point_shown(plot, series, i))
            marker(image, style->clip, pixel_x(x_axis, layout, series->x[i]),
                   pixel_y(y_axis, layout, series->y[i]), style->marker, style->line_width,
                   series->colour, series->infinite_variance);
}

/* A legend entry's text: the label, and for infinite variance the note. */
static void legend_text(const PlotSeries *series, char *text, size_t size)
{
    snprintf(text, size, "%s%s", series->label,
             series->infinite_variance ? " (infinite variance)" : "");
}

/* The number of pixels in `box` that differ from `before`. */
static long changed_pixels(const Image *image, const Image *before, Box box)
{
    box = clip_to_image(box, image);
    long changed = 0;
    for (int row = box.top; row < box.bottom; row++)
        for (int col = box.left; col < box.right; col++) {
            long i = 3 * ((long)row * image->width + col);
            changed += memcmp(image->pixels + i, before->pixels + i, 3 * sizeof(float)) != 0;
        }
    return changed;
}

/* The legend box in the frame's corner where the series drew least (ties: top right,
 * top left, bottom right, bottom left), then its entries: a sample of each series'
 * line and marker, and its text. */
static void draw_legend(Image *image, const Image *before, const Style *style, const Plot *plot,
                        PlotLayout *layout)
{
    double text_width_max = 0.0;
    int entries = 0;
    for (int s = 0; s < plot->series_count; s++) {
        if (!plot->series[s].label)
            continue;
        char text[256];
        legend_text(&plot->series[s], text, sizeof text);
        text_width_max = fmax(text_width_max, text_width(style, text));
        entries++;
    }
    if (entries == 0)
        return;
    double sample = 2.0 * style->size;
    int width = (int)ceil(3.0 * style->pad + sample + text_width_max + style->pad);
    int height = (int)ceil(entries * style->line + 2.0 * style->pad);
    int inset = (int)ceil(style->pad);
    int left[2] = {(int)layout->right - inset - width, (int)layout->left + inset + 1};
    int top[2] = {(int)layout->top + inset + 1, (int)layout->bottom - inset - height};
    Box best = {0, 0, 0, 0};
    long fewest = -1;
    for (int corner = 0; corner < 4; corner++) {
        Box box = {left[corner % 2], top[corner / 2], left[corner % 2] + width,
                   top[corner / 2] + height};
        long changed = changed_pixels(image, before, box);
        if (fewest < 0 || changed < fewest) {
            fewest = changed;
            best = box;
        }
    }
    fill(image, best, LEGEND_BORDER);
    fill(image, (Box){best.left + 1, best.top + 1, best.right - 1, best.bottom - 1}, WHITE);
    Box clip = clip_to_image(best, image);
    double row_top = best.top + style->pad;
    for (int s = 0; s < plot->series_count; s++) {
        const PlotSeries *series = &plot->series[s];
        if (!series->label)
            continue;
        double x0 = best.left + style->pad, y = row_top + 0.5 * style->line;
        stroke(image, clip, x0, y, x0 + sample, y, style->line_width, series->colour,
               series->dashed || series->infinite_variance, 0.0);
        if (series->markers)
            marker(image, clip, x0 + 0.5 * sample, y, style->marker, style->line_width,
                   series->colour, series->infinite_variance);
        char text[256];
        legend_text(series, text, sizeof text);
        draw_text(image, style, text, x0 + sample + style->pad, row_top);
        row_top += style->line;
    }
    layout->legend[0] = best.left;
    layout->legend[1] = best.top;
    layout->legend[2] = best.right;
    layout->legend[3] = best.bottom;
}

static Style style_for(const Plot *plot, const Font *font, int width, int height)
{
    Style style;
    double size =
        plot->text_size > 0.0 ? plot->text_size : round(sqrt((double)width * height) / 32.0);
    style.font = font;
    style.size = plot->text_size > 0.0 ? size : fmin(24.0, fmax(10.0, size));
    style.line = ceil(font_line_height(font, style.size));
    style.ascent = font_ascent(font, style.size);
    style.pad = 0.5 * style.size;
    style.line_width = fmax(2.0, style.size / 8.0);
    style.marker = fmax(4.0, 0.3 * style.size);
    style.tick = 0.35 * style.size;
    return style;
}

/* The frame's rows from the text; the y axis' ticks, hence its numbers' width and the
 * frame's left; the x axis' ticks, the right edge leaving room for half the last number. */
static void lay_out(const Plot *plot, const Style *style, int width, int height, Axis *x_axis,
                    Axis *y_axis, PlotLayout *layout)
{
    memset(layout, 0, sizeof *layout);
    layout->top = round(style->pad + (plot->y.title ? style->line : 0.0) + 0.5 * style->line);
    layout->bottom = round(height - 1 - style->pad - style->tick - style->line -
                           (plot->x.title ? style->line : 0.0) - 0.2 * style->pad);
    TickRoom room = {style->font, style->size, layout->bottom - layout->top, 1};
    choose_axis(plot, 1, &room, y_axis);
    double number_width = 0.0;
    for (int i = 0; i < y_axis->tick_count; i++) {
        char text[32];
        tick_label(y_axis, y_axis->ticks[i], text, sizeof text);
        number_width = fmax(number_width, text_width(style, text));
    }
    layout->left = round(style->pad + number_width + 0.3 * style->size + style->tick);
    double right_room = style->pad + style->size;
    for (int pass = 0; pass < 2; pass++) {
        layout->right = round(width - 1 - right_room);
        room = (TickRoom){style->font, style->size, layout->right - layout->left, 0};
        choose_axis(plot, 0, &room, x_axis);
        char text[32];
        tick_label(x_axis, x_axis->high, text, sizeof text);
        right_room = style->pad + 0.5 * text_width(style, text);
    }
    layout->x_low = x_axis->low;
    layout->x_high = x_axis->high;
    layout->y_low = y_axis->low;
    layout->y_high = y_axis->high;
    layout->x_tick_count = x_axis->tick_count;
    layout->y_tick_count = y_axis->tick_count;
    memcpy(layout->x_ticks, x_axis->ticks, sizeof x_axis->ticks);
    memcpy(layout->y_ticks, y_axis->ticks, sizeof y_axis->ticks);
    for (int s = 0; s < plot->series_count; s++)
        for (int i = 0; i < plot->series[s].count; i++)
            layout->left_out += !point_shown(plot, &plot->series[s], i);
}

Image plot_draw(const Plot *plot, const Font *font, int width, int height, PlotLayout *layout)
{
    PlotLayout own_layout;
    layout = layout ? layout : &own_layout;
    Image image = image_new(width, height), before = image_new(width, height);
    if (!image.pixels || !before.pixels) {
        image_free(&image);
        image_free(&before);
        memset(layout, 0, sizeof *layout);
        return image;
    }
    Style style = style_for(plot, font, width, height);
    Axis x_axis, y_axis;
    lay_out(plot, &style, width, height, &x_axis, &y_axis, layout);
    fill(&image, (Box){0, 0, width, height}, WHITE);
    draw_ticks(&image, &style, &y_axis, layout, 1);
    draw_ticks(&image, &style, &x_axis, layout, 0);
    draw_frame(&image, layout);
    if (plot->x.title)
        draw_text(&image, &style, plot->x.title,
                  0.5 * (layout->left + layout->right - text_width(&style, plot->x.title)),
                  layout->bottom + style.tick + 0.2 * style.pad + style.line);
    if (plot->y.title)
        draw_text(&image, &style, plot->y.title, style.pad, style.pad);
    memcpy(before.pixels, image.pixels, 3 * sizeof(float) * (size_t)width * (size_t)height);
    int margin = (int)ceil(style.marker + style.line_width);
    style.clip = (Box){(int)layout->left - margin, (int)layout->top - margin,
                       (int)layout->right + margin + 1, (int)layout->bottom + margin + 1};
    for (int s = 0; s < plot->series_count; s++)
        draw_series(&image, &style, plot, &plot->series[s], &x_axis, &y_axis, layout);
    draw_legend(&image, &before, &style, plot, layout);
    image_free(&before);
    return image;
}
