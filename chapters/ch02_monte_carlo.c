/* ch02_monte_carlo.c (chapter 2): Monte Carlo diffuse (report §2.2, §3.3, §3.5.3).
 * Figures 2 and 8.
 *
 * New concepts (lib/): lambert (eq. 8), hemisphere (cosine-weighted sampling by
 * inverting the CDF, eqs. 9-12), diffuse, pixel_sampling (sub-pixels and random
 * positions), glass (reflect or refract, chosen by R), path (the path tracer that finds
 * light only when a path happens to hit the lamp). The errors against a reference are
 * the bench's (bench/measure.h).
 *
 * The experiment:
 *   - Figure 2: the room by Monte Carlo path tracing: colour bleeding (red tint on the
 *     left of the ceiling, green on the right) and soft shadows, and noise;
 *   - Figure 8: 1 vs 4 samples per pixel on sub-pixels;
 *   - what the report only describes (§3.3.1): sub-pixels vs random positions at equal
 *     samples, with their errors, at 4 and at --spp samples. (At 1 spp the one sub-pixel
 *     is the whole pixel and its sample a uniform point in it, drawn from the same
 *     numbers as a random position: the two images would be the same, bit for bit.)
 * Every panel here finds light only by hitting the lamp (M = 0), so the images are mostly
 * black speckle: that is this chapter's lesson, not a bug. The report's own Figure 8 was
 * rendered with shadow rays; chapter 3 renders it that way too, and each caption says
 * which it is. The reference is rendered by build/reference from the final chapter's
 * library (experiment.h): the same expectation, with far less noise.
 */
#include <stdio.h>

#include "experiment.h"
#include "path.h"

typedef struct {
    const char *name;
    const char *title;
    int spp;
    PixelSampling sampling;
} Panel;

int main(int argc, char **argv)
{
    ProgramInfo info = {
        "Chapter 2, Monte Carlo diffuse: reproduces the report's Figures 2 and 8 and compares\n"
        "sub-pixels with random positions.",
        FLAGS_COMMON | FLAG_SPP | FLAG_DEPTH | FLAG_REFERENCE_SPP | FLAG_RUNS,
        {.scene = "scenes/room.scene",
         .size = 800,
         .spp = 64,
         .depth = 8,
         .seed = 1,
         .out = "build/figures",
         .reference_spp = DEPTH8_REFERENCE_SPP,
         .runs = CLI_RUNS},
    };
    Options options;
    Scene scene;
    experiment_start(argc, argv, &info, NEEDS_AREA_LIGHT, &options, &scene);
    PathSettings hitting = {.max_depth = options.depth};
    Reference reference;
    experiment_path_reference(&options, &scene, &hitting, NULL, 0.0, &reference);

    const Panel panels[] = {
        {"ch02_figure8_1spp", "Figure 8, left (light by hitting only)", 1, PIXEL_SUBPIXELS},
        {"ch02_figure8_4spp", "Figure 8, right (light by hitting only)", 4, PIXEL_SUBPIXELS},
        {"ch02_random_4spp", "random positions", 4, PIXEL_RANDOM},
        {"ch02_subpixels", "Figure 2", options.spp, PIXEL_SUBPIXELS},
        {"ch02_random", "random positions", options.spp, PIXEL_RANDOM},
    };
    enum {
        PANELS = sizeof panels / sizeof panels[0]
    };
    TableRow rows[PANELS];
    Image images[PANELS];
    char captions[PANELS][256];
    for (int i = 0; i < PANELS; i++) {
        char settings_text[96];
        snprintf(settings_text, sizeof settings_text, "%d spp %s, M=0 depth=%d", panels[i].spp,
                 panels[i].sampling == PIXEL_RANDOM ? "random" : "sub-pixels", options.depth);
        rows[i] = experiment_path_row(&options, &scene, path_radiance, &hitting, panels[i].spp,
                                      panels[i].sampling, panels[i].name, settings_text,
                                      &reference, &images[i]);
        experiment_caption(&rows[i], panels[i].title, captions[i], sizeof captions[i]);
    }

    const char *figure2[] = {captions[3]};
    const char *figure8[] = {captions[0], captions[1]};
    const char *supersampling[] = {captions[1], captions[2], captions[3], captions[4]};
    Image supersampling_images[] = {images[1], images[2], images[3], images[4]};
    experiment_write_figure(&options, "ch02_figure2", &images[3], figure2, 1, PANEL_EXPOSURE);
    experiment_write_figure(&options, "ch02_figure8", images, figure8, 2, PANEL_EXPOSURE);
    experiment_write_figure(&options, "ch02_subpixels_vs_random", supersampling_images,
                            supersampling, 4, PANEL_EXPOSURE);
    experiment_write_table(&options, "ch02_table", rows, PANELS);

    for (int i = 0; i < PANELS; i++)
        image_free(&images[i]);
    measure_reference_free(&reference);
    scene_free(&scene);
    return 0;
}
