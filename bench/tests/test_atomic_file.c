/* test_atomic_file.c (bench, chapter 1): output files are written whole or not at all
 * (atomic_file.h).
 *
 * Every way a write can go wrong is made to happen for real: the caller gives up, the
 * disk refuses the bytes (a file size limit, in a child process), the rename is
 * refused, the process dies halfway. Each time the file that was there before must be
 * intact, and, except after SIGKILL, no temporary file may be left beside it.
 *
 * Signals are raised by the writing child itself at each step of a write, so the race
 * is the same every run: SIGTERM, SIGHUP or a second SIGINT must kill it by that signal
 * and leave no temporary file (the handler of render_install_interrupt, renderer.h); a
 * first SIGINT alone must let the write finish.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <dirent.h>
#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "atomic_file.h"
#include "renderer.h"

#define OLD_CONTENT "the old file\n"
#define BIG_WRITE 100000 /* bytes, far above the file size limit below */

typedef struct {
    char dir[64];
    char target[128]; /* dir/output.txt, holding OLD_CONTENT */
} Scratch;

/* A fresh directory holding only the target, with its old content. */
static int make_scratch(void **state)
{
    Scratch *scratch = malloc(sizeof *scratch);
    if (!scratch)
        return -1;
    strcpy(scratch->dir, "/tmp/test_atomic_file_XXXXXX");
    if (!mkdtemp(scratch->dir)) {
        free(scratch);
        return -1;
    }
    snprintf(scratch->target, sizeof scratch->target, "%s/output.txt", scratch->dir);
    FILE *file = fopen(scratch->target, "w");
    if (!file || fputs(OLD_CONTENT, file) < 0 || fclose(file) != 0)
        return -1;
    *state = scratch;
    return 0;
}

/* Calls `visit` with the path of every entry of the scratch directory; returns their
 * count. */
static int each_entry(const Scratch *scratch, int (*visit)(const char *path))
{
    DIR *dir = opendir(scratch->dir);
    int count = 0;
    for (struct dirent *entry; dir && (entry = readdir(dir));) {
        if (entry->d_name[0] == '.')
            continue;
        char path[512];
        snprintf(path, sizeof path, "%s/%s", scratch->dir, entry->d_name);
        if (visit)
            visit(path);
        count++;
    }
    if (dir)
        closedir(dir);
    return count;
}

static int remove_scratch(void **state)
{
    Scratch *scratch = *state;
    each_entry(scratch, remove);
    rmdir(scratch->dir);
    free(scratch);
    return 0;
}

/* The whole content of a file, as a string (static buffer). */
static const char *content_of(const char *path)
{
    static char content[256];
    FILE *file = fopen(path, "r");
    assert_non_null(file);
    size_t length = fread(content, 1, sizeof content - 1, file);
    content[length] = '\0';
    fclose(file);
    return content;
}

static void write_big(FILE *file)
{
    for (int i = 0; i < BIG_WRITE; i++)
        fputc('x', file);
}

/* The old file is there, unchanged, and it is the only file in the directory. */
static void assert_old_file_alone(const Scratch *scratch)
{
    assert_string_equal(content_of(scratch->target), OLD_CONTENT);
    assert_int_equal(each_entry(scratch, NULL), 1);
}

/* Opens the target and writes `text` to the temporary file; until the close, readers
 * still see the old file. */
static AtomicFile begin_writing(const Scratch *scratch, const char *text)
{
    AtomicFile out;
    assert_int_equal(atomic_open(&out, scratch->target), 0);
    fputs(text, out.file);
    fflush(out.file);
    assert_string_equal(content_of(scratch->target), OLD_CONTENT);
    return out;
}

/* A complete write replaces the old file and leaves no temporary file. */
static void test_complete_write_replaces(void **state)
{
    Scratch *scratch = *state;
    AtomicFile out = begin_writing(scratch, "the new file\n");
    assert_int_equal(atomic_close(&out, 0), 0);
    assert_null(out.file);
    assert_string_equal(content_of(scratch->target), "the new file\n");
    assert_int_equal(each_entry(scratch, NULL), 1);
}

