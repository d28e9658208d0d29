/* test_metamorphic_reference.c (bench, chapter 8): the metamorphic cases (metamorphic.h)
 * with the reference program, build/reference (bench/reference.c), the program every
 * chapter's errors are measured against: a mistake it shares with a chapter would hide
 * from the chapter's error, so it is tested on its own.
 *
 * It renders each scene as the chapters ask it to (depth 64, Schlick), 24 x 24 pixels,
 * 64 samples in its 8 independent batches of sub-pixels, into a temporary folder; its
 * standard errors come from the batches' spread, 7 degrees of freedom each. The program
 * is found in $CHAPTER_DIR (the Makefile's build directory), or build.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include "image.h"
#include "metamorphic.h"

/* The reference program's batches (bench/reference.c). */
enum {
    BATCHES = 8
};

static int read_images(const char *folder, Rendering *out)
{
    Image image, error;
    char path[600], message[700];
    snprintf(path, sizeof path, "%s/0000000000000001.pfm", folder);
    if (image_read_pfm(path, &image, message, sizeof message) != 0)
        return -1;
    snprintf(path, sizeof path, "%s/0000000000000001-stderr.pfm", folder);
    if (image_read_pfm(path, &error, message, sizeof message) != 0) {
        image_free(&image);
        return -1;
    }
    long n = 3L * image.width * image.height;
    *out = (Rendering){image.width,
                       image.height,
                       BATCHES,
                       1,
                       malloc((size_t)n * sizeof(double)),
                       malloc((size_t)n * sizeof(double))};
    int status = out->value && out->error ? 0 : -1;
    for (long i = 0; status == 0 && i < n; i++) {
        out->value[i] = image.pixels[i];
        out->error[i] = error.pixels[i];
    }
    image_free(&image);
    image_free(&error);
    return status;
}

static int render_reference(const char *text, const Scene *scene, uint64_t seed, Rendering *out)
{
    char folder[] = "/tmp/metamorphic-XXXXXX", path[600], command[2400];
    if (!mkdtemp(folder))
        return -1;
    snprintf(path, sizeof path, "%s/scene", folder);
    FILE *file = fopen(path, "w");
    int written = file && fputs(text, file) >= 0;
    if (file && fclose(file) != 0)
        written = 0;
    const char *programs = getenv("CHAPTER_DIR") ? getenv("CHAPTER_DIR") : "build";
    snprintf(command, sizeof command,
             "'%s/reference' --quiet --scene '%s' --size 24 "
             "--reference-spp 64 --depth 64 --seed %llu --out '%s' --key 1",
             programs, path, (unsigned long long)seed, folder);
    int status = written && system(command) == 0 ? read_images(folder, out) : -1;
    snprintf(command, sizeof command, "rm -rf '%s'", folder);
    if (system(command) != 0)
        status = -1;
    return status;
}

static void test_reference(void **state)
{
    Renderer reference = {"reference", render_reference, 0, 0};
    run_cases(&reference);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_reference),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
