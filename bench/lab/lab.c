/* lab.c (bench, chapter 8): the lab's renderer. See lab.h.
 *
 * Each chapter's estimator and defaults are the chapter program's (chapters/): its
 * figure's main panel, with the settings its command line takes, named as docs/lab.md
 * lists them.
 */
#include "lab.h"

#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "json.h"
#include "path_caustics.h"
#include "path_direct.h"
#include "path_final.h"
#include "path_roulette.h"
#include "ppm.h"
#include "record.h"
#include "sample_order.h"
#include "scene_file.h"
#include "sphere_guide.h"
#include "whitted_estimator.h"

#define LAB_CHAPTERS 8
#define LAB_SIZE_MAX 4096

/* Chapter 8's photons per pass and first radius for an image 800 pixels wide, as
 * chapters/ch08_photon_map.c sets them: they scale with the image (docs/chapter8.md). */
#define PHOTONS_PER_PIXEL 0.5

typedef struct {
    int chapter;
    int size;   /* image width */
    int spp;    /* samples per pixel (chapter 8: per pass) */
    int passes; /* chapter 8 */
    PixelSampling sampling;
    uint64_t seed;
    PathSettings path; /* depth (Whitted's too), M, Fresnel, roulette, mis, mirrors, guide */
    int mirror_given;  /* chapter 7's mirror light follows the depth unless given */
    double sigma;      /* >= 0: every Oren-Nayar material's roughness; < 0: the scene's */
    int photons;       /* per pass; 0: PHOTONS_PER_PIXEL per pixel */
    double radius;     /* the first radius; 0: PPM_FIRST_RADIUS_AT_800 scaled */
    double alpha;      /* of the radius schedule */
    char program[64];  /* the chapter program, named in messages */
} LabSettings;

struct Lab {
    Scene scene;
    int has_scene;
    char scene_name[256];
    SceneFileInfo file;
    double *scene_sigma; /* the roughness each material had as read */
    MirrorPlanes mirrors;
    LabSettings settings;
    int configured;
    int width, height;
    Estimator estimate;
    const void *estimator_settings;
    WhittedSettings whitted;
    CausticPathSettings caustic; /* chapter 8: the pass's maps and radius */
    PhotonMap caustics, split;
    int pass; /* whose maps are built, or 0 */
    uint64_t pass_image_seed;
    double rays[4];
    Json json;
    char hash[17];
    char error[4400];
};

static int fail(Lab *lab, const char *format, ...)
{
    va_list args;
    va_start(args, format);
    vsnprintf(lab->error, sizeof lab->error, format, args);
    va_end(args);
    return -1;
}

Lab *lab_new(void)
{
    Lab *lab = calloc(1, sizeof *lab);
    if (lab) {
        scene_init(&lab->scene);
        json_init(&lab->json);
    }
    return lab;
}

static void free_maps(Lab *lab)
{
    if (lab->pass > 0) {
        photon_map_free(&lab->caustics);
        photon_map_free(&lab->split);
    }
    lab->pass = 0;
}

static void free_scene(Lab *lab)
{
    free_maps(lab);
    if (lab->has_scene) {
        scene_free(&lab->scene);
        mirror_planes_free(&lab->mirrors);
    }
    free(lab->scene_sigma);
    lab->scene_sigma = NULL;
    lab->has_scene = 0;
    lab->configured = 0;
}

void lab_free(Lab *lab)
{
    if (!lab)
        return;
    free_scene(lab);
    json_free(&lab->json);
    free(lab);
}

const char *lab_error(const Lab *lab) { return lab->error; }

int lab_load_scene(Lab *lab, const char *text, int length, const char *name)
{
    free_scene(lab);
    snprintf(lab->scene_name, sizeof lab->scene_name, "%s", name);
    if (scene_parse(text, (size_t)length, lab->scene_name, &lab->scene, &lab->file, lab->error,
                    sizeof lab->error) != 0)
        return -1;
    lab->has_scene = 1;
    lab->scene_sigma = malloc((size_t)lab->scene.material_count * sizeof *lab->scene_sigma + 1);
    if (!lab->scene_sigma || mirror_light_find_planes(&lab->scene, &lab->mirrors) != 0) {
        mirror_planes_free(&lab->mirrors);
        scene_free(&lab->scene);
        lab->has_scene = 0;
        return fail(lab, "out of memory");
    }
    for (int i = 0; i < lab->scene.material_count; i++)
        lab->scene_sigma[i] = lab->scene.materials[i].sigma;
    snprintf(lab->hash, sizeof lab->hash, "%016llx", (unsigned long long)lab->file.hash);
    return 0;
}

