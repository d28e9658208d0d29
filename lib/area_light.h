/* area_light.h (chapter 3): sampling area lights, and the direct-light estimator of eq. 21
 * (report §3.7).
 *
 * Introduced in chapter 3. The lights are the emitting triangles the scene listed
 * (scene.h; a quad light is two triangles). A point y is chosen uniformly over their
 * total area A: a triangle with probability area_i / A (binary search in the running
 * sum of areas), then a uniform point in it,
 *     s = sqrt(u1),  y = T(s (1 - u2), s u2)   (eq. 16),
 * whose density over the triangle is constant; so y has density 1/A over all lights.
 *
 * Direct light at x towards the viewer, with M shadow rays (eq. 21, generalised from
 * one light of radiance L0 to several lights each of its own radiance Le):
 *     L_D = A/M * sum_k  Le(y_k) f(x, w_k, w_o) cos(alpha_k) cos(beta_k) / d_k^2 * V_k,
 * alpha_k the angle at x between its normal and w_k (towards y_k), beta_k the angle at
 * y_k between the light's front normal and -w_k, d_k = |y_k - x|, V_k the visibility.
 * A light emits from its front side only, so a sample behind it (cos beta <= 0)
 * contributes nothing; so does one behind the surface at x (cos alpha <= 0).
 * The estimator is unbiased for any M >= 1: each term's mean is the direct light.
 */
#ifndef AREA_LIGHT_H
#define AREA_LIGHT_H

#include "material.h"
#include "render.h"

typedef struct {
    Vec3 point;
    Vec3 normal;   /* the light's front normal */
    Vec3 emission; /* its radiance */
} LightSample;

/* A point uniformly distributed over all lights' area; density 1 / scene->light_area.
 * The scene must have at least one light. */
LightSample area_light_sample(const Scene *scene, double u_select, double u1, double u2);

/* One term of eq. 21 (M = 1): the estimate A Le f cos(alpha) cos(beta) / d^2 V of the
 * direct light from one light point; zero when the light or the surface faces away or
 * the shadow ray is blocked. */
typedef struct {
    Vec3 value;
#if CHAPTER >= 7
    Vec3 wi;    /* the direction towards the light point */
    double pdf; /* its density in solid angle (area_light_pdf); 0 when value is zero */
#endif
} ShadowRay;

ShadowRay area_light_shadow_ray(const Scene *scene, Vec3 x, Vec3 n, Vec3 wo, const Material *m,
                                Rng *rng, RayCounts *counts);

/* Eq. 21 at surface point x with normal n facing the viewer (direction wo), for the
 * diffuse material m, with M = shadow_rays >= 1. */
Vec3 area_light_direct(const Scene *scene, Vec3 x, Vec3 n, Vec3 wo, const Material *m,
                       int shadow_rays, Rng *rng, RayCounts *counts);

#if CHAPTER >= 7
/* The density in solid angle, at a point a distance d away, of the direction towards a
 * light point sampled uniformly by area, where the light's front normal makes the angle
 * beta with the direction back (cos_beta > 0): converting the area density 1/A by
 * dA = d^2 dw / cos(beta),
 *     p(w) = d^2 / (A cos beta).
 * Multiple importance sampling (mis.h) weighs each way of finding the light by it. */
double area_light_pdf(const Scene *scene, double distance, double cos_beta);
#endif

#endif
