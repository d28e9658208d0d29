/* test_scene_file.c (bench, chapter 1): reading the scene format, version 1
 * (scene_file.h, docs/scene-format.md).
 *
 * The report's room loads with the counts its file declares; each material kind and
 * shape is stored as material.h and docs/scene-format.md document (quads split along
 * P0-P2, box and tetrahedron normals outward); an oren_nayar material, checked like
 * the others, is refused until chapter 5 introduces it; comments, blank lines, tabs, a
 * byte order mark and CRLF or CR line ends are only layout; the reader reports the
 * line count and the hash of the bytes it read (SceneFileInfo); and every kind of bad
 * input is an error "NAME:LINE: what is wrong" at the right line that leaves the scene
 * empty -- an invisible non-ASCII character named by its code point, a scale, an
 * emission or a file size beyond the limits, under a name of any length.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "assert_close.h"
#include "scene_file.h"

/* A valid camera line, for scenes that need to load. */
#define CAMERA "camera -1 0 0  0 1 -1  0 -1 -1  0 1 1\n"

static void assert_scene_empty(const Scene *scene)
{
    assert_null(scene->materials);
    assert_null(scene->triangles);
    assert_null(scene->spheres);
    assert_null(scene->point_lights);
    assert_int_equal(scene->material_count + scene->triangle_count + scene->sphere_count +
                         scene->point_light_count,
                     0);
#if CHAPTER >= 3
    assert_null(scene->light_triangles);
    assert_null(scene->light_cumulative);
    assert_int_equal(scene->light_count, 0);
#endif
    /* No camera is left either: a camera read has an image plane of non-zero size. */
    assert_true(vec3_max_abs(scene->camera.right) == 0.0 &&
                vec3_max_abs(scene->camera.up) == 0.0);
}

/* Parse `text` (named "t.scene"), which must succeed; returns what the reader reports
 * of the text beyond the scene. */
static SceneFileInfo parse_ok(const char *text, Scene *scene)
{
    char error[512] = "";
    SceneFileInfo info;
    if (scene_parse(text, strlen(text), "t.scene", scene, &info, error, sizeof error) != 0)
        fail_msg("unexpected error: %s", error);
    return info;
}

/* Read file `path` once and parse it, as every chapter program does (experiment.h);
 * returns what the reader reports of it beyond the scene. */
static SceneFileInfo load_ok(const char *path, Scene *scene)
{
    char error[512] = "", *text;
    size_t length;
    SceneFileInfo info;
    if (scene_file_read(path, &text, &length, error, sizeof error) != 0)
        fail_msg("%s", error);
    int status = scene_parse(text, length, path, scene, &info, error, sizeof error);
    free(text);
    if (status != 0)
        fail_msg("%s", error);
    return info;
}

/* Parsing `text` (named "t.scene") fails with a message that begins "t.scene:LINE: "
 * and contains `what`, and leaves the scene empty. */
static void expect_error(const char *text, int line, const char *what)
{
    Scene scene;
    char error[512] = "", prefix[64];
    assert_int_equal(
        scene_parse(text, strlen(text), "t.scene", &scene, NULL, error, sizeof error), -1);
    snprintf(prefix, sizeof prefix, "t.scene:%d: ", line);
    if (strncmp(error, prefix, strlen(prefix)) != 0 || !strstr(error, what))
        fail_msg("for input \"%s\":\n got      \"%s\"\n expected \"%s...%s...\"", text, error,
                 prefix, what);
    assert_scene_empty(&scene);
}

/* The report's room (scenes/room.scene): 38 triangles (9 quads of 2, 4 triangles, a
 * box of 12 and a tetrahedron of 4), 2 spheres, 9 materials, a camera, and one area
 * light: the lamp quad's 2 triangles, of total area 2 x 2 = 4, facing down; 30 lines. */
static void test_room_loads(void **state)
{
    Scene scene;
    SceneFileInfo info = load_ok("scenes/room.scene", &scene);
    assert_int_equal(scene.triangle_count, 38);
    assert_int_equal(scene.sphere_count, 2);
    assert_int_equal(scene.material_count, 9);
    assert_int_equal(scene.point_light_count, 0);
    assert_int_equal(info.line_count, 30);
#if CHAPTER >= 3
    assert_int_equal(scene.light_count, 2);
    assert_close(scene.light_area, 4.0, 1e-12);
    for (int i = 0; i < scene.light_count; i++)
        assert_close(scene.triangles[scene.light_triangles[i]].normal.z, -1.0, 1e-15);
#endif
    const Material *lamp = &scene.materials[scene_file_material(&scene, "lamp")];
    assert_int_equal(lamp->kind, MATERIAL_LIGHT);
    assert_close(lamp->emission.y, 25.0, 0.0);
    assert_close(vec3_max_abs(lamp->reflectance), 0.0, 0.0);
    assert_close(scene.materials[scene_file_material(&scene, "glass")].ior, 1.5, 0.0);
    /* The camera: eye, bottom-left corner, and the plane's full width and height. */
    assert_close(scene.camera.eye.x, -1.0, 0.0);
    assert_close(scene.camera.right.y, -2.0, 0.0);
    assert_close(scene.camera.up.z, 2.0, 0.0);
    scene_free(&scene);
}

/* The aspect is |BR - BL| / |TL - BL|: 1 for the room, 2 for a plane twice as wide as
 * high and tilted. */
static void test_aspect(void **state)
{
    Camera room = camera_make(vec3(-1, 0, 0), vec3(0, 1, -1), vec3(0, -1, -1), vec3(0, 1, 1));
    Camera tilted = camera_make(vec3(0, 0, 0), vec3(1, 1, 1), vec3(3, 3, 1), vec3(2, 0, 1));
    assert_close(scene_file_aspect(&room), 1, 1e-15);
    assert_close(vec3_dot(tilted.right, tilted.up), 0, 1e-15);
    assert_close(scene_file_aspect(&tilted), 2, 1e-14);
}

/* The Whitted room has a point light with its intensity and no area light. */
static void test_whitted_room_loads(void **state)
{
    Scene scene;
    char error[512] = "";
    if (scene_load("scenes/room_whitted.scene", &scene, error, sizeof error) != 0)
        fail_msg("%s", error);
    assert_int_equal(scene.point_light_count, 1);
    assert_close(scene.point_lights[0].position.z, 4.0, 0.0);
    assert_close(scene.point_lights[0].intensity.x, 150.0, 0.0);
#if CHAPTER >= 3
    assert_int_equal(scene.light_count, 0);
#endif
    scene_free(&scene);
}

