/* area_light.h (chapter 3): sampling the area lights, and the direct-light estimator of
 * eq. 21 (report §3.7).
 *
 * The lights are the emitting triangles (scene.h). A point y is drawn uniformly over
 * their total area A: a triangle with probability area / A, then y = T(s (1 - u2), s u2),
 * s = sqrt(u1) (eq. 16). With M shadow rays, at x towards the viewer,
 *     L_D = A / M sum_k Le(y_k) f(x, w_k, wo) cos(alpha_k) cos(beta_k) / d_k^2 V_k  (21)
 * alpha_k at x, beta_k at y_k between its front normal and -w_k, d_k = |y_k - x|;
 * unbiased for any M >= 1 (docs/chapter3.md).
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

/* Exercise 3.1: a point uniformly distributed over all lights' area; density
 * 1 / scene->light_area. The scene must have at least one light. */
LightSample area_light_sample(const Scene *scene, double u_select, double u1, double u2);

/* One term of eq. 21: the light from one point y, and the direction to it with its
 * density in solid angle (area_light_pdf). value is zero when the light or the surface
 * faces away or the shadow ray is blocked. */
typedef struct {
    Vec3 value;
    Vec3 wi;
    double pdf;
} ShadowRay;

/* Exercise 3.3: one shadow ray from surface point x (unit normal n facing the viewer,
 * direction wo) of the diffuse material m. */
ShadowRay area_light_shadow_ray(const Scene *scene, Vec3 x, Vec3 n, Vec3 wo, const Material *m,
                                Rng *rng, RayCounts *counts);

/* Exercise 3.4: eq. 21 with M = shadow_rays >= 1, the mean of M shadow rays. */
Vec3 area_light_direct(const Scene *scene, Vec3 x, Vec3 n, Vec3 wo, const Material *m,
                       int shadow_rays, Rng *rng, RayCounts *counts);

/* Exercise 3.2: the density in solid angle of the direction towards a light point drawn
 * by area, a distance d away, whose normal makes the angle beta with the way back:
 * dA = d^2 dw / cos(beta) turns the density 1/A into d^2 / (A cos beta). */
double area_light_pdf(const Scene *scene, double distance, double cos_beta);

#endif
