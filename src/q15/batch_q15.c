/* The Q1.15 batches (fresnel_q15.h, BATCHES): a scanline of one
 * material, bit for bit the scalar calls.
 *
 * A file of their own, so that the scalar calls' files are compiled as if
 * the batches did not exist (at -Os the compiler keeps a helper out of line
 * once it has several callers in a file). Three bodies (math_q15.h):
 * Helium four lanes at a time; a long multiply, each Q30 product the high
 * word of shifted operands; and, on the cores with neither, the scalar
 * calls' arithmetic with their set-up done once, or the scalar call itself
 * where that is all there is to share (the LUTs' square root, the power of
 * p != 5, the cubic). Every floor is the
 * scalar call's, so every body agrees with it bit for bit
 * (tests/runtime/q15/test_q15_batch.c on the host, make cross-test on the
 * Cortex-M0, M4F and M55). */
#include "internal.h"

#if FRESNEL_HAS_Q15

/* ---- batches (fresnel_q15.h, BATCHES): F0 + (F90 - F0) x^5, x = 1 - c,
 * with F90 = one for Schlick; w = |F90 - F0|, added when F90 >= F0. The
 * scalar calls' arithmetic: x^5 and the product floored exactly, rounded
 * once (fresnel_i_q30_to_q15). */
#if FRESNEL_I_MVE
/* Helium: four cosines per step, the last step predicated to the n - i left. */
/* x^5 of four cosines: x^2 doubled, its square's high word floor(x^4 / 2^30),
 * then floor(x^4 x / 2^15) (fresnel_i_pow5_q30's floors). */
static uint32x4_t fresnel_i_pow5_mve(uint32x4_t c)
{
    const uint32x4_t one = vdupq_n_u32(FRESNEL_I_ONE_Q15);
    uint32x4_t x = vsubq_u32(one, vminq_u32(c, one)), x2s = vshlq_n_u32(vmulq_u32(x, x), 1);
    return FRESNEL_I_MVE_Q15(vmulhq_u32(x2s, x2s), vshlq_n_u32(x, 16));
}

/* Helium: four cosines per step; the last, short step predicated. */
static void fresnel_i_mix5_mve(uint32_t f0, uint32_t w, int up, const fresnel_q15 *c, fresnel_q15 *out, int n)
{
    const uint32x4_t w16 = vdupq_n_u32(w << 16), base = vdupq_n_u32((f0 << 15) + (1u << 14));
    int i = 0;
    if (up)
        for (; i + 4 <= n; i += 4)
            vstrhq_u32(out + i, vshrq_n_u32(vaddq_u32(base, FRESNEL_I_MVE_Q15(fresnel_i_pow5_mve(vldrhq_u32(c + i)), w16)), 15));
    else
        for (; i + 4 <= n; i += 4)
            vstrhq_u32(out + i, vshrq_n_u32(vsubq_u32(base, FRESNEL_I_MVE_Q15(fresnel_i_pow5_mve(vldrhq_u32(c + i)), w16)), 15));
    if (i < n) {
        mve_pred16_t p = vctp32q((uint32_t)(n - i));
        uint32x4_t d = FRESNEL_I_MVE_Q15(fresnel_i_pow5_mve(vldrhq_z_u32(c + i, p)), w16);
        vstrhq_p_u32(out + i, vshrq_n_u32(up ? vaddq_u32(base, d) : vsubq_u32(base, d), 15), p);
    }
}
#endif

