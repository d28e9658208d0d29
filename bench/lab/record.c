/* record.c (bench, chapter 8): the wrappers that record a path. See record.h.
 *
 * Only the estimator's own calls are noted: a wrapped function called inside another
 * (direct_light's light samples, the photon estimate's probes) is noted as part of the
 * outer one or not at all, by rules that depend only on which wrapped function is
 * outermost, never on whether the compiler inlined a call within one file. A mirror
 * bounce has no call to wrap (path_specular returns the mirror's colour): it is noted
 * when the ray after a mirror vertex is.
 */
#include "record.h"

#include "area_light.h"
#include "diffuse.h"
#include "direct_light.h"
#include "glass.h"
#include "mirror_light.h"
#include "photon_estimate.h"
#include "roulette.h"
#include "schlick.h"
#include "sphere_guide.h"

/* The outermost wrapped function running: the estimator itself (OUTSIDE), the direct
 * light of eq. 21 (chapters 3-6) or of direct_light.h (7-8), a photon estimate, or any
 * other. */
typedef enum {
    OUTSIDE,
    IN_AREA_DIRECT,
    IN_DIRECT,
    IN_PHOTONS,
    IN_OTHER
} Context;

typedef struct {
    Json *json;
    const Scene *scene;
    const PathSettings *path;
    int on, tree;
    Context context;
    int events;        /* written so far */
    Vec3 throughput;   /* the estimator's: the bounces' weights and roulette's division */
    Vec3 accounted;    /* the radiance the notes added, in the estimator's order */
    int material;      /* the last vertex's material, or -1 (none, or a miss) */
    int front;         /* the last vertex was hit on its front side */
    int bounced;       /* a bounce was noted since the last vertex */
    double mis_weight; /* noted since the last vertex, or NAN */
} Recorder;

/* The one recording: the wrappers have no other way to find it. */
static Recorder recorder;

static Context enter(Context inside)
{
    Context outer = recorder.context;
    if (outer == OUTSIDE)
        recorder.context = inside;
    return outer;
}

static void leave(Context outer) { recorder.context = outer; }

static void event(const char *name)
{
    json_text(recorder.json, "%s{\"e\":\"%s\"", recorder.events++ ? "," : "", name);
}

static void vec3_field(const char *name, Vec3 v)
{
    json_text(recorder.json, ",\"%s\":", name);
    json_vec3(recorder.json, v);
}

static void number_field(const char *name, double value)
{
    json_text(recorder.json, ",\"%s\":", name);
    json_number(recorder.json, value);
}

static void end_event(void) { json_text(recorder.json, "}"); }

/* A bounce: its direction, density (NAN: a choice of none or of a discrete branch),
 * weight, and the throughput after it. */
static void note_bounce(const char *kind, Vec3 direction, double pdf, Vec3 weight)
{
    recorder.throughput = vec3_mul(recorder.throughput, weight);
    recorder.bounced = 1;
    event("bounce");
    json_text(recorder.json, ",\"kind\":\"%s\"", kind);
    vec3_field("d", direction);
    number_field("pdf", pdf);
    vec3_field("weight", weight);
    vec3_field("throughput", recorder.throughput);
    end_event();
}

/* A ray the estimator traced: a new vertex, or the end of the path. */
static void note_ray(Ray ray, const Hit *hit)
{
    if (!recorder.tree && recorder.material >= 0 && !recorder.bounced) {
        const Material *m = &recorder.scene->materials[recorder.material];
        if (m->kind == MATERIAL_MIRROR)
            note_bounce("mirror", ray.dir, NAN, m->reflectance);
    }
    event("ray");
    vec3_field("o", ray.origin);
    vec3_field("d", ray.dir);
    if (hit) {
        recorder.material = hit->material;
        recorder.front = vec3_dot(ray.dir, hit->normal) < 0.0;
        json_text(recorder.json, ",\"hit\":{\"m\":%d,\"front\":%d", hit->material,
                  recorder.front);
        number_field("t", hit->t);
        vec3_field("p", hit->point);
        vec3_field("n", hit->normal);
        json_text(recorder.json, "}");
    } else {
        recorder.material = -1;
        json_text(recorder.json, ",\"hit\":null");
    }
    end_event();
    recorder.bounced = 0;
    recorder.mis_weight = NAN;
}

/* Light the estimator added at this vertex: `value` times the throughput. */
static void note_added(const char *name, Vec3 value)
{
    Vec3 added = vec3_mul(recorder.throughput, value);
    recorder.accounted = vec3_add(recorder.accounted, added);
    event(name);
    vec3_field("value", value);
    vec3_field("added", added);
    end_event();
}

