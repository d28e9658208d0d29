/* test_scene_file.c (chapter 1): reading the scene format, version 1 (scene_file.h, SPEC §4,
 * chapter 1).
 *
 * The report's room loads with the counts SPEC §5 gives; each material kind and shape
 * is stored as material.h and SPEC §4 document (quads split along P0-P2, box and
 * tetrahedron normals outward); comments, blank lines, tabs and CRLF are only layout;
 * and every kind of bad input is an error "NAME:LINE: what is wrong" at the right line
 * that leaves the scene empty.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <stdio.h>
#include <string.h>

#include "check.h"
#include "scene_file.h"

/* A valid camera line, for scenes that need to load. */
#define CAMERA "camera -1 0 0  0 1 -1  0 -1 -1  0 1 1\n"

static void assert_scene_empty(const Scene *scene)
{
    assert_null(scene->materials);
    assert_null(scene->triangles);
    assert_null(scene->spheres);
    assert_null(scene->point_lights);
    assert_null(scene->light_triangles);
    assert_null(scene->light_cumulative);
    assert_int_equal(scene->material_count + scene->triangle_count + scene->sphere_count +
                         scene->point_light_count + scene->light_count + scene->has_camera,
                     0);
}

static void parse_ok(const char *text, Scene *scene)
{
    char error[512] = "";
    if (scene_parse(text, strlen(text), "t.scene", scene, error, sizeof error) != 0)
        fail_msg("unexpected error: %s", error);
}

/* Parsing `text` (named "t.scene") fails with a message that begins "t.scene:LINE: "
 * and contains `what`, and leaves the scene empty. */
static void expect_error(const char *text, int line, const char *what)
{
    Scene scene;
    char error[512] = "", prefix[64];
    assert_int_equal(scene_parse(text, strlen(text), "t.scene", &scene, error, sizeof error), -1);
    snprintf(prefix, sizeof prefix, "t.scene:%d: ", line);
    if (strncmp(error, prefix, strlen(prefix)) != 0 || !strstr(error, what))
        fail_msg("for input \"%s\":\n got      \"%s\"\n expected \"%s...%s...\"", text, error,
                 prefix, what);
    assert_scene_empty(&scene);
}

/* The report's room (SPEC §5): 38 triangles (9 quads of 2, 4 triangles, a box of 12
 * and a tetrahedron of 4), 2 spheres, 9 materials, a camera, and one area light: the
 * lamp quad's 2 triangles, of total area 2 x 2 = 4, facing down. */
static void test_room_loads(void **state)
{
    (void)state;
    Scene scene;
    char error[512] = "";
    if (scene_load("scenes/room.scene", &scene, error, sizeof error) != 0)
        fail_msg("%s", error);
    assert_int_equal(scene.triangle_count, 38);
    assert_int_equal(scene.sphere_count, 2);
    assert_int_equal(scene.material_count, 9);
    assert_int_equal(scene.point_light_count, 0);
    assert_true(scene.has_camera);
    assert_int_equal(scene.line_count, 30);
    assert_string_equal(scene.source, "scenes/room.scene");
    assert_int_equal(scene.light_count, 2);
    assert_close(scene.light_area, 4.0, 1e-12);
    for (int i = 0; i < scene.light_count; i++)
        assert_close(scene.triangles[scene.light_triangles[i]].normal.z, -1.0, 1e-15);
    const Material *lamp = &scene.materials[scene_find_material(&scene, "lamp")];
    assert_int_equal(lamp->kind, MATERIAL_LIGHT);
    assert_close(lamp->emission.y, 25.0, 0.0);
    assert_close(vec3_max_abs(lamp->reflectance), 0.0, 0.0);
    assert_close(scene.materials[scene_find_material(&scene, "glass")].ior, 1.5, 0.0);
    /* The camera: eye, bottom-left corner, and the plane's full width and height. */
    assert_close(scene.camera.eye.x, -1.0, 0.0);
    assert_close(scene.camera.right.y, -2.0, 0.0);
    assert_close(scene.camera.up.z, 2.0, 0.0);
    scene_free(&scene);
}

