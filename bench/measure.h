/* measure.h (bench, chapter 2): how far an image is from the truth, and the reference that
 * stands for it (docs/chapter2.md).
 *
 * Introduced in chapter 2. The truth is unknown, so each experiment renders a reference:
 * the same scene and quantity at many more samples, usually with a lower-variance
 * estimator of the same expectation (the path tracer with shadow rays stands in for the
 * one without: both estimate the same integral, path.h). A reference is rendered once
 * and cached in build/references/, named by a 64-bit FNV-1a hash of the scene file's
 * bytes and of a text describing everything that changes its pixels (estimator
 * settings, size, samples, seed); an entry is used only if it proves it is whole and
 * the one asked for (the cache, below).
 *
 * Its own noise is printed beside it: the RMS over pixels and channels of its per-pixel
 * standard errors.
 *
 * Errors, over all pixels and the three channels (N values):
 *     RMSE    = sqrt( sum (x - r)^2 / N )
 *     rel_MSE = sum (x - r)^2 / (r^2 + 0.01) / N
 * (the 0.01 keeps black pixels from dominating the relative error).
 *
 * The reference is noisy too. For one pixel channel let mu be the true value, x the
 * image's estimate and r the reference's, both unbiased and rendered independently. Then
 *     E[(x - r)^2] = E[(x - mu)^2] + E[(r - mu)^2] - 2 E[x - mu] E[r - mu]
 *                  = MSE_true + Var(r),
 * so the raw squared difference overstates the image's error by the reference's
 * variance. Its per-pixel standard error se_r estimates sqrt(Var(r)) without bias: the
 * reference program renders it in independent batches and takes se_r^2 from the spread
 * of their means (render_batches.h; s^2 / n over a pixel's samples, render.h, is
 * unbiased only for independent samples, not for the sub-pixels the batches use), so
 *     MSE = sum ((x - r)^2 - se_r^2) / N
 * estimates the image's own MSE without bias (measure_error_estimate). The relative MSE
 * gets the same correction term by term, ((x - r)^2 - se_r^2) / (r^2 + 0.01): only
 * nearly unbiased, since its weight depends on r itself. The reference's share of the
 * raw MSE, sum se_r^2 / sum (x - r)^2, says how much of a printed error is the judge's
 * own noise: near 0 it is negligible; near 1 the reference cannot tell this image from
 * the truth, and the corrected MSE, a small difference of two noisy numbers, may even be
 * negative. (A deliberately biased image, such as truncated depth, has MSE_true = bias^2
 * + variance; the correction holds as long as the reference is unbiased.)
 *
 * One render's error is one draw of a random variable. Measured over several
 * independent runs (seeds), it is summarised by its mean and spread
 * (measure_summarise_runs). That is meaningless when the estimator's variance is
 * infinite, as for roulette with alpha <= rho^2 (measure_roulette_variance_infinite):
 * then the mean over runs does not settle as runs are added, and such a setting must
 * be marked rather than ranked.
 */
#ifndef MEASURE_H
#define MEASURE_H

#include <stddef.h>
#include <stdint.h>

#include "image.h"
#include "table.h"

typedef struct {
    Image image;
    Image std_error;
    double noise; /* RMS of std_error: the reference's own standard error */
    double spp;
    double seconds;              /* how long it took to render (when it was rendered) */
    int cached;                  /* read from the cache rather than rendered now */
    double mean, mean_std_error; /* the image's mean and its standard error, computed
                                    when it was rendered (measure_image_mean) */
} Reference;

/* FNV-1a over `size` bytes, continuing from `hash` (start with MEASURE_HASH_START). */
#define MEASURE_HASH_START 0xcbf29ce484222325ULL
uint64_t measure_hash(uint64_t hash, const void *data, size_t size);

/* RMSE and relative MSE of image against reference, raw (no correction for the
 * reference's noise). Returns 0, or -1 (and NaN errors) when the sizes differ. */
int measure_error(const Image *image, const Image *reference, double *rmse, double *rel_mse);

