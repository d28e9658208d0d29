/* grading.h (bench, chapter 1): what the exercise graders share (README.md, "Do the chapters
 * yourself").
 *
 * An exercise is one marked function of the lesson ("Exercise N.k" in the comment that
 * documents it), graded by bench/exercise/chapterN.c. A grader knows the right answer (a
 * closed form, a property every right answer has, or the solution's render) and says what
 * is wrong in a student's words, with the numbers behind it. A sampler is graded by the
 * warp test: Pearson's chi-square (chi_square.h) of its samples' histogram against the
 * exact density integrated over each cell, and a picture of both; and by the means of
 * what it draws, each over independent replicates of stratified inputs, Student's t
 * (student_t.h) of their spread: powerful where a valid method other than the task's
 * gives other samples than the solution's from the same numbers.
 */
#ifndef GRADING_H
#define GRADING_H

#include <stddef.h>
#include <stdint.h>

#include "answers.h"
#include "render.h"
#include "test_random.h"

typedef struct {
    const char *id;         /* "2.1" */
    const char *out;        /* the folder the pictures go to (the judge's) */
    const char *references; /* the folder with the solution's reference renders (the judge's) */
    AnswerWriter *writer;   /* the probe's: where the answers go (NULL in the judge) */
    const AnswerReader *answers; /* the judge's: the answers that came back */
    const char *ended; /* the judge's: why no more came, the verdict if it asks for more */
    long next;         /* the judge's: the next answer to read */
    int failed;
    char message[1024]; /* what is wrong (the first failure found), when failed */
    char numbers[4096]; /* the numbers behind the verdict, one line each */
    uint64_t seed;      /* the grading's seed (GRADE_SEED): every random input follows it */
    int pictures;       /* the judge's: warp pictures written so far, each its own file */
} Grading;

/* A render the grader compares, pixel by pixel, with the solution's (render_check.h). */
typedef struct RenderCheck RenderCheck;

typedef struct {
    const char *id;       /* "N.k" */
    const char *function; /* the function whose body the student writes */
    const char *task;     /* what to compute, from what, by which equation and section */
    const char *blank;    /* the body the exercise starts from: it compiles and returns a
                             neutral value */
    void (*grade)(Grading *g);
    const RenderCheck *render; /* its reference render, or NULL */
    const char *uses;          /* the ids of the chapter's other exercises whose functions its
                                  grader's calls reach ("3.1 3.3"), or "" */
} Exercise;

/* Each chapter's table, bench/exercise/chapterN.c; the grader links one of them. */
extern const Exercise exercises[];
extern const int exercise_count;

/* The exercise of that id, or NULL. */
const Exercise *exercise_find(const char *id);

/* Grade exercise e: first every exercise it uses (e->uses, and theirs, in the order the
 * code depends on them), then e itself. The first that fails is the verdict: a grader
 * never blames an exercise for the mistake of one it calls ("exercise 2.1 (...), which
 * path_radiance depends on, is wrong first: ..."). Run alike in the probe and the judge. */
void exercise_grade(const Exercise *e, Grading *g);

/* Each grader runs twice, in two processes. In the student's program (the probe, probe.c)
 * every value the student's code computes passes through ASK, which sends it to the
 * grader built from the solution (the judge, grade.c); there the same grader runs again,
 * ASK returning the values that came back instead of computing them, and decides. So no
 * student code runs where the verdict is made (supervise.h). A grader computes any value
 * of its own from a lesson function (an oracle) only in the judge:
 * if (!grading_probing(g)). */

/* Whether this is the student's program (the probe), not the grader (the judge). */
int grading_probing(const Grading *g);

/* A value the student's code computed: the probe sends it and returns it; the judge
 * returns the one that came back, or, when none is left, fails with g->ended and
 * returns NaN. ASK and ASK_VEC3 compute their expression in the probe only. */
double grading_ask(Grading *g, double value);
Vec3 grading_ask_vec3(Grading *g, Vec3 value);
#define ASK(g, expression) grading_ask((g), grading_probing(g) ? (double)(expression) : 0.0)
#define ASK_VEC3(g, expression)                                                                \
    grading_ask_vec3((g), grading_probing(g) ? (expression) : vec3(0.0, 0.0, 0.0))

