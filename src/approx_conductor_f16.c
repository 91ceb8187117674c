/* The approximate conductor form in binary16 (fresnel_f16.h), with the
 * cancellation-free numerators of approx_conductor.c. */
#include "f16_internal.h"

#if FRESNEL_HAS_F16

fr__h fr__approx_conductor_h(fr__h n, fr__h k, fr__h c)
{
    fr__h one = fr__hc(1.0f), kc, nk2, nc, nmc, npc, ncm, rs, rp;
    c = fr__hunit(c);
    nk2 = fr__hadd(fr__hmul(n, n), fr__hmul(k, k));
    kc = fr__hmul(k, c);
    nc = fr__hmul(n, c);
    nmc = fr__hsub(n, c);
    npc = fr__hadd(n, c);
    ncm = fr__hsub(nc, one);
    rs = fr__hdiv(fr__hadd(fr__hmul(nmc, nmc), fr__hmul(k, k)), fr__hadd(fr__hmul(npc, npc), fr__hmul(k, k)));
    rp = fr__hdiv(fr__hadd(fr__hmul(ncm, ncm), fr__hmul(kc, kc)),
                  fr__hadd(fr__hadd(fr__hmul(fr__hmul(nk2, c), c), fr__hmul(fr__hc(2.0f), nc)), one));
    return fr__hunit(fr__hmul(fr__hc(0.5f), fr__hadd(rs, rp)));
}

fresnel_f16 fresnel_approx_conductor_f16(fresnel_f16 n, fresnel_f16 k, fresnel_f16 c)
{
    return fr__approx_conductor_h(fr__heta(n), fr__hkappa(k), c);
}

#else
typedef int fr__approx_conductor_f16_disabled;
#endif
