/* Cook and Torrance's colour interpolation, in Hoffman's modified form [Hof20]. */
#include "internal.h"

#if FRESNEL_HAS_FLOAT

float fresnel_cook_torrance(float f0, float eta, float kappa, float c)
{
    float d, t;
    eta = fr__eta(eta);
    kappa = fr__kappa(kappa);
    f0 = fr__unit(f0);
    /* (F'(c) - F'(1)) / (1 - F'(1)) = 1 - T'(c) / T'(1) with T' = 1 - F' and
     * T'(1) = 4 eta / ((eta+1)^2 + kappa^2): the quotient of two accurate
     * small numbers, not of two differences of numbers near 1. */
    d = (eta + 1.0f) * (eta + 1.0f) + kappa * kappa;
    t = 1.0f - fr__conductor_transmittance(eta, kappa, c) * d / (4.0f * eta);
    return fr__unit(f0 + (1.0f - f0) * fr__unit(t));
}

fresnel_rgb fresnel_cook_torrance_rgb(fresnel_rgb f0, float eta, float kappa, float c)
{
    float t, d;
    eta = fr__eta(eta);
    kappa = fr__kappa(kappa);
    /* One scalar interpolant for the three channels. */
    d = (eta + 1.0f) * (eta + 1.0f) + kappa * kappa;
    t = fr__unit(1.0f - fr__conductor_transmittance(eta, kappa, c) * d / (4.0f * eta));
    f0.r = fr__unit(f0.r);
    f0.g = fr__unit(f0.g);
    f0.b = fr__unit(f0.b);
    FR__RGB(fr__unit(f0.r + (1.0f - f0.r) * t), fr__unit(f0.g + (1.0f - f0.g) * t),
            fr__unit(f0.b + (1.0f - f0.b) * t));
}

#else
typedef int fr__cook_torrance_disabled; /* FRESNEL_CFG_NO_FLOAT: ISO C wants a declaration */
#endif
