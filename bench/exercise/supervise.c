/* supervise.c (bench, chapter 1): running a student's program under watch. See
 * supervise.h. */
#include "supervise.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>
#ifdef __linux__
#include <sys/prctl.h>
#endif

#define GRACE_SECONDS 1.0
#define CHUNK 65536

/* The signals the guard ignores, so that the program's kill(getppid(), ...) cannot
 * stop it; SIGKILL still can, and is then reported. */
static const int guarded[] = {SIGHUP,  SIGINT,  SIGQUIT, SIGTERM, SIGUSR1, SIGUSR2,
                              SIGPIPE, SIGALRM, SIGTSTP, SIGTTIN, SIGTTOU};
#define GUARDED (int)(sizeof guarded / sizeof guarded[0])

static volatile sig_atomic_t stop_signal;

static void on_stop(int signal) { stop_signal = signal; }

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* This process gets SIGKILL when its parent dies (Linux; elsewhere nothing happens). */
static void die_with_parent(void)
{
#ifdef PR_SET_PDEATHSIG
    prctl(PR_SET_PDEATHSIG, SIGKILL);
#endif
}

/* ---- the student's process, from fork to its program ---- */

static void start_program(const char *const *command, const char *id, int channel, int secret,
                          int output)
{
    for (int signal_number = 1; signal_number < 32; signal_number++)
        signal(signal_number, SIG_DFL);
    sigset_t none;
    sigemptyset(&none);
    sigprocmask(SIG_SETMASK, &none, NULL);
    struct rlimit no_core = {0, 0};
    setrlimit(RLIMIT_CORE, &no_core);
    die_with_parent();
    int null = open("/dev/null", O_RDONLY);
    /* Out of the way first, so that no dup2 below overwrites a descriptor still needed. */
    int high_null = fcntl(null, F_DUPFD_CLOEXEC, 10);
    int high_output = fcntl(output, F_DUPFD_CLOEXEC, 10);
    int high_channel = fcntl(channel, F_DUPFD_CLOEXEC, 10);
    int high_secret = fcntl(secret, F_DUPFD_CLOEXEC, 10);
    if (null < 0 || high_null < 0 || high_output < 0 || high_channel < 0 || high_secret < 0 ||
        dup2(high_null, 0) < 0 || dup2(high_output, 1) < 0 || dup2(high_output, 2) < 0 ||
        dup2(high_channel, 3) < 0 || dup2(high_secret, ANSWERS_SECRET_FD) < 0)
        _exit(126);
    long most = sysconf(_SC_OPEN_MAX);
    for (int fd = ANSWERS_SECRET_FD + 1; fd < (most > 0 && most < 65536 ? most : 65536); fd++)
        close(fd);
    char *argv[SUPERVISE_WORDS + 2];
    int words = 0;
    while (command[words] && words < SUPERVISE_WORDS) {
        argv[words] = (char *)command[words];
        words++;
    }
    argv[words++] = (char *)id;
    argv[words] = NULL;
    execv(command[0], argv);
    char message[1200];
    int length = snprintf(message, sizeof message, "grade: cannot run %s: %s\n", command[0],
                          strerror(errno));
    answers_write_all(2, message, length > 0 ? (size_t)length : 0);
    _exit(127);
}

/* The guard: leads the process group, starts the program and, when it ends, sends the
 * judge its wait status through `status`. */
static void guard(const char *const *command, const char *id, int channel, int secret,
                  int output, int status, pid_t judge)
{
    setpgid(0, 0);
    die_with_parent();
    if (getppid() != judge)
        _exit(1);
    for (int i = 0; i < GUARDED; i++)
        signal(guarded[i], SIG_IGN);
    pid_t student = fork();
    if (student == 0)
        start_program(command, id, channel, secret, output);
    close(channel);
    close(secret);
    close(output);
    int ended;
    if (student < 0)
        _exit(1);
    while (waitpid(student, &ended, 0) < 0)
        if (errno != EINTR)
            _exit(1);
    answers_write_all(status, &ended, sizeof ended);
    _exit(0);
}

/* ---- the judge's side ---- */

typedef struct {
    pid_t guard;
    int channel, output, status; /* read ends, -1 once at their end */
    int program_status;          /* its wait status, once all its bytes are in */
    size_t status_bytes;
    int timed_out;
} Watch;