/* ---- settings ------------------------------------------------------------------------ */

/* Chapter `chapter`'s program's defaults (its figure's main panel), 256 pixels wide. */
static LabSettings chapter_defaults(int chapter)
{
    LabSettings s = {.chapter = chapter,
                     .size = 256,
                     .spp = 1,
                     .passes = 1,
                     .sampling = PIXEL_CENTRE,
                     .seed = 1,
                     .sigma = -1.0,
                     .alpha = PPM_ALPHA,
                     .program = "lab"};
    s.path.max_depth = chapter == 1 ? 10 : chapter >= 6 ? 64 : 8;
    static const int spp[LAB_CHAPTERS + 1] = {0, 1, 64, 4, 4, 16, 4, 64, 8};
    static const int shadow_rays[LAB_CHAPTERS + 1] = {0, 0, 0, 1, 1, 4, 1, 1, 1};
    s.spp = spp[chapter];
    s.path.shadow_rays = shadow_rays[chapter];
    if (chapter >= 2)
        s.sampling = PIXEL_SUBPIXELS;
    if (chapter == 6)
        s.path.rr_survival = 0.5;
    if (chapter >= 7) { /* experiment_final_estimator */
        s.path.rr_throughput = 1;
        s.path.sphere_guide = SPHERE_GUIDE_STRENGTH;
        s.sampling = PIXEL_STRATIFIED;
    }
    if (chapter ==
        8) { /* chapters/ch08_photon_map.c: the mirror's images at the first vertex */
        s.path.mirror_light = 1;
        s.mirror_given = 1;
        s.sampling = PIXEL_PROGRESSIVE;
        s.passes = 16;
    }
    return s;
}

static int whole(Lab *lab, const char *key, const char *value, long min, long max, long *out)
{
    char *end;
    long n = strtol(value, &end, 10);
    if (*value == '\0' || *end != '\0' || n < min || n > max)
        return fail(lab, "%s: expected a whole number from %ld to %ld, got '%s'", key, min, max,
                    value);
    *out = n;
    return 0;
}

/* A real number in [min, max], or in (min, max] where `open`. */
static int real(Lab *lab, const char *key, const char *value, double min, double max, int open,
                double *out)
{
    char *end;
    double x = strtod(value, &end);
    if (*value == '\0' || *end != '\0' || !(x >= min && x <= max) || (open && x == min))
        return fail(lab,
                    open ? "%s: expected a number above %g, at most %g, got '%s'"
                         : "%s: expected a number from %g to %g, got '%s'",
                    key, min, max, value);
    *out = x;
    return 0;
}

/* The settings: each key, the chapter that introduces it, and for a number where it goes
 * in LabSettings (an int or a double) and its range (`open`: the lower end excluded). */
typedef enum {
    WHOLE,
    REAL,
    WORD
} Kind;
static const struct {
    const char *key;
    int chapter;
    Kind kind;
    size_t offset;
    double min, max;
    int open;
} KEYS[] = {
    {"size", 1, WHOLE, offsetof(LabSettings, size), 1, LAB_SIZE_MAX, 0},
    {"depth", 1, WHOLE, offsetof(LabSettings, path.max_depth), 1, 1000, 0},
    {"seed", 1, WORD, 0, 0, 0, 0},
    {"program", 1, WORD, 0, 0, 0, 0},
    {"spp", 2, WHOLE, offsetof(LabSettings, spp), 1, 1 << 20, 0},
    {"sampling", 2, WORD, 0, 0, 0, 0},
    {"M", 3, WHOLE, offsetof(LabSettings, path.shadow_rays), 0, 1000, 0},
    {"fresnel", 4, WORD, 0, 0, 0, 0},
    {"sigma", 5, WORD, 0, 0, 0, 0},
    {"rr", 6, WORD, 0, 0, 0, 0},
    {"mis", 7, WHOLE, offsetof(LabSettings, path.mis), 0, 1, 0},
    {"mirror", 7, WHOLE, offsetof(LabSettings, path.mirror_light), 0, 1000, 0},
    {"guide", 7, REAL, offsetof(LabSettings, path.sphere_guide), 0, 1000, 0},
    {"passes", 8, WHOLE, offsetof(LabSettings, passes), 1, 1 << 20, 0},
    {"photons", 8, WHOLE, offsetof(LabSettings, photons), 1, 1 << 26, 0},
    {"radius", 8, REAL, offsetof(LabSettings, radius), 0, 1e50, 1},
    {"alpha", 8, REAL, offsetof(LabSettings, alpha), 0, 1, 1},
};

