/* The exact Fresnel equations in binary16 (fresnel_f16.h): exact.c's
 * algorithm (smaller of u, v from u v = eta kappa; numerators as sums of
 * squares of differences), with hypot scaled and the p-polarised ratio
 * divided through by max(1, eta^2 + kappa^2) so that nothing exceeds 65504
 * for eta, kappa <= 16. */
#include "internal.h"

#if FRESNEL_HAS_F16

struct fresnel_i_root_h {
    fresnel_i_h u, v, m;
};

static struct fresnel_i_root_h fresnel_i_transmitted_h(fresnel_i_h eta, fresnel_i_h kappa, fresnel_i_h c)
{
    struct fresnel_i_root_h w;
    fresnel_i_h one = fresnel_i_hc(1.0f), half = fresnel_i_hc(0.5f), zero = fresnel_i_hc(0.0f);
    fresnel_i_h ek = fresnel_i_hmul(eta, kappa);
    /* eta^2 - kappa^2 - sin^2 = ((eta - 1)(eta + 1) + c^2) - kappa^2 */
    fresnel_i_h a = fresnel_i_hsub(fresnel_i_hadd(fresnel_i_hmul(fresnel_i_hsub(eta, one), fresnel_i_hadd(eta, one)), fresnel_i_hmul(c, c)), fresnel_i_hmul(kappa, kappa));
    fresnel_i_h abs_a = a < zero ? fresnel_i_hsub(zero, a) : a;
    w.m = fresnel_i_hhypot(abs_a, fresnel_i_hmul(fresnel_i_hc(2.0f), ek));
    if (a >= zero) {
        w.u = fresnel_i_hsqrt(fresnel_i_hmul(half, fresnel_i_hadd(w.m, a)));
        w.v = w.u > zero ? fresnel_i_hdiv(ek, w.u) : zero;
    } else {
        w.v = fresnel_i_hsqrt(fresnel_i_hmul(half, fresnel_i_hsub(w.m, a)));
        w.u = fresnel_i_hdiv(ek, w.v);
    }
    return w;
}

/* 1 / max(1, eta^2 + kappa^2): the scale of the p-polarised terms */
static fresnel_i_h fresnel_i_pscale(fresnel_i_h eta, fresnel_i_h kappa)
{
    fresnel_i_h n2 = fresnel_i_hadd(fresnel_i_hmul(eta, eta), fresnel_i_hmul(kappa, kappa));
    return n2 > fresnel_i_hc(1.0f) ? fresnel_i_hdiv(fresnel_i_hc(1.0f), n2) : fresnel_i_hc(1.0f);
}

fresnel_f16 fresnel_conductor_f16(fresnel_f16 eta, fresnel_f16 kappa, fresnel_f16 c)
{
    struct fresnel_i_root_h w;
    fresnel_i_h zero = fresnel_i_hc(0.0f), s, p, q, u, v, cu, cmu, pu, qv, pmu, qmv, num_s, den_s, num_p, den_p, rs, rp;
    eta = fresnel_i_heta(eta);
    kappa = fresnel_i_hkappa(kappa);
    c = fresnel_i_hunit(c);
    if (fresnel_i_heq(eta, fresnel_i_hc(1.0f)) && fresnel_i_heq(kappa, zero))
        return zero; /* matched index */
    w = fresnel_i_transmitted_h(eta, kappa, c);
    cu = fresnel_i_hadd(c, w.u);
    cmu = fresnel_i_hsub(c, w.u);
    num_s = fresnel_i_hadd(fresnel_i_hmul(cmu, cmu), fresnel_i_hmul(w.v, w.v));
    den_s = fresnel_i_hadd(fresnel_i_hmul(cu, cu), fresnel_i_hmul(w.v, w.v));
    s = fresnel_i_pscale(eta, kappa);
    /* (eta + i kappa)^2 c = p + i q, and u, v, all times s */
    p = fresnel_i_hmul(fresnel_i_hmul(c, fresnel_i_hmul(fresnel_i_hsub(eta, kappa), fresnel_i_hadd(eta, kappa))), s);
    q = fresnel_i_hmul(fresnel_i_hmul(fresnel_i_hmul(fresnel_i_hc(2.0f), fresnel_i_hmul(eta, kappa)), c), s);
    u = fresnel_i_hmul(w.u, s);
    v = fresnel_i_hmul(w.v, s);
    pu = fresnel_i_hadd(p, u);
    qv = fresnel_i_hadd(q, v);
    pmu = fresnel_i_hsub(p, u);
    qmv = fresnel_i_hsub(q, v);
    num_p = fresnel_i_hadd(fresnel_i_hmul(pmu, pmu), fresnel_i_hmul(qmv, qmv));
    den_p = fresnel_i_hadd(fresnel_i_hmul(pu, pu), fresnel_i_hmul(qv, qv));
    rs = den_s > zero ? fresnel_i_hdiv(num_s, den_s) : zero;
    rp = den_p > zero ? fresnel_i_hdiv(num_p, den_p) : zero;
    return fresnel_i_hunit(fresnel_i_hmul(fresnel_i_hc(0.5f), fresnel_i_hadd(rs, rp)));
}