/* `count` values in place: sent by the probe, overwritten in the judge. */
void grading_ask_floats(Grading *g, float *values, long count);

/* Append one line to the numbers behind the verdict. */
void grading_note(Grading *g, const char *format, ...) __attribute__((format(printf, 2, 3)));

/* The exercise fails with this message, unless it has already failed (the first
 * failure is the one to fix). Returns 0, so that a grader may `return grading_fail(...)`. */
int grading_fail(Grading *g, const char *format, ...) __attribute__((format(printf, 2, 3)));

/* Fails and returns 1 when `value` is NaN or infinite, naming `what` it is. */
int grading_not_finite(Grading *g, double value, const char *what);

/* How many decimals, at least 4, show a and b different (%.*f); 17 when none do. */
int grading_decimals(double a, double b);

/* A count with thousands separated: 1310 as "1,310". Returns text. */
char *grading_count(double count, char *text, size_t size);

/* The p-value as text: "p < 1e-9" below 1e-9, else "p = 0.0123". Returns text. */
char *grading_p(double p, char *text, size_t size);

/* Parse the scene `text` (docs/scene-format.md) into *scene. Returns 0, or fails the
 * exercise and returns -1. */
int grading_scene(Grading *g, const char *text, Scene *scene);

/* The course's significance. Every statistical check of every chapter's grading is one
 * of at most COURSE_CHECKS, and the whole course's grading of a right answer fails with
 * probability at most COURSE_FALSE_ALARM: each check runs at Sidak's level
 * 1 - (1 - COURSE_FALSE_ALARM)^(1 / COURSE_CHECKS), about 2.5e-7 (two-sided z about 5.16).
 * A check states its power: the bias it detects with probability GRADING_POWER, from its
 * standard error se, (z_level + z_power) se, about 7.5 se. */
#define COURSE_FALSE_ALARM 1e-4
#define COURSE_CHECKS 400
#define GRADING_POWER 0.99

/* The level of one check of the course (above). */
double grading_level(void);

/* The z with P(|Z| > z) = level for a standard normal Z (two-sided). */
double grading_z(double level);

/* The smallest bias a check at grading_level() of standard error `se` detects with
 * probability GRADING_POWER: (grading_z(level) + z) se with P(Z > z) = 1 - GRADING_POWER. */
double grading_detectable(double se);

/* The grading's seed: GRADE_SEED from the environment, a whole number, 0 (the fixed seed
 * of every check) when it is unset or empty. The probe and the judge read it alike.
 * Returns 0, or -1 with a message in error[size] when it is not a whole number. */
int grading_seed_from_environment(uint64_t *seed, char *error, size_t size);

/* The stream `stream` of random inputs under g's seed: `stream` itself at seed 0. */
uint64_t grading_stream(const Grading *g, uint64_t stream);

/* Randomized stratified inputs: the unit cube [0, 1)^dims (dims <= 3) cut into
 * divisions[0] x divisions[1] x ... cells, a replicate one uniform point in each. Any
 * function's mean over a replicate is an unbiased estimate of its mean over the cube,
 * and for a function that is smooth on most cells (a sampler's mapping, and what is
 * measured of its samples) one far less noisy than as many independent points: the noise
 * comes from within the cells alone, a discontinuity's from the cells it crosses. */
typedef struct {
    int dims, divisions[3];
    long cells; /* a replicate's points */
    int bits;   /* cells <= 2^bits (the order they are visited in) */
} Strata;

/* The strata of the cube [0, 1)^dims cut `divisions` times along each axis. */
Strata grading_strata(int dims, const int *divisions);

/* Point `index` (index mod cells) of a replicate, in u[dims]: given its jitter u (uniform
 * in [0, 1)^dims), u[k] = (cell_k + u[k]) / divisions[k]. The cells are visited in a
 * scrambled order (a fixed bijection), so that the first points of a replicate spread
 * over the whole cube without a pattern (the warp pictures show them). */
void grading_stratify(const Strata *strata, long index, double *u);

