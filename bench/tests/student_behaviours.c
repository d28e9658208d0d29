/* student_behaviours.c (bench, chapter 8): what a student's code might do to its grader.
 *
 * Not built with the project: test_grader.c copies it into a chapter 1 tree as
 * lib/zz_behaviours.c, where exercise 1.1's function passes its answer through
 * student_behaviour(). GRADER_BEHAVIOUR names what the code does there (or, for a few,
 * before main or at exit): end the process, crash, hang, fork, print a fake verdict,
 * forge or spoil the answers' frames, signal its parent or group, flood its output, run
 * the solution's probe, use up memory, processes or disk; "reach:WHAT" tries to reach
 * something outside the sandbox and prints what it got. Graded by the answers alone.
 */
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
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

/* The run's secret, as a constructor can take it from descriptor 4 before the probe
 * does; put back in a pipe of its own, so that the probe still finds it there. */
static unsigned char stolen[ANSWERS_SECRET];
static int have_stolen;

/* The stolen secret on descriptor 4 again, as the judge gives it. */
static void give_back_the_secret(void)
{
    int ends[2];
    if (!have_stolen || pipe(ends) != 0)
        return;
    answers_write_all(ends[1], stolen, ANSWERS_SECRET);
    close(ends[1]);
    if (ends[0] != ANSWERS_SECRET_FD) { /* pipe() may have given it that very number */
        dup2(ends[0], ANSWERS_SECRET_FD);
        close(ends[0]);
    }
}

static void steal_the_secret(void)
{
    have_stolen = answers_read_secret(ANSWERS_SECRET_FD, stolen) == 0;
    give_back_the_secret();
}

