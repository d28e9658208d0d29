/* measure.c (bench, chapter 2): error metrics (corrected for the reference's noise), summaries of
 * several runs, and the reference cache (the infinite-variance mark: chapter 6).
 * See measure.h. */
#include "measure.h"

#include <errno.h>
#include <math.h>
#include <pthread.h>
#include <signal.h>
#include <stdio.h>
#include <stddef.h>
#include <stdlib.h>

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

static int same_size(const Image *a, const Image *b)
{
    return a->width == b->width && a->height == b->height;
}

int measure_error_estimate(const Image *image, const Image *reference,
                           const Image *reference_std_error, ErrorEstimate *error)
{
    if (!same_size(image, reference) ||
        (reference_std_error && !same_size(reference_std_error, reference))) {
        *error = (ErrorEstimate){NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN};
        return -1;
    }
    long n = 3L * image->width * image->height;
    double squared = 0.0, variance = 0.0, relative = 0.0, relative_variance = 0.0;
    for (long i = 0; i < n; i++) {
        double x = image->pixels[i], r = reference->pixels[i];
        double se = reference_std_error ? reference_std_error->pixels[i] : 0.0;
        double weight = 1.0 / (r * r + 0.01);
        squared += (x - r) * (x - r);
        variance += se * se;
        relative += (x - r) * (x - r) * weight;
        relative_variance += se * se * weight;
    }
    error->raw_mse = squared / n;
    error->reference_mse = variance / n;
    error->mse = error->raw_mse - error->reference_mse;
    error->rmse = sqrt(fmax(error->mse, 0.0));
    error->raw_rel_mse = relative / n;
    error->reference_rel_mse = relative_variance / n;
    error->rel_mse = error->raw_rel_mse - error->reference_rel_mse;
    error->reference_share = squared > 0.0 ? variance / squared : 0.0;
    return 0;
}

int measure_error(const Image *image, const Image *reference, double *rmse, double *rel_mse)
{
    ErrorEstimate error;
    int status = measure_error_estimate(image, reference, NULL, &error);
    *rmse = status == 0 ? sqrt(error.raw_mse) : NAN;
    *rel_mse = error.raw_rel_mse;
    return status;
}

double measure_rms(const Image *image)
{
    long n = 3L * image->width * image->height;
    double sum = 0.0;
    for (long i = 0; i < n; i++)
        sum += (double)image->pixels[i] * image->pixels[i];
    return sqrt(sum / n);
}

/* The mean over the pixels of (R + G + B) / 3. */
static double image_mean_of(const Image *image)
{
    long pixels = (long)image->width * image->height;
    double sum = 0.0;
    for (long i = 0; i < pixels; i++) {
        const float *x = image->pixels + 3 * i;
        sum += ((double)x[0] + x[1] + x[2]) / 3.0;
    }
    return sum / pixels;
}

void measure_image_mean(const Image *image, const Image *average_std_error, double *mean,
                        double *mean_std_error)
{
    long pixels = (long)image->width * image->height;
    double variance = 0.0;
    for (long i = 0; i < pixels; i++) {
        const float *e = average_std_error->pixels + 3 * i;
        double s = ((double)e[0] + e[1] + e[2]) / 3.0;
        variance += s * s;
    }
    *mean = image_mean_of(image);
    *mean_std_error = sqrt(variance) / pixels;
}

void measure_fill_row(TableRow *row, const Image *image, const Reference *reference)
{
    ErrorEstimate error;
    const Image *std_error = reference->std_error.pixels ? &reference->std_error : NULL;
    measure_error_estimate(image, &reference->image, std_error, &error);
    row->rmse = error.rmse;
    row->rel_mse = error.rel_mse;
    row->reference_share = error.reference_share;
    row->efficiency = error.rel_mse > 0.0 ? 1.0 / (error.rel_mse * row->seconds) : NAN;
}

/* The mean over the runs of the field at `offset` of each row (a double). */
static double mean_of(const TableRow *runs, int count, size_t offset)
{
    double sum = 0.0;
    for (int i = 0; i < count; i++)
        sum += *(const double *)((const char *)&runs[i] + offset);
    return sum / count;
}

/* The summary of the runs' field at `offset` (a double). */
static int summarise_field(const TableRow *runs, int count, size_t offset, RunSummary *summary)
{
    double *values = malloc(sizeof *values * (size_t)count);
    if (!values)
        return -1;
    for (int i = 0; i < count; i++)
        values[i] = *(const double *)((const char *)&runs[i] + offset);
    int status = measure_summarise_runs(values, count, summary);
    free(values);
    return status;
}

int measure_combine_runs(const TableRow *runs, int count, TableRow *combined)
{
    RunSummary rmse, rel_mse;
    if (summarise_field(runs, count, offsetof(TableRow, rmse), &rmse) != 0 ||
        summarise_field(runs, count, offsetof(TableRow, rel_mse), &rel_mse) != 0)
        return -1;
    *combined = runs[0];
    combined->runs = count;
    combined->rmse = rmse.mean;
    combined->rmse_spread = count > 1 ? rmse.std_dev : NAN;
    combined->rel_mse = rel_mse.mean;
    combined->rel_mse_spread = count > 1 ? rel_mse.std_dev : NAN;
    combined->reference_share = mean_of(runs, count, offsetof(TableRow, reference_share));
    combined->seconds = mean_of(runs, count, offsetof(TableRow, seconds));
    combined->efficiency = combined->rel_mse > 0.0
                               ? 1.0 / (combined->rel_mse * combined->seconds) : NAN;
    combined->nonfinite = 0;
    for (int i = 0; i < count; i++)
        combined->nonfinite += runs[i].nonfinite;
    return 0;
}