static int set_sampling(Lab *lab, LabSettings *s, const char *value)
{
    static const struct {
        const char *name;
        PixelSampling sampling;
        int chapter;
    } modes[] = {{"centre", PIXEL_CENTRE, 1},
                 {"subpixels", PIXEL_SUBPIXELS, 2},
                 {"random", PIXEL_RANDOM, 2},
                 {"stratified", PIXEL_STRATIFIED, 7},
                 {"progressive", PIXEL_PROGRESSIVE, 8}};
    for (size_t i = 0; i < sizeof modes / sizeof modes[0]; i++)
        if (strcmp(value, modes[i].name) == 0) {
            if (modes[i].chapter > s->chapter)
                return fail(lab, "sampling: %s is chapter %d's", value, modes[i].chapter);
            s->sampling = modes[i].sampling;
            return 0;
        }
    return fail(lab,
                "sampling: expected centre, subpixels, random, stratified or progressive, "
                "got '%s'",
                value);
}

/* A setting whose value is a word (or a number or a word). */
static int set_word(Lab *lab, LabSettings *s, const char *key, const char *value)
{
    if (strcmp(key, "seed") == 0) {
        char *end;
        s->seed = strtoull(value, &end, 10);
        if (*value < '0' || *value > '9' || *end != '\0')
            return fail(lab, "seed: expected digits, got '%s'", value);
    } else if (strcmp(key, "program") == 0) {
        snprintf(s->program, sizeof s->program, "%s", value);
    } else if (strcmp(key, "sampling") == 0) {
        return set_sampling(lab, s, value);
    } else if (strcmp(key, "fresnel") == 0) {
        if (strcmp(value, "schlick") != 0 && strcmp(value, "exact") != 0)
            return fail(lab, "fresnel: expected schlick or exact, got '%s'", value);
        s->path.fresnel = strcmp(value, "exact") == 0 ? FRESNEL_EXACT : FRESNEL_SCHLICK;
    } else if (strcmp(key, "sigma") == 0) {
        s->sigma = -1.0;
        if (strcmp(value, "scene") != 0)
            return real(lab, key, value, 0.0, 10.0, 0, &s->sigma);
    } else { /* rr */
        s->path.rr_throughput = strcmp(value, "bounded") == 0;
        if (!s->path.rr_throughput)
            return real(lab, key, value, 0.0, 1.0, 1, &s->path.rr_survival);
    }
    return 0;
}

/* One key=value of chapter s->chapter's settings. */
static int set_key(Lab *lab, LabSettings *s, const char *key, const char *value)
{
    size_t i = 0, count = sizeof KEYS / sizeof KEYS[0];
    while (i < count && strcmp(KEYS[i].key, key) != 0)
        i++;
    if (i == count)
        return fail(lab, "unknown setting '%s'", key);
    if (KEYS[i].chapter > s->chapter)
        return fail(lab, "%s: chapter %d introduces it", key, KEYS[i].chapter);
    if (strcmp(key, "mirror") == 0)
        s->mirror_given = 1;
    char *field = (char *)s + KEYS[i].offset;
    if (KEYS[i].kind == REAL)
        return real(lab, key, value, KEYS[i].min, KEYS[i].max, KEYS[i].open, (double *)field);
    if (KEYS[i].kind == WORD)
        return set_word(lab, s, key, value);
    long n;
    if (whole(lab, key, value, (long)KEYS[i].min, (long)KEYS[i].max, &n) != 0)
        return -1;
    *(int *)field = (int)n;
    return 0;
}

