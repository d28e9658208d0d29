/* stage.c (bench, chapter 9): measuring a stage. See stage.h. */
#include "stage.h"

#include <string.h>

#include "atomic_file.h"
#include "stats.h"

const Stage QUERY_STAGES[QUERY_STAGE_COUNT] = {
    {"every primitive", QUERY_EVERY_PRIMITIVE, 1},
    {"chapter 2's binary tree", QUERY_BINARY_TREE, 1},
    {"the four-wide float tree", QUERY_WIDE_TREE, 1},
};

int stage_measure(Scene *scene, const RenderSettings *settings, Estimator estimate,
                  const void *estimator_settings, const Stage *stage, double seconds,
                  StageResult *result)
{
    memset(result, 0, sizeof *result);
    RenderSettings these = *settings;
    these.threads = stage->threads;
    scene->query = stage->query;
    double cpu_start = stats_cpu_now();
    do {
        RenderResult render_result;
        if (render(scene, &these, estimate, estimator_settings, &render_result) != 0) {
            if (result->renders > 0)
                render_result_free(&result->first);
            scene->query = QUERY_WIDE_TREE;
            return -1;
        }
        result->rays += (double)ray_counts_total(render_result.rays);
        result->wall_seconds += render_result.seconds;
        result->threads = render_result.threads;
        if (result->renders++ == 0)
            result->first = render_result;
        else
            render_result_free(&render_result);
        result->cpu_seconds = stats_cpu_now() - cpu_start;
    } while ((result->cpu_seconds < seconds || result->wall_seconds < seconds) &&
             !render_interrupted());
    scene->query = QUERY_WIDE_TREE;
    return 0;
}

long stage_differing_pixels(const Image *a, const Image *b)
{
    long differing = 0;
    for (long i = 0; i < (long)a->width * a->height; i++)
        differing += memcmp(&a->pixels[3 * i], &b->pixels[3 * i], 3 * sizeof *a->pixels) != 0;
    return differing;
}

/* One row as text: aligned for the terminal, or comma-separated. */
static void print_row(FILE *out, const StageRow *row, const StageRow *first, int csv)
{
    const StageResult *r = &row->result;
    double per_cpu = r->rays / r->cpu_seconds, per_wall = r->rays / r->wall_seconds;
    double first_per_cpu = first->result.rays / first->result.cpu_seconds;
    const char *format =
        csv ? "%s,%s,%d,%d,%.0f,%.4f,%.4f,%.4f,%.4f,%.3f,%ld\n"
            : "%-28s %-6s %7d %7d %12.0f %8.2f %8.2f %9.3f %9.3f %8.2fx %9ld\n";
    fprintf(out, format, row->stage->name, row->scene, r->threads, r->renders, r->rays,
            r->cpu_seconds, r->wall_seconds, 1e-6 * per_cpu, 1e-6 * per_wall,
            per_cpu / first_per_cpu, row->differing);
}

int stage_write_table(const StageRow *rows, int count, const char *path)
{
    printf("%-28s %-6s %7s %7s %12s %8s %8s %9s %9s %9s %9s\n", "panel", "scene", "threads",
           "renders", "rays", "cpu_s", "seconds", "Mray/cpu", "Mray/wall", "x_stage1",
           "differ");
    AtomicFile file;
    if (atomic_open(&file, path) != 0)
        return -1;
    fprintf(file.file, "stage,scene,threads,renders,rays,cpu_seconds,wall_seconds,"
                       "mrays_per_cpu_second,mrays_per_wall_second,speed_up_over_first,"
                       "differing_pixels\n");
    const StageRow *first = rows;
    for (int i = 0; i < count; i++) {
        if (i > 0 && rows[i].scene != rows[i - 1].scene)
            first = &rows[i];
        print_row(stdout, &rows[i], first, 0);
        print_row(file.file, &rows[i], first, 1);
    }
    return atomic_close(&file, 0);
}
