/* Hemispherical averages of uint16_t lookup tables (fresnel_fixed.h): the
 * weighted node sums of src/f32/lut_avg.c (whose header comment derives
 * the weights) in integers.
 *
 * Each weight is made in Q31 from h = 1/(n-1) and x_i = i/(n-1), both the
 * floor from fresnel_udiv_frac_u32, by rounded products
 * (fresnel_i_mul_q31); polynomials in h whose terms have both signs are
 * summed as a positive and a negative part, each scaled into [0, 1). A
 * weight is within a few units of 2^-31; over n nodes of value below 2 that
 * is at most about n 2^-28 of the result, n 2^-13 LSB, and much less as the
 * roundings cancel (the bound in the header is measured for n <= 1024). The sum of node x weight, 16 x 31 bits, is accumulated
 * exactly in two words: the high 15 bits of each weight times the node in
 * units of 2^-30, the low 16 bits in units of 2^-46 with their carries. */
#include "internal.h"

#if FRESNEL_HAS_FIXED

#define FRESNEL_I_AVG_N_MAX 32768

/* round(a b / 2^31) (halves up) for a, b <= 2^31, exactly: rounded, so
 * that the weights' errors do not all lean one way. R: ah, bh <= 2^15, so
 * ah bh <= 2^30 and ah bl + al bh <= 2^32 - 2^17 - 2; with lo >> 16 < 2^16
 * and the half, 2^14, mid stays below 2^32. */
static uint32_t fresnel_i_mul_q31(uint32_t a, uint32_t b)
{
    uint32_t ah = a >> 16, al = a & 0xffffu, bh = b >> 16, bl = b & 0xffffu;
    uint32_t mid = ah * bl + al * bh + ((al * bl) >> 16) + (1u << 14);
    return ((ah * bh) << 1) + (mid >> 15);
}

/* Constants below are round(v 2^31), v in the comment beside each. */
/* The weight of node i (Q31 magnitude, *negative set for a negative one)
 * of an n-node table, 2 <= n <= FRESNEL_I_AVG_N_MAX; form 0 linear in
 * sqrt(c), 1 Catmull-Rom in sqrt(c), 2 linear in c. Ranges: every weight
 * is below 1; the scaled polynomial parts are in [0, 1]. */
static uint32_t fresnel_i_avg_weight_q31(int form, int n, int i, int *negative)
{
    uint32_t last = (uint32_t)n - 1u, h = fresnel_udiv_frac_u32(1u, last, 31);
    uint32_t x = fresnel_udiv_frac_u32((uint32_t)i, last, 31);
    uint32_t h2 = fresnel_i_mul_q31(h, h), h3 = fresnel_i_mul_q31(h2, h), h4 = fresnel_i_mul_q31(h2, h2);
    uint32_t x3 = fresnel_i_mul_q31(fresnel_i_mul_q31(x, x), x), pos, neg;
    *negative = 0;
    if (form == 2) { /* uniform in c: h^2/3, 2h c_i, h - h^2/3 */
        if (i == 0)
            return fresnel_i_mul_q31(h2, 715827883u /* 1 / 3 */);
        if ((uint32_t)i == last)
            return h - fresnel_i_mul_q31(h2, 715827883u /* 1 / 3 */);
        return fresnel_i_mul_q31(h, x) << 1;
    }
    if (form == 0) { /* linear in sqrt(c) */
        if (i == 0)
            return fresnel_i_mul_q31(h4, 429496730u /* 0.2 */);
        if ((uint32_t)i == last) { /* 4h (1/2 + h^2/4 - h/2 - h^3/20) */
            pos = (1u << 30) + (h2 >> 2);
            neg = (h >> 1) + fresnel_i_mul_q31(h3, 107374182u /* 0.05 */);
            return fresnel_i_mul_q31(h, pos - neg) << 2;
        }
        return (fresnel_i_mul_q31(x3, h) << 2) + (fresnel_i_mul_q31(h3, x) << 1);
    }
    if (n == 2) {
        static const uint32_t w2[2] = {368140054u /* 6 / 35 */, 1779343594u /* 29 / 35 */};
        return w2[i];
    }
    if (n == 3) {
        static const uint32_t w3[3] = {42182715u /* 11 / 560 */, 850045611u /* 19 / 48 */,
                                       1339620752u /* 131 / 210 */};
        *negative = i == 0;
        return w3[i];
    }
    if (i == 0) { /* -4h^4 11/140 */
        *negative = 1;
        return fresnel_i_mul_q31(h4, 674923432u /* 11 / 35 */);
    }
    if ((uint32_t)i == last) { /* 4h (11/24 + 11h^3/140 - 3h/10 - h^2/40) */
        pos = 984263339u /* 11 / 24 */ + fresnel_i_mul_q31(h3, 168730858u /* 11 / 140 */);
        neg = fresnel_i_mul_q31(h, 644245094u /* 0.3 */) + fresnel_i_mul_q31(h2, 53687091u /* 1 / 40 */);
        return fresnel_i_mul_q31(h, pos - neg) << 2;
    }
    if ((uint32_t)i == last - 1u) { /* 16h (25/96 + 121h^2/160 - 59h/80 - 209h^3/840), N >= 3 */
        pos = 559240533u /* 25 / 96 */ + fresnel_i_mul_q31(h2, 1624034509u /* 121 / 160 */);
        neg = fresnel_i_mul_q31(h, 1583769190u /* 59 / 80 */) + fresnel_i_mul_q31(h3, 534314384u /* 209 / 840 */);
        return fresnel_i_mul_q31(h, pos - neg) << 4;
    }
    if (i == 1) /* 4h^4 209/210 */
        return fresnel_i_mul_q31(h4, 534314384u /* 209 / 840 */) << 4;
    return fresnel_i_mul_q31(x3, h) << 2;
}

