/* test_chapters.c (bench, chapter 1): a smoke render of every chapter program up to this one.
 *
 * Each program the snapshot has so far runs on a tiny image (16 pixels wide, a few
 * samples, a tiny reference) and must exit 0, print its table (the header line names
 * the "panel" and "seconds" columns), announce each file it writes as "wrote PATH",
 * and every PFM it names must exist and hold only finite numbers (no image a program
 * writes may carry a NaN or an infinity); so too with cameras of odd shapes, whose
 * smaller panels must fit them. Built with each chapter's snapshot, it runs the programs
 * that chapter has, found in $CHAPTER_DIR (the Makefile's build directory).
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "experiment.h"
#include "image.h"

#define SMALL "--quiet --size 16"
#define SMALLEST "--quiet --size 8"
#define FEW_SAMPLES "--spp 2 --reference-spp 4"

/* The programs' folder, $CHAPTER_DIR (or build), and this process's own folder for
 * their output in it, made if needed: test programs may run side by side. */
static const char *programs(void)
{
    return getenv("CHAPTER_DIR") ? getenv("CHAPTER_DIR") : "build";
}

static void scratch(char *folder, size_t size)
{
    snprintf(folder, size, "%s/smoke", programs());
    mkdir(folder, 0777);
    snprintf(folder, size, "%s/smoke/%d", programs(), (int)getpid());
    mkdir(folder, 0777);
}

/* Run one program with `size` (SMALL or SMALLEST) and `samples` into a fresh output
 * folder and check its output. */
static void smoke_at(const char *name, const char *size, const char *samples)
{
    static int runs;
    char folder[500], out[600], command[2048];
    scratch(folder, sizeof folder);
    snprintf(out, sizeof out, "%s/%s-%d", folder, name, runs++);
    snprintf(command, sizeof command, "rm -rf %s && %s/%s %s %s --out %s", out, programs(),
             name, size, samples, out);
    FILE *pipe = popen(command, "r");
    assert_non_null(pipe);
    char line[4608];
    int tables = 0, pfms = 0;
    while (fgets(line, sizeof line, pipe)) {
        if (strncmp(line, "panel ", 6) == 0 && strstr(line, "seconds"))
            tables++;
        if (strncmp(line, "wrote ", 6) != 0)
            continue;
        line[strcspn(line, "\n")] = '\0';
        const char *path = line + 6;
        size_t length = strlen(path);
        if (length < 4 || strcmp(path + length - 4, ".pfm") != 0)
            continue;
        Image image;
        char error[256];
        if (image_read_pfm(path, &image, error, sizeof error) != 0)
            fail_msg("%s: %s", name, error);
        for (long i = 0; i < 3L * image.width * image.height; i++)
            if (!isfinite(image.pixels[i]))
                fail_msg("%s: %s holds a non-finite value", name, path);
        image_free(&image);
        pfms++;
    }
    int status = pclose(pipe);
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
        fail_msg("%s exited with status %d", name,
                 WIFEXITED(status) ? WEXITSTATUS(status) : -1);
    print_message("    %s: %d tables, %d PFM images\n", name, tables, pfms);
    assert_true(tables >= 1);
    assert_true(pfms >= 1);
}

static void smoke(const char *name, const char *samples) { smoke_at(name, SMALL, samples); }

static void test_chapter1(void **state) { smoke("ch01_whitted", ""); }
#if CHAPTER >= 2
static void test_chapter2(void **state) { smoke("ch02_monte_carlo", FEW_SAMPLES); }
#endif
#if CHAPTER >= 3
static void test_chapter3(void **state) { smoke("ch03_shadow_rays", FEW_SAMPLES); }

/* Chapter 3 says in words whether 30 shadow rays lowered one shadow ray's error, from
 * what it measured. In the report's room they do not measurably (the error there is
 * elsewhere); under a lamp just above a floor, with only direct light (depth 2), they
 * do: there the program must not print the room's conclusion. */
