/* test_point_grid.c (chapter 8): Tests of the hashed grid (lib/point_grid.c, chapter 8): every
 * fixed-radius query returns exactly the points that testing every point returns, each once.
 *
 * The hard cases are ties, so the point sets are built to have them: points on an
 * integer grid (many equal coordinates on every axis, many points at exactly the query
 * radius, since integer distances are exact in doubles, and many on the cubes' faces),
 * many copies of the same point, all points on one plane (as photons on a floor are), a
 * cluster with an empty hole queried inside the hole, queries far from every point, the
 * empty grid, and points around 0 and far from it. The grids are built for one radius
 * and queried with smaller and larger ones too. Random clouds with random radii cover
 * the rest. And every radius and point set builds in bounded time and memory, at the
 * scales where rounding decides (test_extreme_scales_build_bounded), also a set that
 * rounding files under 27 cubes per point, the bound.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "point_grid.h"
#include "rng.h"

#define MAX_POINTS 4000

typedef struct {
    int found[MAX_POINTS]; /* how many times each point was reported */
    int count;
    const Vec3 *points;
    Vec3 center;
} Found;

static void record(int index, double distance2, void *context)
{
    Found *f = context;
    Vec3 d = vec3_sub(f->points[index], f->center);
    assert_true(distance2 == vec3_dot(d, d)); /* the distance reported is the point's */
    f->found[index]++;
    f->count++;
}

/* The grid's answer equals brute force's; returns how many points were found. */
static int check_query(const PointGrid *grid, const Vec3 *points, int count, Vec3 center,
                       double radius)
{
    static Found f;
    memset(f.found, 0, sizeof f.found);
    f.count = 0;
    f.points = points;
    f.center = center;
    point_grid_query_radius(grid, center, radius, record, &f);
    int expected = 0;
    for (int i = 0; i < count; i++) {
        Vec3 d = vec3_sub(points[i], center);
        int inside = vec3_dot(d, d) <= radius * radius;
        expected += inside;
        if (f.found[i] != inside)
            fail_msg("point %d (%g %g %g), query (%g %g %g) r=%g: found %d times, expected %d",
                     i, points[i].x, points[i].y, points[i].z, center.x, center.y, center.z,
                     radius, f.found[i], inside);
    }
    assert_int_equal(f.count, expected);
    return expected;
}

static void build(PointGrid *grid, const Vec3 *points, int count, double radius)
{
    assert_int_equal(point_grid_build(grid, points, count, radius), 0);
    assert_int_equal(grid->count, count);
}

/* A 10 x 10 x 10 integer grid queried at grid points and half-integers with integer
 * radii: every query has points at exactly its radius. */
static void test_grid_ties_at_the_radius(void **state)
{
    static Vec3 points[1000];
    int n = 0;
    for (int x = 0; x < 10; x++)
        for (int y = 0; y < 10; y++)
            for (int z = 0; z < 10; z++)
                points[n++] = vec3(x, y, z);
    /* Cubes of side 2 and 8: many points on their faces. */
    const double built[2] = {1.0, 4.0};
    for (int g = 0; g < 2; g++) {
        PointGrid grid;
        build(&grid, points, n, built[g]);
        int at_radius = 0;
        for (int i = 0; i < 300; i++) {
            Rng rng = rng_for_sample(3, 0, (uint64_t)i);
            Vec3 c = vec3((int)(10 * rng_uniform(&rng)), (int)(10 * rng_uniform(&rng)),
                          (int)(10 * rng_uniform(&rng)));
            if (i % 2)
                c = vec3_add(c, vec3(0.5, 0.5, 0.0));
            double radius = 1 + (int)(4 * rng_uniform(&rng));
            check_query(&grid, points, n, c, radius);
            for (int k = 0; k < n; k++) {
                Vec3 d = vec3_sub(points[k], c);
                at_radius += vec3_dot(d, d) == radius * radius;
            }
        }
        print_message("    built for %g: %d point-query pairs at exactly the radius\n",
                      built[g], at_radius);
        assert_true(at_radius > 1000);
        point_grid_free(&grid);
    }
}

