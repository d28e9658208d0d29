/* bvh.c (chapter 1): building and traversing the hierarchy. See bvh.h. */
#include "bvh.h"

#include <float.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    double lower[3], upper[3];
} Box;

static const Box EMPTY = {{INFINITY, INFINITY, INFINITY}, {-INFINITY, -INFINITY, -INFINITY}};

static Box box_union(Box a, Box b)
{
    for (int k = 0; k < 3; k++) {
        a.lower[k] = min2(a.lower[k], b.lower[k]);
        a.upper[k] = max2(a.upper[k], b.upper[k]);
    }
    return a;
}

static Box box_of(Vec3 lower, Vec3 upper)
{
    Box box = {{lower.x, lower.y, lower.z}, {upper.x, upper.y, upper.z}};
    return box;
}

/* Half the surface area: the heuristic compares areas, so the factor 2 is left out. */
static double box_area(Box box)
{
    double x = box.upper[0] - box.lower[0], y = box.upper[1] - box.lower[1];
    double z = box.upper[2] - box.lower[2];
    return x < 0.0 ? 0.0 : x * y + y * z + z * x;
}

static double box_size(Box box)
{
    return max2(box.upper[0] - box.lower[0],
                max2(box.upper[1] - box.lower[1], box.upper[2] - box.lower[2]));
}

static Box primitive_box(BvhPrimitives p, int index)
{
    if (index < p.triangle_count) {
        const Triangle *t = &p.triangles[index];
        Vec3 b = vec3_add(t->v0, t->e1), c = vec3_add(t->v0, t->e2);
        return box_union(box_union(box_of(t->v0, t->v0), box_of(b, b)), box_of(c, c));
    }
    const Sphere *s = &p.spheres[index - p.triangle_count];
    Vec3 r = vec3(s->radius, s->radius, s->radius);
    return box_of(vec3_sub(s->center, r), vec3_add(s->center, r));
}

/* A primitive's defining numbers: two primitives are exact copies when their keys are
 * equal, and a copy answers every ray as the first does, so only the first is kept. */
typedef struct {
    Vec3 key[4];
    int primitive;
} Keyed;

static void primitive_key(BvhPrimitives p, int index, Keyed *keyed)
{
    Vec3 zero = vec3(0, 0, 0);
    keyed->primitive = index;
    if (index < p.triangle_count) {
        const Triangle *t = &p.triangles[index];
        memcpy(keyed->key, (Vec3[4]){t->v0, t->e1, t->e2, zero}, sizeof keyed->key);
    } else { /* the last number 1 tells a sphere from a triangle */
        const Sphere *s = &p.spheres[index - p.triangle_count];
        memcpy(keyed->key, (Vec3[4]){s->center, vec3(s->radius, 0, 0), zero, vec3(0, 0, 1)},
               sizeof keyed->key);
    }
}

static int compare_keyed(const void *a, const void *b)
{
    const Keyed *ka = a, *kb = b;
    int order = memcmp(ka->key, kb->key, sizeof ka->key);
    return order != 0 ? order : (ka->primitive > kb->primitive) - (ka->primitive < kb->primitive);
}

/* The primitives without exact copies into kept[]; returns their count, or -1. */
static int without_copies(BvhPrimitives p, int n, int *kept)
{
    Keyed *keyed = malloc((size_t)n * sizeof *keyed);
    if (!keyed)
        return -1;
    for (int i = 0; i < n; i++)
        primitive_key(p, i, &keyed[i]);
    qsort(keyed, (size_t)n, sizeof *keyed, compare_keyed);
    int count = 0;
    for (int i = 0; i < n; i++)
        if (i == 0 || memcmp(keyed[i].key, keyed[i - 1].key, sizeof keyed[i].key) != 0)
            kept[count++] = keyed[i].primitive;
    free(keyed);
    return count;
}

typedef struct {
    double centre; /* twice the box centre along the axis being sorted */
    int primitive;
} Item;

static int compare_items(const void *a, const void *b)
{
    const Item *ia = a, *ib = b;
    if (ia->centre != ib->centre)
        return ia->centre < ib->centre ? -1 : 1;
    return (ia->primitive > ib->primitive) - (ia->primitive < ib->primitive);
}

