/* Cook-Torrance colour interpolation in binary16 (fresnel_f16.h); the
 * transmittance quotient of cook_torrance.c. */
#include "internal.h"

#if FRESNEL_HAS_F16

fresnel_f16 fresnel_cook_torrance_f16(fresnel_f16 f0, fresnel_f16 eta, fresnel_f16 kappa, fresnel_f16 c)
{
    fresnel_i_h one = fresnel_i_hc(1.0f), ep, d, t;
    eta = fresnel_i_heta(eta);
    kappa = fresnel_i_hkappa(kappa);
    f0 = fresnel_i_hunit(f0);
    ep = fresnel_i_hadd(eta, one);
    d = fresnel_i_hadd(fresnel_i_hmul(ep, ep), fresnel_i_hmul(kappa, kappa));
    /* 1 - T(c) d / (4 eta): divide first, T d would not overflow but d / 4eta is the ratio that matters */
    t = fresnel_i_hsub(one, fresnel_i_hmul(fresnel_i_conductor_transmittance_h(eta, kappa, c), fresnel_i_hdiv(d, fresnel_i_hmul(fresnel_i_hc(4.0f), eta))));
    return fresnel_i_hunit(fresnel_i_hadd(f0, fresnel_i_hmul(fresnel_i_hsub(one, f0), fresnel_i_hunit(t))));
}

#else
typedef int fresnel_i_cook_torrance_f16_disabled;
#endif
