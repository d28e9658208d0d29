/* test_mirror_light.c (chapter 7): Tests of the lamps' images in planar mirrors
 * (lib/mirror_light.c, chapter 7).
 *
 * 1. Finding the planes: the room has one (the mirror wall's two triangles); coplanar
 *    mirror triangles, facing either way, share one plane; a parallel plane elsewhere
 *    is another; mirror spheres and other materials make none.
 * 2. The image is the lamp moved: a tilted lamp above a point, beside a mirror plane
 *    x = 1 of reflectance R, lights the point through the mirror exactly as much (times
 *    R) as the lamp reflected to the far side of x = 1, with no mirror, lights it
 *    directly. Means of many shadow rays of each, within 4 standard errors, per channel.
 *    (Tilted, so that a lamp normal left unreflected shows.)
 * 3. The same light, found the other way: at points of the room (mirror tinted
 *    0.5, 0.7, 0.9), the mean of the mirror light's shadow rays equals that of the
 *    paths that BRDF sampling finds: a cosine-sampled direction that hits the mirror
 *    wall and, reflected, the lamp's front (weight rho R Le). Within 4 standard errors.
 * 4. What it must not light: a point behind the mirror's plane, a point whose view of
 *    the image passes beside the mirror (outside its polygon), and a point whose way
 *    from the mirror to the lamp is blocked all get exactly 0.
 * Fixed seeds; a false failure of a 4-sigma check about once in 16,000 runs.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include "check.h"
#include "diffuse.h"
#include "mirror.h"
#include "mirror_light.h"
#include "scene_file.h"

#define SIGMAS 4.0

static void add_quad(Scene *scene, Vec3 a, Vec3 b, Vec3 c, Vec3 d, int material)
{
    assert_true(scene_add_triangle(scene, triangle_make(a, b, c, material)) >= 0);
    assert_true(scene_add_triangle(scene, triangle_make(a, c, d, material)) >= 0);
}

/* The scene's mirror planes, found afresh. */
static MirrorPlanes planes_of(const Scene *scene)
{
    MirrorPlanes planes;
    assert_int_equal(mirror_light_find_planes(scene, &planes), 0);
    return planes;
}

static void test_planes_of_the_room(void **state)
{
    Scene scene;
    char error[256];
    assert_int_equal(scene_load("scenes/room.scene", &scene, error, sizeof error), 0);
    MirrorPlanes planes = planes_of(&scene);
    assert_int_equal(planes.count, 1);
    /* The mirror wall runs from (13, 0) to (10, 6): normal +-(2, 1, 0) / sqrt(5). */
    const MirrorPlane *plane = &planes.planes[0];
    assert_close(fabs(plane->normal.x), 2.0 / sqrt(5.0), 1e-12);
    assert_close(fabs(plane->normal.y), 1.0 / sqrt(5.0), 1e-12);
    assert_close(plane->normal.z, 0.0, 1e-12);
    assert_close(fabs(plane->offset), 26.0 / sqrt(5.0), 1e-12);
    mirror_planes_free(&planes);
    scene_free(&scene);
}

