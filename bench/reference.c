/* reference.c (bench, chapter 7): the reference renderer, build/reference.
 *
 * Every chapter measures its panels against a reference: the same expectation rendered
 * with many more samples and the lowest-variance estimator we have (measure.h). A
 * chapter's own library may not be able to render it well (chapter 2 has no shadow
 * rays), so this program is built from the final chapter's library, and the chapter
 * programs run it when their cache has no reference yet (experiment.h); a student never
 * needs to run it by hand.
 *
 * It reads the scene from --scene (the chapter programs pipe the bytes they read into
 * /dev/stdin), applies the one change a chapter may make to it (--sigma NAME=S: the
 * roughness of one material, chapter 5's sweep), renders what the path tracer with the
 * given depth and Fresnel mode estimates, with the most efficient unbiased estimator
 * measured (chapter 7's levers table): one shadow ray, Russian roulette with bounded
 * weights (finite variance for any reflectance) and the planar mirrors' images of the
 * lamps at every diffuse hit (mirror_light.h; nothing where a scene has no planar
 * mirror), bounces aimed at the mirror and glass spheres (sphere_guide.h), on jittered
 * sub-pixels, in REFERENCE_BATCHES independent batches (render_batches.h): sub-pixels
 * reach the same noise as random positions with about half the samples at 800 x 800,
 * and the batches still give the per-pixel errors without bias, which the chapters
 * subtract from their MSE. It stores the reference as a cache entry in --out
 * (KEY.pfm, KEY-stderr.pfm and KEY.txt, measure.h), which records the key, the scene's
 * bytes' hash and the settings it was rendered with; when --out cannot take it (a full
 * disk), it says why and stores it in --fallback, a temporary folder the chapter program
 * reads it from. An interrupted render stores nothing and exits with status 130. With
 * --parent PID it ends when that program does (Linux: the parent-death signal), so a
 * chapter program killed outright does not leave it rendering on its own.
 */
#include <ctype.h>
#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#ifdef __linux__
#include <sys/prctl.h>
#endif

#include "error_estimate.h"
#include "measure.h"
#include "path_final.h"
#include "render_batches.h"
#include "scene_file.h"
#include "sphere_guide.h"

static const char *program = "reference";

/* Batches of the reference (render_batches.h); --reference-spp is rounded up to a
 * multiple of them. */
#define REFERENCE_BATCHES 8

static void fail(int status, const char *format, const char *detail)
{
    fprintf(stderr, "%s: ", program);
    fprintf(stderr, format, detail);
    fputc('\n', stderr);
    exit(status);
}

typedef struct {
    const char *scene, *name, *fresnel, *sigma, *out, *fallback;
    long size, spp, depth, parent;
    double target_error, time_limit; /* 0: off */
    unsigned long long seed, key;
    int has_key;
    int quiet;
} Request;

static const char USAGE[] =
    "usage: reference --scene FILE --size N --reference-spp N --depth N --out DIR --key HEX\n"
    "                 [--name NAME] [--fresnel schlick|exact] [--sigma MATERIAL=S] [--seed N]\n"
    "                 [--fallback DIR] [--parent PID] [--quiet] [--target-error E] [--time T]\n"
    "Renders the reference image of a scene into DIR/HEX.pfm, HEX-stderr.pfm and HEX.txt\n"
    "(into the --fallback folder when DIR cannot take them).\n"
    "The chapter programs run it when their cache has no reference yet.\n"
    "With --target-error E (in (0, 1)) or --time T (seconds), it renders batches of\n"
    "--reference-spp / 8 samples until the image's relative RMSE, estimated from its odd\n"
    "and even batches, is at most E, or T seconds are up, prints what that cost, and\n"
    "records the samples it took as the entry's samples per pixel.\n";

static long whole_number(const char *flag, const char *text, long min, long max)
{
    char *end;
    errno = 0;
    long value = strtol(text, &end, 10);
    if (*text == '\0' || *end != '\0' || errno != 0 || value < min || value > max)
        fail(2, "%s: expected a whole number in range", flag);
    return value;
}

/* --target-error (in (0, 1)) or --time (above 0): a finite decimal number, the whole text. */
static double positive_number(const char *flag, const char *text, int below_one)
{
    char *end;
    errno = 0;
    double value = strtod(text, &end);
    if (*text == '\0' || *end != '\0' || errno != 0 ||
        strspn(text, "+-0123456789.eE") != strlen(text) || !(value > 0.0) ||
        (below_one && !(value < 1.0)))
        fail(2,
             below_one ? "%s: expected a number in (0, 1)"
                       : "%s: expected a number of seconds above 0",
             flag);
    return value;
}

