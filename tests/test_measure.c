/* test_measure.c (chapter 2): error metrics, the hash that names a reference, and the reference cache
 * (measure.h, SPEC §6, chapter 2).
 *
 * The metrics are checked against sums done by hand on images of a few pixels; the hash
 * against the published FNV-1a 64 test vectors; the cache by a round trip through a
 * scratch directory, and by breaking one of an entry's three files at a time: each must
 * make the load fail cleanly, leaving an empty Reference (LeakSanitizer checks nothing
 * half-loaded is kept).
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
#include <unistd.h>

#include "check.h"
#include "measure.h"

/* An image whose values, channel by channel in reading order, are `values`. */
static Image image_of(int width, int height, const float *values)
{
    Image image = image_new(width, height);
    assert_non_null(image.pixels);
    memcpy(image.pixels, values, sizeof(float) * 3 * (size_t)width * (size_t)height);
    return image;
}

/* RMSE and relative MSE are sums over every channel of every pixel, divided by N = 6
 * here. Differences 0.5, 0, 0, 1, 0, -0.5 against references 0.5, 0.5, 0, 1, 0.25, 0.5:
 *     RMSE    = sqrt((0.25 + 1 + 0.25) / 6) = 0.5
 *     rel_MSE = (0.25/0.26 + 1/1.01 + 0.25/0.26) / 6 = 0.48552932...
 * A channel with no error adds nothing, whatever its reference. */
static void test_error_by_hand(void **state)
{
    (void)state;
    const float values[] = {1.0f, 0.5f, 0.0f, 2.0f, 0.25f, 0.0f};
    const float truth[] = {0.5f, 0.5f, 0.0f, 1.0f, 0.25f, 0.5f};
    Image image = image_of(2, 1, values), reference = image_of(2, 1, truth);
    double rmse, rel_mse;
    measure_error(&image, &reference, &rmse, &rel_mse);
    assert_close(rmse, 0.5, 1e-15);
    assert_close(rel_mse, (0.25 / 0.26 + 1.0 / 1.01 + 0.25 / 0.26) / 6.0, 1e-15);
    assert_close(rel_mse, 0.4855293221, 1e-10);
    image_free(&image);
    image_free(&reference);
}

/* The 0.01 in the denominator: against a black reference the relative error of a
 * value x is x^2 / 0.01 (finite, not a division by zero), while against a bright one
 * the same absolute error weighs far less: 0.1 off against 0 counts 1, 0.1 off
 * against 10 counts 0.01 / 100.01. The RMSE treats both alike. */
static void test_relative_error_weights_dark_pixels(void **state)
{
    (void)state;
    const float values[] = {0.5f, 0.5f, 0.5f};
    const float dark[] = {0.0f, 0.0f, 0.0f}, bright[] = {10.0f, 10.0f, 10.0f};
    const float bright_values[] = {10.5f, 10.5f, 10.5f};
    Image image = image_of(1, 1, values), black = image_of(1, 1, dark);
    Image brighter = image_of(1, 1, bright_values), white = image_of(1, 1, bright);
    double rmse_dark, rel_dark, rmse_bright, rel_bright;
    measure_error(&image, &black, &rmse_dark, &rel_dark);
    measure_error(&brighter, &white, &rmse_bright, &rel_bright);
    assert_close(rel_dark, 0.25 / 0.01, 1e-12);
    assert_close(rel_bright, 0.25 / 100.01, 1e-12);
    assert_close(rmse_dark, 0.5, 1e-15);
    assert_close(rmse_bright, 0.5, 1e-15);
    image_free(&image);
    image_free(&black);
    image_free(&brighter);
    image_free(&white);
}

/* An image compared with itself has no error at all, exactly. */
static void test_identical_images_have_no_error(void **state)
{
    (void)state;
    const float values[] = {0.0f, 0.3f, 7.0f, 1e-6f, 123.0f, 0.5f};
    Image image = image_of(2, 1, values);
    double rmse = -1.0, rel_mse = -1.0;
    measure_error(&image, &image, &rmse, &rel_mse);
    assert_true(rmse == 0.0);
    assert_true(rel_mse == 0.0);
    image_free(&image);
}

/* RMS over pixels and channels: 1, 2, 2 gives sqrt(9/3) = sqrt(3); the sign of a value
 * does not matter; a constant image's RMS is that constant's magnitude. */
