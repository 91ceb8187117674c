/* Helpers shared by the binary16 model files (src/f16/\*.c); not public.
 *
 * Every arithmetic operation goes through one of the fresnel_i_h* helpers, whose
 * return converts to _Float16: in C99 that conversion (like an assignment
 * or a cast) discards any excess precision, so each operation is one
 * rounding to binary16 even where the compiler evaluates _Float16
 * expressions in float (FLT_EVAL_METHOD 32). See fresnel_f16.h.
 *
 * Where the error bounds of fresnel_f16.h come from: most models lose 2-8
 * half-ulps, the rounding of 1 - c (ulp 2^-11 near 1) multiplied by the
 * slope of (1-c)^5. Near a dielectric's critical angle the reflectance's
 * slope is infinite and binary16's rounding of (eta-1)(eta+1) + c^2 decides
 * total reflection: where the critical angle lies within a binary16 step of
 * a cosine the result can be 1 for 0.5 (eta 0.0703 at c = 1 - 2^-11: 0.485
 * off). binary32 needs exact squares there, and the GLSL port evaluates
 * those models in highp for this reason. The LUT bound is the position's
 * rounding times the steepest table step: sqrt(c) (n-1), the root and the
 * product each rounded to half (ulp 1/8 for positions in [128, 256)). */
#ifndef FRESNEL_F16_INTERNAL_H
#define FRESNEL_F16_INTERNAL_H

#include "fresnel_f16.h"

/* FRESNEL_CFG_NO_F16: nothing, not even <math.h>, which a freestanding
 * fixed-point-only toolchain may lack. */
#if FRESNEL_HAS_F16

/* The NaN policy (fresnel.h CONVENTIONS) compares against NaN and the exact
 * forms rely on IEEE rounding: -ffast-math and its parts break both silently
 * (critical-angle results off by up to 1), so they stop the build here. */
#if defined(__FAST_MATH__) || defined(__FINITE_MATH_ONLY__) && __FINITE_MATH_ONLY__
#error "fresnel: compile the runtime (its sources in src/, or the file that defines FRESNEL_IMPLEMENTATION before including a single-file header) without -ffast-math / -Ofast / -ffinite-math-only: add -fno-fast-math for it; see fresnel.h THREAD SAFETY"
#endif

#include <math.h>

typedef fresnel_f16 fresnel_i_h;

static inline fresnel_i_h fresnel_i_hc(float x) { return (fresnel_i_h)x; } /* a constant, rounded once */
static inline fresnel_i_h fresnel_i_hadd(fresnel_i_h a, fresnel_i_h b) { return (fresnel_i_h)(a + b); }
static inline fresnel_i_h fresnel_i_hsub(fresnel_i_h a, fresnel_i_h b) { return (fresnel_i_h)(a - b); }
static inline fresnel_i_h fresnel_i_hmul(fresnel_i_h a, fresnel_i_h b) { return (fresnel_i_h)(a * b); }
static inline fresnel_i_h fresnel_i_hdiv(fresnel_i_h a, fresnel_i_h b) { return (fresnel_i_h)(a / b); }
/* Correctly rounded: sqrtf is correctly rounded and binary32 has more than
 * 2 * 11 + 2 significand bits, so rounding its result to half again is
 * the same as rounding the exact root. */
static inline fresnel_i_h fresnel_i_hsqrt(fresnel_i_h a) { return (fresnel_i_h)sqrtf((float)a); }

/* a == b for clamped values (no NaN, no -0), by representation: a
 * _Float16 == compiles to a libgcc call (__eqhf2) on x86-64, even written
 * as a float comparison. */
static inline int fresnel_i_heq(fresnel_i_h a, fresnel_i_h b)
{
    union {
        fresnel_i_h h;
        unsigned short u;
    } x, y;
    x.h = a;
    y.h = b;
    return x.u == y.u;
}

/* Clamp into [lo, hi]; NaN (which fails both comparisons) lands on lo. */
static inline fresnel_i_h fresnel_i_hclamp(fresnel_i_h x, fresnel_i_h lo, fresnel_i_h hi) { return x > lo ? (x < hi ? x : hi) : lo; }
static inline fresnel_i_h fresnel_i_hunit(fresnel_i_h x) { return fresnel_i_hclamp(x, fresnel_i_hc(0.0f), fresnel_i_hc(1.0f)); }
static inline fresnel_i_h fresnel_i_heta(fresnel_i_h x) { return fresnel_i_hclamp(x, fresnel_i_hc(FRESNEL_ETA_MIN_F16), fresnel_i_hc(FRESNEL_ETA_MAX_F16)); }
static inline fresnel_i_h fresnel_i_hkappa(fresnel_i_h x) { return fresnel_i_hclamp(x, fresnel_i_hc(0.0f), fresnel_i_hc(FRESNEL_KAPPA_MAX_F16)); }

static inline fresnel_i_h fresnel_i_hpow5(fresnel_i_h x)
{
    fresnel_i_h x2 = fresnel_i_hmul(x, x);
    return fresnel_i_hmul(fresnel_i_hmul(x2, x2), x);
}

/* (1 - c)^p as a GPU's pow: exp(p ln(1 - c)) with the logarithm, the
 * product and the exponential each rounded to half. c = 1 gives 0. */
static inline fresnel_i_h fresnel_i_hpow_one_minus(fresnel_i_h c, fresnel_i_h p)
{
    fresnel_i_h l, y;
    if (!(c < fresnel_i_hc(1.0f)))
        return fresnel_i_hc(0.0f);
    l = (fresnel_i_h)log1pf(-(float)c);
    y = fresnel_i_hmul(p, l);
    return (fresnel_i_h)expf((float)y);
}

/* hypot without overflow: M sqrt(1 + (S/M)^2) for a, b >= 0. */
static inline fresnel_i_h fresnel_i_hhypot(fresnel_i_h a, fresnel_i_h b)
{
    fresnel_i_h big = a > b ? a : b, small = a > b ? b : a, r;
    if (!(big > fresnel_i_hc(0.0f)))
        return fresnel_i_hc(0.0f);
    r = fresnel_i_hdiv(small, big);
    return fresnel_i_hmul(big, fresnel_i_hsqrt(fresnel_i_hadd(fresnel_i_hc(1.0f), fresnel_i_hmul(r, r))));
}

/* Schlick in half (also used by the residual LUT). */
FRESNEL_I_HIDDEN fresnel_i_h fresnel_i_schlick_h(fresnel_i_h f0, fresnel_i_h c);
/* 1 - exact reflectance, for Cook-Torrance (exact_f16.c). */
FRESNEL_I_HIDDEN fresnel_i_h fresnel_i_conductor_transmittance_h(fresnel_i_h eta, fresnel_i_h kappa, fresnel_i_h c);
/* the approximate conductor form for clamped n, k (approx_conductor_f16.c) */
FRESNEL_I_HIDDEN fresnel_i_h fresnel_i_approx_conductor_h(fresnel_i_h n, fresnel_i_h k, fresnel_i_h c);

#endif
#endif
