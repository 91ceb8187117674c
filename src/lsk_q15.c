/* Lazanyi and Szirmay-Kalos in fixed point (fresnel_fixed.h). The rescaled
 * model is Schlick with F0 = F0(n, k) exactly (fresnel.h), so it is
 * evaluated as Schlick with a 30-bit F0; the compensation term
 * a c (1-c)^alpha is formed in fresnel_qf. */
#include "fixed_internal.h"

#if FRESNEL_HAS_FIXED

/* F0 + (1 - F0) x^5 in Q30 with F0 in Q30.
 * R: f0 <= 2^30; (2^30 - f0) x5 / 2^30 <= 2^30 - f0: the sum is <= 2^30. */
static uint32_t fr__lsk_q30(const fresnel_q15_lsk *m, uint32_t c)
{
    uint32_t f0 = m->f0 > FR__ONE_Q30 ? FR__ONE_Q30 : m->f0;
    uint32_t f = f0 + fr__mul_q30(FR__ONE_Q30 - f0, fr__pow5_q30(FR__ONE_Q15 - c));
    FR__RANGE("lsk F", f, 0, 1u << 30);
    return f;
}

fresnel_q15 fresnel_lsk_q15(const fresnel_q15_lsk *m, int32_t c)
{
    return fr__q30_to_q15(fr__lsk_q30(m, fr__q15_arg(c)));
}

fresnel_q15_rgb fresnel_lsk_q15_rgb(const fresnel_q15_lsk m[3], int32_t c)
{
    FR__RGB_Q15(fresnel_lsk_q15(&m[0], c), fresnel_lsk_q15(&m[1], c), fresnel_lsk_q15(&m[2], c));
}

fresnel_q15 fresnel_lsk_comp_q15(const fresnel_q15_lsk *m, int32_t c_in)
{
    uint32_t c = fr__q15_arg(c_in), lsk = fr__lsk_q30(m, c), comp;
    uint32_t alpha = m->alpha <= 0 ? 0u : (m->alpha >= FRESNEL_Q16_ALPHA_MAX ? (uint32_t)FRESNEL_Q16_ALPHA_MAX : (uint32_t)m->alpha);
    fresnel_qf term;
    if (m->a.m == 0 || c == 0)
        return fr__q30_to_q15(lsk);
    term = fr__qf_mul(m->a, fr__qf(c, -15));
    if (alpha)
        term = fr__qf_mul(term, fr__pow_q15(FR__ONE_Q15 - c, alpha));
    comp = fr__qf_to_fix(term, 30); /* saturates: a term above 4 clamps the result to 0 anyway */
    return comp >= lsk ? (fresnel_q15)0 : fr__q30_to_q15(lsk - comp);
}

fresnel_q15_rgb fresnel_lsk_comp_q15_rgb(const fresnel_q15_lsk m[3], int32_t c)
{
    FR__RGB_Q15(fresnel_lsk_comp_q15(&m[0], c), fresnel_lsk_comp_q15(&m[1], c),
                fresnel_lsk_comp_q15(&m[2], c));
}

void fresnel_q15_lsk_prepare(fresnel_q16 n_in, fresnel_q16 k_in, fresnel_q16 a, fresnel_q16 alpha,
                             fresnel_q15_lsk *out)
{
    uint32_t n = n_in <= FRESNEL_Q16_ETA_MIN ? (uint32_t)FRESNEL_Q16_ETA_MIN : (uint32_t)n_in;
    uint32_t k = k_in <= 0 ? 0u : (uint32_t)k_in;
    uint32_t em1 = n >= 65536u ? n - 65536u : 65536u - n;
    fresnel_qf kq = fr__qf(k, -16), d = fr__qf(em1, -16), s = fr__qf(n + 65536u, -16);
    fresnel_qf k2 = fr__qf_mul(kq, kq);
    out->f0 = fr__qf_to_q30_unit(fr__qf_div(fr__qf_add(fr__qf_mul(d, d), k2), fr__qf_add(fr__qf_mul(s, s), k2)));
    out->a = fr__qf(a <= 0 ? 0u : (uint32_t)a, -16);
    out->alpha = alpha <= 0 ? 0 : (alpha >= FRESNEL_Q16_ALPHA_MAX ? FRESNEL_Q16_ALPHA_MAX : alpha);
}

#else
typedef int fr__lsk_q15_disabled;
#endif
