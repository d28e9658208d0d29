/* lab.c (bench, chapter 8): the lab's renderer. See lab.h.
 *
 * Each chapter's estimator and defaults are the chapter program's (chapters/): its
 * figure's main panel, with the settings its command line takes, named as docs/lab.md
 * lists them.
 */
#include "lab.h"

#include <errno.h>
#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "adaptive.h"
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

#define LAB_CHAPTERS 10
#define LAB_SPEED_CHAPTER 9 /* measures speed: no estimator of its own */
#define LAB_SIZE_MAX 4096

/* Settings text and addresses: characters and key=value words at most. The inspector's
 * paths at most; workers at most (the chapter programs' --threads). */
#define LAB_TEXT_MAX 4096
#define LAB_WORDS_MAX 64
#define LAB_PATHS_MAX 64
#define LAB_WORKERS_MAX 1024

/* A scene's text at most: the command line's limit for a scene file (scene_file.h), with
 * its message. */
#define LAB_SCENE_BYTES_MAX ((size_t)64 << 20)
#define LAB_SCENE_BYTES_MAX_TEXT "64 MiB"

/* Chapter 8's photons per pass and first radius for an image 800 pixels wide, as
 * chapters/ch08_photon_map.c sets them: they scale with the image (docs/chapter8.md). */
#define PHOTONS_PER_PIXEL 0.5

/* Chapter 10's rule, as chapters/ch10_adaptive.c sets it: samples per pass where a pixel
 * is above the threshold, at most per pixel, and the target of its figure. */
#define ADAPTIVE_PASS_SAMPLES 8
#define MAX_SAMPLES (1 << 16)
#define ADAPTIVE_TARGET 0.02

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
    double target;   /* chapters 7-10: the image's estimated relative RMSE to stop at; 0: off */
    int max_samples; /* chapter 10: per pixel */
    AdaptiveRule rule; /* chapter 10 */
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
    AdaptivePixel *pixels; /* chapter 10: a band's pixels while it is sampled */
    int *to_add;
    double estimated_error; /* chapter 10: the last plan's, of the image */
    char hash[17];
    const char *prefix; /* of the keys in messages: "" or "b." */
    char words[LAB_TEXT_MAX + 1], raw_words[LAB_TEXT_MAX + 1]; /* split_words' */
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
        lab->prefix = "";
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
    free(lab->pixels);
    free(lab->to_add);
    json_free(&lab->json);
    free(lab);
}

const char *lab_error(const Lab *lab) { return lab->error; }

int lab_load_scene(Lab *lab, const char *text, int length, const char *name)
{
    free_scene(lab);
    snprintf(lab->scene_name, sizeof lab->scene_name, "%s", name);
    if (length < 0 || (size_t)length > LAB_SCENE_BYTES_MAX)
        return fail(lab,
                    "%s:0: larger than " LAB_SCENE_BYTES_MAX_TEXT
                    " (%d bytes), the limit for a scene file",
                    lab->scene_name, length);
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
    static const int spp[LAB_CHAPTERS + 1] = {0, 1, 64, 4, 4, 16, 4, 64, 8, 0, 16};
    static const int shadow_rays[LAB_CHAPTERS + 1] = {0, 0, 0, 1, 1, 4, 1, 1, 1, 0, 1};
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
    if (chapter == 10) { /* chapters/ch10_adaptive.c: exact Fresnel, to its target */
        s.path.fresnel = FRESNEL_EXACT;
        s.sampling = PIXEL_PROGRESSIVE;
        s.target = ADAPTIVE_TARGET;
        s.max_samples = MAX_SAMPLES;
        s.rule = ADAPTIVE_UNBIASED;
    }
    return s;
}

/* A message about setting `key`, named with the prefix of the panel it belongs to
 * ("b." in an address: docs/lab.md). */
static int fail_key(Lab *lab, const char *key, const char *format, ...)
{
    int n = snprintf(lab->error, sizeof lab->error, "%s%s: ", lab->prefix, key);
    if (n < 0 || n >= (int)sizeof lab->error)
        return -1;
    va_list args;
    va_start(args, format);
    vsnprintf(lab->error + n, sizeof lab->error - (size_t)n, format, args);
    va_end(args);
    return -1;
}

/* What a number setting takes: [min, max] (open: (min, max]), whole numbers only or
 * any, and a word it takes instead ("bounded"), or NULL. */
typedef struct {
    double min, max;
    int whole, open;
    const char *word;
} Range;

/* The range in words, as the command line says it (bench/cli.c): "a whole number from
 * 1 to 4096", "a number in (0, 1]", and "or 'WORD'". */
