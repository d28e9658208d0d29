/* cli.c (bench, chapter 1): parsing the shared command line. See cli.h. */
#include "cli.h"

#include <errno.h>
#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

const char *cli_program = "mcrt";

typedef enum {
    VALUE_NONE,
    VALUE_INT,
    VALUE_REAL,
    VALUE_TEXT,
    VALUE_SEED,
    VALUE_FRESNEL,
    VALUE_SWITCH
} ValueKind;

/* One row per flag: its name, what its value is, the range allowed, and its help. */
typedef struct {
    unsigned bit;
    const char *name;
    ValueKind kind;
    double min, max;
    const char *help;
} FlagSpec;

static const FlagSpec FLAG_SPECS[] = {
    {FLAG_SCENE, "--scene", VALUE_TEXT, 0, 0,
     "FILE    scene file to render (docs/scene-format.md)"},
    {FLAG_SIZE, "--size", VALUE_INT, 8, 16384,
     "N       image width in pixels; the height follows the image plane"},
    {FLAG_SPP, "--spp", VALUE_INT, 1, 1 << 20, "N       samples per pixel"},
    {FLAG_SHADOW_RAYS, "--shadow-rays", VALUE_INT, 0, 1 << 16,
     "N       shadow rays per diffuse hit (eq. 21); 0: lights found only by hitting them"},
    {FLAG_RR, "--rr", VALUE_REAL, 0, 1,
     "ALPHA   Russian roulette survival probability, 0 < ALPHA <= 1"},
    {FLAG_DEPTH, "--depth", VALUE_INT, 1, 1000, "N       maximum ray depth"},
    {FLAG_THREADS, "--threads", VALUE_INT, 0, 1024, "N       render threads; 0: one per core"},
    {FLAG_SEED, "--seed", VALUE_SEED, 0, 0,
     "N       random seed (the image is the same for every thread count)"},
    {FLAG_OUT, "--out", VALUE_TEXT, 0, 0, "DIR     directory for the figures"},
    {FLAG_QUIET, "--quiet", VALUE_NONE, 0, 0, "        no progress display"},
    {FLAG_FRESNEL, "--fresnel", VALUE_FRESNEL, 0, 0,
     "MODE    glass reflectance: schlick (the report's) or exact"},
    {FLAG_QUICK, "--quick", VALUE_NONE, 0, 0,
     "        small and fast, for a first look: a quarter of the size, and more runs"},
    {FLAG_REFERENCE_SPP, "--reference-spp", VALUE_INT, 1, 1 << 20,
     "N       samples per pixel of the reference image"},
    {FLAG_RUNS, "--runs", VALUE_INT, 1, CLI_RUNS_MAX,
     "N       independent runs (seeds) of each measured setting: its error is their mean and "
     "spread"},
    {FLAG_STRATA, "--strata", VALUE_SWITCH, 0, 0,
     "on|off  the final estimator's lamp points and bounces stratified across a pixel's "
     "samples"},
    {FLAG_TARGET_ERROR, "--target-error", VALUE_REAL, 0, 1,
     "E       render the main image in passes until its relative RMSE, estimated from its "
     "own samples, is at most E (0.01: 1 %), or --time is up; print what it cost"},
    {FLAG_TIME, "--time", VALUE_REAL, 0, DBL_MAX,
     "T       render the main image in passes for at most T seconds (or until --target-error "
     "is reached)"},
};
#define FLAG_SPEC_COUNT ((int)(sizeof FLAG_SPECS / sizeof FLAG_SPECS[0]))

void cli_fail(int status, const char *format, ...)
{
    va_list args;
    va_start(args, format);
    fprintf(stderr, "%s: ", cli_program);
    vfprintf(stderr, format, args);
    fputc('\n', stderr);
    va_end(args);
    exit(status);
}

static void print_default(const FlagSpec *spec, const Options *d)
{
    switch (spec->bit) {
    case FLAG_SCENE:
        printf(" (default %s)", d->scene);
        break;
    case FLAG_SIZE:
        printf(" (default %d)", d->size);
        break;
    case FLAG_SPP:
        printf(" (default %d)", d->spp);
        break;
    case FLAG_SHADOW_RAYS:
        printf(" (default %d)", d->shadow_rays);
        break;
    case FLAG_RR:
        printf(" (default %g)", d->rr);
        break;
    case FLAG_DEPTH:
        printf(" (default %d)", d->depth);
        break;
    case FLAG_THREADS:
        printf(" (default %d)", d->threads);
        break;
    case FLAG_SEED:
        printf(" (default %llu)", (unsigned long long)d->seed);
        break;
    case FLAG_OUT:
        printf(" (default %s)", d->out);
        break;
#if CHAPTER >= 4
    case FLAG_FRESNEL:
        printf(" (default %s)", d->fresnel == FRESNEL_EXACT ? "exact" : "schlick");
        break;
#endif
    case FLAG_REFERENCE_SPP:
        printf(" (default %d)", d->reference_spp);
        break;
    case FLAG_RUNS:
        printf(" (default %d; with --quick %d)", d->runs, CLI_QUICK_RUNS);
        break;
#if CHAPTER >= 7
    case FLAG_STRATA:
        printf(" (default %s)", d->strata ? "on" : "off");
        break;
    case FLAG_TARGET_ERROR:
    case FLAG_TIME:
        printf(" (default off)");
        break;
#endif
    default:
        break;
    }
}