/* Many copies of a few points: one bucket holds them all. */
static void test_duplicates(void **state)
{
    static Vec3 points[3000];
    for (int i = 0; i < 3000; i++)
        points[i] = i % 3 == 0 ? vec3(1, 2, 3) : i % 3 == 1 ? vec3(1, 2, 4) : vec3(0, 0, 0);
    PointGrid grid;
    build(&grid, points, 3000, 0.5);
    assert_int_equal(check_query(&grid, points, 3000, vec3(1, 2, 3), 0.0), 1000); /* radius 0 */
    assert_int_equal(check_query(&grid, points, 3000, vec3(1, 2, 3.5), 0.5), 2000);
    assert_int_equal(check_query(&grid, points, 3000, vec3(1, 2, 3.5), 0.4999), 0);
    assert_int_equal(check_query(&grid, points, 3000, vec3(0, 0, 0), 10.0), 3000);
    point_grid_free(&grid);
    /* All points the same. */
    for (int i = 0; i < 3000; i++)
        points[i] = vec3(5, 5, 5);
    build(&grid, points, 3000, 1.0);
    assert_int_equal(check_query(&grid, points, 3000, vec3(5, 5, 6), 1.0), 3000);
    assert_int_equal(check_query(&grid, points, 3000, vec3(5, 5, 6), 0.5), 0);
    point_grid_free(&grid);
}

/* Points on the plane z = -5 (like photons on a floor), queried from the plane, above
 * it and below it. */
static void test_points_on_a_plane(void **state)
{
    static Vec3 points[MAX_POINTS];
    for (int i = 0; i < MAX_POINTS; i++) {
        Rng rng = rng_for_sample(5, 0, (uint64_t)i);
        points[i] = vec3(10 * rng_uniform(&rng), 12 * rng_uniform(&rng) - 6, -5);
    }
    PointGrid grid;
    build(&grid, points, MAX_POINTS, 0.6);
    for (int i = 0; i < 200; i++) {
        Rng rng = rng_for_sample(6, 0, (uint64_t)i);
        Vec3 c =
            vec3(10 * rng_uniform(&rng), 12 * rng_uniform(&rng) - 6, -5 + (i % 3 - 1) * 0.1);
        check_query(&grid, points, MAX_POINTS, c, 0.05 + rng_uniform(&rng));
    }
    point_grid_free(&grid);
}

/* A cloud in a shell 2 <= |p| <= 3: queries inside the hole find nothing, queries far
 * away find nothing, and the empty grid finds nothing. */
static void test_empty_regions(void **state)
{
    static Vec3 points[2000];
    for (int i = 0; i < 2000; i++) {
        Rng rng = rng_for_sample(7, 0, (uint64_t)i);
        double z = 2 * rng_uniform(&rng) - 1, phi = 2 * PI * rng_uniform(&rng);
        double s = sqrt(1 - z * z), r = 2 + rng_uniform(&rng);
        points[i] = vec3(r * s * cos(phi), r * s * sin(phi), r * z);
    }
    PointGrid grid;
    build(&grid, points, 2000, 2.0);
    assert_int_equal(check_query(&grid, points, 2000, vec3(0, 0, 0), 1.99), 0);
    assert_int_equal(check_query(&grid, points, 2000, vec3(0.3, -0.2, 0.1), 1.5), 0);
    assert_int_equal(check_query(&grid, points, 2000, vec3(100, 0, 0), 50), 0);
    assert_true(check_query(&grid, points, 2000, vec3(2.5, 0, 0), 0.5) > 0);
    point_grid_free(&grid);

    build(&grid, points, 0, 1.0);
    assert_int_equal(check_query(&grid, points, 0, vec3(0, 0, 0), 1e9), 0);
    point_grid_free(&grid);
    build(&grid, points, 1, 1.0);
    assert_int_equal(check_query(&grid, points, 1, points[0], 0.0), 1);
    point_grid_free(&grid);
}

/* Points on both sides of 0 on every axis, -0 among them, with cube faces at 0; the
 * same of size 1e-30; a cloud 1e20 from the origin built for R = 1e-3 (2^52 cubes of
 * side 2R would not reach it), and one 2^52 from it built for R = 0.5. */
static void test_signs_and_scales(void **state)
{
    static Vec3 points[MAX_POINTS];
    const double scales[4] = {1.0, 1e-30, 1.0, 1.0},
                 offsets[4] = {0.0, 0.0, 1e20, 0x1p52 - 1.0};
    const double built[4] = {0.3, 0.3e-30, 1e-3, 0.5};
    for (int s = 0; s < 4; s++) {
        int n = 0;
        for (int x = -4; x <= 4; x++)
            for (int y = -4; y <= 4; y++)
                for (int z = -4; z <= 4; z++)
                    points[n++] = vec3(offsets[s] + scales[s] * 0.25 * x, scales[s] * 0.25 * y,
                                       z == 0 ? -0.0 : scales[s] * 0.25 * z);
        PointGrid grid;
        build(&grid, points, n, built[s]);
        for (int i = 0; i < 100; i++) {
            Rng rng = rng_for_sample(9, (uint64_t)s, (uint64_t)i);
            Vec3 c = vec3(offsets[s] + scales[s] * (2.5 * rng_uniform(&rng) - 1.25),
                          scales[s] * (i % 4 == 0 ? -0.0 : 2.5 * rng_uniform(&rng) - 1.25),
                          scales[s] * 0.25 * (int)(8 * rng_uniform(&rng) - 4));
            double radius = scales[s] * (i % 2 ? 0.25 : 0.6 * rng_uniform(&rng));
            check_query(&grid, points, n, c, radius);
        }
        point_grid_free(&grid);
    }
}