/* Each material kind fills the fields material.h documents, and nothing else. */
static void test_material_kinds(void **state)
{
    Scene scene;
    parse_ok(CAMERA "material a lambert 0.1 0.2 0.3\n"
                    "material c mirror 0.9 0.8 0.7\n"
                    "material d glass 1.33\n"
                    "material e light 1 2 3\n",
             &scene);
    const Material *m = scene.materials;
    assert_int_equal(scene.material_count, 4);
    assert_string_equal(m[0].name, "a");
    assert_int_equal(m[0].kind, MATERIAL_LAMBERT);
    assert_close(m[0].reflectance.z, 0.3, 0.0);
    assert_close(vec3_max_abs(m[0].emission), 0.0, 0.0);
    assert_int_equal(m[1].kind, MATERIAL_MIRROR);
    assert_close(m[1].reflectance.x, 0.9, 0.0);
    assert_int_equal(m[2].kind, MATERIAL_GLASS);
    assert_close(m[2].ior, 1.33, 0.0);
    assert_close(vec3_max_abs(m[2].reflectance), 0.0, 0.0);
    assert_int_equal(m[3].kind, MATERIAL_LIGHT);
    assert_close(m[3].emission.z, 3.0, 0.0);
    assert_close(vec3_max_abs(m[3].reflectance), 0.0, 0.0);
    assert_true(vec3_max_component(m[3].emission) > 0.0);
    scene_free(&scene);
}

/* The boundary values are accepted: reflectance 0 and 1, emission 0 (a light that emits
 * nothing: a program that needs a light says so, naming it), and a material name of
 * MATERIAL_NAME_MAX - 1 bytes, found under that name. */
static void test_boundary_values_accepted(void **state)
{
    char text[512], name[MATERIAL_NAME_MAX];
    memset(name, 'n', sizeof name - 1);
    name[sizeof name - 1] = '\0';
    snprintf(text, sizeof text,
             CAMERA "material a lambert 0 0 0\nmaterial b mirror 1 1 1\n"
                    "material d light 0 0 0\n"
                    "material %s glass 1e-3\n",
             name);
    Scene scene;
    parse_ok(text, &scene);
    assert_int_equal(scene.material_count, 4);
    assert_int_equal(scene_file_material(&scene, name), 3);
    scene_free(&scene);
}

#if CHAPTER < 5
/* Before chapter 5 an oren_nayar material is refused, after the checks every material
 * line gets (its count of numbers, its reflectance and sigma: test_wrong_count,
 * test_reflectance_out_of_range, test_negative_sigma), by saying which chapter
 * introduces it. */
static void test_oren_nayar_before_chapter_5(void **state)
{
    expect_error(CAMERA "material b oren_nayar 0 1 0.5 0.3\n", 2,
                 "material 'b' is oren_nayar, which chapter 5 introduces");
}
#endif

#if CHAPTER >= 5
/* An Oren-Nayar material fills its reflectance and its roughness sigma, and nothing
 * else, beside the other kinds (test_material_kinds). */
static void test_oren_nayar_material(void **state)
{
    Scene scene;
    parse_ok(CAMERA "material a lambert 0.1 0.2 0.3\n"
                    "material b oren_nayar 0 1 0.5 0.3\n",
             &scene);
    const Material *m = scene.materials;
    assert_int_equal(scene.material_count, 2);
    assert_int_equal(m[0].kind, MATERIAL_LAMBERT);
    assert_string_equal(m[1].name, "b");
    assert_int_equal(m[1].kind, MATERIAL_OREN_NAYAR);
    assert_close(m[1].reflectance.y, 1.0, 0.0);
    assert_close(m[1].sigma, 0.3, 0.0);
    assert_close(vec3_max_abs(m[1].emission), 0.0, 0.0);
    scene_free(&scene);
}

/* The roughness's boundary value, sigma 0 (a Lambertian surface), is accepted, with
 * reflectances 0 and 1. */
static void test_oren_nayar_boundary_values_accepted(void **state)
{
    Scene scene;
    parse_ok(CAMERA "material c oren_nayar 1 0 1 0\n", &scene);
    assert_int_equal(scene.material_count, 1);
    assert_int_equal(scene_file_material(&scene, "c"), 0);
    assert_close(scene.materials[0].sigma, 0.0, 0.0);
    scene_free(&scene);
}
#endif

/* A triangle keeps its vertex order: front side (v1 - v0) x (v2 - v0). */
static void test_triangle_front_side(void **state)
{
    Scene scene;
    parse_ok(CAMERA "material m lambert .5 .5 .5\ntriangle m 0 0 0  0 1 0  1 0 0\n", &scene);
    assert_int_equal(scene.triangle_count, 1);
    assert_close(scene.triangles[0].normal.z, -1.0, 1e-15);
    assert_close(scene.triangles[0].area, 0.5, 1e-15);
    scene_free(&scene);
}

/* A quad is the triangles (P0, P1, P2) and (P0, P2, P3), both facing
 * (P1 - P0) x (P2 - P0), with the quad's area between them. */
static void test_quad_split(void **state)
{
    Scene scene;
    parse_ok(CAMERA "material m lambert .5 .5 .5\nquad m 0 0 0  2 0 0  2 1 0  0 1 0\n", &scene);
    assert_int_equal(scene.triangle_count, 2);
    const Triangle *t = scene.triangles;
    for (int i = 0; i < 2; i++) {
        assert_close(t[i].normal.z, 1.0, 1e-15);
        assert_close(t[i].v0.x, 0.0, 0.0);
    }
    assert_close(t[0].e1.x, 2.0, 0.0); /* P1 - P0 */
    assert_close(t[0].e2.y, 1.0, 0.0); /* P2 - P0 */
    assert_close(t[1].e2.x, 0.0, 0.0); /* P3 - P0 */
    assert_close(t[0].area + t[1].area, 2.0, 1e-15);
    scene_free(&scene);
}

/* Every triangle of `scene` faces away from `inside`, and their areas sum to `area`. */
static void assert_closed_outward(const Scene *scene, Vec3 inside, double area)
{
    double total = 0.0;
    for (int i = 0; i < scene->triangle_count; i++) {
        const Triangle *t = &scene->triangles[i];
        Vec3 centroid =
            vec3_add_scaled(vec3_add_scaled(t->v0, t->e1, 1.0 / 3.0), t->e2, 1.0 / 3.0);
        assert_true(vec3_dot(t->normal, vec3_sub(centroid, inside)) > 0.0);
        total += t->area;
    }
    assert_close(total, area, 1e-12 * area);
}

