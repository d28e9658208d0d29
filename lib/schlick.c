/* schlick.c (chapter 1): Schlick's reflectance, with the erratum of schlick.h. */
#include "schlick.h"

#include <math.h>

#include "snell.h"

double schlick_reflectance(double cos_i, double n_i, double n_t)
{
    /* No interface: eq. 6 would still give (1 - cos)^5 */
    if (n_i == n_t)
        return 0.0;
    double cos_theta = cos_i;
    if (n_i > n_t) {
        cos_theta = snell_cos_transmitted(cos_i, n_i, n_t);
        if (cos_theta < 0.0)
            return 1.0;
    }
    /* R0, eq. 7 */
    double r0 = (n_i - n_t) / (n_i + n_t);
    r0 *= r0;
    /* R(theta), eq. 6 */
    double m = 1.0 - cos_theta;
    return r0 + (1.0 - r0) * m * m * m * m * m;
}