int __real_scene_intersect(const Scene *scene, Ray ray, double tmax, Hit *hit);
int __wrap_scene_intersect(const Scene *scene, Ray ray, double tmax, Hit *hit)
{
    if (!recorder.on)
        return __real_scene_intersect(scene, ray, tmax, hit);
    Context outer = enter(IN_OTHER);
    int found = __real_scene_intersect(scene, ray, tmax, hit);
    leave(outer);
    if (outer == OUTSIDE) {
        note_ray(ray, found ? hit : NULL);
    } else if (outer == IN_DIRECT) { /* a light sample's way to a mirror */
        event("segment");
        vec3_field("o", ray.origin);
        vec3_field("d", ray.dir);
        number_field("t", found ? hit->t : tmax);
        end_event();
    }
    return found;
}

int __real_scene_occluded(const Scene *scene, Vec3 from, Vec3 from_normal, Vec3 to,
                          Vec3 to_normal);
int __wrap_scene_occluded(const Scene *scene, Vec3 from, Vec3 from_normal, Vec3 to,
                          Vec3 to_normal)
{
    if (!recorder.on)
        return __real_scene_occluded(scene, from, from_normal, to, to_normal);
    Context outer = enter(IN_OTHER);
    int blocked = __real_scene_occluded(scene, from, from_normal, to, to_normal);
    leave(outer);
    if (outer == OUTSIDE || outer == IN_AREA_DIRECT || outer == IN_DIRECT) {
        event("shadow");
        vec3_field("from", from);
        vec3_field("to", to);
        json_text(recorder.json, ",\"blocked\":%d", blocked);
        end_event();
    }
    return blocked;
}

/* A light sample of direct_light: towards a lamp, or its image in a mirror. */
static void note_light_sample(const char *via, ShadowRay sample)
{
    event("light");
    json_text(recorder.json, ",\"via\":\"%s\"", via);
    vec3_field("wi", sample.wi);
    number_field("pdf", sample.pdf);
    vec3_field("value", sample.value);
    end_event();
}

ShadowRay __real_area_light_shadow_ray(const Scene *scene, Vec3 x, Vec3 n, Vec3 wo,
                                       const Material *m, Rng *rng, RayCounts *counts);
ShadowRay __wrap_area_light_shadow_ray(const Scene *scene, Vec3 x, Vec3 n, Vec3 wo,
                                       const Material *m, Rng *rng, RayCounts *counts)
{
    if (!recorder.on)
        return __real_area_light_shadow_ray(scene, x, n, wo, m, rng, counts);
    Context outer = enter(IN_OTHER);
    ShadowRay sample = __real_area_light_shadow_ray(scene, x, n, wo, m, rng, counts);
    leave(outer);
    if (outer == IN_DIRECT)
        note_light_sample("lamp", sample);
    return sample;
}

ShadowRay __real_mirror_light_shadow_ray(const Scene *scene, const MirrorPlane *plane, Vec3 x,
                                         Vec3 n, Vec3 wo, const Material *m, Rng *rng,
                                         RayCounts *counts);
ShadowRay __wrap_mirror_light_shadow_ray(const Scene *scene, const MirrorPlane *plane, Vec3 x,
                                         Vec3 n, Vec3 wo, const Material *m, Rng *rng,
                                         RayCounts *counts)
{
    if (!recorder.on)
        return __real_mirror_light_shadow_ray(scene, plane, x, n, wo, m, rng, counts);
    Context outer = enter(IN_OTHER);
    ShadowRay sample = __real_mirror_light_shadow_ray(scene, plane, x, n, wo, m, rng, counts);
    leave(outer);
    if (outer == IN_DIRECT)
        note_light_sample("mirror", sample);
    return sample;
}

Vec3 __real_area_light_direct(const Scene *scene, Vec3 x, Vec3 n, Vec3 wo, const Material *m,
                              int shadow_rays, Rng *rng, RayCounts *counts);
Vec3 __wrap_area_light_direct(const Scene *scene, Vec3 x, Vec3 n, Vec3 wo, const Material *m,
                              int shadow_rays, Rng *rng, RayCounts *counts)
{
    if (!recorder.on)
        return __real_area_light_direct(scene, x, n, wo, m, shadow_rays, rng, counts);
    Context outer = enter(IN_AREA_DIRECT);
    Vec3 direct = __real_area_light_direct(scene, x, n, wo, m, shadow_rays, rng, counts);
    leave(outer);
    if (outer == OUTSIDE)
        note_added("direct", direct);
    return direct;
}

