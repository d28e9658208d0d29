/* probe.c (bench, chapter 1): the student's program, built from the student's library with
 * the chapter's table (grading.h):
 *     probe ID    run exercise ID's grader, sending every value the student's code computes
 *                 to the judge (grade --judge) on file descriptor 3, in frames that carry
 *                 the run's secret (answers.h), read first from descriptor 4; exit 0 once
 *                 all are sent; GRADE_SEED, as the judge's, chooses the random inputs
 * Bad use, or no secret, exits 2; a pipe that fails, 3.
 */
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "grading.h"

int main(int argc, char **argv)
{
    unsigned char secret[ANSWERS_SECRET];
    int have_secret = answers_read_secret(ANSWERS_SECRET_FD, secret) == 0;
    const Exercise *e = argc == 2 ? exercise_find(argv[1]) : NULL;
    if (!e || !have_secret) {
        fprintf(stderr,
                "usage: probe ID, the run's secret on descriptor %d (run by grade "
                "--judge)\n",
                ANSWERS_SECRET_FD);
        return 2;
    }
    setvbuf(stdout, NULL, _IOLBF, 0);
    static AnswerWriter writer;
    answer_writer_init(&writer, 3, secret, e->id);
    memset(secret, 0, sizeof secret);
    Grading g;
    memset(&g, 0, sizeof g);
    g.id = e->id;
    g.writer = &writer;
    char error[200];
    if (grading_seed_from_environment(&g.seed, error, sizeof error) != 0) {
        fprintf(stderr, "probe: %s\n", error);
        _exit(2);
    }
    exercise_grade(e, &g);
    int status = answer_end(&writer) == 0 ? 0 : 3;
    if (status != 0)
        perror("probe: cannot send the answers to the grader");
    /* At once: no student code runs after the answers (no atexit handler, no destructor). */
    fflush(NULL);
    _exit(status);
}
