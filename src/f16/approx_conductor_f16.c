/* The approximate conductor form in binary16 (fresnel_f16.h), with the
 * cancellation-free numerators of approx_conductor.c. */
#include "internal.h"

#if FRESNEL_HAS_F16

fresnel_i_h fresnel_i_approx_conductor_h(fresnel_i_h n, fresnel_i_h k, fresnel_i_h c)
{
    fresnel_i_h one = fresnel_i_hc(1.0f), kc, nk2, nc, nmc, npc, ncm, rs, rp;
    c = fresnel_i_hunit(c);
    nk2 = fresnel_i_hadd(fresnel_i_hmul(n, n), fresnel_i_hmul(k, k));
    kc = fresnel_i_hmul(k, c);
    nc = fresnel_i_hmul(n, c);
    nmc = fresnel_i_hsub(n, c);
    npc = fresnel_i_hadd(n, c);
    ncm = fresnel_i_hsub(nc, one);
    rs = fresnel_i_hdiv(fresnel_i_hadd(fresnel_i_hmul(nmc, nmc), fresnel_i_hmul(k, k)), fresnel_i_hadd(fresnel_i_hmul(npc, npc), fresnel_i_hmul(k, k)));
    rp = fresnel_i_hdiv(fresnel_i_hadd(fresnel_i_hmul(ncm, ncm), fresnel_i_hmul(kc, kc)),
                  fresnel_i_hadd(fresnel_i_hadd(fresnel_i_hmul(fresnel_i_hmul(nk2, c), c), fresnel_i_hmul(fresnel_i_hc(2.0f), nc)), one));
    return fresnel_i_hunit(fresnel_i_hmul(fresnel_i_hc(0.5f), fresnel_i_hadd(rs, rp)));
}

fresnel_f16 fresnel_approx_conductor_f16(fresnel_f16 n, fresnel_f16 k, fresnel_f16 c)
{
    return fresnel_i_approx_conductor_h(fresnel_i_heta(n), fresnel_i_hkappa(k), c);
}

#else
typedef int fresnel_i_approx_conductor_f16_disabled;
#endif
