/* path.h (chapter 2): the Monte Carlo path tracer (report §2.2, §3.4-3.7; eq. 1), first
 * as the simplest estimator: light is found only when a path happens to hit it.
 *
 * A path from the camera bounces at diffuse surfaces in cosine-weighted directions
 * (diffuse.h), reflects at mirrors and refracts or reflects at glass (glass.h). Its
 * throughput T, the product of f cos / pdf over its bounces, weights the emission it
 * hits. The helpers declared here, a path's vertex and its two kinds of bounce, are
 * what a path tracer is built from.
 */
#ifndef PATH_H
#define PATH_H

#include "render.h"
#if CHAPTER >= 4
#include "fresnel.h"
#endif
#if CHAPTER >= 7
#include "mirror_light.h"
#endif

/* The settings of every path tracer; zero (or left out of an initialiser) is each
 * one's plain setting. */
typedef struct {
    int max_depth; /* segments per path at most, the camera ray being the first */
#if CHAPTER >= 3
    int shadow_rays; /* M of eq. 21 at each diffuse hit; 0: light found by hitting it */
#endif
#if CHAPTER >= 4
    FresnelMode fresnel; /* the glass's reflectance: Schlick's or the exact one */
#endif
#if CHAPTER >= 6
    double rr_survival; /* Russian roulette's alpha; 0 (not set) or 1: no roulette */
    int rr_throughput;  /* k >= 1: bounded-weight roulette from segment k on, instead */
#endif
#if CHAPTER >= 7
    int mis;          /* 1: light and BRDF sampling combined by the power heuristic */
    int mirror_light; /* K: at the first K diffuse hits, shadow rays to the lamps' images */
    const MirrorPlanes *mirrors; /* ... in these planar mirrors */
    double sphere_guide; /* > 0: bounces aimed at the mirror and glass spheres, this strongly */
#endif
} PathSettings;

/* A path's vertex: what its ray hit, seen from the ray. */
typedef struct {
    Hit hit;
    const Material *material;
    int front;   /* the ray arrived on the front side */
    Vec3 normal; /* unit, facing the incoming ray */
    Vec3 wo;     /* unit, back along the incoming ray */
} Vertex;

/* Exercise 2.6: the first surface along the ray: 1 and *x (its normal turned to face the
 * ray), or 0 when the ray leaves the scene. */
int path_vertex(const Scene *scene, Ray ray, Vertex *x);

/* At a diffuse vertex x: a cosine-weighted direction (diffuse.h), and the factor the
 * throughput takes, f cos / pdf. */
Vec3 path_diffuse_bounce(const Vertex *x, Rng *rng, Vec3 *direction);

/* At a mirror or glass vertex x reached along direction d: the direction the path goes
 * on in, and the factor its throughput takes (the mirror's colour; 1 at glass). */
Vec3 path_specular(const Vertex *x, Vec3 d, const PathSettings *settings, Rng *rng,
                   Vec3 *direction);

/* Exercise 2.4: the path tracer that finds light only by hitting it. An Estimator
 * (render.h); settings points to a PathSettings. */
Vec3 path_radiance(const Scene *scene, Ray ray, Rng *rng, const void *settings,
                   RayCounts *counts);

#endif
