/* The conductor batch kernel shared by exact.c and exact_avx.c (not
 * public): the forms of fresnel_conductor_prep and, where simd.h has a
 * vector type, the kernel at its width. */
#include "simd.h"

#ifndef FRESNEL_EXACT_BATCH_H
#define FRESNEL_EXACT_BATCH_H

#include <stddef.h>

#if FRESNEL_HAS_FLOAT
/* fresnel_conductor_prep.kind (exact.c) */
enum { FRESNEL_I_MATCHED, FRESNEL_I_DIEL, FRESNEL_I_COND1, FRESNEL_I_COND2 };

/* x86-64 builds for a target without AVX (the SSE2 baseline) carry the
 * batch's 8-lane kernel as well (exact_avx.c, compiled for AVX2 and FMA by a
 * target pragma) and take it where the CPU reports both (__builtin_cpu_supports,
 * which reads the feature word the compiler's runtime fills in once at
 * start-up; the library keeps no state of its own). */
#if FRESNEL_I_SIMD_DISPATCH && FRESNEL_HAS_SIMD && defined(__x86_64__) && defined(__SSE2__) && \
    !defined(__AVX__) && defined(__GNUC__) && !defined(FRESNEL_I_FORCE_AVX)
#define FRESNEL_I_AVX_DISPATCH 1
FRESNEL_I_HIDDEN void fresnel_i_conductor_batch_avx(const fresnel_conductor_prep *p, const float *c, float *out,
                                                    int n);
/* p[0..2] of one form, not the matched index; out holds 3n floats */
FRESNEL_I_HIDDEN void fresnel_i_conductor_rgb_batch_avx(const fresnel_conductor_prep p[3], const float *c, float *out,
                                                        int n);
#else
#define FRESNEL_I_AVX_DISPATCH 0
#endif

#endif /* FRESNEL_HAS_FLOAT */
#endif /* FRESNEL_EXACT_BATCH_H */

/* The kernel, at simd.h's width: once per inclusion of simd.h's vector
 * part (twice in a translation unit that holds exact.c and exact_avx.c). */
#if FRESNEL_HAS_FLOAT && FRESNEL_I_VW && \
    (defined(FRESNEL_I_FORCE_AVX) ? !defined(FRESNEL_EXACT_BATCH_AVX_PART) : !defined(FRESNEL_EXACT_BATCH_PART))
#ifdef FRESNEL_I_FORCE_AVX
#define FRESNEL_EXACT_BATCH_AVX_PART
#else
#define FRESNEL_EXACT_BATCH_PART
#endif
#undef FRESNEL_I_VBATCH
#undef FRESNEL_I_VBATCH_RGB
/* The batch: the same operations in the same order on FRESNEL_I_VW lanes
 * (simd.h), two vectors per step for independent work between the square
 * roots and the divide; the last n mod VW cosines go through one vector
 * on a padded copy, so nothing beyond n is read or written. */
struct fresnel_i_vprep {
    fresnel_i_vf a0, a0_lo, ek, ek4;
};

/* The terms of the cosine that do not depend on the material (cl, the low
 * part of c^2, only where A is not formed by a fused multiply-add). */
struct fresnel_i_vcos {
    fresnel_i_vf c, ch, s2, s4, c2;
#if !FRESNEL_I_FAST_FMA
    fresnel_i_vf cl;
#endif
};

static inline struct fresnel_i_vcos fresnel_i_vcos_terms(fresnel_i_vf c)
{
    const fresnel_i_vf one = fresnel_i_vset(1.0f);
    struct fresnel_i_vcos t;
    t.c = fresnel_i_vunit(c);
    t.ch = fresnel_i_vmul(t.c, t.c);
#if FRESNEL_I_FAST_FMA
    t.s2 = fresnel_i_vfnma(t.c, t.c, one);
#else
    t.cl = fresnel_i_vsquare_lo(t.c, t.ch);
    t.s2 = fresnel_i_vmul(fresnel_i_vsub(one, t.c), fresnel_i_vadd(one, t.c));
#endif
    t.s4 = fresnel_i_vmul(t.s2, t.s2);
    t.c2 = fresnel_i_vadd(t.c, t.c);
    return t;
}

