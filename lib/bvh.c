/* bvh.c (chapter 2): building and traversing the hierarchy. See bvh.h. */
#include "bvh.h"

#include <stdlib.h>

/* A box's distances t are within a few ulps of the exact ones: a box entered up to this
 * factor beyond a distance still counts as entered before it. */
#define ROUNDING (1.0 + 1e-12)

/* The box that holds nothing: adding a point to it gives that point's box. */
static const Box EMPTY = {{{INFINITY, INFINITY, INFINITY}, {-INFINITY, -INFINITY, -INFINITY}}};

/* The box grown to hold the point p. */
static Box box_add(Box box, Vec3 p)
{
    const double q[3] = {p.x, p.y, p.z};
    for (int k = 0; k < 3; k++) {
        box.corner[0][k] = min2(box.corner[0][k], q[k]);
        box.corner[1][k] = max2(box.corner[1][k], q[k]);
    }
    return box;
}

static Box box_union(Box a, Box b)
{
    return box_add(box_add(a, vec3(b.corner[0][0], b.corner[0][1], b.corner[0][2])),
                   vec3(b.corner[1][0], b.corner[1][1], b.corner[1][2]));
}

static double box_extent(Box box, int k) { return box.corner[1][k] - box.corner[0][k]; }

/* Half the surface area: the heuristic compares areas, so the factor 2 is left out. */
static double box_area(Box box)
{
    double x = box_extent(box, 0), y = box_extent(box, 1), z = box_extent(box, 2);
    return x < 0.0 ? 0.0 : x * y + y * z + z * x;
}

static Box primitive_box(BvhPrimitives p, int index)
{
    if (index < p.triangle_count) {
        const Triangle *t = &p.triangles[index];
        Box box = box_add(box_add(EMPTY, t->v0), vec3_add(t->v0, t->e1));
        return box_add(box, vec3_add(t->v0, t->e2));
    }
    const Sphere *s = &p.spheres[index - p.triangle_count];
    Vec3 r = vec3(s->radius, s->radius, s->radius);
    return box_add(box_add(EMPTY, vec3_sub(s->center, r)), vec3_add(s->center, r));
}

/* A node's box is widened on every side by three margins, so that it never turns away a
 * ray that hits what it holds. Its corners are rounded sums (v0 + e1, a sphere's centre
 * plus its radius), off the exact ones by an ulp or two of each coordinate: the first
 * margin is four ulps (2^-50) of the coordinate. The slab test rounds each t it works out,
 * and a triangle accepts hits a little outside its edges (TRIANGLE_EDGE_SLACK): the second
 * margin is 1e-12 of the box's largest side, which holds both. A box of no size at the
 * origin would get neither: the third margin, 2^-1000, is the least width any box has (a
 * normal double, lost in the rounding of any coordinate above 2^-947). All three are far
 * below the offset of a new ray off its surface (RAY_OFFSET, ray.h), so a ray leaving a
 * surface still meets that surface's box. */
#define BOX_COORDINATE_MARGIN 0x1p-50
#define BOX_SIZE_MARGIN 1e-12
#define BOX_LEAST_MARGIN 0x1p-1000

