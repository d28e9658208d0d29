/* bvh.h: a bounding volume hierarchy, so a ray tests a few primitives, not all of them
 * (chapter 1).
 *
 * Every chapter's program uses it, because it changes only how fast a hit is found,
 * never which hit: tests/test_bvh.c checks that it returns exactly what testing every
 * primitive returns. (The report's discussion, §5, asks for speed; this is the first
 * thing every fast renderer does.)
 *
 * A tree of axis-aligned boxes, four children per node. It is built as a binary tree
 * first, top-down: at each node the primitives are sorted by centroid along each axis
 * in turn, and the split minimising the surface area heuristic
 *     cost = area(left box) * count(left) + area(right box) * count(right)
 * is kept (the chance that a ray through the parent hits a child is proportional to the
 * child's surface area). Then every node adopts its grandchildren until it has four
 * children (the largest child is opened first). The room's 38 primitives make about
 * 8 nodes.
 *
 * Degenerate input: exact copies of a primitive answer every ray the same way, so only
 * the first is kept; and primitives whose centroids all coincide cannot be separated
 * by any split, so they become one leaf.
 *
 * Traversal: a ray meets a box when its slab intervals (t at the two planes of each
 * axis) overlap within (0, tmax). Each node keeps its four children's boxes in float,
 * laid out [lower/upper][axis][child], so the four are tested in one pass of four-wide
 * arithmetic: the compiler turns the loop over the children into SSE instructions.
 * The ray brings what every box test needs, computed once per ray: 1/d per axis and its
 * sign, which says which plane of each slab the ray meets first. Children are visited
 * nearer first, and a subtree whose box starts beyond the nearest hit so far is
 * skipped. Shadow rays stop at the first hit of any kind.
 *
 * Float boxes must not lose a hit that the exact box has. The boxes live in the
 * hierarchy's own frame, X = (x - centre) * scale with scale a power of two that maps
 * the scene into [-1, 1]^3, so floats fit any scene's scale. Box planes are rounded
 * outward, the ray's origin towards the side that widens each slab, and a slab overlap
 * is accepted with a relative margin that covers the float arithmetic's rounding
 * (bvh.c). A box test may therefore say "hit" for a ray that just misses; the
 * primitives' own tests, in double, decide.
 *
 * Primitive numbering: 0 .. triangle_count-1 are the triangles, then the spheres.
 */
#ifndef BVH_H
#define BVH_H

#include "sphere.h"
#include "triangle.h"

#ifndef BVH_WIDTH
#define BVH_WIDTH 4 /* children per node */
#endif
#ifndef BVH_LEAF_SIZE
#define BVH_LEAF_SIZE 2 /* most primitives per leaf, unless they cannot be separated */
#endif
#ifndef BVH_NODE_COST
#define BVH_NODE_COST 0.5
#endif

typedef struct {
    /* The children's boxes in the hierarchy's frame: [0] lower, [1] upper corner. An
     * unused slot holds an empty box (lower +inf, upper -inf), which no ray meets. */
    float bounds[2][3][BVH_WIDTH];
    int child[BVH_WIDTH];   /* the child's number among the nodes, or among the leaves */
    int is_leaf[BVH_WIDTH]; /* which of the two */
} BvhNode;

/* A leaf keeps its box in double too, in the scene's coordinates: a float box cannot
 * tell a ray that starts (or ends) RAY_OFFSET off a surface from one that touches it,
 * and every shadow and bounce ray does that. */
typedef struct {
    double bounds[2][3]; /* [0] lower, [1] upper corner */
    int first, count; /* its primitives: entries first .. first + count - 1 of `primitives` */
} BvhLeaf;

typedef struct {
    BvhNode *nodes; /* the root is nodes[0] */
    int node_count;
    BvhLeaf *leaves;
    int leaf_count;
    int *primitives; /* primitive numbers in leaf order (exact copies left out) */
    int primitive_count;
    Vec3 centre;  /* the frame of the float boxes: X = (x - centre) * scale */
    double scale;
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
 * its t, or -1 when nothing is hit. Where several primitives are hit at the same t,
 * any of them. */
int bvh_intersect(const Bvh *bvh, BvhPrimitives primitives, Ray ray, double *tmax);

/* Whether anything is hit with t in (0, tmax). */
int bvh_occluded(const Bvh *bvh, BvhPrimitives primitives, Ray ray, double tmax);

#endif
