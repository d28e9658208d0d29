/* test_plot.c (bench, chapter 4): the line plots of chapters 4 and 7 (plot.h).
 *
 * The ranges and ticks are checked against worked cases and, on log axes, against
 * random data (fixed seed): the range is the tightest 1-2-5 one around the data. The
 * picture is then read back as a person would: a grid line and a tick mark at each
 * numbered tick, with a number under (or beside) it whose ink is as wide as that
 * number's text drawn alone;
 * each point drawn in its series' colour where the axes' mapping puts it; each error
 * bar covering exactly its interval; points that cannot be shown left out (the picture
 * is the same as without them) and counted; a legend with each series' sample and
 * text, in the corner the data leave free; infinite-variance series dashed with hollow
 * markers.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "assert_close.h"
#include "font_fixture.h"
#include "plot.h"
#include "rng.h"

static const Vec3 WHITE = {1, 1, 1}, RED = {0.9, 0.1, 0.1}, BLUE = {0.1, 0.2, 0.9};
static const Vec3 GRID = {0.75, 0.75, 0.75}, BORDER = {0.5, 0.5, 0.5};

static int same_colour(Vec3 a, Vec3 b)
{
    return fabs(a.x - b.x) < 1e-6 && fabs(a.y - b.y) < 1e-6 && fabs(a.z - b.z) < 1e-6;
}

/* Text and frame are black, blended with white at their edges: dark means clearly so. */
static int is_dark(Vec3 p) { return p.x < 0.5 && p.y < 0.5 && p.z < 0.5; }

static Image draw(const Plot *plot, int width, int height, PlotLayout *layout)
{
    Image image = plot_draw(plot, &font, width, height, layout);
    assert_non_null(image.pixels);
    assert_int_equal(image.width, width);
    assert_int_equal(image.height, height);
    return image;
}

static const PlotAxis LOG_AXIS = {NULL, PLOT_LOG, 0, 0, 0};

/* One series of points on log axes. */
static Plot log_plot(PlotSeries *series, const double *x, const double *y, int count)
{
    *series = (PlotSeries){.x = x, .y = y, .count = count, .colour = RED, .markers = 1};
    Plot plot = {LOG_AXIS, LOG_AXIS, series, 1, 0};
    return plot;
}

static void assert_range(const PlotLayout *layout, double x_low, double x_high, double y_low,
                         double y_high)
{
    if (fabs(layout->x_low / x_low - 1) > 1e-9 || fabs(layout->x_high / x_high - 1) > 1e-9 ||
        fabs(layout->y_low / y_low - 1) > 1e-9 || fabs(layout->y_high / y_high - 1) > 1e-9)
        fail_msg("x %g..%g, y %g..%g; expected x %g..%g, y %g..%g", layout->x_low,
                 layout->x_high, layout->y_low, layout->y_high, x_low, x_high, y_low, y_high);
}

static PlotLayout log_layout_of(const double *x, const double *y, int count)
{
    PlotSeries series;
    Plot plot = log_plot(&series, x, y, count);
    PlotLayout layout;
    Image image = draw(&plot, 300, 200, &layout);
    image_free(&image);
    return layout;
}

/* Worked cases: x from 0.03 to 450 gives 0.02..500 and y from 0.002 to 0.5 stays
 * 0.002..0.5 (both ends are 1-2-5 values); one point at a 1-2-5 value gets a step
 * either way (5 gives 2..10, 0.5 gives 0.2..1); one point between gets the values
 * around it (3 gives 2..5); 1 to 100 is 1..100; no points give 1..10; the error
 * bars' ends count. */
static void test_log_range_by_hand(void **state)
{
    const double x[] = {0.03, 2.0, 450.0}, y[] = {0.002, 0.04, 0.5};
    PlotLayout layout = log_layout_of(x, y, 3);
    assert_range(&layout, 0.02, 500, 0.002, 0.5);
    const double five[] = {5.0}, half[] = {0.5}, three[] = {3.0}, point_three[] = {0.3};
    layout = log_layout_of(five, half, 1);
    assert_range(&layout, 2, 10, 0.2, 1);
    layout = log_layout_of(three, point_three, 1);
    assert_range(&layout, 2, 5, 0.2, 0.5);
    const double one_to_hundred[] = {1.0, 100.0};
    layout = log_layout_of(one_to_hundred, one_to_hundred, 2);
    assert_range(&layout, 1, 100, 1, 100);
    layout = log_layout_of(NULL, NULL, 0);
    assert_range(&layout, 1, 10, 1, 10);

    /* Error bars count: 0.3 with a bar from 0.04 to 3 needs 0.02..5; a bar end <= 0
     * does not count. */
    const double bar_low[] = {0.04}, bar_high[] = {3.0}, no_low[] = {-1.0};
    PlotSeries series = {.x = three,
                         .y = point_three,
                         .y_low = bar_low,
                         .y_high = bar_high,
                         .count = 1,
                         .colour = RED};
    Plot plot = {LOG_AXIS, LOG_AXIS, &series, 1, 0};
    Image image = draw(&plot, 300, 200, &layout);
    assert_range(&layout, 2, 5, 0.02, 5);
    image_free(&image);
    series.y_low = no_low;
    image = draw(&plot, 300, 200, &layout);
    assert_range(&layout, 2, 5, 0.2, 5);
    image_free(&image);
}