static void print_usage(const ProgramInfo *info)
{
    printf("usage: %s [options]\n%s\n\noptions:\n", cli_program, info->summary);
    for (int i = 0; i < FLAG_SPEC_COUNT; i++) {
        const FlagSpec *spec = &FLAG_SPECS[i];
        if (!(info->flags & spec->bit))
            continue;
        printf("  %-15s %s", spec->name, spec->help);
        print_default(spec, &info->defaults);
        putchar('\n');
    }
    printf("  %-15s         this help\n", "--help");
}

/* Whether a flag's lowest value is left out of its range: --rr's, --target-error's and
 * --time's 0. */
static int open_below(const FlagSpec *spec)
{
    return spec->bit == FLAG_RR || spec->bit == FLAG_TARGET_ERROR || spec->bit == FLAG_TIME;
}

/* The range a flag takes, in words: "a whole number from 8 to 16384", "a number in
 * (0, 1]", "a number in (0, 1)". */
static void describe_range(const FlagSpec *spec, char *text, size_t size)
{
    if (spec->kind == VALUE_INT)
        snprintf(text, size, "a whole number from %.0f to %.0f", spec->min, spec->max);
    else if (spec->bit == FLAG_TARGET_ERROR)
        snprintf(text, size, "a number in (%g, %g)", spec->min, spec->max);
    else if (spec->bit == FLAG_TIME)
        snprintf(text, size, "a number of seconds above 0");
    else
        snprintf(text, size, "a number in %s%g, %g]", open_below(spec) ? "(" : "[", spec->min,
                 spec->max);
}

/* A whole number or a real in the flag's range, the whole text and nothing else, in
 * decimal; else exit naming what is wrong with it: empty, a space, not a decimal number
 * (hexadecimal, nan, inf, a lone sign), beyond a double's range either way (too large,
 * or below its smallest normal magnitude, where a subnormal keeps few digits), not
 * whole, or out of the range. */
static double parse_number(const FlagSpec *spec, const char *text)
{
    char range[96];
    describe_range(spec, range, sizeof range);
    char *end;
    errno = 0;
    double value = strtod(text, &end);
    int underflow =
        (errno == ERANGE && fabs(value) <= 1.0) || (value != 0.0 && fabs(value) < DBL_MIN);
    if (*text == '\0')
        cli_fail(2, "%s: expected %s, got an empty word", spec->name, range);
    if (strpbrk(text, " \t\n\v\f\r"))
        cli_fail(2, "%s: '%s' has white space in it; expected %s alone", spec->name, text,
                 range);
    if (*end != '\0' || strspn(text, "+-0123456789.eE") != strlen(text))
        cli_fail(2, "%s: '%s' is not a decimal number (such as 16, 0.25 or 1e-3); expected %s",
                 spec->name, text, range);
    if (underflow)
        cli_fail(2,
                 "%s: '%s' is too small to compute with (below %g, the smallest double "
                 "with all its digits); expected %s",
                 spec->name, text, DBL_MIN, range);
    if (errno == ERANGE)
        cli_fail(2, "%s: '%s' is too large for a double (above %g); expected %s", spec->name,
                 text, DBL_MAX, range);
    if (spec->kind == VALUE_INT && value != floor(value))
        cli_fail(2, "%s: '%s' is not a whole number; expected %s", spec->name, text, range);
    if (!(value >= spec->min && value <= spec->max) ||
        (open_below(spec) && !(value > spec->min)) ||
        (spec->bit == FLAG_TARGET_ERROR && !(value < spec->max)))
        cli_fail(2, "%s: expected %s, got '%s'", spec->name, range, text);
    return value;
}

