/* sphere_guide.h (chapter 7): bounces aimed at the mirror and glass spheres, for the
 * caustics (issue 11: spend the samples where the error is).
 *
 * Light that reaches a diffuse point through a glass or mirror sphere (the bright patch
 * that the room's glass sphere focuses on the floor) is found only when the bounce
 * direction happens to hit the sphere and the path then, after refraction, hits the
 * lamp: the path tracer's brightest and rarest samples. From a floor point under the
 * glass sphere a cosine-weighted bounce hits it about one time in ten.
 *
 * So a diffuse bounce chooses, with probability q_k, a direction uniformly in the cone
 * of directions that meet sphere k (half-angle theta_k, sin theta_k = r / |c - x|,
 * solid angle Omega_k = 2 pi (1 - cos theta_k)), and otherwise (1 - sum q_k) the cosine-
 * weighted hemisphere. Whichever it chose, the direction w is weighted by the density
 * of the whole mixture (one-sample MIS with the balance heuristic; Veach 1997, §9.2.4):
 *     p(w) = (1 - sum q_k) cos(w) / pi + sum_k q_k [w in cone k] / Omega_k,
 *     weight = f(w) cos(w) / p(w),
 * which is unbiased for any q_k as long as p(w) > 0 wherever f cos > 0 (the cosine part
 * keeps it so; q_total <= 1/2). A cone direction below the surface has f cos = 0: the
 * path ends there, which costs a sample but biases nothing.
 *
 * q_k = strength * Omega_k / (2 pi), capped so that the total is at most 1/2: a sphere
 * far away gets few samples (its caustic is weak and its cone small), one close by more.
 * Only spheres whose cone is partly above the surface and that do not contain x take
 * part; at most SPHERE_GUIDE_MAX of them (the first in the scene), the others are
 * reached by the cosine part as before.
 */
#ifndef SPHERE_GUIDE_H
#define SPHERE_GUIDE_H

#include "scene.h"

#define SPHERE_GUIDE_MAX 8

/* The strength chapter 7's final estimator uses. Measured on the room at 256 x 256,
 * 64 spp, against one 8192-spp reference: relative RMSE 0.0717 without the guide,
 * 0.0565 at strength 2, 0.0512 at 4, 0.048 to 0.050 at 8, 0.0512 at 16, 0.056 at 32
 * (the cap of 1/2 then holds most points), for about 5% more time. */
#define SPHERE_GUIDE_STRENGTH 8.0

typedef struct {
    int count;
    Vec3 axis[SPHERE_GUIDE_MAX];     /* unit, from x to the sphere's centre */
    double cos_max[SPHERE_GUIDE_MAX]; /* cos theta_k */
    double density[SPHERE_GUIDE_MAX]; /* q_k / Omega_k */
    double share[SPHERE_GUIDE_MAX];   /* q_k */
    double cosine_share;              /* 1 - sum q_k */
} SphereGuide;

/* The cones of the mirror and glass spheres seen from x (unit normal n). */
void sphere_guide_at(const Scene *scene, Vec3 x, Vec3 n, double strength, SphereGuide *guide);

/* A direction drawn from the mixture, from u_select, u1, u2 uniform in [0, 1). */
Vec3 sphere_guide_sample(const SphereGuide *guide, Vec3 n, double u_select, double u1, double u2);

/* The mixture's density p(w) in solid angle. */
double sphere_guide_pdf(const SphereGuide *guide, Vec3 n, Vec3 w);

#endif
