/* photon.h (chapter 8): photons shot from the area lights, and the caustic photon map
 * (beyond the report: its §5 and reference [9], Jensen 1996).
 *
 * A photon starts at a point uniform over the lights' area A, in a cosine-weighted
 * direction, carrying pi A Le / N of the lights' flux. Mirrors filter its power by
 * their colour; glass reflects or refracts it by R (glass.h), power unchanged. At its
 * first diffuse surface it is stored if a specular bounce came before (the caustic
 * map, L S+ D; PHOTON_SPLIT leaves out one planar mirror alone) and ends there. Photons
 * are independent, so any number of threads can shoot a map's (docs/chapter8.md).
 */
#ifndef PHOTON_H
#define PHOTON_H

#include "point_grid.h"
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
    PHOTON_SPLIT,   /* L S+ D but for L M D, one planar mirror and straight on, which the
                     * mirror's images find (path_caustics.h) */
    PHOTON_DIRECT   /* L D (tests only): at the first surface, if it is diffuse */
} PhotonPaths;

typedef struct {
    Ray ray;
    Vec3 power;
} PhotonRay;

/* Exercise 8.3: a photon leaving the lights, one of `emitted` shot in all, from five
 * uniform numbers: u_select, u1, u2 choose the point (area_light_sample), u3, u4 the
 * direction. The scene must have a light. */
PhotonRay photon_emit(const Scene *scene, int emitted, double u_select, double u1, double u2,
                      double u3, double u4);

/* Trace one photon. Returns 1 and fills *stored if it is stored, else 0. Its rays are
 * counted as bounce rays. */
int photon_trace(const Scene *scene, PhotonRay photon, PhotonPaths paths, FresnelMode fresnel,
                 Rng *rng, Photon *stored, RayCounts *counts);

typedef struct {
    int emitted; /* N, photons shot from the lights */
    PhotonPaths paths;
    FresnelMode fresnel; /* the glass reflectance, as the path tracer's */
    uint64_t seed;       /* photon k uses rng_for_sample(seed, k, 0) */
} PhotonMapSettings;

/* Photon k of a map's N: emitted and traced with its own generator. Returns 1 and the
 * photon in *stored if it ends where the map keeps photons, else 0. */
int photon_shoot(const Scene *scene, const PhotonMapSettings *settings, int k, Photon *stored,
                 RayCounts *counts);

typedef struct PhotonMap {
    Photon *photons;
    int count; /* stored */
    int emitted;
    PointGrid grid; /* over the photons' positions */
} PhotonMap;

/* The map of `count` photons stored out of `emitted` shot: a grid over their positions
 * for estimates of `radius` (photons is copied). Returns 0, or -1 when memory runs out. */
int photon_map_build(PhotonMap *map, const Photon *photons, int count, int emitted,
                     double radius);
void photon_map_free(PhotonMap *map);

#endif
