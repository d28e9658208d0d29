/* roulette.c: Russian roulette with survival probability alpha (chapter 6).
 * See roulette.h for why it is unbiased, and the report's erratum. */
#include "roulette.h"

int roulette_survives(double alpha, Rng *rng)
{
    return alpha >= 1.0 || rng_uniform(rng) < alpha;
}