/* Is v one of ..., 0.1, 0.2, 0.5, 1, 2, 5, 10, ...? */
static int is_one_two_five(double v)
{
    double mantissa = v / pow(10.0, floor(log10(v) + 1e-9));
    return fabs(mantissa - 1) < 1e-6 || fabs(mantissa - 2) < 1e-6 || fabs(mantissa - 5) < 1e-6;
}

/* The 1-2-5 value after v (v one of them). */
static double next_one_two_five(double v)
{
    double mantissa = v / pow(10.0, floor(log10(v) + 1e-9));
    return v * (mantissa < 1.5 ? 2.0 : mantissa < 3.0 ? 2.5 : 2.0);
}

/* The range is two 1-2-5 values that enclose [min, max] as tightly as they can: the
 * value after `low` is above min, the one before `high` below max (unless min = max is
 * itself a 1-2-5 value, when the range is one step either way). */
static void assert_tight(double low, double high, double min, double max)
{
    assert_true(is_one_two_five(low) && is_one_two_five(high));
    assert_true(low <= min * (1 + 1e-12) && max <= high * (1 + 1e-12));
    assert_true(low < high);
    if (min == max && is_one_two_five(min)) {
        assert_close(next_one_two_five(low), min, 1e-9 * min);
        assert_close(next_one_two_five(min), high, 1e-9 * high);
        return;
    }
    assert_true(next_one_two_five(low) > min * (1 - 1e-12));
    double mantissa = high / pow(10.0, floor(log10(high) + 1e-9));
    double before_high = high / (fabs(mantissa - 5) < 1e-6 ? 2.5 : 2.0);
    assert_true(before_high < max * (1 + 1e-12));
}

/* Random sets of 1 to 6 points, log-uniform over 1e-6..1e6 (fixed seed): the ranges
 * always enclose every point, tightly, and their ends are 1-2-5 values. */
static void test_log_range_encloses_points(void **state)
{
    for (int trial = 0; trial < 200; trial++) {
        Rng rng = rng_for_sample(2024, 0, (uint64_t)trial);
        int count = 1 + (int)(6 * rng_uniform(&rng));
        double x[6], y[6], min[2] = {INFINITY, INFINITY}, max[2] = {0, 0};
        for (int i = 0; i < count; i++) {
            x[i] = pow(10.0, 12 * rng_uniform(&rng) - 6);
            y[i] = pow(10.0, 12 * rng_uniform(&rng) - 6);
            min[0] = fmin(min[0], x[i]);
            max[0] = fmax(max[0], x[i]);
            min[1] = fmin(min[1], y[i]);
            max[1] = fmax(max[1], y[i]);
        }
        PlotLayout layout = log_layout_of(x, y, count);
        assert_tight(layout.x_low, layout.x_high, min[0], max[0]);
        assert_tight(layout.y_low, layout.y_high, min[1], max[1]);
    }
}

/* Where the axes put (x, y), in pixel centres, computed here from the frame. */
static double fraction(PlotScale scale, double low, double high, double v)
{
    return scale == PLOT_LOG ? log10(v / low) / log10(high / low) : (v - low) / (high - low);
}

static double col_of(const PlotLayout *layout, PlotScale scale, double x)
{
    return layout->left +
           fraction(scale, layout->x_low, layout->x_high, x) * (layout->right - layout->left);
}

static double row_of(const PlotLayout *layout, PlotScale scale, double y)
{
    return layout->bottom -
           fraction(scale, layout->y_low, layout->y_high, y) * (layout->bottom - layout->top);
}

/* The bounding box of the dark pixels in [left, right) x [top, bottom). */
typedef struct {
    int count, left, right, top, bottom; /* inclusive */
} Ink;

