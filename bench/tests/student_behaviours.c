/* student_behaviours.c (bench, chapter 8): what a student's code might do to its grader.
 *
 * Not built with the project: test_grader.c copies it into a chapter 1 tree as
 * lib/zz_behaviours.c, where exercise 1.1's function passes its answer through
 * student_behaviour(). GRADER_BEHAVIOUR names what the code does there (or, for a few,
 * before main or at exit): end the process, crash, hang, fork, print a fake verdict,
 * forge or spoil the answers' frames, signal its parent or group, flood its output,
 * delete its check folder. Each must still be graded by the answers alone.
 */
#include <fcntl.h>
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "exercise/answers.h"

static int is(const char *name)
{
    const char *behaviour = getenv("GRADER_BEHAVIOUR");
    return behaviour && strcmp(behaviour, name) == 0;
}

/* A process that sleeps until killed: a plain child, or, through a double fork, one in
 * a session of its own (reparented away from the process that made it). */
static void leave_sleeper(int new_session)
{
    pid_t child = fork();
    if (child > 0 && new_session)
        waitpid(child, NULL, 0);
    if (child != 0)
        return;
    if (new_session) {
        setsid();
        if (fork() != 0)
            _exit(0);
    }
    for (;;)
        pause();
}

static void write_text(int fd, const char *text)
{
    if (write(fd, text, strlen(text)) < 0)
        return;
}

/* Frames in the grader's own format, but without the run's secret (which this code does
 * not read), and verdict-like lines, on every descriptor; then the end. */
static void forge_everywhere(void)
{
    static AnswerWriter writer;
    unsigned char guessed[ANSWERS_SECRET] = {0};
    for (int fd = 0; fd < 64; fd++) {
        answer_writer_init(&writer, fd, guessed, "1.1");
        for (int i = 0; i < 100; i++)
            answer_put(&writer, INFINITY);
        answer_end(&writer);
    }
    for (int fd = 0; fd < 64; fd++)
        write_text(fd, "pass\nexercise 1.1 (sphere_intersect): pass\n");
    _exit(0);
}

/* The run's secret, read from this process's own command line (probe ID SECRET).
 * Returns 0, or -1. */
static int read_the_secret(unsigned char secret[ANSWERS_SECRET])
{
    char line[4096] = {0};
    int fd = open("/proc/self/cmdline", O_RDONLY);
    ssize_t n = fd >= 0 ? read(fd, line, sizeof line - 1) : -1;
    const char *argument = line;
    for (int i = 0; n > 0 && i < 2; i++)
        argument += strlen(argument) + 1;
    return answers_parse_secret(argument, secret);
}

/* Frames with the run's secret: an end frame before any answer ("end"), answers to
 * another exercise ("other"), a frame with one byte changed ("damaged"), or the first
 * bytes of a frame ("partial"); then the end of the process. */
static void use_the_secret(const char *how)
{
    static AnswerWriter writer;
    unsigned char secret[ANSWERS_SECRET], bytes[256];
    int ends[2];
    if (read_the_secret(secret) != 0 || pipe(ends) != 0)
        _exit(0);
    answer_writer_init(&writer, strcmp(how, "end") == 0 ? 3 : ends[1], secret,
                       strcmp(how, "other") == 0 ? "1.2" : "1.1");
    if (strcmp(how, "end") != 0)
        answer_put(&writer, INFINITY);
    answer_end(&writer);
    ssize_t n = read(ends[0], bytes, sizeof bytes);
    if (strcmp(how, "damaged") == 0)
        bytes[ANSWERS_HEADER] ^= 1;
    if (n > 0 && write(3, bytes, strcmp(how, "partial") == 0 ? 20 : (size_t)n) < 0)
        _exit(1);
    _exit(0);
}

/* The grader: the parent of this process's parent (its guard). */
static void kill_the_grader(void)
{
    char path[64], text[512] = {0};
    snprintf(path, sizeof path, "/proc/%ld/stat", (long)getppid());
    FILE *file = fopen(path, "r");
    if (file) {
        if (fread(text, 1, sizeof text - 1, file) == 0)
            text[0] = '\0';
        fclose(file);
    }
    char *name_end = strrchr(text, ')'), state;
    long grader;
    if (name_end && sscanf(name_end + 1, " %c %ld", &state, &grader) == 2)
        kill((pid_t)grader, SIGKILL);
    for (;;)
        pause();
}

static void flood(long bytes)
{
    static char line[4096];
    memset(line, 'x', sizeof line - 1);
    line[sizeof line - 1] = '\n';
    for (long sent = 0; bytes < 0 || sent < bytes; sent += (long)sizeof line)
        if (write(1, line, sizeof line) < 0)
            return;
}

