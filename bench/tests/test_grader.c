/* test_grader.c (bench, chapter 8): a grader that no student code can fool, stop or escape.
 *
 * Exercise 1.1 is graded through make check-exercise-chapter1 (ONLY=1.1, TIME_LIMIT=1) in
 * chapter 1's blank tree and its solution, each with student_behaviours.c among its lib
 * files. Each behaviour's verdict must be what the answers deserve, in words naming what
 * happened, in the verdicts file too, in time, what it printed as expected, no process
 * left and the judge untouched. Then awkward paths, a reader that stops, what the tree
 * ships (make fragments, links out), trees that are not trees, a judge and a reference
 * replaced, a full disk (as root) and a class graded with make grade-class.
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
    const char *printed;   /* what check/exercise-1.1.log must hold, or NULL */
} Case;

#define SEGV_MEMORY                                                                            \
    "FAIL: crashed: a segmentation fault (an index outside an array, a NULL or "               \
    "uninitialised pointer: a malloc the sandbox's memory limit refused?)"
#define KEPT_OUT(what)                                                                         \
    {                                                                                          \
        "reach:" what, "blank", "FAIL: misses a ray", "kept out of " what "\n"                 \
    }

static const Case cases[] = {
    {"", "blank", "FAIL: misses a ray", NULL},
    {"exit", "blank", "FAIL: your program ended with exit status 0 before answering", NULL},
    {"fork-then-exit", "blank", "FAIL: your program ended with exit status 0 before answering",
     NULL},
    {"constructor-exit", "blank",
     "FAIL: your program ended with exit status 0 before answering", NULL},
    {"atexit", "blank", "FAIL: your program ended with exit status 0", NULL},
    {"exec-true", "blank", "FAIL: your program ended with exit status 0", NULL},
    {"segv-handler-exit", "blank", "FAIL: your program ended with exit status 0", NULL},
    {"print-pass", "blank", "FAIL: misses a ray", NULL},
    {"print-verdict", "blank", "FAIL: misses a ray", NULL},
    {"fork-sleep", "blank", "FAIL: misses a ray", NULL},
    {"setsid-double-fork", "blank", "FAIL: misses a ray", NULL},
    {"new-group", "blank", "FAIL: misses a ray", NULL},
    {"shell-background", "blank", "FAIL: misses a ray", NULL},
    {"ignore-term-loop", "blank", "FAIL: no answer within 1 second:", NULL},
    {"stop-self", "blank", "FAIL: no answer within 1 second:", NULL},
    {"flood-forever", "blank", "FAIL: no answer within 1 second:", NULL},
    {"flood", "blank", "FAIL: misses a ray", NULL},
    {"stdin", "blank", "FAIL: misses a ray", NULL},
    {"close-channel", "blank", "FAIL: your program ended with exit status 3", NULL},
    {"close-all", "blank", "FAIL: your program ended with exit status 3", NULL},
    {"dup-channel", "blank", "FAIL: your program ended with exit status 0 before answering",
     NULL},
    {"garbage-channel", "blank", GARBLED "is not a frame of the grader's)", NULL},
    {"forge-everywhere", "blank", GARBLED "does not carry this run's secret)", NULL},
    {"end-with-the-secret", "blank", "FAIL: your program gave 0 answers", NULL},
    {"other-exercise", "blank", GARBLED "answers another exercise)", NULL},
    {"damaged-frame", "blank", GARBLED "is damaged: its checksum does not match)", NULL},
    {"partial-frame", "blank", "FAIL: your program ended with exit status 0 before answering",
     NULL},
    {"raise-kill", "blank", "FAIL: killed by SIGKILL", NULL},
    {"abort", "blank", "FAIL: crashed: aborted", NULL},
    {"segfault", "blank", "FAIL: crashed: a segmentation fault", NULL},
    {"kill-group", "blank", "FAIL: stopped by signal 15", NULL},
    {"kill-group-kill", "blank", "FAIL: killed by SIGKILL", NULL},
    {"kill-parent", "blank", "FAIL: misses a ray", NULL},
    {"kill-parent-kill", "blank", "FAIL: no answer within 1 second:", NULL},
    {"kill-grader", "blank", "FAIL: killed by SIGKILL", NULL},
    {"nan", "blank", "FAIL: t is NaN", NULL},
    {"chdir", "blank", "FAIL: misses a ray", NULL},
    {"delete-check", "scratch", "FAIL: misses a ray", NULL},
    {"write-verdicts", "blank", "FAIL: misses a ray", NULL},
    {"exec-solution-probe", "blank", "FAIL: misses a ray", "no judge in sight in /proc"},
    {"replace-judge", "blank", "FAIL: misses a ray", "no judge in sight in /proc"},
    {"malloc-20g", "blank", SEGV_MEMORY, NULL},
    {"fork-bomb", "blank", "FAIL: misses a ray", "children of 2000"},
    {"huge-file", "blank",
     "FAIL: crashed: a file grew past the sandbox's limit on a file's size, before "
     "answering",
     NULL},
    KEPT_OUT("tree"),
    KEPT_OUT("repo-build"),
    KEPT_OUT("solution-source"),
    KEPT_OUT("judge-by-path"),
    KEPT_OUT("judge-via-proc"),
    KEPT_OUT("references"),
    KEPT_OUT("home"),
    KEPT_OUT("network"),
    KEPT_OUT("processes"),
    KEPT_OUT("environment"),
    KEPT_OUT("host-tmp"),
    KEPT_OUT("box"),
    KEPT_OUT("signal-outside"),
    {"", "solution", "pass", NULL},
    {"print-fail", "solution", "pass", NULL},
    {"print-verdict", "solution", "pass", NULL},
    {"fork-sleep", "solution", "pass", NULL},
    {"setsid-double-fork", "solution", "pass", NULL},
    {"shell-background", "solution", "pass", NULL},
    {"kill-parent", "solution", "pass", NULL},
    {"flood", "solution", "pass", NULL},
    {"fork-bomb", "solution", "pass", "children of 2000"},
};
#define CASES (int)(sizeof cases / sizeof cases[0])

