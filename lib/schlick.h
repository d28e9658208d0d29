/* schlick.h (chapter 1): Schlick's approximation to the Fresnel reflectance (report §3.5.2,
 * eqs. 6-7).
 *
 * Introduced in chapter 1 (the report's choice; chapter 4 compares it with the exact
 * equations of fresnel.h):
 *     R(theta) = R0 + (1 - R0) (1 - cos theta)^5,   R0 = ((n_i - n_t) / (n_i + n_t))^2.
 * Erratum (SPEC §8.4): eq. 6 uses the angle of incidence, which is right entering the
 * denser medium. Leaving it (n_i > n_t), the approximation must use the cosine of the
 * transmitted angle, otherwise R stays well below 1 up to the critical angle and then
 * jumps to 1; with cos_t, R rises continuously to 1 at the critical angle. Beyond it
 * (total internal reflection) R = 1.
 * With n_i = n_t there is no interface and R = 0 at every angle, as the exact Fresnel
 * equations give; eq. 6 alone would still reflect (1 - cos theta)^5.
 */
#ifndef SCHLICK_H
#define SCHLICK_H

/* Reflectance for incidence cosine cos_i in [0, 1], from index n_i into n_t. */
double schlick_reflectance(double cos_i, double n_i, double n_t);

#endif
