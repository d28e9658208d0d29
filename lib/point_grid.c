/* point_grid.c (chapter 8): building and querying the hashed grid. See point_grid.h. */
#include "point_grid.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>

/* Cube coordinates below this in size are integers that convert to int64_t exactly. */
#define LARGEST_CUBE 0x1p52

/* The cube that holds p, its integer coordinates; NaN or infinite far out. */
static Vec3 cube_of(Vec3 p, double radius)
{
    double inverse_side = 0.5 / radius;
    return vec3(floor(p.x * inverse_side), floor(p.y * inverse_side), floor(p.z * inverse_side));
}

static int is_ordinary(Vec3 cube)
{
    return fabs(cube.x) < LARGEST_CUBE && fabs(cube.y) < LARGEST_CUBE && fabs(cube.z) < LARGEST_CUBE;
}

/* Teschner et al.'s spatial hash of an ordinary cube: each coordinate times a large
 * prime, XORed. */
static int bucket_of(Vec3 cube, int buckets)
{
    uint64_t h = (uint64_t)(int64_t)cube.x * 73856093u ^ (uint64_t)(int64_t)cube.y * 19349663u ^
                 (uint64_t)(int64_t)cube.z * 83492791u;
    return (int)(h & (uint64_t)(buckets - 1));
}

/* The cubes that the ball of radius R around p meets, low[axis] .. high[axis], its box
 * widened a little for the rounding of the distances a query computes. Returns 0 if
 * they are not all ordinary. */
static int cubes_met(Vec3 p, double radius, Vec3 *low, Vec3 *high)
{
    Vec3 widen = vec3_scale(vec3(fabs(p.x) + radius, fabs(p.y) + radius, fabs(p.z) + radius), 1e-9);
    Vec3 reach = vec3_add(vec3(radius, radius, radius), widen);
    *low = cube_of(vec3_sub(p, reach), radius);
    *high = cube_of(vec3_add(p, reach), radius);
    return is_ordinary(*low) && is_ordinary(*high);
}

/* File every point under the cubes its ball meets, counting the filings per bucket
 * (start[b + 1]) when `next` is NULL, else putting filing number next[b]++ in place. */
static void file_points(PointGrid *g, int *next)
{
    for (int i = 0; i < g->count; i++) {
        Vec3 low, high;
        if (!cubes_met(g->points[i], g->radius, &low, &high)) {
            if (next)
                g->unfiled[g->unfiled_count++] = i;
            continue;
        }
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

int point_grid_build(PointGrid *grid, const Vec3 *points, int count, double radius)
{
    /* The filings, counted: at most 3 cubes per axis for each point. */
    size_t n = count > 0 ? (size_t)count : 1;
    PointGrid g = {malloc(n * sizeof *g.points), NULL, NULL, NULL, malloc(n * sizeof *g.unfiled),
                   count, 1, 0, radius};
    int ok = g.points && g.unfiled && count <= (1 << 24);
    for (int i = 0; ok && i < count; i++)
        g.points[i] = points[i];
    long filings = 0;
    for (int i = 0; ok && i < count; i++) {
        Vec3 low, high;
        if (cubes_met(points[i], radius, &low, &high))
            filings += (long)(high.x - low.x + 1) * (long)(high.y - low.y + 1) * (long)(high.z - low.z + 1);
    }
    while (g.buckets / 2 < filings) /* a power of two, at least twice the filings */
        g.buckets *= 2;
    size_t m = filings > 0 ? (size_t)filings : 1;
    g.filed_cube = malloc(m * sizeof *g.filed_cube);
    g.filed_point = malloc(m * sizeof *g.filed_point);
    g.start = calloc((size_t)g.buckets + 1, sizeof *g.start);
    int *next = malloc((size_t)g.buckets * sizeof *next);
    ok = ok && g.filed_cube && g.filed_point && g.start && next;
    if (ok) {
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
    free(grid->unfiled);
    *grid = (PointGrid){NULL, NULL, NULL, NULL, NULL, 0, 0, 0, 0.0};
}

static void visit_if_near(const PointGrid *grid, int i, Vec3 center, double radius2,
                          PointVisit visit, void *context)
{
    Vec3 d = vec3_sub(grid->points[i], center);
    double distance2 = vec3_dot(d, d);
    if (distance2 <= radius2)
        visit(i, distance2, context);
}

void point_grid_query_radius(const PointGrid *grid, Vec3 center, double radius, PointVisit visit,
                             void *context)
{
    double radius2 = radius * radius;
    Vec3 cube = cube_of(center, grid->radius);
    if (!(radius <= grid->radius) || !is_ordinary(cube)) {
        for (int i = 0; i < grid->count; i++)
            visit_if_near(grid, i, center, radius2, visit, context);
        return;
    }
    int b = bucket_of(cube, grid->buckets);
    for (int f = grid->start[b]; f < grid->start[b + 1]; f++) {
        Vec3 c = grid->filed_cube[f]; /* a bucket holds other cubes too */
        if (c.x == cube.x && c.y == cube.y && c.z == cube.z)
            visit_if_near(grid, grid->filed_point[f], center, radius2, visit, context);
    }
    for (int k = 0; k < grid->unfiled_count; k++)
        visit_if_near(grid, grid->unfiled[k], center, radius2, visit, context);
}