/* Parse "key=value" words into *s: chapter=N first, then the others over its defaults. */
static int parse_settings(Lab *lab, const char *text, LabSettings *s)
{
    char words[4096];
    if (snprintf(words, sizeof words, "%s", text) >= (int)sizeof words)
        return fail(lab, "settings: longer than %d characters", (int)sizeof words - 1);
    char *word[64], *value[64];
    int count = 0, chapter = 0;
    for (char *w = strtok(words, " &"); w; w = strtok(NULL, " &")) {
        char *equals = strchr(w, '=');
        if (!equals)
            return fail(lab, "settings: expected key=value, got '%s'", w);
        if (count == 64)
            return fail(lab, "settings: more than 64 of them");
        *equals = '\0';
        word[count] = w;
        value[count++] = equals + 1;
        if (strcmp(w, "chapter") == 0) {
            long n;
            if (whole(lab, "chapter", equals + 1, 1, LAB_CHAPTERS, &n) != 0)
                return -1;
            chapter = (int)n;
        }
    }
    if (chapter == 0)
        return fail(lab, "settings: chapter=N is missing");
    *s = chapter_defaults(chapter);
    for (int i = 0; i < count; i++)
        if (strcmp(word[i], "chapter") != 0 && set_key(lab, s, word[i], value[i]) != 0)
            return -1;
    if (chapter == 7 && !s->mirror_given)
        s->path.mirror_light = s->path.max_depth;
    return 0;
}

/* The scene has what the chapter needs, as the chapter program checks it (experiment.c). */
static int check_scene(Lab *lab, const LabSettings *s)
{
    const Scene *scene = &lab->scene;
    if (s->chapter == 1 && scene->point_light_count == 0)
        return fail(lab, "%s:%d: no point_light: %s needs one", lab->scene_name,
                    lab->file.line_count, s->program);
    if (s->chapter >= 2 && scene->light_count == 0)
        return fail(lab,
                    "%s:%d: no area light (a 'light' material on a triangle, quad, box or "
                    "tetrahedron): %s needs one",
                    lab->scene_name, lab->file.line_count, s->program);
    for (int i = 0; s->chapter < 5 && i < scene->material_count; i++)
        if (scene->materials[i].kind == MATERIAL_OREN_NAYAR)
            return fail(lab, "%s: material '%s' is oren_nayar, which chapter 5 introduces",
                        lab->scene_name, scene->materials[i].name);
    double aspect = scene_file_aspect(&scene->camera), exact_height = s->size / aspect;
    long height = lround(exact_height);
    if (height < 1 || height > LAB_SIZE_MAX || fabs(height - exact_height) > 0.01 * height)
        return fail(lab,
                    "size: %d gives no image whose aspect ratio matches the image plane's "
                    "(%.4g)",
                    s->size, aspect);
    return 0;
}

/* Every Oren-Nayar material's roughness: the scene's, or s->sigma. */
static void apply_sigma(Lab *lab, const LabSettings *s)
{
    for (int i = 0; i < lab->scene.material_count; i++)
        if (lab->scene.materials[i].kind == MATERIAL_OREN_NAYAR)
            lab->scene.materials[i].sigma = s->sigma >= 0.0 ? s->sigma : lab->scene_sigma[i];
}

/* The estimator of chapter s->chapter (its program's), with its settings. */
static void choose_estimator(Lab *lab)
{
    LabSettings *s = &lab->settings;
    s->path.mirrors = s->chapter >= 7 ? &lab->mirrors : NULL;
    lab->estimator_settings = &s->path;
    switch (s->chapter) {
    case 1:
        lab->whitted.max_depth = s->path.max_depth;
        lab->estimate = whitted_estimate;
        lab->estimator_settings = &lab->whitted;
        break;
    case 2:
        lab->estimate = path_radiance;
        break;
    case 3:
    case 4:
    case 5:
        lab->estimate = s->path.shadow_rays > 0 ? path_direct_radiance : path_radiance;
        break;
    case 6:
        lab->estimate = path_roulette_radiance;
        break;
    case 7:
        lab->estimate = path_final_radiance;
        break;
    default:
        lab->estimate = path_caustics_radiance;
        lab->estimator_settings = &lab->caustic;
    }
}