Vec3 __real_direct_light(const Scene *scene, const Vertex *x, int images,
                         const PathSettings *settings, Rng *rng, RayCounts *counts);
Vec3 __wrap_direct_light(const Scene *scene, const Vertex *x, int images,
                         const PathSettings *settings, Rng *rng, RayCounts *counts)
{
    if (!recorder.on)
        return __real_direct_light(scene, x, images, settings, rng, counts);
    Context outer = enter(IN_DIRECT);
    Vec3 direct = __real_direct_light(scene, x, images, settings, rng, counts);
    leave(outer);
    if (outer == OUTSIDE)
        note_added("direct", direct);
    return direct;
}

double __real_direct_light_hit_weight(const Scene *scene, const PathSettings *settings,
                                      double bsdf_pdf, double distance, double cos_beta);
double __wrap_direct_light_hit_weight(const Scene *scene, const PathSettings *settings,
                                      double bsdf_pdf, double distance, double cos_beta)
{
    if (!recorder.on)
        return __real_direct_light_hit_weight(scene, settings, bsdf_pdf, distance, cos_beta);
    Context outer = enter(IN_OTHER);
    double weight =
        __real_direct_light_hit_weight(scene, settings, bsdf_pdf, distance, cos_beta);
    leave(outer);
    if (outer == OUTSIDE) {
        recorder.mis_weight = weight;
        event("mis");
        number_field("weight", weight);
        number_field("bsdf_pdf", bsdf_pdf);
        end_event();
    }
    return weight;
}

Vec3 __real_diffuse_sample(const Material *m, Vec3 n, Vec3 wo, double u1, double u2, Vec3 *wi);
Vec3 __wrap_diffuse_sample(const Material *m, Vec3 n, Vec3 wo, double u1, double u2, Vec3 *wi)
{
    if (!recorder.on)
        return __real_diffuse_sample(m, n, wo, u1, u2, wi);
    Context outer = enter(IN_OTHER);
    Vec3 weight = __real_diffuse_sample(m, n, wo, u1, u2, wi);
    leave(outer);
    if (outer == OUTSIDE)
        note_bounce("diffuse", *wi, diffuse_pdf(n, *wi), weight);
    return weight;
}

Vec3 __real_sphere_guide_bounce(const Scene *scene, const Vertex *x, double strength, Rng *rng,
                                Vec3 *direction, double *pdf);
Vec3 __wrap_sphere_guide_bounce(const Scene *scene, const Vertex *x, double strength, Rng *rng,
                                Vec3 *direction, double *pdf)
{
    if (!recorder.on)
        return __real_sphere_guide_bounce(scene, x, strength, rng, direction, pdf);
    Context outer = enter(IN_OTHER);
    Vec3 weight = __real_sphere_guide_bounce(scene, x, strength, rng, direction, pdf);
    leave(outer);
    if (outer == OUTSIDE)
        note_bounce(strength > 0.0 ? "guided" : "diffuse", *direction, *pdf, weight);
    return weight;
}

Vec3 __real_glass_scatter(Vec3 d, Vec3 n, int entering, double ior,
                          const PathSettings *settings, Rng *rng);
Vec3 __wrap_glass_scatter(Vec3 d, Vec3 n, int entering, double ior,
                          const PathSettings *settings, Rng *rng)
{
    if (!recorder.on)
        return __real_glass_scatter(d, n, entering, ior, settings, rng);
    Context outer = enter(IN_OTHER);
    Vec3 direction = __real_glass_scatter(d, n, entering, ior, settings, rng);
    leave(outer);
    if (outer == OUTSIDE) {
        /* The probability of the branch taken: R of the path's Fresnel mode (glass.h). */
        double n_i = entering ? 1.0 : ior, n_t = entering ? ior : 1.0, cos_i = -vec3_dot(d, n);
        double r = settings->fresnel == FRESNEL_EXACT ? fresnel_reflectance(cos_i, n_i, n_t)
                                                      : schlick_reflectance(cos_i, n_i, n_t);
        int reflected = vec3_dot(direction, n) > 0.0;
        note_bounce(reflected ? "reflected" : "refracted", direction, reflected ? r : 1.0 - r,
                    vec3(1, 1, 1));
    }
    return direction;
}

int __real_roulette_continues(const PathSettings *settings, int segment, Vec3 *throughput,
                              Rng *rng);
