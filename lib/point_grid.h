/* point_grid.h (chapter 8): a hashed grid over 3-D points, to find every point near a
 * place (the photon map's lookup, as in stochastic progressive photon mapping).
 *
 * Space is cut into cubes of side 2R, R the radius the grid is built for. Each point is
 * filed under every cube that its ball of radius R meets (2 x 2 x 2 of them, or fewer),
 * so a query of radius r <= R looks in one cube only, the one that holds its centre, and
 * finds each point there once. Only cubes with points cost memory: a cube's coordinates
 * are hashed to one of about twice as many buckets as filings, a bucket's filings side
 * by side. A query of a larger radius tests every point.
 */
#ifndef POINT_GRID_H
#define POINT_GRID_H

#include "vec.h"

typedef struct {
    Vec3 *points;     /* copies of the points, in the order given */
    Vec3 *filed_cube; /* filing f: points[filed_point[f]] under the cube filed_cube[f] */
    int *filed_point;
    int *start;       /* bucket b holds filings start[b] .. start[b + 1] - 1 */
    int *unfiled;     /* points too far from the origin for cubes: every query tests them */
    int count, buckets, unfiled_count;
    double radius;    /* R */
} PointGrid;

/* Build over `count` points (count may be 0; the points are copied) for queries of
 * `radius` > 0. Returns 0, or -1 when memory runs out or there are more than 2^24
 * points (the grid is then empty). */
int point_grid_build(PointGrid *grid, const Vec3 *points, int count, double radius);

void point_grid_free(PointGrid *grid);

/* Called once for each point found: its index in the array given to build and its
 * squared distance from the query's centre. */
typedef void (*PointVisit)(int index, double distance2, void *context);

/* Every point p with |p - center| <= radius, each once, in no particular order. */
void point_grid_query_radius(const PointGrid *grid, Vec3 center, double radius, PointVisit visit,
                             void *context);

#endif