int lab_configure(Lab *lab, const char *text)
{
    lab->configured = 0;
    if (!lab->has_scene)
        return fail(lab, "no scene");
    LabSettings s;
    if (parse_settings(lab, text, &s) != 0 || check_scene(lab, &s) != 0)
        return -1;
    free_maps(lab);
    lab->settings = s;
    apply_sigma(lab, &s);
    lab->width = s.size;
    lab->height = (int)lround(s.size / scene_file_aspect(&lab->scene.camera));
    if (s.chapter == 8) {
        LabSettings *t = &lab->settings;
        if (t->photons == 0)
            t->photons = (int)(PHOTONS_PER_PIXEL * lab->width * lab->height + 0.5);
        if (t->radius == 0.0)
            t->radius =
                ppm_first_radius(&lab->scene, PPM_FIRST_RADIUS_AT_800) * 800.0 / lab->width;
    }
    choose_estimator(lab);
    lab->configured = 1;
    return 0;
}

static const char *sampling_name(PixelSampling sampling)
{
    switch (sampling) {
    case PIXEL_CENTRE:
        return "centre";
    case PIXEL_SUBPIXELS:
        return "subpixels";
    case PIXEL_RANDOM:
        return "random";
    case PIXEL_STRATIFIED:
        return "stratified";
    default:
        return "progressive";
    }
}

const char *lab_settings(Lab *lab)
{
    if (!lab->configured)
        return fail(lab, "not configured"), NULL;
    const LabSettings *s = &lab->settings;
    const PathSettings *p = &s->path;
    Json *json = &lab->json;
    json_clear(json);
    json_text(json, "{\"chapter\":%d,\"size\":%d,\"seed\":\"%llu\",\"depth\":%d", s->chapter,
              s->size, (unsigned long long)s->seed, p->max_depth);
    if (s->chapter >= 2)
        json_text(json, ",\"spp\":%d,\"sampling\":\"%s\"", s->spp, sampling_name(s->sampling));
    if (s->chapter >= 3)
        json_text(json, ",\"M\":%d", p->shadow_rays);
    if (s->chapter >= 4)
        json_text(json, ",\"fresnel\":\"%s\"",
                  p->fresnel == FRESNEL_EXACT ? "exact" : "schlick");
    if (s->chapter >= 5)
        s->sigma >= 0.0 ? json_text(json, ",\"sigma\":%.17g", s->sigma)
                        : json_text(json, ",\"sigma\":\"scene\"");
    if (s->chapter >= 6)
        p->rr_throughput
            ? json_text(json, ",\"rr\":\"bounded\"")
            : json_text(json, ",\"rr\":%.17g", p->rr_survival > 0.0 ? p->rr_survival : 1.0);
    if (s->chapter >= 7)
        json_text(json, ",\"mis\":%d,\"mirror\":%d,\"guide\":%.17g", p->mis, p->mirror_light,
                  p->sphere_guide);
    if (s->chapter >= 8)
        json_text(json, ",\"passes\":%d,\"photons\":%d,\"radius\":%.17g,\"alpha\":%.17g",
                  s->passes, s->photons, s->radius, s->alpha);
    json_text(json, "}");
    return json->failed ? (fail(lab, "out of memory"), NULL) : json->text;
}

int lab_width(const Lab *lab) { return lab->width; }

int lab_height(const Lab *lab) { return lab->height; }

int lab_steps(const Lab *lab)
{
    const LabSettings *s = &lab->settings;
    return s->chapter == 1 ? 1 : s->chapter == 8 ? s->passes : s->spp;
}

/* ---- rendering ----------------------------------------------------------------------- */

/* Pass `pass`'s photon maps, as bench/ppm.c shoots them. */
static int build_pass(Lab *lab, int pass)
{
    if (lab->pass == pass)
        return 0;
    free_maps(lab);
    const LabSettings *s = &lab->settings;
    uint64_t photon_seed;
    ppm_pass_seeds(s->seed, pass, &lab->pass_image_seed, &photon_seed);
    PhotonMapSettings photons = {s->photons, PHOTON_CAUSTIC, s->path.fresnel, photon_seed};
    PhotonMapSettings split = photons;
    split.paths = PHOTON_SPLIT;
    double radius = ppm_radius(s->radius, s->alpha, pass);
    RayCounts rays = {0, 0, 0};
    if (ppm_photon_map(&lab->caustics, &lab->scene, &photons, radius, 1, &rays) != 0)
        return fail(lab, "out of memory for the photon map");
    if (ppm_photon_map(&lab->split, &lab->scene, &split, radius, 1, &rays) != 0) {
        photon_map_free(&lab->caustics);
        return fail(lab, "out of memory for the photon map");
    }
    lab->caustic = (CausticPathSettings){s->path, &lab->split, &lab->caustics, radius};
    lab->pass = pass;
    lab->rays[3] += (double)(rays.camera + rays.bounce + rays.shadow);
    return 0;
}

