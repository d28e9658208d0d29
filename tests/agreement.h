/* agreement.h (chapter 3): per-pixel agreement of two renders. Do two images estimate
 * the same expectation, pixel by pixel? (Used by the tests of chapters 3-7.)
 * Include after cmocka.h.
 *
 * After Mitsuba 3's render tests (src/render/tests/test_renders.py), which compare each
 * rendered image with a reference by a z-test per pixel and channel, at a significance
 * level corrected for the number of tests. Here both images are renders, each with its
 * own per-pixel standard errors (render.h), so for pixel i and channel c
 *     z = (a - b) / sqrt(se_a^2 + se_b^2),   p = P(|Z| >= |z|) = erfc(|z| / sqrt 2),
 * Z standard normal (both means are averages of many samples). With N such tests, at
 * least one p falls below any level by chance; Sidak's correction tests each at
 *     level' = 1 - (1 - level)^(1 / N),
 * so that N independent tests of agreeing images reject together with probability
 * `level`. (The three channels of a pixel are correlated; for two-sided tests of normal
 * variables Sidak's inequality keeps the chance of any rejection at most `level`
 * whatever the correlation.) The images disagree when the smallest p is below level'.
 * 16 x 16 pixels, 768 tests, level 0.01: each |z| may reach about 4.4.
 *
 * A value whose two standard errors are both 0 is exact in both images: it is not a
 * test, but if the two differ the images disagree (p = 0).
 */
#ifndef AGREEMENT_H
#define AGREEMENT_H

#include <math.h>

#include "image.h"

typedef struct {
    int tests;         /* values compared */
    double level;      /* Sidak-corrected level of each test */
    double smallest_p; /* the smallest p-value, at ... */
    int col, row, channel;
    double z; /* ... where z was this */
} Agreement;

static inline Agreement agreement_test(const Image *a, const Image *se_a, const Image *b,
                                       const Image *se_b, double level)
{
    Agreement result = {0, 0.0, 1.0, -1, -1, -1, 0.0};
    long n = 3L * a->width * a->height;
    for (long i = 0; i < n; i++) {
        double sa = se_a->pixels[i], sb = se_b->pixels[i];
        double difference = (double)a->pixels[i] - b->pixels[i],
               spread = sqrt(sa * sa + sb * sb);
        if (spread == 0.0 && difference == 0.0)
            continue;
        result.tests++;
        double z = spread > 0.0 ? difference / spread : INFINITY;
        double p = erfc(fabs(z) / sqrt(2.0));
        if (p < result.smallest_p || result.channel < 0) {
            result.smallest_p = p;
            result.z = z;
            result.col = (int)(i / 3 % a->width);
            result.row = (int)(i / 3 / a->width);
            result.channel = (int)(i % 3);
        }
    }
    result.level = result.tests > 0 ? -expm1(log1p(-level) / result.tests) : level;
    return result;
}

static inline int agreement_holds(const Agreement *agreement)
{
    return agreement->smallest_p >= agreement->level;
}

static inline void agreement_print(const char *what, const Agreement *agreement)
{
    print_message("    %s: %d values, smallest p = %.2g (z = %+.2f at pixel %d,%d channel %d), "
                  "Sidak level %.2g: %s\n",
                  what, agreement->tests, agreement->smallest_p, agreement->z, agreement->col,
                  agreement->row, agreement->channel, agreement->level,
                  agreement_holds(agreement) ? "agree" : "DISAGREE");
}

#endif