/* A caller that gives up (failed = 1) discards its bytes; its errno is passed on. */
static void test_caller_failure_discards(void **state)
{
    Scratch *scratch = *state;
    AtomicFile out = begin_writing(scratch, "half a new fi");
    errno = ENOMEM;
    assert_int_equal(atomic_close(&out, 1), -1);
    assert_int_equal(errno, ENOMEM);
    assert_old_file_alone(scratch);
}

/* Runs `body` on the target in a child process and returns the child's wait status. */
static int in_child(void (*body)(const char *target), const Scratch *scratch)
{
    fflush(NULL);
    pid_t child = fork();
    assert_true(child >= 0);
    if (child == 0) {
        body(scratch->target);
        _exit(3); /* never reached: each body ends the child */
    }
    int status;
    assert_int_equal(waitpid(child, &status, 0), child);
    return status;
}

/* With a file size limit of 1000 bytes and SIGXFSZ ignored, writes beyond the limit
 * fail with EFBIG; a 100 kB write must then fail in atomic_close with EFBIG. Unbuffered,
 * the write fails at once, leaving nothing for the close to flush, so only the stream's
 * error flag tells atomic_close. */
static void write_past_size_limit(const char *target, int unbuffered)
{
    struct rlimit limit = {1000, 1000};
    signal(SIGXFSZ, SIG_IGN);
    AtomicFile out;
    if (setrlimit(RLIMIT_FSIZE, &limit) != 0 || atomic_open(&out, target) != 0)
        _exit(2);
    if (unbuffered)
        setvbuf(out.file, NULL, _IONBF, 0);
    write_big(out.file);
    int status = atomic_close(&out, 0);
    _exit(status == -1 && errno == EFBIG ? 0 : 1);
}

static void write_beyond_size_limit(const char *target) { write_past_size_limit(target, 0); }

static void write_unbuffered_beyond_size_limit(const char *target)
{
    write_past_size_limit(target, 1);
}

/* Killed halfway, before the close. */
static void die_while_writing(const char *target)
{
    AtomicFile out;
    if (atomic_open(&out, target) != 0)
        _exit(2);
    write_big(out.file);
    fflush(out.file);
    raise(SIGKILL);
}

/* `body` writes into a file the disk refuses (a file size limit, in a child process):
 * the write fails with EFBIG and the old file survives alone. */
static void expect_write_refused(Scratch *scratch, void (*body)(const char *))
{
    int status = in_child(body, scratch);
    assert_true(WIFEXITED(status));
    assert_int_equal(WEXITSTATUS(status), 0);
    assert_old_file_alone(scratch);
}

static void test_write_error_discards(void **state)
{
    expect_write_refused(*state, write_beyond_size_limit);
}

/* The same through an unbuffered stream: the failed write alone must discard the file. */
static void test_unbuffered_write_error_discards(void **state)
{
    expect_write_refused(*state, write_unbuffered_beyond_size_limit);
}

/* The process dies halfway: the old file is intact. Only the temporary file, named after
 * the dead process, is left (nobody was there to remove it); the next run's writer uses
 * its own name. */
static void test_crash_keeps_old_file(void **state)
{
    Scratch *scratch = *state;
    int status = in_child(die_while_writing, scratch);
    assert_true(WIFSIGNALED(status));
    assert_string_equal(content_of(scratch->target), OLD_CONTENT);
    assert_int_equal(each_entry(scratch, NULL), 2);
}

/* The rename is refused (the target is a directory): -1, and the temporary file goes. */
static void test_refused_rename_discards(void **state)
{
    Scratch *scratch = *state;
    char target[160];
    snprintf(target, sizeof target, "%s/a_directory", scratch->dir);
    assert_int_equal(mkdir(target, 0700), 0);
    AtomicFile out;
    assert_int_equal(atomic_open(&out, target), 0);
    fputs("data", out.file);
    assert_int_equal(atomic_close(&out, 0), -1);
    assert_int_equal(errno, EISDIR);
    assert_int_equal(each_entry(scratch, NULL), 2); /* the old file and the directory */
    rmdir(target);
}

