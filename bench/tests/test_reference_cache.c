/* test_reference_cache.c (bench, chapter 2): the reference cache believes only an entry
 * that proves it is whole and is the one asked for (measure.h).
 *
 * A round trip through a scratch folder; then every way an entry can be wrong, each of
 * which must make the load refuse it (-2, one line saying why, an empty Reference):
 * every single bit of each of its three files flipped in turn, each file cut short,
 * grown or missing, another key's or another scene's entry or other settings under this key,
 * values that no render gives in an entry whose checksums are right, a FIFO in a file's
 * place (refused without waiting for a writer). A save stopped by SIGTERM or SIGHUP at
 * random moments leaves the whole entry or nothing, never KEY.pfm alone.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <errno.h>
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "measure.h"
#include "renderer.h"

/* A scratch folder per test, emptied and removed after it. */
static char scratch_dir[64], scratch_path[4300];

static int make_scratch(void **state)
{
    strcpy(scratch_dir, "/tmp/test_reference_cache_XXXXXX");
    return mkdtemp(scratch_dir) ? 0 : -1;
}

static const char *in_scratch(const char *name)
{
    snprintf(scratch_path, sizeof scratch_path, "%s/%s", scratch_dir, name);
    return scratch_path;
}

static int remove_scratch(void **state)
{
    char command[200];
    snprintf(command, sizeof command, "rm -rf '%s'", scratch_dir);
    return system(command) == 0 ? 0 : -1;
}

/* The entry every test asks for, and its three files. */
#define KEY 0x0123456789abcdefULL
#define MEAN_FILE "0123456789abcdef.pfm"
#define STD_ERROR_FILE "0123456789abcdef-stderr.pfm"
#define INFO_FILE "0123456789abcdef.txt"
static const char *const ENTRY_FILES[3] = {MEAN_FILE, STD_ERROR_FILE, INFO_FILE};

static ReferenceIdentity identity_of(uint64_t key, uint64_t scene_hash, long spp)
{
    ReferenceIdentity identity = {key, scene_hash, ""};
    measure_reference_settings(&identity, 3, spp, 16, "schlick", 18446744073709551614ULL, "=0");
    return identity;
}

static ReferenceIdentity wanted(void) { return identity_of(KEY, 0xfeedfacecafebeefULL, 4096); }

/* A reference with distinct values everywhere, as a render would leave it (each
 * standard error below its pixel's value). */
static Reference sample_reference(int width, int height)
{
    Reference reference = {.image = image_new(width, height),
                           .std_error = image_new(width, height),
                           .spp = 4096,
                           .seconds = 12.345678901234567,
                           .mean_std_error = 1.25e-3};
    assert_non_null(reference.image.pixels);
    assert_non_null(reference.std_error.pixels);
    for (int i = 0; i < 3 * width * height; i++) {
        reference.image.pixels[i] = 0.1f * (float)(i % 97) + 1e-7f;
        reference.std_error.pixels[i] = 1e-3f / (float)(i % 89 + 1) * reference.image.pixels[i];
    }
    double unused;
    measure_image_mean(&reference.image, &reference.std_error, &reference.mean, &unused);
    return reference;
}

static void save(const ReferenceIdentity *identity, const Reference *reference)
{
    assert_int_equal(measure_save_reference(scratch_dir, identity, reference), 0);
}

static void save_sample(void)
{
    Reference saved = sample_reference(3, 2);
    ReferenceIdentity identity = wanted();
    save(&identity, &saved);
    measure_reference_free(&saved);
}

/* Load the wanted entry; its status, with why (printed) when it is refused. */
static int load(const char *what, Reference *loaded)
{
    char why[320] = "";
    ReferenceIdentity identity = wanted();
    int status = measure_load_reference(scratch_dir, &identity, 3, 2, loaded, why, sizeof why);
    if (what)
        print_message("    %s: %d (%s)\n", what, status, why);
    if (status != 0) {
        assert_null(loaded->image.pixels);
        assert_null(loaded->std_error.pixels);
        assert_int_equal(loaded->cached, 0);
        assert_true(status == -1 || (why[0] != '\0' && !strchr(why, '\n')));
    }
    return status;
}

/* The load refuses the entry as it now is, saying why. */
static void assert_refused(const char *what)
{
    Reference loaded;
    assert_int_equal(load(what, &loaded), -2);
}

/* Saved then loaded, a reference comes back bit for bit (image and standard errors),
 * with its numbers, marked as cached, its noise the RMS of its standard errors. */
