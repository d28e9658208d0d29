/* test_plot.c (chapter 4): the log-log plot of chapter 7's convergence figure (plot.h).
 *
 * The decades must enclose every point and be as tight as whole decades allow. The
 * picture is read back like a person would: the grid lines are found as columns and
 * rows that are mostly grey or black, and must sit one per decade, evenly spaced, the
 * lowest decade black; each point must then be drawn in its series' colour where the
 * log mapping between those grid lines puts it, with nothing but white elsewhere.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>

#include "check.h"
#include "plot.h"

static const Vec3 WHITE = {1, 1, 1}, BLACK = {0, 0, 0};
static const Vec3 RED = {0.9, 0.1, 0.1}, BLUE = {0.1, 0.2, 0.9};

static int same_colour(Vec3 a, Vec3 b)
{
    return fabs(a.x - b.x) < 1e-6 && fabs(a.y - b.y) < 1e-6 && fabs(a.z - b.z) < 1e-6;
}

static int is_black(Vec3 p) { return same_colour(p, BLACK); }

/* Grey: neutral, and clearly neither black nor white. */
static int is_grey(Vec3 p)
{
    return p.x == p.y && p.y == p.z && p.x > 0.2 && p.x < 0.9;
}

/* Three points of one series spread over several decades, and one lone point. */
static const double LINE_X[] = {0.03, 2.0, 450.0}, LINE_Y[] = {0.002, 0.04, 0.5};
static const double LONE_X[] = {0.5}, LONE_Y[] = {0.01};

static Image sample_plot(int width, int height, int decades[4])
{
    const PlotSeries series[] = {{LINE_X, LINE_Y, 3, RED}, {LONE_X, LONE_Y, 1, BLUE}};
    Image image = plot_log_log(series, 2, width, height, decades);
    assert_non_null(image.pixels);
    return image;
}

static void assert_decades(const int decades[4], int x_low, int x_high, int y_low, int y_high)
{
    if (decades[0] != x_low || decades[1] != x_high || decades[2] != y_low ||
        decades[3] != y_high)
        fail_msg("decades x %d..%d, y %d..%d; expected x %d..%d, y %d..%d", decades[0],
                 decades[1], decades[2], decades[3], x_low, x_high, y_low, y_high);
}

static Image plot_points(const double *x, const double *y, int count, int decades[4])
{
    const PlotSeries series = {x, y, count, RED};
    Image image = plot_log_log(&series, 1, 40, 40, decades);
    assert_non_null(image.pixels);
    return image;
}

/* Worked cases: x from 0.03 to 450 spans 1e-2 to 1e3 and y from 0.002 to 0.5 spans 1e-3
 * to 1e0, taken over both series; a single point still gets one decade each way
 * (5 lies in 1e0..1e1); a point exactly on a decade starts there (10 gives 1e1..1e2);
 * points exactly on decades end there (1 to 100 spans 1e0..1e2, not 1e3); with no
 * points at all, the plot shows 1e0..1e1. */
static void test_decades_by_hand(void **state)
{
    (void)state;
    int decades[4];
    Image image = sample_plot(100, 80, decades);
    assert_decades(decades, -2, 3, -3, 0);
    image_free(&image);

    const double five[] = {5.0}, half[] = {0.5}, ten[] = {10.0}, hundred[] = {100.0};
    image = plot_points(five, half, 1, decades);
    assert_decades(decades, 0, 1, -1, 0);
    image_free(&image);
    image = plot_points(ten, hundred, 1, decades);
    assert_decades(decades, 1, 2, 2, 3);
    image_free(&image);
    const double one_to_hundred[] = {1.0, 100.0}, tenth_to_ten[] = {0.1, 10.0};
    image = plot_points(one_to_hundred, tenth_to_ten, 2, decades);
    assert_decades(decades, 0, 2, -1, 1);
    image_free(&image);

    image = plot_log_log(NULL, 0, 40, 40, decades);
    assert_non_null(image.pixels);
    assert_decades(decades, 0, 1, 0, 1);
    image_free(&image);
}

/* Does [10^low, 10^high] enclose [min, max] as tightly as whole decades allow? The
 * decade above `low` must already be above min, and the one below `high` below max,
 * unless the span is the minimum single decade. */
static void assert_encloses(int low, int high, double min, double max)
{
    assert_true(high - low >= 1);
    assert_true(pow(10.0, low) <= min * (1 + 1e-12));
    assert_true(max <= pow(10.0, high) * (1 + 1e-12));
    assert_true(pow(10.0, low + 1) > min);
    assert_true(high - low == 1 || pow(10.0, high - 1) < max);
}

