/* bvh.c (chapter 1): building and traversing the bounding volume hierarchy.
 * See bvh.h. */
#include "bvh.h"

#include <float.h>
#include <stdlib.h>
#include <string.h>

/* Boxes in double, in the scene's coordinates, for building. */

typedef struct {
    Vec3 lower, upper;
} Box;

static Box box_empty(void)
{
    Box box = {vec3(INFINITY, INFINITY, INFINITY), vec3(-INFINITY, -INFINITY, -INFINITY)};
    return box;
}

static Box box_grow(Box box, Vec3 p)
{
    box.lower = vec3(min2(box.lower.x, p.x), min2(box.lower.y, p.y), min2(box.lower.z, p.z));
    box.upper = vec3(max2(box.upper.x, p.x), max2(box.upper.y, p.y), max2(box.upper.z, p.z));
    return box;
}

static Box box_union(Box a, Box b)
{
    return box_grow(box_grow(a, b.lower), b.upper);
}

static double box_area(Box box)
{
    Vec3 d = vec3_sub(box.upper, box.lower);
    return d.x < 0.0 ? 0.0 : 2.0 * (d.x * d.y + d.y * d.z + d.z * d.x);
}

static Vec3 box_centre(Box box)
{
    return vec3_scale(vec3_add(box.lower, box.upper), 0.5);
}

static double axis_value(Vec3 v, int axis)
{
    return axis == 0 ? v.x : axis == 1 ? v.y : v.z;
}

static Box primitive_box(BvhPrimitives p, int index)
{
    if (index < p.triangle_count) {
        const Triangle *t = &p.triangles[index];
        Box box = box_grow(box_grow(box_empty(), t->v0), vec3_add(t->v0, t->e1));
        return box_grow(box, vec3_add(t->v0, t->e2));
    }
    const Sphere *s = &p.spheres[index - p.triangle_count];
    Vec3 r = vec3(s->radius, s->radius, s->radius);
    Box box = {vec3_sub(s->center, r), vec3_add(s->center, r)};
    return box;
}

/* Exact copies. Two primitives whose stored numbers are equal give every ray the same
 * t, so the first (the lowest number, which testing every primitive reports) answers
 * for all of its copies. Without this, a pile of copies is tested in full by every ray
 * that reaches it: an equal t never lets one copy cull another. A primitive's key is
 * every number its intersection test reads; sorting the keys brings copies together. */
#define KEY_SIZE 12

typedef struct {
    double key[KEY_SIZE];
    int primitive;
} Keyed;

static void primitive_key(BvhPrimitives p, int index, double key[KEY_SIZE])
{
    memset(key, 0, KEY_SIZE * sizeof *key);
    if (index < p.triangle_count) {
        const Triangle *t = &p.triangles[index];
        const Vec3 v[3] = {t->v0, t->e1, t->e2};
        for (int i = 0; i < 3; i++) {
            key[3 * i] = v[i].x;
            key[3 * i + 1] = v[i].y;
            key[3 * i + 2] = v[i].z;
        }
        key[9] = t->area;
        key[10] = t->longest_edge;
    } else {
        const Sphere *s = &p.spheres[index - p.triangle_count];
        key[0] = s->center.x;
        key[1] = s->center.y;
        key[2] = s->center.z;
        key[3] = s->radius;
        key[11] = 1.0; /* a sphere's key never equals a triangle's */
    }
}

static int compare_keyed(const void *a, const void *b)
{
    const Keyed *ka = a, *kb = b;
    int order = memcmp(ka->key, kb->key, sizeof ka->key);
    return order != 0 ? order : (ka->primitive > kb->primitive) - (ka->primitive < kb->primitive);
}

/* Write the primitives that are no copy of a lower-numbered one into `kept`, and
 * return how many there are, or -1 when memory runs out. */
static int without_copies(BvhPrimitives p, int n, int *kept)
{
    Keyed *keyed = malloc((size_t)n * sizeof *keyed);
    if (!keyed)
        return -1;
    for (int i = 0; i < n; i++) {
        primitive_key(p, i, keyed[i].key);
        keyed[i].primitive = i;
    }
    qsort(keyed, (size_t)n, sizeof *keyed, compare_keyed);
    int count = 0;
    for (int i = 0; i < n; i++)
        if (i == 0 || memcmp(keyed[i].key, keyed[i - 1].key, sizeof keyed[i].key) != 0)
            kept[count++] = keyed[i].primitive;
    free(keyed);
    return count;
}

