/* bvh.c (chapter 1): building and traversing the bounding volume hierarchy.
 * See bvh.h. */
#include "bvh.h"

#include <stdlib.h>
#include <string.h>

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
    box.lower = vec3(fmin(box.lower.x, p.x), fmin(box.lower.y, p.y), fmin(box.lower.z, p.z));
    box.upper = vec3(fmax(box.upper.x, p.x), fmax(box.upper.y, p.y), fmax(box.upper.z, p.z));
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

static double axis_value(Vec3 v, int axis)
{
    return axis == 0 ? v.x : axis == 1 ? v.y : v.z;
}

/* What the builder needs: the primitives and their boxes. The sort's comparison reads
 * the boxes and axis through two file-level variables, since qsort passes no context;
 * building is done once per scene, by one thread. */
typedef struct {
    BvhPrimitives primitives;
    Box *boxes;
    Bvh *bvh;
} Builder;

static const Box *sort_boxes;
static int sort_axis;

static int compare_centroids(const void *a, const void *b)
{
    const Box *box_a = &sort_boxes[*(const int *)a], *box_b = &sort_boxes[*(const int *)b];
    double ca = axis_value(vec3_add(box_a->lower, box_a->upper), sort_axis);
    double cb = axis_value(vec3_add(box_b->lower, box_b->upper), sort_axis);
    return (ca > cb) - (ca < cb);
}

static void sort_by_centroid(const Builder *builder, int *items, int count, int axis)
{
    sort_boxes = builder->boxes;
    sort_axis = axis;
    qsort(items, (size_t)count, sizeof *items, compare_centroids);
}

/* Below this level the builder splits at the median, which bounds the tree's depth
 * (and the traversal stack) whatever the heuristic would prefer. */
#define BVH_SAH_LEVELS 32

/* Build the subtree over items[0..count) at `level` and return its node's index. */
static int build(Builder *builder, int *items, int count, int first, int level)
{
    Bvh *bvh = builder->bvh;
    int index = bvh->node_count++;
    Box box = box_empty();
    for (int i = 0; i < count; i++)
        box = box_union(box, builder->boxes[items[i]]);
    bvh->nodes[index].lower = box.lower;
    bvh->nodes[index].upper = box.upper;
    if (count <= BVH_LEAF_SIZE) {
        bvh->nodes[index].first = first;
        bvh->nodes[index].count = count;
        memcpy(bvh->primitives + first, items, (size_t)count * sizeof *items);
        return index;
    }
    /* The surface area heuristic over every split of every axis's centroid order. */
    double *right_area = malloc((size_t)count * sizeof *right_area);
    double best_cost = INFINITY;
    int best_axis = 0, best_split = count / 2;
    for (int axis = 0; axis < 3 && right_area && level < BVH_SAH_LEVELS; axis++) {
        sort_by_centroid(builder, items, count, axis);
        Box right = box_empty();
        for (int i = count - 1; i > 0; i--) {
            right = box_union(right, builder->boxes[items[i]]);
            right_area[i] = box_area(right);
        }
        Box left = box_empty();
        for (int split = 1; split < count; split++) {
            left = box_union(left, builder->boxes[items[split - 1]]);
            double cost = box_area(left) * split + right_area[split] * (count - split);
            if (cost < best_cost) {
                best_cost = cost;
                best_axis = axis;
                best_split = split;
            }
        }
    }
    free(right_area);
    sort_by_centroid(builder, items, count, best_axis);
    bvh->nodes[index].count = 0;
    build(builder, items, best_split, first, level + 1);
    bvh->nodes[index].first =
        build(builder, items + best_split, count - best_split, first + best_split, level + 1);
    return index;
}

/* Give inner node i the boxes of its children (node i + 1 and node `first`). */
static void copy_child_boxes(Bvh *bvh, int i)
{
    BvhNode *node = &bvh->nodes[i];
    const BvhNode *children[2] = {&bvh->nodes[i + 1], &bvh->nodes[node->first]};
    for (int k = 0; k < 2; k++) {
        const double lower[3] = {children[k]->lower.x, children[k]->lower.y, children[k]->lower.z};
        const double upper[3] = {children[k]->upper.x, children[k]->upper.y, children[k]->upper.z};
        for (int axis = 0; axis < 3; axis++) {
            node->child_lower[axis][k] = lower[axis];
            node->child_upper[axis][k] = upper[axis];
        }
    }
}