static Ink dark_ink(const Image *image, int left, int top, int right, int bottom)
{
    Ink ink = {0, image->width, -1, image->height, -1};
    for (int row = top < 0 ? 0 : top; row < bottom && row < image->height; row++)
        for (int col = left < 0 ? 0 : left; col < right && col < image->width; col++)
            if (is_dark(image_get(image, col, row))) {
                ink.count++;
                ink.left = col < ink.left ? col : ink.left;
                ink.right = col > ink.right ? col : ink.right;
                ink.top = row < ink.top ? row : ink.top;
                ink.bottom = row > ink.bottom ? row : ink.bottom;
            }
    return ink;
}

static double label_width(const char *text, double size)
{
    return font_width(&font, text, strlen(text), size);
}

/* How wide the dark ink of `text` is, drawn alone black on white. */
static double ink_width(const char *text, double size)
{
    Image image = image_new(400, 60);
    assert_non_null(image.pixels);
    for (long i = 0; i < 3L * 400 * 60; i++)
        image.pixels[i] = 1.0f;
    font_draw(&image, &font, text, strlen(text), 10.5, 40.0, size, vec3(0, 0, 0));
    Ink ink = dark_ink(&image, 0, 0, 400, 60);
    image_free(&image);
    return ink.right - ink.left + 1;
}

/* The x axis' numbered ticks: the expected values; at each a grid line (most of the
 * column inside the frame is grid grey, or the frame's black at its edges), a tick mark under
 * the frame, and under that a number centred on the tick (within 2 pixels) whose ink is as wide
 * (within a pixel) as that of `labels[i]` drawn alone; halfway between ticks no grid line. */
static void check_x_ticks(const Image *image, const PlotLayout *layout, PlotScale scale,
                          const double *values, const char *const *labels, int count,
                          double size)
{
    assert_int_equal(layout->x_tick_count, count);
    double line = font_line_height(&font, size);
    for (int i = 0; i < count; i++) {
        assert_close(layout->x_ticks[i], values[i], 1e-9 * fabs(values[i]) + 1e-12);
        int col = (int)lround(col_of(layout, scale, values[i]));
        int grid = 0, rows = (int)(layout->bottom - layout->top) - 1;
        for (int row = (int)layout->top + 1; row < layout->bottom; row++)
            grid += same_colour(image_get(image, col, row), GRID) ||
                    ((col == layout->left || col == layout->right) &&
                     is_dark(image_get(image, col, row)));
        assert_true(grid > 0.8 * rows);
        assert_true(is_dark(image_get(image, col, (int)layout->bottom + 2)));
        double half = 0.5 * (layout->right - layout->left) / (count - 1);
        /* From 0.45 em under the frame: the lowest y number, centred on the frame's
         * bottom row, reaches no lower. */
        int top = (int)(layout->bottom + 0.45 * size);
        Ink ink =
            dark_ink(image, (int)(col - half + 1), top, (int)(col + half), (int)(top + line));
        assert_true(ink.count > 5);
        assert_close(0.5 * (ink.left + ink.right), col, 2.0);
        double width = ink_width(labels[i], size);
        if (fabs(ink.right - ink.left + 1 - width) > 1.0)
            fail_msg("label %s: ink %d pixels wide, the text's %.0f", labels[i],
                     ink.right - ink.left + 1, width);
        if (i > 0) {
            int between = (int)lround(0.5 * (col + col_of(layout, scale, values[i - 1])));
            int grid_between = 0;
            for (int row = (int)layout->top + 1; row < layout->bottom; row++)
                grid_between += same_colour(image_get(image, between, row), GRID);
            assert_true(grid_between < 0.2 * rows);
        }
    }
}

/* The y axis' numbered ticks, likewise: a grid row, a tick mark left of the frame, and
 * left of that a number, its ink centred on the row (within 3 pixels), ending within
 * an em of the frame, as wide as labels[i]'s. */
