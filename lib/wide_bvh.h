/* wide_bvh.h (chapter 9): chapter 2's tree made four-wide, with float boxes.
 *
 * Every node of the binary tree (bvh.h) adopts grandchildren until it has four
 * children, so a ray tests four boxes in one pass of four-wide float arithmetic and
 * meets half as many nodes on its way down. The float boxes are rounded outward in the
 * tree's own frame, and each leaf keeps its double box, so the tree still changes only
 * how fast a hit is found, never which (docs/chapter9.md, section 2).
 */
#ifndef WIDE_BVH_H
#define WIDE_BVH_H

#include "bvh.h"

#define WIDE_BVH_WIDTH 4 /* children per node */

/* The children's boxes in the tree's frame, [0] lower and [1] upper corner, the four
 * children's numbers for one plane side by side; an unused child's box is empty (lower
 * +inf, upper -inf). child[k] is a number among the nodes, or among the leaves. */
typedef struct {
    float bounds[2][3][WIDE_BVH_WIDTH];
    int child[WIDE_BVH_WIDTH], is_leaf[WIDE_BVH_WIDTH];
} WideBvhNode;

typedef struct {
    Box box;          /* in the scene's coordinates, as the binary tree's */
    int first, count; /* its primitives: entries first .. first + count - 1 below */
} WideBvhLeaf;

typedef struct {
    WideBvhNode *nodes; /* the root is nodes[0] */
    WideBvhLeaf *leaves;
    int node_count, leaf_count;
    const int *primitives; /* the binary tree's leaf order */
    Triangle *triangles;   /* triangles[i]: a copy of primitive primitives[i], if a triangle */
    double centre[3];      /* the float boxes' frame: X = (x - centre) * scale */
    double scale;
} WideBvh;

/* Build from the binary tree over the same primitives (it must outlive this one).
 * Returns 0, or -1 when memory runs out. */
int wide_bvh_build(WideBvh *wide, const Bvh *binary, BvhPrimitives primitives);
void wide_bvh_free(WideBvh *wide);

/* As bvh_intersect and bvh_occluded (bvh.h). */
int wide_bvh_intersect(const WideBvh *wide, BvhPrimitives primitives, Ray ray, double *tmax);
int wide_bvh_occluded(const WideBvh *wide, BvhPrimitives primitives, Ray ray, double tmax);

#endif