static void test_chapter3_conclusion_follows_the_numbers(void **state)
{
    char folder[500], scene[600], command[2400];
    scratch(folder, sizeof folder);
    snprintf(scene, sizeof scene, "%s/near_lamp.scene", folder);
    FILE *file = fopen(scene, "w");
    assert_non_null(file);
    fputs("camera 0 0 10  -1 -1 9  1 -1 9  -1 1 9\n"
          "material floor lambert 0.5 0.5 0.5\n"
          "material lamp light 5 5 5\n"
          "quad floor  -10 -10 0  10 -10 0  10 10 0  -10 10 0\n"
          "quad lamp   -2 -2 1  -2 2 1  2 2 1  2 -2 1\n",
          file);
    assert_int_equal(fclose(file), 0);
    snprintf(command, sizeof command,
             "%s/ch03_shadow_rays --quiet --scene %s --depth 2 "
             "--size 64 --runs 8 --reference-spp 1024 --out %s/near_lamp",
             programs(), scene, folder);
    FILE *pipe = popen(command, "r");
    assert_non_null(pipe);
    char line[4608];
    int lowered = 0, not_lowered = 0;
    while (fgets(line, sizeof line, pipe)) {
        lowered += strstr(line, "lowered the error of M=1 measurably") != NULL &&
                   strstr(line, "did not") == NULL;
        not_lowered += strstr(line, "did not lower") != NULL;
    }
    assert_int_equal(pclose(pipe), 0);
    assert_int_equal(not_lowered, 0);
    assert_int_equal(lowered, 1);
}
#endif
#if CHAPTER >= 4
static void test_chapter4(void **state) { smoke("ch04_fresnel", FEW_SAMPLES); }
#endif
#if CHAPTER >= 5
static void test_chapter5(void **state) { smoke("ch05_oren_nayar", FEW_SAMPLES); }
#endif
#if CHAPTER >= 6
static void test_chapter6(void **state) { smoke("ch06_russian_roulette", FEW_SAMPLES); }
#endif
#if CHAPTER >= 7
static void test_chapter7(void **state) { smoke("ch07_final", FEW_SAMPLES); }
#endif
#if CHAPTER >= 8
static void test_chapter8(void **state) { smoke("ch08_photon_map", FEW_SAMPLES); }
#endif
#if CHAPTER >= 9
/* Run `program` with `arguments` on the room as the shell filter `edit` changes it
 * (written in the scratch folder as NAME.scene; the program's output goes to NAME/); its
 * standard output and error are read through the returned pipe. */
static FILE *run_on_edited_room(const char *name, const char *edit, const char *program,
                                const char *arguments)
{
    char folder[500], command[2400];
    scratch(folder, sizeof folder);
    snprintf(command, sizeof command, "%s scenes/room.scene > %s/%s.scene", edit, folder, name);
    assert_int_equal(system(command), 0);
    snprintf(command, sizeof command, "%s/%s %s --scene %s/%s.scene --out %s/%s 2>&1",
             programs(), program, arguments, folder, name, folder, name);
    FILE *pipe = popen(command, "r");
    assert_non_null(pipe);
    return pipe;
}

/* Chapter 9 exits 1 unless every stage rendered the same image, bit for bit. */
static void test_chapter9(void **state) { smoke("ch09_fast", "--quick --spp 1"); }

/* A rug of another material in the floor's plane, listed before the floor: where a ray
 * meets both at the same t, every stage must answer the rug (the lower number), so
 * chapter 9 renders the same image in every stage and exits 0. */
static void test_chapter9_ties_in_every_stage(void **state)
{
    FILE *pipe = run_on_edited_room(
        "rug",
        "awk '/# floor/ { print \"quad red  1 -3 -5   4 -3 -5   4 3 -5   1 3 -5\" } { print }'",
        "ch09_fast", "--quiet --quick --spp 1");
    char line[4608];
    int same = 0;
    while (fgets(line, sizeof line, pipe)) {
        if (strstr(line, "differ between the stages"))
            print_message("    %s", line);
        same += strstr(line, "every stage rendered the same image") != NULL;
    }
    assert_int_equal(pclose(pipe), 0);
    assert_int_equal(same, 1);
}

#if CHAPTER >= 10
/* Chapter 10 quickly: its table's ladders stop after a step of a quarter second. */
static void test_chapter10(void **state)
{
    smoke("ch10_adaptive", "--quick --spp 4 --reference-spp 4 --target-error 0.2");
}
#endif

/* A lamp with no blue: chapter 8's ratio of the image's channel means to the reference's
 * has nothing to divide by in blue, and must say so rather than print "nan". */
static void test_chapter8_lamp_without_blue(void **state)
{
    FILE *pipe = run_on_edited_room(
        "yellow", "sed 's/^material lamp   light   25 25 25/material lamp light 25 25 0/'",
        "ch08_photon_map", SMALL " " FEW_SAMPLES);
    char line[4608];
    int ratios = 0;
    while (fgets(line, sizeof line, pipe)) {
        int table_header = strncmp(line, "panel ", 6) == 0; /* its last column is "nan" */
        if (strstr(line, "nan") && !table_header)
            fail_msg("ch08_photon_map printed a NaN: %s", line);
        ratios += strstr(line, "photon map / reference:") != NULL;
    }
    assert_int_equal(pclose(pipe), 0);
    assert_int_equal(ratios, 1);
}
#endif

