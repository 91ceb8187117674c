/* Helpers shared by the binary32 model files (src/f32/\*.c); not public. */
#ifndef FRESNEL_INTERNAL_H
#define FRESNEL_INTERNAL_H

#include "fresnel.h"

/* FRESNEL_CFG_NO_FLOAT: nothing here, so that a fixed-point-only build of
 * all of src/ does not need <math.h> (freestanding toolchains without libm). */
#if FRESNEL_HAS_FLOAT

/* The NaN policy (fresnel.h CONVENTIONS) compares against NaN and the exact
 * forms rely on IEEE rounding: -ffast-math and its parts break both silently
 * (critical-angle results off by up to 1), so they stop the build here. */
#if defined(__FAST_MATH__) || defined(__FINITE_MATH_ONLY__) && __FINITE_MATH_ONLY__
#error "fresnel: compile the runtime (its sources in src/, or the file that defines FRESNEL_IMPLEMENTATION before including a single-file header) without -ffast-math / -Ofast / -ffinite-math-only: add -fno-fast-math for it; see fresnel.h THREAD SAFETY"
#endif

#include <float.h>
#include <math.h>
#include <stdint.h>

/* No contraction into fused multiply-adds: the error-free transformations
 * below need each product rounded, and the batches (simd.h) give the scalar
 * functions' results bit for bit. gcc contracts in its GNU modes (the
 * default, and CMake's) and under -ffp-contract=fast, and ignores the ISO
 * pragma: its optimize pragma turns contraction off for every function
 * defined after it, whatever the command line says. Other compilers take
 * the ISO pragma; clang disregards it under -ffp-contract=fast (fresnel.h
 * THREAD SAFETY). Both last, as the ISO pragma does, to the end of the
 * translation unit. */
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC optimize("fp-contract=off")
#else
#pragma STDC FP_CONTRACT OFF
#endif

/* The error-free squares below rely on the IEEE binary32 layout. */
typedef char fresnel_i_binary32_check[(FLT_MANT_DIG == 24 && FLT_MAX_EXP == 128) ? 1 : -1];

/* Clamp into [lo, hi]. Written with comparisons so that NaN (which fails
 * both) lands on lo and +-Inf on the nearer end: this one line is the whole
 * input policy stated in fresnel.h. */
static inline float fresnel_i_clamp(float x, float lo, float hi)
{
    return x > lo ? (x < hi ? x : hi) : lo;
}

static inline float fresnel_i_unit(float x) { return fresnel_i_clamp(x, 0.0f, 1.0f); }
static inline float fresnel_i_eta(float x) { return fresnel_i_clamp(x, FRESNEL_ETA_MIN, FRESNEL_ETA_MAX); }
/* kappa below FRESNEL_KAPPA_TINY is 0: its square would underflow and the
 * interface could not tell it from a dielectric in any case. */
static inline float fresnel_i_kappa(float x)
{
    return x >= FRESNEL_KAPPA_TINY ? (x < FRESNEL_KAPPA_MAX ? x : FRESNEL_KAPPA_MAX) : 0.0f;
}

/* x^5 by three multiplications: no powf on the hot path. */
static inline float fresnel_i_pow5(float x)
{
    float x2 = x * x;
    return x2 * x2 * x;
}

/* The target has a fused multiply-add instruction, so fmaf is one
 * instruction: gcc says so by FP_FAST_FMAF (math.h, from its
 * __FP_FAST_FMAF), clang 14 only by the instruction set's own macro (x86
 * FMA, Arm's __ARM_FEATURE_FMA: AArch64, FPv4 and later). */
#if defined(FP_FAST_FMAF) || defined(__FMA__) || defined(__ARM_FEATURE_FMA)
#define FRESNEL_I_FAST_FMA 1
#else
#define FRESNEL_I_FAST_FMA 0
#endif

/* x*x = hi + lo exactly: by a fused multiply-add where the target has one,
 * else by Dekker's split, which keeps the top 12 significand bits by
 * masking, so that no compiler contraction or reassociation can disturb it.
 * Both give the exact lo, so the same hi + lo. */