static inline fresnel_i_vf fresnel_i_vexact_terms(const struct fresnel_i_vprep *q, const struct fresnel_i_vcos *t,
                                                  int kind)
{
    const fresnel_i_vf one = fresnel_i_vset(1.0f);
    fresnel_i_vf a, m, tt, b, x, y, c2y, xs, xq, ns, ds, dp, f;
#if FRESNEL_I_FAST_FMA
    a = fresnel_i_vadd(fresnel_i_vfma(t->c, t->c, q->a0), q->a0_lo);
#else
    a = fresnel_i_vadd(fresnel_i_vadd(q->a0, t->ch), fresnel_i_vadd(q->a0_lo, t->cl));
#endif
    if (kind == FRESNEL_I_DIEL) {
        m = fresnel_i_vabs(a);
        tt = m;
    } else {
#if FRESNEL_I_FAST_FMA
        m = fresnel_i_vsqrt(fresnel_i_vfma(a, a, q->ek4));
#else
        m = fresnel_i_vsqrt(fresnel_i_vadd(fresnel_i_vmul(a, a), q->ek4));
#endif
        tt = fresnel_i_vmul(fresnel_i_vset(0.5f), fresnel_i_vadd(m, fresnel_i_vabs(a)));
    }
    b = fresnel_i_vsqrt(tt);
    /* a is neither NaN nor -0: a0 + ch would be -0 only if ch were */
    x = fresnel_i_vsel_nonneg(a, one, b);
    y = fresnel_i_vsel_nonneg(a, b, q->ek);
    c2y = fresnel_i_vmul(t->c2, y);
    xs = fresnel_i_vmul(x, fresnel_i_vadd(m, t->ch));
#if FRESNEL_I_FAST_FMA
    xq = fresnel_i_vmul(x, fresnel_i_vfma(t->ch, m, t->s4));
#else
    xq = fresnel_i_vmul(x, fresnel_i_vadd(fresnel_i_vmul(t->ch, m), t->s4));
#endif
    ns = fresnel_i_vsub(xs, c2y);
    ds = fresnel_i_vadd(xs, c2y);
#if FRESNEL_I_FAST_FMA
    dp = fresnel_i_vfma(c2y, t->s2, xq);
#else
    dp = fresnel_i_vadd(xq, fresnel_i_vmul(c2y, t->s2));
#endif
    if (kind == FRESNEL_I_COND2)
        f = fresnel_i_vmul(fresnel_i_vdiv(ns, ds), fresnel_i_vdiv(xq, dp));
    else
        f = fresnel_i_vdiv(fresnel_i_vmul(ns, xq), fresnel_i_vmul(ds, dp));
    /* f <= 1 by construction (exact.c): only the lower clamp can act */
    return fresnel_i_vmax(f, fresnel_i_vset(0.0f));
}

static inline fresnel_i_vf fresnel_i_vexact(const struct fresnel_i_vprep *q, fresnel_i_vf c, int kind)
{
    struct fresnel_i_vcos t = fresnel_i_vcos_terms(c);
    return fresnel_i_vexact_terms(q, &t, kind);
}

static inline void fresnel_i_vprep_set(struct fresnel_i_vprep *q, const fresnel_conductor_prep *p)
{
    q->a0 = fresnel_i_vset(p->a0);
    q->a0_lo = fresnel_i_vset(p->a0_lo);
    q->ek = fresnel_i_vset(p->ek);
    q->ek4 = fresnel_i_vset(p->ek4);
}

#define FRESNEL_I_VBATCH(name, kind)                                                                   \
    static void name(const fresnel_conductor_prep *p, const float *c, float *out, int n)                \
    {                                                                                                  \
        struct fresnel_i_vprep q;                                                                      \
        int i;                                                                                         \
        fresnel_i_vprep_set(&q, p);                                                                    \
        for (i = 0; n - i >= 2 * FRESNEL_I_VW; i += 2 * FRESNEL_I_VW) {                                \
            fresnel_i_vf f0 = fresnel_i_vexact(&q, fresnel_i_vload(c + i), kind);                      \
            fresnel_i_vf f1 = fresnel_i_vexact(&q, fresnel_i_vload(c + i + FRESNEL_I_VW), kind);       \
            fresnel_i_vstore(out + i, f0);                                                             \
            fresnel_i_vstore(out + i + FRESNEL_I_VW, f1);                                              \
        }                                                                                              \
        for (; n - i >= FRESNEL_I_VW; i += FRESNEL_I_VW)                                               \
            fresnel_i_vstore(out + i, fresnel_i_vexact(&q, fresnel_i_vload(c + i), kind));             \
        if (i < n) {                                                                                   \
            float buf[FRESNEL_I_VW];                                                                   \
            int j, k = n - i;                                                                          \
            for (j = 0; j < FRESNEL_I_VW; j++)                                                         \
                buf[j] = j < k ? c[i + j] : 1.0f;                                                      \
            fresnel_i_vstore(buf, fresnel_i_vexact(&q, fresnel_i_vload(buf), kind));                   \
            for (j = 0; j < k; j++)                                                                    \
                out[i + j] = buf[j];                                                                   \
        }                                                                                              \
    }