static void check_y_ticks(const Image *image, const PlotLayout *layout, PlotScale scale,
                          const double *values, const char *const *labels, int count,
                          double size)
{
    assert_int_equal(layout->y_tick_count, count);
    for (int i = 0; i < count; i++) {
        assert_close(layout->y_ticks[i], values[i], 1e-9 * fabs(values[i]) + 1e-12);
        int row = (int)lround(row_of(layout, scale, values[i]));
        int grid = 0, cols = (int)(layout->right - layout->left) - 1;
        for (int col = (int)layout->left + 1; col < layout->right; col++)
            grid += same_colour(image_get(image, col, row), GRID) ||
                    ((row == layout->top || row == layout->bottom) &&
                     is_dark(image_get(image, col, row)));
        assert_true(grid > 0.8 * cols);
        assert_true(is_dark(image_get(image, (int)layout->left - 2, row)));
        /* Left of the tick marks, which are 0.35 em long. */
        Ink ink = dark_ink(image, 0, (int)(row - 0.5 * size), (int)(layout->left - 0.4 * size),
                           (int)(row + 0.5 * size) + 1);
        assert_true(ink.count > 5);
        assert_close(0.5 * (ink.top + ink.bottom), row, 3.0);
        assert_true(ink.right >= layout->left - 4 - size);
        double width = ink_width(labels[i], size);
        if (fabs(ink.right - ink.left + 1 - width) > 1.0)
            fail_msg("label %s: ink %d pixels wide, the text's %.0f", labels[i],
                     ink.right - ink.left + 1, width);
    }
}

/* Log ticks for given ranges on a 600 x 400 plot (text 15 pixels per em): x from 1e-3
 * to 1e2 gets a numbered tick at each decade (its 1-2-5 values would not have room:
 * 0.3 decade is 30 pixels, "0.005" is 37 wide plus an em); y from 0.1 to 1 gets 0.1,
 * 0.2, 0.5 and 1 (they have room). */
static void test_ticks_at_decades_for_a_given_range(void **state)
{
    const double x[] = {0.01, 10}, y[] = {0.15, 0.8};
    PlotSeries series = {.x = x, .y = y, .count = 2, .colour = BLUE, .markers = 1};
    Plot plot = {{NULL, PLOT_LOG, 1e-3, 1e2, 0}, {NULL, PLOT_LOG, 0.1, 1, 0}, &series, 1, 0};
    PlotLayout layout;
    Image image = draw(&plot, 600, 400, &layout);
    assert_range(&layout, 1e-3, 1e2, 0.1, 1);
    const double decades[] = {1e-3, 1e-2, 1e-1, 1, 10, 100};
    const char *decade_labels[] = {"0.001", "0.01", "0.1", "1", "10", "100"};
    check_x_ticks(&image, &layout, PLOT_LOG, decades, decade_labels, 6, 15);
    const double steps[] = {0.1, 0.2, 0.5, 1};
    const char *step_labels[] = {"0.1", "0.2", "0.5", "1"};
    check_y_ticks(&image, &layout, PLOT_LOG, steps, step_labels, 4, 15);
    image_free(&image);
}

/* Many decades on a short axis: 1e-6 to 1e6 across 200 pixels numbers only the
 * decades whose exponent is a multiple of some k > 1 (so 1 is among them), labels not
 * overlapping. Far from 0.0001 to 100000 the numbers are written like 1e-5. */
static void test_many_decades_thin_out(void **state)
{
    Plot plot = {{NULL, PLOT_LOG, 1e-6, 1e6, 0}, {NULL, PLOT_LOG, 1e-6, 1e6, 0}, NULL, 0, 0};
    PlotLayout layout;
    Image image = draw(&plot, 200, 200, &layout);
    assert_true(layout.x_tick_count >= 2 && layout.x_tick_count < 13);
    double first = log10(layout.x_ticks[0]), step = log10(layout.x_ticks[1]) - first;
    assert_true(step > 1.5);
    int has_one = 0;
    for (int i = 0; i < layout.x_tick_count; i++) {
        double exponent = log10(layout.x_ticks[i]);
        assert_close(exponent, round(exponent), 1e-9);
        assert_close(exponent, first + i * step, 1e-9);
        assert_close(fmod(fabs(exponent), step), 0.0, 1e-9);
        has_one += layout.x_ticks[i] == 1.0;
    }
    assert_int_equal(has_one, 1);
    assert_true(first - step < -6 + 1e-9); /* no decade left out at the low end */
    char text[16];
    snprintf(text, sizeof text, "1e%d", (int)lround(first));
    int col = (int)lround(col_of(&layout, PLOT_LOG, layout.x_ticks[0]));
    Ink ink = dark_ink(&image, col - 20, (int)layout.bottom + 4, col + 20, 200);
    assert_close(ink.right - ink.left + 1, ink_width(text, 10), 1.0);
    image_free(&image);
}

/* Linear axes as chapter 4 gives them: 0 to 90 numbered every 15, 0 to 1 every 0.25
 * (written with the decimals the spacing needs: "0.25", "1.00"); and a range from the
 * data, 0.13 to 0.87, on a spacing the plot chooses: the range is the spacing's
 * multiples around the data. */