/* The error of an image against a noisy reference, as derived above. */
typedef struct {
    double raw_mse;       /* sum (x - r)^2 / N */
    double reference_mse; /* sum se_r^2 / N: what the reference's noise adds to it */
    double mse;           /* raw_mse - reference_mse: the image's own MSE, estimated */
    double rmse;          /* sqrt(mse), or 0 when mse <= 0 */
    double raw_rel_mse;   /* the same three, each term over (r^2 + 0.01) */
    double reference_rel_mse;
    double rel_mse;
    double reference_share; /* reference_mse / raw_mse (0 when both are 0) */
} ErrorEstimate;

/* The estimate of image's error against reference, whose per-pixel, per-channel
 * standard errors are reference_std_error (NULL: a noiseless reference). Returns 0, or
 * -1 (and NaN fields) when the sizes differ. */
int measure_error_estimate(const Image *image, const Image *reference,
                           const Image *reference_std_error, ErrorEstimate *error);

/* Root mean square over all pixels and channels. */
double measure_rms(const Image *image);

/* The row of the highest efficiency among those of finite variance whose efficiency was
 * measured, or -1 if there is none: the most efficient setting that can be ranked. */
int measure_most_efficient(const TableRow *rows, int count);

/* Whether a's mean relative MSE is lower than b's by more than twice the standard error of
 * their difference (each mean's is its runs' spread / sqrt(runs); 0 for one run): a
 * difference the runs' spread cannot explain. */
int measure_clearly_lower(const TableRow *a, const TableRow *b);

/* How many standard errors a lies from b, both measured: (a - b) / sqrt(a_error^2 +
 * b_error^2). */
double measure_z(double a, double a_error, double b, double b_error);

/* The fraction of the pixels of a that differ from b's (same size) in some channel. */
double measure_changed_fraction(const Image *a, const Image *b);

/* The mean brightness (the mean of the three channels) of the pixels within `half` pixels
 * of (col, row) across and down, a window moved inside the image where it pokes out
 * (edge pixels repeated), and its standard error from the pixels' own, per channel in
 * std_error (their channel mean taken as the pixel's: see measure_image_mean). */
void measure_window_mean(const Image *image, const Image *std_error, int col, int row, int half,
                         double *mean, double *mean_std_error);

/* The mean of each channel over the image's pixels. */
void measure_channel_means(const Image *image, double means[3]);

/* The image's mean: over pixels of each pixel's channel mean m_i = (R + G + B) / 3,
 * which is the mean over all pixels and channels; and its standard error. Pixels are
 * independent, so with s_i the standard error of m_i,
 *     se = sqrt(sum_i s_i^2) / P,   P pixels.
 * The channels of one pixel are not independent (one path carries all three, so they
 * rise and fall together), so s_i must come from the samples' own channel means:
 * average_std_error is render.h's grey image of them. Treating the channels as
 * independent, sqrt(sum over channels se_c^2) / 3 instead of s_i, understates se by up
 * to sqrt(3), and z-scores come out that much too large. (Given per-channel errors
 * only, the mean of a pixel's three is read as s_i: an upper bound, the channels taken
 * as fully correlated, since the spread of a sum is at most the sum of the spreads.) */
void measure_image_mean(const Image *image, const Image *average_std_error, double *mean,
                        double *mean_std_error);

/* Fill a table row's error columns from an image and the reference: rmse and rel_mse
 * corrected for the reference's noise (measure_error_estimate), efficiency =
 * 1 / (rel_mse * seconds), NaN when the corrected rel_mse is not positive (the image is
 * as close as this reference can tell). */
void measure_fill_row(TableRow *row, const Image *image, const Reference *reference);

/* Several independent runs of one setting: a list of values (e.g. each run's MSE). */
typedef struct {
    int runs;
    double mean;
    double std_dev;   /* sample standard deviation (n - 1 in the denominator) */
    double std_error; /* of the mean: std_dev / sqrt(runs) */
    double median, min, max;
} RunSummary;

/* Summarise count >= 1 values (std_dev and std_error are 0 for one). Returns 0, or -1
 * when count < 1 or memory runs out (the summary is then all NaN, runs = 0). */
int measure_summarise_runs(const double *values, int count, RunSummary *summary);

