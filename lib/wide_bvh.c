/* wide_bvh.c (chapter 9): making chapter 2's tree four-wide, and traversing it. See
 * wide_bvh.h. */
#include "wide_bvh.h"

#include <float.h>
#include <stdlib.h>

/* Half a binary node's surface area: which inner child to open first. */
static double node_area(const BvhNode *node)
{
    const double(*c)[3] = node->box.corner;
    double x = c[1][0] - c[0][0], y = c[1][1] - c[0][1], z = c[1][2] - c[0][2];
    return x * y + y * z + z * x;
}

/* x rounded to floats outward: below <= x <= above, with room for the slab test's own
 * rounding (docs/chapter9.md derives the step). */
static void float_bracket(double x, float *below, float *above)
{
    float f = (float)x, step = fabsf(f) * 0x1p-21f + 0x1p-100f;
    *below = f - step;
    *above = f + step;
}

/* The binary nodes that binary node `index` stands for in a four-wide node: itself,
 * then its inner nodes opened, the largest first, until there are four or only leaves. */
static int gather_children(const Bvh *binary, int index, int children[WIDE_BVH_WIDTH])
{
    const BvhNode *nodes = binary->nodes;
    int n = 1;
    children[0] = index;
    while (n < WIDE_BVH_WIDTH) {
        int largest = -1;
        for (int k = 0; k < n; k++)
            if (nodes[children[k]].count == 0 &&
                (largest < 0 ||
                 node_area(&nodes[children[k]]) > node_area(&nodes[children[largest]])))
                largest = k;
        if (largest < 0)
            break;
        int opened = children[largest];
        children[largest] = opened + 1;
        children[n++] = nodes[opened].right;
    }
    return n;
}

/* A leaf keeps the binary leaf's double box, widened there by more than the rounding of
 * its slab test. */
static int make_leaf(WideBvh *wide, const BvhNode *node)
{
    WideBvhLeaf *leaf = &wide->leaves[wide->leaf_count];
    *leaf = (WideBvhLeaf){node->box, node->first, node->count};
    return wide->leaf_count++;
}

/* The four-wide node for binary node `index`, and its subtree; returns its number. */
static int make_wide(WideBvh *wide, const Bvh *binary, int index)
{
    int number = wide->node_count++;
    int children[WIDE_BVH_WIDTH];
    int n = gather_children(binary, index, children);
    for (int k = 0; k < WIDE_BVH_WIDTH; k++) {
        WideBvhNode *node = &wide->nodes[number];
        const BvhNode *c = k < n ? &binary->nodes[children[k]] : NULL;
        for (int axis = 0; axis < 3; axis++) {
            float unused;
            node->bounds[0][axis][k] = INFINITY;
            node->bounds[1][axis][k] = -INFINITY;
            if (c) {
                double lower = (c->box.corner[0][axis] - wide->centre[axis]) * wide->scale;
                double upper = (c->box.corner[1][axis] - wide->centre[axis]) * wide->scale;
                float_bracket(lower, &node->bounds[0][axis][k], &unused);
                float_bracket(upper, &unused, &node->bounds[1][axis][k]);
            }
        }
        node->is_leaf[k] = c && c->count > 0;
        node->child[k] = !c             ? -1
                         : c->count > 0 ? make_leaf(wide, c)
                                        : make_wide(wide, binary, children[k]);
    }
    return number;
}

/* The frame: the root's box centred on the origin and scaled by a power of two (so
 * exactly) into [-1, 1]^3, where floats resolve a scene of any size alike. */
static void choose_frame(WideBvh *wide, const BvhNode *root)
{
    double half = 0.0;
    for (int k = 0; k < 3; k++) {
        wide->centre[k] = 0.5 * (root->box.corner[0][k] + root->box.corner[1][k]);
        half = max2(half, 0.5 * (root->box.corner[1][k] - root->box.corner[0][k]));
    }
    int exponent = 0;
    if (half > 0.0 && isfinite(half))
        frexp(half, &exponent);
    wide->scale = ldexp(1.0, -exponent);
}

