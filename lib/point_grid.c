/* point_grid.c (chapter 8): building and querying the hashed grid. See point_grid.h;
 * docs/chapter8.md, section 3, proves the bounds. */
#include "point_grid.h"

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

/* R' = R + WIDENING (|p| + R) + UNDERFLOW, |p| the largest coordinate of the points: far
 * more than the rounding of a distance at such coordinates (a few 1e-16 of them), and
 * than the distances whose squares underflow to 0 (below 1e-161). */
#define WIDENING 1e-12
#define UNDERFLOW 1e-150

/* The cube that holds p: floor(p / (2 R')) on each axis, as the doubles round. */
static Vec3 cube_of(Vec3 p, double reach)
{
    double inverse_side = 0.5 / reach;
    return vec3(floor(p.x * inverse_side), floor(p.y * inverse_side),
                floor(p.z * inverse_side));
}

/* Teschner et al.'s spatial hash of a cube: each coordinate times a large prime, XORed. */
static int bucket_of(Vec3 cube, int buckets)
{
    uint64_t h = (uint64_t)(int64_t)cube.x * 73856093u ^ (uint64_t)(int64_t)cube.y * 19349663u ^
                 (uint64_t)(int64_t)cube.z * 83492791u;
    return (int)(h & (uint64_t)(buckets - 1));
}

/* The cubes that the ball of radius R' around p meets: low[axis] .. high[axis]. */
static void cubes_met(Vec3 p, double reach, Vec3 *low, Vec3 *high)
{
    Vec3 r = vec3(reach, reach, reach);
    *low = cube_of(vec3_sub(p, r), reach);
    *high = cube_of(vec3_add(p, r), reach);
}

/* File every point under the cubes its ball meets, counting the filings per bucket
 * (start[b + 1]) when `next` is NULL, else putting filing number next[b]++ in place.
 * A point with an infinite or NaN coordinate is near no centre: it is not filed. */
static void file_points(PointGrid *g, int *next)
{
    for (int i = 0; i < g->count; i++) {
        Vec3 low, high;
        if (!vec3_is_finite(g->points[i]))
            continue;
        cubes_met(g->points[i], g->reach, &low, &high);
        for (double z = low.z; z <= high.z; z++)
            for (double y = low.y; y <= high.y; y++)
                for (double x = low.x; x <= high.x; x++) {
                    int b = bucket_of(vec3(x, y, z), g->buckets);
                    if (!next) {
                        g->start[b + 1]++;
                        continue;
                    }
                    int f = next[b]++;
                    g->filed_cube[f] = vec3(x, y, z);
                    g->filed_point[f] = i;
                }
    }
}

/* R' for the points; 0 when a cube's side or a point's reach would overflow. */
static double widened_radius(const Vec3 *points, int count, double radius)
{
    double size = 0.0;
    for (int i = 0; i < count; i++)
        if (vec3_is_finite(points[i]))
            size = fmax(size, vec3_max_abs(points[i]));
    double reach = radius + WIDENING * size + WIDENING * radius + UNDERFLOW;
    return size + 2.0 * reach <= DBL_MAX ? reach : 0.0;
}

/* The filings, counted in 64 bits: at most 27 per point (docs/chapter8.md). */
static int64_t count_filings(const PointGrid *g)
{
    int64_t filings = 0;
    for (int i = 0; g->reach > 0.0 && i < g->count; i++) {
        Vec3 low, high;
        if (!vec3_is_finite(g->points[i]))
            continue;
        cubes_met(g->points[i], g->reach, &low, &high);
        filings += (int64_t)(high.x - low.x + 1) * (int64_t)(high.y - low.y + 1) *
                   (int64_t)(high.z - low.z + 1);
    }
    return filings;
}

int point_grid_build(PointGrid *grid, const Vec3 *points, int count, double radius)
{
    size_t n = count > 0 ? (size_t)count : 1;
    PointGrid g = {malloc(n * sizeof *g.points), NULL, NULL, NULL, count, 0, radius, 0.0};
    int ok = g.points && count >= 0 && count <= POINT_GRID_MAX_POINTS && radius > 0.0 &&
             radius < INFINITY;
    for (int i = 0; ok && i < count; i++)
        g.points[i] = points[i];
    if (ok)
        g.reach = widened_radius(points, count, radius);
    int64_t filings = ok ? count_filings(&g) : 0;
    ok = ok && filings <= 27 * (int64_t)count;
    if (ok && g.reach > 0.0) {
        g.buckets = 1;
        while (g.buckets / 2 < filings) /* a power of two, at least twice the filings */
            g.buckets *= 2;
    }
    g.filed_cube = malloc((size_t)(filings > 0 ? filings : 1) * sizeof *g.filed_cube);
    g.filed_point = malloc((size_t)(filings > 0 ? filings : 1) * sizeof *g.filed_point);
    g.start = calloc((size_t)g.buckets + 1, sizeof *g.start);
    int *next = malloc(((size_t)g.buckets + 1) * sizeof *next);
    ok = ok && g.filed_cube && g.filed_point && g.start && next;
    if (ok && g.buckets > 0) {
        /* A counting sort: count per bucket, sum to where each bucket starts, place. */
        file_points(&g, NULL);
        for (int b = 0; b < g.buckets; b++) {
            g.start[b + 1] += g.start[b];
            next[b] = g.start[b];
        }
        file_points(&g, next);
    }
    free(next);
    *grid = g;
    if (!ok) {
        point_grid_free(grid);
        return -1;
    }
    return 0;
}

void point_grid_free(PointGrid *grid)
{
    free(grid->points);
    free(grid->filed_cube);
    free(grid->filed_point);
    free(grid->start);
    *grid = (PointGrid){NULL, NULL, NULL, NULL, 0, 0, 0.0, 0.0};
}

int point_grid_filings(const PointGrid *grid)
{
    return grid->buckets > 0 ? grid->start[grid->buckets] : 0;
}

static void visit_if_near(const PointGrid *grid, int i, Vec3 center, double radius2,
                          PointVisit visit, void *context)
{
    Vec3 d = vec3_sub(grid->points[i], center);
    double distance2 = vec3_dot(d, d);
    if (distance2 <= radius2)
        visit(i, distance2, context);
}

void point_grid_query_radius(const PointGrid *grid, Vec3 center, double radius,
                             PointVisit visit, void *context)
{
    double radius2 = radius * radius;
    if (!(radius <= grid->radius) || radius2 == INFINITY || grid->buckets == 0) {
        for (int i = 0; i < grid->count; i++)
            visit_if_near(grid, i, center, radius2, visit, context);
        return;
    }
    /* Every filed cube lies within 10^12 of the origin: a centre whose cube is farther,
     * or not a number, has no point near it. */
    Vec3 cube = cube_of(center, grid->reach);
    if (!(fabs(cube.x) < 0x1p52 && fabs(cube.y) < 0x1p52 && fabs(cube.z) < 0x1p52))
        return;
    int b = bucket_of(cube, grid->buckets);
    for (int f = grid->start[b]; f < grid->start[b + 1]; f++) {
        Vec3 c = grid->filed_cube[f]; /* a bucket holds other cubes too */
        if (c.x == cube.x && c.y == cube.y && c.z == cube.z)
            visit_if_near(grid, grid->filed_point[f], center, radius2, visit, context);
    }
}