static void test_linear_ticks(void **state)
{
    const double x[] = {0, 45, 90}, y[] = {0.04, 0.1, 1.0};
    PlotSeries series = {.x = x, .y = y, .count = 3, .colour = RED};
    Plot plot = {
        {"angle", PLOT_LINEAR, 0, 90, 15}, {"R", PLOT_LINEAR, 0, 1, 0.25}, &series, 1, 0};
    PlotLayout layout;
    Image image = draw(&plot, 800, 450, &layout);
    const double degrees[] = {0, 15, 30, 45, 60, 75, 90};
    const char *degree_labels[] = {"0", "15", "30", "45", "60", "75", "90"};
    const double quarters[] = {0, 0.25, 0.5, 0.75, 1};
    const char *quarter_labels[] = {"0.00", "0.25", "0.50", "0.75", "1.00"};
    double size = round(sqrt(800.0 * 450.0) / 32.0);
    check_x_ticks(&image, &layout, PLOT_LINEAR, degrees, degree_labels, 7, size);
    check_y_ticks(&image, &layout, PLOT_LINEAR, quarters, quarter_labels, 5, size);
    image_free(&image);

    const double data_x[] = {0.13, 0.5, 0.87}, data_y[] = {-3.2, 7.1, 1.0};
    series = (PlotSeries){.x = data_x, .y = data_y, .count = 3, .colour = RED};
    plot = (Plot){{NULL, PLOT_LINEAR, 0, 0, 0}, {NULL, PLOT_LINEAR, 0, 0, 0}, &series, 1, 0};
    image = draw(&plot, 400, 300, &layout);
    const double *ticks[2] = {layout.x_ticks, layout.y_ticks};
    const int counts[2] = {layout.x_tick_count, layout.y_tick_count};
    const double lows[2] = {layout.x_low, layout.y_low},
                 highs[2] = {layout.x_high, layout.y_high};
    const double mins[2] = {0.13, -3.2}, maxs[2] = {0.87, 7.1};
    for (int axis = 0; axis < 2; axis++) {
        assert_true(counts[axis] >= 3);
        double step = ticks[axis][1] - ticks[axis][0];
        assert_true(is_one_two_five(step));
        assert_close(ticks[axis][0], lows[axis], 1e-9);
        assert_close(ticks[axis][counts[axis] - 1], highs[axis], 1e-9);
        assert_true(lows[axis] <= mins[axis] && lows[axis] + step > mins[axis]);
        assert_true(highs[axis] >= maxs[axis] && highs[axis] - step < maxs[axis]);
    }
    image_free(&image);
}

/* Each point's marker is in its series' colour at the pixel the mapping predicts, and
 * the polyline passes through the middle between points (on log and linear axes). */
static void test_points_where_the_mapping_puts_them(void **state)
{
    const double x[] = {0.03, 2.0, 450.0}, y[] = {0.002, 0.04, 0.5};
    for (int scale = 0; scale < 2; scale++) {
        PlotScale kind = scale ? PLOT_LOG : PLOT_LINEAR;
        PlotSeries series = {.x = x, .y = y, .count = 3, .colour = RED, .markers = 1};
        Plot plot = {{NULL, kind, 0, 0, 0}, {NULL, kind, 0, 0, 0}, &series, 1, 0};
        PlotLayout layout;
        Image image = draw(&plot, 400, 300, &layout);
        double col[3], row[3];
        for (int i = 0; i < 3; i++) {
            col[i] = col_of(&layout, kind, x[i]);
            row[i] = row_of(&layout, kind, y[i]);
            assert_true(
                same_colour(image_get(&image, (int)lround(col[i]), (int)lround(row[i])), RED));
        }
        for (int i = 0; i < 2; i++) {
            int mid_col = (int)lround(0.5 * (col[i] + col[i + 1]));
            int mid_row = (int)lround(0.5 * (row[i] + row[i + 1]));
            assert_true(same_colour(image_get(&image, mid_col, mid_row), RED));
        }
        image_free(&image);
    }
}

/* The pixels of colour `colour` in column `col`, from row `top` to `bottom` inclusive. */
static int coloured_in_column(const Image *image, int col, int top, int bottom, Vec3 colour)
{
    int count = 0;
    for (int row = top; row <= bottom; row++)
        count += same_colour(image_get(image, col, row), colour);
    return count;
}

