/* bvh.h (chapter 1): a bounding volume hierarchy, so a ray tests a few primitives, not all.
 *
 * A binary tree of boxes is built top-down by the surface area heuristic, then every
 * node adopts grandchildren until it has four children, so that a ray tests four boxes
 * in one pass of four-wide float arithmetic. Float boxes are rounded outward in the
 * tree's own frame; each leaf keeps its box in double too. The tree changes how fast a
 * hit is found, never which (docs/chapter1.md, section 6).
 */
#ifndef BVH_H
#define BVH_H

#include "sphere.h"
#include "triangle.h"

#define BVH_WIDTH 4 /* children per node */

/* Levels split by the heuristic; below them a node splits at the median, so that no
 * tree is deeper than BVH_MAX_DEPTH, which bounds the traversal stack. */
#define BVH_SAH_LEVELS 32
#define BVH_MAX_DEPTH 64

/* The children's boxes in the tree's frame, [0] lower and [1] upper corner, the four
 * children's numbers for one plane side by side; an unused child's box is empty (lower
 * +inf, upper -inf). child[k] is a number among the nodes, or among the leaves. */
typedef struct {
    float bounds[2][3][BVH_WIDTH];
    int child[BVH_WIDTH], is_leaf[BVH_WIDTH];
} BvhNode;

typedef struct {
    double bounds[2][3]; /* its box in the scene's coordinates, widened by its rounding */
    int first, count;    /* its primitives: entries first .. first + count - 1 below */
} BvhLeaf;

typedef struct {
    BvhNode *nodes; /* the root is nodes[0] */
    BvhLeaf *leaves;
    int node_count, leaf_count;
    int *primitives;     /* primitive numbers in leaf order; exact copies are left out */
    Triangle *triangles; /* triangles[i]: a copy of primitive primitives[i], if a triangle */
    int primitive_count;
    double centre[3];    /* the float boxes' frame: X = (x - centre) * scale */
    double scale;
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
