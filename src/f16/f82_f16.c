/* Hoffman's F82 model in binary16 (fresnel_f16.h); f82.c's algorithm. */
#include "internal.h"

#if FRESNEL_HAS_F16

fresnel_f16 fresnel_f82_f16(fresnel_f16 f0, fresnel_f16 f82, fresnel_f16 c)
{
    fresnel_i_h one = fresnel_i_hc(1.0f), x, x5, a, om;
    f0 = fresnel_i_hunit(f0);
    f82 = fresnel_i_hunit(f82);
    c = fresnel_i_hunit(c);
    x = fresnel_i_hsub(one, c);
    x5 = fresnel_i_hpow5(x);
    om = fresnel_i_hsub(one, f0);
    /* 823543/46656 = 7^7/6^6 and 49/6, each rounded to half once */
    a = fresnel_i_hadd(fresnel_i_hmul(fresnel_i_hc(823543.0f / 46656.0f), fresnel_i_hsub(f0, f82)), fresnel_i_hmul(fresnel_i_hc(49.0f / 6.0f), om));
    return fresnel_i_hunit(fresnel_i_hsub(fresnel_i_hadd(f0, fresnel_i_hmul(om, x5)), fresnel_i_hmul(fresnel_i_hmul(fresnel_i_hmul(a, c), x5), x)));
}

#else
typedef int fresnel_i_f82_f16_disabled;
#endif