static Box widened(Box box)
{
    double size = max2(box_extent(box, 0), max2(box_extent(box, 1), box_extent(box, 2)));
    for (int k = 0; k < 3; k++) {
        for (int side = 0; side < 2; side++) {
            double margin = fabs(box.corner[side][k]) * BOX_COORDINATE_MARGIN +
                            BOX_SIZE_MARGIN * size + BOX_LEAST_MARGIN;
            box.corner[side][k] += side == 0 ? -margin : margin; /* 0: the lower corner */
        }
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

static void sort_along(const Box *boxes, Item *items, int count, int axis)
{
    for (int i = 0; i < count; i++) {
        const Box *box = &boxes[items[i].primitive];
        items[i].centre = box->corner[0][axis] + box->corner[1][axis];
    }
    qsort(items, (size_t)count, sizeof *items, compare_items);
}

/* The surface area heuristic: a ray that meets a node meets a child with a probability
 * in proportion to the child's area, so the split (the first item of the second child)
 * with the least sum of area times primitives over the three axes; the items are left
 * sorted along its axis. right_area is scratch. */
static int best_split(const Box *boxes, Item *items, int count, double *right_area)
{
    double best_cost = INFINITY;
    int best_axis = 0;
    int best = count / 2;
    for (int axis = 0; axis < 3; axis++) {
        sort_along(boxes, items, count, axis);
        Box right = EMPTY;
        Box left = EMPTY;
        for (int i = count - 1; i > 0; i--) {
            right = box_union(right, boxes[items[i].primitive]);
            right_area[i] = box_area(right);
        }
        for (int split = 1; split < count; split++) {
            left = box_union(left, boxes[items[split - 1].primitive]);
            double cost = box_area(left) * split + right_area[split] * (count - split);
            if (cost < best_cost) {
                best_cost = cost;
                best_axis = axis;
                best = split;
            }
        }
    }
    sort_along(boxes, items, count, best_axis);
    return best;
}

/* The node over items[0 .. count-1], whose primitives are entries first ... of the leaf
 * order, and its subtree; returns its number. A leaf: one primitive; primitives whose
 * box centres all coincide (no split by them tells them apart); or the deepest level. */
static int build(Bvh *bvh, const Box *boxes, Item *items, int count, int first, int level,
                 double *scratch)
{
    int index = bvh->node_count++;
    Box box = EMPTY, centres = EMPTY;
    for (int i = 0; i < count; i++) {
        const double(*c)[3] = boxes[items[i].primitive].corner;
        box = box_union(box, boxes[items[i].primitive]);
        centres =
            box_add(centres, vec3(c[0][0] + c[1][0], c[0][1] + c[1][1], c[0][2] + c[1][2]));
    }
    bvh->nodes[index] = (BvhNode){widened(box), -1, first, count};
    double spread = box_extent(centres, 0) + box_extent(centres, 1) + box_extent(centres, 2);
    if (count == 1 || !(spread > 0.0) || level == BVH_MAX_DEPTH - 1) {
        for (int i = 0; i < count; i++)
            bvh->primitives[first + i] = items[i].primitive;
        return index;
    }
    int split = best_split(boxes, items, count, scratch);
    build(bvh, boxes, items, split, first, level + 1, scratch);
    int right =
        build(bvh, boxes, items + split, count - split, first + split, level + 1, scratch);
    bvh->nodes[index].right = right;
    bvh->nodes[index].count = 0;
    return index;
}

int bvh_build(Bvh *bvh, BvhPrimitives primitives)
{
    int n = primitives.triangle_count + primitives.sphere_count;
    *bvh = (Bvh){NULL, 0, NULL};
    if (n == 0)
        return 0;
    Box *boxes = malloc((size_t)n * sizeof *boxes);
    Item *items = malloc((size_t)n * sizeof *items);
    double *scratch = malloc((size_t)n * sizeof *scratch);
    bvh->nodes = malloc((size_t)(2 * n - 1) * sizeof *bvh->nodes);
    bvh->primitives = malloc((size_t)n * sizeof *bvh->primitives);
    int ok = boxes && items && scratch && bvh->nodes && bvh->primitives;
    for (int i = 0; ok && i < n; i++) {
        boxes[i] = primitive_box(primitives, i);
        items[i].primitive = i;
    }
    if (ok)
        build(bvh, boxes, items, n, 0, 0, scratch);
    else
        bvh_free(bvh);
    free(boxes);
    free(items);
    free(scratch);
    return ok ? 0 : -1;
}

void bvh_free(Bvh *bvh)
{
    free(bvh->nodes);
    free(bvh->primitives);
    *bvh = (Bvh){NULL, 0, NULL};
}

/* The ray as every box test needs it: its origin and 1/d per axis, worked out once. */
typedef struct {
    double origin[3], inverse[3];
} BoxRay;

/* Narrow [*near, *far] to where the ray is between the two planes of axis k, the one
 * it meets first being the upper where d < 0. A slab the ray runs along (d = 0) gives
 * t = +-inf, or NaN on a plane, which the comparisons skip: the slab counts as met. */
static inline void clip_to_slab(const Box *box, const BoxRay *r, int k, double *near,
                                double *far)
{
    int first = r->inverse[k] < 0.0;
    double t_in = (box->corner[first][k] - r->origin[k]) * r->inverse[k];
    double t_out = (box->corner[1 - first][k] - r->origin[k]) * r->inverse[k];
    *near = t_in > *near ? t_in : *near;
    *far = t_out < *far ? t_out : *far;
}

/* Where the ray enters the box within (0, tmax), or INFINITY where it misses it: the
 * slab test, the interval of t inside each pair of planes intersected. */
static inline double box_entry(const Box *box, const BoxRay *r, double tmax)
{
    double near = 0.0, far = tmax;
    clip_to_slab(box, r, 0, &near, &far);
    clip_to_slab(box, r, 1, &near, &far);
    clip_to_slab(box, r, 2, &near, &far);
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
    BoxRay r = {{ray.origin.x, ray.origin.y, ray.origin.z},
                {1.0 / ray.dir.x, 1.0 / ray.dir.y, 1.0 / ray.dir.z}};
    StackEntry stack[BVH_MAX_DEPTH + 1];
    int depth = 0, nearest = -1;
    double bound = *tmax; /* after a hit, just above its t: a tie is tested too (bvh.h) */
    if (bvh->node_count > 0 && vec3_is_finite(ray.origin) && vec3_is_finite(ray.dir))
        stack[depth++] = (StackEntry){0, box_entry(&bvh->nodes[0].box, &r, *tmax)};
    while (depth > 0) {
        StackEntry e = stack[--depth];
        if (e.entry > *tmax * ROUNDING)
            continue;
        const BvhNode *node = &bvh->nodes[e.node];
        for (int i = node->first; i < node->first + node->count; i++) {
            double t = primitive_intersect(p, bvh->primitives[i], ray, bound);
            if (t <= *tmax && (t < *tmax || bvh->primitives[i] < nearest)) {
                *tmax = t;
                bound = t * (1.0 + 0x1p-52) + 0x1p-1074; /* the next double, or the one after */
                nearest = bvh->primitives[i];
                if (any_hit)
                    return nearest;
            }
        }
        if (node->count > 0)
            continue;
        StackEntry near = {e.node + 1, box_entry(&bvh->nodes[e.node + 1].box, &r, *tmax)};
        StackEntry far = {node->right, box_entry(&bvh->nodes[node->right].box, &r, *tmax)};
        if (far.entry < near.entry) {
            StackEntry swap = near;
            near = far;
            far = swap;
        }
        if (far.entry < INFINITY)
            stack[depth++] = far;
        if (near.entry < INFINITY) /* pushed last: popped next */
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
