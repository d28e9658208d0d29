/* chapter4.c (bench, chapter 4): chapter 4's exercises and their graders (grading.h).
 *
 * The exact Fresnel reflectances against eqs. 4-5 written with the angles themselves,
 *     R_s = sin^2(theta_i - theta_t) / sin^2(theta_i + theta_t),
 *     R_p = tan^2(theta_i - theta_t) / tan^2(theta_i + theta_t),
 * ((n_i - n_t) / (n_i + n_t))^2 both at normal incidence, 1 beyond the critical angle,
 * at four pairs of indices and every degree; the unpolarised one against their mean
 * (eq. 3). A wrong answer is named from a catalogue (grading.h) matched at every
 * incidence it gets wrong: s and p swapped, the indices swapped, an amplitude not
 * squared, no total internal reflection, a sum or 1 / 2 in whole numbers where the mean
 * belongs; else the verdict says where it goes wrong and by what ratio.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "fresnel.h"
#include "grading.h"
#include "schlick.h"

static const double pairs[][2] = {{1.0, 1.5}, {1.5, 1.0}, {1.0, 1.33}, {1.6, 1.2}};
#define PAIRS (int)(sizeof pairs / sizeof pairs[0])
#define ANGLES 90
#define POINTS (PAIRS * ANGLES)

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

/* One incidence: cos_i, n_i, n_t, its degrees, the right R_s and R_p (the catalogue's
 * inputs), and what came back. */
enum {
    COS_I,
    N_I,
    N_T,
    DEGREES,
    RIGHT_S,
    RIGHT_P,
    ARITY
};

/* cos(theta_t) by Snell's law, -1 beyond the critical angle. */
static double cos_t_of(const double *in)
{
    double sin2 = pow(in[N_I] / in[N_T], 2.0) * (1.0 - in[COS_I] * in[COS_I]);
    return sin2 >= 1.0 ? -1.0 : sqrt(1.0 - sin2);
}

static double swapped_s(const double *in)
{
    double s, p;
    right_fresnel(acos(fmin(1.0, in[COS_I])) * 180.0 / PI, in[N_T], in[N_I], &s, &p);
    return s;
}

static double swapped_p(const double *in)
{
    double s, p;
    right_fresnel(acos(fmin(1.0, in[COS_I])) * 180.0 / PI, in[N_T], in[N_I], &s, &p);
    return p;
}

static double amplitude_s(const double *in)
{
    double c = cos_t_of(in);
    return (in[N_I] * in[COS_I] - in[N_T] * c) / (in[N_I] * in[COS_I] + in[N_T] * c);
}

static double amplitude_p(const double *in)
{
    double c = cos_t_of(in);
    return (in[N_I] * c - in[N_T] * in[COS_I]) / (in[N_I] * c + in[N_T] * in[COS_I]);
}

static double inverse_s(const double *in) { return 1.0 / in[RIGHT_S]; }
static double inverse_p(const double *in) { return 1.0 / in[RIGHT_P]; }
static double right_p(const double *in) { return in[RIGHT_P]; }
static double right_s(const double *in) { return in[RIGHT_S]; }

/* cos(theta_t) taken as cos^2(theta_t) = 1 - sin^2(theta_t): the square root left out. */
static double unrooted_s(const double *in)
{
    double c = cos_t_of(in) < 0.0 ? -1.0 : cos_t_of(in) * cos_t_of(in);
    return pow((in[N_I] * in[COS_I] - in[N_T] * c) / (in[N_I] * in[COS_I] + in[N_T] * c), 2.0);
}

static double unrooted_p(const double *in)
{
    double c = cos_t_of(in) < 0.0 ? -1.0 : cos_t_of(in) * cos_t_of(in);
    return pow((in[N_I] * c - in[N_T] * in[COS_I]) / (in[N_I] * c + in[N_T] * in[COS_I]), 2.0);
}

static double zero(const double *in)
{
    (void)in;
    return 0.0;
}

static const WrongAnswer wrong_s[] = {
    {"0 at every incidence it gets wrong, as if R_s were never set",
     "R_s = ((n_i cos_i - n_t cos_t) / (n_i cos_i + n_t cos_t))^2 (eq. 4): is R_s assigned, "
     "and not R_p twice?",
     zero},
    {"R_p's formula, ((n_i cos_t - n_t cos_i) / (n_i cos_t + n_t cos_i))^2 (cos_i and cos_t "
     "trade places)",
     "R_s pairs n_i with cos_i and n_t with cos_t: ((n_i cos_i - n_t cos_t) / (n_i cos_i + "
     "n_t cos_t))^2 (eq. 4; the report swaps the labels)",
     right_p},
    {"R_s with n_i and n_t swapped (the light going the other way)",
     "the first index is the incident medium's: fresnel_polarised(cos_i, n_i, n_t)", swapped_s},
    {"the amplitude r_s = (n_i cos_i - n_t cos_t) / (n_i cos_i + n_t cos_t), not squared",
     "the reflectance is the amplitude squared, R_s = r_s^2 (eq. 4); r_s is negative "
     "entering a denser medium",
     amplitude_s},
    {"1 / R_s: the numerator and the denominator swapped",
     "R_s = ((n_i cos_i - n_t cos_t) / (n_i cos_i + n_t cos_t))^2 <= 1 (eq. 4)", inverse_s},
    {"R_s with cos_t^2 = 1 - sin^2(theta_t) where cos_t belongs (the square root left out)",
     "cos_t = sqrt(1 - (n_i / n_t)^2 (1 - cos_i^2)), snell_cos_transmitted", unrooted_s},
};