int wide_bvh_build(WideBvh *wide, const Bvh *binary, BvhPrimitives primitives)
{
    WideBvh empty = {0};
    *wide = empty;
    int n = primitives.triangle_count + primitives.sphere_count;
    if (binary->node_count == 0)
        return 0;
    wide->nodes = malloc((size_t)n * sizeof *wide->nodes);
    wide->leaves = malloc((size_t)n * sizeof *wide->leaves);
    wide->triangles = calloc((size_t)n, sizeof *wide->triangles);
    if (!wide->nodes || !wide->leaves || !wide->triangles) {
        wide_bvh_free(wide);
        return -1;
    }
    wide->primitives = binary->primitives;
    for (int i = 0; i < n; i++)
        if (binary->primitives[i] < primitives.triangle_count)
            wide->triangles[i] = primitives.triangles[binary->primitives[i]];
    choose_frame(wide, &binary->nodes[0]);
    make_wide(wide, binary, 0);
    return 0;
}

void wide_bvh_free(WideBvh *wide)
{
    free(wide->nodes);
    free(wide->leaves);
    free(wide->triangles);
    WideBvh empty = {0};
    *wide = empty;
}

/* What every box test of one ray needs, worked out once: per axis 1/d and which plane
 * of the slab it meets first (the lower one where d >= 0). For the float boxes, in the
 * tree's frame, the origin rounded towards the side that widens each slab, and every
 * number written four times, once per child. (1/d beyond the floats is infinite.) */
typedef struct {
    float origin[2][3][WIDE_BVH_WIDTH]; /* [0] for the near planes, [1] for the far ones */
    float inverse[3][WIDE_BVH_WIDTH];
    int near[3]; /* 0: the lower plane is met first, 1: the upper */
    double exact_origin[3], exact_inverse[3];
} BoxRay;

static inline void box_ray_axis(BoxRay *r, int axis, double origin, double dir, double centre,
                                double scale)
{
    int near = signbit(dir) ? 1 : 0;
    double inverse = 1.0 / dir;
    float below, above;
    float_bracket((origin - centre) * scale, &below, &above);
    float inverse_float =
        fabs(inverse) > FLT_MAX ? (float)copysign(INFINITY, inverse) : (float)inverse;
    for (int k = 0; k < WIDE_BVH_WIDTH; k++) {
        r->origin[0][axis][k] = near ? below : above;
        r->origin[1][axis][k] = near ? above : below;
        r->inverse[axis][k] = inverse_float;
    }
    r->near[axis] = near;
    r->exact_origin[axis] = origin;
    r->exact_inverse[axis] = inverse;
}

/* Narrow each child's interval [near, far] to the slab of one axis: a plain loop over
 * the four children, which the compiler turns into four-wide SSE instructions (`a > b ?
 * a : b` is one of them). */
static inline void clip_to_slab(const WideBvhNode *node, const BoxRay *r, int axis,
                                float near[WIDE_BVH_WIDTH], float far[WIDE_BVH_WIDTH])
{
    const float *near_plane = node->bounds[r->near[axis]][axis];
    const float *far_plane = node->bounds[1 - r->near[axis]][axis];
    for (int k = 0; k < WIDE_BVH_WIDTH; k++) {
        float t_near = (near_plane[k] - r->origin[0][axis][k]) * r->inverse[axis][k];
        float t_far = (far_plane[k] - r->origin[1][axis][k]) * r->inverse[axis][k];
        near[k] = t_near > near[k] ? t_near : near[k];
        far[k] = t_far < far[k] ? t_far : far[k];
    }
}

/* Where the ray enters each child's box within (0, limit), or infinity where it misses
 * it: the slab test of four boxes at once. */
static void children_entry(const WideBvhNode *node, const BoxRay *r, float limit,
                           float entry[WIDE_BVH_WIDTH])
{
    float near[WIDE_BVH_WIDTH] = {0}, far[WIDE_BVH_WIDTH] = {limit, limit, limit, limit};
    clip_to_slab(node, r, 0, near, far);
    clip_to_slab(node, r, 1, near, far);
    clip_to_slab(node, r, 2, near, far);
    for (int k = 0; k < WIDE_BVH_WIDTH; k++)
        entry[k] = near[k] <= far[k] ? near[k] : INFINITY;
}

/* The same test in double for one leaf's box, as chapter 2's tree tests its boxes. */
static int leaf_hit(const WideBvhLeaf *leaf, const BoxRay *r, double tmax)
{
    double near = 0.0, far = tmax;
    for (int k = 0; k < 3; k++) {
        double t_near =
            (leaf->box.corner[r->near[k]][k] - r->exact_origin[k]) * r->exact_inverse[k];
        double t_far =
            (leaf->box.corner[1 - r->near[k]][k] - r->exact_origin[k]) * r->exact_inverse[k];
        near = t_near > near ? t_near : near;
        far = t_far < far ? t_far : far;
    }
    return near <= far * (1.0 + 1e-12);
}