static void delete_check_folder(void)
{
    const char *student = getenv("STUDENT");
    char command[4200];
    snprintf(command, sizeof command, "rm -rf '%s/check'", student ? student : "/nonexistent");
    if (system(command) != 0)
        write_text(2, "could not delete the check folder\n");
}

static void write_fake_verdicts(void)
{
    const char *student = getenv("STUDENT");
    char path[4200];
    snprintf(path, sizeof path, "%s/check/verdicts.txt", student ? student : "/nonexistent");
    FILE *file = fopen(path, "w");
    if (file) {
        fputs("exercise 1.1 (sphere_intersect): pass\nchapter 1: 1 of 1 exercises pass\n",
              file);
        fclose(file);
    }
}

static void on_segv(int signal_number)
{
    (void)signal_number;
    _exit(0);
}

static void exit_zero(void) { _exit(0); }

__attribute__((constructor)) static void before_main(void)
{
    if (is("constructor-exit"))
        exit(0);
    if (is("atexit"))
        atexit(exit_zero);
}

/* Things done once, then the answer goes back as it is. */
static void once(void)
{
    if (is("fork-sleep"))
        leave_sleeper(0);
    else if (is("setsid-double-fork"))
        leave_sleeper(1);
    else if (is("new-group") && fork() == 0) {
        setpgid(0, 0);
        for (;;)
            pause();
    } else if (is("shell-background") && system("sleep 300 &") != 0)
        write_text(2, "no shell\n");
    else if (is("print-pass"))
        printf("PASS\npass\n");
    else if (is("print-verdict"))
        printf("exercise 1.1 (sphere_intersect): pass\nchapter 1: 1 of 1 exercises pass\n");
    else if (is("print-fail"))
        printf("FAIL: wrong\nexercise 1.1 (sphere_intersect): FAIL: wrong\n");
    else if (is("kill-parent"))
        kill(getppid(), SIGTERM);
    else if (is("flood"))
        flood(32L << 20);
    else if (is("stdin"))
        while (read(0, (char[64]){0}, 64) > 0)
            ;
    else if (is("chdir") && chdir("/") != 0)
        write_text(2, "no /\n");
    else if (is("delete-check"))
        delete_check_folder();
    else if (is("write-verdicts"))
        write_fake_verdicts();
    else if (is("garbage-channel"))
        write_text(3, "PASS\n0123456789abcdefghijklmnopqrstuvwxyz0123456789abcdefghij\n");
    fflush(stdout);
}

/* Things that end, stop or spoil the process instead of answering. */
static void instead(void)
{
    if (is("exit"))
        exit(0);
    if (is("fork-then-exit")) { /* the child keeps the answers' pipe open */
        leave_sleeper(0);
        exit(0);
    }
    if (is("atexit"))
        exit(7);
    if (is("exec-true"))
        execl("/bin/true", "true", (char *)NULL);
    if (is("ignore-term-loop")) {
        signal(SIGTERM, SIG_IGN);
        for (volatile unsigned spin = 0;; spin++) /* unsigned: no overflow to sanitize */
            ;
    }
    if (is("stop-self"))
        raise(SIGSTOP);
    if (is("flood-forever"))
        flood(-1);
    if (is("close-channel"))
        close(3);
    if (is("close-all"))
        for (int fd = 0; fd < 1024; fd++)
            close(fd);
    if (is("dup-channel"))
        dup2(1, 3);
    if (is("forge-everywhere"))
        forge_everywhere();
    if (is("end-with-the-secret"))
        use_the_secret("end");
    if (is("other-exercise"))
        use_the_secret("other");
    if (is("damaged-frame"))
        use_the_secret("damaged");
    if (is("partial-frame"))
        use_the_secret("partial");
    if (is("raise-kill"))
        raise(SIGKILL);
    if (is("abort"))
        abort();
    if (is("segfault"))
        raise(SIGSEGV); /* as a bad pointer would, but past the sanitizers too */
    if (is("segv-handler-exit")) {
        signal(SIGSEGV, on_segv);
        raise(SIGSEGV);
    }
    if (is("kill-group"))
        kill(0, SIGTERM);
    if (is("kill-group-kill"))
        kill(0, SIGKILL);
    if (is("kill-parent-kill")) {
        kill(getppid(), SIGKILL);
        for (;;)
            pause();
    }
    if (is("kill-grader"))
        kill_the_grader();
}

double student_behaviour(double answer);

double student_behaviour(double answer)
{
    static int done;
    if (!done) {
        done = 1;
        once();
    }
    instead();
    return is("nan") ? NAN : answer;
}