fresnel_i_h fresnel_i_conductor_transmittance_h(fresnel_i_h eta, fresnel_i_h kappa, fresnel_i_h c)
{
    /* 1 - Rs = 4cu / den_s, 1 - Rp = 4 c u (m + s^2) / den_p (exact.c) */
    struct fresnel_i_root_h w;
    fresnel_i_h zero = fresnel_i_hc(0.0f), one = fresnel_i_hc(1.0f), s, p, q, s2, cu, pu, qv, den_s, den_p, ts, tp, four_cu;
    eta = fresnel_i_heta(eta);
    kappa = fresnel_i_hkappa(kappa);
    c = fresnel_i_hunit(c);
    if (fresnel_i_heq(eta, one) && fresnel_i_heq(kappa, zero))
        return one;
    w = fresnel_i_transmitted_h(eta, kappa, c);
    s = fresnel_i_pscale(eta, kappa);
    p = fresnel_i_hmul(fresnel_i_hmul(c, fresnel_i_hmul(fresnel_i_hsub(eta, kappa), fresnel_i_hadd(eta, kappa))), s);
    q = fresnel_i_hmul(fresnel_i_hmul(fresnel_i_hmul(fresnel_i_hc(2.0f), fresnel_i_hmul(eta, kappa)), c), s);
    s2 = fresnel_i_hmul(fresnel_i_hsub(one, c), fresnel_i_hadd(one, c));
    cu = fresnel_i_hadd(c, w.u);
    den_s = fresnel_i_hadd(fresnel_i_hmul(cu, cu), fresnel_i_hmul(w.v, w.v));
    pu = fresnel_i_hadd(p, fresnel_i_hmul(w.u, s));
    qv = fresnel_i_hadd(q, fresnel_i_hmul(w.v, s));
    den_p = fresnel_i_hadd(fresnel_i_hmul(pu, pu), fresnel_i_hmul(qv, qv));
    four_cu = fresnel_i_hmul(fresnel_i_hmul(fresnel_i_hc(4.0f), c), w.u);
    ts = den_s > zero ? fresnel_i_hdiv(four_cu, den_s) : one;
    /* 4cu (m + s^2) s^2 / den_p as 4cu (((m + s^2) s) s / den_p): for a
     * small eta under a large kappa, 4cu s (u ~ eta, s ~ 1/kappa^2) falls
     * among binary16's subnormals (below 2^-14, spacing 2^-24) near grazing
     * incidence, a 1-2% error in T; (m + s^2) s s and den_p stay normal. */
    tp = den_p > zero ? fresnel_i_hmul(four_cu, fresnel_i_hdiv(fresnel_i_hmul(fresnel_i_hmul(fresnel_i_hadd(w.m, s2), s), s), den_p)) : one;
    return fresnel_i_hunit(fresnel_i_hmul(fresnel_i_hc(0.5f), fresnel_i_hadd(ts, tp)));
}

fresnel_f16 fresnel_dielectric_f16(fresnel_f16 eta, fresnel_f16 c)
{
    fresnel_i_h one = fresnel_i_hc(1.0f), zero = fresnel_i_hc(0.0f), a, w, e2c, rs, rp;
    eta = fresnel_i_heta(eta);
    c = fresnel_i_hunit(c);
    if (fresnel_i_heq(eta, one))
        return zero;
    a = fresnel_i_hadd(fresnel_i_hmul(fresnel_i_hsub(eta, one), fresnel_i_hadd(eta, one)), fresnel_i_hmul(c, c));
    if (a < zero)
        return one; /* total internal reflection */
    w = fresnel_i_hsqrt(a);
    e2c = fresnel_i_hmul(fresnel_i_hmul(eta, eta), c);
    rs = fresnel_i_hdiv(fresnel_i_hsub(c, w), fresnel_i_hadd(c, w));
    rp = fresnel_i_hdiv(fresnel_i_hsub(e2c, w), fresnel_i_hadd(e2c, w));
    return fresnel_i_hunit(fresnel_i_hmul(fresnel_i_hc(0.5f), fresnel_i_hadd(fresnel_i_hmul(rs, rs), fresnel_i_hmul(rp, rp))));
}

#else
typedef int fresnel_i_exact_f16_disabled;
#endif