/* A pipe whose ends close on exec, its read end not blocking. */
static int make_pipe(int ends[2])
{
    if (pipe(ends) != 0)
        return -1;
    fcntl(ends[0], F_SETFD, FD_CLOEXEC);
    fcntl(ends[1], F_SETFD, FD_CLOEXEC);
    fcntl(ends[0], F_SETFL, O_NONBLOCK);
    return 0;
}

static void close_end(int *fd)
{
    if (*fd >= 0)
        close(*fd);
    *fd = -1;
}

/* Read what is there now from one pipe into bytes[size]: the count (> 0), or 0 when
 * nothing is there yet or the pipe has ended (its fd then closed). */
static size_t read_some(int *fd, void *bytes, size_t size)
{
    if (*fd < 0 || size == 0)
        return 0;
    ssize_t n = read(*fd, bytes, size);
    if (n > 0)
        return (size_t)n;
    if (n == 0 || (errno != EAGAIN && errno != EINTR))
        close_end(fd);
    return 0;
}

/* Each returns the bytes it read. */
static size_t read_channel(Watch *w, ProbeRun *run)
{
    unsigned char chunk[CHUNK];
    size_t got = read_some(&w->channel, chunk, sizeof chunk);
    if (got > 0 && answer_feed(&run->answers, chunk, got) == -2)
        snprintf(run->answers.garbled, sizeof run->answers.garbled,
                 "could not be kept: the grader ran out of memory");
    return got;
}

static size_t read_output(Watch *w, ProbeRun *run)
{
    unsigned char chunk[CHUNK];
    size_t got = read_some(&w->output, chunk, sizeof chunk);
    size_t room = SUPERVISE_KEPT - run->output_size;
    memcpy(run->output + run->output_size, chunk, got < room ? got : room);
    run->output_size += got < room ? got : room;
    run->output_total += got;
    return got;
}

static size_t read_status(Watch *w)
{
    size_t got = read_some(&w->status, (unsigned char *)&w->program_status + w->status_bytes,
                           sizeof w->program_status - w->status_bytes);
    w->status_bytes += got;
    return got;
}

static int program_ended(const Watch *w) { return w->status_bytes == sizeof w->program_status; }

/* Whether the run is over: answered, garbled, the program ended, or its guard gone. */
static int over(const Watch *w, const ProbeRun *run)
{
    return run->answers.ended || run->answers.garbled[0] || program_ended(w) || w->status < 0;
}

static void poll_once(Watch *w, ProbeRun *run, double seconds)
{
    struct pollfd fds[3] = {
        {w->channel, POLLIN, 0}, {w->output, POLLIN, 0}, {w->status, POLLIN, 0}};
    if (poll(fds, 3, (int)(seconds * 1000.0) + 1) <= 0)
        return;
    if (fds[0].revents)
        read_channel(w, run);
    if (fds[1].revents)
        read_output(w, run);
    if (fds[2].revents)
        read_status(w);
}

/* Until the run is over, the deadline or a stop signal. */
static void watch(Watch *w, ProbeRun *run, double deadline)
{
    while (!stop_signal && !over(w, run)) {
        double left = deadline - now();
        if (left <= 0.0) {
            w->timed_out = 1;
            return;
        }
        poll_once(w, run, left);
    }
}

/* SIGTERM to the group (and SIGCONT, should it be stopped), then up to GRACE_SECONDS
 * for the program to end. */
static void terminate(Watch *w, ProbeRun *run)
{
    kill(-w->guard, SIGTERM);
    kill(-w->guard, SIGCONT);
    double deadline = now() + GRACE_SECONDS;
    while (!stop_signal && !program_ended(w) && w->status >= 0 && now() < deadline)
        poll_once(w, run, deadline - now());
}

/* The parent of process `pid`, or -1. */
static long parent_of(long pid)
{
    char path[64], text[512];
    snprintf(path, sizeof path, "/proc/%ld/stat", pid);
    FILE *file = fopen(path, "r");
    if (!file)
        return -1;
    size_t n = fread(text, 1, sizeof text - 1, file);
    fclose(file);
    text[n] = '\0';
    char *name_end = strrchr(text, ')'), state;
    long parent;
    if (!name_end || sscanf(name_end + 1, " %c %ld", &state, &parent) != 2)
        return -1;
    return parent;
}

/* SIGKILL to every child of this process. */
static void kill_children(void)
{
    DIR *proc = opendir("/proc");
    if (!proc)
        return;
    long self = (long)getpid();
    struct dirent *entry;
    while ((entry = readdir(proc)) != NULL) {
        char *end;
        long pid = strtol(entry->d_name, &end, 10);
        if (*end == '\0' && pid > 0 && parent_of(pid) == self)
            kill((pid_t)pid, SIGKILL);
    }
    closedir(proc);
}

