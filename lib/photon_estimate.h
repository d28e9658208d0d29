/* photon_estimate.h (chapter 8): reflected radiance from the density of photons.
 * Jensen, "Global illumination using photon maps" (1996): the radiance a diffuse
 * surface reflects, estimated from the photons near it.
 *
 * Introduced in chapter 8. The photons within distance r of x carry the flux that fell
 * on the disk of area pi r^2 around x (the surface is locally flat), each from its own
 * direction wi_p, so the reflected radiance towards wo is
 *     L(x, wo) ~ sum_p f(x, wi_p, wo) Phi_p / (pi r^2)
 * with the surface's BRDF f (Lambert or Oren-Nayar, diffuse.h). This is a box kernel:
 * every photon in the disk counts the same. It estimates the flux density averaged over
 * the disk, not at x itself, so it is biased where that density changes: by about
 * r^2 / 8 times its Laplacian (a blur of radius r), and low at a surface's edge, where
 * part of the disk lies off the surface. The bias goes to zero as r does; the variance
 * grows as 1 / (N r^2), N the photons shot. Progressive photon mapping (ppm.h) shrinks
 * r from pass to pass so that both go to zero.
 *
 * Only photons that landed on a surface facing the same way count: their stored
 * normal within PHOTON_NORMAL_COS of x's (about 26 degrees), and their direction on
 * x's side. Otherwise light on the floor would leak up a wall at a corner, or through
 * a thin surface to its other side.
 */
#ifndef PHOTON_ESTIMATE_H
#define PHOTON_ESTIMATE_H

#include "photon.h"

#define PHOTON_NORMAL_COS 0.9

/* L(x, wo) from `map`'s photons within `radius` of x, for the diffuse material m at a
 * surface with unit normal n facing wo. */
Vec3 photon_estimate_radiance(const PhotonMap *map, double radius, Vec3 x, Vec3 n, Vec3 wo,
                              const Material *m);

#endif
