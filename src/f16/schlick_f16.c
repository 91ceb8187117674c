/* Schlick, generalized Schlick, Schlick internal and the F0 helpers in
 * binary16 (fresnel_f16.h); the algorithms of schlick.c. */
#include "internal.h"

#if FRESNEL_HAS_F16

fresnel_i_h fresnel_i_schlick_h(fresnel_i_h f0, fresnel_i_h c)
{
    fresnel_i_h one = fresnel_i_hc(1.0f);
    f0 = fresnel_i_hunit(f0);
    return fresnel_i_hunit(fresnel_i_hadd(f0, fresnel_i_hmul(fresnel_i_hsub(one, f0), fresnel_i_hpow5(fresnel_i_hsub(one, fresnel_i_hunit(c))))));
}

fresnel_f16 fresnel_schlick_f16(fresnel_f16 f0, fresnel_f16 c) { return fresnel_i_schlick_h(f0, c); }

fresnel_f16 fresnel_schlick_gen_f16(fresnel_f16 f0, fresnel_f16 f90, fresnel_f16 p, fresnel_f16 c)
{
    fresnel_i_h t;
    c = fresnel_i_hunit(c);
    f0 = fresnel_i_hunit(f0);
    f90 = fresnel_i_hunit(f90);
    p = fresnel_i_hclamp(p, fresnel_i_hc(FRESNEL_P_MIN_F16), fresnel_i_hc(FRESNEL_P_MAX_F16));
    t = fresnel_i_heq(p, fresnel_i_hc(5.0f)) ? fresnel_i_hpow5(fresnel_i_hsub(fresnel_i_hc(1.0f), c)) : fresnel_i_hpow_one_minus(c, p);
    return fresnel_i_hunit(fresnel_i_hadd(f0, fresnel_i_hmul(fresnel_i_hsub(f90, f0), t)));
}

fresnel_f16 fresnel_schlick_internal_f16(fresnel_f16 f0, fresnel_f16 eta, fresnel_f16 c)
{
    fresnel_i_h one = fresnel_i_hc(1.0f), ct2;
    eta = fresnel_i_heta(eta);
    c = fresnel_i_hunit(c);
    if (eta >= one)
        return fresnel_i_schlick_h(f0, c);
    /* eta^2 - sin^2 = (eta - 1)(eta + 1) + c^2; eta - 1 is exact (Sterbenz) */
    ct2 = fresnel_i_hadd(fresnel_i_hmul(fresnel_i_hsub(eta, one), fresnel_i_hadd(eta, one)), fresnel_i_hmul(c, c));
    if (!(ct2 > fresnel_i_hc(0.0f)))
        return one;
    return fresnel_i_schlick_h(f0, fresnel_i_hdiv(fresnel_i_hsqrt(ct2), eta));
}

fresnel_f16 fresnel_f0_in_medium_f16(fresnel_f16 f0, fresnel_f16 eta_e)
{
    fresnel_i_h one = fresnel_i_hc(1.0f), r, oms, omr, q;
    eta_e = fresnel_i_heta(eta_e);
    f0 = fresnel_i_hunit(f0);
    r = fresnel_i_hsqrt(f0);
    oms = fresnel_i_hdiv(fresnel_i_hc(2.0f), fresnel_i_hadd(eta_e, one));
    omr = fresnel_i_hdiv(fresnel_i_hsub(one, f0), fresnel_i_hadd(one, r));
    q = fresnel_i_hdiv(fresnel_i_hsub(oms, omr), fresnel_i_hadd(omr, fresnel_i_hmul(r, oms)));
    return fresnel_i_hunit(fresnel_i_hmul(q, q));
}

fresnel_f16 fresnel_f0_from_ior_f16(fresnel_f16 eta, fresnel_f16 kappa)
{
    fresnel_i_h one = fresnel_i_hc(1.0f), k2, em, ep;
    eta = fresnel_i_heta(eta);
    kappa = fresnel_i_hkappa(kappa);
    k2 = fresnel_i_hmul(kappa, kappa);
    em = fresnel_i_hsub(eta, one);
    ep = fresnel_i_hadd(eta, one);
    return fresnel_i_hunit(fresnel_i_hdiv(fresnel_i_hadd(fresnel_i_hmul(em, em), k2), fresnel_i_hadd(fresnel_i_hmul(ep, ep), k2)));
}

#else
typedef int fresnel_i_schlick_f16_disabled; /* ISO C wants a declaration in every file */
#endif
