/* The approximate conductor form in fixed point (fresnel_q15.h), in its
 * transmittance form: 1 - rs = 4nc / (N + 2nc + c^2), 1 - rp = 4nc / (N c^2 +
 * 2nc + 1), N = n^2 + k^2 (expand the numerators and denominators of
 * fresnel_approx_conductor: they differ only in the sign of 2nc). Sums of
 * positive terms only, so qf keeps ~30 bits and only the final rounding
 * shows. */
#include "internal.h"

#if FRESNEL_HAS_Q15

fresnel_q15 fresnel_approx_conductor_q15(const fresnel_nk_prep_q15 *m, int32_t c_in)
{
    uint32_t c = fresnel_i_q15_arg(c_in);
    fresnel_qf one = fresnel_i_qf_one(), cq, c2q, nc2, ts, tp;
    if (c == 0 || m->n.m == 0)
        return FRESNEL_I_ONE_Q15; /* 4nc = 0: rs = rp = 1 */
    cq = fresnel_i_qf(c, -15);
    c2q = fresnel_i_qf(c * c, -30); /* R: <= 2^30, exact */
    nc2 = fresnel_i_qf_scale(fresnel_i_qf_mul(m->n, cq), 1); /* 2nc */
    ts = fresnel_i_qf_div(fresnel_i_qf_scale(nc2, 1), fresnel_i_qf_add(fresnel_i_qf_add(m->nk2, nc2), c2q));
    tp = fresnel_i_qf_div(fresnel_i_qf_scale(nc2, 1), fresnel_i_qf_add(fresnel_i_qf_add(fresnel_i_qf_mul(m->nk2, c2q), nc2), one));
    /* F = 1 - (ts + tp)/2 */
    return fresnel_i_q30_to_q15(FRESNEL_I_ONE_Q30 - fresnel_i_qf_to_q30_unit(fresnel_i_qf_scale(fresnel_i_qf_add(ts, tp), -1)));
}

fresnel_rgb_q15 fresnel_approx_conductor_q15_rgb(const fresnel_nk_prep_q15 m[3], int32_t c)
{
    FRESNEL_I_RGB_Q15(fresnel_approx_conductor_q15(&m[0], c), fresnel_approx_conductor_q15(&m[1], c),
                fresnel_approx_conductor_q15(&m[2], c));
}

fresnel_nk_prep_q15 fresnel_nk_prepare_q15(fresnel_q16 eta_in, fresnel_q16 kappa_in)
{
    fresnel_nk_prep_q15 m;
    fresnel_nk_prep_q15 *out = &m;
    fresnel_q16 n_in = eta_in, k_in = kappa_in;
    fresnel_qf n = fresnel_i_qf(n_in <= FRESNEL_ETA_MIN_Q16 ? (uint32_t)FRESNEL_ETA_MIN_Q16 : (uint32_t)n_in, -16);
    fresnel_qf k = fresnel_i_qf(k_in <= 0 ? 0u : (uint32_t)k_in, -16);
    out->n = n;
    out->nk2 = fresnel_i_qf_add(fresnel_i_qf_mul(n, n), fresnel_i_qf_mul(k, k));
    return m;
}

#else
typedef int fresnel_i_approx_conductor_q15_disabled;
#endif
