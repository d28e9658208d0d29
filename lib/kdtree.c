/* kdtree.c (chapter 8): building and querying the implicit kd-tree. See kdtree.h. */
#include "kdtree.h"

#include <stdlib.h>
#include <string.h>

static double coordinate(Vec3 p, int axis)
{
    return axis == 0 ? p.x : axis == 1 ? p.y : p.z;
}

static void swap_entries(KdTree *tree, int i, int j)
{
    Vec3 point = tree->points[i];
    tree->points[i] = tree->points[j];
    tree->points[j] = point;
    int index = tree->index[i];
    tree->index[i] = tree->index[j];
    tree->index[j] = index;
}

/* The axis along which the points of [lo, hi) spread most. */
static int widest_axis(const KdTree *tree, int lo, int hi)
{
    Vec3 lower = tree->points[lo], upper = tree->points[lo];
    for (int i = lo + 1; i < hi; i++) {
        Vec3 p = tree->points[i];
        lower = vec3(min2(lower.x, p.x), min2(lower.y, p.y), min2(lower.z, p.z));
        upper = vec3(max2(upper.x, p.x), max2(upper.y, p.y), max2(upper.z, p.z));
    }
    Vec3 extent = vec3_sub(upper, lower);
    return extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
}

/* Hoare's FIND: rearrange [lo, hi) so that position k holds the point that would be
 * there if the range were sorted along `axis`, those before it no greater and those
 * after it no smaller. */
static void select_median(KdTree *tree, int lo, int hi, int k, int axis)
{
    int left = lo, right = hi - 1;
    while (left < right) {
        double pivot = coordinate(tree->points[k], axis);
        int i = left, j = right;
        do {
            while (coordinate(tree->points[i], axis) < pivot)
                i++;
            while (pivot < coordinate(tree->points[j], axis))
                j--;
            if (i <= j)
                swap_entries(tree, i++, j--);
        } while (i <= j);
        if (j < k)
            left = i;
        if (k < i)
            right = j;
    }
}

static void build_range(KdTree *tree, int lo, int hi)
{
    if (hi - lo <= KDTREE_LEAF_SIZE) {
        for (int i = lo; i < hi; i++)
            tree->axis[i] = 0; /* unused: a leaf is scanned whole */
        return;
    }
    int mid = lo + (hi - lo) / 2, axis = widest_axis(tree, lo, hi);
    select_median(tree, lo, hi, mid, axis);
    tree->axis[mid] = (unsigned char)axis;
    build_range(tree, lo, mid);
    build_range(tree, mid + 1, hi);
}

int kdtree_build(KdTree *tree, const Vec3 *points, int count)
{
    size_t n = count > 0 ? (size_t)count : 1;
    KdTree t = {malloc(n * sizeof *t.points), malloc(n * sizeof *t.index), malloc(n), count};
    if (!t.points || !t.index || !t.axis) {
        kdtree_free(&t);
        *tree = t;
        return -1;
    }
    if (count > 0)
        memcpy(t.points, points, (size_t)count * sizeof *points);
    for (int i = 0; i < count; i++)
        t.index[i] = i;
    build_range(&t, 0, count);
    *tree = t;
    return 0;
}

void kdtree_free(KdTree *tree)
{
    free(tree->points);
    free(tree->index);
    free(tree->axis);
    tree->points = NULL;
    tree->index = NULL;
    tree->axis = NULL;
    tree->count = 0;
}

void kdtree_use_tree_order(KdTree *tree)
{
    for (int i = 0; i < tree->count; i++)
        tree->index[i] = i;
}

typedef struct {
    const KdTree *tree;
    Vec3 center;
    double radius2;
    KdTreeVisit visit;
    void *context;
} Query;

static void query_range(const Query *q, int lo, int hi)
{
    while (hi - lo > KDTREE_LEAF_SIZE) {
        int mid = lo + (hi - lo) / 2;
        Vec3 p = q->tree->points[mid], d = vec3_sub(q->center, p);
        double distance2 = vec3_dot(d, d);
        if (distance2 <= q->radius2)
            q->visit(q->tree->index[mid], distance2, q->context);
        int axis = q->tree->axis[mid];
        double delta = coordinate(q->center, axis) - coordinate(p, axis);
        /* The far half (across the split from the centre) only if the plane is near. */
        if (delta * delta <= q->radius2) {
            if (delta < 0.0)
                query_range(q, mid + 1, hi);
            else
                query_range(q, lo, mid);
        }
        if (delta < 0.0)
            hi = mid; /* then the near half, by looping */
        else
            lo = mid + 1;
    }
    for (int i = lo; i < hi; i++) { /* a leaf */
        Vec3 d = vec3_sub(q->center, q->tree->points[i]);
        double distance2 = vec3_dot(d, d);
        if (distance2 <= q->radius2)
            q->visit(q->tree->index[i], distance2, q->context);
    }
}

void kdtree_query_radius(const KdTree *tree, Vec3 center, double radius, KdTreeVisit visit,
                         void *context)
{
    Query q = {tree, center, radius * radius, visit, context};
    query_range(&q, 0, tree->count);
}
