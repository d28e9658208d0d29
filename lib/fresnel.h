/* fresnel.h (chapter 4): the exact Fresnel reflectance of a smooth dielectric interface (report
 * §3.5.2, eqs. 3-5).
 *
 * Introduced in chapter 4, which compares it with Schlick's approximation (schlick.h).
 * Light meeting the interface between indices n_i and n_t at incidence angle theta_i
 * is partly reflected and partly refracted to theta_t (Snell's law, snell.h). The
 * reflected fraction depends on the polarisation. With cos_i = cos(theta_i) and
 * cos_t = cos(theta_t):
 *   s-polarised (electric field perpendicular to the plane of incidence; eq. 4):
 *       R_s = ((n_i cos_i - n_t cos_t) / (n_i cos_i + n_t cos_t))^2
 *   p-polarised (electric field in the plane of incidence; eq. 5):
 *       R_p = ((n_i cos_t - n_t cos_i) / (n_i cos_t + n_t cos_i))^2
 *   unpolarised light, half of each:   R = (R_s + R_p) / 2                    (eq. 3)
 * Erratum (SPEC §8.3): the report's eq. 4 is labelled R_p but is R_s, and eq. 5 the
 * other way round; their average R, which the renderer uses, is the same either way.
 *
 * Some landmarks the tests check: at normal incidence R_s = R_p = ((n_i - n_t) /
 * (n_i + n_t))^2 (Schlick's R0); at Brewster's angle tan(theta_i) = n_t / n_i the
 * p-polarised part vanishes, R_p = 0; at grazing incidence R = 1. Leaving the denser
 * medium beyond the critical angle (SPEC §8.2) there is no refracted ray and R = 1
 * (total internal reflection); R rises continuously to 1 as the angle approaches it.
 * When n_i = n_t there is no interface and R = 0 at every angle.
 */
#ifndef FRESNEL_H
#define FRESNEL_H

/* Which reflectance a renderer uses at glass: Schlick's approximation (schlick.h, the
 * report's choice) or the exact equations below. */
typedef enum { FRESNEL_SCHLICK, FRESNEL_EXACT } FresnelMode;

/* The reflectances for incidence cosine cos_i in [0, 1] (clamped), from index n_i
 * into n_t, both > 0. All three return 1 for total internal reflection. */
double fresnel_s(double cos_i, double n_i, double n_t);
double fresnel_p(double cos_i, double n_i, double n_t);
double fresnel_reflectance(double cos_i, double n_i, double n_t);

#endif
