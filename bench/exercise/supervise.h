/* supervise.h (bench, chapter 1): running a student's program under watch, for the grader.
 *
 * The grader (built from the solution: no student code runs in it) starts COMMAND... ID
 * (probe.c, alone or in bench/exercise/sandbox.sh) in a process group of its own, stdin
 * /dev/null, stdout and stderr into a pipe of which it keeps the start, the answers'
 * pipe (answers.h) as descriptor 3, the run's secret in a pipe as descriptor 4. It reads
 * until the end frame, the program's end or the time limit; then SIGTERM, a second's
 * grace and SIGKILL to the group and, as a child subreaper, to every process left behind.
 * A guard process between them takes the program's signals and reports how it ended.
 */
#ifndef SUPERVISE_H
#define SUPERVISE_H

#include <stddef.h>

#include "answers.h"

#define SUPERVISE_KEPT 65536 /* bytes of the program's output kept */
#define SUPERVISE_WORDS 62   /* words of a command at most */

typedef struct {
    AnswerReader answers; /* the values that came back */
    char ended[600];      /* why no more came, in words: the verdict if the grader asks for
                             more (a crash, an exit, the time limit, a garbled frame) */
    char *output;         /* what the program printed, its first SUPERVISE_KEPT bytes */
    size_t output_size, output_total;
} ProbeRun;

/* Run `command` (NULL-terminated words) with exercise `id` as its last word, for at most
 * `seconds`; an exit status of 128 + N is taken as signal N, as the sandbox (and a shell)
 * reports one. Returns 0 (whatever the program did), or -1 with a message in error[size]
 * when the grader itself cannot run it (no pipe, no fork). A SIGINT, SIGTERM or SIGHUP to the
 * grader meanwhile ends every process of the run, then the grader, by that signal. */
int supervise_probe(const char *const *command, const char *id, int seconds, ProbeRun *run,
                    char *error, size_t size);
void probe_run_free(ProbeRun *run);

#endif