int __wrap_roulette_continues(const PathSettings *settings, int segment, Vec3 *throughput,
                              Rng *rng)
{
    if (!recorder.on)
        return __real_roulette_continues(settings, segment, throughput, rng);
    Vec3 before = *throughput;
    Context outer = enter(IN_OTHER);
    int survives = __real_roulette_continues(settings, segment, throughput, rng);
    leave(outer);
    if (outer == OUTSIDE) {
        /* The survival probability roulette.h defines for these settings. */
        double q = settings->rr_throughput > 0
                       ? (segment >= settings->rr_throughput
                              ? roulette_survival_from_throughput(before)
                              : 1.0)
                       : settings->rr_survival;
        recorder.throughput = *throughput;
        event("roulette");
        number_field("q", q > 0.0 && q < 1.0 ? q : 1.0);
        json_text(recorder.json, ",\"survived\":%d", survives);
        vec3_field("throughput", *throughput);
        end_event();
    }
    return survives;
}

Vec3 __real_photon_estimate_radiance(const PhotonMap *map, double radius, Vec3 x, Vec3 n,
                                     Vec3 wo, const Material *m);
Vec3 __wrap_photon_estimate_radiance(const PhotonMap *map, double radius, Vec3 x, Vec3 n,
                                     Vec3 wo, const Material *m)
{
    if (!recorder.on)
        return __real_photon_estimate_radiance(map, radius, x, n, wo, m);
    Context outer = enter(IN_PHOTONS);
    Vec3 caustic = __real_photon_estimate_radiance(map, radius, x, n, wo, m);
    leave(outer);
    if (outer == OUTSIDE)
        note_added("caustic", caustic);
    return caustic;
}

Vec3 __real_photon_estimate_reachable(const Scene *scene, const PhotonMap *map, double radius,
                                      const Vertex *x);
Vec3 __wrap_photon_estimate_reachable(const Scene *scene, const PhotonMap *map, double radius,
                                      const Vertex *x)
{
    if (!recorder.on)
        return __real_photon_estimate_reachable(scene, map, radius, x);
    Context outer = enter(IN_PHOTONS);
    Vec3 caustic = __real_photon_estimate_reachable(scene, map, radius, x);
    leave(outer);
    if (outer == OUTSIDE)
        note_added("caustic", caustic);
    return caustic;
}

void record_start(Json *json, const Scene *scene, const PathSettings *path, int tree)
{
    recorder = (Recorder){json,          scene,         path, 1, tree, OUTSIDE, 0,
                          vec3(1, 1, 1), vec3(0, 0, 0), -1,   0, 0,    NAN};
    json_text(json, "{\"events\":[");
}

/* Whether a and b agree to rounding, relative to `scale`. */
static int agree(Vec3 a, Vec3 b, Vec3 scale)
{
    const double tolerance = 1e-12;
    return fabs(a.x - b.x) <= tolerance * (fabs(scale.x) + fabs(b.x)) &&
           fabs(a.y - b.y) <= tolerance * (fabs(scale.y) + fabs(b.y)) &&
           fabs(a.z - b.z) <= tolerance * (fabs(scale.z) + fabs(b.z));
}

void record_finish(Vec3 radiance)
{
    Json *json = recorder.json;
    recorder.on = 0;
    Vec3 rest = vec3_sub(radiance, recorder.accounted);
    json_text(json, "],\"radiance\":");
    json_vec3(json, radiance);
    if (recorder.tree) {
        json_text(json, ",\"emission\":null,\"accounted\":null}");
        return;
    }
    const Material *m =
        recorder.material >= 0 ? &recorder.scene->materials[recorder.material] : NULL;
    int emitter = m && recorder.front && material_emits(m);
    /* The weights the estimators give emission hit: all, MIS's share, or none. */
    double weights[3] = {1.0, recorder.mis_weight, 0.0};
    double weight = NAN;
    for (int i = 0; emitter && i < 3 && isnan(weight); i++) {
        Vec3 expected = vec3_mul(recorder.throughput, vec3_scale(m->emission, weights[i]));
        if (!isnan(weights[i]) && agree(rest, expected, recorder.accounted))
            weight = weights[i];
    }
    int accounted = emitter ? !isnan(weight) : agree(rest, vec3(0, 0, 0), recorder.accounted);
    if (emitter) {
        json_text(json, ",\"emission\":{");
        json_text(json, "\"le\":");
        json_vec3(json, m->emission);
        json_text(json, ",\"weight\":");
        json_number(json, weight);
        json_text(json, ",\"added\":");
        json_vec3(json, rest);
        json_text(json, "}");
    } else {
        json_text(json, ",\"emission\":null");
    }
    json_text(json, ",\"accounted\":%s}", accounted ? "true" : "false");
}
