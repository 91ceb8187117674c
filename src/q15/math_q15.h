/* The fixed-point arithmetic of src/q15/ (defined in math_q15.c and inline
 * below); not public. Nothing here calls into the model files, and nothing
 * inline here calls math_q15.c: math_q15.c needs only this header, the
 * model files reach it through internal.h.
 *
 * Two kinds of arithmetic, both in 32-bit integers only:
 *
 * 1. Plain fixed point, for Schlick, F82 and the LUTs: unsigned values in
 *    [0, 1] held as Q30 (1 = 2^30) and Q15 (1 = 2^15). A product of two Q30
 *    values is formed from 15-bit halves (fresnel_i_mul_q30), so x^5 keeps 30 bits
 *    without int64.
 *
 * 2. fresnel_qf, value = m 2^e with m in [2^30, 2^31), for the models whose
 *    intermediates span many octaves (exact, approximate conductor,
 *    Gulbrandsen, LSK's powers, F0 helpers). Operations truncate to 31 bits,
 *    a relative error below 2^-29 per operation; they are defined in
 *    math_q15.c and work on non-negative values only: every formula that
 *    uses them is arranged so that signs are handled outside (see exact_q15.c).
 *
 * Range analysis convention: the comment "R:" after a statement states the
 * range of what it computes; tests/runtime/q15/test_q15_bounds.c re-checks the
 * interesting ones through FRESNEL_I_RANGE (active only when the test build
 * defines FRESNEL_RANGE_CHECK).
 */
#ifndef FRESNEL_Q15_MATH_H
#define FRESNEL_Q15_MATH_H

#include <stdint.h>

#include "fresnel_q15.h"

#if FRESNEL_HAS_Q15

#define FRESNEL_I_ONE_Q15 32768u
#define FRESNEL_I_ONE_Q30 (1u << 30)

/* Range assertions of the range analysis. A test build defines
 * FRESNEL_RANGE_CHECK and a function fresnel_i_range_fail that records the
 * violation; the runtime build compiles them away. */
#ifdef FRESNEL_RANGE_CHECK
FRESNEL_I_HIDDEN void fresnel_i_range_fail(const char *what, long long value);
#define FRESNEL_I_RANGE(what, x, lo, hi)                                                                 \
    do {                                                                                           \
        long long v_ = (long long)(x), lo_ = (long long)(lo), hi_ = (long long)(hi);              \
        if (v_ < lo_ || v_ > hi_)                                                                  \
            fresnel_i_range_fail((what), v_);                                                            \
    } while (0)
#else
#define FRESNEL_I_RANGE(what, x, lo, hi) ((void)0)
#endif

/* floor(a b / 2^15) for a < 2^31, b <= 2^15.
 * R: a>>15 < 2^16 and b <= 2^15 give (a>>15) b < 2^31; (a & 0x7fff) b < 2^30;
 * the sum is floor(a b / 2^15) < 2^31. Exact floor: a b / 2^15 =
 * (a>>15) b + (a & 0x7fff) b / 2^15. */
static inline uint32_t fresnel_i_mul_q30_q15(uint32_t a, uint32_t b)
{
    FRESNEL_I_RANGE("mul_q30_q15 a", a, 0, 0x7fffffffu);
    FRESNEL_I_RANGE("mul_q30_q15 b", b, 0, 1u << 15);
    return (a >> 15) * b + (((a & 0x7fffu) * b) >> 15);
}

/* floor(a b / 2^30) for a < 2^31, b <= 2^30, from 15-bit halves.
 * R: ah = a>>15 < 2^16, bh = b>>15 <= 2^15, al, bl < 2^15;
 * ah bh < 2^31; ah bl < 2^31; al bh <= 2^30; al bl < 2^30, >>15 < 2^15;
 * middle sum < 2^31 + 2^30 + 2^15 < 2^32; result = floor(a b / 2^30) < 2^31.
 * Exact floor: a b = ah bh 2^30 + (ah bl + al bh) 2^15 + al bl. */
static inline uint32_t fresnel_i_mul_q30(uint32_t a, uint32_t b)
{
    uint32_t ah = a >> 15, al = a & 0x7fffu, bh = b >> 15, bl = b & 0x7fffu;
    FRESNEL_I_RANGE("mul_q30 a", a, 0, 0x7fffffffu);
    FRESNEL_I_RANGE("mul_q30 b", b, 0, 1u << 30);
    return ah * bh + ((ah * bl + al * bh + ((al * bl) >> 15)) >> 15);
}