/* A box is 12 triangles, each with an axis-aligned normal pointing out of the box,
 * covering its surface area 2(ab + bc + ca); the same at scales 1e-3 and 1e3. */
static void test_box_normals_outward(void **state)
{
    const double scales[] = {1e-3, 1.0, 1e3};
    for (int k = 0; k < 3; k++) {
        double s = scales[k];
        char text[512];
        snprintf(text, sizeof text,
                 CAMERA "material m lambert .5 .5 .5\nbox m %g %g %g %g %g %g\n", 1 * s, 2 * s,
                 3 * s, 2 * s, 4 * s, 6 * s);
        Scene scene;
        parse_ok(text, &scene);
        assert_int_equal(scene.triangle_count, 12);
        assert_closed_outward(&scene, vec3(1.5 * s, 3 * s, 4.5 * s), 2 * (2 + 6 + 3) * s * s);
        for (int i = 0; i < 12; i++)
            assert_close(vec3_max_abs(scene.triangles[i].normal), 1.0, 1e-15);
        scene_free(&scene);
    }
}

/* A tetrahedron is 4 triangles facing away from its centroid, whichever way round its
 * vertices are listed (positive or negative orientation). */
static void test_tetrahedron_normals_outward(void **state)
{
    const char *texts[] = {
        CAMERA "material m lambert .5 .5 .5\ntetrahedron m 0 0 0  1 0 0  0 1 0  0 0 1\n",
        CAMERA "material m lambert .5 .5 .5\ntetrahedron m 0 0 0  0 1 0  1 0 0  0 0 1\n",
    };
    for (int k = 0; k < 2; k++) {
        Scene scene;
        parse_ok(texts[k], &scene);
        assert_int_equal(scene.triangle_count, 4);
        assert_closed_outward(&scene, vec3(0.25, 0.25, 0.25), 1.5 + 0.5 * sqrt(3.0));
        scene_free(&scene);
    }
}

/* Comments (whole lines and after a statement, even touching a number), blank lines,
 * tabs, CRLF line ends and a missing final newline are layout only; the line count is
 * the number of lines. */
static void test_layout(void **state)
{
    const char *text = "# a comment\r\n"
                       "\r\n"
                       "   \t  \r\n"
                       "camera\t-1 0 0  0 1 -1  0 -1 -1  0 1 1   # the eye\r\n"
                       "material m lambert .5 .5 .5#touching\r\n"
                       "sphere m 0 0 0 1";
    Scene scene;
    SceneFileInfo info = parse_ok(text, &scene);
    assert_int_equal(info.line_count, 6);
    assert_int_equal(scene.sphere_count, 1);
    assert_close(scene.materials[0].reflectance.z, 0.5, 0.0);
    scene_free(&scene);
}

/* The accepted spellings of numbers: "1", "-2.5", "1e-3", ".5", "+3", "2.", "1E2". */
static void test_number_spellings(void **state)
{
    Scene scene;
    parse_ok(CAMERA "point_light 1 -2.5 1e-3  .5 +3 2.\nmaterial m glass 1E2\n", &scene);
    const PointLight *light = &scene.point_lights[0];
    assert_close(light->position.x, 1.0, 0.0);
    assert_close(light->position.y, -2.5, 0.0);
    assert_close(light->position.z, 1e-3, 0.0);
    assert_close(light->intensity.x, 0.5, 0.0);
    assert_close(light->intensity.y, 3.0, 0.0);
    assert_close(light->intensity.z, 2.0, 0.0);
    assert_close(scene.materials[0].ior, 100.0, 0.0);
    scene_free(&scene);
}

/* Shapes far smaller or larger than the room are not mistaken for degenerate ones: the
 * flatness tests are relative to each shape's size. */
static void test_scale_invariance(void **state)
{
    Scene scene;
    parse_ok("camera -1e-3 0 0  0 1e-3 -1e-3  0 -1e-3 -1e-3  0 1e-3 1e-3\n"
             "material m lambert .5 .5 .5\n"
             "quad m 0 0 0  1e-4 0 0  1e-4 1e-4 0  0 1e-4 0\n"
             "tetrahedron m 1e3 0 0  1001 0 0  1e3 1 0  1e3 0 1\n"
             "triangle m 1e6 0 0  2e6 0 0  1e6 1e6 0\n"
             "triangle m 1e-40 0 0  2e-40 0 0  1e-40 1e-40 0\n"
             "quad m 0 0 0  1e40 0 0  1e40 1e40 0  0 1e40 0\n",
             &scene);
    assert_int_equal(scene.triangle_count, 10);
    scene_free(&scene);
}

/* An unknown keyword names itself. */
static void test_unknown_keyword(void **state)
{
    expect_error(CAMERA "spher m 0 0 0 1\n", 2, "unknown keyword 'spher'");
    expect_error("Camera -1 0 0  0 1 -1  0 -1 -1  0 1 1\n", 1, "unknown keyword 'Camera'");
}

/* An unknown material kind, or a material without name and kind. */
static void test_unknown_material_kind(void **state)
{
    expect_error("material m plastic 1 1 1\n", 1, "unknown material kind 'plastic'");
    expect_error("material m\n", 1, "needs a name and a kind");
}

/* Too few or too many numbers: the message says how many the keyword takes. */
static void test_wrong_count(void **state)
{
    expect_error("camera -1 0 0  0 1 -1  0 -1 -1  0 1\n", 1, "expected 12 numbers, found 11");
    expect_error("material m lambert 1 1 1 1\n", 1, "expected 3 numbers, found 4");
    expect_error("material m oren_nayar 1 1 1\n", 1, "expected 4 numbers, found 3");
    expect_error("material m glass\n", 1, "expected 1 numbers, found 0");
    expect_error("material m lambert .5 .5 .5\ntriangle m 0 0 0 1 0 0 0 1\n", 2,
                 "expected 9 numbers, found 8");
    expect_error("triangle\n", 1, "expected 9 numbers, found 0");
    expect_error("point_light 0 0 0 1 1 1 1\n", 1, "expected 6 numbers, found 7");
}

/* Tokens that strtod would take but that are not decimal numbers, or not whole ones. */
static void test_not_a_number(void **state)
{
    const char *bad[] = {"nan", "inf", "-infinity", "0x10", "1.5abc", "1e", "e5",
                         ".",   "-",   "+-1",       "1,5",  "--1",    "1e+"};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        char text[128], what[64];
        snprintf(text, sizeof text, "point_light 0 0 %s 1 1 1\n", bad[i]);
        snprintf(what, sizeof what, "'%s' is not a decimal number", bad[i]);
        expect_error(text, 1, what);
    }
}

