/* lambert.c (chapter 2): the Lambertian BRDF, eq. 8. See lambert.h. */
#include "lambert.h"

/* Eq. 8. */
Vec3 lambert_brdf(Vec3 rho) { return vec3_scale(rho, 1.0 / PI); }
