/* cli.h (bench, chapter 1): the command line every chapter program shares.
 *
 * Introduced in chapter 1. Each program declares which flags it takes (a chapter
 * accepts only what it uses) and its defaults, which reproduce the report. Values
 * may follow the flag as the next word or after '=' (--size 200, --size=200).
 * A bad value is an error that names the flag, on stderr, with exit status 2:
 *     ch01_whitted: --size: expected a whole number from 1 to 16384, got '0'
 * --help prints the usage with the defaults and exits 0.
 */
#ifndef CLI_H
#define CLI_H

#include <stdint.h>

#if CHAPTER >= 4
#include "fresnel.h"
#endif

enum {
    FLAG_SCENE = 1u << 0,       /* --scene FILE */
    FLAG_SIZE = 1u << 1,        /* --size N: image width; height follows the image plane */
    FLAG_SPP = 1u << 2,         /* --spp N: samples per pixel */
    FLAG_SHADOW_RAYS = 1u << 3, /* --shadow-rays N: M of eq. 21 (0: lights found by hitting) */
    FLAG_RR = 1u << 4,          /* --rr ALPHA: Russian roulette survival probability */
    FLAG_DEPTH = 1u << 5,       /* --depth N: maximum ray depth */
    FLAG_THREADS = 1u << 6,     /* --threads N: 0 = one per core */
    FLAG_SEED = 1u << 7,        /* --seed N */
    FLAG_OUT = 1u << 8,         /* --out DIR */
    FLAG_QUIET = 1u << 9,       /* --quiet: no progress display */
    FLAG_FRESNEL = 1u << 10,    /* --fresnel schlick|exact */
    FLAG_QUICK = 1u << 11,      /* --quick: a quarter of the default size, more runs */
    FLAG_REFERENCE_SPP = 1u << 12, /* --reference-spp N: samples of the reference image */
    FLAG_RUNS = 1u << 13,          /* --runs N: independent runs of each measured setting */
    FLAG_STRATA = 1u << 14,        /* --strata on|off: stratified pairs (chapter 7; sobol.h) */
    FLAG_TARGET_ERROR = 1u << 15,  /* --target-error E: render to a relative RMSE (chapter 7 on;
                                      error_estimate.h) */
    FLAG_TIME = 1u << 16           /* --time T: render for T seconds (chapter 7 on) */
};

/* --runs: at most; by default, two (at the report's 800 x 800 a run of Figure 7 is long,
 * so full size keeps few runs); and with --quick (small images, so more runs for the
 * same time). */
#define CLI_RUNS_MAX 100
#define CLI_RUNS 2
#define CLI_QUICK_RUNS 5

/* Flags every chapter program takes. */
#define FLAGS_COMMON                                                                           \
    (FLAG_SCENE | FLAG_SIZE | FLAG_THREADS | FLAG_SEED | FLAG_OUT | FLAG_QUIET | FLAG_QUICK)

typedef struct {
    const char *scene;
    int size;
    int spp;
    int shadow_rays;
    double rr;
    int depth;
    int threads;
    uint64_t seed;
    const char *out;
    int quiet;
#if CHAPTER >= 4
    FresnelMode fresnel;
#endif
    int quick;
    int reference_spp;
    int runs;
#if CHAPTER >= 7
    int strata; /* 1: the estimator's pairs of numbers stratified across a pixel's samples */
    double
        target_error;  /* the relative RMSE to render to, estimated from the samples; 0: off */
    double time_limit; /* seconds to render for at most; 0: off */
#endif
    unsigned given;      /* the FLAG_ bits the user set on the command line */
    uint64_t scene_hash; /* of the scene file's bytes (scene_file.h), once it is read */
    int scene_lines;     /* its number of lines */
} Options;

typedef struct {
    const char *summary; /* one line: what the program teaches and reproduces */
    unsigned flags;      /* the FLAG_ bits it accepts */
    Options defaults;
} ProgramInfo;

/* The program's name (argv[0] without its directory), for messages. */
extern const char *cli_program;

/* Parse argv into *options, starting from info->defaults. With --quick, the size not
 * given on the command line is a quarter of its default (the reference keeps its
 * samples per pixel: on a sixteenth of the pixels it is cheap), and --runs is
 * CLI_QUICK_RUNS. Exits on --help (status 0) and on any error (status 2). */
void cli_parse(int argc, char **argv, const ProgramInfo *info, Options *options);

/* A quarter of `value`, but at least `smallest` and at most `value` itself: --quick's
 * sizes, and the chapters' sweeps on quarter-size images. */
int cli_quarter(int value, int smallest);

/* Print "PROGRAM: message" on stderr and exit with `status`. */
void cli_fail(int status, const char *format, ...);

static inline int cli_given(const Options *options, unsigned flag)
{
    return (options->given & flag) != 0;
}

#endif