static void set_value(const FlagSpec *spec, const char *text, Options *o)
{
    if (spec->kind == VALUE_INT || spec->kind == VALUE_REAL) {
        double value = parse_number(spec, text);
        switch (spec->bit) {
        case FLAG_SIZE:
            o->size = (int)value;
            break;
        case FLAG_SPP:
            o->spp = (int)value;
            break;
        case FLAG_SHADOW_RAYS:
            o->shadow_rays = (int)value;
            break;
        case FLAG_RR:
            o->rr = value;
            break;
        case FLAG_DEPTH:
            o->depth = (int)value;
            break;
        case FLAG_THREADS:
            o->threads = (int)value;
            break;
        case FLAG_REFERENCE_SPP:
            o->reference_spp = (int)value;
            break;
        case FLAG_RUNS:
            o->runs = (int)value;
            break;
#if CHAPTER >= 7
        case FLAG_TARGET_ERROR:
            o->target_error = value;
            break;
        case FLAG_TIME:
            o->time_limit = value;
            break;
#endif
        default:
            break;
        }
    } else if (spec->kind == VALUE_SEED) {
        char *end;
        errno = 0;
        unsigned long long seed = strtoull(text, &end, 10);
        if (*text < '0' || *text > '9' || *end != '\0' || errno != 0)
            cli_fail(2, "%s: expected a whole number from 0 to 2^64-1, got '%s'", spec->name,
                     text);
        o->seed = seed;
#if CHAPTER >= 4
    } else if (spec->kind == VALUE_FRESNEL) {
        if (strcmp(text, "schlick") == 0)
            o->fresnel = FRESNEL_SCHLICK;
        else if (strcmp(text, "exact") == 0)
            o->fresnel = FRESNEL_EXACT;
        else
            cli_fail(2, "%s: expected 'schlick' or 'exact', got '%s'", spec->name, text);
#endif
#if CHAPTER >= 7
    } else if (spec->kind == VALUE_SWITCH) {
        if (strcmp(text, "on") == 0)
            o->strata = 1;
        else if (strcmp(text, "off") == 0)
            o->strata = 0;
        else
            cli_fail(2, "%s: expected 'on' or 'off', got '%s'", spec->name, text);
#endif
    } else if (spec->kind == VALUE_TEXT) {
        if (*text == '\0')
            cli_fail(2, "%s: expected a path, got an empty word", spec->name);
        if (spec->bit == FLAG_SCENE)
            o->scene = text;
        else
            o->out = text;
    }
}

/* Every line a program prints is part of its result ("wrote PATH", the tables), so a
 * standard output that could not take them (a full disk, /dev/full) is a failure: found
 * at exit, reported, and the exit status made 1. */
static void check_standard_output(void)
{
    if (fflush(stdout) != 0 || ferror(stdout)) {
        fprintf(stderr, "%s: cannot write to standard output: %s\n", cli_program,
                strerror(errno ? errno : EIO));
        _exit(1);
    }
}

void cli_parse(int argc, char **argv, const ProgramInfo *info, Options *options)
{
    static int checking; /* once per program, however often it parses (the fuzz target) */
    if (!checking++)
        atexit(check_standard_output);
    const char *slash = argc > 0 ? strrchr(argv[0], '/') : NULL;
    if (argc > 0)
        cli_program = slash ? slash + 1 : argv[0];
    *options = info->defaults;
    options->given = 0;
    for (int i = 1; i < argc; i++) {
        const char *word = argv[i];
        if (strcmp(word, "--help") == 0 || strcmp(word, "-h") == 0) {
            print_usage(info);
            exit(0);
        }
        const char *equals = strchr(word, '=');
        size_t name_length = equals ? (size_t)(equals - word) : strlen(word);
        const FlagSpec *spec = NULL;
        for (int k = 0; k < FLAG_SPEC_COUNT; k++)
            if ((info->flags & FLAG_SPECS[k].bit) &&
                strlen(FLAG_SPECS[k].name) == name_length &&
                strncmp(FLAG_SPECS[k].name, word, name_length) == 0)
                spec = &FLAG_SPECS[k];
        if (!spec)
            cli_fail(2, "unknown option '%s' (see %s --help)", word, cli_program);
        options->given |= spec->bit;
        if (spec->kind == VALUE_NONE) {
            if (equals)
                cli_fail(2, "%s takes no value", spec->name);
            if (spec->bit == FLAG_QUIET)
                options->quiet = 1;
            else
                options->quick = 1;
            continue;
        }
        const char *value = equals ? equals + 1 : (i + 1 < argc ? argv[++i] : NULL);
        if (!value)
            cli_fail(2, "%s: missing value", spec->name);
        if (!equals && strncmp(value, "--", 2) == 0)
            cli_fail(2,
                     "%s: missing value (got the option '%s'; a value that starts with "
                     "'--' can be given as %s=VALUE)",
                     spec->name, value, spec->name);
        set_value(spec, value, options);
    }
    if (options->quick && !cli_given(options, FLAG_SIZE))
        options->size = cli_quarter(options->size, 16);
    if (options->quick && !cli_given(options, FLAG_RUNS) && (info->flags & FLAG_RUNS))
        options->runs = CLI_QUICK_RUNS;
}

int cli_quarter(int value, int smallest)
{
    int quarter = value / 4 > smallest ? value / 4 : smallest;
    return quarter < value ? quarter : value;
}
