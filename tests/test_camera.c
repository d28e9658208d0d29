/* test_camera.c (chapter 1): pixel-to-ray mapping and where in a pixel the samples go (camera.h,
 * SPEC §4, report §3.3.1 and §4.1, chapter 1).
 *
 * The mapping is a contract with the scene format: pixel (col, row), row 0 at the top,
 * covers BL + (col+u)/W (BR-BL) + (1-(row+v)/H) (TL-BL). We check its corners and
 * centre on the report's camera and on a tilted, off-origin one, and that sub-pixel
 * and random positions stay inside the pixel.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include "check.h"
#include "camera.h"

typedef struct { Vec3 eye, bl, br, tl; } Corners;

/* The camera of scenes/room.scene (SPEC §5): a 2 x 2 plane at x = 0 seen from
 * (-1,0,0), its left at +y. */
static const Corners room = {{-1, 0, 0}, {0, 1, -1}, {0, -1, -1}, {0, 1, 1}};
/* A 4 x 2 plane, tilted and far from the origin: BR - BL = 4 (0.36, 0.48, 0.8),
 * TL - BL = 2 (0.8, -0.6, 0). */
static const Corners tilted = {{10, 20, 30}, {13, 21.2, 29.4}, {14.44, 23.12, 32.6}, {14.6, 20, 29.4}};

static Camera make(const Corners *c)
{
    return camera_make(c->eye, c->bl, c->br, c->tl);
}

/* The ray starts at the eye, has unit direction and passes through `point`. */
static void assert_through(Ray ray, const Corners *c, Vec3 point)
{
    Vec3 to_point = vec3_sub(point, c->eye);
    double along = vec3_dot(to_point, ray.dir);
    Vec3 miss = vec3_sub(to_point, vec3_scale(ray.dir, along));
    assert_true(ray.origin.x == c->eye.x && ray.origin.y == c->eye.y && ray.origin.z == c->eye.z);
    assert_close(vec3_length(ray.dir), 1, 1e-15);
    assert_true(along > 0);
    assert_close(vec3_length(miss), 0, 1e-13 * vec3_length(to_point));
}

/* The ray through (col 0, row 0, u = v = 0) passes through the top-left corner TL;
 * through (W-1, H-1, u = v -> 1) it reaches the bottom-right corner BR; the centre of
 * the middle pixel of an odd-sized image goes through the plane's centre. */
static void test_corners_and_centre(void **state)
{
    (void)state;
    const Corners *cameras[2] = {&room, &tilted};
    const int widths[2] = {5, 9}, heights[2] = {5, 3};
    double almost_one = nextafter(1.0, 0.0);
    for (int i = 0; i < 2; i++) {
        const Corners *c = cameras[i];
        Camera camera = make(c);
        int w = widths[i], h = heights[i];
        assert_through(camera_ray(&camera, w, h, 0, 0, 0, 0), c, c->tl);
        assert_through(camera_ray(&camera, w, h, w - 1, h - 1, almost_one, almost_one), c, c->br);
        Vec3 centre = vec3_scale(vec3_add(c->br, c->tl), 0.5);
        assert_through(camera_ray(&camera, w, h, w / 2, h / 2, 0.5, 0.5), c, centre);
        /* the bottom-left corner: column 0, the bottom edge of the last row */
        assert_through(camera_ray(&camera, w, h, 0, h - 1, 0, almost_one), c, c->bl);
    }
}

/* Every pixel corner lands where SPEC §4 says, and row 0 is the top: on the room
 * camera the first row looks up (+z) and the first column left (+y). */
static void test_mapping(void **state)
{
    (void)state;
    Camera camera = make(&tilted);
    const int w = 8, h = 4;
    Vec3 right = vec3_sub(tilted.br, tilted.bl), up = vec3_sub(tilted.tl, tilted.bl);
    for (int row = 0; row < h; row++)
        for (int col = 0; col < w; col++) {
            Vec3 corner = vec3_add_scaled(vec3_add_scaled(tilted.bl, right, (double)col / w), up,
                                          1.0 - (double)row / h);
            assert_through(camera_ray(&camera, w, h, col, row, 0, 0), &tilted, corner);
        }
    Camera r = make(&room);
    assert_true(camera_ray(&r, 4, 4, 1, 0, 0.5, 0.5).dir.z > 0);
    assert_true(camera_ray(&r, 4, 4, 0, 1, 0.5, 0.5).dir.y > 0);
}

/* Unit directions over a whole image at random positions in each pixel. */
static void test_unit_directions(void **state)
{
    (void)state;
    Camera camera = make(&tilted);
    Rng rng = rng_for_sample(1, 1, 1);
    for (int row = 0; row < 60; row++)
        for (int col = 0; col < 120; col++) {
            Ray ray = camera_ray(&camera, 120, 60, col, row, rng_uniform(&rng), rng_uniform(&rng));
            assert_close(vec3_length(ray.dir), 1, 1e-15);
        }
}