static void test_round_trip(void **state)
{
    Reference saved = sample_reference(3, 2);
    ReferenceIdentity identity = wanted();
    save(&identity, &saved);
    for (int i = 0; i < 3; i++)
        assert_int_equal(access(in_scratch(ENTRY_FILES[i]), R_OK), 0);
    Reference loaded;
    assert_int_equal(load(NULL, &loaded), 0);
    assert_int_equal(loaded.image.width, 3);
    assert_int_equal(loaded.image.height, 2);
    assert_memory_equal(loaded.image.pixels, saved.image.pixels, 18 * sizeof(float));
    assert_memory_equal(loaded.std_error.pixels, saved.std_error.pixels, 18 * sizeof(float));
    assert_true(loaded.spp == saved.spp && loaded.seconds == saved.seconds);
    assert_true(loaded.mean == saved.mean && loaded.mean_std_error == saved.mean_std_error);
    assert_int_equal(loaded.cached, 1);
    assert_true(loaded.noise == measure_rms(&saved.std_error) && loaded.noise > 0.0);
    measure_reference_free(&loaded);
    measure_reference_free(&saved);
}

/* No description: no entry (-1), an empty Reference even if it held garbage before. */
static void test_missing_entry(void **state)
{
    Reference loaded;
    memset(&loaded, 0x5a, sizeof loaded);
    assert_int_equal(load(NULL, &loaded), -1);
}

static unsigned char *read_file(const char *name, size_t *length)
{
    FILE *file = fopen(in_scratch(name), "rb");
    assert_non_null(file);
    unsigned char *bytes = malloc(1 << 16);
    assert_non_null(bytes);
    *length = fread(bytes, 1, 1 << 16, file);
    fclose(file);
    return bytes;
}

static void write_file(const char *name, const unsigned char *bytes, size_t length)
{
    FILE *file = fopen(in_scratch(name), "wb");
    assert_non_null(file);
    assert_int_equal(fwrite(bytes, 1, length, file), length);
    assert_int_equal(fclose(file), 0);
}

/* Every bit of every file of the entry, flipped alone: each flip refused. */
static void test_every_flipped_bit_is_refused(void **state)
{
    save_sample();
    for (int f = 0; f < 3; f++) {
        size_t length;
        unsigned char *bytes = read_file(ENTRY_FILES[f], &length);
        int accepted = 0;
        for (size_t byte = 0; byte < length; byte++)
            for (int bit = 0; bit < 8; bit++) {
                bytes[byte] ^= (unsigned char)(1u << bit);
                write_file(ENTRY_FILES[f], bytes, length);
                Reference loaded;
                int status = load(NULL, &loaded);
                if (status == 0) {
                    if (!accepted++)
                        print_message("    %s: byte %zu bit %d flipped, yet accepted\n",
                                      ENTRY_FILES[f], byte, bit);
                    measure_reference_free(&loaded);
                }
                bytes[byte] ^= (unsigned char)(1u << bit);
            }
        write_file(ENTRY_FILES[f], bytes, length);
        free(bytes);
        print_message("    %s: %zu bits flipped one at a time, %d accepted\n", ENTRY_FILES[f],
                      8 * length, accepted);
        assert_int_equal(accepted, 0);
    }
    Reference loaded;
    assert_int_equal(load("restored", &loaded), 0);
    measure_reference_free(&loaded);
}

/* Each file cut short (to nothing, to half, by its last byte), grown by a byte, or
 * missing. */
static void test_cut_grown_or_missing_files_are_refused(void **state)
{
    for (int f = 0; f < 3; f++) {
        for (int cut = 0; cut < 5; cut++) {
            save_sample();
            struct stat status;
            assert_int_equal(stat(in_scratch(ENTRY_FILES[f]), &status), 0);
            off_t lengths[3] = {0, status.st_size / 2, status.st_size - 1};
            char what[200];
            if (cut < 3) {
                assert_int_equal(truncate(in_scratch(ENTRY_FILES[f]), lengths[cut]), 0);
                snprintf(what, sizeof what, "%s cut to %lld bytes", ENTRY_FILES[f],
                         (long long)lengths[cut]);
            } else if (cut == 3) {
                FILE *file = fopen(in_scratch(ENTRY_FILES[f]), "ab");
                assert_non_null(file);
                fputc('\n', file);
                assert_int_equal(fclose(file), 0);
                snprintf(what, sizeof what, "%s grown by a byte", ENTRY_FILES[f]);
            } else {
                assert_int_equal(remove(in_scratch(ENTRY_FILES[f])), 0);
                snprintf(what, sizeof what, "%s removed", ENTRY_FILES[f]);
            }
            Reference loaded;
            /* Without its description the entry is not there at all. */
            assert_int_equal(load(what, &loaded), f == 2 && cut == 4 ? -1 : -2);
        }
    }
}

