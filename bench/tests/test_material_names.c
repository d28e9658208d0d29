/* test_material_names.c (bench, chapter 1): the scene reader's materials by name
 * (material_names.h).
 *
 * The reader looks up the material of every shape it reads, so a lookup must cost a
 * name or two whatever the number of materials: a linear scan compares half of them on
 * average, and reading n materials and n shapes would cost n^2 / 2 comparisons. Here
 * 100,000 materials are listed and every one looked up, with the number of names each
 * lookup compares counted.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <stdio.h>
#include <string.h>

#include "material_names.h"
#include "scene_file.h"

/* Materials by name, 100,000 of them. Each name is found at its index, and the cost of
 * a lookup -- the names it compares -- stays that of a hash table at most half full,
 * whatever the count: at most 2 on average and 40 at worst, for the names there and
 * for unknown names alike (a scan compares 50,000 on average). A second material of a
 * name, which the reader refuses before listing it (test_scene_file.c), leaves the
 * first one found, by the table and by the scene's own scan alike. */
static void test_material_lookup(void **state)
{
    enum {
        COUNT = 100000
    };
    Scene scene;
    scene_init(&scene);
    MaterialNames names;
    material_names_init(&names);
    assert_int_equal(material_names_find(&names, &scene, "material0", NULL), -1);
    Material m = {.kind = MATERIAL_LAMBERT};
    for (int i = 0; i < COUNT; i++) {
        snprintf(m.name, sizeof m.name, "material%d", i);
        assert_int_equal(scene_add_material(&scene, m), i);
        assert_int_equal(material_names_add(&names, &scene, i), 0);
    }
    long total = 0, unknown_total = 0;
    int worst = 0;
    for (int i = 0; i < COUNT; i++) {
        char name[MATERIAL_NAME_MAX];
        snprintf(name, sizeof name, "material%d", i);
        int cost = 0;
        assert_int_equal(material_names_find(&names, &scene, name, &cost), i);
        total += cost;
        worst = cost > worst ? cost : worst;
        snprintf(name, sizeof name, "other%d", i);
        cost = 0;
        assert_int_equal(material_names_find(&names, &scene, name, &cost), -1);
        unknown_total += cost;
        worst = cost > worst ? cost : worst;
    }
    print_message("    material lookups: %.2f names compared on average (%.2f for unknown "
                  "names), %d at worst\n",
                  (double)total / COUNT, (double)unknown_total / COUNT, worst);
    assert_true(total <= 2L * COUNT && unknown_total <= 2L * COUNT);
    assert_true(worst <= 40);
    strcpy(m.name, "material7");
    assert_int_equal(scene_add_material(&scene, m), COUNT);
    assert_int_equal(material_names_find(&names, &scene, "material7", NULL), 7);
    assert_int_equal(scene_file_material(&scene, "material7"), 7);
    material_names_free(&names);
    assert_int_equal(material_names_find(&names, &scene, "material7", NULL), -1);
    scene_free(&scene);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_material_lookup),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
