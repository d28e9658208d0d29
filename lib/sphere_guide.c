/* sphere_guide.c (chapter 7): bounces aimed at the mirror and glass spheres. See
 * sphere_guide.h. */
#include "sphere_guide.h"

#include "diffuse.h"
#include "frame.h"
#include "hemisphere.h"

void sphere_guide_at(const Scene *scene, Vec3 x, Vec3 n, double strength, SphereGuide *guide)
{
    guide->count = 0;
    double total = 0.0;
    for (int i = 0; i < scene->sphere_count && guide->count < SPHERE_GUIDE_MAX; i++) {
        const Sphere *sphere = &scene->spheres[i];
        MaterialKind kind = scene->materials[sphere->material].kind;
        if (kind != MATERIAL_MIRROR && kind != MATERIAL_GLASS)
            continue;
        Vec3 to_centre = vec3_sub(sphere->center, x);
        double distance = vec3_length(to_centre);
        if (distance <= sphere->radius)
            continue; /* x inside the sphere: no cone */
        double sin_max = sphere->radius / distance, cos_max = sqrt(1.0 - sin_max * sin_max);
        Vec3 axis = vec3_scale(to_centre, 1.0 / distance);
        if (vec3_dot(axis, n) <= -sin_max)
            continue; /* the whole cone below the surface */
        double solid_angle = 2.0 * PI * (1.0 - cos_max);
        int k = guide->count++;
        guide->axis[k] = axis;
        guide->cos_max[k] = cos_max;
        guide->share[k] = strength * solid_angle / (2.0 * PI);
        total += guide->share[k];
    }
    double scale = total > 0.5 ? 0.5 / total : 1.0;
    guide->cosine_share = 1.0;
    for (int k = 0; k < guide->count; k++) {
        guide->share[k] *= scale;
        guide->density[k] = guide->share[k] / (2.0 * PI * (1.0 - guide->cos_max[k]));
        guide->cosine_share -= guide->share[k];
    }
}

/* Uniform in the cone around `axis`: cos theta uniform in [cos_max, 1]. */
static Vec3 cone_sample(Vec3 axis, double cos_max, double u1, double u2)
{
    double cos_theta = 1.0 - u1 * (1.0 - cos_max);
    double sin_theta = sqrt(fmax(0.0, 1.0 - cos_theta * cos_theta)), phi = 2.0 * PI * u2;
    Vec3 t, b;
    vec3_basis(axis, &t, &b);
    return vec3_from_local(vec3(sin_theta * cos(phi), sin_theta * sin(phi), cos_theta), t, b,
                           axis);
}

Vec3 sphere_guide_sample(const SphereGuide *guide, Vec3 n, double u_select, double u1,
                         double u2)
{
    double below = guide->cosine_share;
    if (u_select < below || guide->count == 0) {
        Vec3 t, b;
        vec3_basis(n, &t, &b);
        return vec3_from_local(hemisphere_sample_cosine(u1, u2), t, b, n);
    }
    int k = 0;
    for (; k < guide->count - 1; k++) {
        below += guide->share[k];
        if (u_select < below)
            break;
    }
    return cone_sample(guide->axis[k], guide->cos_max[k], u1, u2);
}

double sphere_guide_pdf(const SphereGuide *guide, Vec3 n, Vec3 w)
{
    double pdf = guide->cosine_share * fmax(0.0, vec3_dot(n, w)) / PI;
    for (int k = 0; k < guide->count; k++)
        if (vec3_dot(w, guide->axis[k]) >= guide->cos_max[k])
            pdf += guide->density[k];
    return pdf;
}

Vec3 sphere_guide_bounce(const Scene *scene, const Vertex *x, double strength, Rng *rng,
                         Vec3 *direction, double *pdf)
{
    SphereGuide guide;
    guide.count = 0;
    if (strength > 0.0)
        sphere_guide_at(scene, x->hit.point, x->normal, strength, &guide);
    if (guide.count == 0) {
        Vec3 weight = path_diffuse_bounce(x, rng, direction);
        *pdf = diffuse_pdf(x->normal, *direction);
        return weight;
    }
    double u_select = rng_uniform(rng), u1, u2;
    rng_pair(rng, &u1, &u2);
    *direction = sphere_guide_sample(&guide, x->normal, u_select, u1, u2);
    *pdf = sphere_guide_pdf(&guide, x->normal, *direction);
    double cos_theta = vec3_dot(x->normal, *direction);
    if (cos_theta <= 0.0)
        return vec3(0, 0, 0);
    return vec3_scale(diffuse_brdf(x->material, x->normal, *direction, x->wo),
                      cos_theta / *pdf);
}
