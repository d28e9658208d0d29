/* material.h (chapter 1): what a surface does with light, as the scene file declares it (SPEC §4).
 *
 * Introduced in chapter 1; each kind's physics lives in its own file: lambert.h
 * (eq. 8), oren_nayar.h (eqs. 13-14), mirror.h, snell.h, schlick.h and fresnel.h
 * (eqs. 2-7). A material is plain data so the scene can be a flat array of them.
 */
#ifndef MATERIAL_H
#define MATERIAL_H

#include "vec.h"

#define MATERIAL_NAME_MAX 64

typedef enum {
    MATERIAL_LAMBERT,
    MATERIAL_OREN_NAYAR,
    MATERIAL_MIRROR,
    MATERIAL_GLASS,
    MATERIAL_LIGHT
} MaterialKind;

typedef struct {
    char name[MATERIAL_NAME_MAX];
    MaterialKind kind;
    Vec3 reflectance; /* rho of the diffuse kinds (BRDF rho/pi), or the mirror's colour */
    Vec3 emission;    /* emitted radiance Le, from the front side only */
    double sigma;     /* Oren-Nayar roughness: std. dev. of facet slope, radians */
    double ior;       /* glass: index of refraction; the outside medium has index 1 */
} Material;

/* Lambertian and Oren-Nayar surfaces: those that scatter diffusely, where shadow rays
 * are sent and Russian roulette may end a path. */
static inline int material_is_diffuse(const Material *m)
{
    return m->kind == MATERIAL_LAMBERT || m->kind == MATERIAL_OREN_NAYAR;
}

static inline int material_emits(const Material *m)
{
    return m->emission.x > 0.0 || m->emission.y > 0.0 || m->emission.z > 0.0;
}

#endif
