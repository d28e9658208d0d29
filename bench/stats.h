/* stats.h (bench, chapter 1): what a render costs: its time, and its rays by purpose
 * (RayCounts, lib/render.h), summed over the threads.
 */
#ifndef STATS_H
#define STATS_H

#include <stdint.h>

#include "render.h"

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
 * (a time budget that other programs sharing the machine do not eat into). */
double stats_cpu_now(void);

#endif
