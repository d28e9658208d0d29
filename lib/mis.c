/* mis.c (chapter 7): the power heuristic. See mis.h. */
#include "mis.h"

/* Written as 1 / (1 + (g/f)^2), which neither overflows for a huge density (a light seen
 * edge-on) nor divides 0 by 0. */
double mis_power_heuristic(int count_f, double pdf_f, int count_g, double pdf_g)
{
    double f = count_f * pdf_f, g = count_g * pdf_g;
    if (!(f > 0.0))
        return 0.0;
    double ratio = g / f;
    return 1.0 / (1.0 + ratio * ratio);
}