/* A replicate test at grading_level() of `replicates` >= 2 independent, unbiased
 * estimates of one quantity (each the mean over a replicate of stratified inputs): their
 * mean against its exact value by Student's t with replicates - 1 degrees of freedom, the
 * standard error estimated from their spread (student_t.h), so honest whatever the
 * sampler does with the strata. A note with the detectable bias: the noncentral t's shift
 * at power GRADING_POWER times the se (about 8.4 se at 64 replicates, 7.7 at 256); on
 * failure the verdict names `what`, the difference and t, then `hint`. A difference
 * within rounding (1e-12 of the values) passes. Returns 1 when it passes. */
int grading_replicate_test(Grading *g, const char *what, const double *replicate_means,
                           int replicates, double exact, const char *hint);

/* A catalogue of known wrong answers of a closed form: what the code computes instead,
 * in words, what is right, and that wrong value at the grader's inputs. */
typedef struct {
    const char *wrong; /* "(1/2) (R_s + R_p) computed as 1 / 2 * (...) in integers" */
    const char *right; /* why that is wrong and what is right, in words */
    double (*value)(const double *inputs);
} WrongAnswer;

/* The first entry of list[count] whose value matches got[k] to 1e-9 (relative) at every
 * one of `points` inputs (inputs + k * arity), or NULL. Needs points >= 2. */
const WrongAnswer *grading_known_wrong(const WrongAnswer *list, int count, const double *inputs,
                                       int arity, const double *got, int points);

/* Fails naming the match: "your QUANTITY equals WRONG at each of the N inputs tried: RIGHT".
 * Returns 0. */
int grading_fail_known(Grading *g, const char *quantity, const WrongAnswer *known, int points);

/* What a warp test's cells are called: row 0 and the last row named where they are,
 * and the impossible cell, where the density is 0 (expected count 0). */
typedef struct {
    const char *row_name;             /* "ring" */
    const char *first_row, *last_row; /* where row 0 and the last row are: "nearest the pole" */
    const char *col_name;             /* "sector around the normal" */
    const char *impossible;           /* where the impossible cell is: "below the surface" */
} WarpLabels;

/* The warp test's histogram: rows x cols cells and the impossible one. */
typedef struct {
    int rows, cols;
    double *observed, *expected; /* rows * cols + 1 */
    WarpLabels labels;
    int shown;               /* samples kept for the picture */
    double *square, *mapped; /* their (u1, u2) in [0, 1)^2 and where they went, in
                                [-1, 1]^2 (x right, y up) */
} Warp;

/* A warp test of rows x cols cells keeping `shown` samples for the picture. Returns 0,
 * or fails the exercise (out of memory) and returns -1. */
int warp_new(Grading *g, Warp *warp, int rows, int cols, int shown, WarpLabels labels);
void warp_free(Warp *warp);

/* Sample `index` drawn from (u1, u2) fell into cell (row, col), or into the impossible
 * cell when row < 0; (x, y) shows where it went. */
void warp_add(Warp *warp, long index, int row, int col, double u1, double u2, double x,
              double y);

/* Sample `index`, the unit direction `local` of a hemisphere about z drawn from (u1, u2),
 * into a warp test of rows rings of equal height (1 - z, row 0 at the pole) and cols
 * sectors of phi; below the horizon, off the unit sphere or NaN into the impossible cell. */
void warp_add_hemisphere(Warp *warp, long index, double u1, double u2, Vec3 local);

/* Such a warp test's expected counts for `samples` drawn with density cos(theta) / pi:
 * a ring between heights a < b holds b^2 - a^2 of them, each sector 1 / cols of that. */
void warp_expect_cosine(Warp *warp, long samples);

/* The chi-square test of the histogram at significance level `level`, Sidak-corrected
 * for `tests` such tests of the exercise; the picture OUT/exercise-ID-warp.png (samples
 * on the square, where they went, observed and expected counts); on failure the row or
 * column furthest from its expected count, in words, then `hint`. Returns 1 when it
 * passes. */
int grading_warp(Grading *g, const Warp *warp, const char *what, double level, int tests,
                 const char *hint);

#endif
