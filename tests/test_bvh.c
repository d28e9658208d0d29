/* test_bvh.c (chapter 1): Tests of the bounding volume hierarchy (lib/bvh.c, chapter 7).
 *
 * The hierarchy may change only how fast the nearest hit is found, never which hit:
 * for many random rays, in the report's room and in random triangle soups, the BVH's
 * nearest t must equal exactly what testing every primitive gives (the primitive too,
 * unless two primitives tie at that t: the room's tetrahedron stands with its base on
 * the floor, coplanar with it), and
 * its shadow query must agree with "is any primitive hit". Degenerate input (many
 * identical triangles, where the surface area heuristic cannot separate anything)
 * must build a tree of bounded depth and still answer correctly.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include "check.h"
#include "scene_file.h"

static double primitive_t(BvhPrimitives p, int i, Ray ray)
{
    return i < p.triangle_count ? triangle_intersect(&p.triangles[i], ray, 0.0, INFINITY)
                                : sphere_intersect(&p.spheres[i - p.triangle_count], ray, 0.0, INFINITY);
}

/* The reference: every primitive tested, the nearest kept. */
static int brute_force(BvhPrimitives p, Ray ray, double *tmax)
{
    int nearest = -1;
    for (int i = 0; i < p.triangle_count + p.sphere_count; i++) {
        double t = primitive_t(p, i, ray);
        if (t < *tmax) {
            *tmax = t;
            nearest = i;
        }
    }
    return nearest;
}

/* Rays from random points in the box [-extent, extent]^3 in random directions. */
static void compare_with_brute_force(const Scene *scene, double extent, int rays)
{
    BvhPrimitives p = {scene->triangles, scene->triangle_count, scene->spheres, scene->sphere_count};
    int hits = 0;
    for (int i = 0; i < rays; i++) {
        Rng rng = rng_for_sample(42, 0, (uint64_t)i);
        Vec3 origin = vec3(extent * (2 * rng_uniform(&rng) - 1), extent * (2 * rng_uniform(&rng) - 1),
                           extent * (2 * rng_uniform(&rng) - 1));
        Ray ray = {origin, random_unit_vector(&rng)};
        double t_bvh = INFINITY, t_all = INFINITY;
        int bvh = bvh_intersect(&scene->bvh, p, ray, &t_bvh);
        int all = brute_force(p, ray, &t_all);
        if (t_bvh != t_all)
            fail_msg("ray %d from (%g %g %g) dir (%g %g %g): bvh %d t=%.17g, all %d t=%.17g", i,
                     origin.x, origin.y, origin.z, ray.dir.x, ray.dir.y, ray.dir.z, bvh, t_bvh, all, t_all);
        /* Different primitives only where both are hit at exactly this t (a tie). */
        if (bvh != all)
            assert_true(primitive_t(p, bvh, ray) == t_all && primitive_t(p, all, ray) == t_all);
        hits += all >= 0;
        double limit = 0.5 * t_all;
        assert_int_equal(bvh_occluded(&scene->bvh, p, ray, limit), brute_force(p, ray, &limit) >= 0);
    }
    print_message("    %d of %d rays hit something\n", hits, rays);
}

static void test_room_matches_brute_force(void **state)
{
    (void)state;
    Scene scene;
    char error[256];
    assert_int_equal(scene_load("scenes/room.scene", &scene, error, sizeof error), 0);
    compare_with_brute_force(&scene, 6.0, 200000);
    scene_free(&scene);
}

/* Random triangles and spheres of all sizes, overlapping. */
static void test_random_soup_matches_brute_force(void **state)
{
    (void)state;
    Scene scene;
    scene_init(&scene);
    Material grey = {"grey", MATERIAL_LAMBERT, vec3(0.5, 0.5, 0.5), vec3(0, 0, 0), 0.0, 1.0};
    int m = scene_add_material(&scene, grey);
    Rng rng = rng_for_sample(7, 7, 7);
    for (int i = 0; i < 300; i++) {
        Vec3 corner = vec3(8 * rng_uniform(&rng) - 4, 8 * rng_uniform(&rng) - 4, 8 * rng_uniform(&rng) - 4);
        double size = pow(10.0, 2 * rng_uniform(&rng) - 1.5);
        Vec3 a = vec3_add_scaled(corner, random_unit_vector(&rng), size);
        Vec3 b = vec3_add_scaled(corner, random_unit_vector(&rng), size);
        scene_add_triangle(&scene, triangle_make(corner, a, b, m));
        if (i % 10 == 0)
            scene_add_sphere(&scene, (Sphere){corner, 0.5 * size, m});
    }
    assert_int_equal(scene_prepare(&scene), 0);
    compare_with_brute_force(&scene, 5.0, 100000);
    scene_free(&scene);
}

/* 2000 copies of one triangle: no split helps, the builder falls back to median splits
 * below BVH_SAH_LEVELS and the traversal stack is enough. */
static void test_identical_triangles(void **state)
{
    (void)state;
    Scene scene;
    scene_init(&scene);
    Material grey = {"grey", MATERIAL_LAMBERT, vec3(0.5, 0.5, 0.5), vec3(0, 0, 0), 0.0, 1.0};
    int m = scene_add_material(&scene, grey);
    for (int i = 0; i < 2000; i++)
        scene_add_triangle(&scene, triangle_make(vec3(-1, -1, 0), vec3(1, -1, 0), vec3(0, 1, 0), m));
    assert_int_equal(scene_prepare(&scene), 0);
    assert_true(scene.bvh.node_count < 2 * 2000);
    compare_with_brute_force(&scene, 2.0, 20000);
    scene_free(&scene);
}

/* An empty scene has an empty tree, and every ray misses. */
static void test_empty_scene(void **state)
{
    (void)state;
    Scene scene;
    scene_init(&scene);
    assert_int_equal(scene_prepare(&scene), 0);
    Hit hit;
    Ray ray = {vec3(0, 0, 0), vec3(0, 0, 1)};
    assert_int_equal(scene_intersect(&scene, ray, INFINITY, &hit), 0);
    scene_free(&scene);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_room_matches_brute_force),
        cmocka_unit_test(test_random_soup_matches_brute_force),
        cmocka_unit_test(test_identical_triangles),
        cmocka_unit_test(test_empty_scene),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
