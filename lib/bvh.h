/* bvh.h (chapter 1): a bounding volume hierarchy, so a ray tests a few primitives, not all of them.
 *
 * Introduced in chapter 7 (the report's discussion, §5, asks for speed; this is the
 * first thing every fast renderer does). Every chapter's program uses it, because it
 * changes only how fast a hit is found, never which hit: tests/test_bvh.c checks that
 * it returns exactly what testing every primitive returns (scene_intersect_all).
 *
 * A binary tree of axis-aligned boxes. Each leaf holds at most BVH_LEAF_SIZE
 * primitives; each inner node's box encloses its two children's. It is built top-down:
 * at each node the primitives are sorted by centroid along each axis in turn, and the
 * split minimising the surface area heuristic
 *     cost = area(left box) * count(left) + area(right box) * count(right)
 * is kept (the chance a ray through the parent hits a child is proportional to the
 * child's surface area). The room's 38 primitives make about 40 nodes.
 *
 * Traversal: a ray meets a box when its slab intervals (t at the two planes of each
 * axis, via 1/d) overlap within (0, tmax). Each inner node keeps a copy of its two
 * children's boxes, laid out [axis][child], so that both are tested in one pass over
 * the same few numbers (the compiler does the two at once: it made the renderer about
 * 40% faster than testing each child's own node). Children are visited nearer first,
 * and a subtree whose box starts beyond the nearest hit so far is skipped. Shadow rays
 * stop at the first hit of any kind.
 *
 * Primitive numbering: 0 .. triangle_count-1 are the triangles, then the spheres.
 */
#ifndef BVH_H
#define BVH_H

#include "sphere.h"
#include "triangle.h"

#define BVH_LEAF_SIZE 2

typedef struct {
    Vec3 lower, upper; /* the box */
    int first;         /* leaf: first entry in the primitive order; inner: right child */
    int count;         /* leaf: number of primitives; inner: 0 (left child is next) */
    /* Inner nodes: the boxes of the left and right child, [axis][child]. */
    double child_lower[3][2], child_upper[3][2];
} BvhNode;

typedef struct {
    BvhNode *nodes;
    int node_count;
    int *primitives;   /* primitive numbers in leaf order */
    int primitive_count;
} Bvh;

/* The primitives a hierarchy is built over (the scene's arrays). */
typedef struct {
    const Triangle *triangles;
    int triangle_count;
    const Sphere *spheres;
    int sphere_count;
} BvhPrimitives;

/* Build over all the primitives. Returns 0, or -1 when memory runs out. */
int bvh_build(Bvh *bvh, BvhPrimitives primitives);
void bvh_free(Bvh *bvh);

/* Nearest primitive hit with t in (0, *tmax): returns its number and lowers *tmax to
 * its t, or -1 when nothing is hit. */
int bvh_intersect(const Bvh *bvh, BvhPrimitives primitives, Ray ray, double *tmax);

/* Whether anything is hit with t in (0, tmax). */
int bvh_occluded(const Bvh *bvh, BvhPrimitives primitives, Ray ray, double tmax);

#endif
