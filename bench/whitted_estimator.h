/* whitted_estimator.h (bench, chapter 1): Whitted's estimate as any chapter's Estimator.
 *
 * In chapter 1 whitted_radiance (whitted.h) is an Estimator (render.h). From chapter 2 on
 * an Estimator also takes the sample's generator, which Whitted's estimate would ignore:
 * it draws no random numbers. The bench, its tests and the lab render it through this.
 */
#ifndef WHITTED_ESTIMATOR_H
#define WHITTED_ESTIMATOR_H

#include "whitted.h"

#if CHAPTER >= 2
static inline Vec3 whitted_estimate(const Scene *scene, Ray ray, Rng *rng, const void *settings,
                                    RayCounts *counts)
{
    return whitted_radiance(scene, ray, settings, counts);
}
#else
static inline Vec3 whitted_estimate(const Scene *scene, Ray ray, const void *settings,
                                    RayCounts *counts)
{
    return whitted_radiance(scene, ray, settings, counts);
}
#endif

#endif