/* An error bar covers its interval: at the point's column every row from y_high's to
 * y_low's is the series' colour, 3 rows beyond either end are not, and its caps reach
 * sideways. An end <= 0 on the log axis runs the bar to the frame; a NaN end draws no
 * bar. */
static void test_error_bars_span_the_interval(void **state)
{
    const double x[] = {0.3, 1.0, 3.0}, y[] = {0.1, 0.1, 0.1};
    const double low[] = {0.03, -1.0, NAN}, high[] = {0.4, 0.2, 0.5};
    PlotSeries series = {
        .x = x, .y = y, .y_low = low, .y_high = high, .count = 3, .colour = BLUE};
    Plot plot = {{NULL, PLOT_LOG, 0.1, 10, 0}, {NULL, PLOT_LOG, 0.01, 1, 0}, &series, 1, 0};
    PlotLayout layout;
    Image image = draw(&plot, 400, 400, &layout);

    int col = (int)lround(col_of(&layout, PLOT_LOG, x[0]));
    int top = (int)lround(row_of(&layout, PLOT_LOG, high[0]));
    int bottom = (int)lround(row_of(&layout, PLOT_LOG, low[0]));
    assert_int_equal(coloured_in_column(&image, col, top, bottom, BLUE), bottom - top + 1);
    assert_false(same_colour(image_get(&image, col, top - 3), BLUE));
    assert_false(same_colour(image_get(&image, col, bottom + 3), BLUE));
    assert_true(same_colour(image_get(&image, col + 2, top), BLUE));
    assert_true(same_colour(image_get(&image, col - 2, bottom), BLUE));

    col = (int)lround(col_of(&layout, PLOT_LOG, x[1]));
    top = (int)lround(row_of(&layout, PLOT_LOG, high[1]));
    assert_int_equal(coloured_in_column(&image, col, top, (int)layout.bottom, BLUE),
                     (int)layout.bottom - top + 1);

    col = (int)lround(col_of(&layout, PLOT_LOG, x[2]));
    int point = (int)lround(row_of(&layout, PLOT_LOG, y[2]));
    assert_int_equal(coloured_in_column(&image, col, (int)layout.top + 1, point - 4, BLUE), 0);
    image_free(&image);
}

/* Points that axes cannot show are left out and counted, and the picture is exactly
 * the one drawn without them: on log axes an RMSE of 0, a negative time, an infinite
 * value, NaN; on a given range, points beyond it. */
static void test_points_left_out_are_counted(void **state)
{
    const double x[] = {0.1, 0.0, 10.0, -1.0, 1.0, NAN, 0.3};
    const double y[] = {1.0, 2.0, INFINITY, 3.0, 0.5, 1.0, 0.7};
    const double kept_x[] = {0.1, 1.0, 0.3}, kept_y[] = {1.0, 0.5, 0.7};
    PlotSeries all, kept;
    Plot with = log_plot(&all, x, y, 7), without = log_plot(&kept, kept_x, kept_y, 3);
    PlotLayout with_layout, without_layout;
    Image a = draw(&with, 300, 200, &with_layout),
          b = draw(&without, 300, 200, &without_layout);
    assert_int_equal(with_layout.left_out, 4);
    assert_int_equal(without_layout.left_out, 0);
    assert_range(&with_layout, 0.1, 1, 0.5, 1);
    assert_memory_equal(a.pixels, b.pixels, 3 * sizeof(float) * 300 * 200);
    image_free(&a);
    image_free(&b);

    const double range_x[] = {0.5, 2.0, 20.0, 5.0}, range_y[] = {0.3, 0.4, 0.5, 200.0};
    const double inside_x[] = {2.0}, inside_y[] = {0.4};
    with = log_plot(&all, range_x, range_y, 4);
    without = log_plot(&kept, inside_x, inside_y, 1);
    with.x = without.x = (PlotAxis){NULL, PLOT_LOG, 1, 10, 0};
    with.y = without.y = (PlotAxis){NULL, PLOT_LOG, 0.1, 1, 0};
    a = draw(&with, 300, 200, &with_layout);
    b = draw(&without, 300, 200, &without_layout);
    assert_int_equal(with_layout.left_out, 3);
    assert_memory_equal(a.pixels, b.pixels, 3 * sizeof(float) * 300 * 200);
    image_free(&a);
    image_free(&b);
}

static int is_colour_in(const Image *image, const int box[4], Vec3 colour)
{
    int count = 0;
    for (int row = box[1]; row < box[3]; row++)
        for (int col = box[0]; col < box[2]; col++)
            count += same_colour(image_get(image, col, row), colour);
    return count;
}