/* Three channels of one form (fresnel_conductor_rgb_batch): each vector's
 * cosine terms once, the three materials' parts, the rows of three written
 * by fresnel_i_vstore3; two vectors per step as in FRESNEL_I_VBATCH, the
 * last n mod VW cosines through a stack block of 4 VW floats (256 bytes at
 * 16 lanes). out holds 3n floats. */
#define FRESNEL_I_VBATCH_RGB(name, kind)                                                               \
    static void name(const fresnel_conductor_prep p[3], const float *c, float *out, int n)             \
    {                                                                                                  \
        struct fresnel_i_vprep q[3];                                                                   \
        struct fresnel_i_vcos t;                                                                       \
        int i;                                                                                         \
        fresnel_i_vprep_set(&q[0], &p[0]);                                                             \
        fresnel_i_vprep_set(&q[1], &p[1]);                                                             \
        fresnel_i_vprep_set(&q[2], &p[2]);                                                             \
        for (i = 0; n - i >= 2 * FRESNEL_I_VW; i += 2 * FRESNEL_I_VW) {                                \
            struct fresnel_i_vcos t1 = fresnel_i_vcos_terms(fresnel_i_vload(c + i + FRESNEL_I_VW));    \
            fresnel_i_vf r0, g0, b0, r1, g1, b1;                                                       \
            t = fresnel_i_vcos_terms(fresnel_i_vload(c + i));                                          \
            r0 = fresnel_i_vexact_terms(&q[0], &t, kind);                                              \
            r1 = fresnel_i_vexact_terms(&q[0], &t1, kind);                                             \
            g0 = fresnel_i_vexact_terms(&q[1], &t, kind);                                              \
            g1 = fresnel_i_vexact_terms(&q[1], &t1, kind);                                             \
            b0 = fresnel_i_vexact_terms(&q[2], &t, kind);                                              \
            b1 = fresnel_i_vexact_terms(&q[2], &t1, kind);                                             \
            fresnel_i_vstore3(out + 3 * (size_t)i, r0, g0, b0);                                        \
            fresnel_i_vstore3(out + 3 * (size_t)i + 3 * FRESNEL_I_VW, r1, g1, b1);                     \
        }                                                                                              \
        for (; n - i >= FRESNEL_I_VW; i += FRESNEL_I_VW) {                                             \
            t = fresnel_i_vcos_terms(fresnel_i_vload(c + i));                                          \
            fresnel_i_vstore3(out + 3 * (size_t)i, fresnel_i_vexact_terms(&q[0], &t, kind),            \
                              fresnel_i_vexact_terms(&q[1], &t, kind), fresnel_i_vexact_terms(&q[2], &t, kind)); \
        }                                                                                              \
        if (i < n) {                                                                                   \
            float buf[4 * FRESNEL_I_VW];                                                               \
            int j, k = n - i;                                                                          \
            for (j = 0; j < FRESNEL_I_VW; j++)                                                         \
                buf[j] = j < k ? c[i + j] : 1.0f;                                                      \
            t = fresnel_i_vcos_terms(fresnel_i_vload(buf));                                            \
            fresnel_i_vstore3(buf + FRESNEL_I_VW, fresnel_i_vexact_terms(&q[0], &t, kind),             \
                              fresnel_i_vexact_terms(&q[1], &t, kind), fresnel_i_vexact_terms(&q[2], &t, kind)); \
            for (j = 0; j < 3 * k; j++)                                                                \
                out[3 * (size_t)i + j] = buf[FRESNEL_I_VW + j];                                        \
        }                                                                                              \
    }
#endif /* the kernel */