/* Kill the run's group, then every process it left: as a subreaper this process
 * inherits each orphan, so killing its children until it has none kills them all. */
static void end_everything(pid_t group)
{
    kill(-group, SIGKILL);
    double give_up = now() + 10.0;
    for (;;) {
        kill_children();
        int status;
        pid_t pid = waitpid(-1, &status, WNOHANG);
        if (pid < 0 && errno == ECHILD)
            return;
        if (pid > 0)
            continue;
        if (now() > give_up) {
            fprintf(stderr, "grade: a process of the student's program would not end\n");
            return;
        }
        struct timespec pause = {0, 2000000};
        nanosleep(&pause, NULL);
    }
}

/* What the pipes still hold, once every writer is gone. */
static void drain(Watch *w, ProbeRun *run)
{
    while (!run->answers.ended && !run->answers.garbled[0] && read_channel(w, run) > 0)
        ;
    while (read_output(w, run) > 0)
        ;
    while (read_status(w) > 0)
        ;
}

static const char *plural(long n) { return n == 1 ? "" : "s"; }

/* How the program ended, as the verdict for an answer that never came. */
static void describe_status(int status, long answers, char *text, size_t size)
{
    char after[64];
    if (answers == 0)
        snprintf(after, sizeof after, "before answering");
    else
        snprintf(after, sizeof after, "after %ld answer%s, before the last", answers,
                 plural(answers));
    int sandbox_signal =
        WIFEXITED(status) && WEXITSTATUS(status) > 128 && WEXITSTATUS(status) < 128 + 32;
    if (WIFEXITED(status) && !sandbox_signal) {
        snprintf(text, size,
                 "your program ended with exit status %d %s: does your code call "
                 "exit() (in an exercise, a constructor or an atexit handler), or close or "
                 "reuse file descriptor 3?",
                 WEXITSTATUS(status), after);
        return;
    }
    int signal_number = sandbox_signal        ? WEXITSTATUS(status) - 128
                        : WIFSIGNALED(status) ? WTERMSIG(status)
                                              : 0;
    const char *crash =
        signal_number == SIGSEGV ? "a segmentation fault (an index outside an array, a NULL or "
                                   "uninitialised pointer: a malloc the sandbox's memory "
                                   "limit refused?)"
        : signal_number == SIGABRT ? "aborted (an assertion failed, or memory was freed twice?)"
        : signal_number == SIGFPE  ? "an arithmetic error (an integer division by zero?)"
        : signal_number == SIGBUS  ? "a bus error (memory that is not there any more?)"
        : signal_number == SIGILL  ? "an illegal instruction"
        : signal_number == SIGXFSZ ? "a file grew past the sandbox's limit on a file's size"
        : signal_number == SIGXCPU ? "more processor time than the sandbox allows"
                                   : NULL;
    if (crash)
        snprintf(text, size, "crashed: %s, %s", crash, after);
    else if (signal_number == SIGKILL)
        snprintf(text, size,
                 "killed by SIGKILL %s: does your code send it, or use up the "
                 "memory?",
                 after);
    else
        snprintf(text, size,
                 "stopped by signal %d (%s) %s: does your code send signals, to "
                 "itself or its process group?",
                 signal_number, strsignal(signal_number), after);
}

static void describe_end(const Watch *w, ProbeRun *run, int seconds)
{
    long count = run->answers.count;
    if (run->answers.ended)
        snprintf(run->ended, sizeof run->ended,
                 "your program gave %ld answer%s, where the "
                 "grader asks for more: has a function outside the exercises changed?",
                 count, plural(count));
    else if (run->answers.garbled[0])
        snprintf(
            run->ended, sizeof run->ended,
            "your program's answers arrived garbled after %ld "
            "(%s): does your code write to file descriptor 3, fork, or write to memory not "
            "its own?",
            count, run->answers.garbled);
    else if (w->timed_out)
        snprintf(run->ended, sizeof run->ended,
                 "no answer within %d second%s: an endless loop (a "
                 "path that never ends, a loop whose condition never changes)?",
                 seconds, plural(seconds));
    else if (program_ended(w))
        describe_status(w->program_status, count, run->ended, sizeof run->ended);
    else
        snprintf(run->ended, sizeof run->ended,
                 "the grader's guard over your program was "
                 "killed after %ld answer%s: does your code send signals to its parent or its "
                 "process group?",
                 count, plural(count));
}