/* The binary tree. Each item carries the key it is being sorted by (its box centre on
 * one axis), so that the sort needs no other context; ties go by primitive number, so
 * the tree is the same with every C library. */
typedef struct {
    double key;
    int primitive;
} Item;

static int compare_items(const void *a, const void *b)
{
    const Item *ia = a, *ib = b;
    if (ia->key != ib->key)
        return ia->key < ib->key ? -1 : 1;
    return (ia->primitive > ib->primitive) - (ia->primitive < ib->primitive);
}

typedef struct {
    Box box;
    int left, right; /* inner node: its children */
    int first;       /* leaf: its first entry of the primitive order */
    int count;       /* leaf: its number of primitives; inner node: 0 */
} BinaryNode;

typedef struct {
    const Box *boxes;   /* of every primitive */
    BinaryNode *nodes;
    int node_count;
    int *order;         /* the primitives in leaf order */
    double *right_area; /* scratch for the heuristic */
} Builder;

static void sort_along(const Builder *builder, Item *items, int count, int axis)
{
    for (int i = 0; i < count; i++)
        items[i].key = axis_value(box_centre(builder->boxes[items[i].primitive]), axis);
    qsort(items, (size_t)count, sizeof *items, compare_items);
}

/* The surface area heuristic over every split of every axis's order: leaves the items
 * sorted along the best axis and returns the size of the left part. */
static int sah_split(Builder *builder, Item *items, int count)
{
    double best_cost = INFINITY;
    int best_axis = 0, best_split = count / 2;
    for (int axis = 0; axis < 3; axis++) {
        sort_along(builder, items, count, axis);
        Box right = box_empty();
        for (int i = count - 1; i > 0; i--) {
            right = box_union(right, builder->boxes[items[i].primitive]);
            builder->right_area[i] = box_area(right);
        }
        Box left = box_empty();
        for (int split = 1; split < count; split++) {
            left = box_union(left, builder->boxes[items[split - 1].primitive]);
            double cost = box_area(left) * split + builder->right_area[split] * (count - split);
            if (cost < best_cost) {
                best_cost = cost;
                best_axis = axis;
                best_split = split;
            }
        }
    }
    sort_along(builder, items, count, best_axis);
    return best_split;
}

/* Build the subtree over items[0..count), at `level`, whose primitives take the leaf
 * order from `first` on. Returns its node. */
static int build(Builder *builder, Item *items, int count, int first, int level)
{
    int index = builder->node_count++;
    Box box = box_empty(), centres = box_empty();
    for (int i = 0; i < count; i++) {
        box = box_union(box, builder->boxes[items[i].primitive]);
        centres = box_grow(centres, box_centre(builder->boxes[items[i].primitive]));
    }
    BinaryNode *node = &builder->nodes[index];
    node->box = box;
    Vec3 spread = vec3_sub(centres.upper, centres.lower);
    if (count == 1 || !(vec3_max_component(spread) > 0.0)) {
        node->first = first;
        node->count = count;
        for (int i = 0; i < count; i++)
            builder->order[first + i] = items[i].primitive;
        return index;
    }
    int split;
    if (level < BVH_SAH_LEVELS) {
        split = sah_split(builder, items, count);
    } else {
        int axis = spread.x >= spread.y && spread.x >= spread.z ? 0 : spread.y >= spread.z ? 1 : 2;
        sort_along(builder, items, count, axis);
        split = count / 2;
    }
    node->count = 0;
    int left = build(builder, items, split, first, level + 1);
    int right = build(builder, items + split, count - split, first + split, level + 1);
    builder->nodes[index].left = left;
    builder->nodes[index].right = right;
    return index;
}

/* Rounding outward, so that a float box is tested as if it were the exact one, with no
 * margin afterwards. Converting x to a float f rounds by at most u |x| (u = 2^-24);
 * then stepping 8u |f| + 2^-100 away, in float arithmetic that rounds once more, gives
 * a float `below` at least 6u |x| below x, and `above` as far above it. The slab test
 * computes each t = (plane - origin) * (1/d) with three roundings, at most 3u of
 * |plane| + |origin| (over |d|), and the planes and the origin are each moved 6u of
 * their size the widening way: so a computed near t is never larger than the exact
 * one, nor a far t smaller. (And plane - origin is never 0, so 0 * inf, for d = 0,
 * never arises.) */