/* The legend: a box with a grey border inside the frame, holding each labelled series'
 * sample (its colour) and text (dark ink as wide as the label's); an
 * infinite-variance series' entry is longer by the note. It sits in a corner the data
 * leave free (here the points run along the top right, so not there). Without labels
 * there is no legend. */
static void test_legend_present(void **state)
{
    const double x[] = {1, 3, 9}, y[] = {9, 9.5, 9.8}, x2[] = {1, 9}, y2[] = {8, 9};
    PlotSeries series[2] = {
        {.label = "M=20, rr=0.9", .x = x, .y = y, .count = 3, .colour = RED, .markers = 1},
        {.label = "M=1, rr=0.25", .x = x2, .y = y2, .count = 2, .colour = BLUE, .markers = 1},
    };
    Plot plot = {{NULL, PLOT_LINEAR, 0, 10, 0}, {NULL, PLOT_LINEAR, 0, 10, 0}, series, 2, 0};
    PlotLayout layout;
    Image image = draw(&plot, 500, 400, &layout);
    const int *box = layout.legend;
    assert_true(box[0] > layout.left && box[2] < layout.right);
    assert_true(box[1] > layout.top && box[3] < layout.bottom);
    assert_true(box[1] > 0.5 * (layout.top + layout.bottom)); /* below the data */
    assert_true(same_colour(image_get(&image, box[0], (box[1] + box[3]) / 2), BORDER));
    assert_true(same_colour(image_get(&image, box[2] - 1, box[1]), BORDER));
    assert_true(is_colour_in(&image, box, RED) > 10);
    assert_true(is_colour_in(&image, box, BLUE) > 10);
    Ink ink = dark_ink(&image, box[0] + 1, box[1] + 1, box[2] - 1, box[3] - 1);
    assert_close(ink.right - ink.left + 1, ink_width("M=20, rr=0.9", 14), 1.0);
    int width = box[2] - box[0];
    image_free(&image);

    series[0].infinite_variance = 1;
    image = draw(&plot, 500, 400, &layout);
    assert_close(box[2] - box[0] - width,
                 label_width("M=20, rr=0.9 (infinite variance)", 14) -
                     label_width("M=20, rr=0.9", 14),
                 1.5);
    image_free(&image);

    series[0].label = series[1].label = NULL;
    image = draw(&plot, 500, 400, &layout);
    assert_true(box[0] == 0 && box[1] == 0 && box[2] == 0 && box[3] == 0);
    const int whole[4] = {0, 0, 500, 400};
    assert_int_equal(is_colour_in(&image, whole, BORDER), 0);
    image_free(&image);
}

/* Infinite variance stands out: along a long segment the line has gaps (dashed) where
 * the same series without the mark has none, and each marker is hollow (white at its
 * centre, its colour on its ring) instead of filled. */
static void test_infinite_variance_stands_out(void **state)
{
    const double x[] = {1, 9}, y[] = {5, 5};
    for (int mark = 0; mark < 2; mark++) {
        PlotSeries series = {
            .x = x, .y = y, .count = 2, .colour = RED, .markers = 1, .infinite_variance = mark};
        Plot plot = {
            {NULL, PLOT_LINEAR, 0, 10, 0}, {NULL, PLOT_LINEAR, 0, 10, 0}, &series, 1, 0};
        PlotLayout layout;
        Image image = draw(&plot, 400, 300, &layout);
        int row = (int)lround(row_of(&layout, PLOT_LINEAR, 5));
        int from = (int)lround(col_of(&layout, PLOT_LINEAR, 2)),
            to = (int)lround(col_of(&layout, PLOT_LINEAR, 8));
        int gaps = 0;
        for (int col = from; col <= to; col++)
            gaps += !same_colour(image_get(&image, col, row), RED);
        int centre = (int)lround(col_of(&layout, PLOT_LINEAR, 1));
        Vec3 middle = image_get(&image, centre, row);
        if (mark) {
            assert_true(gaps > 0.25 * (to - from));
            assert_true(same_colour(middle, WHITE));
            int ring = 0; /* the marker's ring above its centre, within 8 pixels */
            for (int d = 1; d <= 8; d++)
                ring += same_colour(image_get(&image, centre, row - d), RED);
            assert_true(ring > 0);
        } else {
            assert_int_equal(gaps, 0);
            assert_true(same_colour(middle, RED));
        }
        image_free(&image);
    }
}

