/* The exact Fresnel equations in binary16 (fresnel_f16.h): exact.c's
 * algorithm (smaller of u, v from u v = eta kappa; numerators as sums of
 * squares of differences), with hypot scaled and the p-polarised ratio
 * divided through by max(1, eta^2 + kappa^2) so that nothing exceeds 65504
 * for eta, kappa <= 16. */
#include "f16_internal.h"

#if FRESNEL_HAS_F16

struct fr__root_h {
    fr__h u, v, m;
};

static struct fr__root_h fr__transmitted_h(fr__h eta, fr__h kappa, fr__h c)
{
    struct fr__root_h w;
    fr__h one = fr__hc(1.0f), half = fr__hc(0.5f), zero = fr__hc(0.0f);
    fr__h ek = fr__hmul(eta, kappa);
    /* eta^2 - kappa^2 - sin^2 = ((eta - 1)(eta + 1) + c^2) - kappa^2 */
    fr__h a = fr__hsub(fr__hadd(fr__hmul(fr__hsub(eta, one), fr__hadd(eta, one)), fr__hmul(c, c)), fr__hmul(kappa, kappa));
    fr__h abs_a = a < zero ? fr__hsub(zero, a) : a;
    w.m = fr__hhypot(abs_a, fr__hmul(fr__hc(2.0f), ek));
    if (a >= zero) {
        w.u = fr__hsqrt(fr__hmul(half, fr__hadd(w.m, a)));
        w.v = w.u > zero ? fr__hdiv(ek, w.u) : zero;
    } else {
        w.v = fr__hsqrt(fr__hmul(half, fr__hsub(w.m, a)));
        w.u = fr__hdiv(ek, w.v);
    }
    return w;
}

/* 1 / max(1, eta^2 + kappa^2): the scale of the p-polarised terms */
static fr__h fr__pscale(fr__h eta, fr__h kappa)
{
    fr__h n2 = fr__hadd(fr__hmul(eta, eta), fr__hmul(kappa, kappa));
    return n2 > fr__hc(1.0f) ? fr__hdiv(fr__hc(1.0f), n2) : fr__hc(1.0f);
}

fresnel_f16 fresnel_conductor_f16(fresnel_f16 eta, fresnel_f16 kappa, fresnel_f16 c)
{
    struct fr__root_h w;
    fr__h zero = fr__hc(0.0f), s, p, q, u, v, cu, cmu, pu, qv, pmu, qmv, num_s, den_s, num_p, den_p, rs, rp;
    eta = fr__heta(eta);
    kappa = fr__hkappa(kappa);
    c = fr__hunit(c);
    if (fr__heq(eta, fr__hc(1.0f)) && fr__heq(kappa, zero))
        return zero; /* matched index */
    w = fr__transmitted_h(eta, kappa, c);
    cu = fr__hadd(c, w.u);
    cmu = fr__hsub(c, w.u);
    num_s = fr__hadd(fr__hmul(cmu, cmu), fr__hmul(w.v, w.v));
    den_s = fr__hadd(fr__hmul(cu, cu), fr__hmul(w.v, w.v));
    s = fr__pscale(eta, kappa);
    /* (eta + i kappa)^2 c = p + i q, and u, v, all times s */
    p = fr__hmul(fr__hmul(c, fr__hmul(fr__hsub(eta, kappa), fr__hadd(eta, kappa))), s);
    q = fr__hmul(fr__hmul(fr__hmul(fr__hc(2.0f), fr__hmul(eta, kappa)), c), s);
    u = fr__hmul(w.u, s);
    v = fr__hmul(w.v, s);
    pu = fr__hadd(p, u);
    qv = fr__hadd(q, v);
    pmu = fr__hsub(p, u);
    qmv = fr__hsub(q, v);
    num_p = fr__hadd(fr__hmul(pmu, pmu), fr__hmul(qmv, qmv));
    den_p = fr__hadd(fr__hmul(pu, pu), fr__hmul(qv, qv));
    rs = den_s > zero ? fr__hdiv(num_s, den_s) : zero;
    rp = den_p > zero ? fr__hdiv(num_p, den_p) : zero;
    return fr__hunit(fr__hmul(fr__hc(0.5f), fr__hadd(rs, rp)));
}

fr__h fr__conductor_transmittance_h(fr__h eta, fr__h kappa, fr__h c)
{
    /* 1 - Rs = 4cu / den_s, 1 - Rp = 4 c u (m + s^2) / den_p (exact.c) */
    struct fr__root_h w;
    fr__h zero = fr__hc(0.0f), one = fr__hc(1.0f), s, p, q, s2, cu, pu, qv, den_s, den_p, ts, tp, four_cu;
    eta = fr__heta(eta);
    kappa = fr__hkappa(kappa);
    c = fr__hunit(c);
    if (fr__heq(eta, one) && fr__heq(kappa, zero))
        return one;
    w = fr__transmitted_h(eta, kappa, c);
    s = fr__pscale(eta, kappa);
    p = fr__hmul(fr__hmul(c, fr__hmul(fr__hsub(eta, kappa), fr__hadd(eta, kappa))), s);
    q = fr__hmul(fr__hmul(fr__hmul(fr__hc(2.0f), fr__hmul(eta, kappa)), c), s);
    s2 = fr__hmul(fr__hsub(one, c), fr__hadd(one, c));
    cu = fr__hadd(c, w.u);
    den_s = fr__hadd(fr__hmul(cu, cu), fr__hmul(w.v, w.v));
    pu = fr__hadd(p, fr__hmul(w.u, s));
    qv = fr__hadd(q, fr__hmul(w.v, s));
    den_p = fr__hadd(fr__hmul(pu, pu), fr__hmul(qv, qv));
    four_cu = fr__hmul(fr__hmul(fr__hc(4.0f), c), w.u);
    ts = den_s > zero ? fr__hdiv(four_cu, den_s) : one;
    /* numerator 4cu (m + s^2) s^2, formed as (4cu s)((m + s^2) s) */
    tp = den_p > zero ? fr__hdiv(fr__hmul(fr__hmul(four_cu, s), fr__hmul(fr__hadd(w.m, s2), s)), den_p) : one;
    return fr__hunit(fr__hmul(fr__hc(0.5f), fr__hadd(ts, tp)));
}

fresnel_f16 fresnel_dielectric_f16(fresnel_f16 eta, fresnel_f16 c)
{
    fr__h one = fr__hc(1.0f), zero = fr__hc(0.0f), a, w, e2c, rs, rp;
    eta = fr__heta(eta);
    c = fr__hunit(c);
    if (fr__heq(eta, one))
        return zero;
    a = fr__hadd(fr__hmul(fr__hsub(eta, one), fr__hadd(eta, one)), fr__hmul(c, c));
    if (a < zero)
        return one; /* total internal reflection */
    w = fr__hsqrt(a);
    e2c = fr__hmul(fr__hmul(eta, eta), c);
    rs = fr__hdiv(fr__hsub(c, w), fr__hadd(c, w));
    rp = fr__hdiv(fr__hsub(e2c, w), fr__hadd(e2c, w));
    return fr__hunit(fr__hmul(fr__hc(0.5f), fr__hadd(fr__hmul(rs, rs), fr__hmul(rp, rp))));
}

#else
typedef int fr__exact_f16_disabled;
#endif