static int read_the_secret(unsigned char secret[ANSWERS_SECRET])
{
    memcpy(secret, stolen, ANSWERS_SECRET);
    return have_stolen ? 0 : -1;
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

/* A program of the grader's (`name`: "probe" or "grade", chapter 1's) as /proc shows one
 * to this process: beside a running judge, or in the build folder under the folder a
 * process runs in (make's, the checkout). Into path[size]; 0, or -1 when none is seen. */
static int find_in_proc(const char *name, char *path, size_t size)
{
    DIR *proc = opendir("/proc");
    struct dirent *entry;
    int found = -1;
    while (proc && found != 0 && (entry = readdir(proc)) != NULL) {
        char link[300], target[1024];
        snprintf(link, sizeof link, "/proc/%.200s/exe", entry->d_name);
        ssize_t n = readlink(link, target, sizeof target - 1);
        char *slash = n > 0 ? (target[n] = '\0', strrchr(target, '/')) : NULL;
        if (slash && strcmp(slash, "/grade") == 0 && strstr(target, "/bench/exercise/")) {
            snprintf(path, size, "%.*s/%s", (int)(slash - target), target, name);
            found = access(path, X_OK);
        }
        snprintf(link, sizeof link, "/proc/%.200s/cwd", entry->d_name);
        n = found != 0 ? readlink(link, target, sizeof target - 1) : -1;
        if (n > 0) {
            target[n] = '\0';
            snprintf(path, size, "%s/build/chapter1/bench/exercise/%s", target, name);
            found = access(path, X_OK);
        }
    }
    if (proc)
        closedir(proc);
    return found;
}

/* The forgery: exec the solution's probe, found through /proc, with this run's
 * secret (taken by the constructor) on descriptor 4: it would answer right. */
static void exec_solution_probe(void)
{
    char probe[1100];
    if (find_in_proc("probe", probe, sizeof probe) != 0) {
        printf("no judge in sight in /proc\n");
        return;
    }
    give_back_the_secret();
    execl(probe, "probe", "1.1", (char *)NULL);
    printf("cannot run %s: %s\n", probe, strerror(errno));
}

/* A script renamed over the judge, for the checks after this one. */
static void replace_judge(void)
{
    char path[1100], fake[1200];
    if (find_in_proc("grade", path, sizeof path) != 0) {
        printf("no judge in sight in /proc\n");
        return;
    }
    snprintf(fake, sizeof fake, "%s.fake", path);
    FILE *file = fopen(fake, "w");
    if (!file || fputs("#!/bin/sh\necho pass\n", file) < 0 || fclose(file) != 0 ||
        chmod(fake, 0755) != 0 || rename(fake, path) != 0)
        printf("cannot replace %s: %s\n", path, strerror(errno));
}

/* 20 GB asked for and touched at both ends; refused, it is the NULL a careless student
 * would write through (raised as such, past the sanitizers). */
static void use_20_gb(void)
{
    size_t size = (size_t)20 << 30;
    char *block = malloc(size);
    if (!block)
        raise(SIGSEGV);
    block[0] = block[size - 1] = 1;
    free(block);
}

/* Up to 2000 sleeping children; says how many it could start. */
static void fork_bomb(void)
{
    int started = 0;
    while (started < 2000) {
        pid_t child = fork();
        if (child < 0)
            break;
        if (child == 0)
            for (;;)
                pause();
        started++;
    }
    printf("started %d children of 2000\n", started);
}

/* 256 MiB into /tmp, 1 MiB at a time. */
static void huge_file(void)
{
    static char block[1 << 20];
    FILE *file = fopen("/tmp/huge", "wb");
    int written = 0;
    while (file && written < 256 && fwrite(block, 1, sizeof block, file) == sizeof block &&
           fflush(file) == 0)
        written++;
    printf("wrote %d MiB of 256\n", written);
}

/* A path from an environment variable the test gives, and a tail. */
static const char *given(const char *name, const char *tail, char *path, size_t size)
{
    const char *value = getenv(name);
    snprintf(path, size, "%s%s", value ? value : "/nonexistent", tail);
    return path;
}

static int can_write(const char *path)
{
    int fd = open(path, O_WRONLY | O_CREAT | O_APPEND, 0644);
    if (fd >= 0)
        close(fd);
    return fd >= 0;
}

static int can_read(const char *path)
{
    char byte;
    int fd = open(path, O_RDONLY);
    int got = fd >= 0 && read(fd, &byte, 1) == 1;
    if (fd >= 0)
        close(fd);
    return got;
}

static int count_processes(void)
{
    DIR *proc = opendir("/proc");
    struct dirent *entry;
    int count = 0;
    while (proc && (entry = readdir(proc)) != NULL)
        count += entry->d_name[0] >= '0' && entry->d_name[0] <= '9';
    if (proc)
        closedir(proc);
    return count;
}

static int udp_out(void)
{
    int fd = socket(AF_INET, SOCK_DGRAM, 0);
    struct sockaddr_in to;
    memset(&to, 0, sizeof to);
    to.sin_family = AF_INET;
    to.sin_port = htons(53);
    to.sin_addr.s_addr = htonl(0x08080808);
    int reached = fd >= 0 && connect(fd, (struct sockaddr *)&to, sizeof to) == 0 &&
                  send(fd, "x", 1, 0) == 1;
    if (fd >= 0)
        close(fd);
    return reached;
}

static int file_holds(const char *path, const char *text)
{
    static char bytes[1 << 16];
    int fd = open(path, O_RDONLY);
    ssize_t n = fd >= 0 ? read(fd, bytes, sizeof bytes - 1) : -1;
    if (fd >= 0)
        close(fd);
    for (ssize_t at = 0; at < n; at++)
        if (bytes[at] == '\0')
            bytes[at] = '\n';
    if (n >= 0)
        bytes[n] = '\0';
    return n > 0 && strstr(bytes, text) != NULL;
}

/* One thing outside the sandbox: "reached WHAT" or "kept out of WHAT". */
static void reach(const char *what)
{
    char path[4200];
    int reached = 0;
    if (strcmp(what, "tree") == 0) /* the student's own tree, as the grader was given it */
        reached = can_write(given("GRADER_TREE", "/check/verdicts.txt", path, sizeof path));
    else if (strcmp(what, "repo-build") == 0)
        reached = can_write(given("GRADER_REPO", "/build/escaped", path, sizeof path));
    else if (strcmp(what, "solution-source") == 0)
        reached = can_read(given("GRADER_REPO", "/lib/sphere.c", path, sizeof path));
    else if (strcmp(what, "judge-by-path") == 0)
        reached = can_read(given("GRADER_JUDGE", "", path, sizeof path));
    else if (strcmp(what, "judge-via-proc") == 0)
        reached = find_in_proc("grade", path, sizeof path) == 0;
    else if (strcmp(what, "references") == 0)
        reached = can_write(given("GRADER_REFERENCES", "/escaped.pfm", path, sizeof path));
    else if (strcmp(what, "home") == 0)
        reached = can_read("/root/.bashrc") || can_read("/etc/passwd");
    else if (strcmp(what, "network") == 0)
        reached = udp_out();
    else if (strcmp(what, "processes") == 0)
        reached = count_processes() > 10;
    else if (strcmp(what, "environment") == 0)
        reached = getenv("GRADER_TEST_PRIVATE") != NULL ||
                  file_holds("/proc/1/environ", "GRADER_TEST_PRIVATE");
    else if (strcmp(what, "host-tmp") == 0)
        reached = can_read(given("GRADER_HOST_MARK", "", path, sizeof path));
    else if (strcmp(what, "box") == 0) /* the private copy, read-only while the probe runs */
        reached = can_write("/work/lib/escaped.c") || can_write("lib/escaped.c");
    else if (strcmp(what, "signal-outside") == 0) {
        const char *test = getenv("GRADER_TEST_PID");
        reached = test && kill((pid_t)atol(test), 0) == 0;
    }
    printf("%s %s\n", reached ? "reached" : "kept out of", what);
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
    const char *behaviour = getenv("GRADER_BEHAVIOUR");
    if (behaviour && (strstr(behaviour, "secret") || strstr(behaviour, "-frame") ||
                      strcmp(behaviour, "other-exercise") == 0 ||
                      strcmp(behaviour, "exec-solution-probe") == 0))
        steal_the_secret();
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
    else if (is("exec-solution-probe"))
        exec_solution_probe();
    else if (is("replace-judge"))
        replace_judge();
    else if (is("malloc-20g"))
        use_20_gb();
    else if (is("fork-bomb"))
        fork_bomb();
    else if (is("huge-file"))
        huge_file();
    else if (getenv("GRADER_BEHAVIOUR") &&
             strncmp(getenv("GRADER_BEHAVIOUR"), "reach:", 6) == 0)
        reach(getenv("GRADER_BEHAVIOUR") + 6);
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
