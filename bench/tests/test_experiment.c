/* test_experiment.c (bench, chapter 2): what a chapter program does when it is interrupted
 * (experiment.h; its files are written whole or not at all).
 *
 * SIGINT asks a render to stop. A panel is then saved only if every pixel has at least
 * one sample (an image of zeros must never replace a good one), the message says what
 * was saved, and the program exits with status 130; a SIGINT that came before a render
 * stops the program before it. Each case is driven deterministically: the estimator
 * itself raises SIGINT at a chosen sample, in a child process (the program exits).
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
#include <sys/wait.h>
#include <unistd.h>

#include "experiment.h"

enum {
    SIDE = 8,
    SPP = 4
};
static char out_dir[] = "/tmp/test_experiment_XXXXXX";

/* The estimator's settings: it raises SIGINT at its call number `raise_at` (one thread,
 * so calls come pass by pass, row by row: call SIDE * SIDE is pass 1's first sample). */
typedef struct {
    long raise_at;
    long *calls;
} Interrupting;

static Vec3 interrupting(const Scene *scene, Ray ray, Rng *rng, const void *settings,
                         RayCounts *counts)
{
    const Interrupting *s = settings;
    if ((*s->calls)++ == s->raise_at)
        raise(SIGINT);
    return vec3(1, 1, 1);
}

typedef struct {
    int status;
    char message[1024];
    int png_written;
} Outcome;

/* In a child: render a panel with SIGINT raised by `when` before it, or by the
 * estimator at its call `raise_at` (-1: never), then report. */
static Outcome run_panel(void (*when)(void), long raise_at)
{
    int pipe_ends[2];
    assert_int_equal(pipe(pipe_ends), 0);
    fflush(NULL);
    pid_t child = fork();
    assert_true(child >= 0);
    if (child == 0) {
        dup2(pipe_ends[1], STDERR_FILENO);
        close(pipe_ends[0]);
        Scene scene;
        scene_init(&scene);
        scene.camera =
            camera_make(vec3(0, 0, 0), vec3(-1, -1, 1), vec3(1, -1, 1), vec3(-1, 1, 1));
        Options options = {.out = out_dir, .quiet = 1, .size = SIDE, .threads = 1};
        RenderSettings settings =
            experiment_render_settings(&options, &scene, SPP, PIXEL_RANDOM, "panel");
        render_install_interrupt();
        when();
        long calls = 0;
        Interrupting estimator = {raise_at, &calls};
        RenderResult result;
        experiment_runs(&options, &scene, &settings, interrupting, &estimator, "panel", "test",
                        NULL, 1, &result);
        _exit(0);
    }
    close(pipe_ends[1]);
    Outcome outcome = {0};
    size_t length = 0; /* read to the end: a child writing to a closed pipe would die */
    ssize_t n;
    while ((n = read(pipe_ends[0], outcome.message + length,
                     sizeof outcome.message - 1 - length)) > 0)
        length += (size_t)n;
    outcome.message[length] = '\0';
    close(pipe_ends[0]);
    int status;
    assert_int_equal(waitpid(child, &status, 0), child);
    outcome.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    char path[600];
    snprintf(path, sizeof path, "%s/panel.png", out_dir);
    outcome.png_written = access(path, F_OK) == 0;
    remove(path);
    snprintf(path, sizeof path, "%s/panel.pfm", out_dir);
    remove(path);
    return outcome;
}

static void raise_now(void) { raise(SIGINT); }
static void not_at_all(void) {}

/* SIGINT before the render: nothing is rendered or written, and the message says so. */
static void test_interrupt_before_render(void **state)
{
    Outcome outcome = run_panel(raise_now, -1);
    print_message("    %s", outcome.message);
    assert_int_equal(outcome.status, 130);
    assert_false(outcome.png_written);
    assert_non_null(strstr(outcome.message, "stopped before rendering panel"));
}

/* Without SIGINT, the panel is written and the program goes on. */
static void test_no_interrupt(void **state)
{
    Outcome outcome = run_panel(not_at_all, -1);
    assert_int_equal(outcome.status, 0);
    assert_true(outcome.png_written);
}

/* SIGINT during the first pass: some pixels have no sample yet, so nothing is written
 * (an image of zeros would replace a good one), and the message says nothing was saved. */
static void test_interrupt_in_first_pass(void **state)
{
    Outcome outcome = run_panel(not_at_all, 0);
    print_message("    %s", outcome.message);
    assert_int_equal(outcome.status, 130);
    assert_false(outcome.png_written);
    assert_non_null(strstr(outcome.message, "nothing saved"));
}

/* SIGINT in the second pass: every pixel has a sample, so the panel is saved, and the
 * message names it. */
static void test_interrupt_in_second_pass(void **state)
{
    Outcome outcome = run_panel(not_at_all, SIDE * SIDE);
    print_message("    %s", outcome.message);
    assert_int_equal(outcome.status, 130);
    assert_true(outcome.png_written);
    assert_non_null(strstr(outcome.message, "saved panel after"));
}

int main(void)
{
    if (!mkdtemp(out_dir))
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_interrupt_before_render),
        cmocka_unit_test(test_no_interrupt),
        cmocka_unit_test(test_interrupt_in_first_pass),
        cmocka_unit_test(test_interrupt_in_second_pass),
    };
    int failed = cmocka_run_group_tests(tests, NULL, NULL);
    rmdir(out_dir);
    return failed;
}