/* The image settings of the render, or (chapter 8) of sample `sample`'s pass, with the
 * sample's pass in that render in *index (the sample it takes of a pixel: sample_order.h,
 * as the renderer takes it). */
static ImageSettings image_of(const Lab *lab, int sample, int *index)
{
    const LabSettings *s = &lab->settings;
    ImageSettings image = {lab->width, lab->height, s->spp, s->sampling, s->seed};
    *index = sample;
    if (s->chapter == 8 && s->sampling != PIXEL_PROGRESSIVE) { /* ppm.c's independent passes */
        image.seed = lab->pass_image_seed;
        *index = sample % s->spp;
    }
    return image;
}

/* Pass step + 1's pixel (col, row): the mean of its finite samples, rounded to a float
 * as the pass image that ppm.c averages. */
static Vec3 pass_pixel(Lab *lab, const SampleOrder *order, int step, int col, int row,
                       RayCounts *counts)
{
    PixelSum sum = {{0}, {0}, 0};
    uint64_t pixel = (uint64_t)row * (uint64_t)lab->width + (uint64_t)col;
    for (int k = 0; k < lab->settings.spp; k++) {
        int pass;
        ImageSettings image = image_of(lab, step * lab->settings.spp + k, &pass);
        Vec3 radiance = render_sample(&lab->scene, &image, col, row,
                                      sample_order_sample(order, pixel, pass), lab->estimate,
                                      lab->estimator_settings, counts);
        if (vec3_is_finite(radiance))
            pixel_sum_add(&sum, radiance);
    }
    return vec3((float)sum.mean[0], (float)sum.mean[1], (float)sum.mean[2]);
}

int lab_render_band(Lab *lab, int step, int row0, int rows, double *out)
{
    if (!lab->configured)
        return fail(lab, "not configured");
    if (row0 < 0 || rows < 1 || row0 + rows > lab->height || step < 0 || step >= lab_steps(lab))
        return fail(lab, "no step %d of rows %d to %d", step, row0, row0 + rows - 1);
    lab->rays[3] = 0.0;
    int chapter8 = lab->settings.chapter == 8;
    if (chapter8 && build_pass(lab, step + 1) != 0)
        return -1;
    int pass;
    ImageSettings image = image_of(lab, chapter8 ? step * lab->settings.spp : step, &pass);
    SampleOrder order = sample_order_make(&image);
    RayCounts counts = {0, 0, 0};
    for (int r = 0; r < rows; r++)
        for (int col = 0; col < lab->width; col++) {
            uint64_t at = (uint64_t)(row0 + r) * (uint64_t)lab->width + (uint64_t)col;
            Vec3 radiance =
                chapter8 ? pass_pixel(lab, &order, step, col, row0 + r, &counts)
                         : render_sample(&lab->scene, &image, col, row0 + r,
                                         sample_order_sample(&order, at, pass), lab->estimate,
                                         lab->estimator_settings, &counts);
            double *pixel = out + 3 * ((long)r * lab->width + col);
            pixel[0] = radiance.x;
            pixel[1] = radiance.y;
            pixel[2] = radiance.z;
        }
    lab->rays[0] = (double)counts.camera;
    lab->rays[1] = (double)counts.bounce;
    lab->rays[2] = (double)counts.shadow;
    return 0;
}

double lab_rays(const Lab *lab, int kind)
{
    return kind >= 0 && kind < 4 ? lab->rays[kind] : 0.0;
}

/* ---- the inspector and the plan ------------------------------------------------------ */

