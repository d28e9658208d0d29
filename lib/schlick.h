/* schlick.h (chapter 1): Schlick's approximation to the Fresnel reflectance (report
 * §3.5.2, eqs. 6-7):
 *     R(theta) = R0 + (1 - R0) (1 - cos theta)^5,   R0 = ((n_i - n_t) / (n_i + n_t))^2.
 * Erratum: leaving the denser medium (n_i > n_t) it must use the cosine of the
 * transmitted angle, or R jumps to 1 at the critical angle; beyond it R = 1. With
 * n_i = n_t there is no interface and R = 0.
 */
#ifndef SCHLICK_H
#define SCHLICK_H

/* Exercise 1.6: reflectance for incidence cosine cos_i in [0, 1], from index n_i into n_t. */
double schlick_reflectance(double cos_i, double n_i, double n_t);

#endif