/* The Whitted room has a point light with its intensity and no area light. */
static void test_whitted_room_loads(void **state)
{
    (void)state;
    Scene scene;
    char error[512] = "";
    if (scene_load("scenes/room_whitted.scene", &scene, error, sizeof error) != 0)
        fail_msg("%s", error);
    assert_int_equal(scene.point_light_count, 1);
    assert_close(scene.point_lights[0].position.z, 4.0, 0.0);
    assert_close(scene.point_lights[0].intensity.x, 150.0, 0.0);
    assert_int_equal(scene.light_count, 0);
    scene_free(&scene);
}

/* Each material kind fills the fields material.h documents, and nothing else. */
static void test_material_kinds(void **state)
{
    (void)state;
    Scene scene;
    parse_ok(CAMERA "material a lambert 0.1 0.2 0.3\n"
                    "material b oren_nayar 0 1 0.5 0.3\n"
                    "material c mirror 0.9 0.8 0.7\n"
                    "material d glass 1.33\n"
                    "material e light 1 2 3\n",
             &scene);
    const Material *m = scene.materials;
    assert_int_equal(scene.material_count, 5);
    assert_string_equal(m[0].name, "a");
    assert_int_equal(m[0].kind, MATERIAL_LAMBERT);
    assert_close(m[0].reflectance.z, 0.3, 0.0);
    assert_false(material_emits(&m[0]));
    assert_int_equal(m[1].kind, MATERIAL_OREN_NAYAR);
    assert_close(m[1].reflectance.y, 1.0, 0.0);
    assert_close(m[1].sigma, 0.3, 0.0);
    assert_int_equal(m[2].kind, MATERIAL_MIRROR);
    assert_close(m[2].reflectance.x, 0.9, 0.0);
    assert_int_equal(m[3].kind, MATERIAL_GLASS);
    assert_close(m[3].ior, 1.33, 0.0);
    assert_close(vec3_max_abs(m[3].reflectance), 0.0, 0.0);
    assert_int_equal(m[4].kind, MATERIAL_LIGHT);
    assert_close(m[4].emission.z, 3.0, 0.0);
    assert_close(vec3_max_abs(m[4].reflectance), 0.0, 0.0);
    assert_true(material_emits(&m[4]));
    scene_free(&scene);
}

/* The boundary values are accepted: reflectance 0 and 1, sigma 0, emission 0, and a
 * material name of MATERIAL_NAME_MAX - 1 bytes. */
static void test_boundary_values_accepted(void **state)
{
    (void)state;
    char text[512], name[MATERIAL_NAME_MAX];
    memset(name, 'n', sizeof name - 1);
    name[sizeof name - 1] = '\0';
    snprintf(text, sizeof text,
             CAMERA "material a lambert 0 0 0\nmaterial b mirror 1 1 1\n"
                    "material c oren_nayar 1 0 1 0\nmaterial d light 0 0 0\n"
                    "material %s glass 1e-3\n",
             name);
    Scene scene;
    parse_ok(text, &scene);
    assert_int_equal(scene.material_count, 5);
    assert_int_equal(scene_find_material(&scene, name), 4);
    scene_free(&scene);
}

/* A triangle keeps its vertex order: front side (v1 - v0) x (v2 - v0). */
static void test_triangle_front_side(void **state)
{
    (void)state;
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
    (void)state;
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
        Vec3 centroid = triangle_point(t, 1.0 / 3.0, 1.0 / 3.0);
        assert_true(vec3_dot(t->normal, vec3_sub(centroid, inside)) > 0.0);
        total += t->area;
    }
    assert_close(total, area, 1e-12 * area);
}

/* A box is 12 triangles, each with an axis-aligned normal pointing out of the box,
 * covering its surface area 2(ab + bc + ca); the same at scales 1e-3 and 1e3. */
