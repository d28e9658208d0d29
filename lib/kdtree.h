/* kdtree.h (chapter 8): a kd-tree over 3-D points, to find every point near a place
 * (Jensen 1996: the photon map).
 *
 * Implicit in one array: the middle point of each range splits it along the axis its
 * points spread most, the halves arranged alike, down to leaves of at most
 * KDTREE_LEAF_SIZE points; no child pointers. The median is moved into place by
 * selection, so the build is expected O(N log N). A fixed-radius query visits the half
 * on the centre's side, and the other half only if the splitting plane is within r.
 */
#ifndef KDTREE_H
#define KDTREE_H

#include "vec.h"

#define KDTREE_LEAF_SIZE 8

typedef struct {
    Vec3 *points;         /* copies of the points, in tree order */
    int *index;           /* index[i]: where points[i] was in the array given to build */
    unsigned char *axis;  /* axis[i]: the split axis of the node at i (0 x, 1 y, 2 z) */
    int count;
} KdTree;

/* Build over `count` points (count may be 0; the points are copied). Returns 0, or -1
 * when memory runs out (the tree is then empty). */
int kdtree_build(KdTree *tree, const Vec3 *points, int count);

void kdtree_free(KdTree *tree);

/* For a caller that has put its own items in the tree's order (item i of the new order
 * being the old item tree->index[i]): from now on every index is the position in that
 * order, index[i] = i. The items one query finds then lie near each other in memory. */
void kdtree_use_tree_order(KdTree *tree);

/* Called once for each point found: its index in the array given to build and its
 * squared distance from the query's centre. */
typedef void (*KdTreeVisit)(int index, double distance2, void *context);

/* Every point p with |p - center| <= radius, each once, in no particular order. */
void kdtree_query_radius(const KdTree *tree, Vec3 center, double radius, KdTreeVisit visit,
                         void *context);

#endif
