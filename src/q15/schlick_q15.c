/* Schlick, generalized Schlick, Schlick internal and the F0 helpers in
 * fixed point (fresnel_q15.h).
 *
 * Schlick: x = 1 - c exact in Q15, x^2 exact in Q30, x^4 and x^5 in Q30
 * through 15-bit halves (no int64), so the only rounding that shows is the
 * final one: the bound is 0.5 LSB plus what shows of the 30-bit
 * intermediates (under 0.001 LSB).
 *
 * Generalized Schlick, p != 5: (1-c)^p = (1-c)^floor(p) by repeated squaring
 * in qf, times 2^(-frac(p) L), L = -log2(1-c): log2 from a 64-entry
 * reciprocal table and the series of log(1 + d), |d| < 2^-7, to the cubic
 * term; 2^-y from a 64-entry table and the series of exp to the cubic term
 * (math_q15.c). The power's relative error is below 2^-24 for p <= 64 and
 * 2^-21 up to p = 1000 (the squarings of x^1000), so the bound is 0.501 for
 * p <= 64 and 0.5 + 2^-21 2^15 = 0.516 above.
 *
 * Schlick internal evaluates Schlick from ct in qf, not from ct rounded to a
 * Q15 cosine first. F0 in a medium uses the cancellation-free rearrangement
 * of fresnel_f0_in_medium (schlick.c). */
#include "internal.h"

#if FRESNEL_HAS_Q15

fresnel_q15 fresnel_schlick_q15(int32_t f0, int32_t c)
{
    uint32_t x = FRESNEL_I_ONE_Q15 - fresnel_i_q15_arg(c); /* exact: 1 - c in Q15 */
    return fresnel_i_q30_to_q15(fresnel_i_schlick_q30(fresnel_i_q15_arg(f0), fresnel_i_pow5_q30(x)));
}

/* F0 + (1 - F0)/21 with the division a multiplication by round(2^20/21):
 * (1 - F0) 2^15 <= 2^15 keeps the product below 2^31, and the constant's
 * rounding moves the result by under 0.01 LSB. */
fresnel_q15 fresnel_schlick_avg_q15(int32_t f0_in)
{
    uint32_t f0 = fresnel_i_q15_arg(f0_in);
    return (fresnel_q15)(f0 + (((FRESNEL_I_ONE_Q15 - f0) * 49932u + (1u << 19)) >> 20));
}

fresnel_rgb_q15 fresnel_schlick_avg_q15_rgb(fresnel_rgb_q15 f0)
{
    FRESNEL_I_RGB_Q15(fresnel_schlick_avg_q15(f0.r), fresnel_schlick_avg_q15(f0.g), fresnel_schlick_avg_q15(f0.b));
}

fresnel_rgb_q15 fresnel_schlick_q15_rgb(fresnel_rgb_q15 f0, int32_t c)
{
    uint32_t x5 = fresnel_i_pow5_q30(FRESNEL_I_ONE_Q15 - fresnel_i_q15_arg(c));
    FRESNEL_I_RGB_Q15(fresnel_i_q30_to_q15(fresnel_i_schlick_q30(fresnel_i_q15_arg(f0.r), x5)),
                fresnel_i_q30_to_q15(fresnel_i_schlick_q30(fresnel_i_q15_arg(f0.g), x5)),
                fresnel_i_q30_to_q15(fresnel_i_schlick_q30(fresnel_i_q15_arg(f0.b), x5)));
}

static uint32_t fresnel_i_clamp_p(fresnel_q16 p)
{
    return p <= FRESNEL_P_MIN_Q16 ? (uint32_t)FRESNEL_P_MIN_Q16
                                  : (p >= FRESNEL_P_MAX_Q16 ? (uint32_t)FRESNEL_P_MAX_Q16 : (uint32_t)p);
}