/* Numbers that overflow to infinity, or beyond 1e50 (the scales the reader takes). The
 * room scaled by 1e77 is refused for that, not for "the eye on the image plane" (which
 * a cross product overflowed to infinity would wrongly report). 1e50 itself is
 * accepted. */
static void test_number_out_of_range(void **state)
{
    expect_error("point_light 0 0 1e400 1 1 1\n", 1, "'1e400' is out of range");
    expect_error("point_light 0 0 0 -1e309 1 1\n", 1, "'-1e309' is out of range");
    expect_error("point_light 0 0 0 1e51 1 1\n", 1,
                 "'1e51' is out of range: numbers are "
                 "finite and within +-1e+50");
    expect_error("camera -1e77 0 0  0 1e77 -1e77  0 -1e77 -1e77  0 1e77 1e77\n", 1,
                 "'-1e77' is out of range");
    Scene scene;
    parse_ok(CAMERA "point_light 0 0 -1e50 1 1 1\n", &scene);
    scene_free(&scene);
}

/* Shapes below 1e-50 across are refused as too small (their cross products would
 * underflow), each kind by name; at 1e-49 they are read. */
static void test_too_small(void **state)
{
    const char *shapes[] = {
        "triangle m 0 0 0  %s 0 0  0 %s 0\n", "quad m 0 0 0  %s 0 0  %s %s 0  0 %s 0\n",
        "box m 0 0 0  %s %s %s\n", "tetrahedron m 0 0 0  %s 0 0  0 %s 0  0 0 %s\n",
        "sphere m 0 0 0 %s\n"};
    const char *names[] = {"triangle", "quad", "box", "tetrahedron", "sphere"};
    for (int i = 0; i < 5; i++) {
        char line[256], text[512];
        snprintf(line, sizeof line, shapes[i], "1e-51", "1e-51", "1e-51", "1e-51");
        snprintf(text, sizeof text, CAMERA "material m lambert .5 .5 .5\n%s", line);
        expect_error(text, 3, names[i]);
        expect_error(text, 3, "is too small: the reader takes sizes from 1e-50 to 1e+50");
        snprintf(line, sizeof line, shapes[i], "1e-49", "1e-49", "1e-49", "1e-49");
        snprintf(text, sizeof text, CAMERA "material m lambert .5 .5 .5\n%s", line);
        Scene scene;
        parse_ok(text, &scene);
        scene_free(&scene);
    }
    expect_error("camera -1e-51 0 0  0 1e-51 -1e-51  0 -1e-51 -1e-51  0 1e-51 1e-51\n", 1,
                 "camera: the image plane");
}

/* Below 1e-50 a shape is refused as too small, whatever the scale, and never as flat: a
 * squared length below about 1e-154 underflows (to 0 below about 1e-162), so a reader
 * that squares lengths calls a tiny shape "zero area" or its image plane "collinear".
 * Each kind, and the camera, at 1e-60 down to 1e-300. */
static void test_too_small_at_every_scale(void **state)
{
    const char *shapes[] = {
        "triangle m 0 0 0  1%s 0 0  0 1%s 0\n", "quad m 0 0 0  1%s 0 0  1%s 1%s 0  0 1%s 0\n",
        "box m 0 0 0  1%s 1%s 1%s\n", "tetrahedron m 0 0 0  1%s 0 0  0 1%s 0  0 0 1%s\n",
        "camera 0 0 1%s  -1%s -1%s 0  1%s -1%s 0  -1%s 1%s 0\n"};
    const char *exponents[] = {"e-60", "e-155", "e-160", "e-170", "e-200", "e-300", "e-307"};
    for (int i = 0; i < 5; i++)
        for (int k = 0; k < 7; k++) {
            const char *e = exponents[k];
            char line[512], text[1024];
            snprintf(line, sizeof line, shapes[i], e, e, e, e, e, e, e);
            snprintf(text, sizeof text, "%smaterial m lambert .5 .5 .5\n%s",
                     i < 4 ? CAMERA : "", line);
            expect_error(text, i < 4 ? 3 : 2,
                         "is too small: the reader takes sizes from 1e-50 to 1e+50");
        }
}

/* The flatness tests are relative: at 1e-45 and at 1e45 a flat shape is still found
 * flat (a sliver 1e-12 as thin as long, a quad's corner 1e-6 off its plane, a flat
 * tetrahedron, an image plane's collinear corners, an eye on the image plane), and the
 * same shapes made whole are read. */
static void test_flat_at_extreme_scales(void **state)
{
    const char *flat[][2] = {
        {"triangle m 0 0 0  1%s 0 0  0.5%s 0.000000000001%s 0\n",
         "degenerate triangle (zero area)"},
        {"quad m 0 0 0  1%s 0 0  1%s 1%s 0  0 1%s 0.000001%s\n", "non-planar quad"},
        {"tetrahedron m 0 0 0  1%s 0 0  0 1%s 0  1%s 1%s 0\n", "flat tetrahedron"},
        {"camera 0 0 1%s  -1%s 0 0  1%s 0 0  3%s 0 0\n",
         "the image plane's corners are collinear"},
        {"camera 0 -1%s 0  -1%s -1%s 0  1%s -1%s 0  -1%s 1%s 0\n",
         "the eye is on the image plane"},
    };
    const char *whole[] = {"triangle m 0 0 0  1%s 0 0  0.5%s 0.001%s 0\n",
                           "quad m 0 0 0  1%s 0 0  1%s 1%s 0  0 1%s 0%s\n",
                           "tetrahedron m 0 0 0  1%s 0 0  0 1%s 0  0 0 1%s\n"};
    const char *exponents[] = {"e-45", "e45"};
    for (int k = 0; k < 2; k++) {
        const char *e = exponents[k];
        for (int i = 0; i < 5; i++) {
            char line[512], text[1024];
            snprintf(line, sizeof line, flat[i][0], e, e, e, e, e, e, e);
            snprintf(text, sizeof text, "%smaterial m lambert .5 .5 .5\n%s",
                     i < 3 ? CAMERA : "", line);
            expect_error(text, i < 3 ? 3 : 2, flat[i][1]);
        }
        for (int i = 0; i < 3; i++) {
            char line[512], text[1024];
            snprintf(line, sizeof line, whole[i], e, e, e, e, e);
            snprintf(text, sizeof text, CAMERA "material m lambert .5 .5 .5\n%s", line);
            Scene scene;
            parse_ok(text, &scene);
            scene_free(&scene);
        }
    }
}

/* A number too small for a double to hold with all its digits (a subnormal, or one
 * that reads as 0) is refused as that, not read as a number near 0 that makes a shape
 * "flat" or "collinear" further on; 0 written any way, and the smallest normal double,
 * are read. */
