/* Cook-Torrance colour interpolation in binary16 (fresnel_f16.h); the
 * transmittance quotient of cook_torrance.c. */
#include "f16_internal.h"

#if FRESNEL_HAS_F16

fresnel_f16 fresnel_cook_torrance_f16(fresnel_f16 f0, fresnel_f16 eta, fresnel_f16 kappa, fresnel_f16 c)
{
    fr__h one = fr__hc(1.0f), ep, d, t;
    eta = fr__heta(eta);
    kappa = fr__hkappa(kappa);
    f0 = fr__hunit(f0);
    ep = fr__hadd(eta, one);
    d = fr__hadd(fr__hmul(ep, ep), fr__hmul(kappa, kappa));
    /* 1 - T(c) d / (4 eta): divide first, T d would not overflow but d / 4eta is the ratio that matters */
    t = fr__hsub(one, fr__hmul(fr__conductor_transmittance_h(eta, kappa, c), fr__hdiv(d, fr__hmul(fr__hc(4.0f), eta))));
    return fr__hunit(fr__hadd(f0, fr__hmul(fr__hsub(one, f0), fr__hunit(t))));
}

#else
typedef int fr__cook_torrance_f16_disabled;
#endif
