/* test_grader.c (bench, chapter 8): a grader that no student code can fool or stop.
 *
 * Exercise 1.1 is graded through make check-exercise-chapter1 (ONLY=1.1, TIME_LIMIT=1)
 * in chapter 1's blank tree and in its solution, each with student_behaviours.c among
 * its lib files. For every behaviour the verdict must be what the answers deserve (the
 * blank fails, in words naming what happened; the solution passes), in the verdicts file
 * too, within TIME_LIMIT + 5 s, and no process of the run may be left. Then trees whose
 * paths hold a space, an apostrophe or a leading dash, and a reader that stops after
 * the first line.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include "run_command.h"

#include <dirent.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#define LIMIT 1   /* TIME_LIMIT, seconds */
#define SLACK 5.0 /* seconds a verdict may take beyond it */

#define GARBLED "FAIL: your program's answers arrived garbled after 0 (frame 0 "

typedef struct {
    const char *behaviour; /* GRADER_BEHAVIOUR (student_behaviours.c) */
    const char *tree;      /* "blank", "solution", or "scratch" (a copy of the blank one) */
    const char *verdict;   /* how the verdict must begin */
} Case;

static const Case cases[] = {
    {"", "blank", "FAIL: misses a ray"},
    {"exit", "blank", "FAIL: your program ended with exit status 0 before answering"},
    {"fork-then-exit", "blank", "FAIL: your program ended with exit status 0 before answering"},
    {"constructor-exit", "blank",
     "FAIL: your program ended with exit status 0 before answering"},
    {"atexit", "blank", "FAIL: your program ended with exit status 0"},
    {"exec-true", "blank", "FAIL: your program ended with exit status 0"},
    {"segv-handler-exit", "blank", "FAIL: your program ended with exit status 0"},
    {"print-pass", "blank", "FAIL: misses a ray"},
    {"print-verdict", "blank", "FAIL: misses a ray"},
    {"fork-sleep", "blank", "FAIL: misses a ray"},
    {"setsid-double-fork", "blank", "FAIL: misses a ray"},
    {"new-group", "blank", "FAIL: misses a ray"},
    {"shell-background", "blank", "FAIL: misses a ray"},
    {"ignore-term-loop", "blank", "FAIL: no answer within 1 second:"},
    {"stop-self", "blank", "FAIL: no answer within 1 second:"},
    {"flood-forever", "blank", "FAIL: no answer within 1 second:"},
    {"flood", "blank", "FAIL: misses a ray"},
    {"stdin", "blank", "FAIL: misses a ray"},
    {"close-channel", "blank", "FAIL: your program ended with exit status 3"},
    {"close-all", "blank", "FAIL: your program ended with exit status 3"},
    {"dup-channel", "blank", "FAIL: your program ended with exit status 0 before answering"},
    {"garbage-channel", "blank", GARBLED "is not a frame of the grader's)"},
    {"forge-everywhere", "blank", GARBLED "does not carry this run's secret)"},
    {"end-with-the-secret", "blank", "FAIL: your program gave 0 answers"},
    {"other-exercise", "blank", GARBLED "answers another exercise)"},
    {"damaged-frame", "blank", GARBLED "is damaged: its checksum does not match)"},
    {"partial-frame", "blank", "FAIL: your program ended with exit status 0 before answering"},
    {"raise-kill", "blank", "FAIL: killed by SIGKILL"},
    {"abort", "blank", "FAIL: crashed: aborted"},
    {"segfault", "blank", "FAIL: crashed: a segmentation fault"},
    {"kill-group", "blank", "FAIL: stopped by signal 15"},
    {"kill-group-kill", "blank", "FAIL: the grader's guard over your program was killed"},
    {"kill-parent", "blank", "FAIL: misses a ray"},
    {"kill-parent-kill", "blank", "FAIL: the grader's guard over your program was killed"},
    {"kill-grader", "blank", "FAIL: the grader was stopped"},
    {"nan", "blank", "FAIL: t is NaN"},
    {"chdir", "blank", "FAIL: misses a ray"},
    {"delete-check", "scratch", "FAIL: misses a ray"},
    {"write-verdicts", "blank", "FAIL: misses a ray"},
    {"", "solution", "pass"},
    {"print-fail", "solution", "pass"},
    {"print-verdict", "solution", "pass"},
    {"fork-sleep", "solution", "pass"},
    {"setsid-double-fork", "solution", "pass"},
    {"shell-background", "solution", "pass"},
    {"kill-parent", "solution", "pass"},
    {"flood", "solution", "pass"},
};
#define CASES (int)(sizeof cases / sizeof cases[0])

static char build[1024], root[1100], mark[64];

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* `text` in single quotes for the shell. */
static const char *quoted(const char *text, char *out, size_t size)
{
    size_t n = 0;
    out[n++] = '\'';
    for (; *text && n + 5 < size; text++) {
        if (*text == '\'') {
            memcpy(out + n, "'\\''", 4);
            n += 4;
        } else
            out[n++] = *text;
    }
    out[n++] = '\'';
    out[n] = '\0';
    return out;
}

