/* test_interrupt.c (bench, chapter 1): every chapter program, stopped at random moments.
 *
 * A terminal's Ctrl-C (SIGINT) may come at any moment of a render: the program must
 * then exit with status 130 (or 0, had it finished), leave no temporary file, and every
 * image it wrote must be a finished one: the very bytes an uninterrupted run writes,
 * or the one panel it says it saved, with every pixel sampled at least once.
 * SIGINT, SIGTERM or SIGHUP sent to the program alone (not to its process group, as a
 * terminal sends them) while its reference renders must stop the reference renderer too,
 * promptly, and leave no temporary folder. Chapter 8 interrupted while it renders its
 * photon passes saves the image of the passes completed. And two programs that need the
 * same reference render it once: the second waits for the first and reads it from the
 * cache. The programs are found in $CHAPTER_DIR (default build).
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <dirent.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

static const char *const PROGRAMS[] = {
    "ch01_whitted",    "ch02_monte_carlo",      "ch03_shadow_rays", "ch04_fresnel",
    "ch05_oren_nayar", "ch06_russian_roulette", "ch07_final",       "ch08_photon_map",
};

static char out_dir[] = "/tmp/test_interrupt_XXXXXX";

static const char *programs(void)
{
    return getenv("CHAPTER_DIR") ? getenv("CHAPTER_DIR") : "build";
}

static void sleep_seconds(double seconds)
{
    struct timespec wait = {(time_t)seconds, (long)((seconds - (time_t)seconds) * 1e9)};
    while (nanosleep(&wait, &wait) != 0)
        ;
}

/* Start `program` with `arguments` (split at spaces), its output into `log`; returns its
 * process id. */
static pid_t start(const char *program, const char *arguments, const char *log)
{
    char path[600], words[1024];
    snprintf(path, sizeof path, "%s/%s", programs(), program);
    snprintf(words, sizeof words, "%s", arguments);
    char *argv[32] = {path};
    int argc = 1;
    for (char *word = strtok(words, " "); word && argc < 31; word = strtok(NULL, " "))
        argv[argc++] = word;
    argv[argc] = NULL;
    fflush(NULL);
    pid_t child = fork();
    assert_true(child >= 0);
    if (child == 0) {
        FILE *out = freopen(log, "w", stdout);
        if (!out || dup2(fileno(out), STDERR_FILENO) < 0)
            _exit(127);
        execv(path, argv);
        _exit(127);
    }
    return child;
}