/* A seed (base 10) or a cache key (base 16): digits only, the whole of a 64-bit word. */
static unsigned long long unsigned_word(const char *flag, const char *text, int base)
{
    char *end;
    errno = 0;
    unsigned long long value = strtoull(text, &end, base);
    if (!isxdigit((unsigned char)*text) || *end != '\0' || errno != 0)
        fail(2, base == 16 ? "%s: expected hexadecimal digits" : "%s: expected digits", flag);
    return value;
}

static Request parse(int argc, char **argv)
{
    Request r = {.scene = NULL, .name = NULL, .fresnel = "schlick", .sigma = "=0"};
    for (int i = 1; i < argc; i++) {
        const char *flag = argv[i];
        if (strcmp(flag, "--quiet") == 0) {
            r.quiet = 1;
            continue;
        }
        if (strcmp(flag, "--help") == 0) {
            fputs(USAGE, stdout);
            exit(0);
        }
        if (i + 1 >= argc)
            fail(2, "%s: missing value", flag);
        const char *value = argv[++i];
        if (strcmp(flag, "--scene") == 0)
            r.scene = value;
        else if (strcmp(flag, "--name") == 0)
            r.name = value;
        else if (strcmp(flag, "--fresnel") == 0)
            r.fresnel = value;
        else if (strcmp(flag, "--sigma") == 0)
            r.sigma = value;
        else if (strcmp(flag, "--out") == 0)
            r.out = value;
        else if (strcmp(flag, "--fallback") == 0)
            r.fallback = value;
        else if (strcmp(flag, "--key") == 0) {
            r.key = unsigned_word(flag, value, 16);
            r.has_key = 1;
        } else if (strcmp(flag, "--size") == 0)
            r.size = whole_number(flag, value, 1, 16384);
        else if (strcmp(flag, "--reference-spp") == 0)
            r.spp = whole_number(flag, value, 1, 1 << 24);
        else if (strcmp(flag, "--depth") == 0)
            r.depth = whole_number(flag, value, 1, 1000);
        else if (strcmp(flag, "--seed") == 0)
            r.seed = unsigned_word(flag, value, 10);
        else if (strcmp(flag, "--target-error") == 0)
            r.target_error = positive_number(flag, value, 1);
        else if (strcmp(flag, "--time") == 0)
            r.time_limit = positive_number(flag, value, 0);
        else if (strcmp(flag, "--parent") == 0)
            r.parent = whole_number(flag, value, 1, 1L << 30);
        else
            fail(2, "unknown option '%s' (this program is run by the chapter programs)", flag);
    }
    if (!r.scene || !r.out || !r.has_key || r.size == 0 || r.spp == 0 || r.depth == 0)
        fail(2, "%s", "needs --scene, --size, --reference-spp, --depth, --out and --key");
    if (strcmp(r.fresnel, "schlick") != 0 && strcmp(r.fresnel, "exact") != 0)
        fail(2, "--fresnel: expected 'schlick' or 'exact', got '%s'", r.fresnel);
    return r;
}

/* --sigma NAME=S: set the roughness of the Oren-Nayar material NAME (none if NAME is
 * empty). */
static void apply_sigma(Scene *scene, const char *sigma)
{
    const char *equals = strchr(sigma, '=');
    if (!equals)
        fail(2, "--sigma: expected NAME=SIGMA, got '%s'", sigma);
    if (equals == sigma)
        return;
    char name[MATERIAL_NAME_MAX];
    snprintf(name, sizeof name, "%.*s", (int)(equals - sigma), sigma);
    int material = scene_file_material(scene, name);
    if (material < 0 || scene->materials[material].kind != MATERIAL_OREN_NAYAR)
        fail(2, "--sigma: no oren_nayar material '%s'", name);
    scene->materials[material].sigma = strtod(equals + 1, NULL);
}