static void test_rms_by_hand(void **state)
{
    (void)state;
    const float values[] = {1.0f, -2.0f, 2.0f};
    const float constant[] = {-0.25f, -0.25f, -0.25f, -0.25f, -0.25f, -0.25f};
    Image image = image_of(1, 1, values), flat = image_of(2, 1, constant);
    assert_close(measure_rms(&image), sqrt(3.0), 1e-15);
    assert_close(measure_rms(&flat), 0.25, 1e-15);
    image_free(&image);
    image_free(&flat);
}

/* The image mean is over all N = 6 values: (1 + ... + 6) / 6 = 3.5. Its standard error
 * adds the per-value errors in quadrature: sqrt(3^2 + 4^2) / 6 = 5/6. */
static void test_image_mean_by_hand(void **state)
{
    (void)state;
    const float values[] = {1, 2, 3, 4, 5, 6}, errors[] = {3, 4, 0, 0, 0, 0};
    Image image = image_of(2, 1, values), std_error = image_of(2, 1, errors);
    double mean, mean_std_error;
    measure_image_mean(&image, &std_error, &mean, &mean_std_error);
    assert_close(mean, 3.5, 1e-15);
    assert_close(mean_std_error, 5.0 / 6.0, 1e-15);
    image_free(&image);
    image_free(&std_error);
}

/* Averaging N independent values each with standard error s gives s / sqrt(N): twelve
 * values with s = 0.5 give 0.5 / sqrt(12). */
static void test_image_mean_error_shrinks_as_root_n(void **state)
{
    (void)state;
    float values[12], errors[12];
    for (int i = 0; i < 12; i++) {
        values[i] = 2.0f;
        errors[i] = 0.5f;
    }
    Image image = image_of(2, 2, values), std_error = image_of(2, 2, errors);
    double mean, mean_std_error;
    measure_image_mean(&image, &std_error, &mean, &mean_std_error);
    assert_close(mean, 2.0, 1e-15);
    assert_close(mean_std_error, 0.5 / sqrt(12.0), 1e-15);
    image_free(&image);
    image_free(&std_error);
}

/* A table row gets the same RMSE and relative MSE as measure_error, and efficiency
 * 1 / (rel_MSE * seconds) from the row's own time; the cost columns are left alone. */
static void test_fill_row(void **state)
{
    (void)state;
    const float values[] = {1.0f, 0.5f, 0.0f, 2.0f, 0.25f, 0.0f};
    const float truth[] = {0.5f, 0.5f, 0.0f, 1.0f, 0.25f, 0.5f};
    Reference reference = {.image = image_of(2, 1, truth)};
    Image image = image_of(2, 1, values);
    TableRow row = {.panel = "p", .spp = 4, .seconds = 2.0, .threads = 3, .rays = {1, 2, 3}};
    double rmse, rel_mse;
    measure_error(&image, &reference.image, &rmse, &rel_mse);
    measure_fill_row(&row, &image, &reference);
    assert_true(row.rmse == rmse);
    assert_true(row.rel_mse == rel_mse);
    assert_close(row.efficiency, 1.0 / (rel_mse * 2.0), 1e-12);
    assert_close(row.efficiency, 1.0298, 1e-4);
    assert_true(row.seconds == 2.0 && row.spp == 4 && row.threads == 3);
    assert_int_equal(ray_counts_total(row.rays), 6);
    image_free(&image);
    image_free(&reference.image);
}

/* The published FNV-1a 64 test vectors: the empty string leaves the offset basis;
 * "a" and "foobar" have their known hashes. */
static void test_hash_vectors(void **state)
{
    (void)state;
    assert_true(measure_hash(MEASURE_HASH_START, "", 0) == 0xcbf29ce484222325ULL);
    assert_true(measure_hash(MEASURE_HASH_START, "a", 1) == 0xaf63dc4c8601ec8cULL);
    assert_true(measure_hash(MEASURE_HASH_START, "foobar", 6) == 0x85944171f73967e8ULL);
}

/* Hashing continues from where it left off: "foo" then "bar" is "foobar", so a cache
 * key can be built from a scene file and a settings text without concatenating them. */
static void test_hash_chains(void **state)
{
    (void)state;
    uint64_t foo = measure_hash(MEASURE_HASH_START, "foo", 3);
    assert_true(measure_hash(foo, "bar", 3) == measure_hash(MEASURE_HASH_START, "foobar", 6));
    assert_true(measure_hash(foo, "bar", 3) != measure_hash(MEASURE_HASH_START, "barfoo", 6));
}

