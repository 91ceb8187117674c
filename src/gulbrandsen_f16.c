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
#include "f16_internal.h"

#if FRESNEL_HAS_F16

fresnel_f16 fresnel_gulbrandsen_f16(fresnel_f16 r, fresnel_f16 g, fresnel_f16 c)
{
    fr__h one = fr__hc(1.0f), s, opr, omr, omg, ops, nmin, nmax, n, q, k2;
    /* 0.9999 rounds to 1 in binary16: the largest half below 1 instead */
    r = fr__hclamp(r, fr__hc(0.0f), fr__hc(1.0f - 1.0f / 2048.0f));
    g = fr__hunit(g);
    s = fr__hsqrt(r);
    opr = fr__hadd(one, r);
    omr = fr__hsub(one, r); /* exact for r >= 1/2 */
    omg = fr__hsub(one, g); /* exact for g >= 1/2 */
    ops = fr__hadd(one, s);
    nmin = fr__hdiv(omr, opr);
    nmax = fr__hdiv(fr__hmul(ops, ops), omr);
    n = fr__hadd(fr__hmul(g, nmin), fr__hmul(omg, nmax));
    q = fr__hdiv(fr__hmul(fr__hmul(fr__hc(2.0f), g), s), opr);
    /* the second term overflows to +inf only when k is far outside the
     * binary16 domain, where it is clamped; (1-g) first, so g = 1 gives 0 */
    k2 = fr__hmul(q, fr__hadd(q, fr__hdiv(fr__hmul(fr__hmul(fr__hmul(fr__hc(4.0f), omg), s), nmax), omr)));
    return fr__approx_conductor_h(fr__heta(n), fr__hkappa(fr__hsqrt(k2)), c);
}

#else
typedef int fr__gulbrandsen_f16_disabled;
#endif
