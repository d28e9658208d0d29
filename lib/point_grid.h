/* point_grid.h (chapter 8): a hashed grid over 3-D points, to find every point near a
 * place (the photon map's lookup: a pass's photons are filed in it, and each diffuse vertex
 * of a camera path asks it for the photons near it).
 *
 * Space is cut into cubes of side 2R', R' the radius R the grid is built for widened a
 * little for rounding. Each point is filed under every cube its ball of radius R' meets
 * (2 x 2 x 2 of them, never more than 3 x 3 x 3), so a query of radius r <= R looks in
 * one cube only, the one that holds its centre, and finds each point there once. Only
 * cubes with points cost memory: a cube's coordinates are hashed to one of about twice
 * as many buckets as filings. Build time and memory grow as the count of points, for
 * every R and every point set (docs/chapter8.md).
 */
#ifndef POINT_GRID_H
#define POINT_GRID_H

#include "vec.h"

/* The most points a grid takes: its filings, at most 27 per point, and their buckets
 * then stay below 2^30. */
#define POINT_GRID_MAX_POINTS (1 << 24)

typedef struct {
    Vec3 *points;     /* copies of the points, in the order given */
    Vec3 *filed_cube; /* filing f: points[filed_point[f]] under the cube filed_cube[f] */
    int *filed_point;
    int *start; /* bucket b holds filings start[b] .. start[b + 1] - 1 */
    int count,
        buckets;   /* buckets = 0: no cubes (radius beyond ~1e300), queries test every point */
    double radius; /* R */
    double reach;  /* R': R widened for rounding, half a cube's side */
} PointGrid;

/* Build over `count` points (count may be 0; the points are copied) for queries of a
 * radius 0 < `radius` < infinity. Returns 0, or -1 when memory runs out, the radius is
 * not such a number or there are more than POINT_GRID_MAX_POINTS points (the grid is
 * then empty). */
int point_grid_build(PointGrid *grid, const Vec3 *points, int count, double radius);

void point_grid_free(PointGrid *grid);

/* The number of filings, at most 27 per point. */
int point_grid_filings(const PointGrid *grid);

/* Called once for each point found: its index in the array given to build and its
 * squared distance from the query's centre. */
typedef void (*PointVisit)(int index, double distance2, void *context);

/* Every point p with |p - center|^2 <= radius^2 (as computed in doubles), each once,
 * in no particular order. A radius above the grid's tests every point. */
void point_grid_query_radius(const PointGrid *grid, Vec3 center, double radius,
                             PointVisit visit, void *context);

#endif