static const WrongAnswer wrong_p[] = {
    {"0 at every incidence it gets wrong, as if R_p were never set",
     "R_p = ((n_i cos_t - n_t cos_i) / (n_i cos_t + n_t cos_i))^2 (eq. 5): is R_p assigned, "
     "and not R_s twice?",
     zero},
    {"R_s's formula, ((n_i cos_i - n_t cos_t) / (n_i cos_i + n_t cos_t))^2 (cos_i and cos_t "
     "trade places)",
     "R_p pairs n_i with cos_t and n_t with cos_i: ((n_i cos_t - n_t cos_i) / (n_i cos_t + "
     "n_t cos_i))^2 (eq. 5), the one that vanishes at Brewster's angle",
     right_s},
    {"R_p with n_i and n_t swapped (the light going the other way)",
     "the first index is the incident medium's: fresnel_polarised(cos_i, n_i, n_t)", swapped_p},
    {"the amplitude r_p = (n_i cos_t - n_t cos_i) / (n_i cos_t + n_t cos_i), not squared",
     "the reflectance is the amplitude squared, R_p = r_p^2 (eq. 5)", amplitude_p},
    {"1 / R_p: the numerator and the denominator swapped",
     "R_p = ((n_i cos_t - n_t cos_i) / (n_i cos_t + n_t cos_i))^2 <= 1 (eq. 5)", inverse_p},
    {"R_p with cos_t^2 = 1 - sin^2(theta_t) where cos_t belongs (the square root left out)",
     "cos_t = sqrt(1 - (n_i / n_t)^2 (1 - cos_i^2)), snell_cos_transmitted", unrooted_p},
};

/* The wrong incidences' inputs and values, packed for the catalogue. */
typedef struct {
    double inputs[POINTS * ARITY], got[POINTS];
    int count;
} Wrong;

/* Where `quantity` (got[], right[] over every incidence) is wrong, in words: how many
 * incidences, from which angle to which at which indices, the ratio at the worst; nothing
 * where it is right everywhere. */
static void fail_described(Grading *g, const char *quantity, const double *in,
                           const double *got, int points, const char *equation)
{
    int wrong = 0, first = -1, last = -1, worst = -1;
    double largest = 0.0, low = INFINITY, high = -INFINITY;
    int which = strcmp(quantity, "R_s") == 0   ? RIGHT_S
                : strcmp(quantity, "R_p") == 0 ? RIGHT_P
                                               : -1;
    for (int k = 0; k < points; k++) {
        const double *x = in + (long)k * ARITY;
        double right = which >= 0 ? x[which] : 0.5 * (x[RIGHT_S] + x[RIGHT_P]);
        double off = fabs(got[k] - right);
        if (off <= 1e-9)
            continue;
        wrong++;
        if (first < 0)
            first = k;
        if (k / ANGLES == first / ANGLES)
            last = k;
        if (off > largest)
            largest = off, worst = k;
        if (right > 1e-6)
            low = fmin(low, got[k] / right), high = fmax(high, got[k] / right);
    }
    if (wrong == 0)
        return;
    if (wrong == points && high - low <= 1e-9 * fabs(high)) {
        grading_fail(g,
                     "%s is %.6g times the right value at every incidence: a constant factor "
                     "(look at the factors and constants of %s)",
                     quantity, high, equation);
        return;
    }
    const double *w = in + (long)worst * ARITY, *f = in + (long)first * ARITY;
    double worst_right = which >= 0 ? w[which] : 0.5 * (w[RIGHT_S] + w[RIGHT_P]);
    if (largest <= 4e-6 * fmax(fabs(worst_right), 1e-3)) {
        int digits = grading_decimals(got[worst], worst_right);
        grading_fail(g,
                     "%s agrees with %s to about 7 digits only: %s = %.*f at %.0f degrees from "
                     "index %.2f into %.2f, where %s gives %.*f (wrong at %d of %d incidences, "
                     "where rounding in doubles stays within 1e-9): a float on the way; keep "
                     "the arithmetic in doubles",
                     quantity, equation, quantity, digits, got[worst], w[DEGREES], w[N_I],
                     w[N_T], equation, digits, worst_right, wrong, points);
        return;
    }
    double right = which >= 0 ? w[which] : 0.5 * (w[RIGHT_S] + w[RIGHT_P]);
    char critical[80] = "";
    if (f[N_I] > f[N_T])
        snprintf(critical, sizeof critical, "; its critical angle is %.1f degrees",
                 asin(f[N_T] / f[N_I]) * 180.0 / PI);
    int decimals = grading_decimals(got[worst], right);
    grading_fail(g,
                 "%s is wrong at %d of %d incidences, from index %.2f into %.2f between %.0f "
                 "and %.0f degrees%s; worst at %.0f degrees from %.2f into %.2f: %.*f where "
                 "%s gives %.*f (a ratio of %.4g, a difference of %+.3g)",
                 quantity, wrong, points, f[N_I], f[N_T], f[DEGREES],
                 in[(long)last * ARITY + DEGREES], critical, w[DEGREES], w[N_I], w[N_T],
                 decimals, got[worst], equation, decimals, right,
                 right != 0.0 ? got[worst] / right : NAN, got[worst] - right);
}

