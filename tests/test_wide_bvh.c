/* test_wide_bvh.c (chapter 9): Tests of the four-wide tree (lib/wide_bvh.c).
 *
 * Which hits it finds is checked with chapter 2's tree, ray by ray, against testing
 * every primitive (tests/test_bvh.c runs its rays through both trees from chapter 9
 * on). Here: its float boxes enclose what they bound, rounded outward in the tree's
 * frame (one rounded to nearest instead encloses its primitive only about half the
 * time), every primitive is under exactly one leaf, and a leaf keeps chapter 1's double
 * box; for the room, a soup of 2,000 triangles and a soup a 1e40 across, beyond the
 * range of floats.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include "check.h"
#include "scene_file.h"

/* Whether child k's float box holds the box [lower, upper], in the tree's frame. */
static int encloses(const WideBvh *wide, const WideBvhNode *node, int k, Vec3 lower, Vec3 upper)
{
    const double lo[3] = {lower.x, lower.y, lower.z}, hi[3] = {upper.x, upper.y, upper.z};
    for (int axis = 0; axis < 3; axis++)
        if (!(node->bounds[0][axis][k] <= (lo[axis] - wide->centre[axis]) * wide->scale &&
              node->bounds[1][axis][k] >= (hi[axis] - wide->centre[axis]) * wide->scale))
            return 0;
    return 1;
}

static void primitive_bounds(const Scene *scene, int prim, Vec3 *lower, Vec3 *upper)
{
    if (prim < scene->triangle_count) {
        const Triangle *t = &scene->triangles[prim];
        Vec3 a = t->v0, b = vec3_add(t->v0, t->e1), c = vec3_add(t->v0, t->e2);
        *lower = vec3(fmin(a.x, fmin(b.x, c.x)), fmin(a.y, fmin(b.y, c.y)),
                      fmin(a.z, fmin(b.z, c.z)));
        *upper = vec3(fmax(a.x, fmax(b.x, c.x)), fmax(a.y, fmax(b.y, c.y)),
                      fmax(a.z, fmax(b.z, c.z)));
        return;
    }
    const Sphere *s = &scene->spheres[prim - scene->triangle_count];
    Vec3 r = vec3(s->radius, s->radius, s->radius);
    *lower = vec3_sub(s->center, r);
    *upper = vec3_add(s->center, r);
}

/* Every primitive inside its leaf's float box and inside its double box; every node's
 * children inside the node's own box in its parent. Returns the primitives found. */
static int check_enclosed(const Scene *scene, int index)
{
    const WideBvh *wide = &scene->wide;
    const WideBvhNode *node = &wide->nodes[index];
    int found = 0;
    for (int k = 0; k < WIDE_BVH_WIDTH; k++) {
        if (node->child[k] < 0)
            continue;
        if (!node->is_leaf[k]) {
            const WideBvhNode *child = &wide->nodes[node->child[k]];
            for (int j = 0; j < WIDE_BVH_WIDTH; j++)
                for (int axis = 0; axis < 3 && child->child[j] >= 0; axis++)
                    assert_true(child->bounds[0][axis][j] >= node->bounds[0][axis][k] &&
                                child->bounds[1][axis][j] <= node->bounds[1][axis][k]);
            found += check_enclosed(scene, node->child[k]);
            continue;
        }
        const WideBvhLeaf *leaf = &wide->leaves[node->child[k]];
        for (int i = leaf->first; i < leaf->first + leaf->count; i++, found++) {
            Vec3 lower, upper;
            primitive_bounds(scene, wide->primitives[i], &lower, &upper);
            assert_true(encloses(wide, node, k, lower, upper));
            const double(*c)[3] = leaf->box.corner;
            assert_true(c[0][0] < lower.x && c[0][1] < lower.y && c[0][2] < lower.z &&
                        c[1][0] > upper.x && c[1][1] > upper.y && c[1][2] > upper.z);
        }
    }
    return found;
}

/* A soup of `count` unit-sized random triangles `scale` across. */
static void check_soup(int count, double scale)
{
    Scene soup;
    scene_init(&soup);
    Material grey = {
        .name = "grey", .kind = MATERIAL_LAMBERT, .reflectance = vec3(0.5, 0.5, 0.5)};
    int m = scene_add_material(&soup, grey);
    TestRandom rng = test_random(8, 8, 8);
    for (int i = 0; i < count; i++) {
        Vec3 corner = vec3_scale(vec3(2 * test_uniform(&rng) - 1, 2 * test_uniform(&rng) - 1,
                                      2 * test_uniform(&rng) - 1),
                                 scale);
        Vec3 b = vec3_add_scaled(corner, random_unit_vector(&rng), scale * 1e-3);
        Vec3 c = vec3_add_scaled(corner, random_unit_vector(&rng), scale * 1e-3);
        assert_true(scene_add_triangle(&soup, triangle_make(corner, b, c, m)) >= 0);
    }
    assert_int_equal(scene_prepare(&soup), 0);
    assert_int_equal(check_enclosed(&soup, 0), count);
    scene_free(&soup);
}

static void test_boxes_enclose_their_primitives(void **state)
{
    Scene room;
    char error[256];
    assert_int_equal(scene_load("scenes/room.scene", &room, error, sizeof error), 0);
    assert_int_equal(check_enclosed(&room, 0), room.triangle_count + room.sphere_count);
    scene_free(&room);
    check_soup(2000, 1e3);
    check_soup(300, 1e40);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_boxes_enclose_their_primitives),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
