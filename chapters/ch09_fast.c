/* ch09_fast.c (chapter 9): what makes a ray tracer fast (beyond the report; its
 * "multithreading" future work), each stage measured.
 *
 * New concepts (lib/): wide_bvh (chapter 2's tree made four-wide: four float boxes
 * tested at once, rounded outward in the tree's own frame), and the scene's choice of
 * how its queries find a hit (scene.h), so that the same renders can be timed with
 * every primitive tested, with chapter 2's tree and with the four-wide one.
 *
 * The experiment: Table 1's first row's estimator (1 shadow ray, roulette alpha 0.25)
 * on the room and on the room with a torus knot of 2 x 500 x 200 triangles
 * (bench/mesh.h), each stage rendered again until it has used a second: rays per CPU
 * second per stage, then the four-wide tree on 1, 2, 4, ... threads up to every core
 * (rays per wall second, the speed-up and its limit). Every stage must render the same
 * image bit for bit: the program exits with status 1 if one did not.
 */
#include <stdio.h>

#include "experiment.h"
#include "mesh.h"
#include "path_roulette.h"
#include "stage.h"

enum {
    KNOT_SEGMENTS = 500,
    KNOT_SIDES = 200,
    MAX_ROWS = 32,
    PANEL = 480
};
#define STAGE_SECONDS 1.0 /* a quarter of that with --quick */

/* The room with the knot standing in it, in a white material of its own. */
static void add_knot(Scene *scene)
{
    Material white = {
        .name = "knot", .kind = MATERIAL_LAMBERT, .reflectance = vec3(0.7, 0.7, 0.7)};
    int material = scene_add_material(scene, white);
    if (material < 0 ||
        mesh_add_torus_knot(scene, material, vec3(7, 2.8, 0.5), 2.5, KNOT_SEGMENTS,
                            KNOT_SIDES) != 0 ||
        scene_prepare(scene) != 0)
        cli_fail(1, "out of memory for the knot");
}

/* Measure `stage` on the scene into rows[*count], comparing its image with `first`'s. */
static const PathSettings TABLE1_ROW1 = {
    .max_depth = 64, .shadow_rays = 1, .rr_survival = 0.25};

static void measure(const Options *options, Scene *scene, const char *name,
                    const RenderSettings *settings, const Stage *stage, StageRow *rows,
                    int *count, const StageRow *first)
{
    double seconds = options->quick ? 0.25 * STAGE_SECONDS : STAGE_SECONDS;
    StageRow *row = &rows[(*count)++];
    *row = (StageRow){.scene = name, .stage = stage};
    if (stage_measure(scene, settings, path_roulette_radiance, &TABLE1_ROW1, stage, seconds,
                      &row->result) != 0)
        cli_fail(1, "out of memory");
    experiment_exit_if_interrupted(&row->result.first, NULL);
    if (first)
        row->differing =
            stage_differing_pixels(&first->result.first.image, &row->result.first.image);
}

/* A plot of rays per CPU second (or the threads' speed-up) as a panel the size of `beside`. */
static Image stage_plot(const Image *beside, const char *x_title, const char *y_title,
                        PlotScale y_scale, const PlotSeries *series, int count)
{
    Plot plot = {
        {x_title, PLOT_LINEAR, 0, 0, 1}, {y_title, y_scale, 0, 0, 0}, series, count, 0};
    return experiment_plot(&plot, beside->width, beside->height);
}

/* The figure's image, the room and the knot with the fastest stage (the four-wide tree on
 * every core), rendered to --target-error or --time; no reference renders the knot. */
static void knot_to_target(const Options *options, Scene *scene)
{
    add_knot(scene);
    Options panel = *options;
    panel.size = experiment_width_near(scene, options->quick ? PANEL / 2 : PANEL);
    if (cli_given(options, FLAG_SIZE))
        panel.size = options->size;
    RenderSettings settings = experiment_render_settings(&panel, scene, TARGET_FIRST_SPP,
                                                         PIXEL_SUBPIXELS, "the knot");
    experiment_render_to_target(&panel, scene, &settings, path_roulette_radiance, &TABLE1_ROW1,
                                "ch09_knot", "to target, M=1 rr=0.25, four-wide tree", NULL);
}

