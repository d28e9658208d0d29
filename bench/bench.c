/* bench.c (bench, chapter 7): the speed benchmark (`make bench`). A benchmark, not a
 * test: it asserts nothing and prints what it measures.
 *
 * The workload is Table 1's first row, the report's cheapest full image: the room at
 * 800 x 800, 16 samples per pixel on sub-pixels, 1 shadow ray, roulette alpha 0.25.
 * It renders it on one thread and on all cores, and prints for each the wall time,
 * rays per second (camera, bounce and shadow rays together), per core, samples per
 * second, and the rays per CPU second, which is the per-core speed even on a machine
 * that other programs share (wall time then counts their turns too), and the speed-up.
 * The image is the same for any thread count (bench/tests/test_render.c), so the two
 * runs do exactly the same work. Chapter 9 measures what each stage of the queries buys.
 *
 * Then the room's efficiency, 1 / (relative MSE x seconds), of chapter 7's final
 * estimator (Figure 7's: one shadow ray, bounded-weight roulette, the lamp's mirror
 * image, exact Fresnel, depth 64) at a quarter of the size and 64 spp on all cores,
 * measured over 3 runs against the reference that chapter 7 uses at that size
 * (build/reference, cached in build/references: rendered once), with
 * independent numbers and with the stratified pairs (sobol.h).
 */
#include <stdio.h>
#include <time.h>

#include "cli.h"
#include "experiment.h"
#include "path_final.h"
#include "path_roulette.h"
#include "sphere_guide.h"

static void report(const char *label, const RenderResult *r, double cpu_seconds)
{
    double rays = (double)ray_counts_total(r->rays);
    double samples = (double)r->samples;
    printf("%-7s %2d thread%s %7.2f s %7.2f Mrays/s %7.2f Mrays/s/thread %7.2f Msamples/s"
           " %7.2f Mrays/CPU-s\n",
           label, r->threads, r->threads == 1 ? " " : "s", r->seconds, 1e-6 * rays / r->seconds,
           1e-6 * rays / r->seconds / r->threads, 1e-6 * samples / r->seconds,
           1e-6 * rays / cpu_seconds);
}

int main(int argc, char **argv)
{
    ProgramInfo info = {
        "The speed benchmark: Table 1's first row (16 spp, 1 shadow ray, alpha 0.25) on one\n"
        "thread and on all cores.",
        FLAG_SCENE | FLAG_SIZE | FLAG_SPP | FLAG_THREADS | FLAG_QUIET,
        {.scene = "scenes/room.scene", .size = 800, .spp = 16, .threads = 0, .out = "."},
    };
    Options options;
    Scene scene;
    experiment_start(argc, argv, &info, NEEDS_AREA_LIGHT, &options, &scene);
    PathSettings path = {.max_depth = 64, .shadow_rays = 1, .rr_survival = 0.25};
    int threads[2] = {1, options.threads > 0 ? options.threads : render_core_count()};
    RenderResult results[2];
    double cpu[2];
    printf("room, %d x %d, %d spp, M=1, alpha=0.25 (Table 1, row 1)\n", options.size,
           options.size, options.spp);
    for (int i = 0; i < 2; i++) {
        RenderSettings settings = {
            {options.size, options.size, options.spp, PIXEL_SUBPIXELS, 1},
            threads[i],
            !options.quiet,
            "bench"};
        clock_t start = clock();
        if (render(&scene, &settings, path_roulette_radiance, &path, &results[i]) != 0)
            cli_fail(1, "out of memory");
        cpu[i] = (double)(clock() - start) / CLOCKS_PER_SEC;
        report(i == 0 ? "single" : "multi", &results[i], cpu[i]);
    }
    printf("speed-up %.2f on %d threads (rays: %.1f M camera, %.1f M bounce, %.1f M shadow)\n",
           results[0].seconds / results[1].seconds, results[1].threads,
           1e-6 * results[1].rays.camera, 1e-6 * results[1].rays.bounce,
           1e-6 * results[1].rays.shadow);
    for (int i = 0; i < 2; i++)
        render_result_free(&results[i]);

    Options small = options;
    small.size = experiment_width_near(&scene, cli_quarter(options.size, 16));
    small.spp = 64;
    small.depth = 64;
    small.fresnel = FRESNEL_EXACT;
    small.reference_spp = 256;
    small.runs = 3;
    small.threads = threads[1];
    small.seed = 1;
    MirrorPlanes mirrors;
    if (mirror_light_find_planes(&scene, &mirrors) != 0)
        cli_fail(1, "out of memory");
    PathSettings final = {.max_depth = 64,
                          .shadow_rays = 1,
                          .fresnel = FRESNEL_EXACT,
                          .rr_throughput = 1,
                          .mirror_light = 64,
                          .mirrors = &mirrors,
                          .sphere_guide = SPHERE_GUIDE_STRENGTH};
    printf("\nthe room's efficiency, chapter 7's final estimator, %d pixels wide, %d spp, %d "
           "threads, %d runs:\n",
           small.size, small.spp, small.threads, small.runs);
    Reference reference;
    experiment_path_reference(&small, &scene, &final, NULL, 0.0, &reference);
    const PixelSampling samplings[2] = {PIXEL_SUBPIXELS, PIXEL_STRATIFIED};
    const char *names[2] = {"independent numbers", "stratified pairs"};
    TableRow rows[2];
    for (int i = 0; i < 2; i++) {
        rows[i] = experiment_path_row(&small, &scene, path_final_radiance, &final, small.spp,
                                      samplings[i], names[i], names[i], &reference, NULL);
        printf(
            "  %-20s %6.2f s per run  RMSE %.4f +- %.4f  relative MSE %.3g  efficiency %.3g\n",
            names[i], rows[i].seconds, rows[i].rmse, rows[i].rmse_spread, rows[i].rel_mse,
            rows[i].efficiency);
    }
    printf("stratified pairs: %.2f times the efficiency of independent numbers\n",
           rows[1].efficiency / rows[0].efficiency);
    measure_reference_free(&reference);
    mirror_planes_free(&mirrors);
    scene_free(&scene);
    return 0;
}