static void describe_range(const Range *range, char *text, size_t size)
{
    int n = range->whole ? snprintf(text, size, "a whole number from %.0f to %.0f", range->min,
                                    range->max)
                         : snprintf(text, size, "a number in %s%g, %g]",
                                    range->open ? "(" : "[", range->min, range->max);
    if (range->word && n >= 0 && (size_t)n < size)
        snprintf(text + n, size - (size_t)n, " or '%s'", range->word);
}

/* A number in its range, the whole text and nothing else, in decimal, judged as the
 * chapter programs judge a flag's value (bench/cli.c), in the same order and words:
 * empty, white space, not a decimal number (hexadecimal, nan, inf, a lone sign), beyond
 * a double's range either way, not whole, out of the range. The browser test compares
 * these messages with the command line's. */
static int number(Lab *lab, const char *key, const char *text, const Range *range, double *out)
{
    char expected[96];
    describe_range(range, expected, sizeof expected);
    char *end;
    errno = 0;
    double value = strtod(text, &end);
    int underflow =
        (errno == ERANGE && fabs(value) <= 1.0) || (value != 0.0 && fabs(value) < DBL_MIN);
    if (*text == '\0')
        return fail_key(lab, key, "expected %s, got an empty word", expected);
    if (strpbrk(text, " \t\n\v\f\r"))
        return fail_key(lab, key, "'%s' has white space in it; expected %s alone", text,
                        expected);
    if (*end != '\0' || strspn(text, "+-0123456789.eE") != strlen(text))
        return fail_key(lab, key,
                        "'%s' is not a decimal number (such as 16, 0.25 or 1e-3); expected %s",
                        text, expected);
    if (underflow)
        return fail_key(lab, key,
                        "'%s' is too small to compute with (below %g, the smallest double "
                        "with all its digits); expected %s",
                        text, DBL_MIN, expected);
    if (errno == ERANGE)
        return fail_key(lab, key, "'%s' is too large for a double (above %g); expected %s",
                        text, DBL_MAX, expected);
    if (range->whole && value != floor(value))
        return fail_key(lab, key, "'%s' is not a whole number; expected %s", text, expected);
    if (!(value >= range->min && value <= range->max) || (range->open && !(value > range->min)))
        return fail_key(lab, key, "expected %s, got '%s'", expected, text);
    *out = value;
    return 0;
}

/* A whole number in [min, max] (a setting's, or the page's: pixel, paths). */
static int whole(Lab *lab, const char *key, const char *text, int min, int max, int *out)
{
    Range range = {min, max, 1, 0, NULL};
    double value;
    if (number(lab, key, text, &range, &value) != 0)
        return -1;
    *out = (int)value;
    return 0;
}

/* One of `count` words, or the command line's message: "expected 'a', 'b' or 'c'". */
static int choice(Lab *lab, const char *key, const char *text, const char *const *words,
                  int count, int *out)
{
    for (int i = 0; i < count; i++)
        if (strcmp(text, words[i]) == 0)
            return *out = i, 0;
    char list[256] = "";
    for (int i = 0, n = 0; i < count && n >= 0 && (size_t)n < sizeof list; i++)
        n += snprintf(list + n, sizeof list - (size_t)n, "%s'%s'",
                      i == 0           ? ""
                      : i == count - 1 ? " or "
                                       : ", ",
                      words[i]);
    return fail_key(lab, key, "expected %s, got '%s'", list, text);
}

/* The settings: each key, the chapter that introduces it, and for a number where it goes
 * in LabSettings (an int or a double) and its range. */
