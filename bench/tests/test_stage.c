/* test_stage.c (bench, chapter 9): each of chapter 9's stages answers its ray queries the
 * way it names (stage.h), so that its row measures that way and no other.
 *
 * Two triangles (a square, among 100 small ones elsewhere) are moved far away after the
 * scene's structures are built: testing every primitive sees them where they are now;
 * chapter 2's tree, whose boxes are where they were, turns the ray to their new place
 * away and finds nothing at the old one; the four-wide tree keeps copies of its
 * triangles and sees them where they were. A render of each place through stage_measure
 * shows which answered.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include "stage.h"

/* 1 where the ray hits anything, else 0. */
static Vec3 hit_or_not(const Scene *scene, Ray ray, Rng *rng, const void *settings,
                       RayCounts *counts)
{
    Hit hit;
    counts->camera++;
    double v = scene_intersect(scene, ray, INFINITY, &hit);
    return vec3(v, v, v);
}

/* The mean of a 4 x 4 render by `stage`, looking straight down at (x, 0, 0). */
static double seen(Scene *scene, const Stage *stage, double x)
{
    scene->camera = camera_make(vec3(x, 0, 10), vec3(x - 0.1, -0.1, 9), vec3(x + 0.1, -0.1, 9),
                                vec3(x - 0.1, 0.1, 9));
    RenderSettings settings = {.image = {.width = 4, .height = 4, .spp = 1, .seed = 1},
                               .threads = 1,
                               .label = "stage"};
    StageResult result;
    assert_int_equal(stage_measure(scene, &settings, hit_or_not, NULL, stage, 0.0, &result), 0);
    double sum = 0.0;
    for (int i = 0; i < 3 * 16; i++)
        sum += result.first.image.pixels[i];
    render_result_free(&result.first);
    return sum / (3 * 16);
}

static void test_each_stage_answers_its_own_way(void **state)
{
    Scene scene;
    scene_init(&scene);
    Material grey = {
        .name = "grey", .kind = MATERIAL_LAMBERT, .reflectance = vec3(0.5, 0.5, 0.5)};
    int m = scene_add_material(&scene, grey);
    assert_true(scene_add_triangle(&scene, triangle_make(vec3(-1, -1, 0), vec3(1, -1, 0),
                                                         vec3(1, 1, 0), m)) >= 0);
    assert_true(scene_add_triangle(&scene, triangle_make(vec3(-1, -1, 0), vec3(1, 1, 0),
                                                         vec3(-1, 1, 0), m)) >= 0);
    for (int k = 0; k < 100; k++) { /* small triangles elsewhere: a tree of many nodes */
        Vec3 corner = vec3(-20 + k % 10, -5 + k / 10, 0);
        assert_true(scene_add_triangle(
                        &scene, triangle_make(corner, vec3_add(corner, vec3(0.5, 0, 0)),
                                              vec3_add(corner, vec3(0, 0.5, 0)), m)) >= 0);
    }
    assert_int_equal(scene_prepare(&scene), 0);
    for (int t = 0; t < 2; t++)
        scene.triangles[t].v0 = vec3_add(scene.triangles[t].v0, vec3(100, 0, 0));
    /* What each stage sees at the old place and at the new one. */
    const double expected[QUERY_STAGE_COUNT][2] = {{0, 1}, {0, 0}, {1, 0}};
    for (int s = 0; s < QUERY_STAGE_COUNT; s++) {
        double old_place = seen(&scene, &QUERY_STAGES[s], 0.0),
               new_place = seen(&scene, &QUERY_STAGES[s], 100.0);
        print_message("    %-26s sees %g at the old place, %g at the new\n",
                      QUERY_STAGES[s].name, old_place, new_place);
        if (old_place != expected[s][0] || new_place != expected[s][1])
            fail_msg("the stage '%s' does not answer as it names: %g and %g, not %g and %g",
                     QUERY_STAGES[s].name, old_place, new_place, expected[s][0],
                     expected[s][1]);
    }
    scene_free(&scene);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_each_stage_answers_its_own_way),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
