/* glass.c (chapter 2): choosing reflection or refraction at glass. See glass.h. */
#include "glass.h"

#include "mirror.h"
#include "schlick.h"
#include "snell.h"

Vec3 glass_scatter(Vec3 d, Vec3 n, int entering, double ior, const PathSettings *settings,
                   Rng *rng)
{
    double n_i = entering ? 1.0 : ior, n_t = entering ? ior : 1.0;
    double cos_i = -vec3_dot(d, n);
#if CHAPTER >= 4
    double reflectance = settings->fresnel == FRESNEL_EXACT
                             ? fresnel_reflectance(cos_i, n_i, n_t)
                             : schlick_reflectance(cos_i, n_i, n_t);
#else
    double reflectance = schlick_reflectance(cos_i, n_i, n_t);
#endif
    Vec3 refracted;
    if (rng_uniform(rng) >= reflectance && snell_refract(d, n, n_i, n_t, &refracted))
        return refracted;
    return mirror_reflect(d, n);
}
