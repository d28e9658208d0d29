/* measure.c (bench, chapter 2): error metrics (corrected for the reference's noise), summaries
 * of several runs, and the reference cache (the infinite-variance mark: chapter 6). See
 * measure.h. */
#include "measure.h"

#include <errno.h>
#include <fcntl.h>
#include <float.h>
#include <math.h>
#include <pthread.h>
#include <signal.h>
#include <stdio.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

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

int measure_most_efficient(const TableRow *rows, int count)
{
    int best = -1;
    for (int i = 0; i < count; i++)
        if (!rows[i].infinite_variance && !isnan(rows[i].efficiency) &&
            (best < 0 || rows[i].efficiency > rows[best].efficiency))
            best = i;
    return best;
}

int measure_clearly_lower(const TableRow *a, const TableRow *b)
{
    double se_a = a->runs > 1 ? a->rel_mse_spread / sqrt(a->runs) : 0.0;
    double se_b = b->runs > 1 ? b->rel_mse_spread / sqrt(b->runs) : 0.0;
    return b->rel_mse - a->rel_mse > 2.0 * sqrt(se_a * se_a + se_b * se_b);
}

double measure_z(double a, double a_error, double b, double b_error)
{
    return (a - b) / sqrt(a_error * a_error + b_error * b_error);
}

double measure_changed_fraction(const Image *a, const Image *b)
{
    long pixels = (long)a->width * a->height, changed = 0;
    for (long i = 0; i < pixels; i++)
        changed += a->pixels[3 * i] != b->pixels[3 * i] ||
                   a->pixels[3 * i + 1] != b->pixels[3 * i + 1] ||
                   a->pixels[3 * i + 2] != b->pixels[3 * i + 2];
    return (double)changed / pixels;
}

void measure_window_mean(const Image *image, const Image *std_error, int col, int row, int half,
                         double *mean, double *mean_std_error)
{
    double sum = 0.0, variance = 0.0;
    int n = 0;
    for (int r = row - half; r <= row + half; r++)
        for (int c = col - half; c <= col + half; c++) {
            int cc = c < 0 ? 0 : c >= image->width ? image->width - 1 : c;
            int rc = r < 0 ? 0 : r >= image->height ? image->height - 1 : r;
            double se = vec3_average(image_get(std_error, cc, rc));
            sum += vec3_average(image_get(image, cc, rc));
            variance += se * se;
            n++;
        }
    *mean = sum / n;
    *mean_std_error = sqrt(variance) / n;
}