static void test_number_too_small_to_compute(void **state)
{
    const char *refused[] = {"1e-310", "-1e-400", "4.9e-324", "2.2e-308", "0.0001e-305"};
    for (int i = 0; i < 5; i++) {
        char text[256], message[128];
        snprintf(text, sizeof text, "point_light 0 0 %s 1 1 1\n", refused[i]);
        snprintf(message, sizeof message,
                 "'%s' is too small to compute with: below 2.22507e-308", refused[i]);
        expect_error(text, 1, message);
    }
    Scene scene;
    parse_ok(CAMERA "point_light 0 0e-400 -0.000 2.2250738585072014e-308 1 1\n", &scene);
    scene_free(&scene);
}

/* Emission (and point lights' intensity) above 1e20 is refused, so that the image's
 * radiance stays finite (1e100 would make pixels of 32-bit floats infinite; it is
 * beyond the numbers' range too). 1e20 is read. */
static void test_emission_bound(void **state)
{
    expect_error("material L light 1e100 1e100 1e100\n", 1, "'1e100' is out of range");
    expect_error("material L light 1e30 1e30 1e30\n", 1, "emission 1e30 1e30 1e30 above 1e+20");
    expect_error("material L light 0 1.1e20 0\n", 1, "above 1e+20");
    expect_error("point_light 0 0 0  1 1e21 1\n", 1, "point_light intensity above 1e+20");
    Scene scene;
    parse_ok(CAMERA "material L light 1e20 1e20 1e20\npoint_light 0 0 0 1e20 0 0\n", &scene);
    assert_close(scene.materials[0].emission.y, 1e20, 0.0);
    scene_free(&scene);
}

/* A material used before it is defined, or never. */
static void test_unknown_material(void **state)
{
    expect_error(CAMERA "sphere m 0 0 0 1\nmaterial m lambert .5 .5 .5\n", 2,
                 "unknown material 'm'");
}

static void test_duplicate_material(void **state)
{
    expect_error("material m lambert .5 .5 .5\n\nmaterial m glass 1.5\n", 3,
                 "duplicate material 'm'");
}

/* A name one byte too long for Material.name. */
static void test_material_name_too_long(void **state)
{
    char text[256], name[MATERIAL_NAME_MAX + 1];
    memset(name, 'n', sizeof name - 1);
    name[sizeof name - 1] = '\0';
    snprintf(text, sizeof text, "material %s glass 1.5\n", name);
    expect_error(text, 1, "material name longer than 63 bytes");
}

static void test_second_camera(void **state)
{
    expect_error(CAMERA "# again:\n" CAMERA, 3, "a second camera (the first is on line 1)");
}

/* Reflectance above 1 or below 0, for each kind that has one. */
static void test_reflectance_out_of_range(void **state)
{
    expect_error("material m lambert 0.5 1.01 0.5\n", 1,
                 "reflectance 0.5 1.01 0.5 outside [0, 1]");
    expect_error("material m oren_nayar -0.1 0.5 0.5 0.2\n", 1, "outside [0, 1]");
    expect_error("material m mirror 1 1 2\n", 1, "outside [0, 1]");
    expect_error("material m mirror 1.0000001 1 1\n", 1,
                 "reflectance 1.0000001 1 1 outside [0, 1]");
}

static void test_negative_emission(void **state)
{
    expect_error("material m light 1 -1 1\n", 1, "negative emission");
}

static void test_negative_sigma(void **state)
{
    expect_error("material m oren_nayar .5 .5 .5 -0.1\n", 1, "negative sigma");
}

static void test_ior_not_positive(void **state)
{
    expect_error("material m glass 0\n", 1, "index of refraction 0 must be > 0");
    expect_error("material m glass -1.5\n", 1, "must be > 0");
}

static void test_sphere_radius_not_positive(void **state)
{
    expect_error("material m glass 1.5\nsphere m 0 0 0 -1\n", 2,
                 "sphere radius -1 must be > 0");
    expect_error("material m glass 1.5\nsphere m 0 0 0 0\n", 2, "sphere radius 0 must be > 0");
}

/* Chapter 3 samples area lights by triangle, so an emitting sphere is refused. */
static void test_sphere_light(void **state)
{
    expect_error("material lamp light 1 1 1\nsphere lamp 0 0 0 1\n", 2,
                 "a sphere cannot be a light: area lights are triangles, quads, boxes or "
                 "tetrahedra");
}

static void test_point_light_negative(void **state)
{
    expect_error("point_light 0 0 0  1 1 -1\n", 1, "negative point_light intensity");
}

/* Zero area: collinear vertices, a repeated vertex, and a sliver 1e-12 as thin as it
 * is long (relative, so a large triangle cannot hide it). */
static void test_degenerate_triangle(void **state)
{
    expect_error("material m lambert .5 .5 .5\ntriangle m 0 0 0  1 1 1  2 2 2\n", 2,
                 "degenerate triangle (zero area)");
    expect_error("material m lambert .5 .5 .5\ntriangle m 0 0 0  0 0 0  0 0 1\n", 2,
                 "degenerate triangle");
    expect_error("material m lambert .5 .5 .5\ntriangle m 0 0 0  1e6 0 0  5e5 1e-6 0\n", 2,
                 "degenerate triangle");
}

static void test_degenerate_quad(void **state)
{
    expect_error("material m lambert .5 .5 .5\nquad m 0 0 0  1 0 0  2 0 0  3 0 0\n", 2,
                 "degenerate quad (zero area)");
}

/* P3 a little off the plane of P0, P1, P2 (1e-6 of the quad's size). */
static void test_non_planar_quad(void **state)
{
    expect_error("material m lambert .5 .5 .5\nquad m 0 0 0  1 0 0  1 1 0  0 1 1e-6\n", 2,
                 "non-planar quad");
}

/* A dart (the reflex corner P2), a bow tie (corners out of order), and a triangle with
 * an extra point on one side (a straight corner) are not convex quads. */
static void test_non_convex_quad(void **state)
{
    expect_error("material m lambert .5 .5 .5\nquad m 0 0 0  2 0 0  0.5 0.5 0  0 2 0\n", 2,
                 "non-convex quad: P2");
    expect_error("material m lambert .5 .5 .5\nquad m 0 0 0  1 1 0  1 0 0  0 1 0\n", 2,
                 "non-convex quad");
    expect_error("material m lambert .5 .5 .5\nquad m 0 0 0  2 0 0  1 1 0  0 2 0\n", 2,
                 "non-convex quad: P2");
}

