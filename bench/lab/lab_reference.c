/* lab_reference.c (bench, chapter 8): the references the lab's page can load, and the
 * error of an image against one (build/lab-reference; make lab-references).
 *
 *   lab-reference [--scene FILE] [--size N] [--depth N] [--fresnel schlick|exact]
 *                 [--reference-spp N] [--out DIR] [--error IMAGE.pfm]
 *
 * Gets the reference that a chapter program with the same flags gets (experiment.h: from
 * the cache that `make figures` fills, rendered first by build/reference if it is not
 * there) and writes it for the page as DIR/HASH-WxH-dDEPTH-FRESNEL.js (HASH: the scene
 * file's, lab_scene_hash): a script calling labReference(meta, data), data the image as
 * base64 of little-endian floats, rows from the top, and meta the two numbers that take
 * the reference's own noise out of the page's errors (measure.h's reference_mse and
 * reference_rel_mse). With --error it writes nothing and prints the error of IMAGE
 * against it instead, as the chapter programs measure it: "rmse X rel_mse Y".
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "atomic_file.h"
#include "experiment.h"
#include "image.h"

static void write_base64(FILE *out, const unsigned char *bytes, size_t length)
{
    static const char digits[] =
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    for (size_t i = 0; i < length; i += 3) {
        unsigned long group = (unsigned long)bytes[i] << 16;
        if (i + 1 < length)
            group |= (unsigned long)bytes[i + 1] << 8;
        if (i + 2 < length)
            group |= bytes[i + 2];
        fputc(digits[group >> 18 & 63], out);
        fputc(digits[group >> 12 & 63], out);
        fputc(i + 1 < length ? digits[group >> 6 & 63] : '=', out);
        fputc(i + 2 < length ? digits[group & 63] : '=', out);
    }
}

/* The floats of an image as little-endian bytes, whatever this machine's order. */
static void little_endian(const Image *image, unsigned char *bytes)
{
    size_t count = 3 * (size_t)image->width * image->height;
    for (size_t i = 0; i < count; i++) {
        uint32_t bits;
        memcpy(&bits, &image->pixels[i], 4);
        for (int k = 0; k < 4; k++)
            bytes[4 * i + k] = (unsigned char)(bits >> 8 * k);
    }
}

static void write_reference(const Options *options, const PathSettings *path,
                            const Reference *reference)
{
    ErrorEstimate noise;
    measure_error_estimate(&reference->image, &reference->image, &reference->std_error, &noise);
    char name[128], file[4400];
    snprintf(name, sizeof name, "%016llx-%dx%d-d%d-%s.js",
             (unsigned long long)options->scene_hash, reference->image.width,
             reference->image.height, path->max_depth,
             path->fresnel == FRESNEL_EXACT ? "exact" : "schlick");
    experiment_path(options, name, file, sizeof file);
    size_t length = 12 * (size_t)reference->image.width * reference->image.height;
    unsigned char *bytes = malloc(length);
    AtomicFile out;
    if (!bytes || atomic_open(&out, file) != 0)
        cli_fail(1, "cannot write %s", file);
    little_endian(&reference->image, bytes);
    fprintf(out.file,
            "labReference({\"file\": \"%s\", \"spp\": %.17g, \"mse\": %.17g, "
            "\"rel_mse\": %.17g}, \"",
            name, reference->spp, noise.reference_mse, noise.reference_rel_mse);
    write_base64(out.file, bytes, length);
    fputs("\");\n", out.file);
    free(bytes);
    if (atomic_close(&out, 0) != 0)
        cli_fail(1, "cannot write %s", file);
    printf("wrote %s\n", file);
}

int main(int argc, char **argv)
{
    /* --error IMAGE: taken out before the chapters' flags are parsed. */
    const char *measured = NULL;
    for (int i = 1; i + 1 < argc; i++)
        if (strcmp(argv[i], "--error") == 0) {
            measured = argv[i + 1];
            memmove(&argv[i], &argv[i + 2], (size_t)(argc - i - 1) * sizeof *argv);
            argc -= 2;
            break;
        }
    ProgramInfo info = {
        "The lab's references: a chapter program's reference, written for the page (or, with\n"
        "--error IMAGE.pfm, the error of that image against it).",
        FLAGS_COMMON | FLAG_DEPTH | FLAG_FRESNEL | FLAG_REFERENCE_SPP,
        {.scene = "scenes/room.scene",
         .size = 256,
         .depth = 8,
         .seed = 1,
         .out = "build/lab/references",
         .reference_spp = REFERENCE_SPP},
    };
    Options options;
    Scene scene;
    experiment_start(argc, argv, &info, NEEDS_AREA_LIGHT, &options, &scene);
    PathSettings path = {.max_depth = options.depth, .fresnel = options.fresnel};
    Reference reference;
    experiment_path_reference(&options, &scene, &path, NULL, 0.0, &reference);
    if (measured) {
        Image image;
        char error[4400];
        ErrorEstimate estimate;
        if (image_read_pfm(measured, &image, error, sizeof error) != 0)
            cli_fail(2, "%s", error);
        if (measure_error_estimate(&image, &reference.image, &reference.std_error, &estimate) !=
            0)
            cli_fail(2, "%s: not the reference's size", measured);
        printf("rmse %.17g rel_mse %.17g\n", estimate.rmse, estimate.rel_mse);
        image_free(&image);
    } else {
        write_reference(&options, &path, &reference);
    }
    measure_reference_free(&reference);
    scene_free(&scene);
    return 0;
}
