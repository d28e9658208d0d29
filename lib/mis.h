/* mis.h (chapter 7): multiple importance sampling, the power heuristic (Veach 1997, ch. 9;
 * pbrt's path integrator).
 *
 * Introduced in chapter 7. At a diffuse vertex x there are two ways to find the light
 * that arrives from a lamp:
 *   - light sampling (area_light.h): M shadow rays to points drawn uniformly over the
 *     lamp, whose directions have density p_light(w) = d^2 / (A cos beta) in solid
 *     angle. Good for a small or distant lamp, bad where the lamp is near and seen at
 *     a grazing angle (the ceiling beside this room's lamp: cos beta / d^2 varies
 *     wildly over it);
 *   - BRDF sampling (diffuse.h): the path's next direction, density p_bsdf(w) =
 *     cos(alpha) / pi, which finds the lamp when it happens to hit it. Good exactly where
 *     light sampling is bad, useless for a small lamp.
 * Chapter 3 uses only the first (and drops what the second finds, so nothing is counted
 * twice). Multiple importance sampling keeps both, each sample weighted so that the
 * weights of the ways that can produce a direction w add up to 1 there:
 *     L_D = 1/M sum_k w_light(w_k) f Le cos / p_light(w_k)  +  w_bsdf(w') f Le cos / p_bsdf(w'),
 * unbiased for any weights that sum to 1, and the power heuristic (beta = 2) is close
 * to the best such weights: with n_light = M samples of one and n_bsdf = 1 of the other,
 *     w_light = (M p_light)^2 / ((M p_light)^2 + p_bsdf^2),  w_bsdf = 1 - w_light
 * (the density of a strategy counts once per sample it takes). Each sample is then
 * weighted by how well its own strategy explains it, and a direction that one strategy
 * samples rarely (with a huge value) gets a small weight there.
 */
#ifndef MIS_H
#define MIS_H

/* The power heuristic's weight of strategy f, taking count_f samples of density pdf_f,
 * against strategy g (count_g samples of density pdf_g), for the same direction:
 *     (count_f pdf_f)^2 / ((count_f pdf_f)^2 + (count_g pdf_g)^2);  0 when both are 0. */
double mis_power_heuristic(int count_f, double pdf_f, int count_g, double pdf_g);

#endif
