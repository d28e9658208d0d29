/* kdtree.h (chapter 8): a kd-tree over 3-D points, to find every point near a place.
 * Jensen, "Global illumination using photon maps" (1996): the photon map.
 *
 * Introduced in chapter 8, where the points are where photons landed and the question
 * asked at every diffuse hit is "which photons lie within r of x?". Testing all N
 * photons costs N per query; a balanced kd-tree answers in about log N plus the number
 * found.
 *
 * The tree is implicit in one array. The points of a range [lo, hi) are arranged so
 * that the middle one, mid = (lo + hi) / 2, splits them along one axis: every point of
 * [lo, mid) has a coordinate <= the middle point's on that axis, every point of
 * [mid + 1, hi) one >= it. The two halves are arranged the same way, recursively, down
 * to single points. Building picks, for each range, the axis along which its points
 * spread most (so photons lying on a floor, all at the same height, are never split by
 * height), and moves the median into the middle by selection (Hoare's FIND, expected
 * linear time, and fine with many equal coordinates); the whole build is expected
 * O(N log N). No child pointers are stored: a node's children are the halves of its
 * range.
 *
 * Ranges of at most KDTREE_LEAF_SIZE points are leaves, not split further: a query
 * tests all their points, which lie side by side in memory, instead of descending
 * three more levels (each a jump to another cache line).
 *
 * Fixed-radius query: at a node, report its point if |p - c|^2 <= r^2 (points at
 * exactly r are included), then visit the half on c's side of the split; visit the
 * other half only if the splitting plane is within r of c, since every point there is
 * at least that far away along the axis. At a leaf, test every point.
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
