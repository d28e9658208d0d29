/* mis.h (chapter 7): multiple importance sampling by the power heuristic (Veach 1997,
 * ch. 9).
 *
 * Two ways find the light arriving at a diffuse vertex: shadow rays (light sampling,
 * density d^2 / (A cos beta)) and the path's own bounce (BRDF sampling, cos / pi). Each
 * sample is kept, weighted so that the weights of the ways that can produce a direction
 * add up to 1 there; the power heuristic w_f = (n_f p_f)^2 / ((n_f p_f)^2 + (n_g p_g)^2)
 * is close to the best such weights (docs/chapter7.md).
 */
#ifndef MIS_H
#define MIS_H

/* Exercise 7.1: the power heuristic's weight of strategy f, taking count_f samples of
 * density pdf_f, against strategy g (count_g samples of density pdf_g), for one direction:
 *     (count_f pdf_f)^2 / ((count_f pdf_f)^2 + (count_g pdf_g)^2);  0 when both are 0. */
double mis_power_heuristic(int count_f, double pdf_f, int count_g, double pdf_g);

#endif