/* Each program, the scene it renders by default, and the samples it is run with. */
static const struct {
    const char *name, *scene, *samples;
} PROGRAMS[] = {{"ch01_whitted", "scenes/room_whitted.scene", ""},
                {"ch02_monte_carlo", "scenes/room.scene", FEW_SAMPLES},
                {"ch03_shadow_rays", "scenes/room.scene", FEW_SAMPLES},
                {"ch04_fresnel", "scenes/room.scene", FEW_SAMPLES},
                {"ch05_oren_nayar", "scenes/oren_nayar.scene", FEW_SAMPLES},
                {"ch06_russian_roulette", "scenes/room.scene", FEW_SAMPLES},
                {"ch07_final", "scenes/room.scene", FEW_SAMPLES},
                {"ch08_photon_map", "scenes/room.scene", FEW_SAMPLES},
                {"ch09_fast", "scenes/room.scene", "--quick --spp 1"}};

/* The smallest width --size accepts, 8 pixels, renders in every chapter: its crops,
 * quarter-size sweeps and plots included. */
static void test_smallest_size(void **state)
{
    for (int c = 0; c < CHAPTER && c < 8; c++)
        smoke_at(PROGRAMS[c].name, SMALLEST, PROGRAMS[c].samples);
}

/* `source` with its camera's image plane made `wide` x `high` (its centre one unit in
 * front of the eye, along x, as in the project's scenes), written in the scratch folder;
 * its path in path[size]. */
static void reshaped_scene(const char *source, double wide, double high, char *path,
                           size_t size)
{
    char folder[500], line[4096];
    scratch(folder, sizeof folder);
    snprintf(path, size, "%s/%gx%g-%s", folder, wide, high, strrchr(source, '/') + 1);
    FILE *in = fopen(source, "r"), *out = fopen(path, "w");
    assert_non_null(in);
    assert_non_null(out);
    double x, y, z, w = wide / 2, h = high / 2;
    while (fgets(line, sizeof line, in))
        if (sscanf(line, "camera %lf %lf %lf", &x, &y, &z) == 3)
            fprintf(out,
                    "camera %.17g %.17g %.17g  %.17g %.17g %.17g  %.17g %.17g %.17g  "
                    "%.17g %.17g %.17g\n",
                    x, y, z, x + 1, y + w, z - h, x + 1, y - w, z - h, x + 1, y + w, z + h);
        else
            fputs(line, out);
    fclose(in);
    assert_int_equal(fclose(out), 0);
}

/* Whether a `width` pixels wide image of aspect ratio `aspect` has a rounded height within
 * 1% of the plane's shape, as the programs require. */
static int fits(double aspect, int width)
{
    double exact = width / aspect;
    long height = lround(exact);
    return height >= 1 && height <= 16384 && fabs(height - exact) <= 0.01 * height;
}

/* experiment_width_near gives, for very wide, very tall and odd image planes, a width that
 * fits and that no nearer width beats (of two as near, the smaller); a quarter-size width
 * is no wider than its image (a 1:1000 camera at 8 pixels: 16 would be 16,000 high). */
static void test_width_near_fits_and_is_nearest(void **state)
{
    const double aspects[] = {1.0,    1.5,    32.0,        1.0 / 7.0, 1.37,
                              0.7071, 1000.0, 1.0 / 300.0, 2.999,     0.001};
    const int wanted[] = {1, 8, 12, 16, 25, 100, 240, 4099, 16384};
    for (size_t a = 0; a < sizeof aspects / sizeof *aspects; a++)
        for (size_t k = 0; k < sizeof wanted / sizeof *wanted; k++) {
            Scene scene;
            scene_init(&scene);
            scene.camera =
                camera_make(vec3(0, 0, 0), vec3(-aspects[a] / 2, -0.5, 1),
                            vec3(aspects[a] / 2, -0.5, 1), vec3(-aspects[a] / 2, 0.5, 1));
            int w = experiment_width_near(&scene, wanted[k]), d = abs(w - wanted[k]);
            if (!fits(aspects[a], w))
                fail_msg("aspect %g, wanted %d: width %d does not fit", aspects[a], wanted[k],
                         w);
            for (int c = wanted[k] - d; c <= wanted[k] + d; c++)
                if (c >= 1 && c != w && fits(aspects[a], c) &&
                    (abs(c - wanted[k]) < d || c < w))
                    fail_msg("aspect %g, wanted %d: width %d, but %d fits and is as near",
                             aspects[a], wanted[k], w, c);
            /* A quarter-size sweep's width is never wider than the image it is derived from. */
            if (fits(aspects[a], wanted[k])) {
                int quarter = experiment_width_near(&scene, cli_quarter(wanted[k], 16));
                if (quarter > wanted[k])
                    fail_msg("aspect %g: the quarter of %d is %d wide", aspects[a], wanted[k],
                             quarter);
            }
            scene_free(&scene);
        }
}

