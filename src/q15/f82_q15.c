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

#define FRESNEL_I_K1_FRAC_Q30 699418891u /* round((823543/46656 - 17) 2^30) */
#define FRESNEL_I_K2_OVER_K1_Q30 496782080u /* round((49/6)/(823543/46656) 2^30) = 0.46266 */

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

/* ---- batches (fresnel_q15.h, BATCHES): the scalar call's g, h and
 * rounding with each product floored exactly; h is per material, so its
 * sign is settled once. */
static uint32_t fresnel_i_f82_g_batch(uint32_t x5, uint32_t c)
{
    uint32_t t = fresnel_i_mulw_q15(fresnel_i_mulw_q15(x5, FRESNEL_I_ONE_Q15 - c), c);
    return 17u * t + fresnel_i_mulw_q30(t, FRESNEL_I_K1_FRAC_Q30);
}

static int32_t fresnel_i_f82_h(uint32_t f0, uint32_t f82)
{
    return ((int32_t)f0 - (int32_t)f82) * 32768 + (int32_t)fresnel_i_mul_q30_q15(FRESNEL_I_K2_OVER_K1_Q30, FRESNEL_I_ONE_Q15 - f0);
}

/* F for one channel from x^5, g and the channel's F0 and h. */
static fresnel_q15 fresnel_i_f82_batch_one(uint32_t f0, int32_t h, uint32_t x5, uint32_t g)
{
    uint32_t s = (f0 << 15) + fresnel_i_mulw_q15(x5, FRESNEL_I_ONE_Q15 - f0);
    uint32_t gh = fresnel_i_mulw_q30(h < 0 ? (uint32_t)-h : (uint32_t)h, g);
    return fresnel_i_q30s_to_q15((int32_t)s + (h < 0 ? (int32_t)gh : -(int32_t)gh));
}

#if FRESNEL_I_MVE
/* Helium: x^5 and g of four cosines, then F for one channel's F0 and h. */
typedef struct fresnel_i_f82_mve_xg {
    uint32x4_t x5, g;
} fresnel_i_f82_mve_xg;

static fresnel_i_f82_mve_xg fresnel_i_f82_mve_xg_at(uint32x4_t c)
{
    const uint32x4_t one = vdupq_n_u32(FRESNEL_I_ONE_Q15);
    fresnel_i_f82_mve_xg r;
    uint32x4_t cv = vminq_u32(c, one), x = vsubq_u32(one, cv), x16 = vshlq_n_u32(x, 16);
    uint32x4_t x2s = vshlq_n_u32(vmulq_u32(x, x), 1), t;
    r.x5 = FRESNEL_I_MVE_Q15(vmulhq_u32(x2s, x2s), x16);
    t = FRESNEL_I_MVE_Q15(FRESNEL_I_MVE_Q15(r.x5, x16), vshlq_n_u32(cv, 16));
    r.g = vaddq_u32(vmulq_n_u32(t, 17u), FRESNEL_I_MVE_Q30(t, vdupq_n_u32(FRESNEL_I_K1_FRAC_Q30 << 1)));
    return r;
}

/* F for one channel: Schlick's part, then g h added or taken away by h's
 * sign, held to [0, 2^30] and rounded (fresnel_i_q30s_to_q15). */
static uint32x4_t fresnel_i_f82_mve_channel(fresnel_i_f82_mve_xg xg, uint32_t f0, int32_t h)
{
    uint32x4_t s = vaddq_n_u32(FRESNEL_I_MVE_Q15(xg.x5, vdupq_n_u32((FRESNEL_I_ONE_Q15 - f0) << 16)), f0 << 15);
    uint32x4_t gh = FRESNEL_I_MVE_Q30(xg.g, vdupq_n_u32((h < 0 ? (uint32_t)-h : (uint32_t)h) << 1));
    int32x4_t f = vreinterpretq_s32_u32(h < 0 ? vaddq_u32(s, gh) : vsubq_u32(s, gh));
    f = vminq_s32(vmaxq_s32(f, vdupq_n_s32(0)), vdupq_n_s32((int32_t)FRESNEL_I_ONE_Q30));
    return vrshrq_n_u32(vreinterpretq_u32_s32(f), 15);
}
#endif

