/* bvh.h (chapter 1): a bounding volume hierarchy, so a ray tests a few primitives, not all of them.
 *
 * Every chapter's program uses it, because it changes only how fast a hit is found,
 * never which hit: tests/test_bvh.c checks that it returns exactly what testing every
 * primitive returns. (The report's discussion, §5, asks for speed; this is the first
 * thing every fast renderer does.)
 *
 * A tree of axis-aligned boxes with four children per node, built in two steps.
 *  1. A binary tree, top-down: at each node the primitives are sorted by the centre of
 *     their box along each axis in turn, and the split minimising the surface area
 *     heuristic
 *         cost = area(left box) * count(left) + area(right box) * count(right)
 *     is kept (the chance that a ray through the parent meets a child is proportional
 *     to the child's surface area). Splitting goes on down to single primitives.
 *  2. Every node adopts grandchildren, the largest child's first, until it has four
 *     children: a ray then tests four boxes at once where it tested two.
 * The room's 40 primitives (38 triangles, 2 spheres) make 10 nodes and 25 leaves
 * (a quad's two triangles share a box, and so a leaf).
 *
 * Degenerate input (issue 9 asked for 200,000 copies of one triangle to stay fast):
 * exact copies of a primitive answer every ray the same way, so only the first is
 * kept; and primitives whose box centres all coincide cannot be told apart by any
 * split, so they share one leaf.
 *
 * Traversal: a ray meets a box when its slab intervals (the t at the two planes of
 * each axis) overlap within (0, tmax). Each node keeps its four children's boxes in
 * float, laid out [lower/upper][axis][child], so that the four are tested in one pass
 * of four-wide arithmetic: the compiler turns the loop over the children into SSE
 * instructions. The ray brings what every box test needs, worked out once per ray:
 * 1/d per axis and its sign, which says which plane of each slab the ray meets first.
 * Children are visited nearer first, and a subtree whose box starts beyond the nearest
 * hit so far is skipped. Shadow rays stop at the first hit of any kind.
 *
 * Float boxes must not lose a hit that the exact box has. They live in the hierarchy's
 * own frame, X = (x - centre) * scale with scale a power of two that maps the scene
 * into [-1, 1]^3, so that floats suit a scene of any size. Their planes are rounded
 * outward, and the ray's origin towards the side that widens each slab, by enough to
 * cover the rounding of the slab test's own arithmetic too (bvh.c). So a float box may
 * say "hit" to a ray that just misses, never the other way round. A float, though, resolves
 * only 1e-7 of the scene, and every bounce and shadow ray starts RAY_OFFSET (1e-10,
 * ray.h) off the surface it leaves; a shadow ray also ends that close to the light.
 * The float boxes of those surfaces cannot turn such rays away, so each leaf keeps its
 * box in double too, tested before its primitives (fewer triangle tests, measured
 * faster). A leaf's triangles are copied together in leaf order, so that its tests
 * read neighbouring memory.
 *
 * Primitive numbering: 0 .. triangle_count-1 are the triangles, then the spheres.
 */
#ifndef BVH_H
#define BVH_H

#include "sphere.h"
#include "triangle.h"

#define BVH_WIDTH 4 /* children per node */

/* Levels of the binary tree split by the heuristic; below them the builder splits at
 * the median, so no tree is deeper than BVH_MAX_DEPTH (32 + 31 halvings of at most
 * 2^31 primitives, and one to spare), which bounds the traversal stack. */
#define BVH_SAH_LEVELS 32
#define BVH_MAX_DEPTH 64

typedef struct {
    /* The children's boxes in the hierarchy's frame: [0] lower, [1] upper corner. An
     * unused slot holds an empty box (lower +inf, upper -inf), which no ray meets. */
    float bounds[2][3][BVH_WIDTH];
    int child[BVH_WIDTH];   /* the child's number among the nodes, or among the leaves */
    int is_leaf[BVH_WIDTH]; /* which of the two */
} BvhNode;

typedef struct {
    double bounds[2][3]; /* its box in the scene's coordinates, [0] lower, [1] upper */
    int first, count;    /* its primitives: entries first .. first + count - 1 below */
} BvhLeaf;

typedef struct {
    BvhNode *nodes; /* the root is nodes[0] */
    int node_count;
    BvhLeaf *leaves;
    int leaf_count;
    int *primitives;     /* primitive numbers in leaf order (exact copies left out) */
    Triangle *triangles; /* triangles[i] is a copy of primitive primitives[i], when that
                            is a triangle */
    int primitive_count;
    Vec3 centre;         /* the frame of the float boxes: X = (x - centre) * scale */
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
