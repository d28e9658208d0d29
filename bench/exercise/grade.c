/* grade.c (bench, chapter 1): the exercise grader of one chapter (grading.h), built from
 * the solution's library with the chapter's table, bench/exercise/chapterN.c:
 *     grade --list | --blank ID | --reference ID FOLDER    the exercises, a blank body under
 *                                   its task, the solution's reference render
 *     grade --judge ID OUT REFERENCES SECONDS COMMAND...   run COMMAND... ID (probe.c, built
 *        from the student's library, in its sandbox) under watch (supervise.h) and grade its
 *        answers: "pass" or "FAIL: what is wrong", then the numbers behind it; pictures and
 *        what it printed into OUT; exit 0 or 1; GRADE_SEED (grading.h) chooses the random
 *        inputs, the probe's alike
 * Bad use, or a judge that cannot start its probe, exits 2.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "atomic_file.h"
#include "grading.h"
#include "supervise.h"
#if CHAPTER >= 2
#include "render_check.h"
#endif

#define TASK_WIDTH 84
#define QUOTED_LINES 3
#define QUOTED_WIDTH 100

/* The task as a comment, wrapped at spaces, then the neutral body, indented. */
static void print_blank(const Exercise *e)
{
    int column = printf("    /* Exercise %s.", e->id);
    for (const char *text = e->task; *text;) {
        text += strspn(text, " ");
        int word = (int)strcspn(text, " ");
        if (word == 0)
            break;
        if (column + 1 + word > TASK_WIDTH)
            column = printf("\n     *") - 1;
        column += printf(" %.*s", word, text);
        text += word;
    }
    printf(" */\n");
    for (const char *line = e->blank; *line;) {
        size_t length = strcspn(line, "\n");
        printf("    %.*s\n", (int)length, line);
        line += length + (line[length] == '\n');
    }
}

static int usage(void)
{
    fprintf(stderr, "usage: grade --list | --blank ID | --reference ID FOLDER | --judge ID OUT "
                    "REFERENCES SECONDS COMMAND...\n");
    return 2;
}

/* One line of what the program printed, its bytes made printable, cut at QUOTED_WIDTH;
 * returns where the next line begins. */
static const char *quote_line(const char *text, const char *end, char *quoted)
{
    const char *stop = memchr(text, '\n', (size_t)(end - text));
    stop = stop ? stop : end;
    long length = stop - text;
    int n = length < QUOTED_WIDTH ? (int)length : QUOTED_WIDTH;
    for (int i = 0; i < n; i++)
        quoted[i] = text[i] >= ' ' && text[i] < 127 ? text[i] : '?';
    strcpy(quoted + n, length > QUOTED_WIDTH ? "..." : "");
    return stop < end ? stop + 1 : end;
}

/* What the program printed, kept whole in OUT/exercise-ID.log, its first lines quoted
 * among the numbers (never read for a verdict). */
static void quote_output(Grading *g, const ProbeRun *run)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/exercise-%s.log", g->out, g->id);
    if (run->output_total == 0) {
        remove(path);
        return;
    }
    AtomicFile log;
    int kept = atomic_open(&log, path) == 0;
    if (kept) {
        fwrite(run->output, 1, run->output_size, log.file);
        if (run->output_total > run->output_size)
            fprintf(log.file, "\n[... %zu more bytes not kept]\n",
                    run->output_total - run->output_size);
        kept = atomic_close(&log, 0) == 0;
    }
    char bytes[32], where[64];
    snprintf(where, sizeof where, kept ? "exercise-%s.log" : "exercise-%s.log not written",
             g->id);
    grading_note(g, "your code printed %s bytes (%s), not read by the grader; they begin:",
                 grading_count((double)run->output_total, bytes, sizeof bytes), where);
    const char *text = run->output, *end = run->output + run->output_size;
    for (int line = 0; line < QUOTED_LINES && text < end; line++) {
        char quoted[QUOTED_WIDTH + 4];
        text = quote_line(text, end, quoted);
        grading_note(g, "| %s", quoted);
    }
}

/* The grader: run the probe, replay the grader on its answers, say the verdict. */
static int judge(const Exercise *e, int argc, char **argv)
{
    char *end;
    long seconds = strtol(argv[5], &end, 10);
    if (*end || seconds < 1 || seconds > 86400 || argc - 6 > SUPERVISE_WORDS)
        return usage();
    ProbeRun run;
    char error[512];
    uint64_t seed;
    if (grading_seed_from_environment(&seed, error, sizeof error) != 0) {
        fprintf(stderr, "grade: %s\n", error);
        return 2;
    }
    if (supervise_probe((const char *const *)argv + 6, e->id, (int)seconds, &run, error,
                        sizeof error) != 0) {
        fprintf(stderr, "grade: %s\n", error);
        probe_run_free(&run);
        return 2;
    }
    Grading g;
    memset(&g, 0, sizeof g);
    g.id = e->id;
    g.seed = seed;
    g.out = argv[3];
    g.references = argv[4];
    g.answers = &run.answers;
    g.ended = run.ended;
    exercise_grade(e, &g);
    if (!g.failed && !run.answers.ended)
        grading_fail(&g, "%s", run.ended);
    else if (!g.failed && g.next < run.answers.count)
        grading_fail(&g,
                     "your program gave %ld answers where the grader asked for %ld: has a "
                     "function outside the exercises changed?",
                     run.answers.count, g.next);
    quote_output(&g, &run);
    probe_run_free(&run);
    if (g.failed)
        printf("FAIL: %s\n", g.message);
    else
        printf("pass\n");
    fputs(g.numbers, stdout);
    return g.failed ? 1 : 0;
}

int main(int argc, char **argv)
{
    const Exercise *e = argc >= 3 ? exercise_find(argv[2]) : NULL;
    if (argc == 2 && strcmp(argv[1], "--list") == 0) {
        for (int i = 0; i < exercise_count; i++)
            printf("%s %s\n", exercises[i].id, exercises[i].function);
        return 0;
    }
    if (argc == 3 && strcmp(argv[1], "--blank") == 0 && e) {
        print_blank(e);
        return 0;
    }
    if (argc == 4 && strcmp(argv[1], "--reference") == 0 && e) {
        if (!e->render)
            return 0;
#if CHAPTER >= 2
        char error[512];
        if (render_check_reference(e, argv[3], error, sizeof error) != 0) {
            fprintf(stderr, "grade: %s\n", error);
            return 1;
        }
#endif
        return 0;
    }
    if (argc >= 7 && strcmp(argv[1], "--judge") == 0 && e)
        return judge(e, argc, argv);
    return usage();
}