/* x^5 in Q30 for x in Q15, x <= 2^15.
 * R: x^2 <= 2^30 exact; x^4 = floor(x2 x2 / 2^30) <= 2^30; x^5 <= 2^30.
 * Error: two floors, each < 2^-30, the first multiplied by x <= 1:
 * x^5 is 0 to 2 units of 2^-30 low. */
static inline uint32_t fresnel_i_pow5_q30(uint32_t x)
{
    uint32_t x2 = x * x;
    FRESNEL_I_RANGE("pow5 x", x, 0, 1u << 15);
    uint32_t x4 = fresnel_i_mul_q30(x2, x2);
    return fresnel_i_mul_q30_q15(x4, x);
}

/* ---- the batches' bodies (fresnel_q15.h, BATCHES). Each computes the
 * exact floors above, so all give the scalar calls' results bit for bit.
 *
 * FRESNEL_I_LONG_MUL: the target multiplies 32 x 32 -> 64 bits in one
 * instruction (every Arm core but Armv6-M and Armv8-M Baseline: UMULL;
 * RISC-V with M: MUL and MULHU; x86-64, AArch64), so a product floored by
 * 2^k is one multiply and a shift instead of four multiplies of 15-bit
 * halves. Armv6-M (Cortex-M0, M0+) and Armv8-M Baseline (M23) would call a
 * library routine for it: there the batches use the halves. */
#ifndef FRESNEL_I_LONG_MUL
#if defined(__ARM_ARCH_6M__) || defined(__ARM_ARCH_8M_BASE__)
#define FRESNEL_I_LONG_MUL 0
#else
#define FRESNEL_I_LONG_MUL 1
#endif
#endif

#if FRESNEL_I_LONG_MUL
/* floor(a b / 2^32): the high word of the product, one instruction (UMULL,
 * MULHU). The products below are this with operands shifted so that the
 * floor falls on the word boundary: floor(a b / 2^k) = floor((a 2^i)(b 2^j)
 * / 2^32) for i + j = 32 - k, each shifted operand below 2^32. */
static inline uint32_t fresnel_i_mulhi(uint32_t a, uint32_t b) { return (uint32_t)(((uint64_t)a * b) >> 32); }
/* floor(a b / 2^30), a < 2^31, b <= 2^30: fresnel_i_mul_q30's value */
static inline uint32_t fresnel_i_mulw_q30(uint32_t a, uint32_t b) { return fresnel_i_mulhi(a << 1, b << 1); }
/* floor(a b / 2^15), a < 2^31, b <= 2^15: fresnel_i_mul_q30_q15's value */
static inline uint32_t fresnel_i_mulw_q15(uint32_t a, uint32_t b) { return fresnel_i_mulhi(a << 1, b << 16); }
#else
#define fresnel_i_mulw_q30 fresnel_i_mul_q30
#define fresnel_i_mulw_q15 fresnel_i_mul_q30_q15
#endif

/* x^5 in Q30 (fresnel_i_pow5_q30's value) with the batches' products. */
static inline uint32_t fresnel_i_batch_pow5_q30(uint32_t x)
{
    uint32_t x2 = x * x;
    return fresnel_i_mulw_q15(fresnel_i_mulw_q30(x2, x2), x);
}

/* A cosine code of a batch's input as fresnel_i_q15_arg reads it: codes
 * above one are one. */
static inline uint32_t fresnel_i_batch_c(uint32_t c) { return c > FRESNEL_I_ONE_Q15 ? FRESNEL_I_ONE_Q15 : c; }

/* 1 - c for such a code, c in [0, 65535]: one - c held to [0, one], one
 * USAT where the target saturates (Armv6 and later, not Armv6-M). */
#if defined(__ARM_FEATURE_SAT) && __ARM_FEATURE_SAT
#include <arm_acle.h>
static inline uint32_t fresnel_i_batch_x(uint32_t c) { return (uint32_t)__usat((int32_t)FRESNEL_I_ONE_Q15 - (int32_t)c, 16); }
#else
static inline uint32_t fresnel_i_batch_x(uint32_t c) { return FRESNEL_I_ONE_Q15 - fresnel_i_batch_c(c); }
#endif

/* Helium (Armv8.1-M MVE): four 32-bit lanes; floor(a b / 2^k) as the high
 * words of the products of shifted operands, as fresnel_i_mulhi. */
