/* Lazanyi and Szirmay-Kalos in fixed point (fresnel_q15.h). The rescaled
 * model is Schlick with F0 = F0(n, k) exactly (fresnel.h), so it is
 * evaluated as Schlick with a 30-bit F0; the compensation term
 * a c (1-c)^alpha is formed in fresnel_qf. */
#include "internal.h"

#if FRESNEL_HAS_Q15

/* F0 + (1 - F0) x^5 in Q30 with F0 in Q30.
 * R: f0 <= 2^30; (2^30 - f0) x5 / 2^30 <= 2^30 - f0: the sum is <= 2^30. */
static uint32_t fresnel_i_lsk_q30(const fresnel_lsk_prep_q15 *m, uint32_t c)
{
    uint32_t f0 = m->f0 > FRESNEL_I_ONE_Q30 ? FRESNEL_I_ONE_Q30 : m->f0;
    uint32_t f = f0 + fresnel_i_mul_q30(FRESNEL_I_ONE_Q30 - f0, fresnel_i_pow5_q30(FRESNEL_I_ONE_Q15 - c));
    FRESNEL_I_RANGE("lsk F", f, 0, 1u << 30);
    return f;
}

fresnel_q15 fresnel_lsk_q15(const fresnel_lsk_prep_q15 *m, int32_t c)
{
    return fresnel_i_q30_to_q15(fresnel_i_lsk_q30(m, fresnel_i_q15_arg(c)));
}

fresnel_rgb_q15 fresnel_lsk_q15_rgb(const fresnel_lsk_prep_q15 m[3], int32_t c)
{
    FRESNEL_I_RGB_Q15(fresnel_lsk_q15(&m[0], c), fresnel_lsk_q15(&m[1], c), fresnel_lsk_q15(&m[2], c));
}

fresnel_q15 fresnel_lsk_comp_q15(const fresnel_lsk_prep_q15 *m, int32_t c_in)
{
    uint32_t c = fresnel_i_q15_arg(c_in), lsk = fresnel_i_lsk_q30(m, c), comp;
    uint32_t alpha = m->alpha <= 0 ? 0u : (m->alpha >= FRESNEL_ALPHA_MAX_Q16 ? (uint32_t)FRESNEL_ALPHA_MAX_Q16 : (uint32_t)m->alpha);
    fresnel_qf term;
    if (m->a.m == 0 || c == 0)
        return fresnel_i_q30_to_q15(lsk);
    term = fresnel_i_qf_mul(m->a, fresnel_i_qf(c, -15));
    if (alpha)
        term = fresnel_i_qf_mul(term, fresnel_i_pow_q15(FRESNEL_I_ONE_Q15 - c, alpha));
    comp = fresnel_i_qf_to_fix(term, 30); /* saturates: a term above 4 clamps the result to 0 anyway */
    return comp >= lsk ? (fresnel_q15)0 : fresnel_i_q30_to_q15(lsk - comp);
}

fresnel_rgb_q15 fresnel_lsk_comp_q15_rgb(const fresnel_lsk_prep_q15 m[3], int32_t c)
{
    FRESNEL_I_RGB_Q15(fresnel_lsk_comp_q15(&m[0], c), fresnel_lsk_comp_q15(&m[1], c),
                fresnel_lsk_comp_q15(&m[2], c));
}

fresnel_lsk_prep_q15 fresnel_lsk_prepare_q15(fresnel_q16 eta_in, fresnel_q16 kappa_in, fresnel_q16 a, fresnel_q16 alpha)
{
    fresnel_lsk_prep_q15 m;
    fresnel_lsk_prep_q15 *out = &m;
    fresnel_q16 n_in = eta_in, k_in = kappa_in;
    uint32_t n = n_in <= FRESNEL_ETA_MIN_Q16 ? (uint32_t)FRESNEL_ETA_MIN_Q16 : (uint32_t)n_in;
    uint32_t k = k_in <= 0 ? 0u : (uint32_t)k_in;
    uint32_t em1 = n >= 65536u ? n - 65536u : 65536u - n;
    fresnel_qf kq = fresnel_i_qf(k, -16), d = fresnel_i_qf(em1, -16), s = fresnel_i_qf(n + 65536u, -16);
    fresnel_qf k2 = fresnel_i_qf_mul(kq, kq);
    out->f0 = fresnel_i_qf_to_q30_unit(fresnel_i_qf_div(fresnel_i_qf_add(fresnel_i_qf_mul(d, d), k2), fresnel_i_qf_add(fresnel_i_qf_mul(s, s), k2)));
    out->a = fresnel_i_qf(a <= 0 ? 0u : (uint32_t)a, -16);
    out->alpha = alpha <= 0 ? 0 : (alpha >= FRESNEL_ALPHA_MAX_Q16 ? FRESNEL_ALPHA_MAX_Q16 : alpha);
    return m;
}

#else
typedef int fresnel_i_lsk_q15_disabled;
#endif
