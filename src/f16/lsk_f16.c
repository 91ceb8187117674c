/* LSK rescaled and compensated in binary16 (fresnel_f16.h); lsk.c's algorithm. */
#include "internal.h"

#if FRESNEL_HAS_F16

fresnel_f16 fresnel_lsk_f16(fresnel_f16 n, fresnel_f16 k, fresnel_f16 c)
{
    fresnel_i_h one = fresnel_i_hc(1.0f), k2, nm, np, num, den;
    n = fresnel_i_heta(n);
    k = fresnel_i_hkappa(k);
    c = fresnel_i_hunit(c);
    k2 = fresnel_i_hmul(k, k);
    nm = fresnel_i_hsub(n, one);
    np = fresnel_i_hadd(n, one);
    num = fresnel_i_hadd(fresnel_i_hadd(fresnel_i_hmul(nm, nm), fresnel_i_hmul(fresnel_i_hmul(fresnel_i_hc(4.0f), n), fresnel_i_hpow5(fresnel_i_hsub(one, c)))), k2);
    den = fresnel_i_hadd(fresnel_i_hmul(np, np), k2);
    return fresnel_i_hunit(fresnel_i_hdiv(num, den));
}

fresnel_f16 fresnel_lsk_comp_f16(fresnel_f16 n, fresnel_f16 k, fresnel_f16 a, fresnel_f16 alpha, fresnel_f16 c)
{
    fresnel_i_h comp;
    c = fresnel_i_hunit(c);
    a = fresnel_i_hclamp(a, fresnel_i_hc(0.0f), fresnel_i_hc(64.0f));
    alpha = fresnel_i_hclamp(alpha, fresnel_i_hc(0.0f), fresnel_i_hc(FRESNEL_P_MAX_F16));
    comp = fresnel_i_hmul(a, c);
    if (alpha > fresnel_i_hc(0.0f))
        comp = fresnel_i_hmul(comp, fresnel_i_hpow_one_minus(c, alpha));
    return fresnel_i_hunit(fresnel_i_hsub(fresnel_lsk_f16(n, k, c), comp));
}

#else
typedef int fresnel_i_lsk_f16_disabled;
#endif
