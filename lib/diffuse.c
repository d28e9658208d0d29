/* diffuse.c (chapter 2): the diffuse materials in world space. See diffuse.h. */
#include "diffuse.h"

#include "frame.h"
#include "hemisphere.h"
#include "lambert.h"

Vec3 diffuse_brdf(const Material *m, Vec3 n, Vec3 wi, Vec3 wo)
{
#if CHAPTER >= 5
    if (m->kind == MATERIAL_OREN_NAYAR) {
        Vec3 t, b;
        vec3_basis(n, &t, &b);
        return oren_nayar_brdf(m->reflectance, m->sigma, vec3_to_local(wi, t, b, n),
                               vec3_to_local(wo, t, b, n));
    }
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
    if (m->kind == MATERIAL_OREN_NAYAR)
        return vec3_scale(m->reflectance,
                          oren_nayar_factor(m->sigma, local, vec3_to_local(wo, t, b, n)));
#endif
    return m->reflectance;
}

double diffuse_pdf(Vec3 n, Vec3 wi)
{
    return hemisphere_pdf_cosine(vec3(0, 0, vec3_dot(n, wi)));
}
