/* The exact Fresnel equations in fixed point (fresnel_fixed.h).
 *
 * The binary32 code (exact.c) avoids cancellation by computing the smaller of
 * u^2, v^2 from u v = eta kappa and writing numerators as sums of squares of
 * differences. Here one more step removes the differences altogether: with
 * w = u + iv = sqrt(z^2 - s^2), z = eta + i kappa, m = |w|^2, s^2 = 1 - c^2,
 *   |c + w|^2 - |c - w|^2 = 4 c u,
 *   |z^2 c + w|^2 - |z^2 c - w|^2 = 4 c Re(z^2 conj w) = 4 c u (m + s^2)
 * (because Re(z^2 conj w) = (eta^2 - kappa^2) u + 2 eta kappa v and
 * u^2 - v^2 = eta^2 - kappa^2 - s^2, u v = eta kappa), so the transmittances
 *   Ts = 4cu / (c^2 + 2cu + m),
 *   Tp = 4cu (m + s^2) / (|z|^4 c^2 + 2cu (m + s^2) + m)
 * are ratios of sums of non-negative terms, which fresnel_qf evaluates to
 * ~29 bits, and F = 1 - (Ts + Tp)/2 loses nothing in the subtraction that the
 * Q15 result could show. The one true cancellation is A = eta^2 - kappa^2 -
 * sin^2 near a dielectric's critical angle; A = a0 + c^2 is exact there
 * (shift 0, c^2 exact in Q30). */
#include "fixed_internal.h"

#if FRESNEL_HAS_FIXED

/* A = a0 + c^2 at the prepared scale 2^-(30 - shift).
 * R: |a0| < 2^31 - 2^(30-shift) (prepared layout) and c^2 >> shift <= 2^(30-shift):
 * A fits int32. */
static int32_t fr__a(const fresnel_q15_ior *m, uint32_t c)
{
    uint32_t c2 = c * c; /* R: <= 2^30, exact */
    FR__RANGE("ior shift", m->shift, 0, 30);
    return m->a0 + (int32_t)(m->shift ? (c2 + (1u << (m->shift - 1))) >> m->shift : c2);
}

/* Ts + Tp (= 2 T) as qf, and 0 under total internal reflection (u = 0). */
static fresnel_qf fr__two_t(const fresnel_q15_ior *m, uint32_t c)
{
    int32_t a = fr__a(m, c);
    uint32_t abs_a = a < 0 ? (uint32_t)0 - (uint32_t)a : (uint32_t)a;
    FR__RANGE("exact |A| fits int32", abs_a, 0, 0x7fffffffu);
    fresnel_qf aq = fr__qf(abs_a, m->shift - 30);
    fresnel_qf mq, big, u, cq, c2q, cu, ts, tp, q;
    if (c == 0)
        return fr__qf(0, 0); /* 4cu = 0: grazing incidence reflects everything */
    /* m = |w|^2 = sqrt(A^2 + b^2); big = sqrt((m + |A|)/2) is u for A >= 0
     * and v for A < 0; the other is b / (2 big) (u v = eta kappa = b/2). */
    if (m->b.m == 0) {
        if (a < 0)
            return fr__qf(0, 0); /* dielectric past the critical angle: u = 0 */
        mq = aq;
        u = fr__qf_sqrt(aq);
    } else {
        mq = fr__qf_sqrt(fr__qf_add(fr__qf_mul(aq, aq), fr__qf_mul(m->b, m->b)));
        big = fr__qf_sqrt(fr__qf_scale(fr__qf_add(mq, aq), -1));
        u = a >= 0 ? big : fr__qf_scale(fr__qf_div(m->b, big), -1);
    }
    if (u.m == 0)
        return u; /* A = 0 with b = 0: exactly at the critical angle */
    cq = fr__qf(c, -15);
    c2q = fr__qf(c * c, -30);
    cu = fr__qf_mul(cq, u);
    ts = fr__qf_div(fr__qf_scale(cu, 2), fr__qf_add(fr__qf_add(c2q, fr__qf_scale(cu, 1)), mq));
    /* q = c u (m + s^2), s^2 = 1 - c^2 exact in Q30 */
    q = fr__qf_mul(cu, fr__qf_add(mq, fr__qf(FR__ONE_Q30 - c * c, -30)));
    tp = fr__qf_div(fr__qf_scale(q, 2),
                    fr__qf_add(fr__qf_add(fr__qf_mul(m->n4, c2q), fr__qf_scale(q, 1)), mq));
    return fr__qf_add(ts, tp);
}

/* 1 - (Ts + Tp)/2 in Q30, rounded to Q15. */
static fresnel_q15 fr__reflectance(fresnel_qf two_t)
{
    return fr__q30_to_q15(FR__ONE_Q30 - fr__qf_to_q30_unit(fr__qf_scale(two_t, -1)));
}

static int fr__matched(const fresnel_q15_ior *m) { return m->a0 == 0 && m->b.m == 0; }