/* A --size valid for the image is valid for every smaller image a program derives from it
 * (quarter-size sweeps, chapter 9's knot table and panel): with a 3:2 camera at 21 pixels
 * (a quarter is 16 pixels, 10.67 high) and a 32:1 camera at 32 (16 pixels would be half
 * a pixel high), every program renders, writes its files and exits 0. */
static void test_derived_sizes_fit_the_camera(void **state)
{
    static const struct {
        double wide, high;
        const char *size;
    } cameras[] = {{3, 2, "--quiet --size 21"}, {32, 1, "--quiet --size 32"}};
    for (int c = 0; c < CHAPTER && c < 9; c++)
        for (int k = 0; k < 2; k++) {
            if (c == 8 && k == 0) /* chapter 9 once: its stages take seconds */
                continue;
            char scene[700], size[900];
            reshaped_scene(PROGRAMS[c].scene, cameras[k].wide, cameras[k].high, scene,
                           sizeof scene);
            snprintf(size, sizeof size, "%s --scene %s", cameras[k].size, scene);
            smoke_at(PROGRAMS[c].name, size, PROGRAMS[c].samples);
        }
}

#if CHAPTER >= 3
/* The case as a user meets it: chapter 3 with a 3:2 camera at --size 100 (its
 * sweep's quarter, 25 pixels, would be 16.67 high). And a --size the image itself cannot
 * take (3:2 at 20 pixels: 13.33 high) is refused before any file is written. */
static void test_size_refused_before_any_file(void **state)
{
    char scene[700], size[900], folder[500], command[2400], out[600];
    reshaped_scene("scenes/room.scene", 3, 2, scene, sizeof scene);
    snprintf(size, sizeof size, "--quiet --size 100 --scene %s", scene);
    smoke_at("ch03_shadow_rays", size, FEW_SAMPLES);
    scratch(folder, sizeof folder);
    for (int c = 0; c < CHAPTER && c < 9; c++) {
        snprintf(out, sizeof out, "%s/refused-%d", folder, c);
        reshaped_scene(PROGRAMS[c].scene, 3, 2, scene, sizeof scene);
        snprintf(command, sizeof command,
                 "rm -rf %s && %s/%s --quiet --size 20 --scene %s %s --out %s 2>&1", out,
                 programs(), PROGRAMS[c].name, scene, PROGRAMS[c].samples, out);
        FILE *pipe = popen(command, "r");
        assert_non_null(pipe);
        char line[4608];
        int wrote = 0, refused = 0;
        while (fgets(line, sizeof line, pipe)) {
            wrote += strncmp(line, "wrote ", 6) == 0;
            refused += strstr(line, "--size 20 gives no image") != NULL;
        }
        int status = pclose(pipe);
        if (!WIFEXITED(status) || WEXITSTATUS(status) != 2 || wrote || !refused)
            fail_msg("%s --size 20 with a 3:2 camera: exit %d, %d files written, %s",
                     PROGRAMS[c].name, WIFEXITED(status) ? WEXITSTATUS(status) : -1, wrote,
                     refused ? "refused" : "no message about the size");
        snprintf(command, sizeof command, "test -z \"$(ls -A %s 2>/dev/null)\"", out);
        assert_int_equal(system(command), 0);
    }
}
#endif

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_chapter1),
        cmocka_unit_test(test_smallest_size),
        cmocka_unit_test(test_width_near_fits_and_is_nearest),
        cmocka_unit_test(test_derived_sizes_fit_the_camera),
#if CHAPTER >= 2
        cmocka_unit_test(test_chapter2),
#endif
#if CHAPTER >= 3
        cmocka_unit_test(test_chapter3),
        cmocka_unit_test(test_chapter3_conclusion_follows_the_numbers),
        cmocka_unit_test(test_size_refused_before_any_file),
#endif
#if CHAPTER >= 4
        cmocka_unit_test(test_chapter4),
#endif
#if CHAPTER >= 5
        cmocka_unit_test(test_chapter5),
#endif
#if CHAPTER >= 6
        cmocka_unit_test(test_chapter6),
#endif
#if CHAPTER >= 7
        cmocka_unit_test(test_chapter7),
#endif
#if CHAPTER >= 8
        cmocka_unit_test(test_chapter8),
        cmocka_unit_test(test_chapter8_lamp_without_blue),
#endif
#if CHAPTER >= 9
        cmocka_unit_test(test_chapter9),
        cmocka_unit_test(test_chapter9_ties_in_every_stage),
#endif
#if CHAPTER >= 10
        cmocka_unit_test(test_chapter10),
#endif
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