typedef enum {
    NUMBER,
    WORD
} Kind;
static const struct {
    const char *key;
    int chapter;
    Kind kind;
    size_t offset;
    Range range;
} KEYS[] = {
    {"size", 1, NUMBER, offsetof(LabSettings, size), {1, LAB_SIZE_MAX, 1, 0, NULL}},
    {"depth", 1, NUMBER, offsetof(LabSettings, path.max_depth), {1, 1000, 1, 0, NULL}},
    {"seed", 1, WORD, 0, {0, 0, 0, 0, NULL}},
    {"program", 1, WORD, 0, {0, 0, 0, 0, NULL}},
    {"spp", 2, NUMBER, offsetof(LabSettings, spp), {1, 1 << 20, 1, 0, NULL}},
    {"sampling", 2, WORD, 0, {0, 0, 0, 0, NULL}},
    {"M", 3, NUMBER, offsetof(LabSettings, path.shadow_rays), {0, 1000, 1, 0, NULL}},
    {"fresnel", 4, WORD, 0, {0, 0, 0, 0, NULL}},
    {"sigma", 5, NUMBER, offsetof(LabSettings, sigma), {0, 10, 0, 0, "scene"}},
    {"rr", 6, NUMBER, offsetof(LabSettings, path.rr_survival), {0, 1, 0, 1, "bounded"}},
    {"mis", 7, NUMBER, offsetof(LabSettings, path.mis), {0, 1, 1, 0, NULL}},
    {"mirror", 7, NUMBER, offsetof(LabSettings, path.mirror_light), {0, 1000, 1, 0, NULL}},
    {"guide", 7, NUMBER, offsetof(LabSettings, path.sphere_guide), {0, 1000, 0, 0, NULL}},
    {"passes", 8, NUMBER, offsetof(LabSettings, passes), {1, 1 << 20, 1, 0, NULL}},
    {"photons", 8, NUMBER, offsetof(LabSettings, photons), {1, 1 << 26, 1, 0, NULL}},
    {"radius", 8, NUMBER, offsetof(LabSettings, radius), {0, 1e50, 0, 1, NULL}},
    {"alpha", 8, NUMBER, offsetof(LabSettings, alpha), {0, 1, 0, 1, NULL}},
    {"target", 7, NUMBER, offsetof(LabSettings, target), {0, 1, 0, 0, NULL}},
    {"max", 10, NUMBER, offsetof(LabSettings, max_samples), {4, MAX_SAMPLES, 1, 0, NULL}},
    {"rule", 10, WORD, 0, {0, 0, 0, 0, NULL}},
};

/* Chapter 8's photon map is its own: chapter 10 builds on chapter 7's estimator. */
static int key_in_chapter(int key_chapter, int chapter)
{
    return key_chapter <= chapter && (key_chapter != 8 || chapter == 8);
}

static int set_sampling(Lab *lab, LabSettings *s, const char *value)
{
    static const char *const names[] = {"centre", "subpixels", "random", "stratified",
                                        "progressive"};
    static const PixelSampling modes[] = {PIXEL_CENTRE, PIXEL_SUBPIXELS, PIXEL_RANDOM,
                                          PIXEL_STRATIFIED, PIXEL_PROGRESSIVE};
    static const int chapters[] = {1, 2, 2, 7, 8};
    int i;
    if (choice(lab, "sampling", value, names, 5, &i) != 0)
        return -1;
    if (chapters[i] > s->chapter)
        return fail_key(lab, "sampling", "%s is chapter %d's", value, chapters[i]);
    if (s->chapter == 10 && modes[i] != PIXEL_PROGRESSIVE)
        return fail_key(lab, "sampling", "chapter 10's passes take progressive samples");
    s->sampling = modes[i];
    return 0;
}

