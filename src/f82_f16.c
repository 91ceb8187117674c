/* Hoffman's F82 model in binary16 (fresnel_f16.h); f82.c's algorithm. */
#include "f16_internal.h"

#if FRESNEL_HAS_F16

fresnel_f16 fresnel_f82_f16(fresnel_f16 f0, fresnel_f16 f82, fresnel_f16 c)
{
    fr__h one = fr__hc(1.0f), x, x5, a, om;
    f0 = fr__hunit(f0);
    f82 = fr__hunit(f82);
    c = fr__hunit(c);
    x = fr__hsub(one, c);
    x5 = fr__hpow5(x);
    om = fr__hsub(one, f0);
    /* 823543/46656 = 7^7/6^6 and 49/6, each rounded to half once */
    a = fr__hadd(fr__hmul(fr__hc(823543.0f / 46656.0f), fr__hsub(f0, f82)), fr__hmul(fr__hc(49.0f / 6.0f), om));
    return fr__hunit(fr__hsub(fr__hadd(f0, fr__hmul(om, x5)), fr__hmul(fr__hmul(fr__hmul(a, c), x5), x)));
}

#else
typedef int fr__f82_f16_disabled;
#endif
