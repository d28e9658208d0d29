/* roulette.c (chapter 6): Russian roulette. See roulette.h. */
#include "roulette.h"

int roulette_survives(double alpha, Rng *rng)
{
    return alpha >= 1.0 || rng_uniform(rng) < alpha;
}

double roulette_survival_from_throughput(Vec3 throughput)
{
    return fmin(1.0, vec3_max_component(throughput));
}

int roulette_continues(const PathSettings *settings, int segment, Vec3 *throughput, Rng *rng)
{
    double survival = settings->rr_survival;
    if (settings->rr_throughput > 0)
        survival = segment >= settings->rr_throughput
                       ? roulette_survival_from_throughput(*throughput)
                       : 1.0;
    if (!(survival > 0.0 && survival < 1.0))
        return 1; /* no roulette */
    if (!roulette_survives(survival, rng))
        return 0;
    *throughput = vec3_scale(*throughput, 1.0 / survival);
    return 1;
}
