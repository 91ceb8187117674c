/* Hoffman's F82 model in fixed point (fresnel_q15.h).
 *
 * a c (1-c)^6 with a = K1 (F0 - F82) + K2 (1 - F0), K1 = 7^7/6^6, K2 = 49/6,
 * is rewritten as g h with
 *   g = K1 c (1-c)^6  in [0, 1]  (maximum exactly 1 at c = 1/7),
 *   h = (F0 - F82) + (K2/K1)(1 - F0)  in [-0.5373, 1.4627],
 * so that both factors are Q30 numbers of known range and their product
 * needs no int64. (h >= F0 - 1 + 0.4627 (1 - F0) = -0.5373 (1 - F0);
 * h <= 1 + 0.4627.) */
#include "internal.h"

#if FRESNEL_HAS_Q15


/* g = K1 c x^6 in Q30 from x^5 in Q30 and c, x = 1 - c in Q15.
 * R: x^6 <= 2^30; c x^6 <= (6^6/7^7) 2^30 < 2^26; 17 c x^6 < 2^30.1 is
 * bounded by g <= 1 once the fraction is added: g <= 2^30. */
static uint32_t fresnel_i_f82_g_q30(uint32_t x5, uint32_t c)
{
    uint32_t x6 = fresnel_i_mul_q30_q15(x5, FRESNEL_I_ONE_Q15 - c);
    uint32_t t = fresnel_i_mul_q30_q15(x6, c);
    FRESNEL_I_RANGE("f82 c x^6", t, 0, 60830459); /* (6^6/7^7) 2^30 */
    return 17u * t + fresnel_i_mul_q30(t, FRESNEL_I_K1_FRAC_Q30);
}

static fresnel_q15 fresnel_i_f82_q15(uint32_t f0, uint32_t f82, uint32_t x5, uint32_t g)
{
    /* R: (F0 - F82) 2^15 in [-2^30, 2^30]; the K2/K1 term in [0, 0.4627 2^30] */
    int32_t h = ((int32_t)f0 - (int32_t)f82) * 32768 + (int32_t)fresnel_i_mul_q30_q15(FRESNEL_I_K2_OVER_K1_Q30, FRESNEL_I_ONE_Q15 - f0);
    uint32_t gh;
    int32_t f;
    FRESNEL_I_RANGE("f82 h", h, -576960000, 1570524000); /* -0.5373, 1.4627 in Q30 */
    FRESNEL_I_RANGE("f82 g", g, 0, 1u << 30);
    /* R: |h| < 1.4627 2^30 < 2^31 and g <= 2^30, as fresnel_i_mul_q30 needs */
    gh = fresnel_i_mul_q30(h < 0 ? (uint32_t)-h : (uint32_t)h, g);
    /* R: Schlick part in [0, 2^30]; f in [-1.4627 2^30, 1.5373 2^30], inside int32 */
    f = (int32_t)fresnel_i_schlick_q30(f0, x5) + (h < 0 ? (int32_t)gh : -(int32_t)gh);
    FRESNEL_I_RANGE("f82 F", f, -1570524000, 1650702000);
    return fresnel_i_q30s_to_q15(f);
}

fresnel_q15 fresnel_f82_q15(int32_t f0, int32_t f82, int32_t c_in)
{
    uint32_t c = fresnel_i_q15_arg(c_in), x5 = fresnel_i_pow5_q30(FRESNEL_I_ONE_Q15 - c);
    return fresnel_i_f82_q15(fresnel_i_q15_arg(f0), fresnel_i_q15_arg(f82), x5, fresnel_i_f82_g_q30(x5, c));
}

fresnel_rgb_q15 fresnel_f82_q15_rgb(fresnel_rgb_q15 f0, fresnel_rgb_q15 f82, int32_t c_in)
{
    uint32_t c = fresnel_i_q15_arg(c_in), x5 = fresnel_i_pow5_q30(FRESNEL_I_ONE_Q15 - c), g = fresnel_i_f82_g_q30(x5, c);
    FRESNEL_I_RGB_Q15(fresnel_i_f82_q15(fresnel_i_q15_arg(f0.r), fresnel_i_q15_arg(f82.r), x5, g),
                fresnel_i_f82_q15(fresnel_i_q15_arg(f0.g), fresnel_i_q15_arg(f82.g), x5, g),
                fresnel_i_f82_q15(fresnel_i_q15_arg(f0.b), fresnel_i_q15_arg(f82.b), x5, g));
}

/* F0 - (13/756)(1 - F0) - (K1/126)(F0 - F82) (f32/f82.c), the two
 * corrections in Q18 with the constants round(2^18 13/756) = 4508 and
 * round(2^18 K1/126) = 36724 (Q18 is the finest that keeps the sum inside
 * int32); their rounding adds up to 0.05 LSB to the final rounding's 0.5. */
fresnel_q15 fresnel_f82_avg_q15(int32_t f0_in, int32_t f82_in)
{
    int32_t f0 = (int32_t)fresnel_i_q15_arg(f0_in), f82 = (int32_t)fresnel_i_q15_arg(f82_in);
    /* R: |corr| <= 2^15 (4508 + 36724) < 1.36e9 < 2^31 */
    int32_t corr = (32768 - f0) * 4508 + (f0 - f82) * 36724, v;
    /* rounded to Q15 without shifting a negative number (implementation-defined in C99) */
    v = f0 - (corr >= 0 ? (corr + (1 << 17)) >> 18 : -((-corr + (1 << 17)) >> 18));
    return (fresnel_q15)(v < 0 ? 0 : v > 32768 ? 32768 : v);
}

fresnel_rgb_q15 fresnel_f82_avg_q15_rgb(fresnel_rgb_q15 f0, fresnel_rgb_q15 f82)
{
    FRESNEL_I_RGB_Q15(fresnel_f82_avg_q15(f0.r, f82.r), fresnel_f82_avg_q15(f0.g, f82.g),
                      fresnel_f82_avg_q15(f0.b, f82.b));
}

#else
typedef int fresnel_i_f82_q15_disabled;
#endif
