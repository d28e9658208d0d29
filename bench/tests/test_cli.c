/* test_cli.c (bench, chapter 1): the programs' command line and their handling of bad
 * input (cli.h, experiment.h), run on the real chapter 1 program.
 *
 * Every bad flag value and every bad scene file must give a message on stderr that
 * names the flag, or has the form "PROGRAM: FILE:LINE: what is wrong", exit status 2,
 * and no image. --help exits 0. A good run prints "wrote PATH" for each file, and
 * every file it names exists.
 *
 * The programs are found in $CHAPTER_DIR (the Makefile sets it to its build directory).
 */
#define _GNU_SOURCE /* unshare */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sched.h>
#include <sys/mount.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

static char program[512];
static char out_dir[] = "/tmp/test_cli_XXXXXX";

/* Run a shell command with its standard output captured; returns the exit status. */
static int capture(const char *command, char *output, size_t size)
{
    FILE *pipe = popen(command, "r");
    assert_non_null(pipe);
    size_t n = fread(output, 1, size - 1, pipe);
    output[n] = '\0';
    int status = pclose(pipe);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/* Run `program ARGS` with stdout and stderr captured; returns the exit status. */
static int run(const char *args, char *output, size_t size)
{
    char command[2048];
    snprintf(command, sizeof command, "%s --quiet --out %s/figures %s 2>&1", program, out_dir,
             args);
    return capture(command, output, size);
}

static int figures_written(void)
{
    char path[600];
    snprintf(path, sizeof path, "%s/figures/ch01_whitted.png", out_dir);
    return access(path, F_OK) == 0;
}

/* The run fails with status 2, says `where` and `message`, and writes no image. */
static void expect_error(const char *args, const char *where, const char *message)
{
    char output[4096];
    int status = run(args, output, sizeof output);
    if (status != 2 || strncmp(output, where, strlen(where)) != 0 || !strstr(output, message))
        fail_msg("'%s' gave status %d and\n%s\nexpected status 2, '%s' and '%s'", args, status,
                 output, where, message);
    assert_false(figures_written());
}

static void expect_failure(const char *args, const char *message)
{
    expect_error(args, "ch01_whitted: ", message);
}

static void test_bad_flags(void **state)
{
    expect_failure("--size 0", "--size: expected a whole number from 8 to 16384, got '0'");
    expect_failure("--size 7", "--size: expected a whole number from 8 to 16384, got '7'");
    expect_failure("--size -3", "--size: expected a whole number");
    expect_failure("--size abc", "--size: 'abc' is not a decimal number");
    expect_failure("--size 1.5", "--size: '1.5' is not a whole number; expected a whole number "
                                 "from 8 to 16384");
    expect_failure("--size 99999999999", "--size: expected a whole number from 8 to 16384, "
                                         "got '99999999999'");
    expect_failure("--size", "--size: missing value");
    expect_failure("--threads -1", "--threads: expected a whole number");
    expect_failure("--depth nan", "--depth: 'nan' is not a decimal number");
    expect_failure("--seed -4", "--seed: expected a whole number");
    expect_failure("--spp 4", "unknown option '--spp'"); /* chapter 1 takes no --spp */
    expect_failure("--bogus", "unknown option '--bogus'");
    expect_failure("--quiet=1", "--quiet takes no value");
}

/* Each number a flag may be given is refused with what is wrong with it: nothing, white
 * space around it, a form strtod reads but the flags do not (hexadecimal, nan, inf, a
 * lone sign), beyond a double either way (1e400; 1e-310, a subnormal, and 1e-400, which
 * reads as 0), a fraction for a whole number; and a number in range but for its sign. */
static void test_number_extremes(void **state)
{
    const char *cases[][2] = {
        {"''", "--size: expected a whole number from 8 to 16384, got an empty word"},
        {"'  16'", "--size: '  16' has white space in it"},
        {"'16 '", "--size: '16 ' has white space in it"},
        {"0x10", "--size: '0x10' is not a decimal number"},
        {"0x1p4", "--size: '0x1p4' is not a decimal number"},
        {"inf", "--size: 'inf' is not a decimal number"},
        {"+", "--size: '+' is not a decimal number"},
        {"1e400", "--size: '1e400' is too large for a double"},
        {"1e-310", "--size: '1e-310' is too small to compute with (below 2.22507e-308"},
        {"1e-400", "--size: '1e-400' is too small to compute with"},
        {"16.5", "--size: '16.5' is not a whole number"},
        {"-0", "--size: expected a whole number from 8 to 16384, got '-0'"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        char args[200];
        snprintf(args, sizeof args, "--size %s", cases[i][0]);
        expect_failure(args, cases[i][1]);
    }
    char output[4096];
    assert_int_equal(run("--size 1.6e1 --help", output, sizeof output), 0);
}

#if CHAPTER >= 7
/* --rr (chapter 7's) takes a real number in (0, 1]: 1e-310 is in it, but a subnormal, so it is
 * refused as too small to compute with, not as outside the range; 1e-300 is taken. */
static void test_roulette_extremes(void **state)
{
    const char *directory = getenv("CHAPTER_DIR") ? getenv("CHAPTER_DIR") : "build";
    const char *cases[][2] = {
        {"1e-310", "--rr: '1e-310' is too small to compute with (below 2.22507e-308, the "
                   "smallest double with all its digits); expected a number in (0, 1]"},
        {"0", "--rr: expected a number in (0, 1], got '0'"},
        {"-0", "--rr: expected a number in (0, 1], got '-0'"},
        {"1.0000001", "--rr: expected a number in (0, 1], got '1.0000001'"},
        {"nan", "--rr: 'nan' is not a decimal number"},
        {"1e-300", NULL},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        char command[800], output[4096];
        snprintf(command, sizeof command, "%s/ch07_final --rr %s --help 2>&1", directory,
                 cases[i][0]);
        int status = capture(command, output, sizeof output);
        if (cases[i][1] ? status != 2 || !strstr(output, cases[i][1]) : status != 0)
            fail_msg("--rr %s gave status %d and\n%s\nexpected %s", cases[i][0], status, output,
                     cases[i][1] ? cases[i][1] : "the help");
    }
}
#endif

/* A flag's value may not be the next flag: "--out --help" would otherwise make a
 * directory called --help, and "--scene --quiet" start a full render. A value that does
 * begin with "--" can still be given after '='. */
static void test_flag_value_is_not_a_flag(void **state)
{
    expect_failure("--out --help", "--out: missing value (got the option '--help'");
    expect_failure("--scene --quiet", "--scene: missing value (got the option '--quiet'");
    expect_failure("--size --quick", "--size: missing value");
}

/* --out is checked before anything is rendered: a path through a file is an error that
 * names the flag (exit 2), found before the render (nothing else printed). */
static void test_out_checked_first(void **state)
{
    char path[600], args[800], output[4096];
    snprintf(path, sizeof path, "%s/a_file", out_dir);
    FILE *file = fopen(path, "w");
    assert_non_null(file);
    fclose(file);
    snprintf(args, sizeof args, "--out %s/figures", path);
    assert_int_equal(run(args, output, sizeof output), 2);
    assert_non_null(strstr(output, "--out"));
    assert_non_null(strstr(output, "Not a directory"));
    assert_null(strstr(output, "wrote"));
}

/* A standard output that cannot be written (the "wrote" lines and the table are the
 * program's result) is a failure: exit 1 and a message, not exit 0. */
static void test_standard_output_full(void **state)
{
    char command[1200], message[512];
    snprintf(command, sizeof command, "%s --quiet --size 8 --out %s/full 2>&1 >/dev/full",
             program, out_dir);
    assert_int_equal(capture(command, message, sizeof message), 1);
    assert_non_null(strstr(message, "cannot write to standard output"));
}

/* Write `text` as a scene file in the temporary directory; returns its path. */
static const char *scene_file(const char *text)
{
    static char path[600];
    snprintf(path, sizeof path, "%s/bad.scene", out_dir);
    FILE *file = fopen(path, "w");
    assert_non_null(file);
    fputs(text, file);
    fclose(file);
    return path;
}

#define CAMERA "camera -1 0 0  0 1 -1  0 -1 -1  0 1 1\n"
#define MATERIAL "material white lambert 0.5 0.5 0.5\n"
#define LIGHT "point_light 5 0 4  10 10 10\n"

static void expect_scene_failure(const char *text, int line, const char *message)
{
    char args[700], where[700];
    const char *path = scene_file(text);
    snprintf(args, sizeof args, "--scene %s --size 16", path);
    snprintf(where, sizeof where, "ch01_whitted: %s:%d: ", path, line);
    expect_error(args, where, message);
}

/* One case per class of error in a scene file (docs/scene-format.md), each reported at
 * the line where it is. */
static void test_bad_scenes(void **state)
{
    expect_scene_failure(CAMERA MATERIAL "frobnicate 1 2 3\n", 3,
                         "unknown keyword 'frobnicate'");
    expect_scene_failure(CAMERA MATERIAL "sphere white 1 2 3\n", 3,
                         "expected 4 numbers, found 3");
    expect_scene_failure(CAMERA MATERIAL "sphere white 1 2 x3 1\n", 3,
                         "'x3' is not a decimal number");
    expect_scene_failure(CAMERA MATERIAL "sphere white 1 2 nan 1\n", 3,
                         "'nan' is not a decimal number");
    expect_scene_failure(CAMERA MATERIAL "sphere white 1 2 inf 1\n", 3,
                         "'inf' is not a decimal number");
    expect_scene_failure(CAMERA MATERIAL "sphere red 1 2 3 1\n", 3, "unknown material 'red'");
    expect_scene_failure(CAMERA MATERIAL MATERIAL, 3, "duplicate material 'white'");
    expect_scene_failure(CAMERA "material white lambert 1.5 0.5 0.5\n", 2, "outside [0, 1]");
    expect_scene_failure(CAMERA MATERIAL "sphere white 1 2 3 -1\n", 3, "must be > 0");
    expect_scene_failure(CAMERA "material rough oren_nayar 0.5 0.5 0.5 -0.1\n", 2,
                         "negative sigma");
    expect_scene_failure(CAMERA "material g glass 0\n", 2, "must be > 0");
    expect_scene_failure(CAMERA MATERIAL "triangle white 0 0 0  1 1 1  2 2 2\n", 3,
                         "degenerate");
    expect_scene_failure(CAMERA MATERIAL "quad white 0 0 0  1 0 0  1 1 0  0 1 1\n", 3,
                         "non-planar quad");
    expect_scene_failure(MATERIAL LIGHT, 2, "camera");
    expect_scene_failure(CAMERA MATERIAL "sphere white 5 0 0 1\n", 3, "no point_light");
    char *long_line = malloc(5000);
    memset(long_line, '#', 4998);
    long_line[4998] = '\n';
    long_line[4999] = '\0';
    char text[6000];
    snprintf(text, sizeof text, CAMERA "%s", long_line);
    expect_scene_failure(text, 2, "line longer than 1024 bytes");
    free(long_line);
    /* A file that does not exist, and a directory. */
    expect_failure("--scene /nonexistent/room.scene", "/nonexistent/room.scene:0:");
    expect_failure("--scene /tmp", "/tmp:0:");
}

/* An image size the image plane cannot have: a 2:1 plane needs an even width. */
static void test_aspect_ratio_mismatch(void **state)
{
    char args[700];
    snprintf(args, sizeof args, "--scene %s --size 9",
             scene_file("camera 0 0 0  -2 -1 1  2 -1 1  -2 1 1\n" MATERIAL LIGHT));
    expect_failure(args, "aspect ratio");
}

static void test_help_and_a_good_run(void **state)
{
    char output[8192];
    assert_int_equal(run("--help", output, sizeof output), 0);
    assert_non_null(strstr(output, "usage: ch01_whitted"));
    assert_non_null(strstr(output, "--size"));
    assert_false(figures_written());

    assert_int_equal(run("--size 24 --threads 2", output, sizeof output), 0);
    assert_true(figures_written());
    /* Every "wrote PATH" names a file that exists and is not empty. */
    int files = 0;
    for (char *line = strtok(output, "\n"); line; line = strtok(NULL, "\n")) {
        if (strncmp(line, "wrote ", 6) != 0)
            continue;
        struct stat info;
        assert_int_equal(stat(line + 6, &info), 0);
        assert_true(info.st_size > 0);
        files++;
    }
    assert_int_equal(files, 4); /* PNG, PFM, figure, CSV */
}

#if CHAPTER >= 2
/* Run chapter 2 on a tiny image with `scene_command` (a shell command) in front; returns
 * its exit status and its output in `output`. */
static int run_chapter2(const char *scene_command, const char *scene, char *output, size_t size)
{
    const char *directory = getenv("CHAPTER_DIR") ? getenv("CHAPTER_DIR") : "build";
    char command[2048];
    snprintf(command, sizeof command,
             "%s timeout 60 %s/ch02_monte_carlo --quiet --size 16 --spp 1 --reference-spp 2 "
             "--scene %s --out %s/ch02 2>&1",
             scene_command, directory, scene, out_dir);
    return capture(command, output, size);
}

/* The room with a comment that makes its bytes unlike any other run's. */
static const char *unique_room(const char *name, int variant)
{
    static char path[600];
    snprintf(path, sizeof path, "%s/%s.scene", out_dir, name);
    char command[1400];
    snprintf(command, sizeof command, "(echo '# %s %d %ld'; cat scenes/room.scene) > %s",
             out_dir, variant, (long)getpid(), path);
    assert_int_equal(system(command), 0);
    return path;
}

/* A scene read through a pipe is read once, and its reference is named by the bytes that
 * were read: a second, different scene through the same /dev/stdin gets a reference of
 * its own (it is rendered, not found in the cache), and the first one's bytes again find
 * theirs. */
static void test_piped_scenes_have_their_own_references(void **state)
{
    char output[16384], command[700];
    const char *first = unique_room("first", 1);
    snprintf(command, sizeof command, "cat %s |", first);
    assert_int_equal(run_chapter2(command, "/dev/stdin", output, sizeof output), 0);
    assert_non_null(strstr(output, "spp, rendered in"));
    const char *second = unique_room("second", 2);
    snprintf(command, sizeof command, "cat %s |", second);
    assert_int_equal(run_chapter2(command, "/dev/stdin", output, sizeof output), 0);
    assert_non_null(strstr(output, "spp, rendered in"));
    snprintf(command, sizeof command, "cat %s |", first);
    assert_int_equal(run_chapter2(command, "/dev/stdin", output, sizeof output), 0);
    assert_non_null(strstr(output, "spp, cached"));
}

/* A cache that cannot be written (here a file stands where the folder should be, which
 * stops root too): the program says why, renders its reference into a temporary folder,
 * keeps nothing, and still does its work. */
static void test_unwritable_cache(void **state)
{
    const char *directory = getenv("CHAPTER_DIR") ? getenv("CHAPTER_DIR") : "build";
    char command[2400], output[16384];
    snprintf(command, sizeof command,
             "mkdir -p %s/nocache && cp %s/ch02_monte_carlo %s/reference "
             "%s/nocache/ && : > %s/nocache/references",
             out_dir, directory, directory, out_dir, out_dir);
    assert_int_equal(system(command), 0);
    snprintf(command, sizeof command,
             "%s/nocache/ch02_monte_carlo --quiet --size 16 --spp 1 "
             "--runs 1 --reference-spp 8 --out %s/nocache/figures 2>&1",
             out_dir, out_dir);
    int status = capture(command, output, sizeof output);
    if (status != 0)
        fail_msg("status %d:\n%s", status, output);
    assert_non_null(strstr(output, "cannot write in"));
    assert_non_null(strstr(output, "Not a directory"));
    assert_non_null(strstr(output, "nothing is kept"));
    assert_non_null(strstr(output, "spp, rendered in"));
}

/* A lamp of emission 0 0 0 is read (a light that emits nothing), but chapter 2, which
 * needs an area light, names it as the cause: not "no area light" alone. */
static void test_dark_lamp_named(void **state)
{
    char path[600], command[1400], output[16384];
    snprintf(path, sizeof path, "%s/dark.scene", out_dir);
    snprintf(command, sizeof command,
             "sed 's/^material lamp .*/material lamp light 0 0 0/' "
             "scenes/room.scene > %s",
             path);
    assert_int_equal(system(command), 0);
    assert_int_equal(run_chapter2("", path, output, sizeof output), 2);
    if (!strstr(output, "no area light: material 'lamp' is a light of emission 0 0 0, which "
                        "emits nothing"))
        fail_msg("%s", output);
}

/* A cache on a full disk (a tmpfs of 12 KiB, in a mount namespace of this test's own:
 * skipped where that is not allowed): the reference program says why it cannot write
 * there, keeps the reference in a temporary folder for this run, the program does its
 * work, and the temporary folder is gone after it. */
static void test_full_cache(void **state)
{
    const char *directory = getenv("CHAPTER_DIR") ? getenv("CHAPTER_DIR") : "build";
    char folder[600], command[2400], log[700], temporary[700], output[16384];
    snprintf(folder, sizeof folder, "%s/fullcache", out_dir);
    snprintf(log, sizeof log, "%s/log", folder);
    snprintf(temporary, sizeof temporary, "%s/tmp", folder);
    snprintf(command, sizeof command,
             "mkdir -p %s/references %s && cp %s/ch02_monte_carlo "
             "%s/reference %s/",
             folder, temporary, directory, directory, folder);
    assert_int_equal(system(command), 0);
    fflush(NULL);
    pid_t child = fork();
    assert_true(child >= 0);
    if (child == 0) {
        char cache[700], program[700];
        snprintf(cache, sizeof cache, "%s/references", folder);
        snprintf(program, sizeof program, "%s/ch02_monte_carlo", folder);
        if (unshare(CLONE_NEWNS) != 0 ||
            mount("none", "/", NULL, MS_REC | MS_PRIVATE, NULL) != 0 ||
            mount("none", cache, "tmpfs", 0, "size=12k") != 0)
            _exit(77);
        setenv("TMPDIR", temporary, 1);
        if (!freopen(log, "w", stdout) || dup2(STDOUT_FILENO, STDERR_FILENO) < 0)
            _exit(78);
        execl(program, program, "--quiet", "--size", "64", "--spp", "1", "--runs", "1",
              "--reference-spp", "8", "--out", folder, (char *)NULL);
        _exit(79);
    }
    int status;
    assert_int_equal(waitpid(child, &status, 0), child);
    if (WIFEXITED(status) && WEXITSTATUS(status) == 77) {
        print_message("    skipped: this test may not mount a tmpfs (it needs root)\n");
        skip();
    }
    char left[4096];
    snprintf(command, sizeof command, "ls -A %s", temporary);
    capture(command, left, sizeof left);
    snprintf(command, sizeof command, "grep -v '^wrote\\|^ch02_\\|^panel' %s", log);
    capture(command, output, sizeof output);
    print_message("    %s    temporary folders left: %s\n", output, left[0] ? left : "none\n");
    assert_true(WIFEXITED(status) && WEXITSTATUS(status) == 0);
    assert_non_null(strstr(output, "cannot write the reference into"));
    assert_non_null(strstr(output, "No space left on device: kept in"));
    assert_non_null(strstr(output, "spp, rendered in"));
    assert_string_equal(left, "");
}

/* A FIFO can be read only once: the program must not wait to read it again. */
static void test_scene_from_a_fifo(void **state)
{
    char fifo[600], command[1400], output[16384];
    snprintf(fifo, sizeof fifo, "%s/scene.fifo", out_dir);
    assert_int_equal(mkfifo(fifo, 0600), 0);
    snprintf(command, sizeof command, "(cat %s > %s &) ;", unique_room("fifo", 3), fifo);
    int status = run_chapter2(command, fifo, output, sizeof output);
    if (status != 0)
        fail_msg("status %d:\n%s", status, output);
    assert_non_null(strstr(output, "wrote "));
}
#endif

/* The bench's own programs speak as the chapters' do: the reference renderer prints its
 * usage for --help and refuses a cache key or seed that is not all digits; the gallery makes
 * its --out folder however deep, and fails, rather than exit 0, when what it prints is lost
 * (standard output on a full device). */
static void test_bench_programs(void **state)
{
    const char *directory = getenv("CHAPTER_DIR") ? getenv("CHAPTER_DIR") : "build";
    char command[2048], output[4096];
    snprintf(command, sizeof command, "%s/reference --help 2>&1", directory);
    assert_int_equal(capture(command, output, sizeof output), 0);
    assert_non_null(strstr(output, "usage: reference"));
    const char *bad_numbers[][2] = {
        {"room", "1"}, {"-1", "1"}, {"12345678901234567", "1"}, {"ab", "x"}, {"ab", "-2"}};
    for (size_t i = 0; i < sizeof bad_numbers / sizeof bad_numbers[0]; i++) {
        snprintf(command, sizeof command,
                 "%s/reference --scene scenes/room.scene --size 8 "
                 "--reference-spp 8 --depth 2 --out %s --key %s --seed %s --quiet 2>&1",
                 directory, out_dir, bad_numbers[i][0], bad_numbers[i][1]);
        if (capture(command, output, sizeof output) != 2 || !strstr(output, "expected"))
            fail_msg("reference with --key %s --seed %s: %s", bad_numbers[i][0],
                     bad_numbers[i][1], output);
    }
    snprintf(command, sizeof command, "%s/gallery --out %s/deep/er/gallery 2>&1", directory,
             out_dir);
    assert_int_equal(capture(command, output, sizeof output), 0);
    snprintf(command, sizeof command, "%s/deep/er/gallery/index.html", out_dir);
    assert_int_equal(access(command, F_OK), 0);
    snprintf(command, sizeof command, "%s/gallery --out %s/deep 2>&1 >/dev/full", directory,
             out_dir);
    assert_int_equal(capture(command, output, sizeof output), 1);
    assert_non_null(strstr(output, "cannot write to the standard output"));
}

int main(void)
{
    const char *directory = getenv("CHAPTER_DIR");
    snprintf(program, sizeof program, "%s/ch01_whitted", directory ? directory : "build");
    if (access(program, X_OK) != 0) {
        fprintf(stderr, "test_cli: %s not built (set CHAPTER_DIR)\n", program);
        return 1;
    }
    if (!mkdtemp(out_dir))
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_bad_flags),
        cmocka_unit_test(test_number_extremes),
#if CHAPTER >= 7
        cmocka_unit_test(test_roulette_extremes),
#endif
        cmocka_unit_test(test_flag_value_is_not_a_flag),
        cmocka_unit_test(test_out_checked_first),
        cmocka_unit_test(test_standard_output_full),
        cmocka_unit_test(test_bad_scenes),
        cmocka_unit_test(test_aspect_ratio_mismatch),
        cmocka_unit_test(test_help_and_a_good_run),
        cmocka_unit_test(test_bench_programs),
#if CHAPTER >= 2
        cmocka_unit_test(test_piped_scenes_have_their_own_references),
        cmocka_unit_test(test_scene_from_a_fifo),
        cmocka_unit_test(test_unwritable_cache),
        cmocka_unit_test(test_full_cache),
        cmocka_unit_test(test_dark_lamp_named),
#endif
    };
    int failed = cmocka_run_group_tests(tests, NULL, NULL);
    char command[600];
    snprintf(command, sizeof command, "rm -rf %s", out_dir);
    if (system(command) != 0)
        return 1;
    return failed;
}