static inline void float_bracket(double x, float *below, float *above)
{
    float f = (float)x, step = fabsf(f) * 0x1p-21f + 0x1p-100f;
    *below = f - step;
    *above = f + step;
}

/* A leaf's box in double, widened by what the triangle test may accept beyond a
 * triangle's edges: its slack (triangle.h) is up to 16 DBL_EPSILON (|s| + |e|) / cos
 * in distance, and BVH_LEAF_SIZE_MARGIN of the box's size covers the |e| part for rays
 * down to 1/300 of grazing, the slab test's margin (below, relative to t) the |s| part.
 * Both stay far below RAY_OFFSET, so a ray leaving a surface can still be turned away
 * from the surface's own leaf. (2^-50 |x| covers the rounding of x itself.) */
#define BVH_LEAF_SIZE_MARGIN 1e-12

static void widen_leaf_box(Box box, double bounds[2][3])
{
    Vec3 size = vec3_sub(box.upper, box.lower);
    double widen = BVH_LEAF_SIZE_MARGIN * vec3_max_component(size) + 0x1p-1000;
    for (int axis = 0; axis < 3; axis++) {
        double lower = axis_value(box.lower, axis), upper = axis_value(box.upper, axis);
        bounds[0][axis] = lower - (fabs(lower) * 0x1p-50 + widen);
        bounds[1][axis] = upper + (fabs(upper) * 0x1p-50 + widen);
    }
}

/* The frame: the box of all primitives centred on the origin and scaled by a power of
 * two (so exactly) into [-1, 1]^3. */
static void choose_frame(Bvh *bvh, Box box)
{
    bvh->centre = box_centre(box);
    double half = 0.5 * vec3_max_component(vec3_sub(box.upper, box.lower));
    int exponent = 0;
    if (half > 0.0 && isfinite(half))
        frexp(half, &exponent);
    bvh->scale = ldexp(1.0, -exponent);
}

static double to_frame(const Bvh *bvh, Vec3 p, int axis)
{
    return (axis_value(p, axis) - axis_value(bvh->centre, axis)) * bvh->scale;
}

/* The children binary node `index` stands for in a four-wide node: itself, its inner
 * nodes opened, the largest first, until there are BVH_WIDTH or only leaves. */
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

static int make_leaf(Bvh *bvh, const BinaryNode *node)
{
    BvhLeaf *leaf = &bvh->leaves[bvh->leaf_count];
    widen_leaf_box(node->box, leaf->bounds);
    leaf->first = node->first;
    leaf->count = node->count;
    return bvh->leaf_count++;
}