/* Opening fails cleanly: in a missing directory (ENOENT), and for a path too long for
 * the structure (ENAMETOOLONG); nothing is created. */
static void test_open_failures(void **state)
{
    Scratch *scratch = *state;
    char missing[160];
    snprintf(missing, sizeof missing, "%s/no/such/dir/file", scratch->dir);
    AtomicFile out;
    errno = 0;
    assert_int_equal(atomic_open(&out, missing), -1);
    assert_int_equal(errno, ENOENT);
    char long_path[5000];
    memset(long_path, 'a', sizeof long_path - 1);
    long_path[sizeof long_path - 1] = '\0';
    errno = 0;
    assert_int_equal(atomic_open(&out, long_path), -1);
    assert_int_equal(errno, ENAMETOOLONG);
    assert_old_file_alone(scratch);
}

/* The steps of a write at which a signal arrives. */
typedef enum {
    AT_OPENED,        /* the temporary file exists, empty */
    AT_WRITING,       /* 100 kB written, some of it still in the stream's buffer */
    AT_FLUSHED,       /* all of it on disk */
    AT_BEFORE_RENAME, /* closed, complete, not yet renamed (atomic_close's test hook) */
    STEP_COUNT
} Step;

static const char *const step_names[STEP_COUNT] = {"opened", "writing", "flushed",
                                                   "before rename"};

/* What the child raises at its step; a static, since the rename hook takes no argument
 * (each child has its own copy). */
static struct {
    int signals[2];
    int count;
    Step step;
} plan;

static void raise_planned(void)
{
    for (int i = 0; i < plan.count; i++)
        raise(plan.signals[i]);
}

static void raise_if_at(Step step)
{
    if (plan.step == step)
        raise_planned();
}

static void raise_planned_before_rename(void) { raise_if_at(AT_BEFORE_RENAME); }

/* With the program's signal handling installed: write the file, raising the planned
 * signals at the planned step. Exits 0 if it lives to the end with the file in place,
 * and its SIGINT, if any, noted as an interruption. */
static void write_with_signal(const char *target)
{
    render_install_interrupt();
    AtomicFile out;
    if (atomic_open(&out, target) != 0)
        _exit(2);
    out.before_rename = raise_planned_before_rename;
    raise_if_at(AT_OPENED);
    write_big(out.file);
    raise_if_at(AT_WRITING);
    fflush(out.file);
    raise_if_at(AT_FLUSHED);
    int status = atomic_close(&out, 0);
    _exit(status == 0 && render_interrupted() == (plan.signals[0] == SIGINT) ? 0 : 1);
}

static void set_plan(int first, int second, Step step)
{
    plan.signals[0] = first;
    plan.signals[1] = second;
    plan.count = second ? 2 : 1;
    plan.step = step;
}

/* SIGTERM, SIGHUP, and SIGINT twice, at every step of a write: the child dies of that
 * signal, and the old file is there alone, unchanged. */
static void test_fatal_signal_removes_temporary(void **state)
{
    Scratch *scratch = *state;
    const int patterns[3][2] = {{SIGTERM, 0}, {SIGHUP, 0}, {SIGINT, SIGINT}};
    for (int p = 0; p < 3; p++)
        for (int step = 0; step < STEP_COUNT; step++) {
            set_plan(patterns[p][0], patterns[p][1], (Step)step);
            int status = in_child(write_with_signal, scratch);
            int killer = patterns[p][patterns[p][1] ? 1 : 0];
            if (!WIFSIGNALED(status) || WTERMSIG(status) != killer)
                fail_msg("signal %d at step '%s': the child was not killed by it (status %#x)",
                         killer, step_names[step], status);
            if (each_entry(scratch, NULL) != 1)
                fail_msg("signal %d at step '%s': %d files left", killer, step_names[step],
                         each_entry(scratch, NULL));
            assert_old_file_alone(scratch);
        }
}

/* A first SIGINT only asks a render to stop: at any step, the write goes on to the end
 * and replaces the old file, and nothing else is left. */