static void test_planes_are_shared_and_distinct(void **state)
{
    Scene scene;
    scene_init(&scene);
    Material mirror = {.name = "mirror", .kind = MATERIAL_MIRROR, .reflectance = vec3(1, 1, 1)};
    Material white = {
        .name = "white", .kind = MATERIAL_LAMBERT, .reflectance = vec3(0.5, 0.5, 0.5)};
    int m = scene_add_material(&scene, mirror), w = scene_add_material(&scene, white);
    MirrorPlanes planes = planes_of(&scene);
    assert_int_equal(planes.count, 0);
    /* Two quads in the plane z = 2, one of them facing down, and a white one there. */
    add_quad(&scene, vec3(0, 0, 2), vec3(1, 0, 2), vec3(1, 1, 2), vec3(0, 1, 2), m);
    add_quad(&scene, vec3(5, 5, 2), vec3(5, 6, 2), vec3(6, 6, 2), vec3(6, 5, 2), m);
    add_quad(&scene, vec3(0, 0, 3), vec3(1, 0, 3), vec3(1, 1, 3), vec3(0, 1, 3), w);
    Sphere ball = {vec3(0, 0, 0), 1.0, m};
    assert_true(scene_add_sphere(&scene, ball) >= 0);
    planes = planes_of(&scene);
    assert_int_equal(planes.count, 1);
    assert_close(fabs(planes.planes[0].normal.z), 1.0, 1e-15);
    assert_close(fabs(planes.planes[0].offset), 2.0, 1e-12);
    mirror_planes_free(&planes);
    /* A parallel mirror at z = 2.001 is a plane of its own. */
    add_quad(&scene, vec3(0, 0, 2.001), vec3(1, 0, 2.001), vec3(1, 1, 2.001), vec3(0, 1, 2.001),
             m);
    planes = planes_of(&scene);
    assert_int_equal(planes.count, 2);
    mirror_planes_free(&planes);
    scene_free(&scene);
}

/* Planes are told apart relative to the numbers compared, at every scale: the room's
 * mirror wall, a parallel mirror across the room (where its green wall is) and a mirror
 * with decimal corners in a tilted plane are three planes, each quad's two triangles
 * one, in the room scaled by 2^-40, 1e-12, 1, 1e12 and 2^60. A tolerance with an
 * absolute part, 1e-9 (1 + |offset|), merged the two walls in rooms below about 1e-10. */
static void test_planes_at_every_scale(void **state)
{
    const double scales[] = {0x1p-40, 1e-12, 1.0, 1e12, 0x1p60};
    for (int i = 0; i < 5; i++) {
        double s = scales[i];
        Scene scene;
        scene_init(&scene);
        Material mirror = {
            .name = "mirror", .kind = MATERIAL_MIRROR, .reflectance = vec3(1, 1, 1)};
        int m = scene_add_material(&scene, mirror);
        add_quad(&scene, vec3(13 * s, 0, -5 * s), vec3(13 * s, 0, 5 * s),
                 vec3(10 * s, 6 * s, 5 * s), vec3(10 * s, 6 * s, -5 * s), m);
        add_quad(&scene, vec3(-3 * s, 0, -5 * s), vec3(-3 * s, 0, 5 * s),
                 vec3(0, -6 * s, 5 * s), vec3(0, -6 * s, -5 * s), m);
        Vec3 corner = vec3(2.3 * s, 0.7 * s, -1.9 * s), u = vec3(1.1 * s, 0.3 * s, 0.2 * s),
             v = vec3(-0.2 * s, 0.9 * s, 1.3 * s);
        add_quad(&scene, corner, vec3_add(corner, u), vec3_add(vec3_add(corner, u), v),
                 vec3_add(corner, v), m);
        MirrorPlanes planes = planes_of(&scene);
        print_message("    scale %g: %d planes\n", s, planes.count);
        assert_int_equal(planes.count, 3);
        mirror_planes_free(&planes);
        scene_free(&scene);
    }
}

/* A 0.4 x 0.6 lamp (Le = 2) at height 1 around x = 0.5, tilted to face down and
 * along x (so that its image's normal differs from its own), and the mirror x = 1
 * (reflectance R) as a big quad; or, `moved`, no mirror and the lamp reflected across
 * x = 1: (x, y, z) -> (2 - x, y, z), its corners in reverse order so that it faces
 * the reflected way. */