/* Make the four-wide node for binary node `index` and, recursively, its subtree. */
static int make_wide(Bvh *bvh, const BinaryNode *nodes, int index)
{
    int wide = bvh->node_count++;
    int children[BVH_WIDTH];
    int n = gather_children(nodes, index, children);
    for (int k = 0; k < BVH_WIDTH; k++) {
        BvhNode *node = &bvh->nodes[wide];
        for (int axis = 0; axis < 3; axis++) {
            node->bounds[0][axis][k] = INFINITY;
            node->bounds[1][axis][k] = -INFINITY;
        }
        node->child[k] = -1;
        node->is_leaf[k] = 0;
        if (k >= n)
            continue;
        const BinaryNode *c = &nodes[children[k]];
        for (int axis = 0; axis < 3; axis++) {
            float below, above;
            float_bracket(to_frame(bvh, c->box.lower, axis), &below, &above);
            node->bounds[0][axis][k] = below;
            float_bracket(to_frame(bvh, c->box.upper, axis), &below, &above);
            node->bounds[1][axis][k] = above;
        }
        node->is_leaf[k] = c->count > 0;
        node->child[k] = c->count > 0 ? make_leaf(bvh, c) : make_wide(bvh, nodes, children[k]);
    }
    return wide;
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
    int kept_count = -1;
    if (boxes && kept && items && right_area && binary && bvh->nodes && bvh->leaves &&
        bvh->primitives && bvh->triangles)
        kept_count = without_copies(primitives, n, kept);
    if (kept_count > 0) {
        Box all = box_empty();
        for (int i = 0; i < n; i++)
            boxes[i] = primitive_box(primitives, i);
        for (int i = 0; i < kept_count; i++) {
            items[i].primitive = kept[i];
            all = box_union(all, boxes[kept[i]]);
        }
        Builder builder = {boxes, binary, 0, bvh->primitives, right_area};
        build(&builder, items, kept_count, 0, 0);
        bvh->primitive_count = kept_count;
        for (int i = 0; i < kept_count; i++)
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
    if (kept_count < 0) {
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

/* Traversal. What every box test needs from the ray, worked out once per ray: 1/d per
 * axis; which plane of each slab the ray meets first (the lower one when d >= 0), as
 * the place of that plane among a box's numbers; and the origin. For the float boxes,
 * all of it in the hierarchy's frame, the origin rounded to floats two ways so that
 * the near plane's t can only come out smaller and the far plane's larger
 * (float_bracket), and each number written four times, once per child, so that the
 * loop over the children reads it like the boxes. A direction component of 0 gives
 * 1/d = +-inf (IEEE division), and the slab is then all (t = -inf at both planes) or
 * nothing (+inf at the near one). (A component so small that 1/d overflows a float
 * counts as 0 in the float test: exact but for hits more than 2^28 scene sizes away.) */
typedef struct {
    float origin[2][3][BVH_WIDTH]; /* frame origin, [0] for the near planes, [1] the far */
    float inverse[3][BVH_WIDTH];
    int near_plane[3], far_plane[3]; /* places in a node's bounds (floats from its start) */
    double exact_origin[3];          /* for the leaves' boxes, in the scene's coordinates */
    double exact_inverse[3];
    int exact_near[3], exact_far[3]; /* places in a leaf's bounds */
} BoxRay;

static inline void box_ray_axis(BoxRay *r, int axis, double origin, double dir,
                                double centre, double scale)
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
    r->near_plane[axis] = (near * 3 + axis) * BVH_WIDTH;
    r->far_plane[axis] = ((1 - near) * 3 + axis) * BVH_WIDTH;
    r->exact_origin[axis] = origin;
    r->exact_inverse[axis] = inverse;
    r->exact_near[axis] = near * 3 + axis;
    r->exact_far[axis] = (1 - near) * 3 + axis;
}

static inline void box_ray_init(BoxRay *r, const Bvh *bvh, Ray ray)
{
    box_ray_axis(r, 0, ray.origin.x, ray.dir.x, bvh->centre.x, bvh->scale);
    box_ray_axis(r, 1, ray.origin.y, ray.dir.y, bvh->centre.y, bvh->scale);
    box_ray_axis(r, 2, ray.origin.z, ray.dir.z, bvh->centre.z, bvh->scale);
}

/* Narrow each child's interval [near, far] to the slab of one axis. A plain loop over
 * the four children, which the compiler turns into four-wide SSE instructions.
 * `a > b ? a : b`, not fmaxf (which must handle NaN), is one SSE instruction. */
static inline void clip_to_slab(const BvhNode *node, const BoxRay *r, int axis,
                                float near[BVH_WIDTH], float far[BVH_WIDTH])
{
    const float *near_plane = &node->bounds[0][0][0] + r->near_plane[axis];
    const float *far_plane = &node->bounds[0][0][0] + r->far_plane[axis];
    for (int k = 0; k < BVH_WIDTH; k++) {
        float t_near = (near_plane[k] - r->origin[0][axis][k]) * r->inverse[axis][k];
        float t_far = (far_plane[k] - r->origin[1][axis][k]) * r->inverse[axis][k];
        near[k] = t_near > near[k] ? t_near : near[k];
        far[k] = t_far < far[k] ? t_far : far[k];
    }
}

/* The (frame) distance at which the ray enters each child's box within (0, limit), or
 * infinity where it misses it. */
static inline void children_entry(const BvhNode *node, const BoxRay *r, float limit,
                                  float entry[BVH_WIDTH])
{
    float near[BVH_WIDTH], far[BVH_WIDTH];
    for (int k = 0; k < BVH_WIDTH; k++) {
        near[k] = 0.0f;
        far[k] = limit;
    }
    clip_to_slab(node, r, 0, near, far);
    clip_to_slab(node, r, 1, near, far);
    clip_to_slab(node, r, 2, near, far);
    for (int k = 0; k < BVH_WIDTH; k++)
        entry[k] = near[k] <= far[k] ? near[k] : INFINITY;
}

/* The same slab test in double for one leaf's (widened) box, with a relative margin
 * that covers the three roundings of each t (2^-53 each) many times over, and the
 * triangle test's slack for rays from up to 1/300 of grazing (widen_leaf_box). Where
 * d = 0 and the origin lies on a plane, t = 0 * inf is NaN, which the comparisons
 * skip: the slab counts as met. */
#define BVH_LEAF_MARGIN (1.0 + 1e-12)

static inline void clip_to_leaf_slab(const BvhLeaf *leaf, const BoxRay *r, int axis,
                                     double *near, double *far)
{
    const double *bounds = &leaf->bounds[0][0];
    double t_near = (bounds[r->exact_near[axis]] - r->exact_origin[axis]) * r->exact_inverse[axis];
    double t_far = (bounds[r->exact_far[axis]] - r->exact_origin[axis]) * r->exact_inverse[axis];
    *near = t_near > *near ? t_near : *near;
    *far = t_far < *far ? t_far : *far;
}

static inline int leaf_hit(const BvhLeaf *leaf, const BoxRay *r, double tmax)
{
    double near = 0.0, far = tmax;
    clip_to_leaf_slab(leaf, r, 0, &near, &far);
    clip_to_leaf_slab(leaf, r, 1, &near, &far);
    clip_to_leaf_slab(leaf, r, 2, &near, &far);
    return near <= far * BVH_LEAF_MARGIN;
}

/* Subtrees still to visit, with the distance at which the ray enters their box: one
 * entered beyond the nearest hit found since is skipped when popped. Each level of the
 * tree adds at most BVH_WIDTH - 1 entries. */
typedef struct {
    int child, is_leaf; /* as in BvhNode */
    float entry;
} StackEntry;

#define BVH_STACK ((BVH_WIDTH - 1) * BVH_MAX_DEPTH + 1)

/* Push child k if the ray meets it, keeping the children pushed since `bottom` sorted
 * farthest first, so that the nearest is popped next. */
static inline void push_child(const BvhNode *node, int k, float entry, StackEntry *stack,
                              int bottom, int *depth)
{
    if (entry == INFINITY)
        return;
    StackEntry e = {node->child[k], node->is_leaf[k], entry};
    int i = (*depth)++;
    for (; i > bottom && stack[i - 1].entry < entry; i--)
        stack[i] = stack[i - 1];
    stack[i] = e;
}

/* The four calls written out rather than looped over: the compiler then keeps the four
 * entries in registers (measured 5% faster). */
static inline int push_children(const BvhNode *node, const float entry[BVH_WIDTH],
                                StackEntry *stack, int depth)
{
    _Static_assert(BVH_WIDTH == 4, "push_children pushes four children");
    int bottom = depth;
    push_child(node, 0, entry[0], stack, bottom, &depth);
    push_child(node, 1, entry[1], stack, bottom, &depth);
    push_child(node, 2, entry[2], stack, bottom, &depth);
    push_child(node, 3, entry[3], stack, bottom, &depth);
    return depth;
}

static inline double primitive_intersect(const Bvh *bvh, BvhPrimitives p, int entry, Ray ray,
                                         double tmax)
{
    int index = bvh->primitives[entry];
    if (index < p.triangle_count)
        return triangle_intersect(&bvh->triangles[entry], ray, 0.0, tmax);
    return sphere_intersect(&p.spheres[index - p.triangle_count], ray, 0.0, tmax);
}

/* The traversal shared by both queries: any_hit stops at the first hit found. */
static int traverse(const Bvh *bvh, BvhPrimitives p, Ray ray, double *tmax, int any_hit)
{
    if (bvh->node_count == 0)
        return -1;
    BoxRay box_ray;
    box_ray_init(&box_ray, bvh, ray);
    float below, limit; /* limit: *tmax in the frame, rounded up */
    float_bracket(*tmax * bvh->scale, &below, &limit);
    StackEntry stack[BVH_STACK];
    int depth = 0, nearest = -1;
    StackEntry root = {0, 0, 0.0f};
    stack[depth++] = root;
    while (depth > 0) {
        StackEntry e = stack[--depth];
        if (e.entry > limit)
            continue;
        if (!e.is_leaf) {
            const BvhNode *node = &bvh->nodes[e.child];
            float entry[BVH_WIDTH];
            children_entry(node, &box_ray, limit, entry);
            depth = push_children(node, entry, stack, depth);
            continue;
        }
        const BvhLeaf *leaf = &bvh->leaves[e.child];
        if (!leaf_hit(leaf, &box_ray, *tmax))
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
