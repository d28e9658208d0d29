/* record.h (bench, chapter 8): one sample's path, recorded for the lab's inspector with
 * no line of the estimators changed.
 *
 * The estimators reach the scene and the pieces of their physics through functions of
 * other files: the ray queries, the bounces (diffuse_sample, sphere_guide_bounce,
 * glass_scatter), the direct light and its light samples, roulette, the MIS weight of
 * emission hit, the photon estimates. The lab's programs are linked with each wrapped
 * (the linker's --wrap=NAME sends calls of NAME to __wrap_NAME, which calls the original
 * __real_NAME): the wrapper notes what went in and came out while a recording is on
 * and returns the original's result unchanged. The chapter programs are linked without
 * the wrappers. docs/lab.md: what each note holds.
 */
#ifndef RECORD_H
#define RECORD_H

#include "json.h"
#include "path.h"

/* Record, as JSON into `json`, the calls of the sample about to be taken with `path`'s
 * settings; `tree`: Whitted's ray tree (chapter 1), whose rays are noted without a
 * throughput. */
void record_start(Json *json, const Scene *scene, const PathSettings *path, int tree);

/* End the recording with the radiance the estimator returned: the emission added at
 * the last vertex (what the notes do not account for) and whether it is what that
 * vertex's emission, throughput and MIS weight give. */
void record_finish(Vec3 radiance);

#endif
