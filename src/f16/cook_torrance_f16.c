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
    /* 1 - T(c) / T(1), T(1) = 4 eta / d, as (T(c) / (4 eta)) d: T(c) <= T(1),
     * so no step exceeds d (<= 290); d / (4 eta) would overflow 65504 for
     * eta 2^-10 under kappa 16 (and give 0 for F - F0 at every c). */
    t = fresnel_i_hsub(one, fresnel_i_hmul(fresnel_i_hdiv(fresnel_i_conductor_transmittance_h(eta, kappa, c), fresnel_i_hmul(fresnel_i_hc(4.0f), eta)), d));
    return fresnel_i_hunit(fresnel_i_hadd(f0, fresnel_i_hmul(fresnel_i_hsub(one, f0), fresnel_i_hunit(t))));
}

#else
typedef int fresnel_i_cook_torrance_f16_disabled;
#endif
