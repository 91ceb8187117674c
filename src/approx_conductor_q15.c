/* The approximate conductor form in fixed point (fresnel_fixed.h), in its
 * transmittance form: 1 - rs = 4nc / (N + 2nc + c^2), 1 - rp = 4nc / (N c^2 +
 * 2nc + 1), N = n^2 + k^2 (expand the numerators and denominators of
 * fresnel_approx_conductor: they differ only in the sign of 2nc). */
#include "fixed_internal.h"

#if FRESNEL_HAS_FIXED

fresnel_q15 fresnel_approx_conductor_q15(const fresnel_q15_nk *m, int32_t c_in)
{
    uint32_t c = fr__q15_arg(c_in);
    fresnel_qf one = fr__qf_one(), cq, c2q, nc2, ts, tp;
    if (c == 0 || m->n.m == 0)
        return FR__ONE_Q15; /* 4nc = 0: rs = rp = 1 */
    cq = fr__qf(c, -15);
    c2q = fr__qf(c * c, -30); /* R: <= 2^30, exact */
    nc2 = fr__qf_scale(fr__qf_mul(m->n, cq), 1); /* 2nc */
    ts = fr__qf_div(fr__qf_scale(nc2, 1), fr__qf_add(fr__qf_add(m->nk2, nc2), c2q));
    tp = fr__qf_div(fr__qf_scale(nc2, 1), fr__qf_add(fr__qf_add(fr__qf_mul(m->nk2, c2q), nc2), one));
    /* F = 1 - (ts + tp)/2 */
    return fr__q30_to_q15(FR__ONE_Q30 - fr__qf_to_q30_unit(fr__qf_scale(fr__qf_add(ts, tp), -1)));
}

fresnel_q15_rgb fresnel_approx_conductor_q15_rgb(const fresnel_q15_nk m[3], int32_t c)
{
    FR__RGB_Q15(fresnel_approx_conductor_q15(&m[0], c), fresnel_approx_conductor_q15(&m[1], c),
                fresnel_approx_conductor_q15(&m[2], c));
}

void fresnel_q15_nk_prepare(fresnel_q16 n_in, fresnel_q16 k_in, fresnel_q15_nk *out)
{
    fresnel_qf n = fr__qf(n_in <= FRESNEL_Q16_ETA_MIN ? (uint32_t)FRESNEL_Q16_ETA_MIN : (uint32_t)n_in, -16);
    fresnel_qf k = fr__qf(k_in <= 0 ? 0u : (uint32_t)k_in, -16);
    out->n = n;
    out->nk2 = fr__qf_add(fr__qf_mul(n, n), fr__qf_mul(k, k));
}

#else
typedef int fr__approx_conductor_q15_disabled;
#endif
