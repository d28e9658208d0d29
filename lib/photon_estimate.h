/* photon_estimate.h (chapter 8): reflected radiance from the density of photons (Jensen
 * 1996), and the progressive radius that makes it converge.
 *
 * The photons within r of x carried the flux that fell on the disk pi r^2 around it:
 *     L(x, wo) ~ sum_p f(x, wi_p, wo) Phi_p / (pi r^2).
 * A blur of radius r: biased where the density changes, unbiased as r goes to 0, its
 * variance growing as 1 / (N r^2). Only photons on a surface facing the same way count
 * (normals within PHOTON_NORMAL_COS), so light does not leak round corners.
 */
#ifndef PHOTON_ESTIMATE_H
#define PHOTON_ESTIMATE_H

#include "photon.h"

#define PHOTON_NORMAL_COS 0.9

/* Exercise 8.1: L(x, wo) from `map`'s photons within `radius` of x, for the diffuse
 * material m at a surface with unit normal n facing wo. */
Vec3 photon_estimate_radiance(const PhotonMap *map, double radius, Vec3 x, Vec3 n, Vec3 wo,
                              const Material *m);

/* The points of the disc tested for whether photons can reach them. */
#define EDGE_POINTS 16

/* The same at the diffuse vertex x of `scene`, its flux divided by the area of the disc
 * that photons can reach (photon_estimate.c) instead of pi r^2: near an edge or a wall,
 * where part of the disc is off the surface or behind the wall, pi r^2 darkens the edge. */
Vec3 photon_estimate_reachable(const Scene *scene, const PhotonMap *map, double radius,
                               const Vertex *x);

/* Exercise 8.2, progressive photon mapping: pass j's radius, the power law
 *     r_j = r_1 sqrt(j^(alpha - 1)),   0 < alpha < 1,
 * that Knaus and Zwicker's recurrence r_(j+1)^2 = r_j^2 (j + alpha) / (j + 1) approaches
 * (docs/chapter8.md), so that both the bias (which shrinks with r) and the variance (which
 * grows as 1 / (N r^2) in one pass, but is averaged over the passes) go to zero. */
#define PPM_ALPHA (2.0 / 3.0)
double ppm_radius(double first_radius, double alpha, int pass);

/* A first radius that follows the view and the scene's size, not its units (as
 * stochastic progressive photon mapping takes it from a pixel's footprint): `fraction`
 * of the width the view covers at the depth of what the camera sees, the median depth
 * of the first hits of VIEW_RAYS x VIEW_RAYS camera rays (docs/chapter8.md). Never ~0
 * for a valid scene: the same scene at any scale is blurred alike, and neither an
 * object out of view nor where the lamps are changes it. The scene must have a light. */
#define VIEW_RAYS 16
double ppm_first_radius(const Scene *scene, double fraction);

#endif