static void test_box_min_not_below_max(void **state)
{
    expect_error("material m lambert .5 .5 .5\nbox m 0 0 0  1 0 1\n", 2,
                 "box needs XMIN < XMAX");
    expect_error("material m lambert .5 .5 .5\nbox m 0 0 0  -1 1 1\n", 2, "box needs");
}

static void test_flat_tetrahedron(void **state)
{
    expect_error("material m lambert .5 .5 .5\ntetrahedron m 0 0 0  1 0 0  0 1 0  1 1 0\n", 2,
                 "flat tetrahedron (zero volume)");
}

/* An image plane whose corners are collinear, and an eye on the image plane. */
static void test_degenerate_camera(void **state)
{
    expect_error("camera -1 0 0  0 1 -1  0 -1 -1  0 3 -1\n", 1,
                 "degenerate camera: the image plane's corners are collinear");
    expect_error("camera 0 0 0  0 1 -1  0 1 -1  0 1 1\n", 1, "the image plane's corners");
    expect_error("camera 0 5 5  0 1 -1  0 -1 -1  0 1 1\n", 1, "the eye is on the image plane");
}

/* No camera: reported at the last line, with or without a final newline. */
static void test_missing_camera(void **state)
{
    expect_error("material m lambert .5 .5 .5\n\n# end\n", 3, "no camera");
    expect_error("material m lambert .5 .5 .5\n\n# end", 3, "no camera");
    expect_error("", 0, "no camera");
}

/* A line of SCENE_LINE_MAX bytes is read; one byte more is an error at its line, and
 * so is the same line ended by CRLF (the CR is not counted). */
static void test_overlong_line(void **state)
{
    static char text[2 * SCENE_LINE_MAX];
    char *line = text + strlen(strcpy(text, CAMERA));
    memset(line, ' ', SCENE_LINE_MAX);
    memcpy(line, "point_light 0 0 0 1 1 1", 23);
    strcpy(line + SCENE_LINE_MAX, "\r\n");
    Scene scene;
    parse_ok(text, &scene);
    assert_int_equal(scene.point_light_count, 1);
    scene_free(&scene);
    strcpy(line + SCENE_LINE_MAX, " \n");
    expect_error(text, 2, "line longer than 1024 bytes");
}

/* A NUL byte is an error at its line, even inside a comment. */
static void test_nul_byte(void **state)
{
    const char text[] = CAMERA "# a comment \0 with a NUL\n";
    Scene scene;
    char error[512] = "";
    assert_int_equal(
        scene_parse(text, sizeof text - 1, "t.scene", &scene, NULL, error, sizeof error), -1);
    assert_string_equal(error, "t.scene:2: a NUL byte in the text");
    assert_scene_empty(&scene);
}

/* Line ends and a byte order mark are layout: a UTF-8 BOM at the start is skipped (an
 * editor on Windows adds it), and lines end at LF, CRLF or a lone CR (old Mac files),
 * mixed too; the line count and errors still name the right line. */
static void test_line_ends_and_bom(void **state)
{
    const char *bodies[] = {
        "\xEF\xBB\xBF" CAMERA "material m lambert .5 .5 .5\nsphere m 0 0 0 1\n",
        "camera -1 0 0  0 1 -1  0 -1 -1  0 1 1\rmaterial m lambert .5 .5 .5\r"
        "sphere m 0 0 0 1\r",
        "\xEF\xBB\xBF# mixed\r\ncamera -1 0 0  0 1 -1  0 -1 -1  0 1 1\r"
        "material m lambert .5 .5 .5\n\r\nsphere m 0 0 0 1"};
    const int lines[] = {3, 3, 5};
    for (int i = 0; i < 3; i++) {
        Scene scene;
        SceneFileInfo info = parse_ok(bodies[i], &scene);
        assert_int_equal(scene.sphere_count, 1);
        assert_int_equal(info.line_count, lines[i]);
        scene_free(&scene);
    }
    expect_error("# one\r# two\rcamera\r", 3, "expected 12 numbers");
    expect_error("\xEF\xBB\xBF\r\n\rspher m 0 0 0 1\r\n", 3, "unknown keyword 'spher'");
}

/* Whether the message is printable ASCII: no raw, possibly invisible, bytes. */
static int is_printable(const char *message)
{
    for (const char *p = message; *p; p++)
        if ((unsigned char)*p < 0x20 || (unsigned char)*p >= 0x7F)
            return 0;
    return 1;
}

/* Parsing `text` fails at `line` with a message containing `what`, in ASCII only. */
static void expect_ascii_error(const char *text, int line, const char *what)
{
    expect_error(text, line, what);
    Scene scene;
    char error[512];
    scene_parse(text, strlen(text), "t.scene", &scene, NULL, error, sizeof error);
    if (!is_printable(error))
        fail_msg("the message has raw bytes: \"%s\"", error);
}

/* Outside comments a scene is ASCII: a no-break space, a minus sign, a byte order mark
 * inside the text, a stray byte and a control character (all of which a copy from a web
 * page or a word processor brings in unseen) are each named, with their column, never
 * printed raw; inside a comment they are fine. */
static void test_non_ascii(void **state)
{
    expect_ascii_error(CAMERA "material\xC2\xA0white lambert 1 1 1\n", 2,
                       "non-ASCII character U+00A0 (a no-break space?) in column 9");
    expect_ascii_error(CAMERA "point_light 0 0 \xE2\x88\x92"
                              "1 1 1 1\n",
                       2, "U+2212 (a minus sign? write '-') in column 17");
    expect_ascii_error(CAMERA "\xEF\xBB\xBFsphere m 0 0 0 1\n", 2,
                       "U+FEFF (a byte order mark?) in column 1");
    expect_ascii_error(CAMERA "point_light 0 0 \xC3\xA9 1 1 1\n", 2, "U+00E9 in column 17");
    expect_ascii_error(CAMERA "point_light 0 0 0 1 1 1\xFF\n", 2,
                       "byte 0xFF in column 24 is not ASCII (nor UTF-8)");
    expect_ascii_error(CAMERA "point_light 0 0 0 1 1 1 \xC0\xA0\n", 2,
                       "byte 0xC0 in column 25"); /* an overlong form */
    expect_ascii_error(CAMERA "point_light\x01 0 0 0 1 1 1\n", 2,
                       "control character 0x01 in column 12");
    Scene scene;
    parse_ok(CAMERA "material m lambert .5 .5 .5  # caf\xC3\xA9, \xC2\xA0, \xFF\n", &scene);
    assert_int_equal(scene.material_count, 1);
    scene_free(&scene);
}