static void test_first_interrupt_lets_write_finish(void **state)
{
    Scratch *scratch = *state;
    for (int step = 0; step < STEP_COUNT; step++) {
        set_plan(SIGINT, 0, (Step)step);
        int status = in_child(write_with_signal, scratch);
        assert_true(WIFEXITED(status));
        assert_int_equal(WEXITSTATUS(status), 0);
        assert_int_equal(each_entry(scratch, NULL), 1);
        FILE *file = fopen(scratch->target, "rb");
        assert_non_null(file);
        assert_int_equal(fseek(file, 0, SEEK_END), 0);
        assert_int_equal(ftell(file), BIG_WRITE);
        fclose(file);
        /* Back to the old content for the next step. */
        file = fopen(scratch->target, "w");
        assert_true(file && fputs(OLD_CONTENT, file) >= 0 && fclose(file) == 0);
    }
}

/* Two files being written at once, then SIGTERM: both temporary files go. */
static void write_two_then_terminate(const char *target)
{
    render_install_interrupt();
    char second[200];
    snprintf(second, sizeof second, "%s.second", target);
    AtomicFile a, b;
    if (atomic_open(&a, target) != 0 || atomic_open(&b, second) != 0)
        _exit(2);
    write_big(a.file);
    write_big(b.file);
    raise(SIGTERM);
    _exit(1);
}

static void test_terminate_removes_every_temporary(void **state)
{
    Scratch *scratch = *state;
    int status = in_child(write_two_then_terminate, scratch);
    assert_true(WIFSIGNALED(status));
    assert_int_equal(WTERMSIG(status), SIGTERM);
    assert_old_file_alone(scratch);
}

/* The table of temporary files is full at ATOMIC_OPEN_MAX: one more open fails with
 * EMFILE and creates nothing; closing one makes room again. */
static void test_open_limit(void **state)
{
    Scratch *scratch = *state;
    AtomicFile files[ATOMIC_OPEN_MAX + 1];
    for (int i = 0; i < ATOMIC_OPEN_MAX; i++) {
        char path[200];
        snprintf(path, sizeof path, "%s/file%d", scratch->dir, i);
        assert_int_equal(atomic_open(&files[i], path), 0);
    }
    errno = 0;
    assert_int_equal(atomic_open(&files[ATOMIC_OPEN_MAX], scratch->target), -1);
    assert_int_equal(errno, EMFILE);
    assert_int_equal(each_entry(scratch, NULL), 1 + ATOMIC_OPEN_MAX);
    for (int i = 0; i < ATOMIC_OPEN_MAX; i++)
        assert_int_equal(atomic_close(&files[i], 1), -1);
    assert_int_equal(atomic_open(&files[0], scratch->target), 0);
    assert_int_equal(atomic_close(&files[0], 1), -1);
    assert_old_file_alone(scratch);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(test_complete_write_replaces, make_scratch,
                                        remove_scratch),
        cmocka_unit_test_setup_teardown(test_caller_failure_discards, make_scratch,
                                        remove_scratch),
        cmocka_unit_test_setup_teardown(test_write_error_discards, make_scratch,
                                        remove_scratch),
        cmocka_unit_test_setup_teardown(test_unbuffered_write_error_discards, make_scratch,
                                        remove_scratch),
        cmocka_unit_test_setup_teardown(test_crash_keeps_old_file, make_scratch,
                                        remove_scratch),
        cmocka_unit_test_setup_teardown(test_refused_rename_discards, make_scratch,
                                        remove_scratch),
        cmocka_unit_test_setup_teardown(test_open_failures, make_scratch, remove_scratch),
        cmocka_unit_test_setup_teardown(test_fatal_signal_removes_temporary, make_scratch,
                                        remove_scratch),
        cmocka_unit_test_setup_teardown(test_first_interrupt_lets_write_finish, make_scratch,
                                        remove_scratch),
        cmocka_unit_test_setup_teardown(test_terminate_removes_every_temporary, make_scratch,
                                        remove_scratch),
        cmocka_unit_test_setup_teardown(test_open_limit, make_scratch, remove_scratch),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
