/* The exact Fresnel equations in fixed point (fresnel_q15.h).
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
 * sin^2 near a critical angle (a dielectric, or a conductor with kappa << 1):
 * there the reflectance's slope is unbounded, so A is carried in two words,
 * a0 + c^2 exact to 2^-60 of its scale (fresnel_i_a_qf). */
#include "internal.h"

#if FRESNEL_HAS_Q15

/* The prepared shift, held to the layout's [0, 30] so that a corrupt
 * constant cannot make a shift count undefined. */
static uint32_t fresnel_i_shift(const fresnel_ior_prep_q15 *m)
{
    FRESNEL_I_RANGE("ior shift", m->shift, 0, 30);
    return m->shift <= 0 ? 0u : (m->shift >= 30 ? 30u : (uint32_t)m->shift);
}

static uint32_t fresnel_i_mag(int32_t x) { return x < 0 ? 0u - (uint32_t)x : (uint32_t)x; }

/* |A| and its sign, A = eta^2 - kappa^2 - sin^2 = a0 + c^2. At the prepared
 * scale 2^-(30 - s),
 *   A = (a0 + floor(c^2 / 2^s)) + (a0_lo + (c^2 mod 2^s) 2^(30 - s)) 2^-30:
 * the high word is an exact int32 sum (R: |a0| + 2^(30-s) <= 2^31 - 1 by the
 * layout, c^2 >> s <= 2^(30-s)); the low word is in units of 2^-30 of the
 * high word's unit (R: |a0_lo| <= 2^29, (c^2 mod 2^s) 2^(30-s) < 2^30). Both
 * sums are formed in uint32, so a constant outside the layout wraps rather
 * than overflowing a signed int. */
fresnel_qf fresnel_i_a_qf(const fresnel_ior_prep_q15 *m, uint32_t c, int *negative)
{
    uint32_t s = fresnel_i_shift(m), c2 = c * c; /* R: c^2 <= 2^30, exact */
    int32_t hi = (int32_t)((uint32_t)m->a0 + (c2 >> s));
    int32_t lo = (int32_t)((uint32_t)m->a0_lo + ((c2 & ((1u << s) - 1u)) << (30u - s)));
    fresnel_qf qh = fresnel_i_qf(fresnel_i_mag(hi), (int32_t)s - 30), ql = fresnel_i_qf(fresnel_i_mag(lo), (int32_t)s - 60);
    int below;
    FRESNEL_I_RANGE("exact a0_lo", m->a0_lo, -(1 << 29), 1 << 29);
    if ((hi < 0) == (lo < 0) || hi == 0 || lo == 0) {
        *negative = hi < 0 || (hi == 0 && lo < 0);
        return fresnel_i_qf_add(qh, ql);
    }
    /* opposite signs: |lo| 2^-30 < 2 units of hi, so hi's sign wins unless
     * hi is +-1 and the difference crosses zero */
    qh = fresnel_i_qf_sub(qh, ql, &below);
    *negative = (hi < 0) != (below != 0);
    return qh;
}

/* Ts + Tp (= 2 T) as qf, and 0 under total internal reflection (u = 0). */
static fresnel_qf fresnel_i_two_t(const fresnel_ior_prep_q15 *m, uint32_t c)
{
    int a_negative;
    fresnel_qf aq = fresnel_i_a_qf(m, c, &a_negative);
    fresnel_qf mq, big, u, cq, c2q, cu, ts, tp, q;
    if (c == 0)
        return fresnel_i_qf(0, 0); /* 4cu = 0: grazing incidence reflects everything */
    /* m = |w|^2 = sqrt(A^2 + b^2); big = sqrt((m + |A|)/2) is u for A >= 0
     * and v for A < 0; the other is b / (2 big) (u v = eta kappa = b/2). */
    if (m->b.m == 0) {
        if (a_negative)
            return fresnel_i_qf(0, 0); /* dielectric past the critical angle: u = 0 */
        mq = aq;
        u = fresnel_i_qf_sqrt(aq);
    } else {
        mq = fresnel_i_qf_sqrt(fresnel_i_qf_add(fresnel_i_qf_mul(aq, aq), fresnel_i_qf_mul(m->b, m->b)));
        big = fresnel_i_qf_sqrt(fresnel_i_qf_scale(fresnel_i_qf_add(mq, aq), -1));
        u = a_negative ? fresnel_i_qf_scale(fresnel_i_qf_div(m->b, big), -1) : big;
    }
    if (u.m == 0)
        return u; /* A = 0 with b = 0: exactly at the critical angle */
    cq = fresnel_i_qf(c, -15);
    c2q = fresnel_i_qf(c * c, -30);
    cu = fresnel_i_qf_mul(cq, u);
    ts = fresnel_i_qf_div(fresnel_i_qf_scale(cu, 2), fresnel_i_qf_add(fresnel_i_qf_add(c2q, fresnel_i_qf_scale(cu, 1)), mq));
    /* q = c u (m + s^2), s^2 = 1 - c^2 exact in Q30 */
    q = fresnel_i_qf_mul(cu, fresnel_i_qf_add(mq, fresnel_i_qf(FRESNEL_I_ONE_Q30 - c * c, -30)));
    tp = fresnel_i_qf_div(fresnel_i_qf_scale(q, 2),
                    fresnel_i_qf_add(fresnel_i_qf_add(fresnel_i_qf_mul(m->n4, c2q), fresnel_i_qf_scale(q, 1)), mq));
    return fresnel_i_qf_add(ts, tp);
}