static void test_box_normals_outward(void **state)
{
    (void)state;
    const double scales[] = {1e-3, 1.0, 1e3};
    for (int k = 0; k < 3; k++) {
        double s = scales[k];
        char text[512];
        snprintf(text, sizeof text, CAMERA "material m lambert .5 .5 .5\nbox m %g %g %g %g %g %g\n",
                 1 * s, 2 * s, 3 * s, 2 * s, 4 * s, 6 * s);
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
    (void)state;
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
    (void)state;
    const char *text = "# a comment\r\n"
                       "\r\n"
                       "   \t  \r\n"
                       "camera\t-1 0 0  0 1 -1  0 -1 -1  0 1 1   # the eye\r\n"
                       "material m lambert .5 .5 .5#touching\r\n"
                       "sphere m 0 0 0 1";
    Scene scene;
    parse_ok(text, &scene);
    assert_int_equal(scene.line_count, 6);
    assert_int_equal(scene.sphere_count, 1);
    assert_close(scene.materials[0].reflectance.z, 0.5, 0.0);
    scene_free(&scene);
}

/* The accepted spellings of numbers: "1", "-2.5", "1e-3", ".5", "+3", "2.", "1E2". */
static void test_number_spellings(void **state)
{
    (void)state;
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
    (void)state;
    Scene scene;
    parse_ok("camera -1e-3 0 0  0 1e-3 -1e-3  0 -1e-3 -1e-3  0 1e-3 1e-3\n"
             "material m lambert .5 .5 .5\n"
             "quad m 0 0 0  1e-4 0 0  1e-4 1e-4 0  0 1e-4 0\n"
             "tetrahedron m 1e3 0 0  1001 0 0  1e3 1 0  1e3 0 1\n"
             "triangle m 1e6 0 0  2e6 0 0  1e6 1e6 0\n",
             &scene);
    assert_int_equal(scene.triangle_count, 7);
    scene_free(&scene);
}

/* An unknown keyword names itself. */
static void test_unknown_keyword(void **state)
{
    (void)state;
    expect_error(CAMERA "spher m 0 0 0 1\n", 2, "unknown keyword 'spher'");
    expect_error("Camera -1 0 0  0 1 -1  0 -1 -1  0 1 1\n", 1, "unknown keyword 'Camera'");
}

/* An unknown material kind, or a material without name and kind. */
static void test_unknown_material_kind(void **state)
{
    (void)state;
    expect_error("material m plastic 1 1 1\n", 1, "unknown material kind 'plastic'");
    expect_error("material m\n", 1, "needs a name and a kind");
}

/* Too few or too many numbers: the message says how many the keyword takes. */
static void test_wrong_count(void **state)
{
    (void)state;
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
    (void)state;
    const char *bad[] = {"nan", "inf", "-infinity", "0x10", "1.5abc", "1e", "e5", ".", "-",
                         "+-1", "1,5", "--1", "1e+", "\xc3\xa9"};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        char text[128], what[64];
        snprintf(text, sizeof text, "point_light 0 0 %s 1 1 1\n", bad[i]);
        snprintf(what, sizeof what, "'%s' is not a decimal number", bad[i]);
        expect_error(text, 1, what);
    }
}

/* Numbers that overflow to infinity, or beyond 1e100 (where areas and volumes would). */
static void test_number_out_of_range(void **state)
{
    (void)state;
    expect_error("point_light 0 0 1e400 1 1 1\n", 1, "'1e400' is out of range");
    expect_error("point_light 0 0 0 -1e309 1 1\n", 1, "'-1e309' is out of range");
    expect_error("point_light 0 0 0 1e101 1 1\n", 1, "'1e101' is out of range");
}

/* A material used before it is defined, or never. */
static void test_unknown_material(void **state)
{
    (void)state;
    expect_error(CAMERA "sphere m 0 0 0 1\nmaterial m lambert .5 .5 .5\n", 2,
                 "unknown material 'm'");
}

static void test_duplicate_material(void **state)
{
    (void)state;
    expect_error("material m lambert .5 .5 .5\n\nmaterial m glass 1.5\n", 3,
                 "duplicate material 'm'");
}

/* A name one byte too long for Material.name. */
static void test_material_name_too_long(void **state)
{
    (void)state;
    char text[256], name[MATERIAL_NAME_MAX + 1];
    memset(name, 'n', sizeof name - 1);
    name[sizeof name - 1] = '\0';
    snprintf(text, sizeof text, "material %s glass 1.5\n", name);
    expect_error(text, 1, "material name longer than 63 bytes");
}

