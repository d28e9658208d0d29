/* hemisphere.c (chapter 2): cosine-weighted hemisphere sampling. See hemisphere.h. */
#include "hemisphere.h"

/* Eq. 12 applied to P(theta) = sin^2(theta) and P(phi) = phi / (2 pi). */
Vec3 hemisphere_sample_cosine(double u1, double u2)
{
    double sin_theta = sqrt(u1);
    double cos_theta = sqrt(1.0 - u1);
    double phi = 2.0 * PI * u2;
    return vec3(sin_theta * cos(phi), sin_theta * sin(phi), cos_theta);
}

double hemisphere_pdf_cosine(Vec3 w_local) { return w_local.z > 0.0 ? w_local.z / PI : 0.0; }
