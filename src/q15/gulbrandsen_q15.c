/* Gulbrandsen's edge tint in fixed point (fresnel_q15.h), in fresnel_qf,
 * with nmax in gulbrandsen.c's form and k^2 as a sum of positive terms:
 *   k^2 = q (q + 4 (1-g) sqrt(r) nmax / (1-r)),  q = 2 g sqrt(r) / (1+r),
 * gulbrandsen.c's factored k^2 with its last difference (sqrt r (n+1) + n - 1,
 * which cancels as r -> 1, g -> 1) expanded into positive terms. n is
 * clamped below at FRESNEL_ETA_MIN, as fresnel_gulbrandsen does. */
#include "internal.h"

#if FRESNEL_HAS_Q15

/* nmin = (1 - r)/(1 + r) and nmax = (1 + sqrt r)^2 / (1 - r) (the form that
 * keeps its digits as r -> 1), for r < 1 as qf with 1 - r given exactly. */
static void fresnel_i_nmin_nmax(fresnel_qf sr, fresnel_qf omr, fresnel_qf opr, fresnel_qf *nmin, fresnel_qf *nmax)
{
    fresnel_qf ops = fresnel_i_qf_add(fresnel_i_qf_one(), sr);
    *nmin = fresnel_i_qf_div(omr, opr);
    *nmax = fresnel_i_qf_div(fresnel_i_qf_mul(ops, ops), omr);
}

fresnel_nk_prep_q15 fresnel_gulbrandsen_nk_q15(int32_t r_in, int32_t g_in)
{
    fresnel_nk_prep_q15 m;
    fresnel_nk_prep_q15 *out = &m;
    /* k^2 = g (nmax - nmin)(sqrt r (n+1) + n - 1) / (1 + sqrt r) still
     * subtracts 1 from a sum near 1 when r -> 1 and g -> 1 (silver: the
     * difference is 6e-5 of its terms at r = 0.99988). The last factor is
     * linear in n and n is linear in g, so with s = sqrt r it is the sum of
     * its values at the two ends, g 2s(1-s)/(1+r) + (1-g) 4s/(1-s); with
     * nmax - nmin = 2s(1+s) / ((1-s)(1+r)) all of k^2 becomes
     *   k^2 = q (q + 4 (1-g) s nmax / (1-r)),  q = 2 g s / (1+r),
     * products and sums of positive terms. */
    uint32_t r = fresnel_i_q15_arg(r_in), g = fresnel_i_q15_arg(g_in);
    fresnel_qf s, omr, opr, nmin, nmax, gq, omg, q, k2;
    if (r > FRESNEL_GULBRANDSEN_R_MAX_Q15)
        r = FRESNEL_GULBRANDSEN_R_MAX_Q15;
    s = fresnel_i_qf_sqrt(fresnel_i_qf(r, -15));
    /* R: 1 - r >= 4 and 1 + r < 2^16 in Q15, both exact */
    omr = fresnel_i_qf(FRESNEL_I_ONE_Q15 - r, -15);
    opr = fresnel_i_qf(FRESNEL_I_ONE_Q15 + r, -15);
    fresnel_i_nmin_nmax(s, omr, opr, &nmin, &nmax);
    gq = fresnel_i_qf(g, -15);
    omg = fresnel_i_qf(FRESNEL_I_ONE_Q15 - g, -15);
    out->n = fresnel_i_qf_add(fresnel_i_qf_mul(gq, nmin), fresnel_i_qf_mul(omg, nmax));
    /* fresnel_gulbrandsen feeds n to fresnel_approx_conductor, which clamps
     * it to fresnel.h's domain; r -> 1 with g = 1 gives n = nmin -> 0, so the
     * same model needs the same clamp (FRESNEL_ETA_MIN = 2^-10, FRESNEL_ETA_MIN_Q16) */
    if (fresnel_i_qf_cmp(out->n, fresnel_i_qf(1u << 30, -40)) < 0)
        out->n = fresnel_i_qf(1u << 30, -40);
    q = fresnel_i_qf_div(fresnel_i_qf_scale(fresnel_i_qf_mul(gq, s), 1), opr);
    k2 = fresnel_i_qf_mul(q, fresnel_i_qf_add(q, fresnel_i_qf_div(fresnel_i_qf_scale(fresnel_i_qf_mul(fresnel_i_qf_mul(omg, s), nmax), 2), omr)));
    out->nk2 = fresnel_i_qf_add(fresnel_i_qf_mul(out->n, out->n), k2);
    return m;
}