static void test_second_camera(void **state)
{
    (void)state;
    expect_error(CAMERA "# again:\n" CAMERA, 3, "a second camera (the first is on line 1)");
}

/* Reflectance above 1 or below 0, for each kind that has one. */
static void test_reflectance_out_of_range(void **state)
{
    (void)state;
    expect_error("material m lambert 0.5 1.01 0.5\n", 1, "reflectance 0.5 1.01 0.5 outside [0, 1]");
    expect_error("material m oren_nayar -0.1 0.5 0.5 0.2\n", 1, "outside [0, 1]");
    expect_error("material m mirror 1 1 2\n", 1, "outside [0, 1]");
}

static void test_negative_emission(void **state)
{
    (void)state;
    expect_error("material m light 1 -1 1\n", 1, "negative emission");
}

static void test_negative_sigma(void **state)
{
    (void)state;
    expect_error("material m oren_nayar .5 .5 .5 -0.1\n", 1, "negative sigma");
}

static void test_ior_not_positive(void **state)
{
    (void)state;
    expect_error("material m glass 0\n", 1, "index of refraction 0 must be > 0");
    expect_error("material m glass -1.5\n", 1, "must be > 0");
}

static void test_sphere_radius_not_positive(void **state)
{
    (void)state;
    expect_error("material m glass 1.5\nsphere m 0 0 0 -1\n", 2, "sphere radius -1 must be > 0");
    expect_error("material m glass 1.5\nsphere m 0 0 0 0\n", 2, "sphere radius 0 must be > 0");
}

/* Chapter 3 samples area lights by triangle, so an emitting sphere is refused. */
static void test_sphere_light(void **state)
{
    (void)state;
    expect_error("material lamp light 1 1 1\nsphere lamp 0 0 0 1\n", 2,
                 "a sphere cannot be a light: area lights are triangles, quads, boxes or "
                 "tetrahedra");
}

static void test_point_light_negative(void **state)
{
    (void)state;
    expect_error("point_light 0 0 0  1 1 -1\n", 1, "negative point_light intensity");
}

/* Zero area: collinear vertices, a repeated vertex, and a sliver 1e-12 as thin as it
 * is long (relative, so a large triangle cannot hide it). */
static void test_degenerate_triangle(void **state)
{
    (void)state;
    expect_error("material m lambert .5 .5 .5\ntriangle m 0 0 0  1 1 1  2 2 2\n", 2,
                 "degenerate triangle (zero area)");
    expect_error("material m lambert .5 .5 .5\ntriangle m 0 0 0  0 0 0  0 0 1\n", 2,
                 "degenerate triangle");
    expect_error("material m lambert .5 .5 .5\ntriangle m 0 0 0  1e6 0 0  5e5 1e-6 0\n", 2,
                 "degenerate triangle");
}

static void test_degenerate_quad(void **state)
{
    (void)state;
    expect_error("material m lambert .5 .5 .5\nquad m 0 0 0  1 0 0  2 0 0  3 0 0\n", 2,
                 "degenerate quad (zero area)");
}

/* P3 a little off the plane of P0, P1, P2 (1e-6 of the quad's size). */
static void test_non_planar_quad(void **state)
{
    (void)state;
    expect_error("material m lambert .5 .5 .5\nquad m 0 0 0  1 0 0  1 1 0  0 1 1e-6\n", 2,
                 "non-planar quad");
}

/* A dart (the reflex corner P2), a bow tie (corners out of order), and a triangle with
 * an extra point on one side (a straight corner) are not convex quads. */
static void test_non_convex_quad(void **state)
{
    (void)state;
    expect_error("material m lambert .5 .5 .5\nquad m 0 0 0  2 0 0  0.5 0.5 0  0 2 0\n", 2,
                 "non-convex quad: P2");
    expect_error("material m lambert .5 .5 .5\nquad m 0 0 0  1 1 0  1 0 0  0 1 0\n", 2,
                 "non-convex quad");
    expect_error("material m lambert .5 .5 .5\nquad m 0 0 0  2 0 0  1 1 0  0 2 0\n", 2,
                 "non-convex quad: P2");
}