void fresnel_f82_q15_batch(int32_t f0_in, int32_t f82_in, const fresnel_q15 *c, fresnel_q15 *out, int n)
{
    uint32_t f0 = fresnel_i_q15_arg(f0_in);
    int32_t h = fresnel_i_f82_h(f0, fresnel_i_q15_arg(f82_in));
    int i;
#if FRESNEL_I_MVE
    for (i = 0; i + 4 <= n; i += 4)
        vstrhq_u32(out + i, fresnel_i_f82_mve_channel(fresnel_i_f82_mve_xg_at(vldrhq_u32(c + i)), f0, h));
    if (i < n) {
        mve_pred16_t p = vctp32q((uint32_t)(n - i));
        vstrhq_p_u32(out + i, fresnel_i_f82_mve_channel(fresnel_i_f82_mve_xg_at(vldrhq_z_u32(c + i, p)), f0, h), p);
    }
    return;
#endif
    for (i = 0; i < n; i++) {
        uint32_t x = fresnel_i_batch_x(c[i]), ci = FRESNEL_I_ONE_Q15 - x, x5 = fresnel_i_batch_pow5_q30(x);
        out[i] = fresnel_i_f82_batch_one(f0, h, x5, fresnel_i_f82_g_batch(x5, ci));
    }
}

void fresnel_f82_q15_rgb_batch(fresnel_rgb_q15 f0, fresnel_rgb_q15 f82, const fresnel_q15 *c, fresnel_rgb_q15 *out,
                               int n)
{
    uint32_t r = fresnel_i_q15_arg(f0.r), g = fresnel_i_q15_arg(f0.g), b = fresnel_i_q15_arg(f0.b);
    int32_t hr = fresnel_i_f82_h(r, fresnel_i_q15_arg(f82.r)), hg = fresnel_i_f82_h(g, fresnel_i_q15_arg(f82.g)),
            hb = fresnel_i_f82_h(b, fresnel_i_q15_arg(f82.b));
    int i;
#if FRESNEL_I_MVE
    {
        const uint32x4_t at = vmulq_n_u32(vidupq_n_u32(0, 1), (uint32_t)sizeof *out);
        for (i = 0; i < n; i += 4) {
            mve_pred16_t p = vctp32q((uint32_t)(n - i));
            fresnel_i_f82_mve_xg xg = fresnel_i_f82_mve_xg_at(vldrhq_z_u32(c + i, p));
            uint16_t *row = (uint16_t *)(void *)(out + i);
            vstrhq_scatter_offset_p_u32(row, at, fresnel_i_f82_mve_channel(xg, r, hr), p);
            vstrhq_scatter_offset_p_u32(row + 1, at, fresnel_i_f82_mve_channel(xg, g, hg), p);
            vstrhq_scatter_offset_p_u32(row + 2, at, fresnel_i_f82_mve_channel(xg, b, hb), p);
        }
        return;
    }
#endif
    for (i = 0; i < n; i++) {
        uint32_t x = fresnel_i_batch_x(c[i]), ci = FRESNEL_I_ONE_Q15 - x, x5 = fresnel_i_batch_pow5_q30(x);
        uint32_t gg = fresnel_i_f82_g_batch(x5, ci);
        out[i].r = fresnel_i_f82_batch_one(r, hr, x5, gg);
        out[i].g = fresnel_i_f82_batch_one(g, hg, x5, gg);
        out[i].b = fresnel_i_f82_batch_one(b, hb, x5, gg);
    }
}

#else
typedef int fresnel_i_f82_q15_disabled;
#endif
