/* probe.c (bench, chapter 1): the student's program, built from the student's library with
 * the chapter's table (grading.h):
 *     probe ID SECRET    run exercise ID's grader, sending every value the student's code
 *                        computes to the judge (grade --judge) on file descriptor 3, in
 *                        frames that carry SECRET (answers.h); exit 0 once all are sent
 * Bad use exits 2; a pipe that fails, 3.
 */
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "grading.h"

int main(int argc, char **argv)
{
    const Exercise *e = argc == 3 ? exercise_find(argv[1]) : NULL;
    unsigned char secret[ANSWERS_SECRET];
    if (!e || answers_parse_secret(argv[2], secret) != 0) {
        fprintf(stderr, "usage: probe ID SECRET (run by grade --judge)\n");
        return 2;
    }
    setvbuf(stdout, NULL, _IOLBF, 0);
    static AnswerWriter writer;
    answer_writer_init(&writer, 3, secret, e->id);
    Grading g;
    memset(&g, 0, sizeof g);
    g.id = e->id;
    g.writer = &writer;
    exercise_grade(e, &g);
    int status = answer_end(&writer) == 0 ? 0 : 3;
    if (status != 0)
        perror("probe: cannot send the answers to the grader");
    /* At once: no student code runs after the answers (no atexit handler, no destructor). */
    fflush(NULL);
    _exit(status);
}
