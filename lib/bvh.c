/* bvh.c (chapter 1): building and traversing the hierarchy. See bvh.h. */
#include "bvh.h"

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

static Box box_of_points(const Vec3 *points, int count)
{
    Box box = EMPTY;
    for (int i = 0; i < count; i++) {
        Box point = {{points[i].x, points[i].y, points[i].z}, {points[i].x, points[i].y, points[i].z}};
        box = box_union(box, point);
    }
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
        Vec3 corners[3] = {t->v0, vec3_add(t->v0, t->e1), vec3_add(t->v0, t->e2)};
        return box_of_points(corners, 3);
    }
    const Sphere *s = &p.spheres[index - p.triangle_count];
    Vec3 r = vec3(s->radius, s->radius, s->radius);
    Vec3 corners[2] = {vec3_sub(s->center, r), vec3_add(s->center, r)};
    return box_of_points(corners, 2);
}

/* A primitive's defining numbers: two primitives are exact copies when their keys are
 * equal, and a copy answers every ray as the first does, so only the first is kept. */
typedef struct {
    double key[12];
    int primitive;
} Keyed;

static void primitive_key(BvhPrimitives p, int index, Keyed *keyed)
{
    memset(keyed->key, 0, sizeof keyed->key);
    keyed->primitive = index;
    if (index < p.triangle_count) {
        const Triangle *t = &p.triangles[index];
        const Vec3 v[3] = {t->v0, t->e1, t->e2};
        for (int i = 0; i < 3; i++) {
            keyed->key[3 * i] = v[i].x;
            keyed->key[3 * i + 1] = v[i].y;
            keyed->key[3 * i + 2] = v[i].z;
        }
    } else {
        const Sphere *s = &p.spheres[index - p.triangle_count];
        const double sphere[4] = {s->center.x, s->center.y, s->center.z, s->radius};
        memcpy(keyed->key, sphere, sizeof sphere);
        keyed->key[11] = 1.0; /* a sphere's key never equals a triangle's */
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

/* A node's box, widened by more than the rounding of the slab test and of the
 * triangles' edge slack (triangle.h), so that it never turns away a ray that hits. */
static void set_bounds(BvhNode *node, Box box)
{
    double size = max2(box.upper[0] - box.lower[0],
                       max2(box.upper[1] - box.lower[1], box.upper[2] - box.lower[2]));
    double widen = 1e-12 * size + 0x1p-1000;
    for (int k = 0; k < 3; k++) {
        node->bounds[0][k] = box.lower[k] - (fabs(box.lower[k]) * 0x1p-50 + widen);
        node->bounds[1][k] = box.upper[k] + (fabs(box.upper[k]) * 0x1p-50 + widen);
    }
}

/* The node over items[0 .. count-1], whose primitives go to primitives[first ...]. A
 * node whose box centres all coincide cannot be split by them: it is a leaf. */
static void build(Builder *b, Item *items, int count, int first, int level)
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
    BvhNode *node = &b->bvh->nodes[index];
    set_bounds(node, box);
    int axis = 0;
    for (int k = 1; k < 3; k++)
        if (centres.upper[k] - centres.lower[k] > centres.upper[axis] - centres.lower[axis])
            axis = k;
    if (count == 1 || !(centres.upper[axis] > centres.lower[axis])) {
        node->next = first;
        node->count = count;
        for (int i = 0; i < count; i++)
            b->bvh->primitives[first + i] = items[i].primitive;
        return;
    }
    int split = count / 2;
    if (level < BVH_SAH_LEVELS)
        split = best_split(b, items, count);
    else
        sort_along(b, items, count, axis);
    node->count = 0;
    build(b, items, split, first, level + 1);
    b->bvh->nodes[index].next = b->bvh->node_count;
    build(b, items + split, count - split, first + split, level + 1);
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
    bvh->nodes = malloc((size_t)(2 * n - 1) * sizeof *bvh->nodes);
    bvh->primitives = malloc((size_t)n * sizeof *bvh->primitives);
    int count = -1;
    if (boxes && kept && items && right_area && bvh->nodes && bvh->primitives)
        count = without_copies(primitives, n, kept);
    if (count > 0) {
        for (int i = 0; i < n; i++)
            boxes[i] = primitive_box(primitives, i);
        for (int i = 0; i < count; i++)
            items[i].primitive = kept[i];
        Builder builder = {bvh, boxes, right_area};
        build(&builder, items, count, 0, 0);
        bvh->primitive_count = count;
    }
    free(boxes);
    free(kept);
    free(items);
    free(right_area);
    if (count < 0) {
        bvh_free(bvh);
        return -1;
    }
    return 0;
}

void bvh_free(Bvh *bvh)
{
    free(bvh->nodes);
    free(bvh->primitives);
    memset(bvh, 0, sizeof *bvh);
}

/* What every box test of one ray needs: its origin, 1/d per axis, and which plane of
 * each slab it meets first (the lower one where d >= 0). */
typedef struct {
    double origin[3], inverse[3];
    int near[3];
} BoxRay;

/* Where the ray enters the node's box within (0, tmax), or infinity if it misses it.
 * A slab the ray runs along (d = 0) gives t = +-inf, or NaN on a plane, which the
 * comparisons skip: the slab counts as met. */
static double entry(const BvhNode *node, const BoxRay *r, double tmax)
{
    double near = 0.0, far = tmax;
    for (int k = 0; k < 3; k++) {
        double t_near = (node->bounds[r->near[k]][k] - r->origin[k]) * r->inverse[k];
        double t_far = (node->bounds[1 - r->near[k]][k] - r->origin[k]) * r->inverse[k];
        near = t_near > near ? t_near : near;
        far = t_far < far ? t_far : far;
    }
    return near <= far * (1.0 + 1e-12) ? near : INFINITY;
}

static double primitive_intersect(BvhPrimitives p, int index, Ray ray, double tmax)
{
    if (index < p.triangle_count)
        return triangle_intersect(&p.triangles[index], ray, 0.0, tmax);
    return sphere_intersect(&p.spheres[index - p.triangle_count], ray, 0.0, tmax);
}

/* Both queries: any_hit stops at the first hit found. */
static int traverse(const Bvh *bvh, BvhPrimitives p, Ray ray, double *tmax, int any_hit)
{
    BoxRay r = {{ray.origin.x, ray.origin.y, ray.origin.z},
                {1.0 / ray.dir.x, 1.0 / ray.dir.y, 1.0 / ray.dir.z}, {0, 0, 0}};
    for (int k = 0; k < 3; k++)
        r.near[k] = signbit(r.inverse[k]) ? 1 : 0;
    if (bvh->node_count == 0 || entry(&bvh->nodes[0], &r, *tmax) == INFINITY)
        return -1;
    /* Second children still to visit, with where the ray enters them: one entered
     * beyond the nearest hit found since is skipped. */
    struct { int index; double entry; } stack[BVH_MAX_DEPTH];
    int depth = 0, nearest = -1, index = 0;
    for (;;) {
        const BvhNode *node = &bvh->nodes[index];
        if (node->count > 0) {
            for (int i = node->next; i < node->next + node->count; i++) {
                double t = primitive_intersect(p, bvh->primitives[i], ray, *tmax);
                if (t < *tmax) {
                    *tmax = t;
                    nearest = bvh->primitives[i];
                    if (any_hit)
                        return nearest;
                }
            }
        } else {
            int first = index + 1, second = node->next;
            double t_first = entry(&bvh->nodes[first], &r, *tmax);
            double t_second = entry(&bvh->nodes[second], &r, *tmax);
            if (t_second < t_first) {
                int swap = first;
                first = second;
                second = swap;
                double t = t_first;
                t_first = t_second;
                t_second = t;
            }
            if (t_first != INFINITY) {
                if (t_second != INFINITY) {
                    stack[depth].index = second;
                    stack[depth++].entry = t_second;
                }
                index = first;
                continue;
            }
        }
        do {
            if (depth == 0)
                return nearest;
            index = stack[--depth].index;
        } while (stack[depth].entry > *tmax);
    }
}

int bvh_intersect(const Bvh *bvh, BvhPrimitives primitives, Ray ray, double *tmax)
{
    return traverse(bvh, primitives, ray, tmax, 0);
}

int bvh_occluded(const Bvh *bvh, BvhPrimitives primitives, Ray ray, double tmax)
{
    return traverse(bvh, primitives, ray, &tmax, 1) >= 0;
}