static void test_box_min_not_below_max(void **state)
{
    (void)state;
    expect_error("material m lambert .5 .5 .5\nbox m 0 0 0  1 0 1\n", 2, "box needs XMIN < XMAX");
    expect_error("material m lambert .5 .5 .5\nbox m 0 0 0  -1 1 1\n", 2, "box needs");
}

static void test_flat_tetrahedron(void **state)
{
    (void)state;
    expect_error("material m lambert .5 .5 .5\ntetrahedron m 0 0 0  1 0 0  0 1 0  1 1 0\n", 2,
                 "flat tetrahedron (zero volume)");
}

/* An image plane whose corners are collinear, and an eye on the image plane. */
static void test_degenerate_camera(void **state)
{
    (void)state;
    expect_error("camera -1 0 0  0 1 -1  0 -1 -1  0 3 -1\n", 1,
                 "degenerate camera: the image plane's corners are collinear");
    expect_error("camera 0 0 0  0 1 -1  0 1 -1  0 1 1\n", 1, "the image plane's corners");
    expect_error("camera 0 5 5  0 1 -1  0 -1 -1  0 1 1\n", 1, "the eye is on the image plane");
}

/* No camera: reported at the last line, with or without a final newline. */
static void test_missing_camera(void **state)
{
    (void)state;
    expect_error("material m lambert .5 .5 .5\n\n# end\n", 3, "no camera");
    expect_error("material m lambert .5 .5 .5\n\n# end", 3, "no camera");
    expect_error("", 0, "no camera");
}

/* A line of SCENE_LINE_MAX bytes is read; one byte more is an error at its line, and
 * so is the same line ended by CRLF (the CR is not counted). */
static void test_overlong_line(void **state)
{
    (void)state;
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
    (void)state;
    const char text[] = CAMERA "# a comment \0 with a NUL\n";
    Scene scene;
    char error[512] = "";
    assert_int_equal(scene_parse(text, sizeof text - 1, "t.scene", &scene, error, sizeof error), -1);
    assert_string_equal(error, "t.scene:2: a NUL byte in the text");
    assert_scene_empty(&scene);
}

/* A failure after many good lines frees everything already built. */
static void test_failure_leaves_scene_empty(void **state)
{
    (void)state;
    expect_error(CAMERA "material m lambert .5 .5 .5\nmaterial l light 1 1 1\n"
                        "box m 0 0 0 1 1 1\nbox l 2 2 2 3 3 3\nsphere m 5 5 5 1\n"
                        "point_light 0 0 0 1 1 1\nsphere m 5 5 5 x\n",
                 8, "'x' is not a decimal number");
}

/* A missing file and a directory are errors at line 0 with the system's reason. */
static void test_unreadable_file(void **state)
{
    (void)state;
    Scene scene;
    char error[512] = "";
    assert_int_equal(scene_load("scenes/no-such.scene", &scene, error, sizeof error), -1);
    assert_string_equal(error, "scenes/no-such.scene:0: cannot open: No such file or directory");
    assert_scene_empty(&scene);
    assert_int_equal(scene_load("scenes", &scene, error, sizeof error), -1);
    assert_string_equal(error, "scenes:0: cannot read: Is a directory");
    assert_scene_empty(&scene);
}

/* A small error buffer gets a truncated but terminated message. */
static void test_small_error_buffer(void **state)
{
    (void)state;
    Scene scene;
    char error[12];
    assert_int_equal(scene_parse("x\n", 2, "a-long-file-name.scene", &scene, error, sizeof error),
                     -1);
    assert_string_equal(error, "a-long-file");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_room_loads),
        cmocka_unit_test(test_whitted_room_loads),
        cmocka_unit_test(test_material_kinds),
        cmocka_unit_test(test_boundary_values_accepted),
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
        cmocka_unit_test(test_failure_leaves_scene_empty),
        cmocka_unit_test(test_unreadable_file),
        cmocka_unit_test(test_small_error_buffer),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