static void lamp_beside_mirror(Scene *scene, int moved, Vec3 reflectance)
{
    scene_init(scene);
    Material white = {
        .name = "white", .kind = MATERIAL_LAMBERT, .reflectance = vec3(0.5, 0.5, 0.5)};
    Material lamp = {.name = "lamp", .kind = MATERIAL_LIGHT, .emission = vec3(2, 2, 2)};
    Material mirror = {.name = "mirror", .kind = MATERIAL_MIRROR, .reflectance = reflectance};
    assert_int_equal(scene_add_material(scene, white), 0);
    int l = scene_add_material(scene, lamp), m = scene_add_material(scene, mirror);
    Vec3 corners[4] = {{0.3, -0.3, 0.9}, {0.3, 0.3, 0.9}, {0.7, 0.3, 1.1}, {0.7, -0.3, 1.1}};
    if (moved) {
        Vec3 reflected[4];
        for (int k = 0; k < 4; k++)
            reflected[k] = vec3(2.0 - corners[3 - k].x, corners[3 - k].y, corners[3 - k].z);
        add_quad(scene, reflected[0], reflected[1], reflected[2], reflected[3], l);
    } else {
        add_quad(scene, corners[0], corners[1], corners[2], corners[3], l);
        add_quad(scene, vec3(1, -5, -5), vec3(1, -5, 5), vec3(1, 5, 5), vec3(1, 5, -5), m);
    }
    assert_int_equal(scene_prepare(scene), 0);
    const Vec3 normal = scene->triangles[0].normal;
    assert_true(normal.z < -0.85 && fabs(normal.x) > 0.4); /* down, and tilted */
}

typedef struct {
    double mean[3], error[3];
} Estimate;

static Estimate finish(const double sum[3], const double squares[3], long n)
{
    Estimate e;
    for (int c = 0; c < 3; c++) {
        e.mean[c] = sum[c] / n;
        e.error[c] = sqrt((squares[c] / n - e.mean[c] * e.mean[c]) / (n - 1));
    }
    return e;
}

static void add_sample(Vec3 value, double sum[3], double squares[3])
{
    const double v[3] = {value.x, value.y, value.z};
    for (int c = 0; c < 3; c++) {
        sum[c] += v[c];
        squares[c] += v[c] * v[c];
    }
}

static void assert_same(Estimate a, Estimate b)
{
    for (int c = 0; c < 3; c++) {
        print_message("    channel %d: %.6f +- %.6f against %.6f +- %.6f\n", c, a.mean[c],
                      a.error[c], b.mean[c], b.error[c]);
        assert_true(a.mean[c] > 0.0);
        assert_true(fabs(a.mean[c] - b.mean[c]) <=
                    SIGMAS * sqrt(a.error[c] * a.error[c] + b.error[c] * b.error[c]));
    }
}

/* Mirror-light shadow rays at x (normal n, viewed along n), n_samples of them. */
static Estimate mirror_light_mean(const Scene *scene, Vec3 x, Vec3 n, long n_samples,
                                  uint64_t seed)
{
    double sum[3] = {0}, squares[3] = {0};
    RayCounts counts = {0, 0, 0};
    MirrorPlanes planes = planes_of(scene);
    for (long i = 0; i < n_samples; i++) {
        Rng rng = rng_for_sample(seed, 0, (uint64_t)i);
        add_sample(mirror_light_shadow_ray(scene, &planes.planes[0], x, n, n,
                                           &scene->materials[0], &rng, &counts)
                       .value,
                   sum, squares);
    }
    mirror_planes_free(&planes);
    return finish(sum, squares, n_samples);
}

static void test_image_is_the_lamp_moved(void **state)
{
    const Vec3 tint = vec3(0.5, 0.7, 0.9);
    Scene with_mirror, moved;
    lamp_beside_mirror(&with_mirror, 0, tint);
    lamp_beside_mirror(&moved, 1, tint);
    const Vec3 points[2] = {{0, 0, 0}, {0.6, 0.4, -0.5}};
    for (int p = 0; p < 2; p++) {
        Estimate image = mirror_light_mean(&with_mirror, points[p], vec3(0, 0, 1), 200000, 3);
        double sum[3] = {0}, squares[3] = {0};
        RayCounts counts = {0, 0, 0};
        for (long i = 0; i < 200000; i++) {
            Rng rng = rng_for_sample(4, 0, (uint64_t)i);
            Vec3 value = area_light_shadow_ray(&moved, points[p], vec3(0, 0, 1), vec3(0, 0, 1),
                                               &moved.materials[0], &rng, &counts)
                             .value;
            add_sample(vec3_mul(value, tint), sum, squares);
        }
        assert_same(image, finish(sum, squares, 200000));
    }
    scene_free(&with_mirror);
    scene_free(&moved);
}