fresnel_q15 fresnel_conductor_q15(const fresnel_q15_ior *m, int32_t c)
{
    if (fr__matched(m))
        return 0; /* no interface: nothing reflected at any c, as fresnel_conductor */
    return fr__reflectance(fr__two_t(m, fr__q15_arg(c)));
}

fresnel_q15_rgb fresnel_conductor_q15_rgb(const fresnel_q15_ior m[3], int32_t c)
{
    FR__RGB_Q15(fresnel_conductor_q15(&m[0], c), fresnel_conductor_q15(&m[1], c),
                fresnel_conductor_q15(&m[2], c));
}

/* The dielectric special case (b = 0): m = A, w = u = sqrt(A), and with
 * P = eta^2 c the two transmittances reduce to 4cu/(c+u)^2 and 4Pu/(P+u)^2. */
fresnel_q15 fresnel_dielectric_q15(const fresnel_q15_ior *m, int32_t c_in)
{
    uint32_t c = fr__q15_arg(c_in);
    int32_t a;
    fresnel_qf u, cq, p, ts, tp;
    if (m->b.m != 0)
        return fresnel_conductor_q15(m, c_in); /* not a dielectric after all */
    if (m->a0 == 0)
        return 0; /* matched index */
    a = fr__a(m, c);
    if (a <= 0 || c == 0)
        return FR__ONE_Q15; /* total internal reflection, or grazing */
    u = fr__qf_sqrt(fr__qf((uint32_t)a, m->shift - 30));
    cq = fr__qf(c, -15);
    /* eta^2 = a0 + 1 at the prepared scale. R: a0 + 2^(30-shift) in (0, 2^31) */
    p = fr__qf_mul(fr__qf((uint32_t)(m->a0 + (int32_t)(1u << (30 - m->shift))), m->shift - 30), cq);
    ts = fr__qf_add(cq, u);
    ts = fr__qf_div(fr__qf_scale(fr__qf_mul(cq, u), 2), fr__qf_mul(ts, ts));
    tp = fr__qf_add(p, u);
    tp = fr__qf_div(fr__qf_scale(fr__qf_mul(p, u), 2), fr__qf_mul(tp, tp));
    return fr__reflectance(fr__qf_add(ts, tp));
}

fresnel_qf fr__conductor_transmittance_q15(const fresnel_q15_ior *m, uint32_t c)
{
    if (fr__matched(m))
        return fr__qf_one();
    return fr__qf_scale(fr__two_t(m, c), -1);
}

/* From Q16.16: eta^2 - kappa^2 - 1 = (eta - 1)(eta + 1) - kappa^2, each
 * factor exact in Q16.16, so the cancellation near eta = 1 costs nothing
 * beyond the 2^-29 relative rounding of the two products. */
void fresnel_q15_ior_prepare(fresnel_q16 eta_in, fresnel_q16 kappa_in, fresnel_q15_ior *out)
{
    uint32_t eta = eta_in <= FRESNEL_Q16_ETA_MIN ? (uint32_t)FRESNEL_Q16_ETA_MIN : (uint32_t)eta_in;
    uint32_t kappa = kappa_in <= 0 ? 0u : (uint32_t)kappa_in;
    uint32_t em1 = eta >= 65536u ? eta - 65536u : 65536u - eta;
    fresnel_qf e = fr__qf(eta, -16), k = fr__qf(kappa, -16), one = fr__qf_one();
    fresnel_qf ep1 = fr__qf(eta + 65536u, -16); /* R: < 2^31 + 2^16, unsigned */
    fresnel_qf k2 = fr__qf_mul(k, k), e2 = fr__qf_mul(e, e);
    fresnel_qf prod = fr__qf_mul(fr__qf(em1, -16), ep1);
    fresnel_qf a0, mag1;
    int neg_prod = eta < 65536u, neg = 0;
    int32_t shift;
    /* a0 = +-prod - k2 */
    if (neg_prod) {
        a0 = fr__qf_add(prod, k2);
        neg = a0.m != 0;
    } else {
        a0 = fr__qf_sub(prod, k2, &neg);
    }
    /* smallest shift with |a0| + 1 < 2^(shift+1): |a0| + 1 in [2^(e+30), 2^(e+31)) */
    mag1 = fr__qf_add(a0, one);
    shift = mag1.e + 30;
    if (shift < 0)
        shift = 0;
    if (shift > 30)
        shift = 30; /* outside the domain (eta or kappa above 46340) */
    out->shift = shift;
    {
        uint32_t mag = fr__qf_to_fix(a0, 30 - shift);
        if (mag > 0x7fffffffu)
            mag = 0x7fffffffu;
        out->a0 = neg ? -(int32_t)mag : (int32_t)mag;
    }
    out->b = fr__qf_scale(fr__qf_mul(e, k), 1);
    out->n4 = fr__qf_add(e2, k2);
    out->n4 = fr__qf_mul(out->n4, out->n4);
    out->t1_inv = fr__qf_div(fr__qf_add(fr__qf_mul(ep1, ep1), k2), fr__qf_scale(e, 2));
    out->inv_eta2 = fr__qf_div(one, e2);
}

#else
typedef int fr__exact_q15_disabled;
#endif
