/* sphere_guide.h (chapter 7): bounces aimed at the mirror and glass spheres, for their
 * caustics.
 *
 * A diffuse bounce picks, with probability q_k, a direction uniform in the cone of
 * sphere k (solid angle Omega_k) and otherwise the cosine-weighted hemisphere. Any
 * direction w is weighted by the whole mixture's density (one-sample MIS, Veach §9.2.4)
 *     p(w) = (1 - sum q_k) cos / pi + sum_k q_k [w in cone k] / Omega_k,
 * unbiased since the cosine part keeps p > 0 wherever f cos > 0. q_k = strength Omega_k
 * / (2 pi), the total capped at 1/2 (docs/chapter7.md).
 */
#ifndef SPHERE_GUIDE_H
#define SPHERE_GUIDE_H

#include "path.h"

#define SPHERE_GUIDE_MAX 8

/* The strength chapter 7's final estimator uses (docs/chapter7.md: how it was chosen). */
#define SPHERE_GUIDE_STRENGTH 8.0

typedef struct {
    int count;
    Vec3 axis[SPHERE_GUIDE_MAX];      /* unit, from x to the sphere's centre */
    double cos_max[SPHERE_GUIDE_MAX]; /* cos theta_k */
    double density[SPHERE_GUIDE_MAX]; /* q_k / Omega_k */
    double share[SPHERE_GUIDE_MAX];   /* q_k */
    double cosine_share;              /* 1 - sum q_k */
} SphereGuide;

/* The cones of the mirror and glass spheres seen from x (unit normal n). */
void sphere_guide_at(const Scene *scene, Vec3 x, Vec3 n, double strength, SphereGuide *guide);

/* A direction drawn from the mixture, from u_select, u1, u2 uniform in [0, 1). */
Vec3 sphere_guide_sample(const SphereGuide *guide, Vec3 n, double u_select, double u1,
                         double u2);

/* The mixture's density p(w) in solid angle. */
double sphere_guide_pdf(const SphereGuide *guide, Vec3 n, Vec3 w);

/* The bounce at diffuse vertex x drawn from the mixture of this strength (the cosine-
 * weighted one when no sphere takes part): the throughput's factor f cos / p, zero for
 * a direction below the surface, the direction and its density p. */
Vec3 sphere_guide_bounce(const Scene *scene, const Vertex *x, double strength, Rng *rng,
                         Vec3 *direction, double *pdf);

#endif
