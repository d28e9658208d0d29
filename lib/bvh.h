/* bvh.h (chapter 2): a bounding volume hierarchy, so a ray tests a few primitives, not all.
 *
 * A binary tree of boxes, each holding its node's primitives, split in two by the surface
 * area heuristic. A ray visits a node only if it meets its box, the nearer child first,
 * and skips a box it enters beyond the nearest hit so far. Boxes are widened by their
 * own rounding, and of hits at equal t the lower primitive number wins, in every way a
 * query is answered: the tree changes how fast a hit is found, never which.
 */
#ifndef BVH_H
#define BVH_H

#include "sphere.h"
#include "triangle.h"

/* No tree is deeper: a node at that depth is a leaf, whatever it holds. It bounds the
 * traversal's stack. */
#define BVH_MAX_DEPTH 64

/* An axis-aligned box: corner[0] the lower corner, corner[1] the upper. */
typedef struct {
    double corner[2][3];
} Box;

/* A node of the tree. An inner node's first child is the next node, and `right` is its
 * second; its count is 0. A leaf holds `count` primitives: the entries `first` to
 * first + count - 1 of the tree's leaf order. */
typedef struct {
    Box box;
    int right;
    int first;
    int count;
} BvhNode;

typedef struct {
    BvhNode *nodes; /* in depth-first order, so the root is nodes[0] */
    int node_count;
    int *primitives; /* the primitives' numbers, in the order the leaves hold them */
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

/* The nearest primitive hit with t in (0, *tmax) (of two at equal t, the lower number):
 * its number, with *tmax lowered to its t; or -1 when nothing is hit. */
int bvh_intersect(const Bvh *bvh, BvhPrimitives primitives, Ray ray, double *tmax);

/* Whether anything is hit with t in (0, tmax). */
int bvh_occluded(const Bvh *bvh, BvhPrimitives primitives, Ray ray, double tmax);

#endif