/* The catalogue's entry matching every wrong incidence, or NULL. */
static const WrongAnswer *catalogue(const WrongAnswer *list, int count, const double *in,
                                    const double *got, int which, Wrong *wrong)
{
    wrong->count = 0;
    for (int k = 0; k < POINTS; k++) {
        const double *x = in + (long)k * ARITY;
        double right = which >= 0 ? x[which] : 0.5 * (x[RIGHT_S] + x[RIGHT_P]);
        if (fabs(got[k] - right) <= 1e-9)
            continue;
        for (int i = 0; i < ARITY; i++)
            wrong->inputs[(long)wrong->count * ARITY + i] = x[i];
        wrong->got[wrong->count++] = got[k];
    }
    return grading_known_wrong(list, count, wrong->inputs, ARITY, wrong->got, wrong->count);
}

/* Every incidence's inputs and the right R_s and R_p. */
static void incidences(double *in)
{
    for (int k = 0; k < PAIRS; k++)
        for (int a = 0; a < ANGLES; a++) {
            double *x = in + (long)(k * ANGLES + a) * ARITY;
            x[COS_I] = cos(a * PI / 180.0);
            x[N_I] = pairs[k][0];
            x[N_T] = pairs[k][1];
            x[DEGREES] = a;
            right_fresnel(a, x[N_I], x[N_T], &x[RIGHT_S], &x[RIGHT_P]);
        }
}

static void grade_polarised(Grading *g)
{
    static double in[POINTS * ARITY], got_s[POINTS], got_p[POINTS];
    static Wrong wrong;
    incidences(in);
    for (int k = 0; k < POINTS; k++) {
        const double *x = in + (long)k * ARITY;
        got_s[k] = ASK(g, fresnel_s(x[COS_I], x[N_I], x[N_T]));
        got_p[k] = ASK(g, fresnel_p(x[COS_I], x[N_I], x[N_T]));
        if (grading_not_finite(g, got_s[k], "R_s") || grading_not_finite(g, got_p[k], "R_p"))
            return;
    }
    int s_wrong = 0, p_wrong = 0, swapped = 0, tir = -1;
    for (int k = 0; k < POINTS; k++) {
        const double *x = in + (long)k * ARITY;
        s_wrong += fabs(got_s[k] - x[RIGHT_S]) > 1e-9;
        p_wrong += fabs(got_p[k] - x[RIGHT_P]) > 1e-9;
        swapped += fabs(got_s[k] - x[RIGHT_P]) <= 1e-9 && fabs(got_p[k] - x[RIGHT_S]) <= 1e-9;
        if (tir < 0 && x[RIGHT_S] == 1.0 && (got_s[k] != 1.0 || got_p[k] != 1.0))
            tir = k;
    }
    grading_note(g,
                 "%d incidences (every degree from 0 to 89 at n_i / n_t = 1 / 1.5, 1.5 / 1, 1 "
                 "/ 1.33, 1.6 / 1.2) against the sin and tan forms: R_s wrong at %d, R_p at %d",
                 POINTS, s_wrong, p_wrong);
    if (s_wrong == 0 && p_wrong == 0)
        return;
    if (swapped == POINTS)
        grading_fail(g,
                     "R_s and R_p are swapped at every incidence: R_p, not R_s, vanishes at "
                     "Brewster's angle (%.1f degrees from index 1 into 1.5; the report's "
                     "labels are swapped): R_s = ((n_i cos_i - n_t cos_t) / (n_i cos_i + n_t "
                     "cos_t))^2",
                     atan(1.5) * 180.0 / PI);
    else if (tir >= 0) {
        const double *x = in + (long)tir * ARITY;
        grading_fail(g,
                     "R_s = %.4f, R_p = %.4f at %.0f degrees from index %.2f into %.2f, "
                     "beyond the critical angle %.1f degrees: with no transmitted ray both "
                     "must be 1 (total internal reflection: snell_cos_transmitted returns -1)",
                     got_s[tir], got_p[tir], x[DEGREES], x[N_I], x[N_T],
                     asin(x[N_T] / x[N_I]) * 180.0 / PI);
    }
    const WrongAnswer *known;
    if (s_wrong && (known = catalogue(wrong_s, (int)(sizeof wrong_s / sizeof *wrong_s), in,
                                      got_s, RIGHT_S, &wrong)))
        grading_fail_known(g, "R_s", known, wrong.count);
    if (p_wrong && (known = catalogue(wrong_p, (int)(sizeof wrong_p / sizeof *wrong_p), in,
                                      got_p, RIGHT_P, &wrong)))
        grading_fail_known(g, "R_p", known, wrong.count);
    if (s_wrong)
        fail_described(g, "R_s", in, got_s, POINTS, "eq. 4");
    fail_described(g, "R_p", in, got_p, POINTS, "eq. 5");
}

