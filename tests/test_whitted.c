/* test_whitted.c (chapter 1): the Whitted ray tree (whitted.h, report §2.1, Figure 1, chapter
 * 1).
 *
 * Whitted ray tracing is deterministic (no random numbers: every call here passes a
 * NULL generator), so each test compares with a closed form to rounding, 1e-12
 * relative, in small scenes built in code:
 *   - a point light of intensity I at height h over a Lambertian floor (rho): a point at
 *     horizontal distance x from the light's foot has radiance
 *         L = rho / pi * I * cos(theta) / d^2,   d = sqrt(h^2 + x^2),  cos = h / d,
 *     and two lights add; an occluder leaves an exactly black, hard shadow; a side
 *     turned away from the light is black and sends no shadow ray;
 *   - a mirror of reflectance c shows c times the radiance of the point it reflects;
 *   - glass splits a ray into Schlick's R (reflected) and 1 - R (refracted): with
 *     emitters of known radiance on both branches, L = R L_reflected + (1 - R)
 *     L_refracted, entering glass and leaving it, and beyond the critical angle only
 *     the reflected branch is left (total internal reflection);
 *   - a path has at most max_depth rays: a mirror seen with max_depth 1 is black, two
 *     facing mirrors stop after exactly max_depth - 1 bounces, and a corridor of
 *     mirrors shows c^2 Le of the lamp at its end only when max_depth allows 3 rays;
 *   - an emitting surface gives its emission seen from the front, nothing from behind.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include "check.h"
#include "furnace.h"
#include "schlick.h"
#include "snell.h"
#include "whitted.h"

#define RELATIVE 1e-12
#define GLASS_IOR 1.5

static const Vec3 RHO = {0.75, 0.5, 0.25};
static const Vec3 BLACK = {0, 0, 0};
/* The point light of most tests, at height 2 over the floor z = 0. */
static const Vec3 LIGHT = {0.2, 0.1, 2.0};
static const Vec3 INTENSITY = {10, 20, 5};
/* The glass tests' surroundings: furnace_box_uniform(scene, 0.0, 1.0), black walls that
 * emit radiance 1. */
static const Vec3 WALLS = {1, 1, 1};

static int add_material(Scene *scene, MaterialKind kind, Vec3 reflectance, Vec3 emission)
{
    Material m = {.name = "test",
                  .kind = kind,
                  .reflectance = reflectance,
                  .emission = emission,
                  .ior = GLASS_IOR};
    int index = scene_add_material(scene, m);
    assert_true(index >= 0);
    return index;
}

/* The planar quad (p0, p1, p2, p3) as two triangles; its front side is the one
 * (p1 - p0) x (p2 - p0) points to. */
static void add_quad(Scene *scene, Vec3 p0, Vec3 p1, Vec3 p2, Vec3 p3, int material)
{
    assert_true(scene_add_triangle(scene, triangle_make(p0, p1, p2, material)) >= 0);
    assert_true(scene_add_triangle(scene, triangle_make(p0, p2, p3, material)) >= 0);
}

/* A small triangle centred on `centre` whose front faces along unit `facing`. */
static void add_facing_triangle(Scene *scene, Vec3 centre, Vec3 facing, double size,
                                int material)
{
    Vec3 t, b;
    test_frame(facing, &t, &b);
    Vec3 v0 = vec3_add_scaled(centre, t, size);
    Vec3 v1 = vec3_add_scaled(vec3_add_scaled(centre, t, -0.5 * size), b, 0.866 * size);
    Vec3 v2 = vec3_add_scaled(vec3_add_scaled(centre, t, -0.5 * size), b, -0.866 * size);
    Triangle triangle = triangle_make(v0, v1, v2, material);
    assert_true(vec3_dot(triangle.normal, facing) > 0.99);
    assert_true(scene_add_triangle(scene, triangle) >= 0);
}

/* The axis-aligned box [lo, hi], faces outward. Each face's corners go counter-clockwise
 * around the +axis direction (u = axis + 1, v = axis + 2, cyclic, so u x v = +axis),
 * reversed on the lower face. */