/* camera_aspect is |BR - BL| / |TL - BL|: 1 for the room, 2 for the tilted plane. */
static void test_aspect(void **state)
{
    (void)state;
    Camera r = make(&room), t = make(&tilted);
    assert_close(camera_aspect(&r), 1, 1e-15);
    assert_close(camera_aspect(&t), 2, 1e-14);
}

/* Sub-pixel positions for n samples: all inside [0,1)^2, pairwise distinct, each in
 * its own cell of the ceil(sqrt(n))-column grid; centred on (1/2, 1/2) for n = 1. */
static void assert_subpixels(int n)
{
    double u[64], v[64];
    int columns = (int)ceil(sqrt((double)n)), rows = (n + columns - 1) / columns;
    for (int i = 0; i < n; i++) {
        camera_pixel_position(PIXEL_SUBPIXELS, i, n, NULL, &u[i], &v[i]);
        assert_true(u[i] >= 0 && u[i] < 1 && v[i] >= 0 && v[i] < 1);
        assert_int_equal((int)(u[i] * columns), i % columns);
        assert_int_equal((int)(v[i] * rows), i / columns);
        for (int j = 0; j < i; j++)
            assert_false(u[i] == u[j] && v[i] == v[j]);
    }
}

/* n = 1: the centre; n = 4: the 2 x 2 grid's centres 1/4, 3/4; n = 16: 1/8 ... 7/8;
 * n = 5: three columns (1/6, 1/2, 5/6) in two rows (1/4, 3/4); and the invariants for
 * every n up to 64. */
static void test_subpixels(void **state)
{
    (void)state;
    double u, v;
    camera_pixel_position(PIXEL_SUBPIXELS, 0, 1, NULL, &u, &v);
    assert_close(u, 0.5, 0);
    assert_close(v, 0.5, 0);
    for (int i = 0; i < 4; i++) {
        camera_pixel_position(PIXEL_SUBPIXELS, i, 4, NULL, &u, &v);
        assert_close(u, 0.25 + 0.5 * (i % 2), 1e-15);
        assert_close(v, 0.25 + 0.5 * (i / 2), 1e-15);
    }
    for (int i = 0; i < 16; i++) {
        camera_pixel_position(PIXEL_SUBPIXELS, i, 16, NULL, &u, &v);
        assert_close(u, (2 * (i % 4) + 1) / 8.0, 1e-15);
        assert_close(v, (2 * (i / 4) + 1) / 8.0, 1e-15);
    }
    for (int i = 0; i < 5; i++) {
        camera_pixel_position(PIXEL_SUBPIXELS, i, 5, NULL, &u, &v);
        assert_close(u, (2 * (i % 3) + 1) / 6.0, 1e-15);
        assert_close(v, (2 * (i / 3) + 1) / 4.0, 1e-15);
    }
    for (int n = 1; n <= 64; n++)
        assert_subpixels(n);
}

/* PIXEL_CENTRE is always (1/2, 1/2); PIXEL_RANDOM stays in [0,1)^2, varies, and
 * averages to the centre (10^5 draws, within 5 standard errors sqrt(1/12/N)). */
static void test_centre_and_random(void **state)
{
    (void)state;
    double u, v, sum_u = 0, sum_v = 0;
    camera_pixel_position(PIXEL_CENTRE, 3, 16, NULL, &u, &v);
    assert_true(u == 0.5 && v == 0.5);
    Rng rng = rng_for_sample(2, 3, 4);
    const int n = 100000;
    double first_u;
    camera_pixel_position(PIXEL_RANDOM, 0, n, &rng, &first_u, &v);
    int all_same = 1;
    for (int i = 0; i < n; i++) {
        camera_pixel_position(PIXEL_RANDOM, i, n, &rng, &u, &v);
        assert_true(u >= 0 && u < 1 && v >= 0 && v < 1);
        all_same &= u == first_u;
        sum_u += u;
        sum_v += v;
    }
    assert_false(all_same);
    assert_true(fabs(sum_u / n - 0.5) < 5 * sqrt(1.0 / 12 / n));
    assert_true(fabs(sum_v / n - 0.5) < 5 * sqrt(1.0 / 12 / n));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_corners_and_centre),
        cmocka_unit_test(test_mapping),
        cmocka_unit_test(test_unit_directions),
        cmocka_unit_test(test_aspect),
        cmocka_unit_test(test_subpixels),
        cmocka_unit_test(test_centre_and_random),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
