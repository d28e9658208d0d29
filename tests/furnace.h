/* furnace.h (chapter 1): the closed boxes of the white-furnace tests (test_path.c,
 * test_glass_furnace.c). Include after cmocka.h.
 *
 * In a closed box whose every surface sends out L = Le + rho L whatever arrives, the
 * radiance is L = Le / (1 - rho) at every point in every direction. Two such boxes,
 * both [-1, 1]^3 with every wall facing in:
 *   - furnace_box_uniform: every wall Lambertian rho, emitting Le right up to its edges.
 *     Without shadow rays its estimate along any path is exact (zero variance). With
 *     shadow rays, a hit close to an edge samples light on the neighbouring wall at a
 *     distance d near 0, and eq. 21's cos cos / d^2 has infinite variance: the mean is
 *     right but the measured standard error cannot be trusted.
 *   - furnace_box_bordered: each wall's middle (80% of its width, FURNACE_LIGHT_HALF_WIDTH)
 *     is rho = 0.5 and emits Le = 1; a border along its edges is white (rho = 1) and emits
 *     nothing. Both send out L = 2, so the radiance is still 2 everywhere (for the full
 *     series: unlimited depth), and every light is at least 0.2 from any hit on another
 *     wall, so shadow rays have finite variance. Roulette's second moment stays finite
 *     for alpha >= 0.75: a bounce multiplies it on average by (0.36 * 1 + 0.64 * 0.25) /
 *     0.75 < 1 (border, middle). The transport's decay per bounce is about
 *     0.36 * 1 + 0.64 * 0.5 = 0.68, so a depth of 40 truncates only ~1e-7 of the series.
 * None calls scene_prepare: add anything else first.
 */
#ifndef FURNACE_H
#define FURNACE_H

#include "scene.h"

#define FURNACE_BORDERED_RADIANCE 2.0
#define FURNACE_LIGHT_HALF_WIDTH 0.8

/* The rectangle u in [u0, u1], v in [v0, v1] of the wall at `side` (-1 or 1) along
 * `axis`, u and v along the two other axes, facing into the box. */
static inline void furnace_wall_piece(Scene *scene, int axis, int side, double u0, double u1,
                                      double v0, double v1, int material)
{
    const double corners[4][2] = {{u0, v0}, {u1, v0}, {u1, v1}, {u0, v1}};
    Vec3 p[4];
    for (int k = 0; k < 4; k++) {
        double xyz[3];
        xyz[axis] = side;
        xyz[(axis + 1) % 3] = corners[k][0];
        xyz[(axis + 2) % 3] = corners[k][1];
        p[k] = vec3(xyz[0], xyz[1], xyz[2]);
    }
    /* Counter-clockwise around +axis; on the wall at side = +1 that faces out: reverse. */
    if (side > 0) {
        Vec3 swap = p[1];
        p[1] = p[3];
        p[3] = swap;
    }
    assert_true(scene_add_triangle(scene, triangle_make(p[0], p[1], p[2], material)) >= 0);
    assert_true(scene_add_triangle(scene, triangle_make(p[0], p[2], p[3], material)) >= 0);
}

static inline void furnace_box_uniform(Scene *scene, double rho, double emission)
{
    scene_init(scene);
    Material m = {.name = "furnace",
                  .kind = MATERIAL_LAMBERT,
                  .reflectance = vec3(rho, rho, rho),
                  .emission = vec3(emission, emission, emission)};
    int material = scene_add_material(scene, m);
    for (int axis = 0; axis < 3; axis++)
        for (int side = -1; side <= 1; side += 2)
            furnace_wall_piece(scene, axis, side, -1.0, 1.0, -1.0, 1.0, material);
}

static inline void furnace_box_bordered(Scene *scene)
{
    scene_init(scene);
    Material light = {.name = "light",
                      .kind = MATERIAL_LAMBERT,
                      .reflectance = vec3(0.5, 0.5, 0.5),
                      .emission = vec3(1, 1, 1)};
    Material border = {
        .name = "border", .kind = MATERIAL_LAMBERT, .reflectance = vec3(1, 1, 1)};
    int light_index = scene_add_material(scene, light);
    int border_index = scene_add_material(scene, border);
    const double cuts[4] = {-1.0, -FURNACE_LIGHT_HALF_WIDTH, FURNACE_LIGHT_HALF_WIDTH, 1.0};
    for (int axis = 0; axis < 3; axis++)
        for (int side = -1; side <= 1; side += 2)
            for (int i = 0; i < 3; i++)
                for (int j = 0; j < 3; j++)
                    furnace_wall_piece(scene, axis, side, cuts[i], cuts[i + 1], cuts[j],
                                       cuts[j + 1],
                                       i == 1 && j == 1 ? light_index : border_index);
}

#endif