fresnel_rg_q15 fresnel_gulbrandsen_rg_q15(fresnel_q16 eta_in, fresnel_q16 kappa_in)
{
    fresnel_rg_q15 rg;
    fresnel_q15 *r_out = &rg.r, *g_out = &rg.g;
    fresnel_q16 n_in = eta_in, k_in = kappa_in;
    /* r = F0 of n + ik; g = (nmax(r) - n) / (nmax(r) - nmin(r)) with r
     * clamped to 0.9999 first, clamped to [0, 1]. */
    uint32_t nn = n_in <= FRESNEL_ETA_MIN_Q16 ? (uint32_t)FRESNEL_ETA_MIN_Q16 : (uint32_t)n_in;
    uint32_t kk = k_in <= 0 ? 0u : (uint32_t)k_in;
    uint32_t em1 = nn >= 65536u ? nn - 65536u : 65536u - nn;
    fresnel_qf one = fresnel_i_qf_one(), n = fresnel_i_qf(nn, -16), k = fresnel_i_qf(kk, -16);
    fresnel_qf d = fresnel_i_qf(em1, -16), s = fresnel_i_qf(nn + 65536u, -16), k2 = fresnel_i_qf_mul(k, k);
    fresnel_qf num = fresnel_i_qf_add(fresnel_i_qf_mul(d, d), k2), den = fresnel_i_qf_add(fresnel_i_qf_mul(s, s), k2);
    fresnel_qf r = fresnel_i_qf_div(num, den), rmax = fresnel_i_qf(2147268900u, -31); /* round(0.9999 2^31) */
    fresnel_qf omr, opr, nmin, nmax, span, above;
    int n_above_nmax;
    *r_out = fresnel_i_q30_to_q15(fresnel_i_qf_to_q30_unit(r));
    if (fresnel_i_qf_cmp(r, rmax) > 0) {
        r = rmax;
        omr = fresnel_i_qf_sub(one, rmax, (int *)0);
    } else {
        /* 1 - r = 4n / ((n+1)^2 + k^2), without cancellation */
        omr = fresnel_i_qf_div(fresnel_i_qf_scale(n, 2), den);
    }
    opr = fresnel_i_qf_add(one, r);
    fresnel_i_nmin_nmax(fresnel_i_qf_sqrt(r), omr, opr, &nmin, &nmax);
    span = fresnel_i_qf_sub(nmax, nmin, (int *)0);
    above = fresnel_i_qf_sub(nmax, n, &n_above_nmax);
    if (span.m == 0 || n_above_nmax) {
        *g_out = 0; /* r = 0 (n 1, k 0) has no edge tint; n beyond nmax neither */
        return rg;
    }
    *g_out = fresnel_i_q30_to_q15(fresnel_i_qf_to_q30_unit(fresnel_i_qf_div(above, span)));
    return rg;
}

fresnel_q15 fresnel_gulbrandsen_q15(int32_t r, int32_t g, int32_t c)
{
    fresnel_nk_prep_q15 nk = fresnel_gulbrandsen_nk_q15(r, g);
    return fresnel_approx_conductor_q15(&nk, c);
}

fresnel_rgb_q15 fresnel_gulbrandsen_q15_rgb(fresnel_rgb_q15 r, fresnel_rgb_q15 g, int32_t c)
{
    FRESNEL_I_RGB_Q15(fresnel_gulbrandsen_q15(r.r, g.r, c), fresnel_gulbrandsen_q15(r.g, g.g, c),
                fresnel_gulbrandsen_q15(r.b, g.b, c));
}

#else
typedef int fresnel_i_gulbrandsen_q15_disabled;
#endif
