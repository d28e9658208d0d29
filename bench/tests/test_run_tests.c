/* test_run_tests.c (bench, chapter 1): make test's runner ends every program it runs.
 *
 * bench/run_tests.sh runs three scripts under a time limit of 2 seconds: one that passes,
 * one that fails, and one that hangs with a child of its own (a grandchild of the
 * runner) and ignores SIGTERM. The runner must end, count one passed and two failed,
 * name the hang as a timeout in its FAILED line, and leave no process of the hang
 * running: its whole process group is stopped (SIGKILL 1 s after SIGTERM, here). A
 * runner that does not end within 60 seconds fails the test, its process group killed.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

static char folder[] = "/tmp/test_run_tests_XXXXXX";

static void write_script(const char *name, const char *body)
{
    char path[200];
    snprintf(path, sizeof path, "%s/%s", folder, name);
    FILE *file = fopen(path, "w");
    assert_non_null(file);
    fprintf(file, "#!/bin/sh\n%s", body);
    assert_int_equal(fclose(file), 0);
    assert_int_equal(chmod(path, 0755), 0);
}

/* Whether process `pid` still runs (a zombie, ended but not yet reaped, does not). */
static int running(long pid)
{
    char path[64], stat[512];
    snprintf(path, sizeof path, "/proc/%ld/stat", pid);
    FILE *file = fopen(path, "r");
    if (!file)
        return 0;
    size_t n = fread(stat, 1, sizeof stat - 1, file);
    fclose(file);
    stat[n] = '\0';
    const char *state = strrchr(stat, ')');
    return state && state[1] == ' ' && state[2] != 'Z' && state[2] != 'X';
}

static void sleep_seconds(double seconds)
{
    struct timespec wait = {(time_t)seconds, (long)((seconds - (time_t)seconds) * 1e9)};
    while (nanosleep(&wait, &wait) != 0)
        ;
}

static void test_runner_stops_a_hang(void **state)
{
    char grandchild_file[200], body[600], log[200], command[900];
    snprintf(grandchild_file, sizeof grandchild_file, "%s/grandchild", folder);
    snprintf(log, sizeof log, "%s/runner.log", folder);
    write_script("passes", "echo fine\n");
    write_script("fails", "echo wrong; exit 3\n");
    snprintf(body, sizeof body,
             "trap '' TERM\nsleep 1000 &\necho $! > %s\necho hanging\n"
             "while :; do wait; done\n",
             grandchild_file);
    write_script("hangs", body);
    fflush(NULL);
    pid_t runner = fork();
    assert_true(runner >= 0);
    if (runner == 0) {
        setpgid(0, 0);
        snprintf(command, sizeof command,
                 "TEST_KILL_AFTER=1 sh bench/run_tests.sh %s/logs 2 "
                 "%s/passes %s/hangs %s/fails > %s 2>&1",
                 folder, folder, folder, folder, log);
        execl("/bin/sh", "sh", "-c", command, (char *)NULL);
        _exit(127);
    }
    int status = -1, ended = 0;
    for (int tries = 0; tries < 600 && !ended; tries++) {
        sleep_seconds(0.1);
        ended = waitpid(runner, &status, WNOHANG) == runner;
    }
    if (!ended) {
        kill(-runner, SIGKILL);
        waitpid(runner, &status, 0);
        fail_msg("the runner did not end within 60 s");
    }
    snprintf(command, sizeof command, "cat %s", log);
    FILE *pipe = popen(command, "r");
    assert_non_null(pipe);
    char output[8192];
    size_t n = fread(output, 1, sizeof output - 1, pipe);
    output[n] = '\0';
    pclose(pipe);
    FILE *file = fopen(grandchild_file, "r");
    assert_non_null(file);
    long grandchild = 0;
    assert_int_equal(fscanf(file, "%ld", &grandchild), 1);
    fclose(file);
    int left = 1;
    for (int tries = 0; tries < 50 && left; tries++) {
        left = running(grandchild);
        if (left)
            sleep_seconds(0.1);
    }
    print_message("%s    the hang's child %ld %s\n", output, grandchild,
                  left ? "still runs" : "was stopped with it");
    if (left)
        kill((pid_t)grandchild, SIGKILL);
    assert_true(WIFEXITED(status) && WEXITSTATUS(status) == 1);
    char expected[300];
    snprintf(expected, sizeof expected, "FAILED: %s/hangs: timed out: no end within 2 s",
             folder);
    assert_non_null(strstr(output, expected));
    snprintf(expected, sizeof expected, "FAILED: %s/fails: failed (exit status 3)", folder);
    assert_non_null(strstr(output, expected));
    assert_non_null(strstr(output, "programs: 1 passed, 2 failed"));
    assert_false(left);
}

static int make_folder(void **state) { return mkdtemp(folder) ? 0 : -1; }

static int remove_folder(void **state)
{
    char command[200];
    snprintf(command, sizeof command, "rm -rf '%s'", folder);
    return system(command) == 0 ? 0 : -1;
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_runner_stops_a_hang),
    };
    return cmocka_run_group_tests(tests, make_folder, remove_folder);
}