static double sum(const double *in) { return in[RIGHT_S] + in[RIGHT_P]; }
static double half_s_plus_p(const double *in) { return 0.5 * in[RIGHT_S] + in[RIGHT_P]; }
static double swapped_mean(const double *in) { return 0.5 * (swapped_s(in) + swapped_p(in)); }
static double schlick(const double *in)
{
    return schlick_reflectance(in[COS_I], in[N_I], in[N_T]);
}

static const WrongAnswer wrong_unpolarised[] = {
    {"(1/2) (R_s + R_p) computed as 1 / 2 * (R_s + R_p) in integer arithmetic, which is 0 "
     "in C",
     "1 / 2 divides two whole numbers, 0 with the remainder dropped; write 0.5 * (R_s + R_p) "
     "or (R_s + R_p) / 2 (eq. 3)",
     zero},
    {"R_s + R_p, the sum",
     "unpolarised light is half s, half p: R = (R_s + R_p) / 2 (eq. 3); the sum reflects "
     "twice the light that arrives beyond the critical angle",
     sum},
    {"R_s alone", "unpolarised light is half s, half p: R = (R_s + R_p) / 2 (eq. 3)", right_s},
    {"R_p alone", "unpolarised light is half s, half p: R = (R_s + R_p) / 2 (eq. 3)", right_p},
    {"0.5 * R_s + R_p: the half applied to R_s alone (the parentheses left out)",
     "R = 0.5 * (R_s + R_p) (eq. 3)", half_s_plus_p},
    {"(R_s + R_p) / 2 from fresnel_polarised(cos_i, n_t, n_i): the indices swapped in the call",
     "the incident medium's index comes first: fresnel_polarised(cos_i, n_i, n_t)",
     swapped_mean},
    {"Schlick's approximation (schlick_reflectance)",
     "this exercise asks the exact reflectance of eqs. 3-5, (R_s + R_p) / 2 from "
     "fresnel_polarised; Schlick's differs from it by up to a few per cent",
     schlick},
};

static void grade_unpolarised(Grading *g)
{
    static double in[POINTS * ARITY], got[POINTS];
    static Wrong wrong;
    incidences(in);
    int wrong_count = 0;
    double largest = 0.0;
    for (int k = 0; k < POINTS; k++) {
        const double *x = in + (long)k * ARITY;
        got[k] = ASK(g, fresnel_reflectance(x[COS_I], x[N_I], x[N_T]));
        if (grading_not_finite(g, got[k], "R"))
            return;
        largest = fmax(largest, got[k]);
        wrong_count += fabs(got[k] - 0.5 * (x[RIGHT_S] + x[RIGHT_P])) > 1e-9;
    }
    grading_note(g, "%d incidences against (R_s + R_p) / 2: wrong at %d; the largest R %.4f",
                 POINTS, wrong_count, largest);
    if (wrong_count == 0)
        return;
    const WrongAnswer *known = catalogue(
        wrong_unpolarised, (int)(sizeof wrong_unpolarised / sizeof *wrong_unpolarised), in, got,
        -1, &wrong);
    if (known)
        grading_fail_known(g, "R", known, wrong.count);
    else if (largest > 1.0)
        grading_fail(g,
                     "R = %.4f > 1 somewhere: more light reflected than arrives; unpolarised "
                     "light is half s, half p: R = (R_s + R_p) / 2 (eq. 3)",
                     largest);
    fail_described(g, "R", in, got, POINTS, "(R_s + R_p) / 2");
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