/* The binary tree, built first. */
typedef struct {
    Box box;
    int left, right;  /* inner node: its children */
    int first, count; /* leaf: its entries of the leaf order; inner node: count 0 */
} BinaryNode;

typedef struct {
    BinaryNode *nodes;
    int node_count, *order; /* order: the primitives in leaf order */
    const Box *boxes;       /* of every primitive */
    double *right_area;     /* scratch for the heuristic */
} Builder;

static void sort_along(const Builder *b, Item *items, int count, int axis)
{
    for (int i = 0; i < count; i++) {
        const Box *box = &b->boxes[items[i].primitive];
        items[i].centre = box->lower[axis] + box->upper[axis];
    }
    qsort(items, (size_t)count, sizeof *items, compare_items);
}

/* The split (first item of the right child) with the least heuristic cost over the
 * three axes; the items are left sorted along its axis. */
static int best_split(const Builder *b, Item *items, int count)
{
    double best_cost = INFINITY;
    int best_axis = 0, best = count / 2;
    for (int axis = 0; axis < 3; axis++) {
        sort_along(b, items, count, axis);
        Box right = EMPTY, left = EMPTY;
        for (int i = count - 1; i > 0; i--) {
            right = box_union(right, b->boxes[items[i].primitive]);
            b->right_area[i] = box_area(right);
        }
        for (int split = 1; split < count; split++) {
            left = box_union(left, b->boxes[items[split - 1].primitive]);
            double cost = box_area(left) * split + b->right_area[split] * (count - split);
            if (cost < best_cost) {
                best_cost = cost;
                best_axis = axis;
                best = split;
            }
        }
    }
    sort_along(b, items, count, best_axis);
    return best;
}

/* The node over items[0 .. count-1], whose primitives go to order[first ...]; returns
 * its number. A node whose box centres all coincide cannot be split by them: a leaf. */
static int build(Builder *b, Item *items, int count, int first, int level)
{
    int index = b->node_count++;
    Box box = EMPTY, centres = EMPTY;
    for (int i = 0; i < count; i++) {
        Box primitive = b->boxes[items[i].primitive];
        box = box_union(box, primitive);
        for (int k = 0; k < 3; k++)
            primitive.lower[k] = primitive.upper[k] = primitive.lower[k] + primitive.upper[k];
        centres = box_union(centres, primitive);
    }
    BinaryNode *node = &b->nodes[index];
    *node = (BinaryNode){box, -1, -1, first, count};
    int axis = 0;
    for (int k = 1; k < 3; k++)
        if (centres.upper[k] - centres.lower[k] > centres.upper[axis] - centres.lower[axis])
            axis = k;
    if (count == 1 || !(centres.upper[axis] > centres.lower[axis])) {
        for (int i = 0; i < count; i++)
            b->order[first + i] = items[i].primitive;
        return index;
    }
    int split = count / 2;
    if (level < BVH_SAH_LEVELS)
        split = best_split(b, items, count);
    else
        sort_along(b, items, count, axis);
    node->count = 0;
    b->nodes[index].left = build(b, items, split, first, level + 1);
    b->nodes[index].right = build(b, items + split, count - split, first + split, level + 1);
    return index;
}

/* x rounded to floats outward: below <= x <= above, with room for the slab test's own
 * rounding (docs/chapter1.md derives the step). */
static void float_bracket(double x, float *below, float *above)
{
    float f = (float)x, step = fabsf(f) * 0x1p-21f + 0x1p-100f;
    *below = f - step;
    *above = f + step;
}

/* The children binary node `index` stands for in a four-wide node: itself, then its
 * inner nodes opened, the largest first, until there are four or only leaves. */
static int gather_children(const BinaryNode *nodes, int index, int children[BVH_WIDTH])
{
    int n = 1;
    children[0] = index;
    while (n < BVH_WIDTH) {
        int largest = -1;
        for (int k = 0; k < n; k++)
            if (nodes[children[k]].count == 0 &&
                (largest < 0 || box_area(nodes[children[k]].box) > box_area(nodes[children[largest]].box)))
                largest = k;
        if (largest < 0)
            break;
        const BinaryNode *opened = &nodes[children[largest]];
        children[largest] = opened->left;
        children[n++] = opened->right;
    }
    return n;
}