/* A scratch directory per test; the files a test leaves are removed by name. */
static char scratch_dir[64], scratch_path[4300];

static int make_scratch(void **state)
{
    (void)state;
    strcpy(scratch_dir, "/tmp/test_measure_XXXXXX");
    return mkdtemp(scratch_dir) ? 0 : -1;
}

static const char *in_scratch(const char *name)
{
    snprintf(scratch_path, sizeof scratch_path, "%s/%s", scratch_dir, name);
    return scratch_path;
}

/* The cache entry every test here uses, and its three files' names. */
#define KEY 0x0123456789abcdefULL
static const char *MEAN_FILE = "0123456789abcdef.pfm";
static const char *STD_ERROR_FILE = "0123456789abcdef-stderr.pfm";
static const char *INFO_FILE = "0123456789abcdef.txt";

static int remove_scratch(void **state)
{
    (void)state;
    const char *names[] = {MEAN_FILE, STD_ERROR_FILE, INFO_FILE, "bytes"};
    for (size_t i = 0; i < sizeof names / sizeof names[0]; i++)
        remove(in_scratch(names[i]));
    return rmdir(scratch_dir);
}

/* A reference with distinct values everywhere, as a render would leave it. */
static Reference sample_reference(void)
{
    Reference reference = {.image = image_new(3, 2), .std_error = image_new(3, 2),
                           .spp = 4096, .seconds = 12.345678901234567};
    assert_non_null(reference.image.pixels);
    assert_non_null(reference.std_error.pixels);
    for (int i = 0; i < 18; i++) {
        reference.image.pixels[i] = 0.1f * (float)i + 1e-7f;
        reference.std_error.pixels[i] = 1e-3f / (float)(i + 1);
    }
    return reference;
}

static void assert_empty(const Reference *reference)
{
    assert_null(reference->image.pixels);
    assert_null(reference->std_error.pixels);
}

/* Saved then loaded, a reference comes back bit for bit (image and standard errors),
 * with its spp and seconds, marked as cached, and with its noise computed as the RMS of
 * its standard errors. The files are named by the key in 16 hex digits. */
static void test_reference_round_trip(void **state)
{
    (void)state;
    Reference saved = sample_reference();
    assert_int_equal(measure_save_reference(scratch_dir, KEY, &saved), 0);
    assert_int_equal(access(in_scratch(MEAN_FILE), R_OK), 0);
    assert_int_equal(access(in_scratch(STD_ERROR_FILE), R_OK), 0);
    assert_int_equal(access(in_scratch(INFO_FILE), R_OK), 0);

    Reference loaded;
    assert_int_equal(measure_load_reference(scratch_dir, KEY, 3, 2, &loaded), 0);
    assert_int_equal(loaded.image.width, 3);
    assert_int_equal(loaded.image.height, 2);
    assert_int_equal(loaded.std_error.width, 3);
    assert_int_equal(loaded.std_error.height, 2);
    assert_memory_equal(loaded.image.pixels, saved.image.pixels, 18 * sizeof(float));
    assert_memory_equal(loaded.std_error.pixels, saved.std_error.pixels, 18 * sizeof(float));
    assert_true(loaded.spp == saved.spp);
    assert_true(loaded.seconds == saved.seconds);
    assert_int_equal(loaded.cached, 1);
    assert_true(loaded.noise == measure_rms(&saved.std_error));
    assert_true(loaded.noise > 0.0);
    measure_reference_free(&loaded);
    measure_reference_free(&saved);
}

/* A key that was never saved is not there: -1 and an empty Reference, even if the
 * Reference held garbage before. */
static void test_missing_reference(void **state)
{
    (void)state;
    Reference loaded;
    memset(&loaded, 0x5a, sizeof loaded);
    assert_int_equal(measure_load_reference(scratch_dir, KEY, 3, 2, &loaded), -1);
    assert_empty(&loaded);
    assert_int_equal(loaded.cached, 0);
}

/* Save the sample reference under KEY, then damage one of its files with `damage`. */
static void save_and_damage(void (*damage)(void))
{
    Reference saved = sample_reference();
    assert_int_equal(measure_save_reference(scratch_dir, KEY, &saved), 0);
    measure_reference_free(&saved);
    damage();
}