/* Random sets of 1 to 6 points, log-uniform over 1e-6..1e6 (fixed seed): the decades
 * always enclose every point, tightly, and are at least one decade wide. */
static void test_decades_enclose_points(void **state)
{
    (void)state;
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
        int decades[4];
        Image image = plot_points(x, y, count, decades);
        assert_encloses(decades[0], decades[1], min[0], max[0]);
        assert_encloses(decades[2], decades[3], min[1], max[1]);
        image_free(&image);
    }
}

/* The image is exactly the size asked for, whatever its shape. */
static void test_image_size(void **state)
{
    (void)state;
    const int sizes[][2] = {{300, 200}, {64, 48}, {120, 400}};
    for (int i = 0; i < 3; i++) {
        int decades[4];
        Image image = sample_plot(sizes[i][0], sizes[i][1], decades);
        assert_int_equal(image.width, sizes[i][0]);
        assert_int_equal(image.height, sizes[i][1]);
        image_free(&image);
    }
}

/* The centre of each band of columns (vertical) or rows in which more than half the
 * pixels are of the colour `is_colour` tells: the grid lines of that colour. Returns
 * how many. */
static int find_lines(const Image *image, int vertical, int (*is_colour)(Vec3),
                      double centres[16])
{
    int lines = 0, band_start = -1;
    int along = vertical ? image->width : image->height;
    int across = vertical ? image->height : image->width;
    for (int i = 0; i <= along; i++) {
        int matching = 0;
        for (int j = 0; i < along && j < across; j++)
            matching += is_colour(vertical ? image_get(image, i, j) : image_get(image, j, i));
        int in_band = 2 * matching > across;
        if (in_band && band_start < 0)
            band_start = i;
        if (!in_band && band_start >= 0) {
            assert_true(lines < 16);
            centres[lines++] = 0.5 * (band_start + i - 1);
            band_start = -1;
        }
    }
    return lines;
}

/* Checks one direction's grid: one black line at the lowest decade, a grey line at each
 * decade above it, all evenly spaced (within a pixel: lines are drawn at whole pixels).
 * Decades grow with the pixel index for `sign` = +1 (x, rightwards) and against it for
 * -1 (y: upwards, towards row 0). The lowest and highest lines go to low and high. */
static void check_grid(const Image *image, int vertical, int span, int sign, double *low,
                       double *high)
{
    double black[16], grey[16];
    assert_int_equal(find_lines(image, vertical, is_black, black), 1);
    assert_int_equal(find_lines(image, vertical, is_grey, grey), span);
    double first = black[0], last = sign > 0 ? grey[span - 1] : grey[0];
    double spacing = (last - first) / span;
    assert_true(sign * spacing > 0);
    for (int d = 1; d <= span; d++)
        assert_close(grey[sign > 0 ? d - 1 : span - d], first + d * spacing, 1.0);
    *low = first;
    *high = last;
}

/* Where the plot's grid lines are, found from the image: the lowest decade's line (the
 * black axis) and the highest's (the last grey line), as pixel centres. */
typedef struct {
    double x_low, x_high, y_low, y_high;
} Frame;

static Frame find_frame(const Image *image, const int decades[4])
{
    Frame frame;
    check_grid(image, 1, decades[1] - decades[0], +1, &frame.x_low, &frame.x_high);
    check_grid(image, 0, decades[3] - decades[2], -1, &frame.y_low, &frame.y_high);
    return frame;
}

/* The grid: one line per decade each way, the axes (lowest decades) black, the rest
 * grey, evenly spaced; and the grid fills the image but for a margin under a tenth of
 * each side. Checked on the sample plot (5 x 3 decades) and on an empty one (1 x 1). */
static void test_grid_lines_at_decades(void **state)
{
    (void)state;
    int decades[4];
    Image image = sample_plot(300, 200, decades);
    Frame frame = find_frame(&image, decades);
    assert_true(frame.x_low > 0 && frame.x_low < 30);
    assert_true(frame.x_high > 270 && frame.x_high < 300);
    assert_true(frame.y_low > 180 && frame.y_low < 200);
    assert_true(frame.y_high > 0 && frame.y_high < 20);
    image_free(&image);

    image = plot_log_log(NULL, 0, 100, 100, decades);
    assert_non_null(image.pixels);
    find_frame(&image, decades);
    image_free(&image);
}

/* Where the log mapping puts (x, y) between the grid lines, in pixels. */
static void predicted_pixel(const Frame *frame, const int decades[4], double x, double y,
                            double *col, double *row)
{
    double fx = (log10(x) - decades[0]) / (decades[1] - decades[0]);
    double fy = (log10(y) - decades[2]) / (decades[3] - decades[2]);
    *col = frame->x_low + fx * (frame->x_high - frame->x_low);
    *row = frame->y_low + fy * (frame->y_high - frame->y_low);
}

