/* Schlick, generalized Schlick, Schlick internal and the F0 helpers in
 * binary16 (fresnel_f16.h); the algorithms of schlick.c. */
#include "f16_internal.h"

#if FRESNEL_HAS_F16

fr__h fr__schlick_h(fr__h f0, fr__h c)
{
    fr__h one = fr__hc(1.0f);
    f0 = fr__hunit(f0);
    return fr__hunit(fr__hadd(f0, fr__hmul(fr__hsub(one, f0), fr__hpow5(fr__hsub(one, fr__hunit(c))))));
}

fresnel_f16 fresnel_schlick_f16(fresnel_f16 f0, fresnel_f16 c) { return fr__schlick_h(f0, c); }

fresnel_f16 fresnel_schlick_gen_f16(fresnel_f16 f0, fresnel_f16 f90, fresnel_f16 p, fresnel_f16 c)
{
    fr__h t;
    c = fr__hunit(c);
    f0 = fr__hunit(f0);
    f90 = fr__hunit(f90);
    p = fr__hclamp(p, fr__hc(FRESNEL_F16_P_MIN), fr__hc(FRESNEL_F16_P_MAX));
    t = fr__heq(p, fr__hc(5.0f)) ? fr__hpow5(fr__hsub(fr__hc(1.0f), c)) : fr__hpow_one_minus(c, p);
    return fr__hunit(fr__hadd(f0, fr__hmul(fr__hsub(f90, f0), t)));
}

fresnel_f16 fresnel_schlick_internal_f16(fresnel_f16 f0, fresnel_f16 eta, fresnel_f16 c)
{
    fr__h one = fr__hc(1.0f), ct2;
    eta = fr__heta(eta);
    c = fr__hunit(c);
    if (eta >= one)
        return fr__schlick_h(f0, c);
    /* eta^2 - sin^2 = (eta - 1)(eta + 1) + c^2; eta - 1 is exact (Sterbenz) */
    ct2 = fr__hadd(fr__hmul(fr__hsub(eta, one), fr__hadd(eta, one)), fr__hmul(c, c));
    if (!(ct2 > fr__hc(0.0f)))
        return one;
    return fr__schlick_h(f0, fr__hdiv(fr__hsqrt(ct2), eta));
}

fresnel_f16 fresnel_f0_in_medium_f16(fresnel_f16 f0, fresnel_f16 eta_e)
{
    fr__h one = fr__hc(1.0f), r, oms, omr, q;
    eta_e = fr__heta(eta_e);
    f0 = fr__hunit(f0);
    r = fr__hsqrt(f0);
    oms = fr__hdiv(fr__hc(2.0f), fr__hadd(eta_e, one));
    omr = fr__hdiv(fr__hsub(one, f0), fr__hadd(one, r));
    q = fr__hdiv(fr__hsub(oms, omr), fr__hadd(omr, fr__hmul(r, oms)));
    return fr__hunit(fr__hmul(q, q));
}

fresnel_f16 fresnel_f0_from_ior_f16(fresnel_f16 eta, fresnel_f16 kappa)
{
    fr__h one = fr__hc(1.0f), k2, em, ep;
    eta = fr__heta(eta);
    kappa = fr__hkappa(kappa);
    k2 = fr__hmul(kappa, kappa);
    em = fr__hsub(eta, one);
    ep = fr__hadd(eta, one);
    return fr__hunit(fr__hdiv(fr__hadd(fr__hmul(em, em), k2), fr__hadd(fr__hmul(ep, ep), k2)));
}

#else
typedef int fr__schlick_f16_disabled; /* ISO C wants a declaration in every file */
#endif
