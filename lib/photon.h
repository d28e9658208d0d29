/* photon.h (chapter 8): photons shot from the area lights, and the caustic photon map.
 * The report's §5 and its reference [9]: Jensen, "Global illumination using photon
 * maps" (1996).
 *
 * Introduced in chapter 8. The path tracer finds light that reached a diffuse surface
 * through mirrors or glass (paths L S+ D, in Heckbert's notation: light, one or more
 * specular bounces, a diffuse one) only when a path happens to hit the lamp after a
 * specular bounce: rarely, and brightly. Photons go the other way, from the light.
 *
 * Emission. A photon starts at a point y uniform over the lights' total area A
 * (area_light_sample: density 1/A) in a direction w cosine-weighted about the light's
 * front normal (hemisphere.h: density cos(theta)/pi). A light of radiance Le emits the
 * flux Phi = integral over its area and hemisphere of Le cos(theta) = pi Le A, and a
 * photon must carry its share of it: Le(y) cos / (p(y) p(w)) / N = pi A Le(y) / N,
 * i.e. Phi / N each for a single lamp (the cosine cancels: every photon carries the
 * same power).
 *
 * Tracing. At a mirror the photon is reflected and its power filtered by the mirror's
 * colour; at glass it is reflected with probability R and refracted otherwise, with
 * the path tracer's own glass_scatter (path.h): since the probabilities are the Fresnel
 * weights, the power is unchanged. At the first diffuse surface it is stored (position,
 * the direction it came from, the surface's normal on its side, its power) if at least
 * one specular bounce came before, and it ends there: that is the caustic map, L S+ D.
 * A photon whose first surface is diffuse is dropped: that light is direct light, which
 * the shadow rays estimate. A photon that reaches a light, leaves the scene, or makes
 * more than PHOTON_MAX_BOUNCES specular bounces is dropped too.
 *
 * A test-only mode stores the other kind instead: photons whose first surface is
 * diffuse (L D), so that a density estimate of direct light can be checked against a
 * closed form (tests/test_photon_estimate.c).
 */
#ifndef PHOTON_H
#define PHOTON_H

#include "kdtree.h"
#include "path.h"

#define PHOTON_MAX_BOUNCES 64

typedef struct {
    Vec3 position;
    Vec3 incoming; /* unit direction back towards where the photon came from */
    Vec3 normal;   /* the surface's unit normal on the side the photon arrived */
    Vec3 power;    /* flux, watts per channel */
} Photon;

/* Which photons a map stores. */
typedef enum {
    PHOTON_CAUSTIC, /* L S+ D: at the first diffuse surface after a specular bounce */
    PHOTON_DIRECT   /* L D (tests only): at the first surface, if it is diffuse */
} PhotonPaths;

typedef struct {
    Ray ray;
    Vec3 power;
} PhotonRay;

/* A photon leaving the lights, one of `emitted` shot in all, from five uniform numbers:
 * u_select, u1, u2 choose the point (area_light_sample), u3, u4 the direction. The
 * scene must have a light. */
PhotonRay photon_emit(const Scene *scene, int emitted, double u_select, double u1, double u2,
                      double u3, double u4);

/* Trace one photon. Returns 1 and fills *stored if it is stored, else 0. Its rays are
 * counted as bounce rays. */
int photon_trace(const Scene *scene, PhotonRay photon, PhotonPaths paths, FresnelMode fresnel,
                 Rng *rng, Photon *stored, RayCounts *counts);

typedef struct {
    int emitted;         /* N, photons shot from the lights */
    PhotonPaths paths;
    FresnelMode fresnel; /* the glass reflectance, as the path tracer's */
    uint64_t seed;       /* photon k uses rng_for_sample(seed, k, 0) */
    int threads;         /* 0: one per core; the map is the same for any count */
} PhotonMapSettings;

typedef struct PhotonMap {
    Photon *photons; /* in the kd-tree's order (photon.c) */
    int count;       /* stored */
    int emitted;
    KdTree tree;     /* over the photons' positions */
} PhotonMap;

/* Shoot and trace settings->emitted photons, keep those `paths` asks for, and build
 * the kd-tree over them. Rays traced are added to *counts. Returns 0, or -1 when
 * memory runs out (the map is then empty). */
int photon_map_build(PhotonMap *map, const Scene *scene, const PhotonMapSettings *settings,
                     RayCounts *counts);

void photon_map_free(PhotonMap *map);

#endif
