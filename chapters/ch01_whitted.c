/* ch01_whitted.c (chapter 1): Whitted ray tracing (report §2.1, Figure 1).
 *
 * New concepts (lib/), top down: whitted (with mirror, snell, schlick), render, scene,
 * camera, material, sphere, triangle, bvh, ray, vec. The experiment: the room lit by a point
 * light, one ray through each pixel centre: hard shadows, no colour bleeding, the ray tree in
 * the mirrors and the glass. Whitted is deterministic: no noise to measure, only its cost.
 */
#include <stdio.h>

#include "experiment.h"
#include "whitted.h"

int main(int argc, char **argv)
{
    ProgramInfo info = {
        "Chapter 1, Whitted ray tracing: reproduces the report's Figure 1.",
        FLAGS_COMMON | FLAG_DEPTH,
        {.scene = "scenes/room_whitted.scene",
         .size = 800,
         .depth = 10,
         .seed = 1,
         .out = "build/figures"},
    };
    Options options;
    Scene scene;
    experiment_start(argc, argv, &info, NEEDS_POINT_LIGHT, &options, &scene);
    WhittedSettings whitted = {options.depth};
    RenderSettings settings = experiment_render_settings(&options, &scene, 1, "Whitted");
    RenderResult result;
    experiment_render_serial(&scene, &settings, whitted_radiance, &whitted, &result);

    char settings_text[96], caption[160];
    snprintf(settings_text, sizeof settings_text, "1 ray/pixel, depth %d, point light",
             options.depth);
    snprintf(caption, sizeof caption, "Figure 1: Whitted ray tracing\n%s\n%.2f s",
             settings_text, result.seconds);
    const char *captions[] = {caption};
    experiment_write_panel(&options, "ch01_whitted", &result);
    experiment_write_figure(&options, "ch01_figure1", &result.image, captions, 1, 1.0);
    TableRow row = experiment_row("Figure 1", settings_text, &result);
    experiment_write_table(&options, "ch01_table", &row, 1);

    render_result_free(&result);
    scene_free(&scene);
    return 0;
}
