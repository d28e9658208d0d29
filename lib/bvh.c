/* bvh.c (chapter 1): building and traversing the hierarchy. See bvh.h. */
#include "bvh.h"

#include <stdlib.h>

/* A box's distances t are within a few ulps of the exact ones: a box entered up to this
 * factor beyond a distance still counts as entered before it. */
#define ROUNDING (1.0 + 1e-12)

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

/* The box grown by more than the rounding of a ray's slab test and the triangles' edge
 * slack (triangle.h), so that it never turns away a ray that hits what it holds. */
static Box widened(Box box)
{
    double size = max2(box.upper[0] - box.lower[0],
                       max2(box.upper[1] - box.lower[1], box.upper[2] - box.lower[2]));
    double widen = 1e-12 * size + 0x1p-1000;
    for (int k = 0; k < 3; k++) {
        box.lower[k] -= fabs(box.lower[k]) * 0x1p-50 + widen;
        box.upper[k] += fabs(box.upper[k]) * 0x1p-50 + widen;
    }
    return box;
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

typedef struct {
    Bvh *bvh;
    const Box *boxes;   /* of every primitive */
    double *right_area; /* scratch for the heuristic */
} Builder;

static void sort_along(const Builder *b, Item *items, int count, int axis)
{
    for (int i = 0; i < count; i++) {
        const Box *box = &b->boxes[items[i].primitive];
        items[i].centre = box->lower[axis] + box->upper[axis];
    }
    qsort(items, (size_t)count, sizeof *items, compare_items);
}

/* The surface area heuristic: a ray that meets a node meets a child with a probability
 * in proportion to the child's area, so the split (the first item of the second child)
 * with the least sum of area times primitives over the three axes; the items are left
 * sorted along its axis. */
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

/* The node over items[0 .. count-1], whose primitives are entries first ... of the leaf
 * order; returns its number. Primitives whose box centres all coincide cannot be split
 * by them: a leaf. */
static int build(Builder *b, Item *items, int count, int first, int level)
{
    int index = b->bvh->node_count++;
    Box box = EMPTY, centres = EMPTY;
    for (int i = 0; i < count; i++) {
        Box primitive = b->boxes[items[i].primitive];
        box = box_union(box, primitive);
        for (int k = 0; k < 3; k++)
            primitive.lower[k] = primitive.upper[k] = primitive.lower[k] + primitive.upper[k];
        centres = box_union(centres, primitive);
    }
    box = widened(box);
    BvhNode leaf = {{{box.lower[0], box.lower[1], box.lower[2]},
                     {box.upper[0], box.upper[1], box.upper[2]}}, -1, first, count};
    b->bvh->nodes[index] = leaf;
    int axis = 0;
    for (int k = 1; k < 3; k++)
        if (centres.upper[k] - centres.lower[k] > centres.upper[axis] - centres.lower[axis])
            axis = k;
    if (count == 1 || !(centres.upper[axis] > centres.lower[axis])) {
        for (int i = 0; i < count; i++)
            b->bvh->primitives[first + i] = items[i].primitive;
        return index;
    }
    int split = count / 2;
    if (level < BVH_SAH_LEVELS)
        split = best_split(b, items, count);
    else
        sort_along(b, items, count, axis);
    build(b, items, split, first, level + 1);
    int right = build(b, items + split, count - split, first + split, level + 1);
    b->bvh->nodes[index].right = right;
    b->bvh->nodes[index].count = 0;
    return index;
}

int bvh_build(Bvh *bvh, BvhPrimitives primitives)
{
    int n = primitives.triangle_count + primitives.sphere_count;
    Bvh empty = {NULL, 0, NULL};
    *bvh = empty;
    if (n == 0)
        return 0;
    Box *boxes = malloc((size_t)n * sizeof *boxes);
    Item *items = malloc((size_t)n * sizeof *items);
    double *right_area = malloc((size_t)n * sizeof *right_area);
    bvh->nodes = malloc((size_t)(2 * n - 1) * sizeof *bvh->nodes);
    bvh->primitives = malloc((size_t)n * sizeof *bvh->primitives);
    int ok = boxes && items && right_area && bvh->nodes && bvh->primitives;
    if (ok) {
        for (int i = 0; i < n; i++) {
            boxes[i] = primitive_box(primitives, i);
            items[i].primitive = i;
        }
        Builder builder = {bvh, boxes, right_area};
        build(&builder, items, n, 0, 0);
    }
    free(boxes);
    free(items);
    free(right_area);
    if (!ok) {
        bvh_free(bvh);
        return -1;
    }
    return 0;
}

void bvh_free(Bvh *bvh)
{
    free(bvh->nodes);
    free(bvh->primitives);
    Bvh empty = {NULL, 0, NULL};
    *bvh = empty;
}

/* What every box test of one ray needs, worked out once: per axis 1/d, and which
 * plane of the slab it meets first (the upper one where d < 0). */
typedef struct {
    double origin[3], inverse[3];
    int near[3];
} BoxRay;

static BoxRay box_ray(Ray ray)
{
    BoxRay r = {{ray.origin.x, ray.origin.y, ray.origin.z},
                {1.0 / ray.dir.x, 1.0 / ray.dir.y, 1.0 / ray.dir.z}, {0, 0, 0}};
    for (int k = 0; k < 3; k++)
        r.near[k] = signbit(r.inverse[k]) ? 1 : 0;
    return r;
}

/* Narrow [*near, *far] to where the ray is between the two planes of one axis. A slab
 * the ray runs along (d = 0) gives t = +-inf, or NaN on a plane, which the comparisons
 * skip: the slab counts as met. */
static inline void clip_to_slab(const BvhNode *node, const BoxRay *r, int k, double *near,
                                double *far)
{
    double t_in = (node->bounds[r->near[k]][k] - r->origin[k]) * r->inverse[k];
    double t_out = (node->bounds[1 - r->near[k]][k] - r->origin[k]) * r->inverse[k];
    *near = t_in > *near ? t_in : *near;
    *far = t_out < *far ? t_out : *far;
}

/* Where the ray enters the node's box within (0, tmax), or INFINITY where it misses it:
 * the slab test, the interval of t inside each pair of planes intersected. */
static inline double box_entry(const BvhNode *node, const BoxRay *r, double tmax)
{
    double near = 0.0, far = tmax;
    clip_to_slab(node, r, 0, &near, &far);
    clip_to_slab(node, r, 1, &near, &far);
    clip_to_slab(node, r, 2, &near, &far);
    return near <= far * ROUNDING ? near : INFINITY;
}

static double primitive_intersect(BvhPrimitives p, int index, Ray ray, double tmax)
{
    if (index < p.triangle_count)
        return triangle_intersect(&p.triangles[index], ray, 0.0, tmax);
    return sphere_intersect(&p.spheres[index - p.triangle_count], ray, 0.0, tmax);
}

typedef struct {
    int node;
    double entry; /* where the ray enters its box */
} StackEntry;

/* Both queries: any_hit stops at the first hit found. A non-finite ray hits nothing. */
static int traverse(const Bvh *bvh, BvhPrimitives p, Ray ray, double *tmax, int any_hit)
{
    BoxRay r = box_ray(ray);
    StackEntry stack[BVH_MAX_DEPTH + 1];
    int depth = 0, nearest = -1;
    if (bvh->node_count > 0 && vec3_is_finite(ray.origin) && vec3_is_finite(ray.dir))
        stack[depth++] = (StackEntry){0, box_entry(&bvh->nodes[0], &r, *tmax)};
    while (depth > 0) {
        StackEntry e = stack[--depth];
        if (e.entry > *tmax * ROUNDING)
            continue;
        const BvhNode *node = &bvh->nodes[e.node];
        for (int i = node->first; i < node->first + node->count; i++) {
            double t = primitive_intersect(p, bvh->primitives[i], ray, *tmax);
            if (t < *tmax) {
                *tmax = t;
                nearest = bvh->primitives[i];
                if (any_hit)
                    return nearest;
            }
        }
        if (node->count > 0)
            continue;
        StackEntry near = {e.node + 1, box_entry(&bvh->nodes[e.node + 1], &r, *tmax)};
        StackEntry far = {node->right, box_entry(&bvh->nodes[node->right], &r, *tmax)};
        if (far.entry < near.entry) {
            StackEntry swap = near;
            near = far;
            far = swap;
        }
        if (far.entry < INFINITY)
            stack[depth++] = far;
        if (near.entry < INFINITY)
            stack[depth++] = near;
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