int bvh_build(Bvh *bvh, BvhPrimitives primitives)
{
    int n = primitives.triangle_count + primitives.sphere_count;
    memset(bvh, 0, sizeof *bvh);
    if (n == 0)
        return 0;
    Builder builder = {primitives, malloc((size_t)n * sizeof(Box)), bvh};
    int *items = malloc((size_t)n * sizeof *items);
    bvh->nodes = malloc((size_t)(2 * n - 1) * sizeof *bvh->nodes);
    bvh->primitives = malloc((size_t)n * sizeof *bvh->primitives);
    if (!builder.boxes || !items || !bvh->nodes || !bvh->primitives) {
        free(builder.boxes);
        free(items);
        bvh_free(bvh);
        return -1;
    }
    for (int i = 0; i < n; i++) {
        items[i] = i;
        builder.boxes[i] = primitive_box(primitives, i);
    }
    bvh->primitive_count = n;
    build(&builder, items, n, 0, 0);
    for (int i = 0; i < bvh->node_count; i++)
        if (bvh->nodes[i].count == 0)
            copy_child_boxes(bvh, i);
    free(builder.boxes);
    free(items);
    return 0;
}

void bvh_free(Bvh *bvh)
{
    free(bvh->nodes);
    free(bvh->primitives);
    memset(bvh, 0, sizeof *bvh);
}

/* The distances at which the ray enters the node's two children's boxes, or INFINITY
 * where it misses one within (0, tmax): the slab test. inverse = 1/d per axis (huge
 * for d = 0: the slab is then all or nothing). max2/min2 rather than fmax/fmin, which
 * the C library must make NaN-aware: this is the renderer's innermost loop. */
static inline void children_entry(const BvhNode *node, const double origin[3],
                                  const double inverse[3], double tmax, double entry[2])
{
    double near[2] = {0.0, 0.0}, far[2] = {tmax, tmax};
    for (int axis = 0; axis < 3; axis++)
        for (int k = 0; k < 2; k++) {
            double t0 = (node->child_lower[axis][k] - origin[axis]) * inverse[axis];
            double t1 = (node->child_upper[axis][k] - origin[axis]) * inverse[axis];
            near[k] = max2(near[k], min2(t0, t1));
            far[k] = min2(far[k], max2(t0, t1));
        }
    /* A relative margin keeps flat boxes (a wall's) and rounding from losing a hit. */
    for (int k = 0; k < 2; k++)
        entry[k] = near[k] <= far[k] * (1.0 + 1e-12) ? near[k] : INFINITY;
}

static inline double primitive_intersect(BvhPrimitives p, int index, Ray ray, double tmax)
{
    if (index < p.triangle_count)
        return triangle_intersect(&p.triangles[index], ray, 0.0, tmax);
    return sphere_intersect(&p.spheres[index - p.triangle_count], ray, 0.0, tmax);
}

/* The traversal shared by both queries: any_hit stops at the first hit found. The
 * stack holds subtrees still to visit with the distance at which the ray enters their
 * box, so that one beyond the nearest hit found since is skipped when popped. */
static double safe_inverse(double d)
{
    return 1.0 / (d != 0.0 ? d : copysign(1e-300, d)); /* huge, never infinite: no 0 * inf */
}

static int traverse(const Bvh *bvh, BvhPrimitives p, Ray ray, double *tmax, int any_hit)
{
    const double origin[3] = {ray.origin.x, ray.origin.y, ray.origin.z};
    const double inverse[3] = {safe_inverse(ray.dir.x), safe_inverse(ray.dir.y),
                               safe_inverse(ray.dir.z)};
    if (bvh->node_count == 0)
        return -1;
    struct { int node; double entry; } stack[BVH_SAH_LEVELS + 32];
    int depth = 0, nearest = -1, node = 0;
    for (;;) {
        const BvhNode *n = &bvh->nodes[node];
        if (n->count > 0) {
            for (int i = n->first; i < n->first + n->count; i++) {
                double t = primitive_intersect(p, bvh->primitives[i], ray, *tmax);
                if (t < *tmax) {
                    *tmax = t;
                    nearest = bvh->primitives[i];
                    if (any_hit)
                        return nearest;
                }
            }
        } else {
            int near = node + 1, far = n->first;
            double entry[2];
            children_entry(n, origin, inverse, *tmax, entry);
            double t_near = entry[0], t_far = entry[1];
            if (t_far < t_near) {
                int swap = near;
                near = far;
                far = swap;
                double t = t_near;
                t_near = t_far;
                t_far = t;
            }
            if (t_far < INFINITY) {
                stack[depth].node = far;
                stack[depth++].entry = t_far;
            }
            if (t_near < INFINITY) {
                node = near;
                continue;
            }
        }
        do {
            if (depth == 0)
                return nearest;
            depth--;
        } while (stack[depth].entry > *tmax * (1.0 + 1e-12)); /* margin as in children_entry */
        node = stack[depth].node;
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