/* Two-word accumulator of node x weight: hi in 2^-30, lo in 2^-46. */
typedef struct fresnel_i_acc {
    uint32_t hi, lo;
} fresnel_i_acc;

static void fresnel_i_acc_add(fresnel_i_acc *a, uint32_t v, uint32_t w)
{
    uint32_t lo = v * (w & 0xffffu);
    a->hi += v * (w >> 16);
    a->lo += lo;
    if (a->lo < lo)
        a->hi += 1u << 16; /* 2^32 units of 2^-46 */
}

static fresnel_q15 fresnel_i_avg_u16(const uint16_t *table, int n, int form)
{
    fresnel_i_acc plus = {0u, 0u}, minus = {0u, 0u};
    uint32_t top = FRESNEL_I_ONE_Q15, s, m, r;
    int i, negative;
    if (n <= 1)
        return n == 1 ? table[0] : 0;
    for (i = 0; i < n; i++) {
        uint32_t w = fresnel_i_avg_weight_q31(form, n, i, &negative);
        fresnel_i_acc_add(negative ? &minus : &plus, table[i], w);
        top = table[i] > top ? table[i] : top;
    }
    s = plus.hi + (plus.lo >> 16);
    m = minus.hi + (minus.lo >> 16);
    if (m >= s)
        return 0;
    r = (s - m + (1u << 14)) >> 15;
    return (fresnel_q15)(r < top ? r : top);
}

static int fresnel_i_avg_n(int n) { return n <= 0 ? 0 : (n > FRESNEL_I_AVG_N_MAX ? FRESNEL_I_AVG_N_MAX : n); }

fresnel_q15 fresnel_lut_avg_u16_q15(const uint16_t *table, int n)
{
    return fresnel_i_avg_u16(table, fresnel_i_avg_n(n), 0);
}
fresnel_q15 fresnel_lut_cubic_avg_u16_q15(const uint16_t *table, int n)
{
    return fresnel_i_avg_u16(table, fresnel_i_avg_n(n), 1);
}
fresnel_q15 fresnel_lut_linear_avg_u16_q15(const uint16_t *table, int n)
{
    return fresnel_i_avg_u16(table, fresnel_i_avg_n(n), 2);
}

static fresnel_rgb_q15 fresnel_i_avg_u16_rgb(const uint16_t *table, int n, int form)
{
    n = fresnel_i_avg_n(n);
    FRESNEL_I_RGB_Q15(fresnel_i_avg_u16(table, n, form), fresnel_i_avg_u16(table + n, n, form),
                      fresnel_i_avg_u16(table + 2 * n, n, form));
}

fresnel_rgb_q15 fresnel_lut_avg_u16_q15_rgb(const uint16_t *table, int n)
{
    return fresnel_i_avg_u16_rgb(table, n, 0);
}
fresnel_rgb_q15 fresnel_lut_cubic_avg_u16_q15_rgb(const uint16_t *table, int n)
{
    return fresnel_i_avg_u16_rgb(table, n, 1);
}
fresnel_rgb_q15 fresnel_lut_linear_avg_u16_q15_rgb(const uint16_t *table, int n)
{
    return fresnel_i_avg_u16_rgb(table, n, 2);
}

#else
typedef int fresnel_i_lut_avg_q15_disabled;
#endif
