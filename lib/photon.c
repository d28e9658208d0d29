/* photon.c (chapter 8): photon emission, tracing and the photon map. See photon.h. */
#include "photon.h"

#include <stdlib.h>
#include <string.h>

#include "area_light.h"
#include "frame.h"
#include "hemisphere.h"

PhotonRay photon_emit(const Scene *scene, int emitted, double u_select, double u1, double u2,
                      double u3, double u4)
{
    LightSample light = area_light_sample(scene, u_select, u1, u2);
    Vec3 t, b;
    vec3_basis(light.normal, &t, &b);
    Vec3 direction = vec3_from_local(hemisphere_sample_cosine(u3, u4), t, b, light.normal);
    PhotonRay photon;
    photon.ray = ray_spawn(light.point, light.normal, direction, vec3_max_abs(light.point));
    /* Phi / N for this light's share: pi A Le(y) / N (photon.h). */
    photon.power = vec3_scale(light.emission, PI * scene->light_area / emitted);
    return photon;
}

int photon_trace(const Scene *scene, PhotonRay photon, PhotonPaths paths, FresnelMode fresnel,
                 Rng *rng, Photon *stored, RayCounts *counts)
{
    Ray ray = photon.ray;
    Vec3 power = photon.power;
    PathSettings glass = {.fresnel = fresnel};
    int planar_mirror_first = 0;
    for (int bounce = 0; bounce <= PHOTON_MAX_BOUNCES; bounce++) {
        Vertex x;
        counts->bounce++;
        if (!path_vertex(scene, ray, &x) || x.material->kind == MATERIAL_LIGHT)
            return 0; /* gone, or at an emitter, which reflects nothing */
        if (material_is_diffuse(x.material)) {
            int specular_before = bounce > 0;
            if (specular_before != (paths != PHOTON_DIRECT) ||
                (paths == PHOTON_SPLIT && bounce == 1 && planar_mirror_first))
                return 0;
            *stored = (Photon){x.hit.point, x.wo, x.normal, power};
            return 1;
        }
        if (bounce == 0)
            planar_mirror_first = x.material->kind == MATERIAL_MIRROR && x.hit.triangle >= 0;
        Vec3 direction;
        power = vec3_mul(power, path_specular(&x, ray.dir, &glass, rng, &direction));
        ray = ray_spawn(x.hit.point, x.normal, direction, x.hit.scale);
    }
    return 0;
}

int photon_shoot(const Scene *scene, const PhotonMapSettings *settings, int k, Photon *stored,
                 RayCounts *counts)
{
    Rng rng = rng_for_sample(settings->seed, (uint64_t)k, 0);
    double u[5];
    for (int i = 0; i < 5; i++)
        u[i] = rng_uniform(&rng);
    PhotonRay ray = photon_emit(scene, settings->emitted, u[0], u[1], u[2], u[3], u[4]);
    return photon_trace(scene, ray, settings->paths, settings->fresnel, &rng, stored, counts);
}

int photon_map_build(PhotonMap *map, const Photon *photons, int count, int emitted,
                     double radius)
{
    memset(map, 0, sizeof *map);
    map->emitted = emitted;
    size_t size = (size_t)(count > 0 ? count : 1);
    Vec3 *positions = malloc(size * sizeof *positions);
    map->photons = malloc(size * sizeof *map->photons);
    int ok = positions && map->photons;
    for (int i = 0; ok && i < count; i++) {
        positions[i] = photons[i].position;
        map->photons[i] = photons[i];
    }
    ok = ok && point_grid_build(&map->grid, positions, count, radius) == 0;
    if (ok)
        map->count = count;
    free(positions);
    if (!ok)
        photon_map_free(map);
    return ok ? 0 : -1;
}

void photon_map_free(PhotonMap *map)
{
    free(map->photons);
    point_grid_free(&map->grid);
    map->photons = NULL;
    map->count = 0;
}