int main(int argc, char **argv)
{
    ProgramInfo info = {
        "Chapter 9, what makes it fast: rays per CPU second with every primitive tested,\n"
        "chapter 2's tree and the four-wide tree, then on every core. With --target-error\n"
        "or --time it renders the room and the knot alone (four-wide tree, every core;\n"
        "--size its width), in passes, to that error or for that time, and prints what it\n"
        "cost (no reference renders the knot: the estimate alone).",
        FLAGS_COMMON | FLAG_SPP | FLAG_TARGET_ERROR | FLAG_TIME,
        {.scene = "scenes/room.scene",
         .size = 200,
         .spp = 4,
         .seed = 1,
         .out = "build/figures"},
    };
    Options options;
    Scene scene;
    experiment_start(argc, argv, &info, NEEDS_AREA_LIGHT, &options, &scene);
    if (experiment_to_target(&options)) {
        knot_to_target(&options, &scene);
        scene_free(&scene);
        return 0;
    }
    RenderSettings room_image =
        experiment_render_settings(&options, &scene, options.spp, PIXEL_SUBPIXELS, "stage");
    StageRow rows[MAX_ROWS];
    int count = 0;
    for (int s = 0; s < QUERY_STAGE_COUNT; s++)
        measure(&options, &scene, "room", &room_image, &QUERY_STAGES[s], rows, &count,
                s ? &rows[0] : NULL);

    Stage thread_stages[MAX_ROWS];
    char thread_names[MAX_ROWS][40];
    int cores = options.threads > 0 ? options.threads : render_core_count(),
        thread_first = count;
    for (int t = 1, k = 0;
         count<MAX_ROWS - QUERY_STAGE_COUNT; t = 2 * t> cores && t < cores ? cores : 2 * t,
             k++) {
        snprintf(thread_names[k], sizeof thread_names[k], "four-wide, %d thread%s", t,
                 t > 1 ? "s" : "");
        thread_stages[k] = (Stage){thread_names[k], QUERY_WIDE_TREE, t};
        measure(&options, &scene, "room", &room_image, &thread_stages[k], rows, &count,
                &rows[0]);
        if (t >= cores)
            break;
    }

    add_knot(&scene);
    printf("the knot: %d triangles, %d in all\n", 2 * KNOT_SEGMENTS * KNOT_SIDES,
           scene.triangle_count);
    Options small = options;
    small.size = experiment_width_near(&scene, cli_quarter(options.size, 32) / 2);
    RenderSettings knot_image =
        experiment_render_settings(&small, &scene, 1, PIXEL_SUBPIXELS, "stage");
    int knot_first = count;
    for (int s = 0; s < QUERY_STAGE_COUNT; s++)
        measure(&options, &scene, "knot", &knot_image, &QUERY_STAGES[s], rows, &count,
                s ? &rows[knot_first] : NULL);
    char path[4400];
    experiment_path(&options, "ch09_stages.csv", path, sizeof path);
    if (stage_write_table(rows, count, path) != 0)
        cli_fail(1, "cannot write %s", path);
    printf("wrote %s\n", path);

    long differing = 0;
    for (int i = 0; i < count; i++)
        differing += rows[i].differing;
    if (differing == 0)
        printf("every stage rendered the same image, bit for bit\n");

    double stage_x[QUERY_STAGE_COUNT], room_rate[QUERY_STAGE_COUNT],
        knot_rate[QUERY_STAGE_COUNT];
    for (int s = 0; s < QUERY_STAGE_COUNT; s++) {
        stage_x[s] = s + 1;
        room_rate[s] = 1e-6 * rows[s].result.rays / rows[s].result.cpu_seconds;
        knot_rate[s] =
            1e-6 * rows[knot_first + s].result.rays / rows[knot_first + s].result.cpu_seconds;
    }
    double threads[MAX_ROWS], speed_up[MAX_ROWS];
    int thread_count = knot_first - thread_first;
    for (int k = 0; k < thread_count; k++) {
        const StageResult *r = &rows[thread_first + k].result,
                          *one = &rows[thread_first].result;
        threads[k] = r->threads;
        speed_up[k] = (r->rays / r->wall_seconds) / (one->rays / one->wall_seconds);
    }
    PlotSeries rates[2] = {{"the room (40 primitives)",
                            stage_x,
                            room_rate,
                            NULL,
                            NULL,
                            QUERY_STAGE_COUNT,
                            {0.8, 0.2, 0.1},
                            1,
                            0,
                            0},
                           {"the room and the knot (200,000 triangles)",
                            stage_x,
                            knot_rate,
                            NULL,
                            NULL,
                            QUERY_STAGE_COUNT,
                            {0.1, 0.3, 0.8},
                            1,
                            0,
                            0}};
    PlotSeries scaling[2] = {
        {"measured", threads, speed_up, NULL, NULL, thread_count, {0.1, 0.5, 0.1}, 1, 0, 0},
        {"ideal", threads, threads, NULL, NULL, thread_count, {0.5, 0.5, 0.5}, 0, 1, 0}};
    Options panel = options;
    panel.size = experiment_width_near(&scene, options.quick ? PANEL / 2 : PANEL);
    RenderSettings panel_image =
        experiment_render_settings(&panel, &scene, options.spp, PIXEL_SUBPIXELS, "the knot");
    RenderResult knot_panel;
    experiment_render(&scene, &panel_image, path_roulette_radiance, &TABLE1_ROW1, &knot_panel);
    experiment_write_panel(&options, "ch09_knot", &knot_panel);
    Image panels[3] = {knot_panel.image,
                       stage_plot(&knot_panel.image,
                                  "stage: 1 every primitive, 2 binary tree, 3 four-wide",
                                  "million rays per CPU second", PLOT_LOG, rates, 2),
                       stage_plot(&knot_panel.image, "threads",
                                  "speed-up (rays per wall second)", PLOT_LINEAR, scaling, 2)};
    char knot_caption[160], left[160], right[160];
    snprintf(knot_caption, sizeof knot_caption,
             "The room and the knot, %d spp\n%.2f s on %d threads", options.spp,
             knot_panel.seconds, knot_panel.threads);
    snprintf(left, sizeof left, "Rays per CPU second per stage\n%s",
             differing == 0 ? "every stage's image the same, bit for bit" : "images differ");
    snprintf(right, sizeof right, "The four-wide tree on 1 to %d threads\n%.2fx on %d", cores,
             speed_up[thread_count - 1], (int)threads[thread_count - 1]);
    const char *captions[3] = {knot_caption, left, right};
    experiment_write_figure(&options, "ch09_figure", panels, captions, 3, PANEL_EXPOSURE);
    for (int k = 1; k < 3; k++)
        image_free(&panels[k]);
    render_result_free(&knot_panel);
    for (int i = 0; i < count; i++)
        render_result_free(&rows[i].result.first);
    scene_free(&scene);
    if (differing > 0)
        cli_fail(1,
                 "%ld pixels differ between the stages (the differ column): the trees must "
                 "find the hits that testing every primitive finds",
                 differing);
    return 0;
}