/* Grids of one to four points, each filed under its 8 cubes, have few buckets (16 to
 * 64), and two cubes of one point often share one (about 1 pair in 50 with 16): 300
 * such grids at random places, queried at each point and around it, must still find
 * each point once. */
static void test_few_points(void **state)
{
    Vec3 points[4];
    for (int trial = 0; trial < 300; trial++) {
        Rng rng = rng_for_sample(10, 0, (uint64_t)trial);
        int n = 1 + trial % 4;
        for (int i = 0; i < n; i++)
            points[i] = vec3(100 * rng_uniform(&rng) - 50, 100 * rng_uniform(&rng) - 50,
                             100 * rng_uniform(&rng) - 50);
        PointGrid grid;
        build(&grid, points, n, 0.5);
        for (int i = 0; i < n; i++) {
            check_query(&grid, points, n, points[i], 0.5);
            for (int k = 0; k < 10; k++) {
                Vec3 c =
                    vec3_add(points[i], vec3(rng_uniform(&rng) - 0.5, rng_uniform(&rng) - 0.5,
                                             rng_uniform(&rng) - 0.5));
                check_query(&grid, points, n, c, 0.5);
            }
        }
        point_grid_free(&grid);
    }
}

/* Random clouds of every size up to MAX_POINTS, random centres and radii. */
static void test_random_clouds(void **state)
{
    static Vec3 points[MAX_POINTS];
    for (int cloud = 0; cloud < 20; cloud++) {
        Rng rng = rng_for_sample(8, 1, (uint64_t)cloud);
        int n = 1 + (int)(MAX_POINTS * rng_uniform(&rng));
        for (int i = 0; i < n; i++)
            points[i] = vec3(rng_uniform(&rng), 3 * rng_uniform(&rng), 0.2 * rng_uniform(&rng));
        PointGrid grid;
        build(&grid, points, n, 0.3 * rng_uniform(&rng) + 1e-3);
        for (int i = 0; i < 50; i++) {
            Vec3 c = vec3(1.2 * rng_uniform(&rng) - 0.1, 3.2 * rng_uniform(&rng) - 0.1,
                          0.4 * rng_uniform(&rng) - 0.1);
            check_query(&grid, points, n, c, 0.3 * rng_uniform(&rng));
        }
        point_grid_free(&grid);
    }
}

/* Every radius > 0 and every point set builds in bounded time and memory, and answers
 * as testing every point does: at most 27 filings per point (the build is linear in the
 * count of points) and buckets at most four times the filings, at scales where rounding
 * decides: |p| ~ 5 with R = 1e-11 (a ball of 1e-11 among coordinates whose rounding is
 * 1e-15), R = 1e-300 among points 1e-299 apart (squared distances underflow to 0, so
 * every pair is "within" R), subnormal coordinates and radius, R = 1e300, points at
 * 1e300, all points equal, coordinates from 1e-300 to 1e300 in one set, points near the
 * largest double, and infinite and NaN coordinates (never near anything). */
typedef struct {
    const char *name;
    Vec3 base;
    double spread; /* points at base + spread (u - 1/2), u uniform in [0, 1)^3 */
    double radius;
    int wild; /* 1: coordinates +-10^e, e uniform in [-300, 300]; 2: some not finite */
} Extreme;

static Vec3 extreme_point(const Extreme *e, Rng *rng)
{
    double u[3];
    for (int a = 0; a < 3; a++) {
        double x = rng_uniform(rng);
        u[a] = e->wild == 1 ? (x < 0.5 ? -1 : 1) * pow(10.0, 600 * rng_uniform(rng) - 300)
                            : e->spread * (x - 0.5);
    }
    return vec3_add(e->base, vec3(u[0], u[1], u[2]));
}