/* A leaf's double box, widened by more than the rounding of its slab test and the
 * triangles' edge slack (triangle.h), so that it never turns away a ray that hits. */
static int make_leaf(Bvh *bvh, const BinaryNode *node)
{
    BvhLeaf *leaf = &bvh->leaves[bvh->leaf_count];
    *leaf = (BvhLeaf){.first = node->first, .count = node->count};
    const Box *box = &node->box;
    double widen = 1e-12 * box_size(*box) + 0x1p-1000;
    for (int k = 0; k < 3; k++) {
        leaf->bounds[0][k] = box->lower[k] - (fabs(box->lower[k]) * 0x1p-50 + widen);
        leaf->bounds[1][k] = box->upper[k] + (fabs(box->upper[k]) * 0x1p-50 + widen);
    }
    return bvh->leaf_count++;
}

/* The four-wide node for binary node `index`, and its subtree; returns its number. */
static int make_wide(Bvh *bvh, const BinaryNode *nodes, int index)
{
    int wide = bvh->node_count++;
    int children[BVH_WIDTH];
    int n = gather_children(nodes, index, children);
    for (int k = 0; k < BVH_WIDTH; k++) {
        BvhNode *node = &bvh->nodes[wide];
        const BinaryNode *c = k < n ? &nodes[children[k]] : NULL;
        for (int axis = 0; axis < 3; axis++) {
            float unused;
            node->bounds[0][axis][k] = INFINITY;
            node->bounds[1][axis][k] = -INFINITY;
            if (c) {
                double lower = (c->box.lower[axis] - bvh->centre[axis]) * bvh->scale;
                double upper = (c->box.upper[axis] - bvh->centre[axis]) * bvh->scale;
                float_bracket(lower, &node->bounds[0][axis][k], &unused);
                float_bracket(upper, &unused, &node->bounds[1][axis][k]);
            }
        }
        node->is_leaf[k] = c && c->count > 0;
        node->child[k] = !c ? -1 : c->count > 0 ? make_leaf(bvh, c) : make_wide(bvh, nodes, children[k]);
    }
    return wide;
}

/* The frame: the scene's box centred on the origin and scaled by a power of two (so
 * exactly) into [-1, 1]^3, where floats resolve a scene of any size alike. */
static void choose_frame(Bvh *bvh, Box box)
{
    for (int k = 0; k < 3; k++)
        bvh->centre[k] = 0.5 * (box.lower[k] + box.upper[k]);
    double half = 0.5 * box_size(box);
    int exponent = 0;
    if (half > 0.0 && isfinite(half))
        frexp(half, &exponent);
    bvh->scale = ldexp(1.0, -exponent);
}

int bvh_build(Bvh *bvh, BvhPrimitives primitives)
{
    int n = primitives.triangle_count + primitives.sphere_count;
    memset(bvh, 0, sizeof *bvh);
    if (n == 0)
        return 0;
    Box *boxes = malloc((size_t)n * sizeof *boxes);
    int *kept = malloc((size_t)n * sizeof *kept);
    Item *items = malloc((size_t)n * sizeof *items);
    double *right_area = malloc((size_t)n * sizeof *right_area);
    BinaryNode *binary = malloc((size_t)(2 * n - 1) * sizeof *binary);
    bvh->nodes = malloc((size_t)n * sizeof *bvh->nodes);
    bvh->leaves = malloc((size_t)n * sizeof *bvh->leaves);
    bvh->primitives = malloc((size_t)n * sizeof *bvh->primitives);
    bvh->triangles = calloc((size_t)n, sizeof *bvh->triangles);
    int count = -1;
    if (boxes && kept && items && right_area && binary && bvh->nodes && bvh->leaves &&
        bvh->primitives && bvh->triangles)
        count = without_copies(primitives, n, kept);
    if (count > 0) {
        Box all = EMPTY;
        for (int i = 0; i < n; i++)
            boxes[i] = primitive_box(primitives, i);
        for (int i = 0; i < count; i++) {
            items[i].primitive = kept[i];
            all = box_union(all, boxes[kept[i]]);
        }
        Builder builder = {binary, 0, bvh->primitives, boxes, right_area};
        build(&builder, items, count, 0, 0);
        bvh->primitive_count = count;
        for (int i = 0; i < count; i++)
            if (bvh->primitives[i] < primitives.triangle_count)
                bvh->triangles[i] = primitives.triangles[bvh->primitives[i]];
        choose_frame(bvh, all);
        make_wide(bvh, binary, 0);
    }
    free(boxes);
    free(kept);
    free(items);
    free(right_area);
    free(binary);
    if (count < 0) {
        bvh_free(bvh);
        return -1;
    }
    return 0;
}