const char *lab_record(Lab *lab, int col, int row, int first, int count)
{
    if (!lab->configured)
        return fail(lab, "not configured"), NULL;
    if (col < 0 || col >= lab->width || row < 0 || row >= lab->height || first < 0 ||
        count < 1 || count > 1024)
        return fail(lab, "no pixel (%d, %d) or samples %d to %d", col, row, first,
                    first + count - 1),
               NULL;
    const LabSettings *s = &lab->settings;
    Json *json = &lab->json;
    json_clear(json);
    json_text(json, "{\"col\":%d,\"row\":%d,\"paths\":[", col, row);
    for (int k = 0; k < count; k++) {
        int sample = first + k, pass;
        if (s->chapter == 8 && build_pass(lab, sample / s->spp + 1) != 0)
            return NULL;
        ImageSettings image = image_of(lab, sample, &pass);
        SampleOrder order = sample_order_make(&image);
        uint64_t pixel = (uint64_t)row * (uint64_t)lab->width + (uint64_t)col;
        int index = sample_order_sample(&order, pixel, pass);
        RayCounts counts = {0, 0, 0};
        json_text(json, "%s{\"sample\":%d,\"path\":", k ? "," : "", sample);
        record_start(json, &lab->scene, s->chapter == 1 ? NULL : &s->path, s->chapter == 1);
        Vec3 radiance = render_sample(&lab->scene, &image, col, row, index, lab->estimate,
                                      lab->estimator_settings, &counts);
        record_finish(radiance);
        json_text(json, "}");
    }
    json_text(json, "]}");
    if (json->failed)
        return fail(lab, "out of memory recording the paths"), NULL;
    return json->text;
}

static const char *kind_name(MaterialKind kind)
{
    switch (kind) {
    case MATERIAL_LAMBERT:
        return "lambert";
    case MATERIAL_MIRROR:
        return "mirror";
    case MATERIAL_GLASS:
        return "glass";
    case MATERIAL_LIGHT:
        return "light";
    default:
        return "oren_nayar";
    }
}

/* Triangles listed for the plan at most (a bigger scene's plan shows its first ones). */
#define PLAN_TRIANGLES 20000

const char *lab_scene(Lab *lab)
{
    if (!lab->has_scene)
        return fail(lab, "no scene"), NULL;
    const Scene *scene = &lab->scene;
    const Camera *c = &scene->camera;
    Json *json = &lab->json;
    json_clear(json);
    json_text(json, "{\"name\":");
    json_string(json, lab->scene_name);
    json_text(json, ",\"camera\":{\"eye\":");
    json_vec3(json, c->eye);
    json_text(json, ",\"bottom_left\":");
    json_vec3(json, c->bottom_left);
    json_text(json, ",\"right\":");
    json_vec3(json, c->right);
    json_text(json, ",\"up\":");
    json_vec3(json, c->up);
    json_text(json, "},\"materials\":[");
    for (int i = 0; i < scene->material_count; i++) {
        const Material *m = &scene->materials[i];
        json_text(json, "%s{\"name\":", i ? "," : "");
        json_string(json, m->name);
        json_text(json, ",\"kind\":\"%s\",\"reflectance\":", kind_name(m->kind));
        json_vec3(json, m->reflectance);
        json_text(json, ",\"emission\":");
        json_vec3(json, m->emission);
        json_text(json, "}");
    }
    json_text(json, "],\"triangles\":[");
    for (int i = 0; i < scene->triangle_count && i < PLAN_TRIANGLES; i++) {
        const Triangle *t = &scene->triangles[i];
        json_text(json, "%s[", i ? "," : "");
        json_vec3(json, t->v0);
        json_text(json, ",");
        json_vec3(json, vec3_add(t->v0, t->e1));
        json_text(json, ",");
        json_vec3(json, vec3_add(t->v0, t->e2));
        json_text(json, ",%d]", t->material);
    }
    json_text(json, "],\"spheres\":[");
    for (int i = 0; i < scene->sphere_count; i++) {
        const Sphere *sphere = &scene->spheres[i];
        json_text(json, "%s[", i ? "," : "");
        json_vec3(json, sphere->center);
        json_text(json, ",");
        json_number(json, sphere->radius);
        json_text(json, ",%d]", sphere->material);
    }
    json_text(json, "],\"point_lights\":[");
    for (int i = 0; i < scene->point_light_count; i++) {
        json_text(json, "%s", i ? "," : "");
        json_vec3(json, scene->point_lights[i].position);
    }
    json_text(json, "]}");
    if (json->failed)
        return fail(lab, "out of memory"), NULL;
    return json->text;
}

const char *lab_scene_hash(Lab *lab) { return lab->has_scene ? lab->hash : ""; }