static char build[1024], abs_build[2100], repo[1024], root[1100], abs_root[2200], mark[64],
    host_mark[100];

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

/* What the behaviours may see of the machine (student_behaviours.c): the test's own
 * variables, named in SANDBOX_ENV, and one that must not reach them. */
static const char *test_environment(const char *student, char *text, size_t size)
{
    char tree[1400], q_tree[3000];
    snprintf(tree, sizeof tree, "%s%s%s", student[0] == '/' ? "" : repo,
             student[0] == '/' ? "" : "/", student);
    snprintf(text, size,
             "GRADER_TEST_MARK=%s GRADER_TREE=%s GRADER_REPO='%s' GRADER_JUDGE='%s/chapter1/"
             "bench/exercise/grade' GRADER_REFERENCES='%s/exercise/references/chapter1' "
             "GRADER_HOST_MARK='%s' GRADER_TEST_PID=%ld GRADER_TEST_PRIVATE=1 "
             "SANDBOX_ENV='GRADER_BEHAVIOUR GRADER_TEST_MARK GRADER_TREE GRADER_REPO "
             "GRADER_JUDGE GRADER_REFERENCES GRADER_HOST_MARK GRADER_TEST_PID STUDENT'",
             mark, quoted(tree, q_tree, sizeof q_tree), repo, abs_build, abs_build, host_mark,
             (long)getpid());
    return text;
}

/* Grade exercises ONLY of chapter `chapter` in the tree STUDENT (as make is given it) with
 * `behaviour`, every process of it marked in its environment; `extra`: more for make's
 * command line (or ""); `pipe_to`: a command the output goes through (or ""). Returns
 * make's exit status; the output in *out, the time in *seconds. */
static int grade(int chapter, const char *student, const char *behaviour, const char *only,
                 const char *extra, const char *pipe_to, char **out, double *seconds)
{
    char command[16384], q_student[2200], q_behaviour[200], q_only[100], environment[8192];
    snprintf(command, sizeof command,
             "env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL %s GRADER_BEHAVIOUR=%s TIME_LIMIT=%d "
             "ASAN_OPTIONS=handle_segv=0:handle_abort=0 make --no-print-directory -s "
             "BUILD=%s check-exercise-chapter%d STUDENT=%s ONLY=%s %s 2>&1 %s",
             test_environment(student, environment, sizeof environment),
             quoted(behaviour, q_behaviour, sizeof q_behaviour), LIMIT, build, chapter,
             quoted(student, q_student, sizeof q_student), quoted(only, q_only, sizeof q_only),
             extra, pipe_to);
    double start = now();
    int status = run_command(command, out);
    *seconds = now() - start;
    return status;
}