/* A name long enough to fill the error buffer (a 609- or 4000-character path) is
 * shortened in its middle, so the message keeps "...end-of-name:LINE: reason" (where
 * the file is and what is wrong, rather than only the start of a long path); under
 * that name a good scene is read. */
static void test_long_name(void **state)
{
    const size_t lengths[] = {609, 4000};
    for (int i = 0; i < 2; i++) {
        static char name[4001];
        memset(name, 'd', lengths[i]);
        memcpy(name, "/very/", 6);
        strcpy(name + lengths[i] - 11, "/room.scene");
        Scene scene;
        char error[512];
        const char *text = CAMERA "spher m 0 0 0 1\n";
        assert_int_equal(
            scene_parse(text, strlen(text), name, &scene, NULL, error, sizeof error), -1);
        const char *end = "dd/room.scene:2: unknown keyword 'spher'";
        size_t length = strlen(error);
        assert_true(length < sizeof error);
        assert_true(length > strlen(end));
        assert_string_equal(error + length - strlen(end), end);
        assert_memory_equal(error, "/very/", 6);
        assert_non_null(strstr(error, "..."));
        text = CAMERA;
        assert_int_equal(
            scene_parse(text, strlen(text), name, &scene, NULL, error, sizeof error), 0);
        scene_free(&scene);
    }
}

/* Writes zeros into `fd` until the reader closes it; exits with the number of MiB
 * written (rounded up, at most 255), so the test learns how much the reader took. */
static void write_zeros_until_closed(int fd, const char *text, size_t length)
{
    static char zeros[1 << 16];
    signal(SIGPIPE, SIG_IGN);
    long long written = 0;
    for (ssize_t n; (n = write(fd, zeros, sizeof zeros)) > 0;)
        written += n;
    long long mib = (written + (1 << 20) - 1) >> 20;
    _exit(mib < 255 ? (int)mib : 255);
}

static void write_text(int fd, const char *text, size_t length)
{
    _exit(write(fd, text, length) == (ssize_t)length ? 0 : 1);
}

/* A pipe that a child process fills by calling feed(fd, text, length): its path
 * ("/dev/fd/N") in pipe_path[64], its reading end in *read_end; returns the child. */
static pid_t start_pipe(void (*feed)(int fd, const char *text, size_t length), const char *text,
                        size_t length, char *pipe_path, int *read_end)
{
    int ends[2];
    assert_int_equal(pipe(ends), 0);
    fflush(NULL);
    pid_t writer = fork();
    assert_true(writer >= 0);
    if (writer == 0) {
        close(ends[0]);
        feed(ends[1], text, length);
    }
    close(ends[1]);
    snprintf(pipe_path, 64, "/dev/fd/%d", ends[0]);
    *read_end = ends[0];
    return writer;
}

/* Close the pipe after reading and wait for its child; its wait status goes to *fed. */
static void finish_pipe(pid_t writer, int read_end, int *fed)
{
    close(read_end);
    assert_int_equal(waitpid(writer, fed, 0), writer);
}

/* scene_load from a pipe fed by feed(fd, text, length); the child's wait status goes
 * to *fed. */
static int load_from_pipe(void (*feed)(int fd, const char *text, size_t length),
                          const char *text, size_t length, Scene *scene, char *error,
                          size_t error_size, int *fed)
{
    char pipe_path[64];
    int read_end;
    pid_t writer = start_pipe(feed, text, length, pipe_path, &read_end);
    int status = scene_load(pipe_path, scene, error, error_size);
    finish_pipe(writer, read_end, fed);
    return status;
}

/* The bytes of a pipe fed by feed(fd, text, length), read once by scene_file_read,
 * then parsed as a chapter program does (experiment.h), *info filled; the child's
 * wait status goes to *fed. */
static int parse_from_pipe(void (*feed)(int fd, const char *text, size_t length),
                           const char *text, size_t length, Scene *scene, SceneFileInfo *info,
                           char *error, size_t error_size, int *fed)
{
    char pipe_path[64], *bytes;
    size_t bytes_length;
    int read_end;
    pid_t writer = start_pipe(feed, text, length, pipe_path, &read_end);
    int status = scene_file_read(pipe_path, &bytes, &bytes_length, error, error_size);
    finish_pipe(writer, read_end, fed);
    if (status != 0)
        return status;
    status = scene_parse(bytes, bytes_length, pipe_path, scene, info, error, error_size);
    free(bytes);
    return status;
}

/* A scene file over 64 MiB is refused at line 0, so that an endless stream cannot fill
 * the memory: an endless stream after 64 MiB + 1 bytes, not more -- /dev/zero, and a
 * pipe that counts what it gave (64 MiB, plus the pipe's own buffer: 65 MiB at most)
 * -- and a sparse regular file of 64 MiB + 1 from its size, unread. */
static void test_size_limit(void **state)
{
    Scene scene;
    char error[512];
    assert_int_equal(scene_load("/dev/zero", &scene, error, sizeof error), -1);
    assert_string_equal(error, "/dev/zero:0: larger than 64 MiB, the limit for a scene file");
    assert_scene_empty(&scene);

    int status;
    assert_int_equal(
        load_from_pipe(write_zeros_until_closed, NULL, 0, &scene, error, sizeof error, &status),
        -1);
    assert_non_null(strstr(error, ":0: larger than 64 MiB, the limit for a scene file"));
    assert_true(WIFEXITED(status));
    if (WEXITSTATUS(status) > 65)
        fail_msg("the reader took %d MiB of an endless pipe", WEXITSTATUS(status));

    char path[] = "/tmp/test_scene_file_XXXXXX";
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    assert_int_equal(ftruncate(fd, (64 << 20) + 1), 0);
    close(fd);
    char expected[128];
    snprintf(expected, sizeof expected,
             "%s:0: larger than 64 MiB (67108865 bytes), the limit for a scene file", path);
    assert_int_equal(scene_load(path, &scene, error, sizeof error), -1);
    unlink(path);
    assert_string_equal(error, expected);
}

/* The bytes are read once and the reader reports their hash (SceneFileInfo.hash), so a
 * cache can name the scene without opening the path again -- a pipe or a FIFO cannot be
 * read twice. Read from a file and from a pipe, the hash is that of the bytes; different
 * bytes, a different hash. */