#if defined(__ARM_FEATURE_MVE) && (__ARM_FEATURE_MVE & 1) && !defined(FRESNEL_I_NO_MVE)
#include <arm_mve.h>
#define FRESNEL_I_MVE 1
/* floor(a b / 2^15), a < 2^31, b <= 2^15; b16 = b << 16 */
#define FRESNEL_I_MVE_Q15(a, b16) vmulhq_u32(vshlq_n_u32((a), 1), (b16))
/* floor(a b / 2^30), a < 2^31, b <= 2^30; b1 = b << 1 */
#define FRESNEL_I_MVE_Q30(a, b1) vmulhq_u32(vshlq_n_u32((a), 1), (b1))
#else
#define FRESNEL_I_MVE 0
#endif

/* Round a Q30 value in [0, 2^30] to Q15 (half up). R: v + 2^14 < 2^31. */
static inline fresnel_q15 fresnel_i_q30_to_q15(uint32_t v)
{
    FRESNEL_I_RANGE("result in Q30", v, 0, 1u << 30);
    return (fresnel_q15)((v + (1u << 14)) >> 15);
}

/* Clamp a signed Q30 value to [0, 2^30] and round to Q15. */
static inline fresnel_q15 fresnel_i_q30s_to_q15(int32_t v)
{
    return v <= 0 ? (fresnel_q15)0 : (v >= (int32_t)FRESNEL_I_ONE_Q30 ? (fresnel_q15)FRESNEL_I_ONE_Q15 : fresnel_i_q30_to_q15((uint32_t)v));
}

/* ---- fresnel_qf (math_q15.c). Non-negative values; zero is m == 0. */
FRESNEL_I_HIDDEN fresnel_qf fresnel_i_qf(uint32_t x, int32_t e); /* x 2^e, normalised (x any uint32) */
FRESNEL_I_HIDDEN fresnel_qf fresnel_i_qf_mul(fresnel_qf a, fresnel_qf b);
FRESNEL_I_HIDDEN fresnel_qf fresnel_i_qf_add(fresnel_qf a, fresnel_qf b);
/* |a - b|; *negative set when a < b (may be NULL when a >= b is known) */
FRESNEL_I_HIDDEN fresnel_qf fresnel_i_qf_sub(fresnel_qf a, fresnel_qf b, int *negative);
FRESNEL_I_HIDDEN fresnel_qf fresnel_i_qf_div(fresnel_qf a, fresnel_qf b); /* b != 0 */
FRESNEL_I_HIDDEN fresnel_qf fresnel_i_qf_sqrt(fresnel_qf a);
/* round(a 2^frac), saturating at 2^32 - 1 */
FRESNEL_I_HIDDEN uint32_t fresnel_i_qf_to_fix(fresnel_qf a, int32_t frac);
/* a < b: -1, a == b: 0, a > b: 1 */
FRESNEL_I_HIDDEN int fresnel_i_qf_cmp(fresnel_qf a, fresnel_qf b);
/* a 2^k */
static inline fresnel_qf fresnel_i_qf_scale(fresnel_qf a, int32_t k)
{
    a.e += k;
    return a;
}

/* The tables of fresnel_i_sqrt_q30 (defined in lut_q15.c, its user). */
FRESNEL_I_HIDDEN extern const uint32_t fresnel_i_sqrt_chord_q15[98];
FRESNEL_I_HIDDEN extern const uint32_t fresnel_i_rsqrt_chord_q15[194];