/* The background is white, titles are drawn (dark ink above the frame for y, under
 * the numbers for x), and nothing is drawn outside [0, 1]. */
static void test_background_and_titles(void **state)
{
    Plot plot = {
        {"time (s)", PLOT_LOG, 0.01, 1, 0}, {"RMSE", PLOT_LOG, 0.1, 10, 0}, NULL, 0, 0};
    PlotLayout layout;
    Image image = draw(&plot, 300, 200, &layout);
    assert_true(same_colour(image_get(&image, 0, 0), WHITE));
    assert_true(same_colour(image_get(&image, 299, 0), WHITE));
    assert_true(same_colour(image_get(&image, 0, 199), WHITE));
    assert_true(same_colour(image_get(&image, 299, 199), WHITE));
    for (long i = 0; i < 3L * 300 * 200; i++)
        assert_true(image.pixels[i] >= 0.0f && image.pixels[i] <= 1.0f);
    double size = 10; /* sqrt(300 * 200) / 32 = 7.7, at least 10 */
    Ink y_title = dark_ink(&image, 0, 0, 300, (int)layout.top - (int)(0.5 * size));
    assert_close(y_title.right - y_title.left + 1, ink_width("RMSE", size), 1.0);
    Ink x_title =
        dark_ink(&image, 0, (int)(layout.bottom + 4 + font_line_height(&font, size)), 300, 200);
    assert_close(x_title.right - x_title.left + 1, ink_width("time (s)", size), 1.0);
    assert_close(0.5 * (x_title.left + x_title.right), 0.5 * (layout.left + layout.right), 2.0);
    image_free(&image);
}

/* Drawing always finishes and stays inside the image (the sanitizer run checks
 * that): tiny images, a single pixel, extreme values (kept to 1e-300..1e300 on log
 * axes, up to 1e300 in size on linear ones), ticks far finer than the range. */
static void test_extremes_are_safe(void **state)
{
    const double x[] = {1e-300, 1e300, 1e-320, 1e308, 3.0},
                 y[] = {1e300, 1e-300, 5.0, 5.0, 4.0};
    const double low[] = {-1e308, 0.0, NAN, 1.0, 3.0},
                 high[] = {1e308, INFINITY, 1.0, 2.0, 5.0};
    PlotSeries series = {.label = "extreme",
                         .x = x,
                         .y = y,
                         .y_low = low,
                         .y_high = high,
                         .count = 5,
                         .colour = RED,
                         .markers = 1,
                         .infinite_variance = 1};
    const int sizes[][2] = {{1, 1}, {5, 3}, {40, 40}, {300, 200}};
    for (int kind = 0; kind < 3; kind++) {
        Plot plot = {LOG_AXIS, LOG_AXIS, &series, 1, 0};
        if (kind == 1)
            plot.x = plot.y = (PlotAxis){NULL, PLOT_LINEAR, 0, 0, 0};
        if (kind == 2)
            plot.x = plot.y = (PlotAxis){NULL, PLOT_LINEAR, -1e300, 1e300, 1e-300};
        for (int s = 0; s < 4; s++) {
            PlotLayout layout;
            Image image = draw(&plot, sizes[s][0], sizes[s][1], &layout);
            assert_true(layout.x_tick_count <= PLOT_MAX_TICKS);
            assert_true(isfinite(layout.x_low) && isfinite(layout.x_high));
            assert_true(isfinite(layout.y_low) && isfinite(layout.y_high));
            assert_int_equal(layout.left_out,
                             kind == 0 ? 2 : 1); /* 1e-320 is drawable on linear axes */
            image_free(&image);
        }
    }
    Image none = plot_draw(&(Plot){LOG_AXIS, LOG_AXIS, NULL, 0, 0}, &font, 0, 10, NULL);
    assert_null(none.pixels);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_log_range_by_hand),
        cmocka_unit_test(test_log_range_encloses_points),
        cmocka_unit_test(test_ticks_at_decades_for_a_given_range),
        cmocka_unit_test(test_many_decades_thin_out),
        cmocka_unit_test(test_linear_ticks),
        cmocka_unit_test(test_points_where_the_mapping_puts_them),
        cmocka_unit_test(test_error_bars_span_the_interval),
        cmocka_unit_test(test_points_left_out_are_counted),
        cmocka_unit_test(test_legend_present),
        cmocka_unit_test(test_infinite_variance_stands_out),
        cmocka_unit_test(test_background_and_titles),
        cmocka_unit_test(test_extremes_are_safe),
    };
    return cmocka_run_group_tests(tests, load_font, free_font);
}