/* Each point is drawn in its series' colour at the pixel the log mapping predicts, and
 * the series' polyline passes through the middle of each segment between its points.
 * The lone point is a square dot (7 x 7 pixels) centred within a pixel of where it
 * belongs, and nothing else has its colour. */
static void test_points_where_the_mapping_puts_them(void **state)
{
    (void)state;
    int decades[4];
    Image image = sample_plot(300, 200, decades);
    Frame frame = find_frame(&image, decades);
    double col[3], row[3];
    for (int i = 0; i < 3; i++) {
        predicted_pixel(&frame, decades, LINE_X[i], LINE_Y[i], &col[i], &row[i]);
        assert_true(same_colour(image_get(&image, (int)lround(col[i]), (int)lround(row[i])), RED));
    }
    for (int i = 0; i < 2; i++) {
        int mid_col = (int)lround(0.5 * (col[i] + col[i + 1]));
        int mid_row = (int)lround(0.5 * (row[i] + row[i + 1]));
        assert_true(same_colour(image_get(&image, mid_col, mid_row), RED));
    }

    double lone_col, lone_row;
    predicted_pixel(&frame, decades, LONE_X[0], LONE_Y[0], &lone_col, &lone_row);
    int count = 0, min_col = image.width, max_col = -1, min_row = image.height, max_row = -1;
    for (int r = 0; r < image.height; r++)
        for (int c = 0; c < image.width; c++)
            if (same_colour(image_get(&image, c, r), BLUE)) {
                count++;
                min_col = c < min_col ? c : min_col;
                max_col = c > max_col ? c : max_col;
                min_row = r < min_row ? r : min_row;
                max_row = r > max_row ? r : max_row;
            }
    assert_int_equal(count, 49);
    assert_int_equal(max_col - min_col, 6);
    assert_int_equal(max_row - min_row, 6);
    assert_close(0.5 * (min_col + max_col), lone_col, 1.0);
    assert_close(0.5 * (min_row + max_row), lone_row, 1.0);
    image_free(&image);
}

/* The background is white: the corners are, most of the picture is, and every pixel
 * is white, a grid colour or a series colour (nothing else is drawn). */
static void test_background_is_white(void **state)
{
    (void)state;
    int decades[4];
    Image image = sample_plot(300, 200, decades);
    assert_true(same_colour(image_get(&image, 0, 0), WHITE));
    assert_true(same_colour(image_get(&image, 299, 0), WHITE));
    assert_true(same_colour(image_get(&image, 0, 199), WHITE));
    assert_true(same_colour(image_get(&image, 299, 199), WHITE));
    long white = 0;
    for (int r = 0; r < image.height; r++)
        for (int c = 0; c < image.width; c++) {
            Vec3 p = image_get(&image, c, r);
            white += same_colour(p, WHITE);
            assert_true(same_colour(p, WHITE) || is_grey(p) || is_black(p) ||
                        same_colour(p, RED) || same_colour(p, BLUE));
        }
    assert_true(white > 0.8 * 300 * 200);
    image_free(&image);
}

/* Points that log axes cannot show (an RMSE of exactly 0, an infinite efficiency, a
 * negative time) are left out: the decades come from the other points, and drawing
 * finishes (with a zero, log10 would give -infinity and the line an endless loop). */
static void test_undrawable_points_left_out(void **state)
{
    (void)state;
    const double x[] = {0.1, 0.0, 10.0, -1.0, 1.0};
    const double y[] = {1.0, 2.0, INFINITY, 3.0, 0.5};
    PlotSeries series = {x, y, 5, vec3(1, 0, 0)};
    int decades[4];
    Image plot = plot_log_log(&series, 1, 200, 100, decades);
    assert_non_null(plot.pixels);
    assert_int_equal(decades[0], -1); /* x from 0.1 and 1 only */
    assert_int_equal(decades[1], 0);
    assert_int_equal(decades[2], -1); /* y from 1 and 0.5 only */
    assert_int_equal(decades[3], 0);
    image_free(&plot);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_decades_by_hand),
        cmocka_unit_test(test_decades_enclose_points),
        cmocka_unit_test(test_image_size),
        cmocka_unit_test(test_grid_lines_at_decades),
        cmocka_unit_test(test_points_where_the_mapping_puts_them),
        cmocka_unit_test(test_background_is_white),
        cmocka_unit_test(test_undrawable_points_left_out),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