static int wait_for(pid_t child)
{
    int status;
    assert_int_equal(waitpid(child, &status, 0), child);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

static double seconds_now(void)
{
    struct timespec now;
    clock_gettime(CLOCK_MONOTONIC, &now);
    return (double)now.tv_sec + 1e-9 * (double)now.tv_nsec;
}

static void empty_folder(const char *folder)
{
    char command[1600];
    snprintf(command, sizeof command, "rm -rf '%s' && mkdir -p '%s'", folder, folder);
    assert_int_equal(system(command), 0);
}

/* Panels rendered for as long as another took (chapter 8's photon map beside the path
 * tracer, at equal time): their pass count, and so their bytes, vary from run to run. */
static int time_budgeted(const char *name) { return strcmp(name, "ch08_photon_map.pfm") == 0; }

/* The panel the program says it saved when interrupted, and after how many samples per
 * pixel ("interrupted: saved NAME after S samples per pixel"); 0 if it says none. */
static int saved_when_interrupted(const char *log, char *name, size_t size, double *spp)
{
    FILE *file = fopen(log, "r");
    assert_non_null(file);
    char line[4096];
    int found = 0;
    while (!found && fgets(line, sizeof line, file)) {
        char *said = strstr(line, "interrupted: saved ");
        char saved[256];
        if (said && sscanf(said, "interrupted: saved %255s after %lf", saved, spp) == 2) {
            snprintf(name, size, "%s.pfm", saved);
            found = 1;
        }
    }
    fclose(file);
    return found;
}

/* Every file in `folder` is a finished one: no temporary file is left, and each PFM is
 * byte for byte the one the uninterrupted run wrote into `whole`, if given (a render is
 * the same for the same seed), but for the one panel the program says it saved when
 * interrupted, which must have at least one sample in every pixel, and those rendered
 * in a time budget. Returns the number of
 * PFMs. */
static int check_folder(const char *folder, const char *whole, const char *log,
                        const char *what)
{
    char partial[300] = "";
    double spp = 0.0;
    if (saved_when_interrupted(log, partial, sizeof partial, &spp) && spp < 1.0)
        fail_msg("%s: saved %s after %.2f samples per pixel: some pixels have none", what,
                 partial, spp);
    DIR *directory = opendir(folder);
    if (!directory)
        return 0;
    int pfms = 0;
    struct dirent *entry;
    while ((entry = readdir(directory)) != NULL) {
        const char *name = entry->d_name;
        if (strstr(name, ".tmp."))
            fail_msg("%s: a temporary file is left: %s", what, name);
        size_t length = strlen(name);
        if (!whole || length < 4 || strcmp(name + length - 4, ".pfm") != 0)
            continue;
        char command[2600];
        snprintf(command, sizeof command, "cmp -s '%s/%s' '%s/%s'", folder, name, whole, name);
        if (strcmp(name, partial) != 0 && !time_budgeted(name) && system(command) != 0)
            fail_msg("%s: %s is not the uninterrupted run's, and not said to be partial", what,
                     name);
        pfms++;
    }
    closedir(directory);
    return pfms;
}

/* Start `program` with `settings`, writing into `folder`, and stop it with SIGINT after
 * `moment` seconds; check what it left. */
static void interrupt_at(const char *program, const char *settings, const char *folder,
                         const char *whole, double moment, double duration)
{
    char arguments[1400], log[760];
    snprintf(log, sizeof log, "%s.log", folder);
    snprintf(arguments, sizeof arguments, "%s --out %s", settings, folder);
    empty_folder(folder);
    pid_t child = start(program, arguments, log);
    sleep_seconds(moment);
    kill(child, SIGINT);
    int status = wait_for(child);
    int pfms = check_folder(folder, whole, log, program);
    print_message("    %s, SIGINT after %.3f s of %.3f: status %d, %d PFM images\n", program,
                  moment, duration, status, pfms);
    assert_true(status == 130 || status == 0);
}

/* Each program, once to the end and then stopped by SIGINT at random moments of that
 * run's duration: status 130 (or 0), finished images only. Then stopped early in runs
 * that would take hours, in the middle of a panel's first samples. */
static void test_sigint_at_random_moments(void **state)
{
    unsigned seed = (unsigned)time(NULL) ^ (unsigned)getpid();
    srand(seed);
    print_message("    random moments from seed %u\n", seed);
    int chapters = CHAPTER < 8 ? CHAPTER : 8;
    for (int c = 0; c < chapters; c++) {
        char arguments[800], whole[600], folder[700], log[700];
        const char *settings = c == 0 ? "--quiet --size 1024"
                                      : "--quiet --size 24 --spp 64 --reference-spp 8 --seed 5";
        snprintf(whole, sizeof whole, "%s/%s-whole", out_dir, PROGRAMS[c]);
        snprintf(log, sizeof log, "%s.log", whole);
        snprintf(arguments, sizeof arguments, "%s --out %s", settings, whole);
        empty_folder(whole);
        wait_for(start(PROGRAMS[c], arguments, log));
        double began = seconds_now();
        assert_int_equal(wait_for(start(PROGRAMS[c], arguments, log)), 0);
        double duration = seconds_now() - began;
        for (int m = 0; m < 3; m++) {
            snprintf(folder, sizeof folder, "%s/%s-%d", out_dir, PROGRAMS[c], m);
            interrupt_at(PROGRAMS[c], settings, folder, whole, duration * rand() / RAND_MAX,
                         duration);
        }
        if (c == 0)
            continue;
        const char *endless = "--quiet --size 256 --spp 1048576 --reference-spp 1 --seed 5";
        snprintf(folder, sizeof folder, "%s/%s-endless", out_dir, PROGRAMS[c]);
        interrupt_at(PROGRAMS[c], endless, folder, NULL, 2.0, 2.0);
        for (int m = 0; m < 3; m++)
            interrupt_at(PROGRAMS[c], endless, folder, NULL, 0.02 + 0.3 * rand() / RAND_MAX,
                         0.0);
    }
}

#if CHAPTER >= 2
/* The processes whose command line holds "--parent PID": reference renderers started
 * by that program. */
static int children_of(pid_t parent)
{
    /* The arguments in /proc/PID/cmdline end each in a NUL. */
    char needle[40];
    int needle_length =
        snprintf(needle, sizeof needle, "--parent%c%ld", '\0', (long)parent) + 1;
    DIR *proc = opendir("/proc");
    if (!proc)
        return 0;
    int found = 0;
    struct dirent *entry;
    while (!found && (entry = readdir(proc)) != NULL) {
        char path[300], line[8192];
        snprintf(path, sizeof path, "/proc/%s/cmdline", entry->d_name);
        FILE *file = fopen(path, "rb");
        if (!file)
            continue;
        size_t n = fread(line, 1, sizeof line, file);
        fclose(file);
        for (size_t i = 0; i + (size_t)needle_length <= n && !found; i++)
            found = memcmp(line + i, needle, (size_t)needle_length) == 0;
    }
    closedir(proc);
    return found;
}

/* Wait up to `seconds` for the child to end: its status as wait_for gives it, or -1
 * (after killing it and what it started) if it did not end. */
static int wait_at_most(pid_t child, double seconds)
{
    for (double waited = 0.0; waited < seconds; waited += 0.05) {
        int status;
        pid_t ended = waitpid(child, &status, WNOHANG);
        assert_true(ended >= 0);
        if (ended == child)
            return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
        sleep_seconds(0.05);
    }
    kill(child, SIGKILL);
    wait_for(child);
    return -1;
}

/* Whether the reference renderer started by `parent` is still there after a moment. */
static int reference_outlives(pid_t parent)
{
    int left = 1;
    for (int tries = 0; tries < 40 && left; tries++) {
        sleep_seconds(0.05);
        left = children_of(parent);
    }
    return left;
}

/* The names in `folder`, as one text ("" when it is empty). */
static void names_in(const char *folder, char *names, size_t size)
{
    names[0] = '\0';
    DIR *directory = opendir(folder);
    assert_non_null(directory);
    struct dirent *entry;
    while ((entry = readdir(directory)) != NULL)
        if (strcmp(entry->d_name, ".") != 0 && strcmp(entry->d_name, "..") != 0)
            snprintf(names + strlen(names), size - strlen(names), "%s ", entry->d_name);
    closedir(directory);
}

/* `signal_number` to `program` alone while its reference renders, the programs found in
 * `programs_dir`, with its temporary folders in a fresh $TMPDIR: the program ends (of
 * the signal, or with status 130 for SIGINT) within 30 seconds, and so does the
 * reference renderer, and no temporary folder is left. */
static void signal_while_the_reference_renders(const char *programs_dir, int signal_number,
                                               const char *what)
{
    char folder[600], log[700], arguments[800], temporary[700], names[2000];
    snprintf(folder, sizeof folder, "%s/alone-%d", out_dir, signal_number);
    snprintf(log, sizeof log, "%s.log", folder);
    snprintf(temporary, sizeof temporary, "%s/tmp-%d", out_dir, signal_number);
    empty_folder(folder);
    empty_folder(temporary);
    snprintf(arguments, sizeof arguments,
             "--quiet --size 64 --spp 4 --reference-spp 1000000 --seed 91 --out %s", folder);
    setenv("TMPDIR", temporary, 1);
    setenv("CHAPTER_DIR", programs_dir, 1);
    pid_t child = start("ch02_monte_carlo", arguments, log);
    unsetenv("TMPDIR");
    int started = 0;
    for (int tries = 0; tries < 200 && !started; tries++) {
        sleep_seconds(0.05);
        started = children_of(child);
    }
    assert_true(started);
    kill(child, signal_number);
    int status = wait_at_most(child, 30.0);
    int left = reference_outlives(child);
    names_in(temporary, names, sizeof names);
    print_message("    %s: %s to the program alone while its reference renders: status %d, "
                  "the reference renderer %s, temporary folders left: %s\n",
                  what, strsignal(signal_number), status,
                  left ? "outlived it" : "ended with it", names[0] ? names : "none");
    assert_int_equal(status, signal_number == SIGINT ? 130 : 128 + signal_number);
    assert_false(left);
    assert_string_equal(names, "");
    check_folder(folder, NULL, log, what);
}

/* SIGINT, SIGTERM and SIGHUP, each to the program alone, while its reference renders:
 * with the cache in build/ (the reference renderer falls back to a temporary folder),
 * and with a cache that cannot be written (a file stands where its folder would be: the
 * reference renders into a temporary folder). */
static void test_signals_to_the_program_alone_stop_the_reference(void **state)
{
    const char *programs_dir = strdup(programs());
    assert_non_null(programs_dir);
    char unwritable[700], command[2400];
    snprintf(unwritable, sizeof unwritable, "%s/unwritable", out_dir);
    snprintf(command, sizeof command,
             "mkdir -p '%s' && cp '%s/ch02_monte_carlo' '%s/reference' "
             "'%s/' && touch '%s/references'",
             unwritable, programs_dir, programs_dir, unwritable, unwritable);
    assert_int_equal(system(command), 0);
    const int signals[3] = {SIGINT, SIGTERM, SIGHUP};
    for (int i = 0; i < 3; i++) {
        signal_while_the_reference_renders(programs_dir, signals[i], "cache in build/");
        signal_while_the_reference_renders(unwritable, signals[i], "cache not writable");
    }
    setenv("CHAPTER_DIR", programs_dir, 1);
    free((void *)programs_dir);
}
/* A program waiting for another to render the reference both need (the lock on its
 * cache entry) is stopped by SIGINT sent to it alone: status 130 within 30 seconds, and
 * it says what it was waiting for, rather than waiting on until the other is done. */
static void test_sigint_while_waiting_for_another_programs_reference(void **state)
{
    char arguments[2][800], log[2][700];
    unsigned seed = (unsigned)time(NULL) ^ (unsigned)getpid();
    pid_t children[2];
    for (int i = 0; i < 2; i++) {
        snprintf(log[i], sizeof log[i], "%s/waiting-%d.log", out_dir, i);
        snprintf(arguments[i], sizeof arguments[i],
                 "--quiet --size 64 --spp 1 --runs 1 --reference-spp 1000000 --seed %u "
                 "--out %s/waiting-%d",
                 seed, out_dir, i);
    }
    children[0] = start("ch02_monte_carlo", arguments[0], log[0]);
    int started = 0;
    for (int tries = 0; tries < 200 && !started; tries++) {
        sleep_seconds(0.05);
        started = children_of(children[0]);
    }
    assert_true(started);
    children[1] = start("ch02_monte_carlo", arguments[1], log[1]);
    sleep_seconds(1.0);
    int waiting = !children_of(children[1]);
    kill(children[1], SIGINT);
    int status = wait_at_most(children[1], 30.0);
    kill(children[0], SIGTERM);
    wait_for(children[0]);
    FILE *file = fopen(log[1], "r");
    assert_non_null(file);
    char said[4096] = "";
    size_t n = fread(said, 1, sizeof said - 1, file);
    said[n] = '\0';
    fclose(file);
    print_message("    SIGINT to the program waiting for the other's reference: status %d: %s",
                  status, said);
    assert_true(waiting);
    assert_int_equal(status, 130);
    assert_non_null(strstr(said, "interrupted while waiting for another program to render the "
                                 "reference"));
}

/* Two programs needing the same new reference at once: one renders it, the other reads
 * it from the cache. */
static void test_one_reference_for_two_programs(void **state)
{
    char arguments[2][800], log[2][700];
    pid_t children[2];
    unsigned seed = (unsigned)time(NULL) ^ (unsigned)getpid();
    for (int i = 0; i < 2; i++) {
        snprintf(log[i], sizeof log[i], "%s/twice-%d.log", out_dir, i);
        snprintf(arguments[i], sizeof arguments[i],
                 "--quiet --size 32 --spp 1 --runs 1 --reference-spp 5000 --seed %u --out "
                 "%s/twice-%d",
                 seed, out_dir, i);
        children[i] = start("ch02_monte_carlo", arguments[i], log[i]);
    }
    int rendered = 0, cached = 0;
    for (int i = 0; i < 2; i++) {
        assert_int_equal(wait_for(children[i]), 0);
        FILE *file = fopen(log[i], "r");
        assert_non_null(file);
        char line[4096];
        while (fgets(line, sizeof line, file))
            if (strncmp(line, "reference:", 10) == 0) {
                rendered += strstr(line, "spp, rendered in") != NULL;
                cached += strstr(line, "cached, rendered in") != NULL;
            }
        fclose(file);
    }
    print_message("    references: %d rendered, %d read from the cache\n", rendered, cached);
    assert_int_equal(rendered, 1);
    assert_int_equal(cached, 1);
}
#endif

#if CHAPTER >= 8
/* Chapter 8's photon panel renders passes for the processor time its path-traced panel
 * took. SIGINT well into them, before their end, saves the image of the passes
 * completed: at least one pass of 8 samples per pixel (of 256 in the path-traced panel,
 * so a pass is a small part of the time). "Well into" is a moment on a clock that other
 * programs share: 0.7 times as long after the path-traced panel is
 * written as that took from the start, and where that came before the first pass had
 * ended (nothing saved, as it must), again later: 0.85, then 0.95 times. */
static void test_sigint_saves_the_photon_passes(void **state)
{
    char folder[600], log[700], arguments[800], path_panel[700], saved[300];
    snprintf(folder, sizeof folder, "%s/photons", out_dir);
    snprintf(log, sizeof log, "%s.log", folder);
    snprintf(path_panel, sizeof path_panel, "%s/ch08_path.pfm", folder);
    snprintf(arguments, sizeof arguments,
             "--quiet --size 32 --spp 256 --reference-spp 8 --seed 5 --out %s", folder);
    const double moments[] = {0.7, 0.85, 0.95};
    int status = 0, said = 0;
    double spp = 0.0;
    for (int attempt = 0; attempt < 3 && !said; attempt++) {
        empty_folder(folder);
        double began = seconds_now();
        pid_t child = start("ch08_photon_map", arguments, log);
        while (access(path_panel, F_OK) != 0 && seconds_now() - began < 120.0)
            sleep_seconds(0.01);
        double path_seconds = seconds_now() - began;
        sleep_seconds(moments[attempt] * path_seconds);
        kill(child, SIGINT);
        status = wait_for(child);
        said = saved_when_interrupted(log, saved, sizeof saved, &spp);
        print_message(
            "    path-traced panel after %.2f s, SIGINT %.2f s into the photon passes: "
            "status %d, saved %s after %.2f samples per pixel\n",
            path_seconds, moments[attempt] * path_seconds, status, said ? saved : "nothing",
            spp);
        assert_int_equal(status, 130);
    }
    assert_true(said);
    assert_string_equal(saved, "ch08_photon_map.pfm");
    assert_true(spp >= 8.0);
    check_folder(folder, NULL, log, "photon passes");
    char panel[700];
    snprintf(panel, sizeof panel, "%s/ch08_photon_map.pfm", folder);
    assert_int_equal(access(panel, R_OK), 0);
}
#endif

static int make_out_dir(void **state) { return mkdtemp(out_dir) ? 0 : -1; }

static int remove_out_dir(void **state)
{
    char command[200];
    snprintf(command, sizeof command, "rm -rf '%s'", out_dir);
    return system(command) == 0 ? 0 : -1;
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_sigint_at_random_moments),
#if CHAPTER >= 2
        cmocka_unit_test(test_signals_to_the_program_alone_stop_the_reference),
        cmocka_unit_test(test_one_reference_for_two_programs),
        cmocka_unit_test(test_sigint_while_waiting_for_another_programs_reference),
#endif
#if CHAPTER >= 8
        cmocka_unit_test(test_sigint_saves_the_photon_passes),
#endif
    };
    return cmocka_run_group_tests(tests, make_out_dir, remove_out_dir);
}
