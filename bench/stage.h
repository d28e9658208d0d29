/* stage.h (bench, chapter 9): one stage of chapter 9's speed measurement.
 *
 * A stage is a way of answering the ray queries (every primitive, chapter 2's tree, the
 * four-wide tree) on a number of threads. It renders the same image again and again
 * until it has used `seconds` of processor time and of wall time, so that a fast stage
 * is timed over long enough to be measured; rays per CPU second then compare the ways
 * of querying, rays per wall second the threads. The first render's image is kept, to
 * check that every stage renders the same image bit for bit.
 */
#ifndef STAGE_H
#define STAGE_H

#include "renderer.h"

typedef struct {
    const char *name;
    QueryMethod query;
    int threads; /* 0: one per core */
} Stage;

typedef struct {
    double rays;        /* traced, over every render */
    double cpu_seconds; /* processor time, every thread together */
    double wall_seconds;
    int renders;
    int threads;
    RenderResult first; /* the first render */
} StageResult;

/* The stages of querying that chapter 9 compares, on one thread: every primitive tested,
 * chapter 2's binary tree, the four-wide tree (in that order). */
enum {
    QUERY_STAGE_COUNT = 3
};
extern const Stage QUERY_STAGES[QUERY_STAGE_COUNT];

/* Measure a stage. Returns 0, or -1 when memory runs out (nothing is then allocated). */
int stage_measure(Scene *scene, const RenderSettings *settings, Estimator estimate,
                  const void *estimator_settings, const Stage *stage, double seconds,
                  StageResult *result);

/* The pixels in which two images of one size differ in any bit of any channel. */
long stage_differing_pixels(const Image *a, const Image *b);

/* One row of the table: a stage measured on a scene, and how many of its first
 * render's pixels differ from the first stage's on that scene. */
typedef struct {
    const char *scene;
    const Stage *stage;
    StageResult result;
    long differing;
} StageRow;

/* Print the rows (rays per CPU second and per wall second, the speed-up over the
 * scene's first row) and write them as CSV to `path`. Returns 0, or -1 with errno set
 * when the file cannot be written. */
int stage_write_table(const StageRow *rows, int count, const char *path);

#endif