/* 1 - (Ts + Tp)/2 in Q30, rounded to Q15. */
static fresnel_q15 fresnel_i_reflectance(fresnel_qf two_t)
{
    return fresnel_i_q30_to_q15(FRESNEL_I_ONE_Q30 - fresnel_i_qf_to_q30_unit(fresnel_i_qf_scale(two_t, -1)));
}

static int fresnel_i_matched(const fresnel_ior_prep_q15 *m) { return m->a0 == 0 && m->a0_lo == 0 && m->b.m == 0; }

fresnel_q15 fresnel_conductor_q15(const fresnel_ior_prep_q15 *m, int32_t c)
{
    if (fresnel_i_matched(m))
        return 0; /* no interface: nothing reflected at any c, as fresnel_conductor */
    return fresnel_i_reflectance(fresnel_i_two_t(m, fresnel_i_q15_arg(c)));
}

fresnel_rgb_q15 fresnel_conductor_q15_rgb(const fresnel_ior_prep_q15 m[3], int32_t c)
{
    FRESNEL_I_RGB_Q15(fresnel_conductor_q15(&m[0], c), fresnel_conductor_q15(&m[1], c),
                fresnel_conductor_q15(&m[2], c));
}

/* The dielectric special case (b = 0): m = A, w = u = sqrt(A), and with
 * P = eta^2 c the two transmittances reduce to 4cu/(c+u)^2 and 4Pu/(P+u)^2. */
fresnel_q15 fresnel_dielectric_q15(const fresnel_ior_prep_q15 *m, int32_t c_in)
{
    uint32_t c = fresnel_i_q15_arg(c_in);
    int a_negative, e2_negative;
    fresnel_qf aq, u, cq, p, ts, tp;
    if (m->b.m != 0)
        return fresnel_conductor_q15(m, c_in); /* not a dielectric after all */
    if (fresnel_i_matched(m))
        return 0;
    aq = fresnel_i_a_qf(m, c, &a_negative);
    if (a_negative || aq.m == 0 || c == 0)
        return FRESNEL_I_ONE_Q15; /* total internal reflection, or grazing */
    u = fresnel_i_qf_sqrt(aq);
    cq = fresnel_i_qf(c, -15);
    /* eta^2 = A at c = 1, both words: for eta -> 0 the high word a0 + 1
     * keeps only log2(eta^2 2^30) bits (17 at eta = 0.01), and P's relative
     * error shows in the result near normal incidence. */
    p = fresnel_i_qf_mul(fresnel_i_a_qf(m, FRESNEL_I_ONE_Q15, &e2_negative), cq);
    ts = fresnel_i_qf_add(cq, u);
    ts = fresnel_i_qf_div(fresnel_i_qf_scale(fresnel_i_qf_mul(cq, u), 2), fresnel_i_qf_mul(ts, ts));
    tp = fresnel_i_qf_add(p, u);
    tp = fresnel_i_qf_div(fresnel_i_qf_scale(fresnel_i_qf_mul(p, u), 2), fresnel_i_qf_mul(tp, tp));
    return fresnel_i_reflectance(fresnel_i_qf_add(ts, tp));
}

fresnel_qf fresnel_i_conductor_transmittance_q15(const fresnel_ior_prep_q15 *m, uint32_t c)
{
    if (fresnel_i_matched(m))
        return fresnel_i_qf_one();
    return fresnel_i_qf_scale(fresnel_i_two_t(m, c), -1);
}

/* a b as two 32-bit words, from 16-bit halves. R: each partial product
 * < 2^32; mid < 3 2^16. */
static void fresnel_i_mul_wide(uint32_t a, uint32_t b, uint32_t *hi, uint32_t *lo)
{
    uint32_t al = a & 0xffffu, ah = a >> 16, bl = b & 0xffffu, bh = b >> 16;
    uint32_t ll = al * bl, lh = al * bh, hl = ah * bl;
    uint32_t mid = (ll >> 16) + (lh & 0xffffu) + (hl & 0xffffu);
    *lo = (ll & 0xffffu) | (mid << 16);
    *hi = ah * bh + (lh >> 16) + (hl >> 16) + (mid >> 16);
}