static int compare_doubles(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

int measure_summarise_runs(const double *values, int count, RunSummary *summary)
{
    *summary = (RunSummary){0, NAN, NAN, NAN, NAN, NAN, NAN};
    double *sorted = count >= 1 ? malloc(sizeof *sorted * (size_t)count) : NULL;
    if (!sorted)
        return -1;
    /* Welford's running mean and M2, as render.h does per pixel. */
    double mean = 0.0, m2 = 0.0;
    for (int i = 0; i < count; i++) {
        double delta = values[i] - mean;
        mean += delta / (i + 1);
        m2 += delta * (values[i] - mean);
        sorted[i] = values[i];
    }
    qsort(sorted, (size_t)count, sizeof *sorted, compare_doubles);
    summary->runs = count;
    summary->mean = mean;
    summary->std_dev = count > 1 ? sqrt(m2 / (count - 1)) : 0.0;
    summary->std_error = summary->std_dev / sqrt((double)count);
    summary->median = count % 2 ? sorted[count / 2]
                                : 0.5 * (sorted[count / 2 - 1] + sorted[count / 2]);
    summary->min = sorted[0];
    summary->max = sorted[count - 1];
    free(sorted);
    return 0;
}

#if CHAPTER >= 6
int measure_roulette_variance_infinite(double alpha, double max_reflectance)
{
    return alpha < 1.0 && alpha <= max_reflectance * max_reflectance;
}
#endif

static void reference_paths(const char *directory, uint64_t key, char *mean, char *error,
                            char *info, size_t size)
{
    snprintf(mean, size, "%s/%016llx.pfm", directory, (unsigned long long)key);
    snprintf(error, size, "%s/%016llx-stderr.pfm", directory, (unsigned long long)key);
    snprintf(info, size, "%s/%016llx.txt", directory, (unsigned long long)key);
}

/* Whether every value of the image is finite and >= 0: radiance, or its error. */
static int radiance_like(const Image *image)
{
    for (long i = 0; i < 3L * image->width * image->height; i++)
        if (!(isfinite(image->pixels[i]) && image->pixels[i] >= 0.0f))
            return 0;
    return 1;
}

/* Say why an entry is broken; returns -2. */
static int broken(Reference *reference, char *why, size_t why_size, const char *reason)
{
    measure_reference_free(reference);
    snprintf(why, why_size, "%s", reason);
    return -2;
}

int measure_load_reference(const char *directory, uint64_t key, int width, int height,
                           Reference *reference, char *why, size_t why_size)
{
    char mean[4200], error[4200], info[4200], message[256];
    reference_paths(directory, key, mean, error, info, sizeof mean);
    *reference = (Reference){0};
    FILE *file = fopen(info, "r");
    if (!file)
        return -1;
    int fields = fscanf(file, "spp %lf seconds %lf mean %lf mean_std_error %lf",
                        &reference->spp, &reference->seconds, &reference->mean,
                        &reference->mean_std_error);
    fclose(file);
    if (fields != 4 || !(reference->spp > 0.0 && isfinite(reference->spp)) ||
        !(reference->seconds >= 0.0 && isfinite(reference->seconds)) ||
        !isfinite(reference->mean) ||
        !(reference->mean_std_error >= 0.0 && isfinite(reference->mean_std_error)))
        return broken(reference, why, why_size, "its description is not four finite numbers");
    if (image_read_pfm(mean, &reference->image, message, sizeof message) != 0 ||
        image_read_pfm(error, &reference->std_error, message, sizeof message) != 0)
        return broken(reference, why, why_size, message);
    if (reference->image.width != width || reference->image.height != height ||
        reference->std_error.width != width || reference->std_error.height != height)
        return broken(reference, why, why_size, "its images are of another size");
    if (!radiance_like(&reference->image))
        return broken(reference, why, why_size, "a pixel is negative or not finite");
    if (!radiance_like(&reference->std_error))
        return broken(reference, why, why_size, "a standard error is negative or not finite");
    double image_mean = image_mean_of(&reference->image);
    if (!(fabs(image_mean - reference->mean) <= 1e-9 * fabs(reference->mean) + 1e-300))
        return broken(reference, why, why_size, "its stored mean is not its image's");
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

/* The entry's three files; the description file last: an entry without it is not there
 * (measure_load_reference). */
static int save_files(const char *mean, const char *error, const char *info,
                      const Reference *reference)
{
    remove(info);
    if (image_write_pfm(&reference->image, mean) != 0)
        return -1;
    if (image_write_pfm(&reference->std_error, error) != 0)
        return undo_save(mean, NULL);
    AtomicFile file;
    if (atomic_open(&file, info) != 0)
        return undo_save(mean, error);
    fprintf(file.file, "spp %.17g seconds %.17g mean %.17g mean_std_error %.17g\n",
            reference->spp, reference->seconds, reference->mean, reference->mean_std_error);
    if (atomic_close(&file, 0) != 0)
        return undo_save(mean, error);
    return 0;
}

int measure_save_reference(const char *directory, uint64_t key, const Reference *reference)
{
    char mean[4200], error[4200], info[4200];
    reference_paths(directory, key, mean, error, info, sizeof mean);
    sigset_t ending, previous;
    sigemptyset(&ending);
    sigaddset(&ending, SIGINT);
    sigaddset(&ending, SIGTERM);
    sigaddset(&ending, SIGHUP);
    pthread_sigmask(SIG_BLOCK, &ending, &previous);
    int status = save_files(mean, error, info, reference);
    int saved = errno;
    pthread_sigmask(SIG_SETMASK, &previous, NULL);
    errno = saved;
    return status;
}

void measure_reference_free(Reference *reference)
{
    image_free(&reference->image);
    image_free(&reference->std_error);
}
