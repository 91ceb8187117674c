/* Helpers shared by the fixed-point model files (src/q15/\*_q15.c); not
 * public. The arithmetic they build on is math_q15.h.
 */
#ifndef FRESNEL_Q15_INTERNAL_H
#define FRESNEL_Q15_INTERNAL_H

#include "math_q15.h"

#if FRESNEL_HAS_Q15

/* A Q15 argument as the API promises: any int32, clamped to [0, one]. */
static inline uint32_t fresnel_i_q15_arg(int32_t x)
{
    return x <= 0 ? 0u : (x >= 32768 ? FRESNEL_I_ONE_Q15 : (uint32_t)x);
}

/* F82's constants (f82_q15.c derives them; batch_q15.c uses them too). */
#define FRESNEL_I_K1_FRAC_Q30 699418891u /* round((823543/46656 - 17) 2^30) */
#define FRESNEL_I_K2_OVER_K1_Q30 496782080u /* round((49/6)/(823543/46656) 2^30) = 0.46266 */

/* A LUT's node count as the functions read it (lut_q15.c, batch_q15.c): n
 * above FRESNEL_I_LUT_N_MAX is taken as FRESNEL_I_LUT_N_MAX (so only entries
 * the caller's table has are read), n <= 0 as 0, for which the callers read
 * no entry at all. */
#define FRESNEL_I_LUT_N_MAX 32768
static inline int fresnel_i_qlut_n(int n) { return n <= 0 ? 0 : (n > FRESNEL_I_LUT_N_MAX ? FRESNEL_I_LUT_N_MAX : n); }

/* Schlick's F0 + (1 - F0) x5 in Q30 from F0 in Q15 and x5 in Q30.
 * R: f0 2^15 <= 2^30 - (1 - f0) 2^15 ... the sum is <= f0 2^15 + (2^15 - f0) 2^15 = 2^30. */
static inline uint32_t fresnel_i_schlick_q30(uint32_t f0, uint32_t x5)
{
    FRESNEL_I_RANGE("schlick f0", f0, 0, 1u << 15);
    FRESNEL_I_RANGE("schlick weight", x5, 0, 1u << 30);
    return (f0 << 15) + fresnel_i_mul_q30_q15(x5, FRESNEL_I_ONE_Q15 - f0);
}

static inline fresnel_qf fresnel_i_qf_one(void) { return fresnel_i_qf(1u, 0); }
/* a value clamped to [0, 1] as Q30 */
static inline uint32_t fresnel_i_qf_to_q30_unit(fresnel_qf a)
{
    uint32_t v = fresnel_i_qf_to_fix(a, 30);
    return v > FRESNEL_I_ONE_Q30 ? FRESNEL_I_ONE_Q30 : v;
}

/* |eta^2 - kappa^2 - sin^2| of m at c with ~60 bits, and its sign (exact_q15.c). */
FRESNEL_I_HIDDEN fresnel_qf fresnel_i_a_qf(const fresnel_ior_prep_q15 *m, uint32_t c, int *negative);

/* 1 - exact Fresnel of m at c (exact_q15.c), in qf: Cook-Torrance's T(c). */
FRESNEL_I_HIDDEN fresnel_qf fresnel_i_conductor_transmittance_q15(const fresnel_ior_prep_q15 *m, uint32_t c);

/* The thin film's tables (film_q15.c), exposed for their test. */
FRESNEL_I_HIDDEN extern const uint16_t fresnel_i_film_sin_q15[257];
FRESNEL_I_HIDDEN extern const uint16_t fresnel_i_film_exp2_q15[65];
FRESNEL_I_HIDDEN extern const uint16_t fresnel_i_film_recip_q15[257];

#define FRESNEL_I_RGB_Q15(expr_r, expr_g, expr_b) \
    do { fresnel_rgb_q15 out_; out_.r = (expr_r); out_.g = (expr_g); out_.b = (expr_b); return out_; } while (0)

#endif /* FRESNEL_HAS_Q15 */
#endif