void measure_channel_means(const Image *image, double means[3])
{
    double sum[3] = {0, 0, 0};
    long pixels = (long)image->width * image->height;
    for (long i = 0; i < 3 * pixels; i++)
        sum[i % 3] += image->pixels[i];
    for (int c = 0; c < 3; c++)
        means[c] = sum[c] / pixels;
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
    combined->efficiency =
        combined->rel_mse > 0.0 ? 1.0 / (combined->rel_mse * combined->seconds) : NAN;
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
    summary->median =
        count % 2 ? sorted[count / 2] : 0.5 * (sorted[count / 2 - 1] + sorted[count / 2]);
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

void measure_reference_settings(ReferenceIdentity *identity, long width, long spp, long depth,
                                const char *fresnel, unsigned long long seed, const char *sigma)
{
    snprintf(identity->settings, sizeof identity->settings,
             "--size %ld --reference-spp %ld --depth %ld --fresnel %s --seed %llu --sigma %s",
             width, spp, depth, fresnel, seed, sigma);
}

/* The paths of entry KEY's image, standard errors and description. */
typedef struct {
    char image[4200], std_error[4200], description[4200];
} EntryPaths;

static void entry_paths(const char *directory, uint64_t key, EntryPaths *paths)
{
    unsigned long long k = (unsigned long long)key;
    snprintf(paths->image, sizeof paths->image, "%s/%016llx.pfm", directory, k);
    snprintf(paths->std_error, sizeof paths->std_error, "%s/%016llx-stderr.pfm", directory, k);
    snprintf(paths->description, sizeof paths->description, "%s/%016llx.txt", directory, k);
}

/* The bytes of a regular file, at most `limit` of them, in a buffer to free (with a NUL
 * after them). Opened without waiting, so that a FIFO put in a file's place cannot stop
 * the program. Returns 0, or -1 with errno set (EINVAL: not a regular file; EFBIG:
 * longer than limit). */
static int read_whole_file(const char *path, size_t limit, char **bytes, size_t *length)
{
    int fd = open(path, O_RDONLY | O_NONBLOCK);
    if (fd < 0)
        return -1;
    struct stat status;
    int reason = fstat(fd, &status) != 0             ? errno
                 : !S_ISREG(status.st_mode)          ? EINVAL
                 : (uintmax_t)status.st_size > limit ? EFBIG
                                                     : 0;
    size_t size = reason ? 0 : (size_t)status.st_size;
    char *buffer = reason ? NULL : malloc(size + 1);
    if (!reason && !buffer)
        reason = ENOMEM;
    size_t done = 0;
    while (!reason && done < size) {
        ssize_t n = read(fd, buffer + done, size - done);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            reason = n < 0 ? errno : EIO; /* shorter than it said: cut meanwhile */
        else
            done += (size_t)n;
    }
    close(fd);
    if (reason) {
        free(buffer);
        errno = reason;
        return -1;
    }
    buffer[size] = '\0';
    *bytes = buffer;
    *length = size;
    return 0;
}

/* The largest image file the cache reads: 16384 x 16384 pixels of three floats. */
#define ENTRY_IMAGE_MAX ((size_t)12 << 28 | 4096)

/* A file's length and FNV-1a checksum, if it is at most `limit` bytes long (not read
 * when it is longer); 0, or -1 with errno set. */
static int file_fingerprint(const char *path, size_t limit, size_t *length, uint64_t *checksum)
{
    char *bytes;
    if (read_whole_file(path, limit, &bytes, length) != 0)
        return -1;
    *checksum = measure_hash(MEASURE_HASH_START, bytes, *length);
    free(bytes);
    return 0;
}

/* What a description holds, besides the identity. */
typedef struct {
    ReferenceIdentity identity;
    int width, height;
    double spp, seconds, mean, mean_std_error;
    size_t image_length, std_error_length;
    unsigned long long image_checksum, std_error_checksum;
} Description;

#define DESCRIPTION_HEADER "reference cache entry, version 2\n"
#define CHECKSUM_LINE_LENGTH 26 /* "checksum " + 16 hex digits + "\n" */

/* The description's text without its checksum line; returns its length, or -1 if it
 * does not fit in text[size]. */
static int description_text(const Description *d, char *text, size_t size)
{
    int n = snprintf(text, size,
                     DESCRIPTION_HEADER
                     "key %016llx\nscene %016llx\nsettings %s\nwidth %d height %d\n"
                     "spp %.17g\nseconds %.17g\nmean %.17g\nmean_std_error %.17g\n"
                     "image %zu bytes, fnv-1a %016llx\nstderr %zu bytes, fnv-1a %016llx\n",
                     (unsigned long long)d->identity.key,
                     (unsigned long long)d->identity.scene_hash, d->identity.settings, d->width,
                     d->height, d->spp, d->seconds, d->mean, d->mean_std_error, d->image_length,
                     d->image_checksum, d->std_error_length, d->std_error_checksum);
    return n >= 0 && (size_t)n < size ? n : -1;
}

static void checksum_line(const char *text, size_t length, char line[CHECKSUM_LINE_LENGTH + 1])
{
    snprintf(line, CHECKSUM_LINE_LENGTH + 1, "checksum %016llx\n",
             (unsigned long long)measure_hash(MEASURE_HASH_START, text, length));
}

/* Read a description whose last line checks its bytes. Returns 0, or -1 with why. */
static int read_description(const char *text, size_t length, Description *d, char *why,
                            size_t why_size)
{
    char line[CHECKSUM_LINE_LENGTH + 1];
    if (length < CHECKSUM_LINE_LENGTH ||
        (checksum_line(text, length - CHECKSUM_LINE_LENGTH, line),
         memcmp(line, text + length - CHECKSUM_LINE_LENGTH, CHECKSUM_LINE_LENGTH) != 0)) {
        snprintf(why, why_size,
                 "its description does not match its checksum: damaged, cut "
                 "short, or of an older version");
        return -1;
    }
    unsigned long long key, scene;
    int used = 0;
    *d = (Description){0};
    int fields = sscanf(
        text,
        DESCRIPTION_HEADER "key %16llx scene %16llx settings %319[^\n] width %d height %d "
                           "spp %lf seconds %lf mean %lf mean_std_error %lf "
                           "image %zu bytes, fnv-1a %16llx stderr %zu bytes, fnv-1a %16llx %n",
        &key, &scene, d->identity.settings, &d->width, &d->height, &d->spp, &d->seconds,
        &d->mean, &d->mean_std_error, &d->image_length, &d->image_checksum,
        &d->std_error_length, &d->std_error_checksum, &used);
    if (fields != 13 || (size_t)used != length - CHECKSUM_LINE_LENGTH) {
        snprintf(why, why_size, "its description is not the one this program writes");
        return -1;
    }
    d->identity.key = key;
    d->identity.scene_hash = scene;
    return 0;
}

/* Whether the description is of the reference `wanted`; if not, why. */
static int is_wanted(const Description *d, const ReferenceIdentity *wanted, char *why,
                     size_t why_size)
{
    if (d->identity.key != wanted->key)
        snprintf(why, why_size, "it is the entry of key %016llx, copied under this one",
                 (unsigned long long)d->identity.key);
    else if (d->identity.scene_hash != wanted->scene_hash)
        snprintf(why, why_size,
                 "it was rendered from other scene bytes (hash %016llx, not "
                 "%016llx)",
                 (unsigned long long)d->identity.scene_hash,
                 (unsigned long long)wanted->scene_hash);
    else if (strcmp(d->identity.settings, wanted->settings) != 0)
        snprintf(why, why_size, "it was rendered with other settings (%s)",
                 d->identity.settings);
    else
        return 1;
    return 0;
}

/* Whether the file at `path` is the one the description records; if not, why. A file
 * longer than recorded is not read. */
static int is_recorded_file(const char *path, size_t length, unsigned long long checksum,
                            char *why, size_t why_size)
{
    size_t actual_length;
    uint64_t actual;
    const char *name = strrchr(path, '/') ? strrchr(path, '/') + 1 : path;
    if (file_fingerprint(path, length, &actual_length, &actual) != 0) {
        if (errno == EFBIG)
            snprintf(why, why_size, "%s is longer than the %zu bytes it was written with", name,
                     length);
        else
            snprintf(why, why_size, "%s cannot be read: %s", name,
                     errno == EINVAL ? "not a regular file" : strerror(errno));
    } else if (actual_length != length) {
        snprintf(why, why_size, "%s has %zu bytes, not the %zu it was written with", name,
                 actual_length, length);
    } else if (actual != checksum) {
        snprintf(why, why_size, "%s does not match its checksum: damaged", name);
    } else {
        return 1;
    }
    return 0;
}

/* Whether every value of the image is finite and >= 0: radiance, or its error. */
static int radiance_like(const Image *image)
{
    for (long i = 0; i < 3L * image->width * image->height; i++)
        if (!(isfinite(image->pixels[i]) && image->pixels[i] >= 0.0f))
            return 0;
    return 1;
}

/* Whether no standard error exceeds its pixel's value (with a little room for the two
 * values' rounding to float): a mean of B batches x_b >= 0 has sum (x_b - mean)^2 <=
 * max x_b * sum x_b - B mean^2 <= B mean^2 (B - 1), so its standard error,
 * sqrt(sum (x_b - mean)^2 / (B - 1) / B), is at most the mean. */
static int errors_within_values(const Reference *reference)
{
    const float *x = reference->image.pixels, *se = reference->std_error.pixels;
    for (long i = 0; i < 3L * reference->image.width * reference->image.height; i++)
        if (!((double)se[i] <= (double)x[i] * (1.0 + 1e-6) + FLT_MIN))
            return 0;
    return 1;
}

/* Say why an entry cannot be used; returns -2. */
static int broken(Reference *reference, char *why, size_t why_size, const char *reason)
{
    measure_reference_free(reference);
    if (reason)
        snprintf(why, why_size, "%s", reason);
    return -2;
}

/* The numbers of a description that no render gives, or NULL. */
static const char *implausible_numbers(const Description *d, int width, int height)
{
    if (d->width != width || d->height != height)
        return "it is of another size";
    if (!(d->spp > 0.0 && isfinite(d->spp) && d->seconds >= 0.0 && isfinite(d->seconds) &&
          d->mean >= 0.0 && isfinite(d->mean) && d->mean_std_error >= 0.0 &&
          isfinite(d->mean_std_error)))
        return "its spp, seconds or mean are not finite numbers >= 0";
    return NULL;
}

/* The images' values that no render gives, or NULL. */
static const char *implausible_images(const Reference *reference, const Description *d)
{
    const Image *image = &reference->image, *std_error = &reference->std_error;
    if (image->width != d->width || image->height != d->height ||
        std_error->width != d->width || std_error->height != d->height)
        return "its images are of another size";
    if (!radiance_like(image))
        return "a pixel is negative or not finite";
    if (!radiance_like(std_error))
        return "a standard error is negative or not finite";
    if (!errors_within_values(reference))
        return "a standard error exceeds its pixel's value, which no render gives";
    double mean = image_mean_of(image);
    if (!(fabs(mean - d->mean) <= 1e-9 * fabs(d->mean) + 1e-300))
        return "its stored mean is not its image's";
    return NULL;
}

int measure_load_reference(const char *directory, const ReferenceIdentity *wanted, int width,
                           int height, Reference *reference, char *why, size_t why_size)
{
    EntryPaths paths;
    entry_paths(directory, wanted->key, &paths);
    *reference = (Reference){0};
    char *text, message[512];
    size_t length;
    if (read_whole_file(paths.description, 1 << 16, &text, &length) != 0) {
        if (errno == ENOENT)
            return -1;
        snprintf(message, sizeof message, "its description cannot be read: %s",
                 errno == EINVAL ? "not a regular file" : strerror(errno));
        return broken(reference, why, why_size, message);
    }
    Description d;
    int status = read_description(text, length, &d, why, why_size);
    free(text);
    if (status != 0)
        return broken(reference, why, why_size, NULL);
    if (!is_wanted(&d, wanted, why, why_size))
        return broken(reference, why, why_size, NULL);
    const char *wrong = implausible_numbers(&d, width, height);
    if (wrong)
        return broken(reference, why, why_size, wrong);
    if (!is_recorded_file(paths.image, d.image_length, d.image_checksum, why, why_size) ||
        !is_recorded_file(paths.std_error, d.std_error_length, d.std_error_checksum, why,
                          why_size))
        return broken(reference, why, why_size, NULL);
    if (image_read_pfm(paths.image, &reference->image, message, sizeof message) != 0 ||
        image_read_pfm(paths.std_error, &reference->std_error, message, sizeof message) != 0)
        return broken(reference, why, why_size, message);
    wrong = implausible_images(reference, &d);
    if (wrong)
        return broken(reference, why, why_size, wrong);
    reference->spp = d.spp;
    reference->seconds = d.seconds;
    reference->mean = d.mean;
    reference->mean_std_error = d.mean_std_error;
    reference->noise = measure_rms(&reference->std_error);
    reference->cached = 1;
    return 0;
}

/* Remove the files of a failed save (never a folder in their place), keeping errno;
 * returns -1. */
static int undo_save(const EntryPaths *paths)
{
    int saved = errno;
    unlink(paths->image);
    unlink(paths->std_error);
    errno = saved;
    return -1;
}

/* The entry's three files; the description last: an entry without it is not there,
 * and it vouches for the images' bytes as they are on disk. */
static int save_files(const EntryPaths *paths, const ReferenceIdentity *identity,
                      const Reference *reference)
{
    if (remove(paths->description) != 0 && errno != ENOENT)
        return -1;
    Description d = {*identity,
                     reference->image.width,
                     reference->image.height,
                     reference->spp,
                     reference->seconds,
                     reference->mean,
                     reference->mean_std_error,
                     0,
                     0,
                     0,
                     0};
    uint64_t image_checksum, std_error_checksum;
    if (image_write_pfm(&reference->image, paths->image) != 0 ||
        image_write_pfm(&reference->std_error, paths->std_error) != 0 ||
        file_fingerprint(paths->image, ENTRY_IMAGE_MAX, &d.image_length, &image_checksum) !=
            0 ||
        file_fingerprint(paths->std_error, ENTRY_IMAGE_MAX, &d.std_error_length,
                         &std_error_checksum) != 0)
        return undo_save(paths);
    d.image_checksum = image_checksum;
    d.std_error_checksum = std_error_checksum;
    char text[2048], line[CHECKSUM_LINE_LENGTH + 1];
    int length = description_text(&d, text, sizeof text);
    if (length < 0) {
        errno = ENAMETOOLONG;
        return undo_save(paths);
    }
    checksum_line(text, (size_t)length, line);
    AtomicFile file;
    if (atomic_open(&file, paths->description) != 0)
        return undo_save(paths);
    fputs(text, file.file);
    fputs(line, file.file);
    if (atomic_close(&file, 0) != 0)
        return undo_save(paths);
    return 0;
}

int measure_save_reference(const char *directory, const ReferenceIdentity *identity,
                           const Reference *reference)
{
    EntryPaths paths;
    entry_paths(directory, identity->key, &paths);
    sigset_t ending, previous;
    sigemptyset(&ending);
    sigaddset(&ending, SIGINT);
    sigaddset(&ending, SIGTERM);
    sigaddset(&ending, SIGHUP);
    pthread_sigmask(SIG_BLOCK, &ending, &previous);
    int status = save_files(&paths, identity, reference);
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