static void fresnel_i_mix5_batch(uint32_t f0, uint32_t f90, const fresnel_q15 *c, fresnel_q15 *out, int n)
{
    uint32_t base = f0 << 15, w = f90 >= f0 ? f90 - f0 : f0 - f90;
    int i;
#if FRESNEL_I_MVE
    fresnel_i_mix5_mve(f0, w, f90 >= f0, c, out, n);
    return;
#endif
#if FRESNEL_I_LONG_MUL
    /* w = one (F0 0, F90 1): the product is x^5 itself; else
     * floor(x^5 w / 2^15) is the high word of (2 x^5)(w 2^16) and of
     * x^5 (w 2^17) alike, the latter one shift fewer, for w < 2^15 */
    if (w == FRESNEL_I_ONE_Q15 && f90 >= f0) {
        for (i = 0; i < n; i++)
            out[i] = fresnel_i_q30_to_q15(base + fresnel_i_batch_pow5_q30(fresnel_i_batch_x(c[i])));
        return;
    }
    if (w < FRESNEL_I_ONE_Q15) {
        uint32_t w17 = w << 17;
        base += 1u << 14;
        /* four cosines a step: one loop test for four */
#define FRESNEL_I_MIX5_AT(k, op) (fresnel_q15)((base op fresnel_i_mulhi(fresnel_i_batch_pow5_q30(fresnel_i_batch_x(c[k])), w17)) >> 15)
        if (f90 >= f0) {
            for (i = 0; i + 4 <= n; i += 4) {
                out[i] = FRESNEL_I_MIX5_AT(i, +);
                out[i + 1] = FRESNEL_I_MIX5_AT(i + 1, +);
                out[i + 2] = FRESNEL_I_MIX5_AT(i + 2, +);
                out[i + 3] = FRESNEL_I_MIX5_AT(i + 3, +);
            }
            for (; i < n; i++)
                out[i] = FRESNEL_I_MIX5_AT(i, +);
        } else {
            for (i = 0; i + 4 <= n; i += 4) {
                out[i] = FRESNEL_I_MIX5_AT(i, -);
                out[i + 1] = FRESNEL_I_MIX5_AT(i + 1, -);
                out[i + 2] = FRESNEL_I_MIX5_AT(i + 2, -);
                out[i + 3] = FRESNEL_I_MIX5_AT(i + 3, -);
            }
            for (; i < n; i++)
                out[i] = FRESNEL_I_MIX5_AT(i, -);
        }
#undef FRESNEL_I_MIX5_AT
        return;
    }
#endif
    if (f90 >= f0) {
        for (i = 0; i < n; i++)
            out[i] = fresnel_i_q30_to_q15(base + fresnel_i_mulw_q15(fresnel_i_batch_pow5_q30(fresnel_i_batch_x(c[i])), w));
    } else {
        for (i = 0; i < n; i++)
            out[i] = fresnel_i_q30_to_q15(base - fresnel_i_mulw_q15(fresnel_i_batch_pow5_q30(fresnel_i_batch_x(c[i])), w));
    }
}

void fresnel_schlick_q15_batch(int32_t f0, const fresnel_q15 *c, fresnel_q15 *out, int n)
{
    fresnel_i_mix5_batch(fresnel_i_q15_arg(f0), FRESNEL_I_ONE_Q15, c, out, n);
}

