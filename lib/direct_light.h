/* direct_light.h (chapter 7): the light arriving straight from the lamps at a diffuse
 * vertex, with multiple importance sampling (mis.h) and the lamps' images in planar
 * mirrors (mirror_light.h).
 *
 * M shadow rays go to the lamps and, at a vertex that uses the images, M more to each
 * mirror's image of them. With mis on, each is weighted by the power heuristic against
 * the path's own bounce, which then adds the complementary share of the emission it
 * hits. With mis off and no images it is eq. 21, area_light_direct.
 */
#ifndef DIRECT_LIGHT_H
#define DIRECT_LIGHT_H

#include "path.h"

/* The direct light at diffuse vertex x; with `images`, through the mirrors too. */
Vec3 direct_light(const Scene *scene, const Vertex *x, int images, const PathSettings *settings,
                  Rng *rng, RayCounts *counts);

/* The power heuristic's share of emission that a path hit after a diffuse bounce of
 * density bsdf_pdf, travelling `distance` in all (unfolded at mirrors) to a light whose
 * normal makes cos_beta with the way back: the rest went to the shadow rays. */
double direct_light_hit_weight(const Scene *scene, const PathSettings *settings,
                               double bsdf_pdf, double distance, double cos_beta);

#endif