static int check(const char *student, const char *behaviour, const char *only,
                 const char *pipe_to, char **out, double *seconds)
{
    return grade(1, student, behaviour, only, "", pipe_to, out, seconds);
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

/* The file's text (the last two read stay valid), or NULL. */
static char *read_text(const char *path)
{
    FILE *file = fopen(path, "rb");
    if (!file)
        return NULL;
    static char texts[2][1 << 20];
    static int next;
    char *text = texts[next++ % 2];
    size_t n = fread(text, 1, sizeof texts[0] - 1, file);
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

/* Whether chapter 1's judge is still the program make built (its recorded checksum). */
static int judge_intact(void)
{
    char command[4200];
    snprintf(command, sizeof command,
             "cd '%s/chapter1/bench/exercise' && "
             "[ \"$(sha256sum < grade | cut -c 1-64)\" = \"$(cut -c 1-64 grade.sha256)\" ]",
             build);
    return system(command) == 0;
}

/* Grade one case and judge the grading: the verdict and its file, what the program
 * printed (`printed`, or NULL), the time, what is left, the judge. Returns 1 when all is
 * as it must be, printing a line either way. */
static int graded_as_expected(const char *label, const char *student, const char *tree,
                              const char *behaviour, const char *expected, const char *printed)
{
    char *out, line[2048], file_line[2048], path[2200];
    double seconds;
    int status = check(student, behaviour, "1.1", "", &out, &seconds);
    int left = survivors();
    snprintf(path, sizeof path, "%s/check/verdicts.txt", tree);
    const char *file = read_text(path);
    verdict_of(out, "1.1", line, sizeof line);
    verdict_of(file, "1.1", file_line, sizeof file_line);
    snprintf(path, sizeof path, "%s/check/exercise-1.1.log", tree);
    const char *log = printed ? read_text(path) : NULL;
    int passes = strcmp(expected, "pass") == 0;
    int intact = judge_intact();
    int ok = strstr(line, expected) == line && strcmp(line, file_line) == 0 &&
             (passes ? status == 0 : status != 0) && file && strstr(file, "chapter 1: ") &&
             seconds <= LIMIT + SLACK && left == 0 && intact &&
             (!printed || (log && strstr(log, printed) && !strstr(log, "reached ") &&
                           !strstr(log, "started 2000 ")));
    printf("%-4s %-28s %5.1f s  %s  %s\n", ok ? "ok" : "BAD", label, seconds,
           left ? "PROCESSES LEFT" : "none left", line);
    if (!ok)
        printf("    expected \"%s\"%s%s (status %d; file's verdict \"%s\"%s); printed: %.300s; "
               "the output:\n%s\n",
               expected, printed ? ", printing " : "", printed ? printed : "", status,
               file_line, intact ? "" : "; THE JUDGE WAS CHANGED", log ? log : "(nothing)",
               out);
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
    assert_non_null(getcwd(repo, sizeof repo));
    snprintf(abs_build, sizeof abs_build, "%s%s%s", build[0] == '/' ? "" : repo,
             build[0] == '/' ? "" : "/", build);
    snprintf(abs_root, sizeof abs_root, "%s/exercise/grader-test", abs_build);
    snprintf(host_mark, sizeof host_mark, "/tmp/grader-host-mark-%s", mark);
    shell("echo host > '%s'", host_mark);
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
        good += graded_as_expected(label, tree, tree, c->behaviour, c->verdict, c->printed);
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
        good += graded_as_expected(names[i], tree, tree, "", "FAIL: misses a ray", NULL);
    }
    snprintf(tree, sizeof tree, "%s/dash", root);
    snprintf(link, sizeof link, "-grader-test-%ld", (long)getpid());
    shell("rm -rf '%s' && cp -Rp '%s' '%s' && ln -s \"$PWD\"/'%s' ./%s", tree, blank, tree,
          tree, link);
    int dash = graded_as_expected(link, link, tree, "", "FAIL: misses a ray", NULL);
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

/* A tree that ships make fragments (dependency files with $(shell ...), a rule) where the
 * old grader's make read them: none runs, nothing is left. */
static void test_shipped_make_fragments(void **state)
{
    (void)state;
    char tree[1300], planted[2300], *out, line[2048];
    double seconds;
    snprintf(tree, sizeof tree, "%s/fragments", root);
    snprintf(planted, sizeof planted, "%s/planted-by-a-fragment", abs_root);
    shell("rm -rf '%s' '%s' && cp -Rp '%s/blank' '%s' && mkdir -p '%s/check/build/lib' && "
          "for name in sphere zz_behaviours camera; do printf '%%s\\n' "
          "'$(shell touch %s; sleep 300 &)' "
          "'check/build/probe: ; cp %s/chapter1/bench/exercise/probe $@' "
          "> '%s/check/build/lib/'$name.d; done",
          tree, planted, root, tree, tree, planted, abs_build, tree);
    int status = check(tree, "", "1.1", "", &out, &seconds);
    verdict_of(out, "1.1", line, sizeof line);
    int left = survivors();
    printf("shipped .d files: %s; %s; %d processes left\n", line,
           access(planted, F_OK) == 0 ? "A FRAGMENT RAN" : "none ran", left);
    assert_int_not_equal(status, 0);
    assert_non_null(strstr(line, "FAIL: misses a ray"));
    assert_int_not_equal(access(planted, F_OK), 0);
    assert_int_equal(left, 0);
    free(out);
}

/* check/, check/build or check/build.log a link out of the tree: refused by name, and
 * what they point at untouched. */
static void test_links_out_of_the_tree(void **state)
{
    (void)state;
    const char *links[] = {"check", "check/build", "check/build.log"};
    char tree[1300], outside[2300], *out;
    double seconds;
    snprintf(tree, sizeof tree, "%s/links", root);
    snprintf(outside, sizeof outside, "%s/outside", abs_root);
    for (int i = 0; i < 3; i++) {
        shell(
            "rm -rf '%s' '%s' && cp -Rp '%s/blank' '%s' && mkdir -p '%s/folder' '%s/check' && "
            "echo keep > '%s/file' && echo keep > '%s/folder/file' && rm -rf '%s/%s' && "
            "ln -s '%s/%s' '%s/%s'",
            tree, outside, root, tree, outside, tree, outside, outside, tree, links[i], outside,
            i == 2 ? "file" : "folder", tree, links[i]);
        int status = check(tree, "", "1.1", "", &out, &seconds);
        char wanted[1400];
        snprintf(wanted, sizeof wanted, "%s is a symbolic link", links[i]);
        char command[8000];
        snprintf(command, sizeof command,
                 "[ \"$(cat '%s/file')\" = keep ] && [ \"$(ls '%s/folder')\" = file ] && "
                 "[ \"$(cat '%s/folder/file')\" = keep ]",
                 outside, outside, outside);
        int untouched = system(command) == 0;
        printf("%s a link: status %d, %s; outside %s\n", links[i], status,
               strstr(out, wanted) ? "refused by name" : "NOT REFUSED",
               untouched ? "untouched" : "CHANGED");
        assert_int_equal(status, 2);
        assert_non_null(strstr(out, wanted));
        assert_true(untouched);
        free(out);
    }
}

/* STUDENT=/ (or a link to it), or the repository itself: not a tree, whatever it holds. */
static void test_not_a_tree(void **state)
{
    (void)state;
    char link[1300], *out;
    double seconds;
    snprintf(link, sizeof link, "%s/root-link", root);
    shell("rm -f '%s' && ln -s / '%s'", link, link);
    const char *students[] = {"/", link, ".", repo};
    const char *words[] = {"is the whole file system", "is the whole file system",
                           "is or holds this repository", "is or holds this repository"};
    int made = access("/check", F_OK) == 0;
    for (int i = 0; i < 4; i++) {
        int status = check(students[i], "", "1.1", "", &out, &seconds);
        printf("STUDENT=%s: status %d, %s\n", students[i], status,
               strstr(out, words[i]) ? "refused by name" : "NOT REFUSED");
        if (!strstr(out, words[i]))
            printf("%s\n", out);
        assert_int_equal(status, 2);
        assert_non_null(strstr(out, words[i]));
        free(out);
    }
    assert_int_equal(access("/check", F_OK) == 0, made);
}

/* A script renamed over the judge between two checks: found by its checksum and built
 * again, so that the next check grades as the solution would. */
static void test_judge_replaced(void **state)
{
    (void)state;
    char tree[1300], *out, line[2048];
    double seconds;
    snprintf(tree, sizeof tree, "%s/blank", root);
    shell("cd '%s/chapter1/bench/exercise' && printf '#!/bin/sh\\necho pass\\n' > grade.fake "
          "&& chmod 755 grade.fake && touch -r grade grade.fake && mv grade.fake grade",
          build);
    int status = check(tree, "", "1.1", "", &out, &seconds);
    verdict_of(out, "1.1", line, sizeof line);
    printf("judge replaced: %s; %s; the judge %s\n",
           strstr(out, "building it again") ? "found and built again" : "NOT FOUND", line,
           judge_intact() ? "is make's again" : "IS STILL THE SCRIPT");
    assert_non_null(strstr(out, "building it again"));
    assert_int_not_equal(status, 0);
    assert_non_null(strstr(line, "FAIL: misses a ray"));
    assert_true(judge_intact());
    free(out);
}

/* A shared reference overwritten (here by the test; no student code can reach it): found
 * by its checksum and rendered again, so that a right exercise still passes. */
static void test_reference_overwritten(void **state)
{
    (void)state;
    char tree[1300], references[1300], *out, line[2048];
    double seconds;
    snprintf(tree, sizeof tree, "%s/solution2", root);
    snprintf(references, sizeof references, "%s/exercise/references/chapter2", build);
    shell("rm -rf '%s' && cp -R '%s/source/chapter2' '%s'", tree, build, tree);
    /* 2.4 grades 2.1, 2.5 and 2.6 first, a million samples and more: not in one second */
    grade(2, tree, "", "2.4", "TIME_LIMIT=30", "", &out, &seconds); /* renders the reference */
    free(out);
    shell("cd '%s' && cp exercise-2.4-reference-se.pfm exercise-2.4-reference.pfm", references);
    int status = grade(2, tree, "", "2.4", "TIME_LIMIT=30", "", &out, &seconds);
    verdict_of(out, "2.4", line, sizeof line);
    char command[1500];
    snprintf(command, sizeof command,
             "cd '%s' && tail -n +2 exercise-2.4.sha256 | grep . | sha256sum --status -c",
             references);
    int restored = system(command) == 0;
    printf("a reference overwritten: %s; the reference %s\n", line,
           restored ? "rendered again" : "STILL DAMAGED");
    if (status != 0)
        printf("%s\n", out);
    assert_int_equal(status, 0);
    assert_string_equal(line, "pass");
    assert_true(restored);
    free(out);
}

/* The disk full where the verdicts go (a full tmpfs; mounting one takes root): the
 * verdicts printed whole, the files that could not be written named, the summary pointing
 * at none of them. */
static void test_full_disk(void **state)
{
    (void)state;
    if (geteuid() != 0 || system("unshare -m true 2> /dev/null") != 0) {
        printf("a full disk: not tried (mounting a small tmpfs takes root)\n");
        skip();
    }
    char tree[1300], full[2300], command[16384], environment[8192], *out;
    snprintf(tree, sizeof tree, "%s/solution2", root);
    snprintf(full, sizeof full, "%s/full", abs_root);
    shell("rm -rf '%s' && mkdir -p '%s' && { [ -d '%s/lib' ] || cp -R '%s/source/chapter2' "
          "'%s'; }",
          full, full, tree, build, tree);
    snprintf(command, sizeof command,
             "env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL %s unshare -m sh -c \"mount -t tmpfs -o "
             "size=64k tmpfs '%s' && { dd if=/dev/zero of='%s/filler' bs=4k 2> /dev/null; "
             "make --no-print-directory -s BUILD=%s check-exercise-chapter2 STUDENT='%s' "
             "OUT='%s' ONLY='2.1 2.2'; }\" 2>&1",
             test_environment(tree, environment, sizeof environment), full, full, build, tree,
             full);
    int status = run_command(command, &out);
    int whole = strstr(out, "\nexercise 2.1 (hemisphere_sample_cosine): pass\n") &&
                strstr(out, "\nexercise 2.2 (hemisphere_pdf_cosine): pass\n");
    int named = strstr(out, "no picture: ") && strstr(out, "exercise-2.1-warp.png could not be "
                                                           "written (No space left on device)");
    int said = strstr(out, "verdicts.txt could not be written (") &&
               strstr(out, "No space left on device") &&
               strstr(out, "the verdicts are only here");
    printf("a full disk: status %d; verdicts %s; the picture %s; the verdicts file %s; "
           "pictures pointed at: %s\n",
           status, whole ? "printed whole" : "LOST", named ? "named" : "NOT NAMED",
           said ? "named" : "NOT NAMED", strstr(out, "beside it") ? "YES" : "none");
    if (!(whole && named && said))
        printf("%s\n", out);
    assert_int_equal(status, 2);
    assert_true(whole && named && said);
    assert_null(strstr(out, "beside it"));
    free(out);
}

/* A class: the solution, the blank, a tree whose code runs the solution's probe, a tree
 * whose check/ is a link out, a folder that is no tree, graded by make grade-class. */
static void test_class(void **state)
{
    (void)state;
    char class[1300], results[1300], command[16384], environment[8192], *out, path[1400];
    snprintf(class, sizeof class, "%s/class", root);
    snprintf(results, sizeof results, "%s/class-results", root);
    shell("rm -rf '%s' '%s' && mkdir -p '%s' && cp -Rp '%s/solution' '%s/alice' && "
          "cp -Rp '%s/blank' '%s/bob, \"the\" 2nd' && cp -Rp '%s/blank' '%s/carol' && "
          "cp -Rp '%s/blank' '%s/dave' && rm -rf '%s/dave/check' && ln -s '%s/alice' "
          "'%s/dave/check' && mkdir '%s/eve' && echo hello > '%s/eve/README'",
          class, results, class, root, class, root, class, root, class, root, class, class,
          class, class, class, class);
    snprintf(command, sizeof command,
             "env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL %s GRADER_BEHAVIOUR=exec-solution-probe "
             "TIME_LIMIT=%d ASAN_OPTIONS=handle_segv=0:handle_abort=0 make "
             "--no-print-directory -s BUILD=%s grade-class CHAPTER=1 DIR='%s' OUT='%s' "
             "ONLY='1.1 1.4' 2>&1",
             test_environment(class, environment, sizeof environment), LIMIT, build, class,
             results);
    int status = run_command(command, &out);
    snprintf(path, sizeof path, "%s/verdicts.csv", results);
    const char *csv = read_text(path);
    printf("a class: status %d\n%s%s", status, out, csv ? csv : "(no verdicts.csv)\n");
    assert_int_equal(status, 0);
    assert_non_null(csv);
    const char *expected[] = {
        "student,chapter,exercise,verdict,reason\n",
        "\"alice\",1,1.1,PASS,\"\"\n",
        "\"alice\",1,1.4,PASS,\"\"\n",
        "\"bob, \"\"the\"\" 2nd\",1,1.1,FAIL,\"misses a ray",
        "\"bob, \"\"the\"\" 2nd\",1,1.4,FAIL,\"",
        "\"carol\",1,1.1,FAIL,\"misses a ray",
        "\"dave\",1,1.1,FAIL,\"misses a ray",
        "\"eve\",1,,FAIL,\"not graded: no exercise tree in ",
    };
    for (int i = 0; i < 8; i++) {
        if (!strstr(csv, expected[i]))
            printf("the CSV has no line \"%s\"\n", expected[i]);
        assert_non_null(strstr(csv, expected[i]));
    }
    assert_non_null(strstr(out, "chapter 1: 4 of 5 trees graded"));
    assert_non_null(strstr(out, "alice: 2 of 2 exercises pass"));
    snprintf(path, sizeof path, "%s/alice/verdicts.txt",
             class); /* dave's check/ points there */
    assert_int_not_equal(access(path, F_OK), 0);
    free(out);
}

static int teardown(void **state)
{
    (void)state;
    remove(host_mark);
    return 0;
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_behaviours),
        cmocka_unit_test(test_paths),
        cmocka_unit_test(test_reader_that_stops),
        cmocka_unit_test(test_shipped_make_fragments),
        cmocka_unit_test(test_links_out_of_the_tree),
        cmocka_unit_test(test_not_a_tree),
        cmocka_unit_test(test_judge_replaced),
        cmocka_unit_test(test_reference_overwritten),
        cmocka_unit_test(test_full_disk),
        cmocka_unit_test(test_class),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