/* sqrt(c) in Q30 for c in Q15, [0, 2^15]: floor(sqrt(c 2^45)), the value
 * of the digit-by-digit root (fresnel_isqrt_u32's method) carried to 30
 * bits, here from two tables and a fixed sequence of steps: 7 multiplies,
 * no loop (tests/runtime/q15/test_q15_math.c compares it with the definition for
 * every c).
 *
 * Normalise: c' = c 4^m in [2^13, 2^15] (m <= 7: shifts by 8, 4 and 2
 * bits); the result is floor(R / 2^m) for R = floor(sqrt(c' 2^45)), as
 * floor(floor(v) / 2^m) = floor(v / 2^m). With s = sqrt(X), X = c' 2^15
 * in [2^28, 2^30], R = y 2^15 + z for y = floor(s) in [2^14, 2^15] and
 * z = floor(2^15 u), u = s - y in [0, 1).
 *
 * y: the chord of fresnel_i_sqrt_chord_q15 (s in units of 2^-16 at every
 * 256th c') over c''s segment is below s (sqrt is concave, the table and the
 * interpolation floored) by less than 0.51: the chord's sag, 256^2 / 8
 * times |d^2 sqrt(x 2^15) / dx^2| <= 2^-14, is at most 1/2. Its integer
 * part yh is y or y - 1, and X - yh^2 > 2 yh exactly when it is y - 1;
 * then y = yh + 1 and rem = X - y^2 = X - yh^2 - 2 yh - 1, in [0, 2y].
 * R: s[1] - s[0] < 2^24, times d <= 255 < 2^32; the chord <= 2^31.
 *
 * g, about 2^44 / s: the chord of fresnel_i_rsqrt_chord_q15 (ceil(2^44 / s)
 * at every 128th c'). 1/sqrt is convex, the table rounded up and the
 * interpolation's step down, so g >= 2^44 / s, and g is at most 2^-15.4
 * relative above it (the chord's gap, (3/32)(128 / 2^13)^2; measured for
 * every c' by tests/runtime/q15/test_q15_math.c).
 * R: t[0] - t[1] < 2^23, times d <= 127 < 2^30; g in [2^29, 2^30].
 *
 * z: u = rem / (2y + u), so 2^15 rem / (2s) = 2^15 (u - u^2 / (2s)) is in
 * (2^15 u - 1, 2^15 u] (2s >= 2^15), and g's excess adds at most
 * 2^15 2^-15.4 = 0.76: z0 = floor(rem g / 2^30) is z - 1, z or z + 1.
 * rem g from 15-bit halves of g: R: rem < 2^16, g >> 15 <= 2^15,
 * g & 0x7fff < 2^15, each product < 2^31.
 * A candidate w is at most z when (y 2^15 + w)^2 <= X 2^30, i.e.
 * w^2 + 2 y w 2^15 <= rem 2^30: with G = rem 2^15 - 2 y w, when
 * G >= ceil(w^2 / 2^15). Tested at w = z0 and z0 + 1: z = z0 - 1 + the
 * number that pass. R: rem 2^15 < 2^31, 2 y w <= 2^31 + 2^16, w^2 < 2^31;
 * for w in [z - 1, z + 2], |G| < 2^18, held as G + 2^18 in (0, 2^19) in
 * uint32. */
static inline uint32_t fresnel_i_sqrt_q30(uint32_t c)
{
    const uint32_t *s, *t;
    uint32_t m = 0, y, x, rem, big, g, z, w, b, pass;
    FRESNEL_I_RANGE("sqrt_q30 c", c, 0, FRESNEL_I_ONE_Q15);
    if (c == 0)
        return 0;
    if (c < (1u << 13)) {
        if (c < (1u << 7)) {
            c <<= 8;
            m = 4;
        }
        if (c < (1u << 11)) {
            c <<= 4;
            m += 2;
        }
        if (c < (1u << 13)) {
            c <<= 2;
            m += 1;
        }
    }
    s = fresnel_i_sqrt_chord_q15 + ((c >> 8) - 32u);
    y = (s[0] + (((s[1] - s[0]) * (c & 255u)) >> 8)) >> 16;
    t = fresnel_i_rsqrt_chord_q15 + ((c >> 7) - 64u);
    g = t[0] - (((t[0] - t[1]) * (c & 127u)) >> 7);
    x = c << 15;
    rem = x - y * y;
    big = rem > 2u * y;
    rem -= big ? 2u * y + 1u : 0u;
    y += big;
    FRESNEL_I_RANGE("sqrt_q30 y", y, 1u << 14, 1u << 15);
    FRESNEL_I_RANGE("sqrt_q30 rem", rem, 0, 2u * y);
    z = (rem * (g >> 15) + ((rem * (g & 0x7fffu)) >> 15)) >> 15;
    w = (rem << 15) + (1u << 18) - 2u * y * z;
    b = z * z;
    pass = w >= ((b + 32767u) >> 15) + (1u << 18);
    w -= 2u * y;
    b += 2u * z + 1u;
    pass += w >= ((b + 32767u) >> 15) + (1u << 18);
    z = z + pass - 1u;
    FRESNEL_I_RANGE("sqrt_q30 low bits", z, 0, 32767);
    return ((y << 15) + z) >> m;
}

/* The power function's tables (math_q15.c), exposed for their test. */
FRESNEL_I_HIDDEN extern const uint16_t fresnel_i_log2_r[64];
FRESNEL_I_HIDDEN extern const uint32_t fresnel_i_log2_t[64];
FRESNEL_I_HIDDEN extern const uint32_t fresnel_i_exp2_t[64];

/* x^p for x in Q15 ([0, 2^15]) and p in Q16.16 (p > 0): relative error
 * below 2^-24 for p <= 64, 2^-21 for p <= 1000 (math_q15.c). */
FRESNEL_I_HIDDEN fresnel_qf fresnel_i_pow_q15(uint32_t x, uint32_t p);

#endif /* FRESNEL_HAS_Q15 */
#endif
