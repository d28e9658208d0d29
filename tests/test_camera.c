/* test_camera.c (chapter 1): the pixel-to-ray mapping (camera.h; report §3.3, §4.1).
 *
 * The mapping is a contract with the scene format: pixel (col, row), row 0 at the top,
 * covers BL + (col+u)/W (BR-BL) + (1-(row+v)/H) (TL-BL). We check its corners and
 * centre on the report's camera and on a tilted, off-origin one.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <string.h>

#include "check.h"
#include "camera.h"

typedef struct {
    Vec3 eye, bl, br, tl;
} Corners;

/* The camera of scenes/room.scene: a 2 x 2 plane at x = 0 seen from
 * (-1,0,0), its left at +y. */
static const Corners room = {{-1, 0, 0}, {0, 1, -1}, {0, -1, -1}, {0, 1, 1}};
/* A 4 x 2 plane, tilted and far from the origin: BR - BL = 4 (0.36, 0.48, 0.8),
 * TL - BL = 2 (0.8, -0.6, 0). */
static const Corners tilted = {
    {10, 20, 30}, {13, 21.2, 29.4}, {14.44, 23.12, 32.6}, {14.6, 20, 29.4}};

static Camera make(const Corners *c) { return camera_make(c->eye, c->bl, c->br, c->tl); }

/* The ray starts at the eye, has unit direction and passes through `point`. */
static void assert_through(Ray ray, const Corners *c, Vec3 point)
{
    Vec3 to_point = vec3_sub(point, c->eye);
    double along = vec3_dot(to_point, ray.dir);
    Vec3 miss = vec3_sub(to_point, vec3_scale(ray.dir, along));
    assert_true(ray.origin.x == c->eye.x && ray.origin.y == c->eye.y &&
                ray.origin.z == c->eye.z);
    assert_close(vec3_length(ray.dir), 1, 1e-15);
    assert_true(along > 0);
    assert_close(vec3_length(miss), 0, 1e-13 * vec3_length(to_point));
}

/* The ray through (col 0, row 0, u = v = 0) passes through the top-left corner TL;
 * through (W-1, H-1, u = v -> 1) it reaches the bottom-right corner BR; the centre of
 * the middle pixel of an odd-sized image goes through the plane's centre. */
static void test_corners_and_centre(void **state)
{
    const Corners *cameras[2] = {&room, &tilted};
    const int widths[2] = {5, 9}, heights[2] = {5, 3};
    double almost_one = nextafter(1.0, 0.0);
    for (int i = 0; i < 2; i++) {
        const Corners *c = cameras[i];
        Camera camera = make(c);
        int w = widths[i], h = heights[i];
        assert_through(camera_ray(&camera, w, h, 0, 0, 0, 0), c, c->tl);
        assert_through(camera_ray(&camera, w, h, w - 1, h - 1, almost_one, almost_one), c,
                       c->br);
        Vec3 centre = vec3_scale(vec3_add(c->br, c->tl), 0.5);
        assert_through(camera_ray(&camera, w, h, w / 2, h / 2, 0.5, 0.5), c, centre);
        /* the bottom-left corner: column 0, the bottom edge of the last row */
        assert_through(camera_ray(&camera, w, h, 0, h - 1, 0, almost_one), c, c->bl);
    }
}

/* Every pixel corner lands where the scene format says, and row 0 is the top: on the room
 * camera the first row looks up (+z) and the first column left (+y). */
static void test_mapping(void **state)
{
    Camera camera = make(&tilted);
    const int w = 8, h = 4;
    Vec3 right = vec3_sub(tilted.br, tilted.bl), up = vec3_sub(tilted.tl, tilted.bl);
    for (int row = 0; row < h; row++)
        for (int col = 0; col < w; col++) {
            Vec3 corner = vec3_add_scaled(vec3_add_scaled(tilted.bl, right, (double)col / w),
                                          up, 1.0 - (double)row / h);
            assert_through(camera_ray(&camera, w, h, col, row, 0, 0), &tilted, corner);
        }
    Camera r = make(&room);
    assert_true(camera_ray(&r, 4, 4, 1, 0, 0.5, 0.5).dir.z > 0);
    assert_true(camera_ray(&r, 4, 4, 0, 1, 0.5, 0.5).dir.y > 0);
}

/* Unit directions over a whole image at random positions in each pixel. */
static void test_unit_directions(void **state)
{
    Camera camera = make(&tilted);
    TestRandom rng = test_random(1, 1, 1);
    for (int row = 0; row < 60; row++)
        for (int col = 0; col < 120; col++) {
            Ray ray =
                camera_ray(&camera, 120, 60, col, row, test_uniform(&rng), test_uniform(&rng));
            assert_close(vec3_length(ray.dir), 1, 1e-15);
        }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_corners_and_centre),
        cmocka_unit_test(test_mapping),
        cmocka_unit_test(test_unit_directions),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
