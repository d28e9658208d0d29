/* chapter4.c (bench, chapter 4): chapter 4's exercises and their graders (grading.h).
 *
 * The exact Fresnel reflectances against eqs. 4-5 written with the angles themselves,
 *     R_s = sin^2(theta_i - theta_t) / sin^2(theta_i + theta_t),
 *     R_p = tan^2(theta_i - theta_t) / tan^2(theta_i + theta_t),
 * ((n_i - n_t) / (n_i + n_t))^2 both at normal incidence, 1 beyond the critical angle,
 * at four pairs of indices and every degree; the unpolarised one against their mean
 * (eq. 3). A wrong answer is named: s and p swapped, the indices swapped, no total
 * internal reflection, a sum where the mean belongs.
 */
#include <math.h>
#include <stdio.h>

#include "fresnel.h"
#include "grading.h"

static const double pairs[][2] = {{1.0, 1.5}, {1.5, 1.0}, {1.0, 1.33}, {1.6, 1.2}};
#define PAIRS (int)(sizeof pairs / sizeof pairs[0])

/* R_s and R_p by the angles; 1 and 1 beyond the critical angle. */
static void right_fresnel(double degrees, double n_i, double n_t, double *s, double *p)
{
    double ti = degrees * PI / 180.0, sin_t = n_i / n_t * sin(ti);
    if (sin_t >= 1.0) {
        *s = *p = 1.0;
        return;
    }
    if (degrees == 0.0) {
        *s = *p = pow((n_i - n_t) / (n_i + n_t), 2.0);
        return;
    }
    double tt = asin(sin_t);
    *s = pow(sin(ti - tt) / sin(ti + tt), 2.0);
    *p = pow(tan(ti - tt) / tan(ti + tt), 2.0);
}

static void grade_polarised(Grading *g)
{
    int checked = 0;
    for (int k = 0; k < PAIRS && !g->failed; k++)
        for (int a = 0; a < 90 && !g->failed; a++, checked++) {
            double n_i = pairs[k][0], n_t = pairs[k][1], cos_i = cos(a * PI / 180.0);
            double s, p, swapped_s, swapped_p;
            right_fresnel(a, n_i, n_t, &s, &p);
            double got_s = ASK(g, fresnel_s(cos_i, n_i, n_t));
            double got_p = ASK(g, fresnel_p(cos_i, n_i, n_t));
            if (grading_not_finite(g, got_s, "R_s") || grading_not_finite(g, got_p, "R_p"))
                break;
            if (fabs(got_s - s) <= 1e-9 && fabs(got_p - p) <= 1e-9)
                continue;
            double brewster = atan(n_t / n_i) * 180.0 / PI;
            double critical = n_i > n_t ? asin(n_t / n_i) * 180.0 / PI : 90.0;
            double sin_t = n_i / n_t * sin(a * PI / 180.0);
            /* the same incidence seen from the other side: the indices swapped */
            double cos_other = sin_t < 1.0 ? sqrt(1.0 - sin_t * sin_t) : 0.0;
            right_fresnel(acos(cos_other) * 180.0 / PI, n_t, n_i, &swapped_s, &swapped_p);
            double got_other_s = ASK(g, fresnel_s(cos_other, n_t, n_i));
            if (s == 1.0 && (got_s != 1.0 || got_p != 1.0))
                grading_fail(g,
                             "R_s = %.4f, R_p = %.4f at %d degrees from index %.2f into %.2f, "
                             "beyond the critical angle %.1f degrees: with no transmitted ray "
                             "both must be 1 (total internal reflection)",
                             got_s, got_p, a, n_i, n_t, critical);
            else if (fabs(got_s - p) <= 1e-9 && fabs(got_p - s) <= 1e-9)
                grading_fail(
                    g,
                    "R_s and R_p are swapped: at %d degrees from index %.2f into "
                    "%.2f, R_s = %.4f and R_p = %.4f should be %.4f and %.4f (R_p, not "
                    "R_s, vanishes at Brewster's angle, %.1f degrees; the report's "
                    "labels are swapped)",
                    a, n_i, n_t, got_s, got_p, s, p, brewster);
            else if (sin_t < 1.0 && a > 0 && fabs(got_s - s) > 1e-9 &&
                     fabs(got_s - swapped_s) > 1e-9 && fabs(got_s - got_other_s) <= 1e-9 &&
                     fabs(cos_other - cos_i) > 1e-6)
                grading_fail(g,
                             "R_s = %.4f at %d degrees from index %.2f into %.2f, where eqs. "
                             "4-5 give %.4f: are n_i and n_t, or cos_i and cos_t, swapped?",
                             got_s, a, n_i, n_t, s);
            else {
                int d = grading_decimals(got_s, s) > grading_decimals(got_p, p)
                            ? grading_decimals(got_s, s)
                            : grading_decimals(got_p, p);
                char off[120] = "";
                if (d > 4)
                    snprintf(off, sizeof off,
                             " (off by %.2g and %.2g, where rounding stays "
                             "within 1e-9)",
                             got_s - s, got_p - p);
                grading_fail(g,
                             "at %d degrees from index %.2f into %.2f, R_s = %.*f and R_p = "
                             "%.*f, where eqs. 4-5 give %.*f and %.*f%s%s",
                             a, n_i, n_t, d, got_s, d, got_p, d, s, d, p, off,
                             fabs(got_s - swapped_s) <= 1e-9 && fabs(got_p - swapped_p) <= 1e-9
                                 ? ": those of the same angles with n_i and n_t swapped"
                                 : "");
            }
        }
    grading_note(g,
                 "%d incidences (every degree from 0 to 89 at n_i / n_t = 1 / 1.5, 1.5 / 1, 1 "
                 "/ 1.33, 1.6 / 1.2) against the sin and tan forms",
                 checked);
}

