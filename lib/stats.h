/* stats.h (chapter 1): what a render costs: wall-clock time and rays traced (SPEC §6).
 *
 * Introduced in chapter 1. Rays are counted by purpose, so a table can say where the
 * time went: camera rays (one per sample), bounce rays (every ray a path continues
 * with: diffuse, mirror, glass), shadow rays (visibility tests towards a light).
 * Each render thread counts into its own RayCounts, a row at a time (render.c); they
 * are summed at the end.
 */
#ifndef STATS_H
#define STATS_H

#include <stdint.h>

typedef struct {
    uint64_t camera, bounce, shadow;
} RayCounts;

static inline uint64_t ray_counts_total(RayCounts c) { return c.camera + c.bounce + c.shadow; }

static inline void ray_counts_add(RayCounts *sum, RayCounts c)
{
    sum->camera += c.camera;
    sum->bounce += c.bounce;
    sum->shadow += c.shadow;
}

/* Seconds on a monotonic clock since an arbitrary start: subtract two readings. */
double stats_now(void);

/* Seconds of processor time used by this process so far, all its threads together
 * (chapter 8: a time budget that other programs sharing the machine do not eat into). */
double stats_cpu_now(void);

#endif