/* (1 - c)^p in Q30: Schlick's multiplications for p = 5, the power function otherwise. */
static uint32_t fresnel_i_weight_q30(uint32_t c, uint32_t p)
{
    if (p == 5u * 65536u)
        return fresnel_i_pow5_q30(FRESNEL_I_ONE_Q15 - c);
    return fresnel_i_qf_to_q30_unit(fresnel_i_pow_q15(FRESNEL_I_ONE_Q15 - c, p));
}

/* F0 + (F90 - F0) t in Q30, t in Q30. R: |F90 - F0| <= 2^15, so the product
 * is <= 2^30 in magnitude and the sum stays in [0, 2^30] (a convex combination). */
static fresnel_q15 fresnel_i_mix_q15(uint32_t f0, uint32_t f90, uint32_t t)
{
    uint32_t base = f0 << 15;
    if (f90 >= f0)
        return fresnel_i_q30_to_q15(base + fresnel_i_mul_q30_q15(t, f90 - f0));
    return fresnel_i_q30_to_q15(base - fresnel_i_mul_q30_q15(t, f0 - f90));
}

fresnel_q15 fresnel_schlick_gen_q15(int32_t f0, int32_t f90, fresnel_q16 p, int32_t c)
{
    return fresnel_i_mix_q15(fresnel_i_q15_arg(f0), fresnel_i_q15_arg(f90), fresnel_i_weight_q30(fresnel_i_q15_arg(c), fresnel_i_clamp_p(p)));
}

fresnel_rgb_q15 fresnel_schlick_gen_q15_rgb(fresnel_rgb_q15 f0, fresnel_rgb_q15 f90, fresnel_q16 p,
                                            int32_t c)
{
    uint32_t t = fresnel_i_weight_q30(fresnel_i_q15_arg(c), fresnel_i_clamp_p(p));
    FRESNEL_I_RGB_Q15(fresnel_i_mix_q15(fresnel_i_q15_arg(f0.r), fresnel_i_q15_arg(f90.r), t),
                fresnel_i_mix_q15(fresnel_i_q15_arg(f0.g), fresnel_i_q15_arg(f90.g), t),
                fresnel_i_mix_q15(fresnel_i_q15_arg(f0.b), fresnel_i_q15_arg(f90.b), t));
}

/* (1 - ct)^5 in Q30 for Schlick internal, or 2^31 for total internal
 * reflection. ct^2 = (eta^2 - sin^2) / eta^2, the numerator from the two
 * words of the prepared a0 (exact_q15.c), so that it keeps its digits near
 * the critical angle where it is the small difference of two numbers. */
static uint32_t fresnel_i_internal_weight_q30(const fresnel_ior_prep_q15 *m, uint32_t c)
{
    uint32_t ct, x, x2;
    int negative;
    fresnel_qf a;
    if (m->a0 > 0 || (m->a0 == 0 && m->a0_lo >= 0))
        return fresnel_i_pow5_q30(FRESNEL_I_ONE_Q15 - c); /* eta >= 1: external, c as is */
    a = fresnel_i_a_qf(m, c, &negative);
    if (negative || a.m == 0)
        return 1u << 31; /* past the critical angle */
    ct = fresnel_i_qf_to_q30_unit(fresnel_i_qf_sqrt(fresnel_i_qf_mul(a, m->inv_eta2)));
    x = FRESNEL_I_ONE_Q30 - ct;   /* R: [0, 2^30] */
    x2 = fresnel_i_mul_q30(x, x); /* R: <= 2^30 */
    return fresnel_i_mul_q30(fresnel_i_mul_q30(x2, x2), x);
}

static fresnel_q15 fresnel_i_internal_q15(uint32_t f0, uint32_t w)
{
    return w > FRESNEL_I_ONE_Q30 ? (fresnel_q15)FRESNEL_I_ONE_Q15 : fresnel_i_q30_to_q15(fresnel_i_schlick_q30(f0, w));
}