/* From Q16.16: V = (eta^2 - kappa^2 - 1) 2^32 = +-(eta - 1)(eta + 1) - kappa^2,
 * exactly, in two words (R: |eta - 1| < 2^31, eta + 1 < 2^32, kappa < 2^31:
 * both products < 2^63, their difference too). Then the layout's a0, a0_lo
 * and shift from V exactly, and the other constants in qf. */
fresnel_ior_prep_q15 fresnel_ior_prepare_q15(fresnel_q16 eta_in, fresnel_q16 kappa_in)
{
    fresnel_ior_prep_q15 m;
    fresnel_ior_prep_q15 *out = &m;
    uint32_t eta = eta_in <= FRESNEL_ETA_MIN_Q16 ? (uint32_t)FRESNEL_ETA_MIN_Q16 : (uint32_t)eta_in;
    uint32_t kappa = kappa_in <= 0 ? 0u : (uint32_t)kappa_in;
    uint32_t em1 = eta >= 65536u ? eta - 65536u : 65536u - eta;
    uint32_t ph, pl, kh, kl, vh, vl;
    int neg;
    int32_t s;
    fresnel_qf e = fresnel_i_qf(eta, -16), k = fresnel_i_qf(kappa, -16), one = fresnel_i_qf_one();
    fresnel_qf ep1 = fresnel_i_qf(eta + 65536u, -16); /* R: < 2^31 + 2^16, unsigned */
    fresnel_qf k2 = fresnel_i_qf_mul(k, k), e2 = fresnel_i_qf_mul(e, e);
    fresnel_i_mul_wide(em1, eta + 65536u, &ph, &pl);
    fresnel_i_mul_wide(kappa, kappa, &kh, &kl);
    if (eta < 65536u) { /* V = -(P + K) */
        vl = pl + kl;
        vh = ph + kh + (vl < pl);
        neg = 1;
    } else if (ph > kh || (ph == kh && pl >= kl)) { /* V = P - K >= 0 */
        vl = pl - kl;
        vh = ph - kh - (pl < kl);
        neg = 0;
    } else { /* V = -(K - P) */
        vl = kl - pl;
        vh = kh - ph - (kl < pl);
        neg = 1;
    }
    /* a0 2^(30-s) = V / 2^(2+s): take the smallest s whose rounded quotient
     * q leaves room for c^2, q + 2^(30-s) <= 2^31 - 1 (the layout) */
    for (s = 0; s <= 30; s++) {
        uint32_t k_bits = (uint32_t)s + 2u, q, low, half;
        int32_t r;
        if (k_bits < 32u && (vh >> k_bits) != 0)
            continue; /* quotient above 32 bits */
        q = k_bits == 32u ? vh : (vh << (32u - k_bits)) | (vl >> k_bits);
        if (q > 0x7fffffffu - (1u << (30u - (uint32_t)s)))
            continue; /* also before rounding: 0xffffffff would round to 0 */
        low = k_bits == 32u ? vl : vl & ((1u << k_bits) - 1u);
        half = 1u << (k_bits - 1u);
        if (low >= half) { /* round up; the remainder goes negative */
            q++;
            r = -(int32_t)((k_bits == 32u ? 0xffffffffu : (1u << k_bits) - 1u) - low) - 1;
        } else {
            r = (int32_t)low;
        }
        if (q > 0x7fffffffu - (1u << (30u - (uint32_t)s)))
            continue;
        /* a0_lo = r 2^30 / 2^(2+s) = r 2^(28-s); R: |r| <= 2^(1+s), so |a0_lo| <= 2^29 */
        if (s <= 28) {
            r *= (int32_t)(1u << (28u - (uint32_t)s));
        } else {
            uint32_t sh = (uint32_t)s - 28u, mag = fresnel_i_mag(r);
            mag = (mag + (1u << (sh - 1u))) >> sh;
            r = r < 0 ? -(int32_t)mag : (int32_t)mag;
        }
        out->a0 = neg ? -(int32_t)q : (int32_t)q;
        out->a0_lo = neg ? -r : r;
        out->shift = s;
        break;
    }
    if (s > 30) { /* outside the domain (eta or kappa above ~46000): saturate */
        out->shift = 30;
        out->a0 = neg ? -0x7fffffff + 1 : 0x7fffffff - 1;
        out->a0_lo = 0;
    }
    out->b = fresnel_i_qf_scale(fresnel_i_qf_mul(e, k), 1);
    out->n4 = fresnel_i_qf_add(e2, k2);
    out->n4 = fresnel_i_qf_mul(out->n4, out->n4);
    out->t1_inv = fresnel_i_qf_div(fresnel_i_qf_add(fresnel_i_qf_mul(ep1, ep1), k2), fresnel_i_qf_scale(e, 2));
    out->inv_eta2 = fresnel_i_qf_div(one, e2);
    return m;
}

#else
typedef int fresnel_i_exact_q15_disabled;
#endif
