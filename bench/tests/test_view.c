/* test_view.c (bench, chapter 5): where a point of the scene appears in the image (view.h).
 *
 * The projection inverts the camera: a point on the camera ray through (u, v) of pixel
 * (col, row) appears at (col + u, row + v), for the room's camera and for one whose image
 * plane's sides are not perpendicular; a point behind the eye is said to be. From chapter
 * 8, the crops' places in the room, checked by tracing: the pixel said to show the lamps'
 * image in the mirror wall sees the mirror, and the mirror shows the lamp there; the pixel
 * said to show the glass sphere's caustic sees a surface beyond the sphere on the line
 * from the lamp through the sphere's centre.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>

#include "assert_close.h"
#include "mirror.h"
#include "rng.h"
#include "scene_file.h"
#include "view.h"

/* Points on random camera rays, at distances from 0.1 to 20, appear where the rays
 * started (to 1e-9 of a pixel), in front of the eye; the same points mirrored through
 * the eye are behind it. */
static void assert_inverts(const Camera *camera, int width, int height)
{
    Rng rng = rng_for_sample(5, 6, 7);
    for (int i = 0; i < 1000; i++) {
        int col = (int)(rng_uniform(&rng) * width), row = (int)(rng_uniform(&rng) * height);
        double u = rng_uniform(&rng), v = rng_uniform(&rng), t = 0.1 + 20.0 * rng_uniform(&rng);
        Ray ray = camera_ray(camera, width, height, col, row, u, v);
        double x, y;
        assert_int_equal(view_position(camera, width, height, ray_at(ray, t), &x, &y), 1);
        assert_close(x, col + u, 1e-9);
        assert_close(y, row + v, 1e-9);
        assert_int_equal(view_position(camera, width, height, ray_at(ray, -t), &x, &y), 0);
    }
}

static void test_projection_inverts_the_camera(void **state)
{
    Camera room = camera_make(vec3(-1, 0, 0), vec3(0, 1, -1), vec3(0, -1, -1), vec3(0, 1, 1));
    assert_inverts(&room, 64, 64);
    /* The image plane a parallelogram, tilted, the eye off its axis. */
    Camera skewed = camera_make(vec3(0.3, -0.2, -2), vec3(-1, -0.5, 0.2), vec3(1.5, -0.1, 0.4),
                                vec3(-0.6, 1.2, -0.1));
    assert_inverts(&skewed, 48, 30);
}

/* view_pixel: the pixel that holds the position, and 0 outside the image or behind the
 * eye. */
static void test_pixel_inside_the_image(void **state)
{
    Camera room = camera_make(vec3(-1, 0, 0), vec3(0, 1, -1), vec3(0, -1, -1), vec3(0, 1, 1));
    int col = -1, row = -1;
    Ray ray = camera_ray(&room, 20, 10, 13, 7, 0.25, 0.75);
    assert_int_equal(view_pixel(&room, 20, 10, ray_at(ray, 3.0), &col, &row), 1);
    assert_int_equal(col, 13);
    assert_int_equal(row, 7);
    assert_int_equal(view_pixel(&room, 20, 10, ray_at(ray, -3.0), &col, &row), 0);
    assert_int_equal(view_pixel(&room, 20, 10, vec3(5, 7, 0), &col, &row), 0);  /* left of it */
    assert_int_equal(view_pixel(&room, 20, 10, vec3(5, -7, 0), &col, &row), 0); /* right */
    assert_int_equal(view_pixel(&room, 20, 10, vec3(5, 0, 9), &col, &row), 0);  /* above */
    assert_int_equal(view_pixel(&room, 20, 10, vec3(5, 0, -9), &col, &row), 0); /* below */
}

#if CHAPTER >= 8
enum {
    SIDE = 64
};

static Hit trace(const Scene *scene, Ray ray)
{
    Hit hit;
    assert_int_equal(scene_intersect(scene, ray, INFINITY, &hit), 1);
    return hit;
}

/* The camera ray through the pixel's centre meets the mirror wall, and its reflection
 * meets the lamp. */
static void test_mirror_image_seen_there(void **state)
{
    Scene scene;
    char error[256];
    assert_int_equal(scene_load("scenes/room.scene", &scene, error, sizeof error), 0);
    MirrorPlanes mirrors;
    assert_int_equal(mirror_light_find_planes(&scene, &mirrors), 0);
    int col, row;
    assert_int_equal(view_mirror_image_pixel(&scene, &mirrors, SIDE, SIDE, &col, &row), 1);
    Ray ray = camera_ray(&scene.camera, SIDE, SIDE, col, row, 0.5, 0.5);
    Hit wall = trace(&scene, ray);
    assert_int_equal(scene.materials[wall.material].kind, MATERIAL_MIRROR);
    Vec3 n = vec3_dot(wall.normal, ray.dir) < 0.0 ? wall.normal : vec3_neg(wall.normal);
    Vec3 reflected = mirror_reflect(ray.dir, n);
    Hit lamp = trace(&scene,
                     (Ray){ray_offset_origin(wall.point, n, reflected, wall.scale), reflected});
    assert_int_equal(scene.materials[lamp.material].kind, MATERIAL_LIGHT);
    mirror_planes_free(&mirrors);
    scene_free(&scene);
}

/* The camera ray through the pixel's centre meets a surface beyond the glass sphere
 * (farther from the lamp than the sphere's far side), within a pixel's footprint there
 * (0.3 in the room at 64 pixels) of the line from the lamp's centre through the
 * sphere's. Without a glass sphere there is no caustic to show. */
static void test_caustic_seen_there(void **state)
{
    Scene scene;
    char error[256];
    assert_int_equal(scene_load("scenes/room.scene", &scene, error, sizeof error), 0);
    int col, row;
    assert_int_equal(view_caustic_pixel(&scene, SIDE, SIDE, &col, &row), 1);
    Hit seen = trace(&scene, camera_ray(&scene.camera, SIDE, SIDE, col, row, 0.5, 0.5));
    const Sphere *glass = &scene.spheres[0];
    assert_int_equal(scene.materials[glass->material].kind, MATERIAL_GLASS);
    Vec3 lamp = vec3(5, 0, 4.99); /* the room's lamp, 4 < x < 6, -1 < y < 1 */
    Vec3 axis = vec3_normalize(vec3_sub(glass->center, lamp)),
         to_seen = vec3_sub(seen.point, lamp);
    double along = vec3_dot(to_seen, axis);
    double off_line = vec3_length(vec3_sub(to_seen, vec3_scale(axis, along)));
    print_message("    pixel (%d, %d): %.3f beyond the sphere's centre, %.3f off the line\n",
                  col, row, along - vec3_length(vec3_sub(glass->center, lamp)), off_line);
    assert_true(along > vec3_length(vec3_sub(glass->center, lamp)) + glass->radius);
    assert_true(off_line < 0.3);
    scene.materials[glass->material].kind = MATERIAL_MIRROR;
    assert_int_equal(view_caustic_pixel(&scene, SIDE, SIDE, &col, &row), 0);
    scene_free(&scene);
}
#endif

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_projection_inverts_the_camera),
        cmocka_unit_test(test_pixel_inside_the_image),
#if CHAPTER >= 8
        cmocka_unit_test(test_mirror_image_seen_there),
        cmocka_unit_test(test_caustic_seen_there),
#endif
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
