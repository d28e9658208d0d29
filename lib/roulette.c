/* roulette.c (chapter 6): Russian roulette with survival probability alpha.
 * See roulette.h for why it is unbiased, and the report's erratum. */
#include "roulette.h"

int roulette_survives(double alpha, Rng *rng)
{
    return alpha >= 1.0 || rng_uniform(rng) < alpha;
}

double roulette_survival_from_throughput(Vec3 throughput)
{
    return fmin(1.0, vec3_max_component(throughput));
}
