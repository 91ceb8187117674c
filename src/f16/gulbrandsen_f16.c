/* Gulbrandsen's edge tint in binary16 (fresnel_f16.h).
 *
 * gulbrandsen.c's factored k^2 still has one difference,
 * sqrt r (n + 1) + n - 1, which in binary16 loses most of its digits for
 * metals (silver: r 0.99, g 1, the sum is 0.005 from terms near 1). It is
 * linear in n, and n is linear in g, so with s = sqrt r it is the sum of its
 * values at the two ends, g 2s(1-s)/(1+r) + (1-g) 4s/(1-s); with
 * nmax - nmin = 2s(1+s) / ((1-s)(1+r)) the whole of k^2 becomes
 *   k^2 = q (q + 4 (1-g) s nmax / (1-r)),  q = 2 g s / (1+r),
 * sums and products of positive terms only. */
#include "internal.h"

#if FRESNEL_HAS_F16

fresnel_f16 fresnel_gulbrandsen_f16(fresnel_f16 r, fresnel_f16 g, fresnel_f16 c)
{
    fresnel_i_h one = fresnel_i_hc(1.0f), s, opr, omr, omg, ops, nmin, nmax, n, q, k2;
    /* 0.9999 rounds to 1 in binary16: the largest half below 1 instead */
    r = fresnel_i_hclamp(r, fresnel_i_hc(0.0f), fresnel_i_hc(1.0f - 1.0f / 2048.0f));
    g = fresnel_i_hunit(g);
    s = fresnel_i_hsqrt(r);
    opr = fresnel_i_hadd(one, r);
    omr = fresnel_i_hsub(one, r); /* exact for r >= 1/2 */
    omg = fresnel_i_hsub(one, g); /* exact for g >= 1/2 */
    ops = fresnel_i_hadd(one, s);
    nmin = fresnel_i_hdiv(omr, opr);
    nmax = fresnel_i_hdiv(fresnel_i_hmul(ops, ops), omr);
    n = fresnel_i_hadd(fresnel_i_hmul(g, nmin), fresnel_i_hmul(omg, nmax));
    q = fresnel_i_hdiv(fresnel_i_hmul(fresnel_i_hmul(fresnel_i_hc(2.0f), g), s), opr);
    /* the second term overflows to +inf only when k is far outside the
     * binary16 domain, where it is clamped; (1-g) first, so g = 1 gives 0 */
    k2 = fresnel_i_hmul(q, fresnel_i_hadd(q, fresnel_i_hdiv(fresnel_i_hmul(fresnel_i_hmul(fresnel_i_hmul(fresnel_i_hc(4.0f), omg), s), nmax), omr)));
    return fresnel_i_approx_conductor_h(fresnel_i_heta(n), fresnel_i_hkappa(fresnel_i_hsqrt(k2)), c);
}

#else
typedef int fresnel_i_gulbrandsen_f16_disabled;
#endif
