/* photon.c (chapter 8): photon emission, tracing and the photon map. See photon.h. */
#include "photon.h"

#include <pthread.h>
#include <stdlib.h>
#include <string.h>

#include "area_light.h"
#include "hemisphere.h"
#include "mirror.h"

PhotonRay photon_emit(const Scene *scene, int emitted, double u_select, double u1, double u2,
                      double u3, double u4)
{
    LightSample light = area_light_sample(scene, u_select, u1, u2);
    Vec3 t, b;
    vec3_basis(light.normal, &t, &b);
    Vec3 direction = vec3_from_local(hemisphere_sample_cosine(u3, u4), t, b, light.normal);
    PhotonRay photon;
    photon.ray = ray_spawn(light.point, light.normal, direction, scene->scale);
    /* Phi / N for this light's share: pi A Le(y) / N (photon.h). */
    photon.power = vec3_scale(light.emission, PI * scene->light_area / emitted);
    return photon;
}

int photon_trace(const Scene *scene, PhotonRay photon, PhotonPaths paths, FresnelMode fresnel,
                 Rng *rng, Photon *stored, RayCounts *counts)
{
    Ray ray = photon.ray;
    Vec3 power = photon.power;
    for (int bounce = 0; bounce <= PHOTON_MAX_BOUNCES; bounce++) {
        Hit hit;
        counts->bounce++;
        if (!scene_intersect(scene, ray, INFINITY, &hit))
            return 0;
        const Material *m = &scene->materials[hit.material];
        int front = vec3_dot(ray.dir, hit.normal) < 0.0;
        Vec3 n = front ? hit.normal : vec3_neg(hit.normal); /* facing the photon */
        if (material_is_diffuse(m)) {
            int specular_before = bounce > 0;
            if (specular_before != (paths == PHOTON_CAUSTIC))
                return 0;
            *stored = (Photon){hit.point, vec3_neg(ray.dir), n, power};
            return 1;
        }
        Vec3 direction;
        if (m->kind == MATERIAL_LIGHT)
            return 0; /* an emitter reflects nothing */
        if (m->kind == MATERIAL_MIRROR) {
            direction = mirror_reflect(ray.dir, n);
            power = vec3_mul(power, m->reflectance);
        } else {
            PathSettings glass = {.fresnel = fresnel};
            direction = glass_scatter(ray.dir, n, front, m->ior, &glass, rng);
        }
        ray = ray_spawn(hit.point, n, direction, scene->scale);
    }
    return 0;
}

/* One thread's share: photons [first, end), stored into its own growing array. */
typedef struct {
    const Scene *scene;
    const PhotonMapSettings *settings;
    int first, end;
    Photon *photons;
    int count, capacity;
    RayCounts rays;
    int failed;
} Worker;

/* The thread works on its own copy of its Worker and writes it back at the end: the
 * workers sit side by side in one array, and two threads updating counters in one
 * cache line at every ray would pass the line between their cores (false sharing, as
 * in render.c). */
static void trace_into(Worker *w)
{
    const PhotonMapSettings *s = w->settings;
    for (int k = w->first; k < w->end; k++) {
        Rng rng = rng_for_sample(s->seed, (uint64_t)k, 0);
        double u[5];
        for (int i = 0; i < 5; i++)
            u[i] = rng_uniform(&rng);
        PhotonRay ray = photon_emit(w->scene, s->emitted, u[0], u[1], u[2], u[3], u[4]);
        Photon photon;
        if (!photon_trace(w->scene, ray, s->paths, s->fresnel, &rng, &photon, &w->rays))
            continue;
        if (w->count == w->capacity) {
            int capacity = w->capacity ? 2 * w->capacity : 1024;
            Photon *grown = realloc(w->photons, (size_t)capacity * sizeof *grown);
            if (!grown) {
                w->failed = 1;
                return;
            }
            w->photons = grown;
            w->capacity = capacity;
        }
        w->photons[w->count++] = photon;
    }
}

static void *trace_share(void *argument)
{
    Worker *shared = argument, own = *shared;
    trace_into(&own);
    *shared = own;
    return NULL;
}

/* Build the tree over the workers' photons (taken in the order they were shot), and
 * keep the photons in the tree's order, so that those near each other in space are
 * near each other in memory too: a query then reads a few cache lines, not one per
 * photon. */
static int gather(PhotonMap *map, const Worker *workers, int threads)
{
    int count = 0;
    for (int i = 0; i < threads; i++)
        count += workers[i].count;
    size_t size = (size_t)(count > 0 ? count : 1);
    Photon *shot = malloc(size * sizeof *shot);
    Vec3 *positions = malloc(size * sizeof *positions);
    map->photons = malloc(size * sizeof *map->photons);
    int ok = shot && positions && map->photons;
    for (int i = 0, at = 0; ok && i < threads; at += workers[i].count, i++)
        if (workers[i].count > 0)
            memcpy(shot + at, workers[i].photons, (size_t)workers[i].count * sizeof *shot);
    for (int i = 0; ok && i < count; i++)
        positions[i] = shot[i].position;
    ok = ok && kdtree_build(&map->tree, positions, count) == 0;
    if (ok) {
        map->count = count;
        for (int i = 0; i < count; i++)
            map->photons[i] = shot[map->tree.index[i]];
        kdtree_use_tree_order(&map->tree);
    }
    free(shot);
    free(positions);
    return ok ? 0 : -1;
}

int photon_map_build(PhotonMap *map, const Scene *scene, const PhotonMapSettings *settings,
                     RayCounts *counts)
{
    memset(map, 0, sizeof *map);
    map->emitted = settings->emitted;
    int threads = settings->threads > 0 ? settings->threads : render_core_count();
    Worker *workers = calloc((size_t)threads, sizeof *workers);
    pthread_t *ids = calloc((size_t)threads, sizeof *ids);
    int status = workers && ids ? 0 : -1;
    for (int i = 0; status == 0 && i < threads; i++)
        workers[i] = (Worker){scene, settings, (int)((long)settings->emitted * i / threads),
                              (int)((long)settings->emitted * (i + 1) / threads), NULL, 0, 0,
                              {0, 0, 0}, 0};
    int started = 1;
    for (int i = 1; status == 0 && i < threads; i++) {
        if (pthread_create(&ids[i], NULL, trace_share, &workers[i]) != 0)
            break; /* the rest are traced below, on this thread */
        started = i + 1;
    }
    if (status == 0) {
        trace_share(&workers[0]);
        for (int i = 1; i < started; i++)
            pthread_join(ids[i], NULL);
        for (int i = started; i < threads; i++)
            trace_share(&workers[i]);
    }
    for (int i = 0; status == 0 && i < threads; i++) {
        status = workers[i].failed ? -1 : 0;
        ray_counts_add(counts, workers[i].rays);
    }
    if (status == 0)
        status = gather(map, workers, threads);
    for (int i = 0; workers && i < threads; i++)
        free(workers[i].photons);
    free(workers);
    free(ids);
    if (status != 0)
        photon_map_free(map);
    return status;
}

void photon_map_free(PhotonMap *map)
{
    free(map->photons);
    kdtree_free(&map->tree);
    map->photons = NULL;
    map->count = 0;
}