static void test_source_hash(void **state)
{
    static char text[8192];
    FILE *file = fopen("scenes/room.scene", "rb");
    assert_non_null(file);
    size_t length = fread(text, 1, sizeof text, file);
    fclose(file);
    assert_true(length > 0 && length < sizeof text);
    uint64_t expected = scene_hash(SCENE_HASH_START, text, length);
    Scene scene;
    char error[512];
    SceneFileInfo info = load_ok("scenes/room.scene", &scene);
    assert_true(info.hash == expected);
    scene_free(&scene);

    int fed;
    if (parse_from_pipe(write_text, text, length, &scene, &info, error, sizeof error, &fed) !=
        0)
        fail_msg("%s", error);
    assert_true(WIFEXITED(fed) && WEXITSTATUS(fed) == 0);
    assert_int_equal(scene.triangle_count, 38);
    assert_true(info.hash == expected);
    scene_free(&scene);

    text[length - 2] ^= 1; /* a different digit or letter in the last line's comment */
    info = parse_ok(text, &scene);
    assert_true(info.hash != expected);
    scene_free(&scene);
}

/* 100,000 materials and 100,000 spheres using them, each its own: read with every
 * sphere on its material. The reader finds each shape's material by name in a hash
 * table, not by a scan of all the materials before it (test_material_names.c holds the
 * lookup's cost). */
static void test_many_materials(void **state)
{
    enum {
        COUNT = 100000
    };
    size_t size = (size_t)COUNT * 80 + sizeof CAMERA, used = 0;
    char *text = malloc(size);
    assert_non_null(text);
    used += (size_t)snprintf(text, size, CAMERA);
    for (int i = 0; i < COUNT; i++)
        used +=
            (size_t)snprintf(text + used, size - used, "material m%d lambert .5 .5 .5\n", i);
    for (int i = 0; i < COUNT; i++)
        used += (size_t)snprintf(text + used, size - used, "sphere m%d %d %d 5 0.25\n",
                                 COUNT - 1 - i, i % 400, i / 400);
    Scene scene;
    char error[512] = "";
    int status = scene_parse(text, used, "many.scene", &scene, NULL, error, sizeof error);
    free(text);
    if (status != 0)
        fail_msg("%s", error);
    assert_int_equal(scene.material_count, COUNT);
    assert_int_equal(scene.sphere_count, COUNT);
    for (int i = 0; i < COUNT; i++)
        assert_int_equal(scene.spheres[i].material, COUNT - 1 - i);
    scene_free(&scene);
}

/* A failure after many good lines frees everything already built. */
static void test_failure_leaves_scene_empty(void **state)
{
    expect_error(CAMERA "material m lambert .5 .5 .5\nmaterial l light 1 1 1\n"
                        "box m 0 0 0 1 1 1\nbox l 2 2 2 3 3 3\nsphere m 5 5 5 1\n"
                        "point_light 0 0 0 1 1 1\nsphere m 5 5 5 x\n",
                 8, "'x' is not a decimal number");
}

/* A missing file and a directory are errors at line 0 with the system's reason. */
static void test_unreadable_file(void **state)
{
    Scene scene;
    char error[512] = "";
    assert_int_equal(scene_load("scenes/no-such.scene", &scene, error, sizeof error), -1);
    assert_string_equal(error,
                        "scenes/no-such.scene:0: cannot open: No such file or directory");
    assert_scene_empty(&scene);
    assert_int_equal(scene_load("scenes", &scene, error, sizeof error), -1);
    assert_string_equal(error, "scenes:0: cannot read: Is a directory");
    assert_scene_empty(&scene);
}

/* A small error buffer gets a truncated but terminated message. */
static void test_small_error_buffer(void **state)
{
    Scene scene;
    char error[12];
    assert_int_equal(
        scene_parse("x\n", 2, "a-long-file-name.scene", &scene, NULL, error, sizeof error), -1);
    assert_string_equal(error, "a-long-file");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_room_loads),
        cmocka_unit_test(test_aspect),
        cmocka_unit_test(test_whitted_room_loads),
        cmocka_unit_test(test_material_kinds),
        cmocka_unit_test(test_boundary_values_accepted),
#if CHAPTER < 5
        cmocka_unit_test(test_oren_nayar_before_chapter_5),
#endif
#if CHAPTER >= 5
        cmocka_unit_test(test_oren_nayar_material),
        cmocka_unit_test(test_oren_nayar_boundary_values_accepted),
#endif
        cmocka_unit_test(test_triangle_front_side),
        cmocka_unit_test(test_quad_split),
        cmocka_unit_test(test_box_normals_outward),
        cmocka_unit_test(test_tetrahedron_normals_outward),
        cmocka_unit_test(test_layout),
        cmocka_unit_test(test_number_spellings),
        cmocka_unit_test(test_scale_invariance),
        cmocka_unit_test(test_unknown_keyword),
        cmocka_unit_test(test_unknown_material_kind),
        cmocka_unit_test(test_wrong_count),
        cmocka_unit_test(test_not_a_number),
        cmocka_unit_test(test_number_out_of_range),
        cmocka_unit_test(test_too_small),
        cmocka_unit_test(test_too_small_at_every_scale),
        cmocka_unit_test(test_flat_at_extreme_scales),
        cmocka_unit_test(test_number_too_small_to_compute),
        cmocka_unit_test(test_emission_bound),
        cmocka_unit_test(test_unknown_material),
        cmocka_unit_test(test_duplicate_material),
        cmocka_unit_test(test_material_name_too_long),
        cmocka_unit_test(test_second_camera),
        cmocka_unit_test(test_reflectance_out_of_range),
        cmocka_unit_test(test_negative_emission),
        cmocka_unit_test(test_negative_sigma),
        cmocka_unit_test(test_ior_not_positive),
        cmocka_unit_test(test_sphere_radius_not_positive),
        cmocka_unit_test(test_sphere_light),
        cmocka_unit_test(test_point_light_negative),
        cmocka_unit_test(test_degenerate_triangle),
        cmocka_unit_test(test_degenerate_quad),
        cmocka_unit_test(test_non_planar_quad),
        cmocka_unit_test(test_non_convex_quad),
        cmocka_unit_test(test_box_min_not_below_max),
        cmocka_unit_test(test_flat_tetrahedron),
        cmocka_unit_test(test_degenerate_camera),
        cmocka_unit_test(test_missing_camera),
        cmocka_unit_test(test_overlong_line),
        cmocka_unit_test(test_nul_byte),
        cmocka_unit_test(test_many_materials),
        cmocka_unit_test(test_line_ends_and_bom),
        cmocka_unit_test(test_non_ascii),
        cmocka_unit_test(test_long_name),
        cmocka_unit_test(test_size_limit),
        cmocka_unit_test(test_source_hash),
        cmocka_unit_test(test_failure_leaves_scene_empty),
        cmocka_unit_test(test_unreadable_file),
        cmocka_unit_test(test_small_error_buffer),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