/* Rename entry `key`'s three files to the wanted key's names. */
static void copy_under_wanted_key(uint64_t key)
{
    const char *suffixes[3] = {".pfm", "-stderr.pfm", ".txt"};
    for (int i = 0; i < 3; i++) {
        char from[4300];
        snprintf(from, sizeof from, "%s/%016llx%s", scratch_dir, (unsigned long long)key,
                 suffixes[i]);
        assert_int_equal(rename(from, in_scratch(ENTRY_FILES[i])), 0);
    }
}

/* Whole entries, but not the one asked for: another key's copied under this key (its
 * own scene, or the same scene), another scene's or other settings' under this key. */
static void test_other_entries_are_refused(void **state)
{
    Reference saved = sample_reference(3, 2);
    ReferenceIdentity other_key_and_scene = identity_of(0x1111, 0x2222, 4096);
    save(&other_key_and_scene, &saved);
    copy_under_wanted_key(0x1111);
    assert_refused("another scene's entry copied under this key");

    ReferenceIdentity other_key = identity_of(0x1111, wanted().scene_hash, 4096);
    save(&other_key, &saved);
    copy_under_wanted_key(0x1111);
    assert_refused("another key's entry of this scene copied under this key");

    ReferenceIdentity other_scene = identity_of(KEY, 0x2222, 4096);
    save(&other_scene, &saved);
    assert_refused("this key, another scene");

    ReferenceIdentity other_settings = identity_of(KEY, wanted().scene_hash, 8192);
    save(&other_settings, &saved);
    assert_refused("this key and scene, other settings");
    measure_reference_free(&saved);
}

/* An entry whose checksums are right but whose values no render gives: a pixel negative
 * or infinite, a standard error above its pixel, non-finite seconds, a stored mean
 * that is not the image's, another size. */
static void test_impossible_values_are_refused(void **state)
{
    ReferenceIdentity identity = wanted();
    for (int k = 0; k < 7; k++) {
        Reference forged = sample_reference(3, 2);
        const char *what[7] = {"a pixel of -1e30",
                               "an infinite pixel",
                               "a standard error of 5.6e34",
                               "a standard error of 2 x its pixel",
                               "NaN seconds",
                               "a stored mean 1% off",
                               "a 2 x 3 image"};
        switch (k) {
        case 0:
            forged.image.pixels[4] = -1e30f;
            break;
        case 1:
            forged.image.pixels[7] = INFINITY;
            break;
        case 2:
            forged.std_error.pixels[2] = 5.6e34f;
            break;
        case 3:
            forged.std_error.pixels[9] = 2.0f * forged.image.pixels[9];
            break;
        case 4:
            forged.seconds = NAN;
            break;
        case 5:
            forged.mean *= 1.01;
            break;
        default:
            forged.image.width = forged.std_error.width = 2;
            forged.image.height = forged.std_error.height = 3;
        }
        save(&identity, &forged);
        assert_refused(what[k]);
        measure_reference_free(&forged);
    }
}

static void on_alarm(int signal_number)
{
    (void)signal_number;
    static const char message[] = "a FIFO in the cache stopped the load\n";
    ssize_t unused = write(STDERR_FILENO, message, sizeof message - 1);
    (void)unused;
    _exit(1);
}

/* A FIFO in place of a file (no one writes to it) is refused at once. */
static void test_fifo_in_a_files_place_is_refused(void **state)
{
    signal(SIGALRM, on_alarm);
    for (int f = 0; f < 3; f++) {
        save_sample();
        assert_int_equal(remove(in_scratch(ENTRY_FILES[f])), 0);
        assert_int_equal(mkfifo(in_scratch(ENTRY_FILES[f]), 0600), 0);
        alarm(10);
        char what[200];
        snprintf(what, sizeof what, "a FIFO in place of %s", ENTRY_FILES[f]);
        assert_refused(what);
        alarm(0);
        assert_int_equal(remove(in_scratch(ENTRY_FILES[f])), 0);
    }
    signal(SIGALRM, SIG_DFL);
}

/* A save that fails part-way (a folder stands where the standard errors go, as a full
 * disk would stop it) leaves no part of the entry behind; so does one into a folder
 * that does not exist. */
static void test_failed_save_leaves_nothing(void **state)
{
    assert_int_equal(mkdir(in_scratch(STD_ERROR_FILE), 0700), 0);
    Reference saved = sample_reference(3, 2);
    ReferenceIdentity identity = wanted();
    assert_int_equal(measure_save_reference(scratch_dir, &identity, &saved), -1);
    assert_int_equal(access(in_scratch(MEAN_FILE), F_OK), -1);
    assert_int_equal(access(in_scratch(INFO_FILE), F_OK), -1);
    assert_int_equal(rmdir(in_scratch(STD_ERROR_FILE)), 0);
    assert_int_equal(measure_save_reference(in_scratch("no_such_dir"), &identity, &saved), -1);
    measure_reference_free(&saved);
}

