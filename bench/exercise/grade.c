/* grade.c (bench, chapter 1): the exercise grader of one chapter (grading.h).
 *
 * Built from a chapter's library (the student's tree, or the solution) with that
 * chapter's table, bench/exercise/chapterN.c:
 *     grade --list                  each exercise: "ID FUNCTION"
 *     grade --blank ID              the body exercise ID starts from, under its task
 *     grade --reference ID FOLDER   render exercise ID's reference (from the solution)
 *     grade ID OUT REFERENCES       grade exercise ID: "PASS" or "FAIL: what is wrong" on
 *                                   the first line, the numbers behind it on the next
 *                                   ones; pictures into OUT; exit 0 (pass) or 1 (fail)
 * Bad use exits 2. bench/exercise/check.sh runs each exercise in a process of its own,
 * under a time limit, so that a crash or a hang is a verdict too.
 */
#include <stdio.h>
#include <string.h>

#include "grading.h"
#if CHAPTER >= 2
#include "render_check.h"
#endif

#define TASK_WIDTH 84

static const Exercise *find(const char *id)
{
    for (int i = 0; i < exercise_count; i++)
        if (strcmp(exercises[i].id, id) == 0)
            return &exercises[i];
    return NULL;
}

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
    fprintf(stderr, "usage: grade --list | --blank ID | --reference ID FOLDER | ID OUT "
                    "REFERENCES\n");
    return 2;
}

int main(int argc, char **argv)
{
    if (argc == 2 && strcmp(argv[1], "--list") == 0) {
        for (int i = 0; i < exercise_count; i++)
            printf("%s %s\n", exercises[i].id, exercises[i].function);
        return 0;
    }
    const Exercise *e = argc >= 3 ? find(argv[1][0] == '-' ? argv[2] : argv[1]) : NULL;
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
    if (argc != 4 || argv[1][0] == '-' || !e)
        return usage();
    Grading g;
    memset(&g, 0, sizeof g);
    g.id = e->id;
    g.out = argv[2];
    g.references = argv[3];
    e->grade(&g);
    if (g.failed)
        printf("FAIL: %s\n", g.message);
    else
        printf("PASS\n");
    fputs(g.numbers, stdout);
    return g.failed ? 1 : 0;
}