static void add_box(Scene *scene, Vec3 lo, Vec3 hi, int material)
{
    const double low[3] = {lo.x, lo.y, lo.z}, high[3] = {hi.x, hi.y, hi.z};
    const int corners[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    for (int axis = 0; axis < 3; axis++)
        for (int side = 0; side < 2; side++) {
            Vec3 p[4];
            for (int k = 0; k < 4; k++) {
                int c = side ? k : 3 - k;
                int u = (axis + 1) % 3, v = (axis + 2) % 3;
                double xyz[3];
                xyz[axis] = side ? high[axis] : low[axis];
                xyz[u] = corners[c][0] ? high[u] : low[u];
                xyz[v] = corners[c][1] ? high[v] : low[v];
                p[k] = vec3(xyz[0], xyz[1], xyz[2]);
            }
            add_quad(scene, p[0], p[1], p[2], p[3], material);
            Vec3 n = scene->triangles[scene->triangle_count - 1].normal;
            const double normal[3] = {n.x, n.y, n.z};
            assert_true(normal[axis] == (side ? 1.0 : -1.0));
        }
}

static void add_point_light(Scene *scene, Vec3 position, Vec3 intensity)
{
    PointLight light = {position, intensity};
    assert_true(scene_add_point_light(scene, light) >= 0);
}

/* A new scene: the floor z = 0 (x and y in [-4, 4], facing up) of the given material,
 * under a point light of intensity INTENSITY at `light`. Returns the floor's material;
 * the caller may add more, then calls scene_prepare. */
static int lit_floor(Scene *scene, MaterialKind kind, Vec3 reflectance, Vec3 emission,
                     Vec3 light)
{
    scene_init(scene);
    int material = add_material(scene, kind, reflectance, emission);
    add_quad(scene, vec3(-4, -4, 0), vec3(4, -4, 0), vec3(4, 4, 0), vec3(-4, 4, 0), material);
    add_point_light(scene, light, INTENSITY);
    return material;
}

/* The radiance arriving at `origin` from the direction of `target`. */
static Vec3 radiance(const Scene *scene, Vec3 origin, Vec3 target, int max_depth,
                     RayCounts *counts)
{
    WhittedSettings settings = {max_depth};
    return whitted_radiance(scene, ray_through(origin, target), &settings, counts);
}

static void assert_colour_close(Vec3 a, Vec3 b)
{
    assert_close(a.x, b.x, RELATIVE * fabs(b.x));
    assert_close(a.y, b.y, RELATIVE * fabs(b.y));
    assert_close(a.z, b.z, RELATIVE * fabs(b.z));
}

static void assert_black(Vec3 a) { assert_true(a.x == 0.0 && a.y == 0.0 && a.z == 0.0); }

/* The closed form at floor point p (normal +z) lit by one point light:
 * rho / pi * I * cos(theta) / d^2 with cos(theta) = h / d, d = sqrt(h^2 + x^2). */
static Vec3 floor_closed_form(Vec3 light, Vec3 intensity, Vec3 p)
{
    double h = light.z - p.z, x = hypot(light.x - p.x, light.y - p.y);
    double d = sqrt(h * h + x * x);
    return vec3_scale(vec3_mul(RHO, intensity), (h / d) / (d * d) / PI);
}

/* The point light's inverse-square law and Lambert's cosine law, exactly: I = (10, 20, 5)
 * at height h = 2 over rho = (0.75, 0.5, 0.25), camera rays straight down onto points
 * x = 0 to 3.5 from the light's foot (cos theta from 1 down to 0.5). One shadow ray per
 * point, no bounce. */
static void test_point_light_closed_form(void **state)
{
    Scene scene;
    lit_floor(&scene, MATERIAL_LAMBERT, RHO, BLACK, LIGHT);
    assert_int_equal(scene_prepare(&scene), 0);
    const double xs[] = {0.0, 0.5, 1.3, 2.0, 3.5};
    for (int k = 0; k < 5; k++) {
        Vec3 p = vec3(LIGHT.x + xs[k], LIGHT.y, 0.0);
        RayCounts counts = {0, 0, 0};
        Vec3 l = radiance(&scene, vec3(p.x, p.y, 1.0), p, 5, &counts);
        assert_colour_close(l, floor_closed_form(LIGHT, INTENSITY, p));
        assert_true(counts.shadow == 1 && counts.bounce == 0);
    }
    scene_free(&scene);
}

/* Light adds: with a second light the radiance is the sum of the two closed forms, and
 * two shadow rays are sent. The same holds seen from any direction (Lambertian: the
 * radiance does not depend on the viewing direction). */
static void test_two_point_lights_add(void **state)
{
    const Vec3 light_b = vec3(-1.5, 0.7, 3.0), intensity_b = vec3(4, 1, 30);
    Scene scene;
    lit_floor(&scene, MATERIAL_LAMBERT, RHO, BLACK, LIGHT);
    add_point_light(&scene, light_b, intensity_b);
    assert_int_equal(scene_prepare(&scene), 0);
    const Vec3 points[] = {vec3(0.9, -0.4, 0), vec3(-2.0, 1.5, 0), vec3(3.0, 3.0, 0)};
    const Vec3 eyes[] = {vec3(0.9, -0.4, 1), vec3(-1.0, -1.0, 2.5), vec3(0.0, 0.5, 0.7)};
    for (int k = 0; k < 3; k++) {
        Vec3 expected = vec3_add(floor_closed_form(LIGHT, INTENSITY, points[k]),
                                 floor_closed_form(light_b, intensity_b, points[k]));
        RayCounts counts = {0, 0, 0};
        assert_colour_close(radiance(&scene, eyes[k], points[k], 5, &counts), expected);
        assert_true(counts.shadow == 2);
    }
    scene_free(&scene);
}

#if CHAPTER >= 5
/* Whitted ray tracing shades Oren-Nayar surfaces (chapter 5) as Lambertian: a rough
 * floor (sigma = 0.5) gives the same closed form. */
static void test_oren_nayar_shaded_as_lambert(void **state)
{
    Scene scene;
    lit_floor(&scene, MATERIAL_OREN_NAYAR, RHO, BLACK, LIGHT);
    scene.materials[0].sigma = 0.5;
    assert_int_equal(scene_prepare(&scene), 0);
    Vec3 p = vec3(1.1, -0.3, 0.0);
    RayCounts counts = {0, 0, 0};
    assert_colour_close(radiance(&scene, vec3(-0.5, 0.4, 1.5), p, 5, &counts),
                        floor_closed_form(LIGHT, INTENSITY, p));
    scene_free(&scene);
}
#endif

/* Hard shadows: a sphere of radius 0.25 halfway up to the light (at height 1 under a light
 * at height 2) casts a shadow of radius 2 tan(asin(0.25)) = 0.5164 on the floor. Just
 * inside it the radiance is exactly 0; just outside it is the full closed form (a point
 * is wholly lit or wholly dark: no penumbra). A small triangle, either side up, blocks
 * too. The blocked shadow rays are sent and counted. */
static void test_hard_shadow(void **state)
{
    Scene scene;
    int white = lit_floor(&scene, MATERIAL_LAMBERT, RHO, BLACK, LIGHT);
    Sphere occluder = {vec3(LIGHT.x, LIGHT.y, 1.0), 0.25, white};
    assert_true(scene_add_sphere(&scene, occluder) >= 0);
    /* Two triangles over the points (2.2, 2.1) and (-1.8, -1.9), facing up and down. */
    add_facing_triangle(&scene, vec3(1.2, 1.1, 1.0), vec3(0, 0, 1), 0.1, white);
    add_facing_triangle(&scene, vec3(-0.8, -0.9, 1.0), vec3(0, 0, -1), 0.1, white);
    assert_int_equal(scene_prepare(&scene), 0);
    double shadow_radius = 2.0 * tan(asin(0.25));
    const Vec3 dark[] = {vec3(LIGHT.x, LIGHT.y, 0),
                         vec3(LIGHT.x + shadow_radius - 0.01, LIGHT.y, 0), vec3(2.2, 2.1, 0),
                         vec3(-1.8, -1.9, 0)};
    for (int k = 0; k < 4; k++) {
        RayCounts counts = {0, 0, 0};
        assert_black(radiance(&scene, vec3(dark[k].x, dark[k].y, 0.5), dark[k], 5, &counts));
        assert_true(counts.shadow == 1);
    }
    Vec3 lit = vec3(LIGHT.x + shadow_radius + 0.01, LIGHT.y, 0.0);
    RayCounts counts = {0, 0, 0};
    assert_colour_close(radiance(&scene, vec3(lit.x, lit.y, 0.5), lit, 5, &counts),
                        floor_closed_form(LIGHT, INTENSITY, lit));
    scene_free(&scene);
}

/* Diffuse surfaces are two-sided, so the floor's underside is shaded too, with its
 * normal facing the viewer (down): a light above is behind it, cos(theta) < 0, so the
 * underside is black and no shadow ray is sent; a light below lights it by the same
 * closed form (mirrored), and then the top is black. */
static void test_side_facing_away_is_black(void **state)
{
    for (int side = -1; side <= 1; side += 2) {
        Vec3 light = vec3(LIGHT.x, LIGHT.y, side * LIGHT.z);
        Scene scene;
        lit_floor(&scene, MATERIAL_LAMBERT, RHO, BLACK, light);
        assert_int_equal(scene_prepare(&scene), 0);
        Vec3 p = vec3(1.0, 0.5, 0.0);
        Vec3 facing_eye = vec3(1.0, 0.5, side), away_eye = vec3(1.0, 0.5, -side);
        RayCounts counts = {0, 0, 0};
        assert_black(radiance(&scene, away_eye, p, 5, &counts));
        assert_true(counts.shadow == 0);
        assert_colour_close(radiance(&scene, facing_eye, p, 5, &counts),
                            floor_closed_form(LIGHT, INTENSITY, p));
        assert_true(counts.shadow == 1);
        scene_free(&scene);
    }
}

/* The lit floor with a mirror of reflectance c = (0.9, 0.6, 0.3) standing in the plane
 * x = 2. */
static const Vec3 MIRROR_COLOUR = {0.9, 0.6, 0.3};

static void mirror_scene(Scene *scene)
{
    lit_floor(scene, MATERIAL_LAMBERT, RHO, BLACK, LIGHT);
    int mirror = add_material(scene, MATERIAL_MIRROR, MIRROR_COLOUR, BLACK);
    add_quad(scene, vec3(2, -2, 0), vec3(2, -2, 2), vec3(2, 2, 2), vec3(2, 2, 0), mirror);
    assert_int_equal(scene_prepare(scene), 0);
}

/* A perfect mirror shows c times what it reflects: aiming at the mirror image
 * q' = (4 - q.x, q.y, 0) of floor point q, the ray reflects onto q, and the radiance
 * is c times the radiance seen directly at q (which is the closed form, in any viewing
 * direction). One bounce and one shadow ray. To 1e-12 the test must know one more
 * thing: the reflected ray starts off the mirror by RAY_OFFSET times the hit point's
 * largest coordinate (ray.h: its x, 2), towards the room, so it is
 * the reflected ray moved by that much along -x, and lands that much short of q;
 * ignoring it is a relative error of about 1e-10. */
static void test_mirror_shows_c_times_mirrored_point(void **state)
{
    Scene scene;
    mirror_scene(&scene);
    const double offset = RAY_OFFSET * 2.0;
    const Vec3 points[] = {vec3(1.0, 0.3, 0), vec3(0.0, -1.0, 0), vec3(1.7, 0.9, 0)};
    const Vec3 eye = vec3(0.0, 0.5, 1.2);
    for (int k = 0; k < 3; k++) {
        Vec3 q = points[k], q_mirrored = vec3(4.0 - q.x, q.y, 0.0);
        Vec3 q_landed = vec3(q.x - offset, q.y, 0.0);
        RayCounts direct_counts = {0, 0, 0}, counts = {0, 0, 0};
        Vec3 direct = radiance(&scene, eye, q_landed, 5, &direct_counts);
        assert_colour_close(direct, floor_closed_form(LIGHT, INTENSITY, q_landed));
        Vec3 seen = radiance(&scene, eye, q_mirrored, 5, &counts);
        assert_colour_close(seen, vec3_mul(MIRROR_COLOUR, direct));
        assert_true(counts.bounce == 1 && counts.shadow == 1);
    }
    scene_free(&scene);
}

/* Depth: a path has at most max_depth rays, the camera ray being the first. With
 * max_depth 1 the mirror's reflected ray is never traced and the mirror is black (it
 * does not emit); with max_depth 2 it shows its reflection. */
static void test_mirror_black_at_depth_one(void **state)
{
    Scene scene;
    mirror_scene(&scene);
    const Vec3 eye = vec3(0.0, 0.5, 1.2), q_mirrored = vec3(3.0, 0.3, 0.0);
    RayCounts counts = {0, 0, 0};
    assert_black(radiance(&scene, eye, q_mirrored, 1, &counts));
    assert_true(counts.bounce == 0 && counts.shadow == 0);
    Vec3 seen = radiance(&scene, eye, q_mirrored, 2, &counts);
    assert_true(seen.x > 0.0 && counts.bounce == 1);
    scene_free(&scene);
}

/* Two facing mirrors (x = -1 and x = 1) and a ray along x between them: it would bounce
 * forever. With max_depth N the tree stops after exactly N - 1 bounces (N rays), for N up
 * to 1000, and finds nothing (black). */
static void test_facing_mirrors_terminate(void **state)
{
    Scene scene;
    scene_init(&scene);
    int mirror = add_material(&scene, MATERIAL_MIRROR, vec3(1, 1, 1), BLACK);
    add_quad(&scene, vec3(1, -1, -1), vec3(1, 1, -1), vec3(1, 1, 1), vec3(1, -1, 1), mirror);
    add_quad(&scene, vec3(-1, -1, -1), vec3(-1, -1, 1), vec3(-1, 1, 1), vec3(-1, 1, -1),
             mirror);
    assert_int_equal(scene_prepare(&scene), 0);
    const int depths[] = {1, 2, 3, 10, 1000};
    for (int k = 0; k < 5; k++) {
        RayCounts counts = {0, 0, 0};
        Vec3 l = radiance(&scene, vec3(0, 0.2, 0.1), vec3(1, 0.2, 0.1), depths[k], &counts);
        assert_black(l);
        assert_true(counts.bounce == (uint64_t)depths[k] - 1);
        assert_true(counts.bounce <= (uint64_t)depths[k]);
    }
    scene_free(&scene);
}

/* A corridor of two mirrors (y = -1 and y = 1, reflectance c) ending in an emitting
 * wall (x = 10, Le): a ray from the origin rising with slope 0.45 meets the mirrors at
 * x = 2.22 and 6.67 and the wall at x = 10, so it arrives after exactly 2 reflections
 * and sees c^2 Le, if max_depth allows its 3 rays; with max_depth 2 it sees nothing. */
static void test_mirror_corridor_depth(void **state)
{
    const Vec3 c = vec3(0.9, 0.5, 0.2), le = vec3(2, 3, 4);
    Scene scene;
    scene_init(&scene);
    int mirror = add_material(&scene, MATERIAL_MIRROR, c, BLACK);
    int lamp = add_material(&scene, MATERIAL_LIGHT, BLACK, le);
    add_quad(&scene, vec3(0, 1, -1), vec3(10, 1, -1), vec3(10, 1, 1), vec3(0, 1, 1), mirror);
    add_quad(&scene, vec3(0, -1, -1), vec3(0, -1, 1), vec3(10, -1, 1), vec3(10, -1, -1),
             mirror);
    add_quad(&scene, vec3(10, -1, -1), vec3(10, -1, 1), vec3(10, 1, 1), vec3(10, 1, -1), lamp);
    assert_int_equal(scene_prepare(&scene), 0);
    Vec3 origin = vec3(0, 0, 0), target = vec3(1, 0.45, 0);
    RayCounts counts = {0, 0, 0};
    assert_black(radiance(&scene, origin, target, 2, &counts));
    for (int depth = 3; depth <= 6; depth++)
        assert_colour_close(radiance(&scene, origin, target, depth, &counts),
                            vec3_mul(vec3_mul(c, c), le));
    scene_free(&scene);
}

/* Glass entering from air at angle theta: furnace.h's box with every wall black
 * (rho = 0) and emitting L_reflected = 1, a glass block (z in [-0.9, 0]) whose top the
 * ray hits at (0.1, 0.2, 0), and inside it an emitting plate (z = -0.5, facing up,
 * Le = L_refracted = (5, 3, 2)) that the refracted ray meets. The reflected ray sees
 * the walls, so L = R + (1 - R) L_refracted, R = Schlick's reflectance at cos(theta)
 * from 1 into 1.5: from R0 = 0.04 at normal incidence up to 0.77 at 89 degrees. */
static void test_glass_entering_splits_by_schlick(void **state)
{
    const Vec3 l_refracted = vec3(5, 3, 2);
    Scene scene;
    furnace_box_uniform(&scene, 0.0, WALLS.x);
    int glass = add_material(&scene, MATERIAL_GLASS, BLACK, BLACK);
    int plate = add_material(&scene, MATERIAL_LIGHT, BLACK, l_refracted);
    add_box(&scene, vec3(-0.9, -0.9, -0.9), vec3(0.9, 0.9, 0.0), glass);
    add_quad(&scene, vec3(-0.8, -0.8, -0.5), vec3(0.8, -0.8, -0.5), vec3(0.8, 0.8, -0.5),
             vec3(-0.8, 0.8, -0.5), plate);
    assert_int_equal(scene_prepare(&scene), 0);
    const double degrees[] = {0, 30, 60, 80, 89};
    const Vec3 hit = vec3(0.1, 0.2, 0.0);
    for (int k = 0; k < 5; k++) {
        double theta = degrees[k] * PI / 180.0;
        Vec3 origin = vec3(hit.x - 0.5 * sin(theta), hit.y, 0.5 * cos(theta));
        double r = schlick_reflectance(cos(theta), 1.0, GLASS_IOR);
        Vec3 expected = vec3_add(vec3_scale(WALLS, r), vec3_scale(l_refracted, 1.0 - r));
        RayCounts counts = {0, 0, 0};
        Vec3 l = radiance(&scene, origin, hit, 5, &counts);
        print_message("    theta %2.0f deg: R = %.6f, L = (%.6f, %.6f, %.6f)\n", degrees[k], r,
                      l.x, l.y, l.z);
        assert_colour_close(l, expected);
        assert_true(counts.bounce == 2);
    }
    scene_free(&scene);
}

/* Leaving glass: a ray inside a glass sphere (radius 0.5, in the box of the test above)
 * meets its surface at angle theta. The reflected ray runs along a chord to an emitting
 * plate inside the sphere (Le_in = (4, 2, 1)); the refracted one leaves into the box
 * (L_out = 1). Below the critical angle arcsin(1 / 1.5) = 41.81 degrees, L = R Le_in +
 * (1 - R) L_out with Schlick's R from 1.5 into 1 (the cosine of the transmitted angle,
 * the erratum of schlick.h); from the critical angle on, total internal reflection leaves only
 * the reflected part, L = Le_in exactly, and no refracted ray is traced. */
static void test_glass_total_internal_reflection(void **state)
{
    const Vec3 le_in = vec3(4, 2, 1);
    const double critical = test_critical_angle(GLASS_IOR, 1.0);
    const double thetas[] = {10 * PI / 180, 30 * PI / 180, 41 * PI / 180, critical,
                             45 * PI / 180, 60 * PI / 180, 75 * PI / 180};
    const Vec3 top = vec3(0, 0, 0.5); /* where the ray meets the sphere: normal +z */
    for (int k = 0; k < 7; k++) {
        double theta = thetas[k];
        Vec3 d = vec3(sin(theta), 0, cos(theta)), reflected = vec3(sin(theta), 0, -cos(theta));
        Scene scene;
        furnace_box_uniform(&scene, 0.0, WALLS.x);
        int glass = add_material(&scene, MATERIAL_GLASS, BLACK, BLACK);
        Sphere sphere = {vec3(0, 0, 0), 0.5, glass};
        assert_true(scene_add_sphere(&scene, sphere) >= 0);
        /* The chord from the top has length 2 * 0.5 * cos(theta); the plate sits halfway. */
        Vec3 plate_centre = vec3_add_scaled(top, reflected, 0.5 * cos(theta));
        add_facing_triangle(&scene, plate_centre, vec3_neg(reflected), 0.03,
                            add_material(&scene, MATERIAL_LIGHT, BLACK, le_in));
        assert_int_equal(scene_prepare(&scene), 0);

        RayCounts counts = {0, 0, 0};
        Vec3 l = radiance(&scene, vec3_add_scaled(top, d, -0.2), top, 5, &counts);
        double r = schlick_reflectance(cos(theta), GLASS_IOR, 1.0);
        print_message("    theta %.4f deg: R = %.6f, L = (%.6f, %.6f, %.6f)\n",
                      theta * 180 / PI, r, l.x, l.y, l.z);
        if (theta >= critical) {
            assert_true(r == 1.0);
            assert_colour_close(l, le_in);
            assert_true(counts.bounce == 1);
        } else {
            assert_true(r < 1.0);
            assert_colour_close(l, vec3_add(vec3_scale(le_in, r), vec3_scale(WALLS, 1.0 - r)));
            assert_true(counts.bounce == 2);
        }
        scene_free(&scene);
    }
}

/* An emitting surface (material light, Le = (2, 3, 4)) seen from its front gives
 * exactly Le, from its back exactly nothing, and it reflects nothing: a point light
 * shining on it adds nothing and no shadow ray is sent. */
static void test_emitter_front_and_back(void **state)
{
    const Vec3 le = vec3(2, 3, 4);
    Scene scene;
    lit_floor(&scene, MATERIAL_LIGHT, BLACK, le, LIGHT);
    assert_int_equal(scene_prepare(&scene), 0);
    const Vec3 p = vec3(0.7, -0.3, 0.0);
    RayCounts counts = {0, 0, 0};
    Vec3 front = radiance(&scene, vec3(0.0, 0.0, 1.0), p, 5, &counts);
    assert_true(front.x == le.x && front.y == le.y && front.z == le.z);
    assert_black(radiance(&scene, vec3(0.0, 0.0, -1.0), p, 5, &counts));
    assert_true(counts.shadow == 0 && counts.bounce == 0);
    scene_free(&scene);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_point_light_closed_form),
        cmocka_unit_test(test_two_point_lights_add),
#if CHAPTER >= 5
        cmocka_unit_test(test_oren_nayar_shaded_as_lambert),
#endif
        cmocka_unit_test(test_hard_shadow),
        cmocka_unit_test(test_side_facing_away_is_black),
        cmocka_unit_test(test_mirror_shows_c_times_mirrored_point),
        cmocka_unit_test(test_mirror_black_at_depth_one),
        cmocka_unit_test(test_facing_mirrors_terminate),
        cmocka_unit_test(test_mirror_corridor_depth),
        cmocka_unit_test(test_glass_entering_splits_by_schlick),
        cmocka_unit_test(test_glass_total_internal_reflection),
        cmocka_unit_test(test_emitter_front_and_back),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
