/* measure.c (chapter 2): error metrics and the reference cache. See measure.h. */
#include "measure.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>

#include "atomic_file.h"

uint64_t measure_hash(uint64_t hash, const void *data, size_t size)
{
    const unsigned char *bytes = data;
    for (size_t i = 0; i < size; i++) {
        hash ^= bytes[i];
        hash *= 0x100000001b3ULL;
    }
    return hash;
}

void measure_error(const Image *image, const Image *reference, double *rmse, double *rel_mse)
{
    long n = 3L * image->width * image->height;
    double squared = 0.0, relative = 0.0;
    for (long i = 0; i < n; i++) {
        double x = image->pixels[i], r = reference->pixels[i];
        double e2 = (x - r) * (x - r);
        squared += e2;
        relative += e2 / (r * r + 0.01);
    }
    *rmse = sqrt(squared / n);
    *rel_mse = relative / n;
}

double measure_rms(const Image *image)
{
    long n = 3L * image->width * image->height;
    double sum = 0.0;
    for (long i = 0; i < n; i++)
        sum += (double)image->pixels[i] * image->pixels[i];
    return sqrt(sum / n);
}

void measure_image_mean(const Image *image, const Image *std_error, double *mean,
                        double *mean_std_error)
{
    long n = 3L * image->width * image->height;
    double sum = 0.0, variance = 0.0;
    for (long i = 0; i < n; i++) {
        sum += image->pixels[i];
        variance += (double)std_error->pixels[i] * std_error->pixels[i];
    }
    *mean = sum / n;
    *mean_std_error = sqrt(variance) / n;
}

void measure_fill_row(TableRow *row, const Image *image, const Reference *reference)
{
    measure_error(image, &reference->image, &row->rmse, &row->rel_mse);
    row->efficiency = 1.0 / (row->rel_mse * row->seconds);
}

static void reference_paths(const char *directory, uint64_t key, char *mean, char *error,
                            char *info, size_t size)
{
    snprintf(mean, size, "%s/%016llx.pfm", directory, (unsigned long long)key);
    snprintf(error, size, "%s/%016llx-stderr.pfm", directory, (unsigned long long)key);
    snprintf(info, size, "%s/%016llx.txt", directory, (unsigned long long)key);
}

int measure_load_reference(const char *directory, uint64_t key, int width, int height,
                           Reference *reference)
{
    char mean[4200], error[4200], info[4200], message[256];
    reference_paths(directory, key, mean, error, info, sizeof mean);
    *reference = (Reference){0};
    FILE *file = fopen(info, "r");
    if (!file)
        return -1;
    int fields = fscanf(file, "spp %lf seconds %lf", &reference->spp, &reference->seconds);
    fclose(file);
    /* An entry whose images are not both width x height is broken (a partial write, or
     * a file put there by hand): it is rendered again, never compared pixel by pixel. */
    if (fields != 2 || !(reference->spp > 0.0) ||
        image_read_pfm(mean, &reference->image, message, sizeof message) != 0 ||
        image_read_pfm(error, &reference->std_error, message, sizeof message) != 0 ||
        reference->image.width != width || reference->image.height != height ||
        reference->std_error.width != width || reference->std_error.height != height) {
        measure_reference_free(reference);
        return -1;
    }
    reference->noise = measure_rms(&reference->std_error);
    reference->cached = 1;
    return 0;
}

/* Remove the files of a failed save, keeping errno. */
static int undo_save(const char *first, const char *second)
{
    int saved = errno;
    remove(first);
    if (second)
        remove(second);
    errno = saved;
    return -1;
}

int measure_save_reference(const char *directory, uint64_t key, const Reference *reference)
{
    char mean[4200], error[4200], info[4200];
    reference_paths(directory, key, mean, error, info, sizeof mean);
    /* The description file last: an entry without it is not there (measure_load_reference). */
    remove(info);
    if (image_write_pfm(&reference->image, mean) != 0)
        return -1;
    if (image_write_pfm(&reference->std_error, error) != 0)
        return undo_save(mean, NULL);
    AtomicFile file;
    if (atomic_open(&file, info) != 0)
        return undo_save(mean, error);
    fprintf(file.file, "spp %.17g seconds %.17g\n", reference->spp, reference->seconds);
    if (atomic_close(&file, 0) != 0)
        return undo_save(mean, error);
    return 0;
}

void measure_reference_free(Reference *reference)
{
    image_free(&reference->image);
    image_free(&reference->std_error);
}
