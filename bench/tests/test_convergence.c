/* test_convergence.c (bench, chapter 7): the convergence plot and what it says
 * (convergence.h), by hand on series of table rows.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>

#include "assert_close.h"
#include "convergence.h"

static TableRow row(double seconds, double rmse, double spread, int infinite_variance)
{
    TableRow r = {0};
    r.seconds = seconds;
    r.rmse = rmse;
    r.rmse_spread = spread;
    r.infinite_variance = infinite_variance;
    return r;
}

/* Falls at every step, or not: a step that stays level, one that rises, a NaN. */
static void test_falls(void **state)
{
    TableRow falling[3] = {row(1, 4, NAN, 0), row(2, 2, NAN, 0), row(4, 1, NAN, 0)};
    assert_true(convergence_falls(falling, 3));
    assert_true(convergence_falls(falling, 1));
    TableRow level[3] = {row(1, 4, NAN, 0), row(2, 2, NAN, 0), row(4, 2, NAN, 0)};
    assert_false(convergence_falls(level, 3));
    TableRow rising[3] = {row(1, 4, NAN, 0), row(2, 5, NAN, 0), row(4, 1, NAN, 0)};
    assert_false(convergence_falls(rising, 3));
    TableRow unmeasured[2] = {row(1, 4, NAN, 0), row(2, NAN, NAN, 0)};
    assert_false(convergence_falls(unmeasured, 2));
}

/* The slope from the first row to the last, whatever lies between: an error that falls
 * as 1 / sqrt(time) has slope -1/2; one that falls as 1 / time, -1. */
static void test_slope(void **state)
{
    TableRow root[3] = {row(1, 1, NAN, 0), row(3, 7, NAN, 0), row(16, 0.25, NAN, 0)};
    assert_close(convergence_slope(root, 3), -0.5, 1e-15);
    TableRow linear[2] = {row(0.5, 8, NAN, 0), row(4, 1, NAN, 0)};
    assert_close(convergence_slope(linear, 2), -1.0, 1e-15);
}

/* Two settings of two steps: the points, their bars (none without a spread), the
 * infinite-variance mark from a setting's first row, and the guide: over the last
 * setting's times (2 to 8 s), from twice its first error (2 x 3), falling as
 * 1 / sqrt(time) to 3. Too many settings or steps are refused. */
static void test_plot(void **state)
{
    TableRow rows[4] = {row(1, 4, 0.5, 1), row(2, 3, NAN, 0), row(2, 3, 1, 0),
                        row(8, 1, 0.25, 1)};
    const char *labels[2] = {"first", "second"};
    const Vec3 colours[2] = {{1, 0, 0}, {0, 0, 1}};
    ConvergencePlot plot;
    assert_int_equal(convergence_plot(&plot, rows, 2, 2, labels, colours), 0);
    assert_int_equal(plot.plot.series_count, 3);
    const PlotSeries *first = &plot.series[0], *second = &plot.series[1],
                     *guide = &plot.series[2];
    assert_string_equal(first->label, "first");
    assert_true(first->colour.x == 1 && second->colour.z == 1);
    assert_int_equal(first->count, 2);
    assert_true(first->x[1] == 2 && first->y[1] == 3);
    assert_true(first->y_low[0] == 3.5 && first->y_high[0] == 4.5);
    assert_true(first->y_low[1] == 3 && first->y_high[1] == 3);
    assert_true(second->y_low[1] == 0.75 && second->y_high[1] == 1.25);
    assert_int_equal(first->infinite_variance, 1);
    assert_int_equal(second->infinite_variance, 0);
    assert_int_equal(guide->count, 2);
    assert_true(guide->x[0] == 2 && guide->x[1] == 8);
    assert_close(guide->y[0], 6, 1e-15);
    assert_close(guide->y[1], 3, 1e-15);
    assert_true(guide->dashed && !guide->markers);
    assert_true(plot.plot.x.scale == PLOT_LOG && plot.plot.y.scale == PLOT_LOG);
    assert_int_equal(
        convergence_plot(&plot, rows, CONVERGENCE_MAX_SERIES + 1, 1, labels, colours), -1);
    assert_int_equal(
        convergence_plot(&plot, rows, 1, CONVERGENCE_MAX_STEPS + 1, labels, colours), -1);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_falls),
        cmocka_unit_test(test_slope),
        cmocka_unit_test(test_plot),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