static void shell(const char *format, ...)
{
    char command[8192];
    va_list args;
    va_start(args, format);
    vsnprintf(command, sizeof command, format, args);
    va_end(args);
    if (system(command) != 0)
        fail_msg("failed: %s", command);
}

/* Grade exercises ONLY of the tree STUDENT (as make is given it) with `behaviour`,
 * every process of it marked in its environment. `pipe_to`: a command the output goes
 * through (or ""). Returns make's exit status; the output in *out, the time in *seconds. */
static int check(const char *student, const char *behaviour, const char *only,
                 const char *pipe_to, char **out, double *seconds)
{
    char command[8192], q_student[2200], q_behaviour[200], q_only[100];
    snprintf(
        command, sizeof command,
        "env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL GRADER_TEST_MARK=%s GRADER_BEHAVIOUR=%s "
        "TIME_LIMIT=%d ASAN_OPTIONS=handle_segv=0:handle_abort=0 make --no-print-directory "
        "-s BUILD=%s check-exercise-chapter1 STUDENT=%s ONLY=%s 2>&1 %s",
        mark, quoted(behaviour, q_behaviour, sizeof q_behaviour), LIMIT, build,
        quoted(student, q_student, sizeof q_student), quoted(only, q_only, sizeof q_only),
        pipe_to);
    double start = now();
    int status = run_command(command, out);
    *seconds = now() - start;
    return status;
}

/* Processes alive with this test's mark in their environment; each is killed when `kill_them`.
 */
static int marked(int kill_them)
{
    char wanted[128];
    int found = 0;
    snprintf(wanted, sizeof wanted, "GRADER_TEST_MARK=%s", mark);
    DIR *proc = opendir("/proc");
    assert_non_null(proc);
    struct dirent *entry;
    while ((entry = readdir(proc)) != NULL) {
        char *end, path[300];
        long pid = strtol(entry->d_name, &end, 10);
        if (*end || pid <= 0 || pid == (long)getpid())
            continue;
        snprintf(path, sizeof path, "/proc/%ld/environ", pid);
        FILE *file = fopen(path, "rb");
        if (!file)
            continue;
        static char environment[1 << 20];
        size_t n = fread(environment, 1, sizeof environment - 1, file);
        fclose(file);
        for (size_t at = 0; at < n; at += strlen(environment + at) + 1)
            if (strcmp(environment + at, wanted) == 0) {
                found++;
                if (kill_them)
                    kill((pid_t)pid, SIGKILL);
                break;
            }
    }
    closedir(proc);
    return found;
}

/* The processes of the run still alive a fifth of a second after it (one already
 * killed may take a moment to go); each is killed. */
static int survivors(void)
{
    if (marked(0) == 0)
        return 0;
    struct timespec moment = {0, 200000000};
    nanosleep(&moment, NULL);
    return marked(1);
}

static char *read_text(const char *path)
{
    FILE *file = fopen(path, "rb");
    if (!file)
        return NULL;
    static char text[1 << 20];
    size_t n = fread(text, 1, sizeof text - 1, file);
    fclose(file);
    text[n] = '\0';
    return text;
}

/* The line of exercise `id`'s verdict in `text`, or "". */
static const char *verdict_of(const char *text, const char *id, char *line, size_t size)
{
    char prefix[64];
    snprintf(prefix, sizeof prefix, "\nexercise %s (", id);
    const char *at = text ? strstr(text, prefix) : NULL;
    line[0] = '\0';
    if (at) {
        at = strstr(at, "): ") + 3;
        snprintf(line, size, "%.*s", (int)strcspn(at, "\n"), at);
    }
    return line;
}

/* Grade one case and judge the grading: the verdict and its file, the time, what is
 * left. Returns 1 when all is as it must be, printing a line either way. */
static int graded_as_expected(const char *label, const char *student, const char *tree,
                              const char *behaviour, const char *expected)
{
    char *out, line[2048], file_line[2048], path[2200];
    double seconds;
    int status = check(student, behaviour, "1.1", "", &out, &seconds);
    int left = survivors();
    snprintf(path, sizeof path, "%s/check/verdicts.txt", tree);
    const char *file = read_text(path);
    verdict_of(out, "1.1", line, sizeof line);
    verdict_of(file, "1.1", file_line, sizeof file_line);
    int passes = strcmp(expected, "pass") == 0;
    int ok = strstr(line, expected) == line && strcmp(line, file_line) == 0 &&
             (passes ? status == 0 : status != 0) && file && strstr(file, "chapter 1: ") &&
             seconds <= LIMIT + SLACK && left == 0;
    printf("%-4s %-28s %5.1f s  %s  %s\n", ok ? "ok" : "BAD", label, seconds,
           left ? "PROCESSES LEFT" : "none left", line);
    if (!ok)
        printf("    expected \"%s\" (status %d; file's verdict \"%s\"); the output:\n%s\n",
               expected, status, file_line, out);
    free(out);
    return ok;
}