fresnel_q15 fresnel_schlick_internal_q15(int32_t f0, const fresnel_ior_prep_q15 *m, int32_t c)
{
    return fresnel_i_internal_q15(fresnel_i_q15_arg(f0), fresnel_i_internal_weight_q30(m, fresnel_i_q15_arg(c)));
}

fresnel_rgb_q15 fresnel_schlick_internal_q15_rgb(fresnel_rgb_q15 f0, const fresnel_ior_prep_q15 *m, int32_t c)
{
    uint32_t w = fresnel_i_internal_weight_q30(m, fresnel_i_q15_arg(c));
    FRESNEL_I_RGB_Q15(fresnel_i_internal_q15(fresnel_i_q15_arg(f0.r), w), fresnel_i_internal_q15(fresnel_i_q15_arg(f0.g), w),
                fresnel_i_internal_q15(fresnel_i_q15_arg(f0.b), w));
}

/* eta and kappa of the Q16.16 API, clamped to the fixed-point domain. */
static uint32_t fresnel_i_eta_q16(fresnel_q16 x) { return x <= FRESNEL_ETA_MIN_Q16 ? (uint32_t)FRESNEL_ETA_MIN_Q16 : (uint32_t)x; }
static uint32_t fresnel_i_kappa_q16(fresnel_q16 x) { return x <= 0 ? 0u : (uint32_t)x; }

/* ((eta-1)^2 + kappa^2) / ((eta+1)^2 + kappa^2): eta - 1 and eta + 1 are
 * exact in Q16.16 (eta + 1 < 2^32 unsigned), each square has 31 bits. */
static fresnel_qf fresnel_i_f0_qf(uint32_t eta, uint32_t kappa)
{
    uint32_t em1 = eta >= 65536u ? eta - 65536u : 65536u - eta;
    fresnel_qf k = fresnel_i_qf(kappa, -16), d = fresnel_i_qf(em1, -16), s = fresnel_i_qf(eta + 65536u, -16);
    fresnel_qf k2 = fresnel_i_qf_mul(k, k);
    return fresnel_i_qf_div(fresnel_i_qf_add(fresnel_i_qf_mul(d, d), k2), fresnel_i_qf_add(fresnel_i_qf_mul(s, s), k2));
}

fresnel_q15 fresnel_f0_from_ior_q15(fresnel_q16 eta, fresnel_q16 kappa)
{
    return fresnel_i_q30_to_q15(fresnel_i_qf_to_q30_unit(fresnel_i_f0_qf(fresnel_i_eta_q16(eta), fresnel_i_kappa_q16(kappa))));
}

fresnel_q15 fresnel_f0_in_medium_q15(int32_t f0_in, fresnel_q16 eta_e)
{
    /* As fresnel_f0_in_medium: r = sqrt F0, 1 - s = 2/(etaE + 1),
     * 1 - r = (1 - F0)/(1 + r); q = ((1-s) - (1-r)) / ((1-r) + r (1-s)). */
    uint32_t f0 = fresnel_i_q15_arg(f0_in);
    fresnel_qf one = fresnel_i_qf_one();
    fresnel_qf r = fresnel_i_qf_sqrt(fresnel_i_qf(f0, -15));
    fresnel_qf oms = fresnel_i_qf_div(fresnel_i_qf(2u, 0), fresnel_i_qf(fresnel_i_eta_q16(eta_e) + 65536u, -16));
    fresnel_qf omr = fresnel_i_qf_div(fresnel_i_qf(FRESNEL_I_ONE_Q15 - f0, -15), fresnel_i_qf_add(one, r));
    fresnel_qf den = fresnel_i_qf_add(omr, fresnel_i_qf_mul(r, oms)); /* > 0: 1 - r s > 0 */
    fresnel_qf q = fresnel_i_qf_div(fresnel_i_qf_sub(oms, omr, (int *)0), den);
    return fresnel_i_q30_to_q15(fresnel_i_qf_to_q30_unit(fresnel_i_qf_mul(q, q)));
}

#else
typedef int fresnel_i_schlick_q15_disabled;
#endif