/* A setting whose value is a word. */
static int set_word(Lab *lab, LabSettings *s, const char *key, const char *value)
{
    if (strcmp(key, "seed") == 0) {
        char *end;
        errno = 0;
        s->seed = strtoull(value, &end, 10);
        if (*value < '0' || *value > '9' || *end != '\0' || errno != 0)
            return fail_key(lab, key, "expected a whole number from 0 to 2^64-1, got '%s'",
                            value);
    } else if (strcmp(key, "program") == 0) {
        snprintf(s->program, sizeof s->program, "%s", value);
    } else if (strcmp(key, "sampling") == 0) {
        return set_sampling(lab, s, value);
    } else if (strcmp(key, "rule") == 0) {
        static const char *const rules[] = {"biased", "unbiased"};
        int unbiased;
        if (choice(lab, key, value, rules, 2, &unbiased) != 0)
            return -1;
        s->rule = unbiased ? ADAPTIVE_UNBIASED : ADAPTIVE_BIASED;
    } else { /* fresnel */
        static const char *const modes[] = {"schlick", "exact"};
        int exact;
        if (choice(lab, key, value, modes, 2, &exact) != 0)
            return -1;
        s->path.fresnel = exact ? FRESNEL_EXACT : FRESNEL_SCHLICK;
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
        return fail(lab, "unknown setting '%s%s'", lab->prefix, key);
    if (KEYS[i].chapter > s->chapter)
        return fail_key(lab, key, "chapter %d introduces it", KEYS[i].chapter);
    if (!key_in_chapter(KEYS[i].chapter, s->chapter))
        return fail_key(lab, key, "chapter %d's only", KEYS[i].chapter);
    if (strcmp(key, "mirror") == 0)
        s->mirror_given = 1;
    if (KEYS[i].kind == WORD)
        return set_word(lab, s, key, value);
    const Range *range = &KEYS[i].range;
    int word = range->word && strcmp(value, range->word) == 0;
    if (strcmp(key, "rr") == 0)
        s->path.rr_throughput = word;
    if (strcmp(key, "sigma") == 0 && word)
        s->sigma = -1.0;
    double x;
    if (word)
        return 0;
    if (number(lab, key, value, range, &x) != 0)
        return -1;
    char *field = (char *)s + KEYS[i].offset;
    if (range->whole)
        *(int *)field = (int)x;
    else
        *(double *)field = x;
    return 0;
}

/* ---- words: settings text and the page's address ------------------------------------ */

/* key=value words, each value decoded from its %XX escapes: one value per key, which
 * cannot carry a separator into the next. */
typedef struct {
    const char *key[LAB_WORDS_MAX], *value[LAB_WORDS_MAX];
    int count;
} Words;

static int hex_digit(char c)
{
    return c >= '0' && c <= '9'   ? c - '0'
           : c >= 'a' && c <= 'f' ? c - 'a' + 10
           : c >= 'A' && c <= 'F' ? c - 'A' + 10
                                  : -1;
}

/* Decode text's %XX escapes in place; -1 where a '%' is not followed by two hexadecimal
 * digits, or decodes to a NUL byte (the message quotes `word`, as given). */
static int decode(Lab *lab, char *text, const char *word)
{
    for (const char *p = text; (p = strchr(p, '%')); p += 3)
        if (hex_digit(p[1]) < 0 || hex_digit(p[2]) < 0 || (p[1] == '0' && p[2] == '0'))
            return fail(lab,
                        "settings: '%s' has a malformed escape: '%%' must be followed by two "
                        "hexadecimal digits, not 00",
                        word);
    char *out = text;
    for (const char *p = text; *p; out++)
        if (*p == '%') {
            *out = (char)(16 * hex_digit(p[1]) + hex_digit(p[2]));
            p += 3;
        } else {
            *out = *p++;
        }
    *out = '\0';
    return 0;
}

/* Split text at any of `separators` into key=value words (empty words skipped), each
 * key and value decoded; a key given twice is an error. The words point into
 * lab->words. */
static int split_words(Lab *lab, const char *text, const char *separators, Words *w)
{
    w->count = 0;
    if (strlen(text) > LAB_TEXT_MAX)
        return fail(lab, "settings: longer than %d characters", LAB_TEXT_MAX);
    char *raw = lab->raw_words, *words = lab->words;
    memcpy(raw, text, strlen(text) + 1);
    memcpy(words, text, strlen(text) + 1);
    for (size_t at = 0, length, end = strlen(raw); at < end; at += length + 1) {
        length = strcspn(raw + at, separators);
        if (length == 0)
            continue;
        raw[at + length] = words[at + length] = '\0';
        char *equals = strchr(words + at, '=');
        if (!equals)
            return fail(lab, "settings: expected key=value, got '%s'", raw + at);
        if (w->count == LAB_WORDS_MAX)
            return fail(lab, "settings: more than %d of them", LAB_WORDS_MAX);
        *equals = '\0';
        if (decode(lab, words + at, raw + at) != 0 || decode(lab, equals + 1, raw + at) != 0)
            return -1;
        for (int k = 0; k < w->count; k++)
            if (strcmp(w->key[k], words + at) == 0)
                return fail(lab, "settings: '%s' is given twice", words + at);
        w->key[w->count] = words + at;
        w->value[w->count++] = equals + 1;
    }
    return 0;
}

/* The value of `key` among the words, or NULL. */
static const char *word_value(const Words *w, const char *key)
{
    for (int i = 0; i < w->count; i++)
        if (strcmp(w->key[i], key) == 0)
            return w->value[i];
    return NULL;
}

/* A chapter the lab renders, 1 to LAB_CHAPTERS but the one that measures speed. */
static int chapter_number(Lab *lab, const char *text, int *chapter)
{
    if (whole(lab, "chapter", text, 1, LAB_CHAPTERS, chapter) != 0)
        return -1;
    if (*chapter == LAB_SPEED_CHAPTER)
        return fail_key(lab, "chapter",
                        "chapter %d measures speed and has no estimator of its own (every "
                        "chapter here renders with its four-wide tree)",
                        LAB_SPEED_CHAPTER);
    return 0;
}

/* The words into *s: chapter first (`chapter`, when the words have none; 0: required),
 * then the others over its defaults. */
static int parse_settings(Lab *lab, const Words *w, int chapter, LabSettings *s)
{
    const char *given = word_value(w, "chapter");
    if (given && chapter_number(lab, given, &chapter) != 0)
        return -1;
    if (chapter == 0)
        return fail(lab, "settings: chapter=N is missing");
    *s = chapter_defaults(chapter);
    for (int i = 0; i < w->count; i++)
        if (strcmp(w->key[i], "chapter") != 0 && set_key(lab, s, w->key[i], w->value[i]) != 0)
            return -1;
    if ((chapter == 7 || chapter == 10) && !s->mirror_given)
        s->path.mirror_light = s->path.max_depth;
    if (chapter == 10 && (s->spp + 3) / 4 * 4 > s->max_samples)
        return fail_key(lab, "spp", "the minimum samples per pixel, %d, is above max, %d",
                        s->spp, s->max_samples);
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
    case 10:
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
    Words words;
    lab->prefix = "";
    if (split_words(lab, text, " &", &words) != 0 || parse_settings(lab, &words, 0, &s) != 0 ||
        check_scene(lab, &s) != 0)
        return -1;
    free_maps(lab);
    free(lab->pixels);
    free(lab->to_add);
    lab->pixels = NULL;
    lab->to_add = NULL;
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
        json_text(json, ",\"mis\":%d,\"mirror\":%d,\"guide\":%.17g,\"target\":%.17g", p->mis,
                  p->mirror_light, p->sphere_guide, s->target);
    if (s->chapter == 10)
        json_text(json, ",\"max\":%d,\"rule\":\"%s\"", s->max_samples,
                  s->rule == ADAPTIVE_UNBIASED ? "unbiased" : "biased");
    if (s->chapter == 8)
        json_text(json, ",\"passes\":%d,\"photons\":%d,\"radius\":%.17g,\"alpha\":%.17g",
                  s->passes, s->photons, s->radius, s->alpha);
    json_text(json, "}");
    return json->failed ? (fail(lab, "out of memory"), NULL) : json->text;
}

static int scene_has_glass(const Scene *scene)
{
    for (int i = 0; i < scene->material_count; i++)
        if (scene->materials[i].kind == MATERIAL_GLASS)
            return 1;
    return 0;
}

const char *lab_biases(Lab *lab)
{
    if (!lab->configured)
        return fail(lab, "not configured"), NULL;
    const LabSettings *s = &lab->settings;
    Json *json = &lab->json;
    json_clear(json);
    json_text(json, "[");
    if (s->chapter == 1) {
        json_string(json, "the light diffuse surfaces send each other (Whitted's ray tree "
                          "follows mirrors and glass only)");
    } else {
        json_text(json, "\"the light of paths longer than %d segments (each is cut there)\"",
                  s->path.max_depth);
        if (s->path.fresnel == FRESNEL_SCHLICK && scene_has_glass(&lab->scene)) {
            json_text(json, ",");
            json_string(json, "the difference between Schlick's reflectance of the glass and "
                              "the exact Fresnel one");
        }
        if (s->chapter == 10 && s->rule == ADAPTIVE_BIASED) {
            json_text(json, ",");
            json_string(json, "the biased rule's: a pixel whose samples happen to look "
                              "converged stops early, and dark pixels stay darker");
        }
        if (s->chapter == 8) {
            json_text(json, ",");
            json_string(json, "the photon map's blur of the caustics over its radius "
                              "(consistent: it shrinks with the passes)");
        }
    }
    json_text(json, "]");
    return json->failed ? (fail(lab, "out of memory"), NULL) : json->text;
}

int lab_width(const Lab *lab) { return lab->width; }

int lab_height(const Lab *lab) { return lab->height; }

/* Chapter 10's minimum samples per pixel: spp in whole quarters, as its program has it. */
static int adaptive_min_samples(const LabSettings *s) { return (s->spp + 3) / 4 * 4; }

int lab_steps(const Lab *lab)
{
    const LabSettings *s = &lab->settings;
    if (s->chapter == 10) /* the first pass to the minimum, then a pass's samples each */
        return 1 + (s->max_samples - adaptive_min_samples(s) + ADAPTIVE_PASS_SAMPLES - 1) /
                       ADAPTIVE_PASS_SAMPLES;
    return s->chapter == 1 ? 1 : s->chapter == 8 ? s->passes : s->spp;
}

/* ---- the page's address -------------------------------------------------------------- */

/* A panel's settings as JSON: {"chapter":N,"scene":"NAME" or "","settings":[[key,
 * value],...]}, the values as given (each checked: none has a separator in it). */
static void panel_json(Json *json, int chapter, const char *scene, const Words *w)
{
    json_text(json, "{\"chapter\":%d,\"scene\":", chapter);
    json_string(json, scene ? scene : "");
    json_text(json, ",\"settings\":[");
    for (int i = 0, n = 0; i < w->count; i++)
        if (strcmp(w->key[i], "chapter") != 0) {
            json_text(json, "%s[", n++ ? "," : "");
            json_string(json, w->key[i]);
            json_text(json, ",");
            json_string(json, w->value[i]);
            json_text(json, "]");
        }
    json_text(json, "]}");
}

/* A scene name of the page's, or the message listing them. */
static int check_scene_name(Lab *lab, const char *key, const char *name, const char *scenes)
{
    size_t length = strlen(name);
    for (const char *p = scenes; *p; p += strcspn(p, "\n"), p += *p == '\n')
        if (strcspn(p, "\n") == length && strncmp(p, name, length) == 0 && length > 0)
            return 0;
    char list[1024] = "";
    size_t n = 0;
    for (const char *p = scenes; *p && n < sizeof list; p += *p == '\n') {
        int k = (int)strcspn(p, "\n"), written;
        written = snprintf(list + n, sizeof list - n, "%s%.*s", n ? ", " : "", k, p);
        n += written > 0 ? (size_t)written : 0;
        p += k;
    }
    return fail_key(lab, key, "expected one of the page's scenes (%s), got '%s'", list, name);
}

/* Panel B's words: A's (only size and seed where B is another chapter), then its own. */
static void panel_b_words(const Words *a, int a_chapter, const Words *own, int b_chapter,
                          Words *b)
{
    b->count = 0;
    for (int i = 0; i < a->count; i++)
        if ((b_chapter == a_chapter || strcmp(a->key[i], "size") == 0 ||
             strcmp(a->key[i], "seed") == 0) &&
            !word_value(own, a->key[i])) {
            b->key[b->count] = a->key[i];
            b->value[b->count++] = a->value[i];
        }
    for (int i = 0; i < own->count; i++) {
        b->key[b->count] = own->key[i];
        b->value[b->count++] = own->value[i];
    }
}

/* The page's own keys: layout, fairness, reference, workers, paths, pixel. */
static int page_key(Lab *lab, const char *key, const char *value, int cores, Json *json,
                    char *note, size_t note_size)
{
    static const char *const layouts[] = {"one", "two"},
                             *const fairness[] = {"samples", "time"},
                             *const references[] = {"schlick", "exact"};
    int i, col, row;
    if (strcmp(key, "layout") == 0 || strcmp(key, "fairness") == 0 ||
        strcmp(key, "reference") == 0) {
        const char *const *words = key[0] == 'l'   ? layouts
                                   : key[0] == 'f' ? fairness
                                                   : references;
        if (choice(lab, key, value, words, 2, &i) != 0)
            return -1;
        json_text(json, ",\"%s\":\"%s\"", key, words[i]);
    } else if (strcmp(key, "workers") == 0) {
        if (whole(lab, key, value, 0, LAB_WORKERS_MAX, &i) != 0)
            return -1;
        int used = i < 1 ? 1 : i > cores ? cores : i;
        if (used != i)
            snprintf(note, note_size, "workers: %d %s; using %d", i,
                     i < 1 ? "is fewer than one" : "is more than this browser's cores", used);
        json_text(json, ",\"workers\":%d", used);
    } else if (strcmp(key, "paths") == 0) {
        if (whole(lab, key, value, 1, LAB_PATHS_MAX, &i) != 0)
            return -1;
        json_text(json, ",\"paths\":%d", i);
    } else if (strcmp(key, "pixel") == 0) {
        char text[LAB_TEXT_MAX + 1];
        snprintf(text, sizeof text, "%s", value);
        char *comma = strchr(text, ',');
        if (!comma)
            return fail_key(lab, key, "expected COL,ROW (two whole numbers), got '%s'", value);
        *comma = '\0';
        if (whole(lab, key, text, 0, LAB_SIZE_MAX - 1, &col) != 0 ||
            whole(lab, key, comma + 1, 0, LAB_SIZE_MAX - 1, &row) != 0)
            return -1;
        json_text(json, ",\"pixel\":[%d,%d]", col, row);
    } else {
        return 1;
    }
    return 0;
}

const char *lab_fragment(Lab *lab, const char *fragment, const char *scenes, int cores)
{
    Words all, a = {.count = 0}, own = {.count = 0}, b;
    Json *json = &lab->json;
    json_clear(json);
    json_text(json, "{\"page\":{");
    lab->prefix = "";
    cores = cores < 1 ? 1 : cores > LAB_WORKERS_MAX ? LAB_WORKERS_MAX : cores;
    char note[256] = "";
    const char *scene_a = NULL, *scene_b = NULL;
    int status = split_words(lab, fragment, "&", &all);
    json_text(json, "\"cores\":%d", cores);
    for (int i = 0; status == 0 && i < all.count; i++) {
        const char *key = all.key[i], *value = all.value[i];
        int b_key = strncmp(key, "b.", 2) == 0;
        Words *panel = b_key ? &own : &a;
        if (b_key)
            key += 2;
        if (strcmp(key, "scene") == 0) {
            lab->prefix = b_key ? "b." : "";
            status = check_scene_name(lab, key, value, scenes);
            *(b_key ? &scene_b : &scene_a) = value;
        } else if (strcmp(key, "program") == 0) {
            status = fail(lab, "unknown setting '%s'", all.key[i]);
        } else if (b_key ||
                   (status = page_key(lab, key, value, cores, json, note, sizeof note)) == 1) {
            panel->key[panel->count] = key;
            panel->value[panel->count++] = value;
            status = 0;
        }
        lab->prefix = "";
    }
    LabSettings sa, sb;
    if (status != 0 || parse_settings(lab, &a, LAB_CHAPTERS, &sa) != 0)
        return NULL;
    int b_chapter = sa.chapter;
    const char *given = word_value(&own, "chapter");
    lab->prefix = "b.";
    if (given && chapter_number(lab, given, &b_chapter) != 0)
        return lab->prefix = "", NULL;
    panel_b_words(&a, sa.chapter, &own, b_chapter, &b);
    status = parse_settings(lab, &b, b_chapter, &sb);
    lab->prefix = "";
    if (status != 0)
        return NULL;
    json_text(json, ",\"b\":%d,\"note\":", own.count > 0 || scene_b != NULL);
    json_string(json, note);
    json_text(json, "},\"a\":");
    panel_json(json, sa.chapter, scene_a, &a);
    json_text(json, ",\"b\":");
    panel_json(json, sb.chapter, scene_b ? scene_b : scene_a, &b);
    json_text(json, "}");
    if (json->failed)
        return fail(lab, "out of memory"), NULL;
    return json->text;
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
    if (s->chapter == 10) { /* adaptive.c's quarters: sample s is s / 4 of quarter s mod 4 */
        image.spp = 0;
        image.seed = rng_hash(s->seed * 4 + (uint64_t)(sample % 4));
        *index = sample / 4;
    }
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
    if (lab->settings.chapter == 10)
        return fail(lab, "chapter 10 renders in passes (lab_adaptive_band)");
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

/* ---- chapter 10's passes ------------------------------------------------------------- */

/* The rule of adaptive.h, as chapters/ch10_adaptive.c sets it: its threshold the target's
 * square. */
static AdaptiveSettings adaptive_settings(const LabSettings *s)
{
    return (AdaptiveSettings){s->rule, adaptive_min_samples(s), s->max_samples,
                              ADAPTIVE_PASS_SAMPLES, s->target * s->target};
}

/* The lab's pixels of the whole image (a band's are copied in and out), allocated once. */
static int adaptive_buffers(Lab *lab)
{
    size_t count = (size_t)lab->width * (size_t)lab->height;
    free(lab->pixels);
    free(lab->to_add);
    lab->pixels = calloc(count, sizeof *lab->pixels);
    lab->to_add = calloc(count, sizeof *lab->to_add);
    if (!lab->pixels || !lab->to_add)
        return fail(lab, "out of memory for %zu pixels", count);
    return 0;
}

/* Pixel p from or into the page's arrays: LAB_PIXEL_STATE numbers (quarter q's sums of r, g,
 * b at 3q, its dropped samples at 12 + q) and a count. */
static void pixel_in(AdaptivePixel *pixel, const double *sums, int samples)
{
    for (int q = 0; q < 4; q++) {
        pixel->sum[q] = vec3(sums[3 * q], sums[3 * q + 1], sums[3 * q + 2]);
        pixel->dropped[q] = (int)sums[12 + q];
    }
    pixel->samples = samples;
}

static void pixel_out(const AdaptivePixel *pixel, double *sums)
{
    for (int q = 0; q < 4; q++) {
        sums[3 * q] = pixel->sum[q].x;
        sums[3 * q + 1] = pixel->sum[q].y;
        sums[3 * q + 2] = pixel->sum[q].z;
        sums[12 + q] = pixel->dropped[q];
    }
}

long lab_adaptive_plan(Lab *lab, int pass, const double *sums, const int *samples,
                       double *estimate, int *to_add)
{
    if (!lab->configured || lab->settings.chapter != 10)
        return fail(lab, "chapter 10 is not configured");
    long count = (long)lab->width * lab->height;
    if (!lab->pixels && adaptive_buffers(lab) != 0)
        return -1;
    for (long p = 0; p < count; p++)
        pixel_in(&lab->pixels[p], sums + LAB_PIXEL_STATE * p, samples[p]);
    AdaptiveSettings rule = adaptive_settings(&lab->settings);
    long active = adaptive_plan(&rule, lab->pixels, lab->width, lab->height, estimate, to_add);
    if (active < 0)
        return fail(lab, "out of memory for the plan");
    double sum = 0.0;
    for (long p = 0; p < count; p++)
        sum += estimate[p];
    lab->estimated_error = sqrt(sum / count);
    if (pass > 0 && lab->estimated_error <= lab->settings.target) /* adaptive_renderer.h */
        return 0;
    return active;
}

double lab_estimated_error(const Lab *lab) { return lab->estimated_error; }

int lab_adaptive_band(Lab *lab, int row0, int rows, double *sums, int *samples,
                      const int *to_add, double *values)
{
    if (!lab->configured || lab->settings.chapter != 10)
        return fail(lab, "chapter 10 is not configured");
    if (row0 < 0 || rows < 1 || row0 + rows > lab->height)
        return fail(lab, "no rows %d to %d", row0, row0 + rows - 1);
    if (!lab->pixels && adaptive_buffers(lab) != 0)
        return -1;
    long first = (long)row0 * lab->width, count = (long)rows * lab->width;
    for (long i = 0; i < count; i++) {
        pixel_in(&lab->pixels[first + i], sums + LAB_PIXEL_STATE * i, samples[i]);
        lab->to_add[first + i] = to_add[i];
    }
    int pass;
    ImageSettings image = image_of(lab, 0, &pass);
    image.seed = lab->settings.seed; /* adaptive_sample_rows makes the quarters' seeds */
    RayCounts counts = {0, 0, 0};
    adaptive_sample_rows(&lab->scene, &image, lab->estimate, lab->estimator_settings,
                         lab->pixels, lab->to_add, row0, row0 + rows, &counts);
    for (long i = 0; i < count; i++) {
        const AdaptivePixel *pixel = &lab->pixels[first + i];
        pixel_out(pixel, sums + LAB_PIXEL_STATE * i);
        samples[i] = pixel->samples;
        Vec3 value = adaptive_pixel_value(pixel, lab->settings.rule);
        values[3 * i] = value.x;
        values[3 * i + 1] = value.y;
        values[3 * i + 2] = value.z;
    }
    lab->rays[0] = (double)counts.camera;
    lab->rays[1] = (double)counts.bounce;
    lab->rays[2] = (double)counts.shadow;
    lab->rays[3] = 0.0;
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
    const LabSettings *s = &lab->settings;
    /* The render's samples of a pixel, as many as an int counts. */
    long long samples = s->chapter == 10
                            ? adaptive_min_samples(s)
                            : (long long)lab_steps(lab) * (s->chapter == 8 ? s->spp : 1);
    if (samples > INT_MAX)
        samples = INT_MAX;
    if (col < 0 || col >= lab->width || row < 0 || row >= lab->height)
        return fail(lab, "pixel: (%d, %d) is not in the %d x %d image", col, row, lab->width,
                    lab->height),
               NULL;
    if (count < 1 || count > LAB_PATHS_MAX)
        return fail(lab, "paths: expected a whole number from 1 to %d, got %d", LAB_PATHS_MAX,
                    count),
               NULL;
    if (first < 0 || first > samples - count)
        return fail(lab, "samples %d to %lld: the render takes samples 0 to %lld of a pixel",
                    first, (long long)first + count - 1, samples - 1),
               NULL;
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

/* Triangles and spheres listed for the plan at most (a bigger scene's plan shows its
 * first ones, and says how many there are). */
#define PLAN_TRIANGLES 20000
#define PLAN_SPHERES 20000

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
    json_text(json, ",\"triangle_count\":%d,\"sphere_count\":%d", scene->triangle_count,
              scene->sphere_count);
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
    for (int i = 0; i < scene->sphere_count && i < PLAN_SPHERES; i++) {
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