static void make_tree(const char *tree, const char *source)
{
    shell("rm -rf '%s' && cp -R '%s' '%s' && "
          "cp bench/tests/student_behaviours.c '%s/lib/zz_behaviours.c'",
          tree, source, tree, tree);
    shell("sed -i 's/^double sphere_intersect(/double original_sphere_intersect(/' "
          "'%s/lib/sphere.c' && "
          "printf '%%s\\n' 'double student_behaviour(double answer);' "
          "'double sphere_intersect(const Sphere *sphere, Ray ray, double tmin, double tmax)' "
          "'{' "
          "'    return student_behaviour(original_sphere_intersect(sphere, ray, tmin, tmax));' "
          "'}' "
          ">> '%s/lib/sphere.c'",
          tree, tree);
    char *out;
    double seconds;
    check(tree, "", "1.1", "", &out, &seconds); /* builds it */
    free(out);
}

static int setup(void **state)
{
    (void)state;
    snprintf(build, sizeof build, "%s",
             getenv("CHAPTER_DIR") ? getenv("CHAPTER_DIR") : "build");
    snprintf(root, sizeof root, "%s/exercise/grader-test", build);
    snprintf(mark, sizeof mark, "%ld-%ld", (long)getpid(), (long)time(NULL));
    shell(
        "rm -rf '%s' && mkdir -p '%s' && sh bench/exercise/exercise.sh 1 '%s/source/chapter1' "
        "'%s/chapter1/bench/exercise/grade' '%s/blank-source' > /dev/null",
        root, root, build, build, root);
    char tree[1300], source[1300];
    snprintf(tree, sizeof tree, "%s/blank", root);
    snprintf(source, sizeof source, "%s/blank-source", root);
    make_tree(tree, source);
    snprintf(tree, sizeof tree, "%s/solution", root);
    snprintf(source, sizeof source, "%s/source/chapter1", build);
    make_tree(tree, source);
    shell("cp -Rp '%s/blank' '%s/scratch'", root, root);
    return 0;
}

static void test_behaviours(void **state)
{
    (void)state;
    int good = 0;
    for (int i = 0; i < CASES; i++) {
        const Case *c = &cases[i];
        char tree[1300], label[100];
        snprintf(tree, sizeof tree, "%s/%s", root, c->tree);
        snprintf(label, sizeof label, "%s %s", c->tree,
                 c->behaviour[0] ? c->behaviour : "(as it is)");
        good += graded_as_expected(label, tree, tree, c->behaviour, c->verdict);
    }
    printf("%d of %d behaviours graded as their answers deserve, in time, nothing left\n", good,
           CASES);
    assert_int_equal(good, CASES);
}

/* Trees at awkward paths: a space, an apostrophe, and (through a link in the top folder,
 * where make resolves relative paths) a leading dash. */
static void test_paths(void **state)
{
    (void)state;
    const char *names[] = {"with space", "it's"};
    char tree[1400], blank[1300], link[100];
    snprintf(blank, sizeof blank, "%s/blank", root);
    int good = 0;
    for (int i = 0; i < 2; i++) {
        snprintf(tree, sizeof tree, "%s/%s", root, names[i]);
        char q_tree[3000];
        shell("rm -rf %s && cp -Rp '%s' %s", quoted(tree, q_tree, sizeof q_tree), blank,
              quoted(tree, q_tree, sizeof q_tree));
        good += graded_as_expected(names[i], tree, tree, "", "FAIL: misses a ray");
    }
    snprintf(tree, sizeof tree, "%s/dash", root);
    snprintf(link, sizeof link, "-grader-test-%ld", (long)getpid());
    shell("rm -rf '%s' && cp -Rp '%s' '%s' && ln -s \"$PWD\"/'%s' ./%s", tree, blank, tree,
          tree, link);
    int dash = graded_as_expected(link, link, tree, "", "FAIL: misses a ray");
    shell("rm -f ./%s", link);
    assert_int_equal(good + dash, 3);
}

/* `| head -1`: the reader goes after one line; the verdicts file is still whole. */
static void test_reader_that_stops(void **state)
{
    (void)state;
    char tree[1300], path[1400], *out, line[2048];
    double seconds;
    snprintf(tree, sizeof tree, "%s/blank", root);
    snprintf(path, sizeof path, "%s/check/verdicts.txt", tree);
    check(tree, "", "1.1 1.4", "| head -n 1", &out, &seconds);
    const char *file = read_text(path);
    printf("| head -1: printed \"%.*s\"; the verdicts file has %s\n", (int)strcspn(out, "\n"),
           out, file ? verdict_of(file, "1.4", line, sizeof line) : "(no file)");
    assert_non_null(strstr(out, "chapter 1: checking"));
    assert_null(strchr(out, '\n') ? strchr(strchr(out, '\n') + 1, '\n') : NULL);
    assert_non_null(file);
    assert_non_null(strstr(file, "exercise 1.4 (mirror_reflect): FAIL: "));
    assert_non_null(strstr(file, "chapter 1: 0 of 2 exercises pass"));
    assert_int_equal(survivors(), 0);
    free(out);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_behaviours),
        cmocka_unit_test(test_paths),
        cmocka_unit_test(test_reader_that_stops),
    };
    return cmocka_run_group_tests(tests, setup, NULL);
}