/* Three channels per cosine: x^5 once, three blends (fresnel_schlick_q15_rgb). */
void fresnel_schlick_q15_rgb_batch(fresnel_rgb_q15 f0, const fresnel_q15 *c, fresnel_rgb_q15 *out, int n)
{
    uint32_t r = fresnel_i_q15_arg(f0.r), g = fresnel_i_q15_arg(f0.g), b = fresnel_i_q15_arg(f0.b);
    int i;
#if FRESNEL_I_MVE
    {
        const uint32x4_t wr = vdupq_n_u32((FRESNEL_I_ONE_Q15 - r) << 16), wg = vdupq_n_u32((FRESNEL_I_ONE_Q15 - g) << 16),
                         wb = vdupq_n_u32((FRESNEL_I_ONE_Q15 - b) << 16);
        const uint32_t half = 1u << 14;
        /* byte offsets of four fresnel_rgb_q15 in a row */
        const uint32x4_t at = vmulq_n_u32(vidupq_n_u32(0, 1), (uint32_t)sizeof *out);
        for (i = 0; i < n; i += 4) {
            mve_pred16_t p = vctp32q((uint32_t)(n - i));
            uint32x4_t x5 = fresnel_i_pow5_mve(vldrhq_z_u32(c + i, p));
            uint16_t *row = (uint16_t *)(void *)(out + i);
            vstrhq_scatter_offset_p_u32(row, at, vshrq_n_u32(vaddq_n_u32(FRESNEL_I_MVE_Q15(x5, wr), (r << 15) + half), 15), p);
            vstrhq_scatter_offset_p_u32(row + 1, at, vshrq_n_u32(vaddq_n_u32(FRESNEL_I_MVE_Q15(x5, wg), (g << 15) + half), 15), p);
            vstrhq_scatter_offset_p_u32(row + 2, at, vshrq_n_u32(vaddq_n_u32(FRESNEL_I_MVE_Q15(x5, wb), (b << 15) + half), 15), p);
        }
        return;
    }
#endif
    for (i = 0; i < n; i++) {
        uint32_t x5 = fresnel_i_batch_pow5_q30(fresnel_i_batch_x(c[i]));
        out[i].r = fresnel_i_q30_to_q15((r << 15) + fresnel_i_mulw_q15(x5, FRESNEL_I_ONE_Q15 - r));
        out[i].g = fresnel_i_q30_to_q15((g << 15) + fresnel_i_mulw_q15(x5, FRESNEL_I_ONE_Q15 - g));
        out[i].b = fresnel_i_q30_to_q15((b << 15) + fresnel_i_mulw_q15(x5, FRESNEL_I_ONE_Q15 - b));
    }
}

/* p = 5 as Schlick's blend toward F90; any other p is the scalar call per
 * cosine (its power function is per cosine in any case). */
void fresnel_schlick_gen_q15_batch(int32_t f0, int32_t f90, fresnel_q16 p, const fresnel_q15 *c, fresnel_q15 *out,
                                   int n)
{
    int i;
    if (p == 5 * 65536) {
        fresnel_i_mix5_batch(fresnel_i_q15_arg(f0), fresnel_i_q15_arg(f90), c, out, n);
        return;
    }
    for (i = 0; i < n; i++)
        out[i] = fresnel_schlick_gen_q15(f0, f90, p, c[i]);
}