/* Catch SIGINT, SIGTERM and SIGHUP (into stop_signal) while a run is watched. */
static void catch_stops(struct sigaction saved[3])
{
    static const int stops[3] = {SIGINT, SIGTERM, SIGHUP};
    struct sigaction action;
    memset(&action, 0, sizeof action);
    action.sa_handler = on_stop;
    sigemptyset(&action.sa_mask);
    stop_signal = 0;
    for (int i = 0; i < 3; i++)
        sigaction(stops[i], &action, &saved[i]);
}

static void release_stops(const struct sigaction saved[3])
{
    static const int stops[3] = {SIGINT, SIGTERM, SIGHUP};
    for (int i = 0; i < 3; i++)
        sigaction(stops[i], &saved[i], NULL);
    if (stop_signal) {
        signal(stop_signal, SIG_DFL);
        raise(stop_signal);
    }
}

/* Become a subreaper, fork the guard and keep the pipes' read ends. Returns the guard's
 * process id, or -1 with errno set. */
static pid_t start_guard(const char *const *command, const char *id, int secret,
                         int pipes[3][2])
{
#ifdef PR_SET_CHILD_SUBREAPER
    prctl(PR_SET_CHILD_SUBREAPER, 1);
#endif
    signal(SIGCHLD, SIG_DFL); /* children stay to be waited for */
    pid_t judge = getpid(), pid = fork();
    if (pid == 0)
        guard(command, id, pipes[0][1], secret, pipes[1][1], pipes[2][1], judge);
    if (pid > 0)
        setpgid(pid, pid); /* as the guard does: whichever comes first */
    for (int i = 0; i < 3; i++)
        close_end(&pipes[i][1]);
    return pid;
}

/* Watch until the end, the deadline or a stop signal; then leave nothing behind. */
static void watch_to_the_end(Watch *w, ProbeRun *run, int seconds)
{
    watch(w, run, now() + seconds);
    if (w->timed_out)
        terminate(w, run);
    end_everything(w->guard);
    drain(w, run);
    describe_end(w, run, seconds);
}

/* A pipe that holds the run's secret, its write end closed: the read end, or -1. */
static int secret_pipe(const unsigned char secret[ANSWERS_SECRET])
{
    int ends[2];
    if (pipe(ends) != 0)
        return -1;
    fcntl(ends[0], F_SETFD, FD_CLOEXEC);
    int written = answers_write_all(ends[1], secret, ANSWERS_SECRET);
    close(ends[1]);
    if (written != 0) {
        close(ends[0]);
        return -1;
    }
    return ends[0];
}

int supervise_probe(const char *const *command, const char *id, int seconds, ProbeRun *run,
                    char *error, size_t size)
{
    memset(run, 0, sizeof *run);
    int pipes[3][2] = {{-1, -1}, {-1, -1}, {-1, -1}}; /* the answers, the output, the status */
    unsigned char secret[ANSWERS_SECRET];
    int secret_fd = -1;
    run->output = malloc(SUPERVISE_KEPT);
    int ready = run->output && answers_new_secret(secret) == 0 &&
                (secret_fd = secret_pipe(secret)) >= 0;
    for (int i = 0; i < 3; i++)
        ready = ready && make_pipe(pipes[i]) == 0;
    pid_t guard_pid = -1;
    if (ready) {
        answer_reader_init(&run->answers, secret, id);
        struct sigaction saved[3];
        catch_stops(saved);
        guard_pid = start_guard(command, id, secret_fd, pipes);
        close_end(&secret_fd);
        Watch w = {guard_pid, pipes[0][0], pipes[1][0], pipes[2][0], 0, 0, 0};
        for (int i = 0; i < 3; i++)
            pipes[i][0] = -1; /* the watch's now: it closes each at its end */
        if (guard_pid > 0)
            watch_to_the_end(&w, run, seconds);
        close_end(&w.channel);
        close_end(&w.output);
        close_end(&w.status);
        release_stops(saved);
    }
    if (guard_pid < 0)
        snprintf(error, size, "cannot start the student's program: %s", strerror(errno));
    close_end(&secret_fd);
    for (int i = 0; i < 3; i++) {
        close_end(&pipes[i][0]);
        close_end(&pipes[i][1]);
    }
    return guard_pid < 0 ? -1 : 0;
}

void probe_run_free(ProbeRun *run)
{
    answer_reader_free(&run->answers);
    free(run->output);
    run->output = NULL;
}