/* One table row for count >= 1 independent runs of one setting, each measured with
 * measure_fill_row: rmse, rel_mse, reference_share and seconds are the means over the
 * runs, rmse_spread and rel_mse_spread the standard deviations of the runs' RMSE and
 * relative MSE (NaN for one run),
 * efficiency = 1 / (mean rel_mse x mean seconds) (NaN unless positive); the rest (names,
 * rays, spp, threads) is the first run's, with the non-finite samples of all. Returns 0,
 * or -1 when memory runs out. */
int measure_combine_runs(const TableRow *runs, int count, TableRow *combined);

#if CHAPTER >= 6
/* Whether Russian roulette with constant survival probability alpha (roulette.h) gives
 * the path tracer infinite variance in a scene whose largest diffuse reflectance (over
 * materials and channels) is max_reflectance. At a diffuse bounce of reflectance rho the
 * path survives with probability alpha and its weight is multiplied by rho / alpha
 * (cosine sampling makes f cos / pdf = rho), so the second moment of the weight is
 * multiplied by alpha (rho / alpha)^2 = rho^2 / alpha per bounce. Over paths of every
 * length that is a geometric series, finite only if rho^2 / alpha < 1 (at equality
 * every term is the same). So for alpha > max_reflectance^2 the variance is finite for
 * certain; for alpha <= max_reflectance^2 it is infinite in a closed room of that
 * reflectance (the white furnace), and in any scene where paths can keep bouncing on
 * such surfaces: this returns 1 then, marking a setting whose error cannot be pinned
 * down. alpha >= 1 is no roulette: 0. (A depth limit D keeps the variance finite
 * formally, but it grows as (rho^2 / alpha)^D.) For Oren-Nayar surfaces pass the
 * largest weight rho * oren_nayar_factor a bounce can carry, which exceeds rho at
 * grazing angles. */
int measure_roulette_variance_infinite(double alpha, double max_reflectance);
#endif

/* The reference cache. An entry is three files in the cache folder: KEY.pfm (the
 * image), KEY-stderr.pfm (its per-pixel standard errors) and KEY.txt, its description,
 * written last: what it is (its key, the hash of the scene file's bytes it was rendered
 * from, its settings as text), its numbers (spp, seconds, mean and its standard error),
 * each image's length and FNV-1a checksum, and a last line with the checksum of the
 * description itself. An entry is used only if it proves that it is whole and is the one
 * asked for: a flipped bit anywhere, a file cut short or missing, another scene's or
 * another key's entry copied under this key, values that no render gives (a standard
 * error above its pixel's value: a pixel is the mean of batches that are >= 0, so its
 * standard error is at most that mean) each make it broken, to be rendered again.
 * FNV-1a tells any change of one byte for certain (each step is a bijection of the
 * running hash), and other damage with probability 1 - 2^-64; it guards against
 * accidents, not against someone who means to forge an entry. */
typedef struct {
    uint64_t key;        /* names the entry's files */
    uint64_t scene_hash; /* of the scene file's bytes (scene_file.h) */
    char settings[320];  /* measure_reference_settings */
} ReferenceIdentity;

/* A reference's settings as text: its width, samples per pixel asked for, depth,
 * Fresnel mode ("schlick" or "exact"), seed and the roughness a chapter set
 * ("NAME=SIGMA", or "=0" for none), in the words the reference program is given. */
void measure_reference_settings(ReferenceIdentity *identity, long width, long spp, long depth,
                                const char *fresnel, unsigned long long seed,
                                const char *sigma);

/* Load the cached reference `wanted` from `directory`, both images width x height.
 * Returns 0; -1 when there is no entry (no description); -2 when the entry cannot be
 * used, with why in why[why_size] (one line). A file that is not a regular file (a FIFO,
 * a folder) is not opened for reading, so it cannot stop the program. */
int measure_load_reference(const char *directory, const ReferenceIdentity *wanted, int width,
                           int height, Reference *reference, char *why, size_t why_size);

/* Store one: the two images, then the description that completes the entry (any old
 * description removed first), with the signals that end the program held back
 * meanwhile, so that a signal leaves the whole entry or none of it. Returns 0, or -1 with
 * errno set and nothing of the entry left behind. */
int measure_save_reference(const char *directory, const ReferenceIdentity *identity,
                           const Reference *reference);

void measure_reference_free(Reference *reference);

#endif
