/* test_stats.c (bench, chapter 1): what a render costs: the monotonic clock and the ray
 * counts (stats.h; RayCounts, lib/render.h).
 *
 * The clock must never run backwards and must measure a known sleep; processor time
 * (chapter 8's time budget) must count work and not sleep; ray counts from several
 * threads must add up per purpose, and their total must be the sum of the three.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <time.h>

#include "stats.h"

/* Readings taken back to back never decrease: a monotonic clock is not set back by
 * time adjustments, so a render's duration is never negative. */
static void test_clock_is_monotonic(void **state)
{
    double previous = stats_now();
    assert_true(isfinite(previous));
    for (int i = 0; i < 100000; i++) {
        double now = stats_now();
        assert_true(now >= previous);
        previous = now;
    }
}

/* A 20 ms sleep measures between 15 ms (the clock's resolution is far finer, and sleep
 * never returns early) and 1 s (generous, for a loaded machine): the clock counts
 * seconds, not milliseconds or ticks. */
static void test_clock_measures_a_sleep(void **state)
{
    struct timespec twenty_ms = {0, 20000000};
    double start = stats_now();
    assert_int_equal(nanosleep(&twenty_ms, NULL), 0);
    double elapsed = stats_now() - start;
    if (!(elapsed > 0.015 && elapsed < 1.0))
        fail_msg("a 20 ms sleep measured %.6f s", elapsed);
}

/* Processor time (chapter 8's time budget): a 20 ms sleep uses almost none of it, and
 * 50 ms of busy work on this thread uses at least 40 ms of it (it can be more only by
 * other threads, and there are none) and at most the wall-clock time it took. */
static void test_processor_time(void **state)
{
    struct timespec twenty_ms = {0, 20000000};
    double cpu = stats_cpu_now();
    assert_int_equal(nanosleep(&twenty_ms, NULL), 0);
    double slept = stats_cpu_now() - cpu;
    if (!(slept >= 0.0 && slept < 0.01))
        fail_msg("a 20 ms sleep used %.6f s of processor time", slept);
    volatile double sink = 0.0;
    double wall = stats_now(), start = stats_cpu_now();
    while (stats_cpu_now() - start < 0.05)
        sink = sink + 1.0;
    double busy = stats_cpu_now() - start, took = stats_now() - wall;
    if (!(busy >= 0.04 && busy <= took + 1e-3))
        fail_msg("busy work: %.6f s of processor time in %.6f s", busy, took);
}

/* Adding per-thread counts sums each purpose separately, and the total is camera +
 * bounce + shadow. Counts beyond 32 bits (a long render) do not wrap. */
static void test_ray_counts_add_and_total(void **state)
{
    RayCounts sum = {0, 0, 0};
    const RayCounts threads[] = {{100, 250, 30}, {7, 0, 1}, {0, 5000000000ULL, 0}};
    for (int i = 0; i < 3; i++)
        ray_counts_add(&sum, threads[i]);
    assert_true(sum.camera == 107);
    assert_true(sum.bounce == 5000000250ULL);
    assert_true(sum.shadow == 31);
    assert_true(ray_counts_total(sum) == 107 + 5000000250ULL + 31);
    assert_true(ray_counts_total((RayCounts){0, 0, 0}) == 0);
    ray_counts_add(&sum, (RayCounts){0, 0, 0});
    assert_true(ray_counts_total(sum) == 5000000388ULL);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_clock_is_monotonic),
        cmocka_unit_test(test_clock_measures_a_sleep),
        cmocka_unit_test(test_processor_time),
        cmocka_unit_test(test_ray_counts_add_and_total),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
