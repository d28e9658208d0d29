/* glass.h (chapter 2): a path at glass: reflection or refraction, chosen by the Fresnel
 * reflectance R (report §3.5.2).
 *
 * Whitted (chapter 1) traces both branches, weighted R and 1 - R: a path that meets
 * glass k times becomes a tree of up to 2^k rays. A Monte Carlo path instead reflects
 * with probability R and refracts with probability 1 - R, each with weight 1: its
 * expected value is R L_reflected + (1 - R) L_refracted, the same, for one ray per
 * interface (docs/chapter2.md).
 */
#ifndef GLASS_H
#define GLASS_H

#include "path.h"

/* The new direction of a path with unit direction d at glass of index `ior`, whose unit
 * normal n faces d's origin (entering: coming from outside the glass). R is Schlick's
 * until chapter 4, whose settings->fresnel chooses it or the exact Fresnel equations. */
Vec3 glass_scatter(Vec3 d, Vec3 n, int entering, double ior, const PathSettings *settings,
                   Rng *rng);

#endif