static void grade_unpolarised(Grading *g)
{
    int checked = 0;
    double largest = 0.0;
    for (int k = 0; k < PAIRS && !g->failed; k++)
        for (int a = 0; a < 90 && !g->failed; a++, checked++) {
            double n_i = pairs[k][0], n_t = pairs[k][1], cos_i = cos(a * PI / 180.0), s, p;
            right_fresnel(a, n_i, n_t, &s, &p);
            double got = ASK(g, fresnel_reflectance(cos_i, n_i, n_t)), want = 0.5 * (s + p);
            if (grading_not_finite(g, got, "R"))
                break;
            largest = fmax(largest, got);
            if (fabs(got - want) <= 1e-9)
                continue;
            if (got > 1.0)
                grading_fail(g,
                             "R = %.4f > 1 at %d degrees from index %.2f into %.2f: more light "
                             "reflected than arrives; unpolarised light is half s, half p: R = "
                             "(R_s + R_p) / 2 = %.4f (eq. 3)",
                             got, a, n_i, n_t, want);
            else if (fabs(got - (s + p)) <= 1e-9)
                grading_fail(
                    g,
                    "R = %.4f at %d degrees from index %.2f into %.2f is R_s + R_p: "
                    "unpolarised light is half s, half p, R = (R_s + R_p) / 2 = %.4f "
                    "(eq. 3); the sum reflects twice the light that arrives beyond the "
                    "critical angle",
                    got, a, n_i, n_t, want);
            else if (fabs(got - s) <= 1e-9 || fabs(got - p) <= 1e-9)
                grading_fail(
                    g,
                    "R = %.4f at %d degrees from index %.2f into %.2f is R_%s alone; "
                    "unpolarised light is half s, half p: (R_s + R_p) / 2 = %.4f (eq. 3)",
                    got, a, n_i, n_t, fabs(got - s) <= 1e-9 ? "s" : "p", want);
            else
                grading_fail(g,
                             "R = %.*f at %d degrees from index %.2f into %.2f, where (R_s + "
                             "R_p) / 2 = %.*f (eq. 3)",
                             grading_decimals(got, want), got, a, n_i, n_t,
                             grading_decimals(got, want), want);
        }
    grading_note(g, "%d incidences against (R_s + R_p) / 2; the largest R returned %.4f",
                 checked, largest);
}

const Exercise exercises[] = {
    {"4.1", "fresnel_polarised",
     "Return R_s and R_p at incidence cosine cos_i from index n_i into n_t: 0 and 0 when n_i "
     "= n_t; with cos_t = snell_cos_transmitted(cos_i, n_i, n_t), 1 and 1 when it is -1 "
     "(total internal reflection); else R_s = ((n_i cos_i - n_t cos_t) / (n_i cos_i + n_t "
     "cos_t))^2 and R_p = ((n_i cos_t - n_t cos_i) / (n_i cos_t + n_t cos_i))^2 (eqs. 4-5, "
     "whose labels the report swaps). See docs/chapter4.md, section 2.",
     "Polarised r = {0.0, 0.0};\nreturn r;", grade_polarised, NULL, ""},
    {"4.2", "fresnel_reflectance",
     "Return the reflectance of unpolarised light, half s and half p: R = (R_s + R_p) / 2 "
     "(eq. 3), from fresnel_polarised. See docs/chapter4.md, section 2.",
     "return 0.0;", grade_unpolarised, NULL, "4.1"},
};
const int exercise_count = sizeof exercises / sizeof exercises[0];