void fresnel_schlick_gen_q15_rgb_batch(fresnel_rgb_q15 f0, fresnel_rgb_q15 f90, fresnel_q16 p, const fresnel_q15 *c,
                                       fresnel_rgb_q15 *out, int n)
{
    int i;
    for (i = 0; i < n; i++)
        out[i] = fresnel_schlick_gen_q15_rgb(f0, f90, p, c[i]);
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

/* ---- batches (fresnel_q15.h, BATCHES): the scalar calls' position,
 * interpolation and clamp per cosine, n's clamp once. */
#if FRESNEL_I_MVE
/* Helium, four cosines in 32-bit lanes, every step the scalar one's.
 * fresnel_i_sqrt_q30 of c in [0, one]: the normalising m from the leading
 * zeros (the one m with c 4^m in [2^13, 2^15], as the scalar's tests find
 * it; c = 0 is read as 2^13 and given 0 at the end), the two chords
 * gathered from their tables, then the scalar's corrections. */
static uint32x4_t fresnel_i_sqrt_q30_mve(uint32x4_t c)
{
    /* m = max(clz - 17, 0) / 2; c = 0 gives 0 below, whatever its lanes read */
    uint32x4_t m = vshrq_n_u32(vqsubq_n_u32(vclzq_u32(c), 17u), 1);
    uint32x4_t cn = vshlq_u32(c, vreinterpretq_s32_u32(vshlq_n_u32(m, 1)));
    uint32x4_t q8 = vshrq_n_u32(cn, 8), q7 = vshrq_n_u32(cn, 7), si = vqsubq_n_u32(q8, 32u), ti = vqsubq_n_u32(q7, 64u);
    uint32x4_t s0 = vldrwq_gather_shifted_offset_u32(fresnel_i_sqrt_chord_q15, si);
    uint32x4_t s1 = vldrwq_gather_shifted_offset_u32(fresnel_i_sqrt_chord_q15 + 1, si);
    uint32x4_t y = vshrq_n_u32(vaddq_u32(s0, vshrq_n_u32(vmulq_u32(vsubq_u32(s1, s0), vsubq_u32(cn, vshlq_n_u32(q8, 8))), 8)), 16);
    uint32x4_t t0 = vldrwq_gather_shifted_offset_u32(fresnel_i_rsqrt_chord_q15, ti);
    uint32x4_t t1 = vldrwq_gather_shifted_offset_u32(fresnel_i_rsqrt_chord_q15 + 1, ti);
    uint32x4_t g = vsubq_u32(t0, vshrq_n_u32(vmulq_u32(vsubq_u32(t0, t1), vsubq_u32(cn, vshlq_n_u32(q7, 7))), 7));
    uint32x4_t rem = vsubq_u32(vshlq_n_u32(cn, 15), vmulq_u32(y, y)), y2 = vshlq_n_u32(y, 1), z, zl, w, b;
    mve_pred16_t big = vcmphiq_u32(rem, y2), pass;
    rem = vsubq_m_u32(rem, rem, vaddq_n_u32(y2, 1u), big);
    y = vaddq_m_n_u32(y, y, 1u, big);
    y2 = vshlq_n_u32(y, 1);
    z = FRESNEL_I_MVE_Q30(rem, vshlq_n_u32(g, 1));
    /* G = rem 2^15 - 2 y w against ceil(w^2 / 2^15), compared signed (the
     * scalar offsets both by 2^18 to compare them unsigned: |G| < 2^18) */
    w = vsubq_u32(vshlq_n_u32(rem, 15), vmulq_u32(y2, z));
    b = vmulq_u32(z, z);
    pass = vcmpgeq_s32(vreinterpretq_s32_u32(w), vreinterpretq_s32_u32(vshrq_n_u32(vaddq_n_u32(b, 32767u), 15)));
    zl = vsubq_n_u32(z, 1u);
    zl = vaddq_m_n_u32(zl, zl, 1u, pass); /* z0 - 1 + the first pass */
    w = vsubq_u32(w, y2);
    b = vaddq_u32(b, vaddq_n_u32(vshlq_n_u32(z, 1), 1u)); /* + 2 z0 + 1 */
    pass = vcmpgeq_s32(vreinterpretq_s32_u32(w), vreinterpretq_s32_u32(vshrq_n_u32(vaddq_n_u32(b, 32767u), 15)));
    zl = vaddq_m_n_u32(zl, zl, 1u, pass);
    y = vshlq_u32(vaddq_u32(vshlq_n_u32(y, 15), zl), vnegq_s32(vreinterpretq_s32_u32(m)));
    return vpselq_u32(c, y, vcmpeqq_n_u32(c, 0u)); /* c = 0: 0 */
}

/* fresnel_i_position for k = nodes + 1 >= 2 nodes, then the two nodes
 * around each lane interpolated and rounded. The position is at most
 * nodes 2^15, so i passes nodes - 1 only at the last node, where the
 * scalar takes the last segment's end: i = nodes - 1 and t = pos - i 2^15
 * give that and, below it, pos's own fraction. The linear interpolation
 * of two nodes never exceeds the larger, so fresnel_i_curve_q15's clamp
 * leaves its rounding as it is. */
static uint32x4_t fresnel_i_lut_at_mve(const uint16_t *table, uint32x4_t x, uint32_t nodes, uint32x4_t last)
{
    uint32x4_t xh = vshrq_n_u32(x, 15);
    uint32x4_t pos = vaddq_u32(vmulq_n_u32(xh, nodes),
                               vshrq_n_u32(vaddq_n_u32(vmulq_n_u32(vsubq_u32(x, vshlq_n_u32(xh, 15)), nodes), 1u << 14), 15));
    uint32x4_t i = vminq_u32(vshrq_n_u32(pos, 15), last), t = vsubq_u32(pos, vshlq_n_u32(i, 15));
    uint32x4_t v0 = vldrhq_gather_shifted_offset_u32(table, i), v1 = vldrhq_gather_shifted_offset_u32(table + 1, i);
    return vrshrq_n_u32(vaddq_u32(vshlq_n_u32(v0, 15), vmulq_u32(vsubq_u32(v1, v0), t)), 15);
}

#define FRESNEL_I_LUT_MVE_LOOP(position)                                                                               \
    const uint32x4_t last = vdupq_n_u32((uint32_t)k - 2u), one = vdupq_n_u32(FRESNEL_I_ONE_Q15);                       \
    int j;                                                                                                             \
    for (j = 0; j + 4 <= n; j += 4) {                                                                                  \
        uint32x4_t cv = vminq_u32(vldrhq_u32(c + j), one);                                                             \
        vstrhq_u32(out + j, fresnel_i_lut_at_mve(table, position, (uint32_t)k - 1u, last));                           \
    }                                                                                                                  \
    if (j < n) {                                                                                                       \
        mve_pred16_t p = vctp32q((uint32_t)(n - j));                                                                   \
        uint32x4_t cv = vminq_u32(vldrhq_z_u32(c + j, p), one);                                                        \
        vstrhq_p_u32(out + j, fresnel_i_lut_at_mve(table, position, (uint32_t)k - 1u, last), p);                      \
    }

/* Four cosines a step, a short last one predicated. */
static void fresnel_i_lut_u16_mve(const uint16_t *table, int k, const fresnel_q15 *c, fresnel_q15 *out, int n)
{
    FRESNEL_I_LUT_MVE_LOOP(fresnel_i_sqrt_q30_mve(cv))
}

static void fresnel_i_lut_linear_u16_mve(const uint16_t *table, int k, const fresnel_q15 *c, fresnel_q15 *out, int n)
{
    FRESNEL_I_LUT_MVE_LOOP(vshlq_n_u32(cv, 15))
}
#undef FRESNEL_I_LUT_MVE_LOOP
#endif

#if FRESNEL_I_LONG_MUL && !FRESNEL_I_MVE
/* A position (fresnel_i_position's pos) to its node pair and rounded
 * interpolation, for k >= 2 nodes (last = k - 2), as fresnel_i_lut_at_mve
 * explains: the same as fresnel_i_lut_u16's. */
static fresnel_q15 fresnel_i_lut_pos_u16(const uint16_t *table, uint32_t pos, uint32_t last)
{
    uint32_t i = pos >> 15, t, v0;
    i = i > last ? last : i;
    t = pos - (i << 15);
    v0 = table[i];
    return (fresnel_q15)(((v0 << 15) + (table[i + 1] - v0) * t + (1u << 14)) >> 15);
}

/* Forced inline under GCC and Clang: the per-cosine path of the loops
 * below, where -O2 would otherwise call it; the rare exact path a call. */
#if defined(__GNUC__)
#define FRESNEL_I_BATCH_INLINE static inline __attribute__((always_inline))
#define FRESNEL_I_BATCH_CALL static __attribute__((noinline))
#else
#define FRESNEL_I_BATCH_INLINE static inline
#define FRESNEL_I_BATCH_CALL static
#endif

/* pos = floor((S kk + 2^14) / 2^15), S = fresnel_i_sqrt_q30(c) */
FRESNEL_I_BATCH_CALL uint32_t fresnel_i_sqrt_pos_exact(uint32_t c, uint32_t kk)
{
    return (uint32_t)(((uint64_t)fresnel_i_sqrt_q30(c) * kk + (1u << 14)) >> 15);
}

/* The position of c (a code in [0, one]) in a table uniform in sqrt(c),
 * fresnel_i_sqrt_pos_exact's, for kk = k - 1, taking S's last two
 * corrections only where they can matter. In fresnel_i_sqrt_q30's terms
 * (math_q15.h): c' = c 4^m in [2^13, 2^15], m from the leading zeros;
 * X = c' 2^15, s = sqrt(X); g from the reciprocal chord, in
 * [2^44 / s, (2^44 / s)(1 + 2^-15.4)]. Then X g / 2^44 is in
 * [s, s + 2^15 2^-15.4] = [s, s + 0.76], so its floor is y = floor(s) or
 * y + 1; y + 1 shows as X - (y + 1)^2 < 0 (>= -(2 y + 1), held signed),
 * and stepping back gives y and rem = X - y^2 in [0, 2 y], the scalar's.
 * z0 = floor(rem g / 2^30) is z - 1, z or z + 1 (the scalar's comment), so
 * S0 = floor((y 2^15 + z0) / 2^m) is within 1 of S, and S kk + 2^14 is
 * S0 kk + 2^14 moved by at most kk. When the low 15 bits of the latter are
 * in [kk, 2^15 - 1 - kk], that move crosses no multiple of 2^15 and S0
 * gives pos; otherwise (about 2 kk in 2^15 cosines, and every cosine when
 * 2 kk >= 2^15: lim = 0) S itself is taken. c = 0 gives pos 0, as S = 0
 * does. */
FRESNEL_I_BATCH_INLINE uint32_t fresnel_i_sqrt_pos(uint32_t c, uint32_t kk, uint32_t lim)
{
    const uint32_t *t;
    uint32_t m, y, g, x, rem;
    uint64_t p;
    if (c == 0)
        return 0;
#if defined(__GNUC__)
    m = (uint32_t)__builtin_clz(c);
    m = m > 17u ? (m - 17u) >> 1 : 0u;
#else
    for (m = 0; (c << (2u * m)) < (1u << 13); m++)
        ;
#endif
    x = c << (2u * m);
    t = fresnel_i_rsqrt_chord_q15 + ((x >> 7) - 64u);
    g = t[0] - (((t[0] - t[1]) * (x & 127u)) >> 7);
    x <<= 15;
    y = (uint32_t)(((uint64_t)x * g) >> 44);
    rem = x - y * y;
    if ((int32_t)rem < 0) {
        y--;
        rem += 2u * y + 1u;
    }
    p = (uint64_t)(((y << 15) + fresnel_i_mulhi(rem << 2, g)) >> m) * kk + (1u << 14);
    if (((uint32_t)p & 0x7fffu) - kk < lim)
        return (uint32_t)(p >> 15);
    return fresnel_i_sqrt_pos_exact(c, kk);
}
#endif

void fresnel_lut_u16_q15_batch(const uint16_t *table, int nodes, const fresnel_q15 *c, fresnel_q15 *out, int n)
{
    int i;
#if FRESNEL_I_MVE || FRESNEL_I_LONG_MUL
    int k = fresnel_i_qlut_n(nodes);
#endif
#if FRESNEL_I_MVE
    if (k >= 2) {
        fresnel_i_lut_u16_mve(table, k, c, out, n);
        return;
    }
#elif FRESNEL_I_LONG_MUL
    if (k >= 2) {
        uint32_t kk = (uint32_t)k - 1u, lim = kk < (1u << 14) ? (1u << 15) - 2u * kk : 0u;
        for (i = 0; i < n; i++)
            out[i] = fresnel_i_lut_pos_u16(table, fresnel_i_sqrt_pos(fresnel_i_batch_c(c[i]), kk, lim), kk - 1u);
        return;
    }
#endif
    for (i = 0; i < n; i++)
        out[i] = fresnel_lut_u16_q15(table, nodes, c[i]);
}

void fresnel_lut_linear_u16_q15_batch(const uint16_t *table, int nodes, const fresnel_q15 *c, fresnel_q15 *out, int n)
{
    int i;
#if FRESNEL_I_MVE || FRESNEL_I_LONG_MUL
    int k = fresnel_i_qlut_n(nodes);
#endif
#if FRESNEL_I_MVE
    if (k >= 2) {
        fresnel_i_lut_linear_u16_mve(table, k, c, out, n);
        return;
    }
#elif FRESNEL_I_LONG_MUL
    /* x = c 2^15 has no fraction bits: the position is c (k - 1) exactly */
    if (k >= 2) {
        for (i = 0; i < n; i++)
            out[i] = fresnel_i_lut_pos_u16(table, fresnel_i_batch_c(c[i]) * (uint32_t)(k - 1), (uint32_t)k - 2u);
        return;
    }
#endif
    for (i = 0; i < n; i++)
        out[i] = fresnel_lut_linear_u16_q15(table, nodes, c[i]);
}

void fresnel_lut_cubic_u16_q15_batch(const uint16_t *table, int nodes, const fresnel_q15 *c, fresnel_q15 *out, int n)
{
    int i;
    for (i = 0; i < n; i++)
        out[i] = fresnel_lut_cubic_u16_q15(table, nodes, c[i]);
}

#if FRESNEL_I_LONG_MUL && !FRESNEL_I_MVE
/* One position, the three channels' tables (k nodes each) read at it. */
static fresnel_rgb_q15 fresnel_i_lut_pos_u16_rgb(const uint16_t *table, int k, uint32_t pos)
{
    fresnel_rgb_q15 v;
    v.r = fresnel_i_lut_pos_u16(table, pos, (uint32_t)k - 2u);
    v.g = fresnel_i_lut_pos_u16(table + k, pos, (uint32_t)k - 2u);
    v.b = fresnel_i_lut_pos_u16(table + 2 * k, pos, (uint32_t)k - 2u);
    return v;
}
#endif

void fresnel_lut_u16_q15_rgb_batch(const uint16_t *table, int nodes, const fresnel_q15 *c, fresnel_rgb_q15 *out, int n)
{
    int i;
#if FRESNEL_I_LONG_MUL && !FRESNEL_I_MVE
    int k = fresnel_i_qlut_n(nodes);
    if (k >= 2) {
        uint32_t kk = (uint32_t)k - 1u, lim = kk < (1u << 14) ? (1u << 15) - 2u * kk : 0u;
        for (i = 0; i < n; i++)
            out[i] = fresnel_i_lut_pos_u16_rgb(table, k, fresnel_i_sqrt_pos(fresnel_i_batch_c(c[i]), kk, lim));
        return;
    }
#endif
    for (i = 0; i < n; i++)
        out[i] = fresnel_lut_u16_q15_rgb(table, nodes, c[i]);
}

void fresnel_lut_linear_u16_q15_rgb_batch(const uint16_t *table, int nodes, const fresnel_q15 *c, fresnel_rgb_q15 *out,
                                          int n)
{
    int i;
#if FRESNEL_I_LONG_MUL && !FRESNEL_I_MVE
    int k = fresnel_i_qlut_n(nodes);
    if (k >= 2) {
        for (i = 0; i < n; i++)
            out[i] = fresnel_i_lut_pos_u16_rgb(table, k, fresnel_i_batch_c(c[i]) * (uint32_t)(k - 1));
        return;
    }
#endif
    for (i = 0; i < n; i++)
        out[i] = fresnel_lut_linear_u16_q15_rgb(table, nodes, c[i]);
}

void fresnel_lut_cubic_u16_q15_rgb_batch(const uint16_t *table, int nodes, const fresnel_q15 *c, fresnel_rgb_q15 *out,
                                         int n)
{
    int i;
    for (i = 0; i < n; i++)
        out[i] = fresnel_lut_cubic_u16_q15_rgb(table, nodes, c[i]);
}

#else
typedef int fresnel_i_batch_q15_disabled;
#endif
