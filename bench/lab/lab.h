/* lab.h (bench, chapter 8): the lab's renderer, the part of its page that is C.
 *
 * One chapter's estimator (1 to 8, 10) with that chapter's settings, on a scene read from
 * text, rendered a band of rows at a time for one step: a step is one sample of every
 * pixel (chapters 1-7), or one pass of progressive photon mapping (chapter 8, its
 * mean over the pass's samples rounded as ppm.h's pass image is). Whoever takes the
 * steps of a pixel in order and averages them as renderer.h does (Welford's update)
 * gets the chapter program's image, bit for bit, with any number of workers. Built to
 * WebAssembly for the page (bench/lab/lab.js) and natively (lab_native.c), both linked
 * with the recorder (record.h) that notes a sample's path for the inspector.
 */
#ifndef LAB_H
#define LAB_H

#include "render.h"

typedef struct Lab Lab;

/* A lab with no scene; NULL when memory runs out. */
Lab *lab_new(void);
void lab_free(Lab *lab);

/* The message of the last call that failed. */
const char *lab_error(const Lab *lab);

/* Read the scene from `length` bytes of text, `name` standing for its file in
 * messages, which are the scene reader's ("NAME:LINE: what is wrong"). Returns 0, or -1.
 * The lab's settings are kept; configure again before rendering. */
int lab_load_scene(Lab *lab, const char *text, int length, const char *name);

/* Settings as "key=value" words, separated by spaces or '&' (docs/lab.md lists them),
 * each key and value decoded from its %XX escapes after the split, so that a value is
 * one value (a space or '&' in it is refused with the value): chapter=N first sets that
 * chapter's defaults, the rest override them; a key the chapter does not have yet, or
 * given twice, is an error. Each value is judged as the chapter programs judge a flag's
 * (bench/cli.c: the same words). Also checks that the scene has the light the chapter
 * needs, with the chapter program's message. Returns 0, or -1. */
int lab_configure(Lab *lab, const char *settings);

/* The page's address fragment (without '#', as the address has it: escapes not decoded)
 * checked, every key as lab_configure checks it, with its messages, and the page's own:
 * keys without a prefix are panel A's settings, "b." ones panel B's (B starts as A, or
 * from A's size, seed and scene when b.chapter differs), scene and b.scene one of
 * `scenes` (names separated by newlines), layout=one|two, fairness=samples|time,
 * reference=schlick|exact, workers=N (0 to 1024, used between 1 and `cores`, with a
 * note when it is moved), paths=K (1 to 64), pixel=COL,ROW. No scene is needed (the
 * scene's own checks come with lab_configure). Returns, as JSON,
 *   {"page":{"cores":C,"layout":...,"workers":N,...,"b":0|1,"note":"..."},
 *    "a":{"chapter":N,"scene":"NAME" or "","settings":[["key","value"],...]},"b":{...}}
 * with the page's keys that were given and each panel's settings as given (chapter
 * apart); NULL (lab_error) on the first key refused. Valid until the next call. */
const char *lab_fragment(Lab *lab, const char *fragment, const char *scenes, int cores);

/* The settings configured, every one the chapter has, as JSON: {"chapter":7,"size":256,
 * "spp":64,...} with the names and values lab_configure takes. NULL on failure. */
const char *lab_settings(Lab *lab);

/* The biases of the estimator configured, as a JSON array of phrases, each what its
 * expectation misses or changes (an unbiased one: []): Whitted's ray tree leaves out
 * diffuse interreflection; a path cut after its depth, the light of longer paths;
 * Schlick's reflectance in a scene with glass, the exact Fresnel one's difference; the
 * photon map (chapter 8), its blur over the radius. The standard error of the samples
 * leaves these out; the page says so. NULL on failure. Valid until the next call. */
const char *lab_biases(Lab *lab);

int lab_width(const Lab *lab);
int lab_height(const Lab *lab);

/* The steps of the render configured: samples per pixel, passes (chapter 8), 1 for
 * Whitted's deterministic image. */
int lab_steps(const Lab *lab);

/* Step `step` (from 0) of rows row0 .. row0 + rows - 1 into out[3 * (r * width + c)],
 * r counted from row0: the sample's radiance (NaN or infinite as the estimator returned
 * it), or in chapter 8 the pass's pixel. Returns 0, or -1 (out of memory, rows outside
 * the image). */
int lab_render_band(Lab *lab, int step, int row0, int rows, double *out);

/* The numbers the page keeps per pixel of chapter 10 besides its count (below). */
#define LAB_PIXEL_STATE 16

/* Chapter 10's pass `pass` (from 0) planned (adaptive_plan, with chapters/ch10_adaptive.c's
 * rule: the threshold the target's square): the pixels' state as the page keeps it, sums
 * (LAB_PIXEL_STATE per pixel: quarter q's r, g, b at 16 p + 3 q, its dropped samples at
 * 16 p + 12 + q) and samples, in; each pixel's estimated
 * relative MSE and the samples to add, out. Returns the pixels that get samples, 0 when the
 * render is done (none does, or after the first pass the image's estimated relative RMSE,
 * lab_estimated_error, is at most the target), or -1. */
long lab_adaptive_plan(Lab *lab, int pass, const double *sums, const int *samples,
                       double *estimate, int *to_add);

/* The image's estimated relative RMSE at the last plan: sqrt(mean of the estimates). */
double lab_estimated_error(const Lab *lab);

/* The planned samples of rows row0 .. row0 + rows - 1 (adaptive_sample_rows): the band's
 * sums and samples (as lab_adaptive_plan's, the band's only) updated in place, and each
 * pixel's value as the rule keeps it into values (3 per pixel). Returns 0, or -1. */
int lab_adaptive_band(Lab *lab, int row0, int rows, double *sums, int *samples,
                      const int *to_add, double *values);

/* Rays traced by the last lab_render_band or lab_adaptive_band: 0 camera, 1 bounce, 2 shadow, 3
 * photon rays (of the pass's photon maps, chapter 8, counted by the band that built them). */
double lab_rays(const Lab *lab, int kind);

/* Samples first .. first + count - 1 (count at most 64, all among the render's samples
 * of a pixel) of pixel (col, row), each path recorded (record.h), as JSON:
 * {"col":C,"row":R,"paths":[{"sample":S,...}, ...]}. NULL on failure (lab_error). The text
 * stays valid until the next call. */
const char *lab_record(Lab *lab, int col, int row, int first, int count);

/* The scene for drawing its plan: camera, materials, triangles, spheres, point lights,
 * as JSON; NULL on failure. Valid until the next call. */
const char *lab_scene(Lab *lab);

/* The 64-bit hash of the scene's bytes (scene_file.h), as 16 hex digits: the page uses
 * it to find the reference of this scene. */
const char *lab_scene_hash(Lab *lab);

#endif