/* BRDF sampling's estimate of the light at x by way of the mirror wall: weight rho R Le
 * for a cosine-sampled direction that hits a mirror triangle and then a lamp's front. */
static Estimate hitting_mean(const Scene *scene, Vec3 x, Vec3 n, long n_samples, uint64_t seed)
{
    const Material *white = &scene->materials[0];
    double sum[3] = {0}, squares[3] = {0};
    for (long i = 0; i < n_samples; i++) {
        Rng rng = rng_for_sample(seed, 1, (uint64_t)i);
        Vec3 d, value = vec3(0, 0, 0);
        double u1 = rng_uniform(&rng), u2 = rng_uniform(&rng);
        Vec3 weight = diffuse_sample(white, n, n, u1, u2, &d);
        Hit at_mirror, at_lamp;
        if (scene_intersect(scene, ray_spawn(x, n, d, vec3_max_abs(x)), INFINITY, &at_mirror) &&
            at_mirror.triangle >= 0 &&
            scene->materials[at_mirror.material].kind == MATERIAL_MIRROR) {
            Vec3 r = mirror_reflect(d, at_mirror.normal);
            const Material *mirror = &scene->materials[at_mirror.material];
            if (scene_intersect(
                    scene, ray_spawn(at_mirror.point, at_mirror.normal, r, at_mirror.scale),
                    INFINITY, &at_lamp) &&
                vec3_dot(r, at_lamp.normal) < 0.0)
                value = vec3_mul(vec3_mul(weight, mirror->reflectance),
                                 scene->materials[at_lamp.material].emission);
        }
        add_sample(value, sum, squares);
    }
    return finish(sum, squares, n_samples);
}

static void test_same_light_as_hitting_the_lamp_in_the_room(void **state)
{
    Scene scene;
    char error[256];
    assert_int_equal(scene_load("scenes/room.scene", &scene, error, sizeof error), 0);
    int mirror = scene_file_material(&scene, "mirror");
    scene.materials[mirror].reflectance = vec3(0.5, 0.7, 0.9);
    assert_int_equal(scene_file_material(&scene, "white"), 0);
    /* On the floor near the mirror, and on the floor under the lamp. */
    const Vec3 points[2] = {{9, 2, -5}, {3, 0, -5}};
    for (int p = 0; p < 2; p++)
        assert_same(mirror_light_mean(&scene, points[p], vec3(0, 0, 1), 100000, 5),
                    hitting_mean(&scene, points[p], vec3(0, 0, 1), 1500000, 6));
    scene_free(&scene);
}

