/* diffuse.c (chapter 2): the diffuse materials in world space: Lambert (chapter 2), then
 * Oren-Nayar (chapter 5). See diffuse.h. */
#include "diffuse.h"

#include "hemisphere.h"
#include "lambert.h"
#if CHAPTER >= 5
#include "oren_nayar.h"
#endif

#if CHAPTER >= 5
/* wi and wo in the local frame (t, b, n). */
static void to_local(Vec3 n, Vec3 wi, Vec3 wo, Vec3 *wi_local, Vec3 *wo_local)
{
    Vec3 t, b;
    vec3_basis(n, &t, &b);
    *wi_local = vec3(vec3_dot(wi, t), vec3_dot(wi, b), vec3_dot(wi, n));
    *wo_local = vec3(vec3_dot(wo, t), vec3_dot(wo, b), vec3_dot(wo, n));
}
#endif

Vec3 diffuse_brdf(const Material *m, Vec3 n, Vec3 wi, Vec3 wo)
{
#if CHAPTER >= 5
    if (m->kind == MATERIAL_OREN_NAYAR) {
        Vec3 wi_local, wo_local;
        to_local(n, wi, wo, &wi_local, &wo_local);
        return oren_nayar_brdf(m->reflectance, m->sigma, wi_local, wo_local);
    }
#else
    (void)n, (void)wi, (void)wo;
#endif
    return lambert_brdf(m->reflectance);
}

Vec3 diffuse_sample(const Material *m, Vec3 n, Vec3 wo, double u1, double u2, Vec3 *wi)
{
    Vec3 t, b;
    vec3_basis(n, &t, &b);
    Vec3 local = hemisphere_sample_cosine(u1, u2);
    *wi = vec3_from_local(local, t, b, n);
#if CHAPTER >= 5
    if (m->kind == MATERIAL_OREN_NAYAR) {
        Vec3 wo_local = vec3(vec3_dot(wo, t), vec3_dot(wo, b), vec3_dot(wo, n));
        return vec3_scale(m->reflectance, oren_nayar_factor(m->sigma, local, wo_local));
    }
#else
    (void)wo;
#endif
    return m->reflectance;
}
#if CHAPTER >= 7

double diffuse_pdf(Vec3 n, Vec3 wi)
{
    return fmax(0.0, vec3_dot(n, wi)) / PI;
}
#endif
