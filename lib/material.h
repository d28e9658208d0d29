/* material.h (chapter 1): what a surface does with light, as the scene file declares it:
 * plain data; each kind's physics is in a file of its own (mirror.h, snell.h, ...). */
#ifndef MATERIAL_H
#define MATERIAL_H

#include "vec.h"

#define MATERIAL_NAME_MAX 64

typedef enum {
    MATERIAL_LAMBERT,
    MATERIAL_MIRROR,
    MATERIAL_GLASS,
    MATERIAL_LIGHT,
#if CHAPTER >= 5
    MATERIAL_OREN_NAYAR,
#endif
} MaterialKind;

typedef struct {
    char name[MATERIAL_NAME_MAX];
    MaterialKind kind;
    Vec3 reflectance; /* rho of a diffuse surface (BRDF rho/pi), or the mirror's colour */
    Vec3 emission;    /* emitted radiance Le, from the front side only */
    double ior;       /* glass: index of refraction; the outside medium has index 1 */
#if CHAPTER >= 5
    double sigma; /* Oren-Nayar roughness: std. dev. of facet slope, radians */
#endif
} Material;

/* The surfaces that scatter diffusely, light arriving from every direction. */
static inline int material_is_diffuse(const Material *m)
{
#if CHAPTER >= 5
    return m->kind == MATERIAL_LAMBERT || m->kind == MATERIAL_OREN_NAYAR;
#else
    return m->kind == MATERIAL_LAMBERT;
#endif
}
#if CHAPTER >= 3

/* Whether it is an area light (area_light.h). */
static inline int material_emits(const Material *m)
{
    return m->emission.x > 0.0 || m->emission.y > 0.0 || m->emission.z > 0.0;
}
#endif

#endif
