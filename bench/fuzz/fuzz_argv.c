/* fuzz_argv.c (bench, chapter 7): libFuzzer target for the command line of every chapter
 * program (cli.h).
 *
 * The input is one byte choosing which flags beyond FLAGS_COMMON the program takes
 * (each chapter's set is one of the 128), then the argument words, separated by NUL
 * bytes. cli_parse ends the program on --help (status 0) and on any error (status 2);
 * to run millions of command lines in one process, with coverage, the Makefile
 * compiles cli.c with its exit() renamed to fuzz_argv_exit, which jumps back here
 * (cli_parse allocates nothing, so nothing leaks). The parser's promises, checked so
 * that the fuzzer finds inputs that break them: it ends only with 0, after --help or
 * -h, or with 2; and a parse that returns has only flags the program takes, each value
 * in its flag's range, a flag not given at its default, and the paths either the
 * defaults or words of the command line, never empty.
 */
#include <float.h>
#include <setjmp.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"

#define WORDS_MAX 64

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
_Noreturn void fuzz_argv_exit(int status);

static jmp_buf parse_ended;

_Noreturn void fuzz_argv_exit(int status)
{
    longjmp(parse_ended, status + 1); /* never 0: setjmp's own return */
}

static const unsigned extra_flags[7] = {FLAG_SPP,
                                        FLAG_SHADOW_RAYS,
                                        FLAG_RR,
                                        FLAG_DEPTH,
                                        FLAG_FRESNEL,
                                        FLAG_REFERENCE_SPP,
                                        FLAG_TARGET_ERROR | FLAG_TIME};

static ProgramInfo program_taking(uint8_t choice)
{
    ProgramInfo info = {"fuzz",
                        FLAGS_COMMON,
                        {.scene = "scenes/room.scene",
                         .size = 800,
                         .spp = 64,
                         .shadow_rays = 4,
                         .rr = 0.75,
                         .depth = 64,
                         .seed = 1,
                         .out = "build/figures",
                         .reference_spp = 256}};
    for (int i = 0; i < 7; i++)
        if (choice & (1u << i))
            info.flags |= extra_flags[i];
    return info;
}

static int is_word(const char *text, char **argv, int argc)
{
    for (int i = 1; i < argc; i++)
        if (text >= argv[i] && text <= argv[i] + strlen(argv[i]))
            return 1;
    return 0;
}

static int in_range(double value, double low, double high)
{
    return value >= low && value <= high;
}

static void check_parsed(const Options *o, const ProgramInfo *info, char **argv, int argc)
{
    const Options *d = &info->defaults;
    if ((o->given & ~info->flags) != 0)
        abort();
    if (!in_range(o->size, 1, 16384) || !in_range(o->spp, 1, 1 << 20) ||
        !in_range(o->shadow_rays, 0, 1 << 16) || !(o->rr > 0.0 && o->rr <= 1.0) ||
        !in_range(o->depth, 1, 1000) || !in_range(o->threads, 0, 1024) ||
        !in_range(o->reference_spp, 1, 1 << 20) ||
        (o->fresnel != FRESNEL_SCHLICK && o->fresnel != FRESNEL_EXACT))
        abort();
    if ((cli_given(o, FLAG_TARGET_ERROR) ? !(o->target_error > 0.0 && o->target_error < 1.0)
                                         : o->target_error != 0.0) ||
        (cli_given(o, FLAG_TIME) ? !(o->time_limit > 0.0 && o->time_limit <= DBL_MAX)
                                 : o->time_limit != 0.0))
        abort();
    if ((!cli_given(o, FLAG_SPP) && o->spp != d->spp) ||
        (!cli_given(o, FLAG_SHADOW_RAYS) && o->shadow_rays != d->shadow_rays) ||
        (!cli_given(o, FLAG_RR) && o->rr != d->rr) ||
        (!cli_given(o, FLAG_DEPTH) && o->depth != d->depth) ||
        (!cli_given(o, FLAG_THREADS) && o->threads != d->threads) ||
        (!cli_given(o, FLAG_SEED) && o->seed != d->seed) ||
        (!cli_given(o, FLAG_FRESNEL) && o->fresnel != d->fresnel) ||
        (!cli_given(o, FLAG_QUIET) && o->quiet) || (!cli_given(o, FLAG_QUICK) && o->quick) ||
        (!cli_given(o, FLAG_SIZE) && !o->quick && o->size != d->size))
        abort();
    if (!*o->scene || !*o->out ||
        (cli_given(o, FLAG_SCENE) ? !is_word(o->scene, argv, argc) : o->scene != d->scene) ||
        (cli_given(o, FLAG_OUT) ? !is_word(o->out, argv, argc) : o->out != d->out))
        abort();
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size == 0)
        return 0;
    ProgramInfo info = program_taking(data[0]);
    char *text = malloc(size); /* the words, each ended by a NUL */
    char *argv[WORDS_MAX + 2] = {"ch0_fuzz"};
    int argc = 1, asked_for_help = 0;
    if (!text)
        return 0;
    memcpy(text, data + 1, size - 1);
    text[size - 1] = '\0';
    for (char *word = text; word < text + size - 1 && argc <= WORDS_MAX;
         word += strlen(word) + 1) {
        argv[argc++] = word;
        asked_for_help |= strcmp(word, "--help") == 0 || strcmp(word, "-h") == 0;
    }
    argv[argc] = NULL;
    Options options;
    int ended = setjmp(parse_ended);
    if (ended == 0) {
        cli_parse(argc, argv, &info, &options);
        check_parsed(&options, &info, argv, argc);
    } else if (!(ended - 1 == 2 || (ended - 1 == 0 && asked_for_help))) {
        abort();
    }
    free(text);
    return 0;
}
