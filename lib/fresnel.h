/* fresnel.h (chapter 4): the exact Fresnel reflectance of a smooth dielectric (report
 * §3.5.2, eqs. 3-5), which chapter 4 compares with Schlick's (schlick.h).
 *
 *     R_s = ((n_i cos_i - n_t cos_t) / (n_i cos_i + n_t cos_t))^2    (eq. 4)
 *     R_p = ((n_i cos_t - n_t cos_i) / (n_i cos_t + n_t cos_i))^2    (eq. 5)
 *     R = (R_s + R_p) / 2                                              (eq. 3)
 * Erratum: the report labels eq. 4 R_p and eq. 5 R_s; their average is unaffected.
 * Beyond the critical angle R = 1 (total internal reflection); with n_i = n_t, R = 0.
 */
#ifndef FRESNEL_H
#define FRESNEL_H

/* Which reflectance a renderer uses at glass: Schlick's approximation (schlick.h, the
 * report's choice) or the exact equations below. */
typedef enum {
    FRESNEL_SCHLICK,
    FRESNEL_EXACT
} FresnelMode;

/* The reflectances for incidence cosine cos_i in [0, 1] (clamped), from index n_i
 * into n_t, both > 0. All three return 1 for total internal reflection. */
double fresnel_s(double cos_i, double n_i, double n_t);
double fresnel_p(double cos_i, double n_i, double n_t);
double fresnel_reflectance(double cos_i, double n_i, double n_t);

/* The critical angle arcsin(n_t / n_i) in radians, beyond which light in the denser
 * medium is totally reflected (snell.h), for n_i > n_t; pi/2 when n_i <= n_t. */
double fresnel_critical_angle(double n_i, double n_t);

#endif
