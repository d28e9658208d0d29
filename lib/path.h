/* path.h (chapter 2): the Monte Carlo path tracer (report §2.2, §3.4-3.7; eq. 1).
 *
 * Introduced in chapter 2; chapters 3-7 switch on its options one by one:
 *   shadow_rays  M of eq. 21 (chapter 3). M = 0: light is found only when a path hits
 *                it (chapter 2). M >= 1: at every diffuse hit, M shadow rays estimate
 *                the direct light (area_light.h), and emission that a path then hits
 *                right after a diffuse bounce is not added again (it was counted by
 *                the shadow rays); emission seen from the camera or after a mirror or
 *                glass bounce is added, since no shadow ray accounts for it.
 *   rr_survival  Russian roulette's alpha (chapter 6; roulette.h); 0 or 1: no roulette.
 *   rr_throughput  roulette with bounded weights instead (chapter 6; roulette.h): at a
 *                diffuse hit on segment k or later, the path survives with probability
 *                min(1, max component of its throughput). 0: off (rr_survival applies).
 *   max_depth    a path has at most this many segments, the camera ray being the first.
 *                The same count bounds both ways of finding light (a shadow ray is the
 *                segment after its hit), so every M estimates the same quantity.
 *   fresnel      glass reflectance: Schlick (chapter 1) or exact Fresnel (chapter 4).
 *   mis          multiple importance sampling of the lamps (chapter 7; mis.h), with
 *                M >= 1: each shadow ray's light is weighted by the power heuristic, and
 *                emission that a path hits right after a diffuse bounce is added too,
 *                weighted by the complementary share, instead of dropped.
 *   sphere_guide bounces aimed at the mirror and glass spheres (chapter 7;
 *                sphere_guide.h): at a diffuse hit the bounce direction comes from a
 *                mixture of the cosine-weighted hemisphere and the spheres' cones, this
 *                strong, weighted by the mixture's density. 0: cosine only.
 *   mirror_light the lamps seen in planar mirrors (chapter 7; mirror_light.h), with
 *                M >= 1: at the first mirror_light diffuse hits of a path, M shadow rays
 *                more per mirror plane go to the lamps' mirror images, and a path that
 *                goes from such a hit straight to a planar mirror and then hits a lamp
 *                does not add that emission again (with mis: adds its weighted share).
 *                0: off.
 *
 * One sample of eq. 1 along a path x_1, x_2, ...: the throughput T (product of
 * f cos / pdf over the bounces so far, divided by alpha at each roulette survival)
 * multiplies each light contribution. At a diffuse surface the next direction is drawn
 * from the cosine-weighted hemisphere (diffuse.h); at a mirror it is the mirror
 * direction, weighted by the mirror's colour; at glass it is reflection with
 * probability R and refraction with probability 1 - R, so the weight R / R (or
 * (1-R)/(1-R)) is 1: one branch per path, unbiased because the branch probabilities
 * equal the Fresnel weights. The report (and Whitted, chapter 1) traces both branches,
 * weighted R and 1 - R: less noise per path, but a path that meets glass k times
 * becomes a tree of up to 2^k rays (the room's glass sphere alone gives 2 per crossing
 * and more inside it), spending most of its rays on branches of small weight; splitting
 * by R keeps one ray per interface and spends the samples on more paths instead.
 * An emitter reflects nothing and ends the path.
 */
#ifndef PATH_H
#define PATH_H

#include "render.h"
#if CHAPTER >= 4
#include "fresnel.h"
#endif

/* Fields in the order the chapters add them; zero (or omitted in an initialiser) is
 * each option's plain setting: no shadow rays, Schlick, no roulette. */
typedef struct {
    int max_depth;
#if CHAPTER >= 3
    int shadow_rays;
#endif
#if CHAPTER >= 4
    FresnelMode fresnel;
#endif
#if CHAPTER >= 6
    double rr_survival; /* 0 (not set) or 1: no roulette */
    int rr_throughput;  /* k >= 1: bounded-weight roulette from segment k on; 0: alpha */
#endif
#if CHAPTER >= 7
    int mis;          /* 1: light and BRDF sampling combined by the power heuristic */
    int mirror_light; /* K: at the first K diffuse hits, shadow rays to the lamps' images */
    double sphere_guide; /* > 0: bounces aimed at mirror and glass spheres, this strongly */
#endif
} PathSettings;

/* An Estimator (render.h); settings points to a PathSettings. */
Vec3 path_radiance(const Scene *scene, Ray ray, Rng *rng, const void *settings,
                   RayCounts *counts);

/* Glass: pick reflection (probability R) or refraction for ray direction d hitting a
 * surface with normal n facing d's origin (entering: from outside the glass). Returns
 * the new direction. The photon tracer (photon.h) scatters at glass the same way. */
Vec3 glass_scatter(Vec3 d, Vec3 n, int entering, double ior, const PathSettings *settings,
                   Rng *rng);

#if CHAPTER >= 8
/* Chapter 8: the path tracer with the caustics from a photon map (photon.h).
 * Light reaching a diffuse hit x splits by the path it took from the lamp:
 *   L D         straight from the lamp: the shadow rays (M >= 1), or hitting it (M = 0);
 *   L S+ D      through one or more mirror or glass bounces: the caustic map, whose
 *               radiance estimate (photon_estimate.h) is added at every diffuse hit;
 *   L ... D D   via another diffuse surface: the path continues and the same split is
 *               made again at the next diffuse hit.
 * So once a path has made a diffuse bounce, emission it then hits after mirror or glass
 * bounces is no longer added: it is L S+ D light at that diffuse hit, which the map
 * already counted. Emission seen from the camera directly or through mirrors and glass
 * only (L S* E) is still added: the map never sees it. Each light path is thus counted
 * by exactly one of the estimators (tests/test_caustic_path.c). The photon map knows no
 * depth limit (photon.h bounds only its specular chains), so this equals the path
 * tracer's expectation where max_depth is never reached, as with roulette and 64.
 * The lamp's images in planar mirrors (mirror_light) must then be off: the caustic map
 * holds that light too. */
struct PhotonMap;

typedef struct {
    PathSettings path;
    const struct PhotonMap *caustics; /* the caustic map (PHOTON_CAUSTIC) */
    double radius;                    /* of its radiance estimate */
} CausticPathSettings;

/* An Estimator; settings points to a CausticPathSettings. */
Vec3 path_radiance_caustics(const Scene *scene, Ray ray, Rng *rng, const void *settings,
                            RayCounts *counts);
#endif

/* The settings as text for tables and captions, e.g. "M=1 rr=0.25 depth=16 schlick". */
void path_describe(const PathSettings *settings, char *text, int size);

#endif