static void remove_info(void) { assert_int_equal(remove(in_scratch(INFO_FILE)), 0); }

static void truncate_mean(void)
{
    assert_int_equal(truncate(in_scratch(MEAN_FILE), 40), 0);
}

static void truncate_std_error(void)
{
    assert_int_equal(truncate(in_scratch(STD_ERROR_FILE), 40), 0);
}

static void mismatch_std_error(void)
{
    Image small = image_new(2, 2);
    assert_non_null(small.pixels);
    assert_int_equal(image_write_pfm(&small, in_scratch(STD_ERROR_FILE)), 0);
    image_free(&small);
}

static void replace_by_one_pixel(void)
{
    Image tiny = image_new(1, 1);
    assert_non_null(tiny.pixels);
    assert_int_equal(image_write_pfm(&tiny, in_scratch(MEAN_FILE)), 0);
    assert_int_equal(image_write_pfm(&tiny, in_scratch(STD_ERROR_FILE)), 0);
    image_free(&tiny);
}

static void garble_info(void)
{
    FILE *file = fopen(in_scratch(INFO_FILE), "w");
    assert_non_null(file);
    fputs("samples many\n", file);
    assert_int_equal(fclose(file), 0);
}

/* Each way an entry can be broken (no .txt, a .txt that does not parse, a truncated
 * image, a truncated standard-error image read after a good image, a standard-error
 * image of another size, which measure_image_mean would read past, both images
 * replaced by a consistent 1 x 1 pair, not the size asked for) fails the load
 * with -1 and an empty Reference; under LeakSanitizer, an image read before the
 * failure must have been freed. */
static void test_broken_reference(void **state)
{
    (void)state;
    void (*damages[])(void) = {remove_info, garble_info, truncate_mean, truncate_std_error,
                               mismatch_std_error, replace_by_one_pixel};
    for (size_t i = 0; i < sizeof damages / sizeof damages[0]; i++) {
        save_and_damage(damages[i]);
        Reference loaded;
        assert_int_equal(measure_load_reference(scratch_dir, KEY, 3, 2, &loaded), -1);
        assert_empty(&loaded);
        assert_int_equal(loaded.cached, 0);
    }
}

/* Saving into a directory that does not exist fails with -1 rather than crashing. */
static void test_save_into_missing_directory(void **state)
{
    (void)state;
    Reference saved = sample_reference();
    assert_int_equal(measure_save_reference(in_scratch("no_such_dir"), KEY, &saved), -1);
    measure_reference_free(&saved);
}

/* A save that fails part-way (here the standard-error image cannot be written: a
 * directory stands where it should go, as a full disk would stop it) leaves no part of
 * the entry behind: not the mean image, not the .txt. */
static void test_failed_save_leaves_nothing(void **state)
{
    (void)state;
    assert_int_equal(mkdir(in_scratch(STD_ERROR_FILE), 0700), 0);
    Reference saved = sample_reference();
    assert_int_equal(measure_save_reference(scratch_dir, KEY, &saved), -1);
    assert_int_equal(access(in_scratch(MEAN_FILE), F_OK), -1);
    assert_int_equal(access(in_scratch(INFO_FILE), F_OK), -1);
    assert_int_equal(rmdir(in_scratch(STD_ERROR_FILE)), 0);
    measure_reference_free(&saved);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_error_by_hand),
        cmocka_unit_test(test_relative_error_weights_dark_pixels),
        cmocka_unit_test(test_identical_images_have_no_error),
        cmocka_unit_test(test_rms_by_hand),
        cmocka_unit_test(test_image_mean_by_hand),
        cmocka_unit_test(test_image_mean_error_shrinks_as_root_n),
        cmocka_unit_test(test_fill_row),
        cmocka_unit_test(test_hash_vectors),
        cmocka_unit_test(test_hash_chains),
        cmocka_unit_test_setup_teardown(test_reference_round_trip, make_scratch, remove_scratch),
        cmocka_unit_test_setup_teardown(test_missing_reference, make_scratch, remove_scratch),
        cmocka_unit_test_setup_teardown(test_broken_reference, make_scratch, remove_scratch),
        cmocka_unit_test_setup_teardown(test_save_into_missing_directory, make_scratch,
                                        remove_scratch),
        cmocka_unit_test_setup_teardown(test_failed_save_leaves_nothing, make_scratch,
                                        remove_scratch),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