static double seconds_now(void)
{
    struct timespec now;
    clock_gettime(CLOCK_MONOTONIC, &now);
    return (double)now.tv_sec + 1e-9 * (double)now.tv_nsec;
}

/* The names in the scratch folder, in ls's order, as one text. */
static void list_scratch(char *text, size_t size)
{
    char command[300];
    snprintf(command, sizeof command, "ls -A '%s' | tr '\\n' ' '", scratch_dir);
    FILE *listing = popen(command, "r");
    assert_non_null(listing);
    size_t n = fread(text, 1, size - 1, listing);
    text[n] = '\0';
    pclose(listing);
}

/* Empty the scratch folder. */
static void empty_scratch(void)
{
    char command[300];
    snprintf(command, sizeof command, "rm -f '%s'/*", scratch_dir);
    assert_int_equal(system(command), 0);
}

/* A process that saves a 512 x 512 reference as the reference program does (its signal
 * handlers installed), stopped by `signal_number` `delay` seconds after it starts the
 * save. Returns how it ended. */
static int save_and_signal(const Reference *reference, int signal_number, double delay)
{
    int ready[2];
    assert_int_equal(pipe(ready), 0);
    fflush(NULL);
    pid_t child = fork();
    assert_true(child >= 0);
    if (child == 0) {
        render_install_interrupt();
        ReferenceIdentity identity = identity_of(KEY, wanted().scene_hash, 4096);
        ssize_t unused = write(ready[1], "x", 1);
        (void)unused;
        _exit(measure_save_reference(scratch_dir, &identity, reference) == 0 ? 0 : 3);
    }
    close(ready[1]);
    char byte;
    assert_int_equal(read(ready[0], &byte, 1), 1);
    close(ready[0]);
    struct timespec wait = {0, (long)(delay * 1e9)};
    nanosleep(&wait, NULL);
    kill(child, signal_number);
    int status;
    assert_int_equal(waitpid(child, &status, 0), child);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

/* SIGTERM and SIGHUP at random moments of a save: the folder then holds the three files
 * of an entry that loads, or nothing; never a part, never a temporary file. */
static void test_signal_during_save_leaves_all_or_nothing(void **state)
{
    Reference big = sample_reference(512, 512);
    ReferenceIdentity identity = identity_of(KEY, wanted().scene_hash, 4096);
    double began = seconds_now();
    save(&identity, &big);
    double duration = seconds_now() - began;
    empty_scratch();
    unsigned seed = (unsigned)time(NULL) ^ (unsigned)getpid();
    srand(seed);
    print_message("    a save takes %.1f ms; random moments from seed %u\n", 1e3 * duration,
                  seed);
    int whole = 0, none = 0;
    for (int trial = 0; trial < 16; trial++) {
        int signal_number = trial % 2 ? SIGHUP : SIGTERM;
        double delay = 1.2 * duration * rand() / RAND_MAX;
        int ended = save_and_signal(&big, signal_number, delay);
        char names[1000];
        list_scratch(names, sizeof names);
        Reference loaded;
        char why[320] = "";
        int status =
            measure_load_reference(scratch_dir, &identity, 512, 512, &loaded, why, sizeof why);
        int complete = strcmp(names, STD_ERROR_FILE " " MEAN_FILE " " INFO_FILE " ") == 0;
        if (status == 0)
            measure_reference_free(&loaded);
        if (!(names[0] == '\0' || (complete && status == 0)))
            fail_msg("%s after %.2f ms (status %d) left: %s(%s)", strsignal(signal_number),
                     1e3 * delay, ended, names, why);
        whole += names[0] != '\0';
        none += names[0] == '\0';
        empty_scratch();
    }
    print_message("    16 signals: %d left the whole entry, %d nothing\n", whole, none);
    measure_reference_free(&big);
}

int main(void)
{
#define SCRATCH(test) cmocka_unit_test_setup_teardown(test, make_scratch, remove_scratch)
    const struct CMUnitTest tests[] = {
        SCRATCH(test_round_trip),
        SCRATCH(test_missing_entry),
        SCRATCH(test_every_flipped_bit_is_refused),
        SCRATCH(test_cut_grown_or_missing_files_are_refused),
        SCRATCH(test_other_entries_are_refused),
        SCRATCH(test_impossible_values_are_refused),
        SCRATCH(test_fifo_in_a_files_place_is_refused),
        SCRATCH(test_failed_save_leaves_nothing),
        SCRATCH(test_signal_during_save_leaves_all_or_nothing),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