/* Into --out, or else into --fallback (saying why), or fail naming both reasons. */
static void save(const Request *request, const ReferenceIdentity *identity,
                 const Reference *reference)
{
    if (measure_save_reference(request->out, identity, reference) == 0)
        return;
    char reason[4400];
    snprintf(reason, sizeof reason, "%s: %s", request->out, strerror(errno));
    if (!request->fallback)
        fail(1, "cannot write the reference into %s", reason);
    if (measure_save_reference(request->fallback, identity, reference) != 0) {
        char both[8900];
        snprintf(both, sizeof both, "%s, nor into %s: %s", reason, request->fallback,
                 strerror(errno));
        fail(1, "cannot write the reference into %s", both);
    }
    fprintf(stderr, "%s: cannot write the reference into %s: kept in %s for this run only\n",
            program, reason, request->fallback);
}

/* The batches (all alike, so their spread still gives each pixel's standard error) until
 * the target or the time is reached; the line that says what it cost. */
static RenderResult render_reference_to_target(const Request *request, const Scene *scene,
                                               const RenderSettings *settings,
                                               const PathSettings *path)
{
    TargetSettings target = {request->target_error, request->time_limit,
                             settings->image.spp / REFERENCE_BATCHES, 0, 0};
    TargetResult result;
    if (render_to_target(scene, settings, path_final_radiance, path, &target, &result) != 0)
        fail(1, "%s", "out of memory");
    if (!result.render.interrupted) {
        char line[512];
        target_describe(&target, &result.estimate, NULL, result.stop, result.render.seconds,
                        render_samples_per_pixel(&result.render),
                        (double)ray_counts_total(result.render.rays), result.passes, line,
                        sizeof line);
        printf("%s\n", line);
    }
    return result.render;
}

int main(int argc, char **argv)
{
    Request request = parse(argc, argv);
#ifdef __linux__
    if (request.parent > 0) {
        prctl(PR_SET_PDEATHSIG, SIGTERM);
        if (getppid() != (pid_t)request.parent)
            fail(1, "%s", "the program that started this one has ended");
    }
#endif
    Scene scene;
    SceneFileInfo file;
    char error[4400], *text;
    size_t length;
    if (scene_file_read(request.scene, &text, &length, error, sizeof error) != 0 ||
        scene_parse(text, length, request.scene, &scene, &file, error, sizeof error) != 0)
        fail(2, "%s", error);
    free(text);
    apply_sigma(&scene, request.sigma);
    MirrorPlanes mirrors;
    if (mirror_light_find_planes(&scene, &mirrors) != 0)
        fail(1, "%s", "out of memory");

    PathSettings path = {.max_depth = (int)request.depth,
                         .shadow_rays = 1,
                         .fresnel = strcmp(request.fresnel, "exact") == 0 ? FRESNEL_EXACT
                                                                          : FRESNEL_SCHLICK,
                         .rr_throughput = 1,
                         .mirror_light = (int)request.depth,
                         .mirrors = &mirrors,
                         .sphere_guide = SPHERE_GUIDE_STRENGTH};
    RenderSettings settings = {0};
    settings.image.width = (int)request.size;
    settings.image.height = (int)lround(request.size / scene_file_aspect(&scene.camera));
    settings.image.spp =
        (int)((request.spp + REFERENCE_BATCHES - 1) / REFERENCE_BATCHES * REFERENCE_BATCHES);
    settings.image.sampling = PIXEL_SUBPIXELS;
    settings.image.seed = request.seed;
    settings.progress = !request.quiet;
    settings.label = "reference";
    render_install_interrupt();
    RenderResult result;
    long recorded_spp = request.spp;
    if (request.target_error > 0.0 || request.time_limit > 0.0) {
        result = render_reference_to_target(&request, &scene, &settings, &path);
        recorded_spp = lround(render_samples_per_pixel(&result));
    } else if (render_batches(&scene, &settings, REFERENCE_BATCHES, path_final_radiance, &path,
                              &result) != 0)
        fail(1, "%s", "out of memory");
    if (result.interrupted)
        fail(130, "%s", "interrupted; nothing was cached");
    Reference reference = {result.image,
                           result.std_error,
                           measure_rms(&result.std_error),
                           render_samples_per_pixel(&result),
                           result.seconds,
                           0,
                           0.0,
                           0.0};
    measure_image_mean(&result.image, &result.average_std_error, &reference.mean,
                       &reference.mean_std_error);
    image_free(&result.average_std_error);
    ReferenceIdentity identity = {request.key, file.hash, ""};
    measure_reference_settings(&identity, request.size, recorded_spp, request.depth,
                               request.fresnel, request.seed, request.sigma);
    save(&request, &identity, &reference);
    render_result_free(&result);
    mirror_planes_free(&mirrors);
    scene_free(&scene);
    return 0;
}