static void test_where_the_image_gives_nothing(void **state)
{
    Scene scene;
    lamp_beside_mirror(&scene, 0, vec3(1, 1, 1));
    Estimate behind = mirror_light_mean(&scene, vec3(1.5, 0, 0), vec3(0, 0, 1), 10000, 7);
    assert_true(behind.mean[0] == 0.0);
    scene_free(&scene);

    /* A small mirror (y in [-0.1, 0.1], z in [-0.1, 0.1] at x = 1) before a white wall
     * at x = 1.4: from (0, 3, 0) the lamp's image at y in [-0.3, 0.3] is seen beside
     * the mirror, where the wall is. */
    scene_init(&scene);
    Material white = {
        .name = "white", .kind = MATERIAL_LAMBERT, .reflectance = vec3(0.5, 0.5, 0.5)};
    Material lamp = {.name = "lamp", .kind = MATERIAL_LIGHT, .emission = vec3(2, 2, 2)};
    Material mirror = {.name = "mirror", .kind = MATERIAL_MIRROR, .reflectance = vec3(1, 1, 1)};
    scene_add_material(&scene, white);
    int l = scene_add_material(&scene, lamp), m = scene_add_material(&scene, mirror);
    add_quad(&scene, vec3(0.3, -0.3, 1), vec3(0.3, 0.3, 1), vec3(0.7, 0.3, 1),
             vec3(0.7, -0.3, 1), l);
    add_quad(&scene, vec3(1, -0.1, -0.1), vec3(1, -0.1, 0.1), vec3(1, 0.1, 0.1),
             vec3(1, 0.1, -0.1), m);
    add_quad(&scene, vec3(1.4, -5, -5), vec3(1.4, -5, 5), vec3(1.4, 5, 5), vec3(1.4, 5, -5), 0);
    assert_int_equal(scene_prepare(&scene), 0);
    Estimate beside = mirror_light_mean(&scene, vec3(0, 3, 0), vec3(0, 0, 1), 10000, 8);
    assert_true(beside.mean[0] == 0.0);
    Estimate through = mirror_light_mean(&scene, vec3(0.5, 0, -1), vec3(0, 0, 1), 10000, 8);
    assert_true(through.mean[0] > 0.0); /* the same mirror does show it from here */
    /* A white slab between the mirror and the lamp: blocked. */
    add_quad(&scene, vec3(0.2, -1, 0.5), vec3(0.2, 1, 0.5), vec3(1.2, 1, 0.5),
             vec3(1.2, -1, 0.5), 0);
    assert_int_equal(scene_prepare(&scene), 0);
    Estimate blocked = mirror_light_mean(&scene, vec3(0.5, 0, -1), vec3(0, 0, 1), 10000, 8);
    assert_true(blocked.mean[0] == 0.0);
    scene_free(&scene);
}

/* A second mirror in the way: a small tilted mirror at x = 0.8, in another plane,
 * stands between the floor point and the big mirror x = 1. Every shadow ray to the lamp's
 * image in x = 1 meets the small mirror first, which does not show that image: nothing
 * may arrive. (A path that does reflect in the small mirror is that mirror's own image,
 * sampled for its own plane.) */
static void test_another_mirror_in_the_way(void **state)
{
    Scene scene;
    lamp_beside_mirror(&scene, 0, vec3(1, 1, 1));
    int mirror = scene.material_count - 1;
    add_quad(&scene, vec3(0.78, -0.4, 0.15), vec3(0.82, 0.4, 0.15), vec3(0.82, 0.4, 0.7),
             vec3(0.78, -0.4, 0.7), mirror);
    assert_int_equal(scene_prepare(&scene), 0);
    MirrorPlanes planes = planes_of(&scene);
    assert_int_equal(planes.count, 2);
    const MirrorPlane *big =
        fabs(planes.planes[0].offset) > 0.9 ? &planes.planes[0] : &planes.planes[1];
    RayCounts counts = {0, 0, 0};
    double arrived = 0.0;
    for (int i = 0; i < 20000; i++) {
        Rng rng = rng_for_sample(12, 0, (uint64_t)i);
        arrived += mirror_light_shadow_ray(&scene, big, vec3(0.5, 0, 0), vec3(0, 0, 1),
                                           vec3(0, 0, 1), &scene.materials[0], &rng, &counts)
                       .value.x;
    }
    print_message("    through the big mirror, past the small one: %g\n", arrived);
    assert_true(arrived == 0.0);
    mirror_planes_free(&planes);
    scene_free(&scene);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_planes_of_the_room),
        cmocka_unit_test(test_planes_are_shared_and_distinct),
        cmocka_unit_test(test_planes_at_every_scale),
        cmocka_unit_test(test_image_is_the_lamp_moved),
        cmocka_unit_test(test_same_light_as_hitting_the_lamp_in_the_room),
        cmocka_unit_test(test_where_the_image_gives_nothing),
        cmocka_unit_test(test_another_mirror_in_the_way),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