static void test_extreme_scales_build_bounded(void **state)
{
    static Vec3 points[1000];
    const Extreme cases[] = {
        {"|p| ~ 5, R = 1e-11", {5, -3, 4}, 4e-11, 1e-11, 0},
        {"R = 1e-300, points 1e-299 apart", {0, 0, 0}, 1e-299, 1e-300, 0},
        {"subnormal coordinates and radius", {0, 0, 0}, 1e-310, 1e-320, 0},
        {"R = 1e300", {1, 2, 3}, 10, 1e300, 0},
        {"points at 1e300, R = 1", {1e300, -1e300, 5e299}, 1e299, 1.0, 0},
        {"points at 1e300, R = 1e299", {1e300, -1e300, 5e299}, 1e299, 1e299, 0},
        {"all points equal", {7, 7, 7}, 0.0, 0.5, 0},
        {"1e-300 to 1e300 in one set, R = 1", {0, 0, 0}, 0.0, 1.0, 1},
        {"1e-300 to 1e300 in one set, R = 1e-100", {0, 0, 0}, 0.0, 1e-100, 1},
        {"near the largest double", {1.5e308, -1.5e308, 0}, 1e307, 1.0, 0},
        {"R = 1e308: no cubes, every point tested", {1, 2, 3}, 10, 1e308, 0},
        {"infinite and NaN coordinates among others", {1, 1, 1}, 1.0, 0.1, 2},
    };
    const int n = 1000;
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        const Extreme *e = &cases[k];
        Rng rng = rng_for_sample(12, (uint64_t)k, 0);
        for (int i = 0; i < n; i++) {
            points[i] = i % 7 == 3 ? points[i - 1] : extreme_point(e, &rng);
            if (e->wild == 2 && i % 10 == 0)
                points[i] = i % 20 ? vec3(INFINITY, 1, 1) : vec3(1, NAN, 1);
        }
        print_message("    %-44s", e->name);
        fflush(stdout); /* a build that hangs shows where */
        PointGrid grid;
        build(&grid, points, n, e->radius);
        int filings = point_grid_filings(&grid);
        print_message(" %5.2f filings per point, %d buckets\n", (double)filings / n,
                      grid.buckets);
        assert_true(filings <= 27 * n);
        assert_true(grid.buckets <= 4 * filings + 1);
        int found = 0;
        for (int q = 0; q < 300; q++) {
            Vec3 c = extreme_point(e, &rng);
            if (q % 3)
                c = points[(int)(n * rng_uniform(&rng))];
            if (!vec3_is_finite(c))
                c = e->base;
            const double radii[4] = {e->radius, 0.5 * e->radius, 0.0, 2.0 * e->radius};
            found += check_query(&grid, points, n, c, radii[q % 4]);
        }
        assert_true(found > 0);
        point_grid_free(&grid);
    }
}

/* Rounding can file a point under three cubes on an axis: where its ball's ends, p - R'
 * and p + R', round away from each other across two cube boundaries. Points (x, x, x)
 * for which it does so on every axis (found by a search of coordinates near powers of
 * two, R far below the widening) are filed 27 times each, the bound; the grid must take
 * them and answer as testing every point does. */
static void test_three_cubes_on_every_axis(void **state)
{
    static const double coordinates[3] = {0x1.000000018f06p+24, 0x1.00000000eda35p+0,
                                          -0x1.00000000b00edp+19},
                        radii[3] = {0x1.7850e1da07a72p-43, 0x1.141b7a072911ep-66,
                                    0x1.69fc82615a7f1p-40};
    static Vec3 points[100];
    for (int k = 0; k < 3; k++) {
        double x = coordinates[k];
        for (int i = 0; i < 100; i++)
            points[i] = vec3(x, x, x);
        PointGrid grid;
        build(&grid, points, 100, radii[k]);
        int filings = point_grid_filings(&grid);
        print_message("    x = %.17g, R = %g: %.2f filings per point\n", x, radii[k],
                      filings / 100.0);
        assert_int_equal(filings, 27 * 100);
        assert_int_equal(check_query(&grid, points, 100, points[0], radii[k]), 100);
        assert_int_equal(
            check_query(&grid, points, 100, vec3(x, x, nextafter(x, 0.0)), radii[k]), 0);
        point_grid_free(&grid);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_extreme_scales_build_bounded), /* first: it names a hang */
        cmocka_unit_test(test_three_cubes_on_every_axis),
        cmocka_unit_test(test_grid_ties_at_the_radius),
        cmocka_unit_test(test_duplicates),
        cmocka_unit_test(test_points_on_a_plane),
        cmocka_unit_test(test_empty_regions),
        cmocka_unit_test(test_signs_and_scales),
        cmocka_unit_test(test_few_points),
        cmocka_unit_test(test_random_clouds),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