static inline void fresnel_i_square_exact(float x, float *hi, float *lo)
{
#if FRESNEL_I_FAST_FMA
    *hi = x * x;
    *lo = fmaf(x, x, -*hi);
#else
    union {
        float f;
        uint32_t u;
    } split;
    float xh, xl;
    split.f = x;
    split.u &= 0xfffff000u;
    xh = split.f;
    xl = x - xh;
    *hi = x * x;
    *lo = ((xh * xh - *hi) + 2.0f * xh * xl) + xl * xl;
#endif
}

/* eta^2 - kappa^2 - sin^2(theta) = (eta^2 + c^2 - 1) - kappa^2.
 * Near the critical angle eta^2 + c^2 - 1 is the difference of nearly equal
 * numbers and its square root is taken next, so a rounding of eta^2 or c^2
 * (6e-8) would become an error of 1e-4 in the reflectance. Both squares are
 * formed exactly and summed with their rounding error carried (Knuth's
 * TwoSum), so the result is correct to a rounding of itself. */
/* Where the target has binary64 in hardware, the same in binary64: eta^2 and
 * c^2 are exact there (48 bits), and so nearly is their sum, at a third of
 * the operations. */
#if defined(__SSE2__) || defined(__aarch64__) || (defined(__ARM_FP) && (__ARM_FP & 8)) || \
    (defined(__riscv_flen) && __riscv_flen >= 64)
#define FRESNEL_I_HW_DOUBLE 1
#else
#define FRESNEL_I_HW_DOUBLE 0
#endif
static inline float fresnel_i_eta2_minus_sin2(float eta, float c, float kappa2)
{
#if FRESNEL_I_HW_DOUBLE
    double e = eta, x = c;
    return (float)(((e * e - 1.0) + x * x) - (double)kappa2);
#else
    float eh, el, ch, cl, s, t, err;
    fresnel_i_square_exact(eta, &eh, &el);
    fresnel_i_square_exact(c, &ch, &cl);
    s = eh + ch;
    t = s - eh;
    err = (eh - (s - t)) + (ch - t);
    /* s - 1 is exact where it can cancel (s in [0.5, 2], Sterbenz). */
    return (s - 1.0f) + ((err + el + cl) - kappa2);
#endif
}

/* The top 12 significand bits of x, by masking (see fresnel_i_square_exact). */
static inline float fresnel_i_split_hi(float x)
{
    union {
        float f;
        uint32_t u;
    } split;
    split.f = x;
    split.u &= 0xfffff000u;
    return split.f;
}

/* (1 - c)^p for c in [0, 1], p > 0, as exp(p log1p(-c)): powf(1 - c, p) would
 * first round 1 - c, an error that p multiplies. The product y = p l is
 * formed exactly as hi + lo (Dekker) and exp(hi + lo) = exp(hi)(1 + lo):
 * the rounding of y would be an error of |y| 2^-24 relative, and |y| reaches
 * ln(a c), about 5, where the LSK compensation term matters. */
static inline float fresnel_i_pow_one_minus(float c, float p)
{
    float l, hi, lo, e, ph, pl, lh, ll;
    if (!(c < 1.0f))
        return 0.0f;
    l = log1pf(-c);
    hi = p * l;
    ph = fresnel_i_split_hi(p);
    pl = p - ph;
    lh = fresnel_i_split_hi(l);
    ll = l - lh;
    lo = ((ph * lh - hi) + ph * ll + pl * lh) + pl * ll;
    e = expf(hi);
    return e + e * lo;
}

/* C99's restrict; C++, which compiles these files in a unity build (the
 * single-file runtime included from a .cpp), spells it __restrict. */
#ifdef __cplusplus
#define FRESNEL_I_RESTRICT __restrict
#else
#define FRESNEL_I_RESTRICT restrict
#endif

/* Apply a scalar model channel by channel. */
#define FRESNEL_I_RGB(expr_r, expr_g, expr_b) \
    do { fresnel_rgb out_; out_.r = (expr_r); out_.g = (expr_g); out_.b = (expr_b); return out_; } while (0)

/* 1 - fresnel_conductor(eta, kappa, c), computed directly so that it keeps
 * its relative precision when the reflectance is close to 1 (exact.c). */
FRESNEL_I_HIDDEN float fresnel_i_conductor_transmittance(float eta, float kappa, float c);

#endif /* FRESNEL_HAS_FLOAT */
#endif
