/* Helpers shared by the binary16 model files (src/\*_f16.c); not public.
 *
 * Every arithmetic operation goes through one of the fr__h* helpers, whose
 * return converts to _Float16: in C99 that conversion (like an assignment
 * or a cast) discards any excess precision, so each operation is one
 * rounding to binary16 even where the compiler evaluates _Float16
 * expressions in float (FLT_EVAL_METHOD 32). See fresnel_f16.h. */
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
#error "fresnel: compile src/ without -ffast-math / -Ofast / -ffinite-math-only (add -fno-fast-math for these files); see fresnel.h THREAD SAFETY"
#endif

#include <math.h>

typedef fresnel_f16 fr__h;

static inline fr__h fr__hc(float x) { return (fr__h)x; } /* a constant, rounded once */
static inline fr__h fr__hadd(fr__h a, fr__h b) { return (fr__h)(a + b); }
static inline fr__h fr__hsub(fr__h a, fr__h b) { return (fr__h)(a - b); }
static inline fr__h fr__hmul(fr__h a, fr__h b) { return (fr__h)(a * b); }
static inline fr__h fr__hdiv(fr__h a, fr__h b) { return (fr__h)(a / b); }
/* Correctly rounded: sqrtf is correctly rounded and binary32 has more than
 * 2 * 11 + 2 significand bits, so rounding its result to half again is
 * the same as rounding the exact root. */
static inline fr__h fr__hsqrt(fr__h a) { return (fr__h)sqrtf((float)a); }

/* a == b for clamped values (no NaN, no -0), by representation: a
 * _Float16 == compiles to a libgcc call (__eqhf2) on x86-64, even written
 * as a float comparison. */
static inline int fr__heq(fr__h a, fr__h b)
{
    union {
        fr__h h;
        unsigned short u;
    } x, y;
    x.h = a;
    y.h = b;
    return x.u == y.u;
}

/* Clamp into [lo, hi]; NaN (which fails both comparisons) lands on lo. */
static inline fr__h fr__hclamp(fr__h x, fr__h lo, fr__h hi) { return x > lo ? (x < hi ? x : hi) : lo; }
static inline fr__h fr__hunit(fr__h x) { return fr__hclamp(x, fr__hc(0.0f), fr__hc(1.0f)); }
static inline fr__h fr__heta(fr__h x) { return fr__hclamp(x, fr__hc(FRESNEL_F16_ETA_MIN), fr__hc(FRESNEL_F16_ETA_MAX)); }
static inline fr__h fr__hkappa(fr__h x) { return fr__hclamp(x, fr__hc(0.0f), fr__hc(FRESNEL_F16_KAPPA_MAX)); }

static inline fr__h fr__hpow5(fr__h x)
{
    fr__h x2 = fr__hmul(x, x);
    return fr__hmul(fr__hmul(x2, x2), x);
}

/* (1 - c)^p as a GPU's pow: exp(p ln(1 - c)) with the logarithm, the
 * product and the exponential each rounded to half. c = 1 gives 0. */
static inline fr__h fr__hpow_one_minus(fr__h c, fr__h p)
{
    fr__h l, y;
    if (!(c < fr__hc(1.0f)))
        return fr__hc(0.0f);
    l = (fr__h)log1pf(-(float)c);
    y = fr__hmul(p, l);
    return (fr__h)expf((float)y);
}

/* hypot without overflow: M sqrt(1 + (S/M)^2) for a, b >= 0. */
static inline fr__h fr__hhypot(fr__h a, fr__h b)
{
    fr__h big = a > b ? a : b, small = a > b ? b : a, r;
    if (!(big > fr__hc(0.0f)))
        return fr__hc(0.0f);
    r = fr__hdiv(small, big);
    return fr__hmul(big, fr__hsqrt(fr__hadd(fr__hc(1.0f), fr__hmul(r, r))));
}

/* Schlick in half (also used by the residual LUT). */
fr__h fr__schlick_h(fr__h f0, fr__h c);
/* 1 - exact reflectance, for Cook-Torrance (exact_f16.c). */
fr__h fr__conductor_transmittance_h(fr__h eta, fr__h kappa, fr__h c);
/* the approximate conductor form for clamped n, k (approx_conductor_f16.c) */
fr__h fr__approx_conductor_h(fr__h n, fr__h k, fr__h c);

#endif
#endif
