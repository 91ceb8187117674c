/* Cook and Torrance's colour interpolation, in Hoffman's modified form [Hof20]. */
#include "internal.h"

#if FRESNEL_HAS_FLOAT

float fresnel_cook_torrance(float f0, float eta, float kappa, float c)
{
    float d, t;
    eta = fresnel_i_eta(eta);
    kappa = fresnel_i_kappa(kappa);
    f0 = fresnel_i_unit(f0);
    /* (F'(c) - F'(1)) / (1 - F'(1)) = 1 - T'(c) / T'(1) with T' = 1 - F' and
     * T'(1) = 4 eta / ((eta+1)^2 + kappa^2): the quotient of two accurate
     * small numbers, not of two differences of numbers near 1. */
    d = (eta + 1.0f) * (eta + 1.0f) + kappa * kappa;
    t = 1.0f - fresnel_i_conductor_transmittance(eta, kappa, c) * d / (4.0f * eta);
    return fresnel_i_unit(f0 + (1.0f - f0) * fresnel_i_unit(t));
}

fresnel_rgb fresnel_cook_torrance_rgb(fresnel_rgb f0, float eta, float kappa, float c)
{
    float t, d;
    eta = fresnel_i_eta(eta);
    kappa = fresnel_i_kappa(kappa);
    /* One scalar interpolant for the three channels. */
    d = (eta + 1.0f) * (eta + 1.0f) + kappa * kappa;
    t = fresnel_i_unit(1.0f - fresnel_i_conductor_transmittance(eta, kappa, c) * d / (4.0f * eta));
    f0.r = fresnel_i_unit(f0.r);
    f0.g = fresnel_i_unit(f0.g);
    f0.b = fresnel_i_unit(f0.b);
    FRESNEL_I_RGB(fresnel_i_unit(f0.r + (1.0f - f0.r) * t), fresnel_i_unit(f0.g + (1.0f - f0.g) * t),
            fresnel_i_unit(f0.b + (1.0f - f0.b) * t));
}

#else
typedef int fresnel_i_cook_torrance_disabled; /* FRESNEL_CFG_NO_FLOAT: ISO C wants a declaration */
#endif
