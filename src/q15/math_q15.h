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
 * range of what it computes; tests/test_fixed_bounds.c re-checks the
 * interesting ones through FRESNEL_I_RANGE (active only when the test build
 * defines FRESNEL_RANGE_CHECK).
 */
#ifndef FRESNEL_Q15_MATH_H
#define FRESNEL_Q15_MATH_H

#include <stdint.h>

#include "fresnel_fixed.h"

#if FRESNEL_HAS_FIXED

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

/* The power function's tables (math_q15.c), exposed for their test. */
FRESNEL_I_HIDDEN extern const uint16_t fresnel_i_log2_r[64];
FRESNEL_I_HIDDEN extern const uint32_t fresnel_i_log2_t[64];
FRESNEL_I_HIDDEN extern const uint32_t fresnel_i_exp2_t[64];

/* x^p for x in Q15 ([0, 2^15]) and p in Q16.16 (p > 0): relative error
 * below 2^-24 for p <= 64, 2^-21 for p <= 1000 (math_q15.c). */
FRESNEL_I_HIDDEN fresnel_qf fresnel_i_pow_q15(uint32_t x, uint32_t p);

#endif /* FRESNEL_HAS_FIXED */
#endif
