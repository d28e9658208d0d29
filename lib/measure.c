/* measure.c: error metrics and the reference cache (chapter 2). See measure.h. */
#include "measure.h"

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

uint64_t measure_hash_file(uint64_t hash, const char *path)
{
    FILE *file = fopen(path, "rb");
    if (!file)
        return 0;
    unsigned char buffer[65536];
    size_t n;
    while ((n = fread(buffer, 1, sizeof buffer, file)) > 0)
        hash = measure_hash(hash, buffer, n);
    int failed = ferror(file);
    fclose(file);
    return failed ? 0 : hash;
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

int measure_load_reference(const char *directory, uint64_t key, Reference *reference)
{
    char mean[4200], error[4200], info[4200], message[256];
    reference_paths(directory, key, mean, error, info, sizeof mean);
    *reference = (Reference){0};
    FILE *file = fopen(info, "r");
    if (!file)
        return -1;
    int fields = fscanf(file, "spp %lf seconds %lf", &reference->spp, &reference->seconds);
    fclose(file);
    /* Two images of different sizes are a broken entry: their pixels are read in pairs. */
    if (fields != 2 || image_read_pfm(mean, &reference->image, message, sizeof message) != 0 ||
        image_read_pfm(error, &reference->std_error, message, sizeof message) != 0 ||
        reference->std_error.width != reference->image.width ||
        reference->std_error.height != reference->image.height) {
        measure_reference_free(reference);
        return -1;
    }
    reference->noise = measure_rms(&reference->std_error);
    reference->cached = 1;
    return 0;
}

int measure_save_reference(const char *directory, uint64_t key, const Reference *reference)
{
    char mean[4200], error[4200], info[4200];
    reference_paths(directory, key, mean, error, info, sizeof mean);
    if (image_write_pfm(&reference->image, mean) != 0 ||
        image_write_pfm(&reference->std_error, error) != 0)
        return -1;
    AtomicFile file;
    if (atomic_open(&file, info) != 0)
        return -1;
    fprintf(file.file, "spp %.17g seconds %.17g\n", reference->spp, reference->seconds);
    return atomic_close(&file, 0);
}

void measure_reference_free(Reference *reference)
{
    image_free(&reference->image);
    image_free(&reference->std_error);
}
