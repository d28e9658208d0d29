/* bvh.h (chapter 1): a bounding volume hierarchy, so a ray tests a few primitives, not all.
 *
 * A binary tree of axis-aligned boxes, built top-down: at each node the primitives are
 * sorted by the centres of their boxes along each axis, and the split with the least
 * surface area heuristic, area(left) count(left) + area(right) count(right), is kept.
 * A ray visits the nearer child first and skips a box that starts beyond its nearest
 * hit so far. The tree changes how fast a hit is found, never which (docs/chapter1.md).
 */
#ifndef BVH_H
#define BVH_H

#include "sphere.h"
#include "triangle.h"

/* Levels split by the heuristic; below them a node splits at the median, so that no
 * tree is deeper than BVH_MAX_DEPTH, the traversal stack's size. */
#define BVH_SAH_LEVELS 32
#define BVH_MAX_DEPTH 64

typedef struct {
    double bounds[2][3]; /* the node's box, widened by its rounding: [0] lower, [1] upper */
    int next;            /* inner node: its second child (the first is the next node);
                            leaf: its first entry of primitives[] */
    int count;           /* leaf: its number of primitives; inner node: 0 */
} BvhNode;

typedef struct {
    BvhNode *nodes; /* depth first, the root first */
    int node_count;
    int *primitives; /* primitive numbers in leaf order; exact copies are left out */
    int primitive_count;
} Bvh;

/* The primitives a hierarchy is built over: numbers 0 .. triangle_count - 1 are the
 * triangles, then the spheres. */
typedef struct {
    const Triangle *triangles;
    int triangle_count;
    const Sphere *spheres;
    int sphere_count;
} BvhPrimitives;

/* Build over all the primitives. Returns 0, or -1 when memory runs out. */
int bvh_build(Bvh *bvh, BvhPrimitives primitives);
void bvh_free(Bvh *bvh);

/* The nearest primitive hit with t in (0, *tmax): its number, with *tmax lowered to its
 * t; or -1 when nothing is hit. */
int bvh_intersect(const Bvh *bvh, BvhPrimitives primitives, Ray ray, double *tmax);

/* Whether anything is hit with t in (0, tmax). */
int bvh_occluded(const Bvh *bvh, BvhPrimitives primitives, Ray ray, double tmax);

#endif
