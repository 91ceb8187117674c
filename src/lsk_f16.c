/* LSK rescaled and compensated in binary16 (fresnel_f16.h); lsk.c's algorithm. */
#include "f16_internal.h"

#if FRESNEL_HAS_F16

fresnel_f16 fresnel_lsk_f16(fresnel_f16 n, fresnel_f16 k, fresnel_f16 c)
{
    fr__h one = fr__hc(1.0f), k2, nm, np, num, den;
    n = fr__heta(n);
    k = fr__hkappa(k);
    c = fr__hunit(c);
    k2 = fr__hmul(k, k);
    nm = fr__hsub(n, one);
    np = fr__hadd(n, one);
    num = fr__hadd(fr__hadd(fr__hmul(nm, nm), fr__hmul(fr__hmul(fr__hc(4.0f), n), fr__hpow5(fr__hsub(one, c)))), k2);
    den = fr__hadd(fr__hmul(np, np), k2);
    return fr__hunit(fr__hdiv(num, den));
}

fresnel_f16 fresnel_lsk_comp_f16(fresnel_f16 n, fresnel_f16 k, fresnel_f16 a, fresnel_f16 alpha, fresnel_f16 c)
{
    fr__h comp;
    c = fr__hunit(c);
    a = fr__hclamp(a, fr__hc(0.0f), fr__hc(64.0f));
    alpha = fr__hclamp(alpha, fr__hc(0.0f), fr__hc(FRESNEL_F16_P_MAX));
    comp = fr__hmul(a, c);
    if (alpha > fr__hc(0.0f))
        comp = fr__hmul(comp, fr__hpow_one_minus(c, alpha));
    return fr__hunit(fr__hsub(fresnel_lsk_f16(n, k, c), comp));
}

#else
typedef int fr__lsk_f16_disabled;
#endif