/* Subtrees still to visit, with where the ray enters their box: one entered beyond the
 * nearest hit found since is skipped. Each level adds at most WIDE_BVH_WIDTH - 1 entries. */
typedef struct {
    int child, is_leaf;
    float entry;
} StackEntry;

/* Push child k if the ray meets it, keeping the children pushed since `bottom` sorted
 * farthest first, so that the nearest is popped next. */
static void push_child(const WideBvhNode *node, int k, float entry, StackEntry *stack,
                       int bottom, int *depth)
{
    if (entry == INFINITY)
        return;
    int i = (*depth)++;
    for (; i > bottom && stack[i - 1].entry < entry; i--)
        stack[i] = stack[i - 1];
    stack[i] = (StackEntry){node->child[k], node->is_leaf[k], entry};
}

static double primitive_intersect(const WideBvh *wide, BvhPrimitives p, int entry, Ray ray,
                                  double tmax)
{
    int index = wide->primitives[entry];
    if (index < p.triangle_count)
        return triangle_intersect(&wide->triangles[entry], ray, 0.0, tmax);
    return sphere_intersect(&p.spheres[index - p.triangle_count], ray, 0.0, tmax);
}

/* Both queries: any_hit stops at the first hit found. A non-finite ray hits nothing (its
 * slab tests, all NaN, would rule out no child slot, not even an empty one). */
static int traverse(const WideBvh *wide, BvhPrimitives p, Ray ray, double *tmax, int any_hit)
{
    if (wide->node_count == 0 || !vec3_is_finite(ray.origin) || !vec3_is_finite(ray.dir))
        return -1;
    BoxRay r;
    box_ray_axis(&r, 0, ray.origin.x, ray.dir.x, wide->centre[0], wide->scale);
    box_ray_axis(&r, 1, ray.origin.y, ray.dir.y, wide->centre[1], wide->scale);
    box_ray_axis(&r, 2, ray.origin.z, ray.dir.z, wide->centre[2], wide->scale);
    float below, limit; /* *tmax in the frame, rounded up */
    float_bracket(*tmax * wide->scale, &below, &limit);
    StackEntry stack[(WIDE_BVH_WIDTH - 1) * BVH_MAX_DEPTH + 1];
    stack[0] = (StackEntry){0, 0, 0.0f}; /* the root */
    int depth = 1, nearest = -1;
    double bound = *tmax; /* after a hit, just above its t: a tie is tested too (bvh.h) */
    while (depth > 0) {
        StackEntry e = stack[--depth];
        if (e.entry > limit)
            continue;
        if (!e.is_leaf) {
            float entry[WIDE_BVH_WIDTH];
            children_entry(&wide->nodes[e.child], &r, limit, entry);
            int bottom = depth; /* four calls, not a loop: the entries stay in registers */
            push_child(&wide->nodes[e.child], 0, entry[0], stack, bottom, &depth);
            push_child(&wide->nodes[e.child], 1, entry[1], stack, bottom, &depth);
            push_child(&wide->nodes[e.child], 2, entry[2], stack, bottom, &depth);
            push_child(&wide->nodes[e.child], 3, entry[3], stack, bottom, &depth);
            continue;
        }
        const WideBvhLeaf *leaf = &wide->leaves[e.child];
        if (!leaf_hit(leaf, &r, *tmax))
            continue;
        for (int i = leaf->first; i < leaf->first + leaf->count; i++) {
            double t = primitive_intersect(wide, p, i, ray, bound);
            if (t <= *tmax && (t < *tmax || wide->primitives[i] < nearest)) {
                *tmax = t;
                bound = t * (1.0 + 0x1p-52) + 0x1p-1074; /* the next double, or the one after */
                nearest = wide->primitives[i];
                if (any_hit)
                    return nearest;
                float_bracket(t * wide->scale, &below, &limit);
            }
        }
    }
    return nearest;
}

int wide_bvh_intersect(const WideBvh *wide, BvhPrimitives primitives, Ray ray, double *tmax)
{
    return traverse(wide, primitives, ray, tmax, 0);
}

int wide_bvh_occluded(const WideBvh *wide, BvhPrimitives primitives, Ray ray, double tmax)
{
    return traverse(wide, primitives, ray, &tmax, 1) >= 0;
}