void bvh_free(Bvh *bvh)
{
    free(bvh->nodes);
    free(bvh->leaves);
    free(bvh->primitives);
    free(bvh->triangles);
    memset(bvh, 0, sizeof *bvh);
}

/* What every box test of one ray needs, worked out once: per axis 1/d and which plane
 * of the slab it meets first (the lower one where d >= 0). For the float boxes, in the
 * tree's frame, the origin rounded towards the side that widens each slab, and every
 * number written four times, once per child. (1/d beyond the floats is infinite.) */
typedef struct {
    float origin[2][3][BVH_WIDTH]; /* [0] for the near planes, [1] for the far ones */
    float inverse[3][BVH_WIDTH];
    int near[3];                   /* 0: the lower plane is met first, 1: the upper */
    double exact_origin[3], exact_inverse[3];
} BoxRay;

static inline void box_ray_axis(BoxRay *r, int axis, double origin, double dir, double centre,
                                double scale)
{
    int near = signbit(dir) ? 1 : 0;
    double inverse = 1.0 / dir;
    float below, above;
    float_bracket((origin - centre) * scale, &below, &above);
    float inverse_float = fabs(inverse) > FLT_MAX ? (float)copysign(INFINITY, inverse) : (float)inverse;
    for (int k = 0; k < BVH_WIDTH; k++) {
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
static inline void clip_to_slab(const BvhNode *node, const BoxRay *r, int axis,
                                float near[BVH_WIDTH], float far[BVH_WIDTH])
{
    const float *near_plane = node->bounds[r->near[axis]][axis];
    const float *far_plane = node->bounds[1 - r->near[axis]][axis];
    for (int k = 0; k < BVH_WIDTH; k++) {
        float t_near = (near_plane[k] - r->origin[0][axis][k]) * r->inverse[axis][k];
        float t_far = (far_plane[k] - r->origin[1][axis][k]) * r->inverse[axis][k];
        near[k] = t_near > near[k] ? t_near : near[k];
        far[k] = t_far < far[k] ? t_far : far[k];
    }
}

/* Where the ray enters each child's box within (0, limit), or infinity where it misses
 * it: the slab test of four boxes at once. */
static void children_entry(const BvhNode *node, const BoxRay *r, float limit,
                           float entry[BVH_WIDTH])
{
    float near[BVH_WIDTH] = {0}, far[BVH_WIDTH] = {limit, limit, limit, limit};
    clip_to_slab(node, r, 0, near, far);
    clip_to_slab(node, r, 1, near, far);
    clip_to_slab(node, r, 2, near, far);
    for (int k = 0; k < BVH_WIDTH; k++)
        entry[k] = near[k] <= far[k] ? near[k] : INFINITY;
}

/* The same test in double for one leaf's box. A slab the ray runs along (d = 0) gives
 * t = +-inf, or NaN on a plane, which the comparisons skip: the slab counts as met. */
static int leaf_hit(const BvhLeaf *leaf, const BoxRay *r, double tmax)
{
    double near = 0.0, far = tmax;
    for (int k = 0; k < 3; k++) {
        double t_near = (leaf->bounds[r->near[k]][k] - r->exact_origin[k]) * r->exact_inverse[k];
        double t_far = (leaf->bounds[1 - r->near[k]][k] - r->exact_origin[k]) * r->exact_inverse[k];
        near = t_near > near ? t_near : near;
        far = t_far < far ? t_far : far;
    }
    return near <= far * (1.0 + 1e-12);
}

/* Subtrees still to visit, with where the ray enters their box: one entered beyond the
 * nearest hit found since is skipped. Each level adds at most BVH_WIDTH - 1 entries. */
typedef struct {
    int child, is_leaf;
    float entry;
} StackEntry;

/* Push child k if the ray meets it, keeping the children pushed since `bottom` sorted
 * farthest first, so that the nearest is popped next. */
static void push_child(const BvhNode *node, int k, float entry, StackEntry *stack,
                       int bottom, int *depth)
{
    if (entry == INFINITY)
        return;
    int i = (*depth)++;
    for (; i > bottom && stack[i - 1].entry < entry; i--)
        stack[i] = stack[i - 1];
    stack[i] = (StackEntry){node->child[k], node->is_leaf[k], entry};
}

static double primitive_intersect(const Bvh *bvh, BvhPrimitives p, int entry, Ray ray,
                                  double tmax)
{
    int index = bvh->primitives[entry];
    if (index < p.triangle_count)
        return triangle_intersect(&bvh->triangles[entry], ray, 0.0, tmax);
    return sphere_intersect(&p.spheres[index - p.triangle_count], ray, 0.0, tmax);
}

/* Both queries: any_hit stops at the first hit found. A non-finite ray hits nothing. */
static int traverse(const Bvh *bvh, BvhPrimitives p, Ray ray, double *tmax, int any_hit)
{
    if (bvh->node_count == 0 || !vec3_is_finite(ray.origin) || !vec3_is_finite(ray.dir))
        return -1;
    BoxRay r;
    box_ray_axis(&r, 0, ray.origin.x, ray.dir.x, bvh->centre[0], bvh->scale);
    box_ray_axis(&r, 1, ray.origin.y, ray.dir.y, bvh->centre[1], bvh->scale);
    box_ray_axis(&r, 2, ray.origin.z, ray.dir.z, bvh->centre[2], bvh->scale);
    float below, limit; /* *tmax in the frame, rounded up */
    float_bracket(*tmax * bvh->scale, &below, &limit);
    StackEntry stack[(BVH_WIDTH - 1) * BVH_MAX_DEPTH + 1];
    stack[0] = (StackEntry){0, 0, 0.0f}; /* the root */
    int depth = 1, nearest = -1;
    while (depth > 0) {
        StackEntry e = stack[--depth];
        if (e.entry > limit)
            continue;
        if (!e.is_leaf) {
            float entry[BVH_WIDTH];
            children_entry(&bvh->nodes[e.child], &r, limit, entry);
            int bottom = depth; /* four calls, not a loop: the entries stay in registers */
            push_child(&bvh->nodes[e.child], 0, entry[0], stack, bottom, &depth);
            push_child(&bvh->nodes[e.child], 1, entry[1], stack, bottom, &depth);
            push_child(&bvh->nodes[e.child], 2, entry[2], stack, bottom, &depth);
            push_child(&bvh->nodes[e.child], 3, entry[3], stack, bottom, &depth);
            continue;
        }
        const BvhLeaf *leaf = &bvh->leaves[e.child];
        if (!leaf_hit(leaf, &r, *tmax))
            continue;
        for (int i = leaf->first; i < leaf->first + leaf->count; i++) {
            double t = primitive_intersect(bvh, p, i, ray, *tmax);
            if (t < *tmax) {
                *tmax = t;
                nearest = bvh->primitives[i];
                if (any_hit)
                    return nearest;
                float_bracket(t * bvh->scale, &below, &limit);
            }
        }
    }
    return nearest;
}

int bvh_intersect(const Bvh *bvh, BvhPrimitives primitives, Ray ray, double *tmax)
{
    return traverse(bvh, primitives, ray, tmax, 0);
}

int bvh_occluded(const Bvh *bvh, BvhPrimitives primitives, Ray ray, double tmax)
{
    return traverse(bvh, primitives, ray, &tmax, 1) >= 0;
}
