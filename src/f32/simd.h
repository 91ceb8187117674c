/* Binary32 vectors for the batch kernels of src/f32/ (not public): one set of
 * inline operations per instruction set, chosen at compile time from the
 * compiler's target macros, so a kernel is written once and built at the
 * width the target has:
 *   __AVX512F__  16 lanes    __AVX__ 8 lanes    __SSE2__ 4 lanes
 *   (FRESNEL_I_FORCE_AVX: the AVX2 kernel that exact_avx.c compiles, with
 *   FMA for the exact square only, for run-time selection in an SSE2 build)
 *   __ARM_NEON on AArch64 (which has vector sqrt and divide) 4 lanes.
 * FRESNEL_CFG_NO_SIMD, or none of these, gives FRESNEL_I_VW 0 and the
 * kernels' scalar loops. Every operation is the IEEE one of the scalar code
 * (sqrt and divide correctly rounded, no contraction), so a lane gives the
 * scalar function's result bit for bit; fresnel_i_vfms (a b - c, one
 * rounding) only where the scalar code uses fmaf (FRESNEL_I_FAST_FMA,
 * internal.h). fresnel_i_vstore3 writes three vectors as rows of three
 * floats (fresnel_rgb): shuffles (SSE2, AVX), lane permutations and blends
 * (AVX2, AVX-512 by halves), vst3q (NEON). */
#ifndef FRESNEL_SIMD_H
#define FRESNEL_SIMD_H

#include "internal.h"

/* 0: no run-time choice of kernel (the tests' way to reach the SSE2
 * kernel on a CPU with AVX; exact_batch.h). */
#ifndef FRESNEL_I_SIMD_DISPATCH
#define FRESNEL_I_SIMD_DISPATCH 1
#endif

#if FRESNEL_HAS_FLOAT && FRESNEL_HAS_SIMD && defined(__SSE2__)
#include <emmintrin.h>
/* p[3i], p[3i+1], p[3i+2] = r[i], g[i], b[i] for 4 lanes: rows of three
 * (fresnel_rgb) from three vectors, by shuffles. */
static inline void fresnel_i_store3_128(float *p, __m128 r, __m128 g, __m128 b)
{
    __m128 rg = _mm_unpacklo_ps(r, g);                             /* r0 g0 r1 g1 */
    __m128 gb = _mm_unpacklo_ps(g, b);                             /* g0 b0 g1 b1 */
    __m128 rg_hi = _mm_unpackhi_ps(r, g);                          /* r2 g2 r3 g3 */
    __m128 gb_hi = _mm_unpackhi_ps(g, b);                          /* g2 b2 g3 b3 */
    __m128 br = _mm_shuffle_ps(b, r, _MM_SHUFFLE(1, 1, 0, 0));     /* b0 b0 r1 r1 */
    __m128 br_hi = _mm_shuffle_ps(b, r, _MM_SHUFFLE(3, 3, 2, 2));  /* b2 b2 r3 r3 */
    _mm_storeu_ps(p, _mm_shuffle_ps(rg, br, _MM_SHUFFLE(2, 0, 1, 0)));         /* r0 g0 b0 r1 */
    _mm_storeu_ps(p + 4, _mm_shuffle_ps(gb, rg_hi, _MM_SHUFFLE(1, 0, 3, 2)));  /* g1 b1 r2 g2 */
    _mm_storeu_ps(p + 8, _mm_shuffle_ps(br_hi, gb_hi, _MM_SHUFFLE(3, 2, 2, 0))); /* b2 r3 g3 b3 */
}
#endif
#endif /* FRESNEL_SIMD_H */

/* The vector part: once at the build's width and, where exact_avx.c
 * compiles the 8-lane kernel (FRESNEL_I_FORCE_AVX, which gives its names an
 * _avx suffix), once more at 8 lanes, so that both kernels can share one
 * translation unit (a unity build; the single-file runtime of
 * ports/single.sh). */
#if defined(FRESNEL_I_FORCE_AVX) && !defined(FRESNEL_SIMD_AVX_PART)
#define FRESNEL_SIMD_AVX_PART
#define FRESNEL_I_SIMD_PART 1
#elif !defined(FRESNEL_I_FORCE_AVX) && !defined(FRESNEL_SIMD_PART)
#define FRESNEL_SIMD_PART
#define FRESNEL_I_SIMD_PART 1
#else
#define FRESNEL_I_SIMD_PART 0
#endif
#if FRESNEL_I_SIMD_PART
#undef FRESNEL_I_VW
#undef FRESNEL_I_VSEL_SIGN
#if FRESNEL_HAS_FLOAT && FRESNEL_HAS_SIMD && (defined(__AVX2__) || defined(FRESNEL_I_FORCE_AVX))
#include <immintrin.h>
/* The same for 8 lanes: each vector's lanes permuted to the positions they
 * take in the three output rows of 8 floats (lane i goes to float 3i + k),
 * then each row blended from the three. */
static inline void fresnel_i_store3_256(float *p, __m256 r, __m256 g, __m256 b)
{
    __m256 rp = _mm256_permutevar8x32_ps(r, _mm256_setr_epi32(0, 3, 6, 1, 4, 7, 2, 5));
    __m256 gp = _mm256_permutevar8x32_ps(g, _mm256_setr_epi32(5, 0, 3, 6, 1, 4, 7, 2));
    __m256 bp = _mm256_permutevar8x32_ps(b, _mm256_setr_epi32(2, 5, 0, 3, 6, 1, 4, 7));
    _mm256_storeu_ps(p, _mm256_blend_ps(_mm256_blend_ps(rp, gp, 0x92), bp, 0x24));      /* r g b r g b r g */
    _mm256_storeu_ps(p + 8, _mm256_blend_ps(_mm256_blend_ps(rp, gp, 0x24), bp, 0x49));  /* b r g b r g b r */
    _mm256_storeu_ps(p + 16, _mm256_blend_ps(_mm256_blend_ps(rp, gp, 0x49), bp, 0x92)); /* g b r g b r g b */
}
#endif

#if FRESNEL_HAS_FLOAT && FRESNEL_HAS_SIMD

#if defined(__AVX512F__)
#include <immintrin.h>
#define FRESNEL_I_VW 16
typedef __m512 fresnel_i_vf;
typedef __mmask16 fresnel_i_vm;
static inline fresnel_i_vf fresnel_i_vset(float x) { return _mm512_set1_ps(x); }
static inline fresnel_i_vf fresnel_i_vload(const float *p) { return _mm512_loadu_ps(p); }
static inline void fresnel_i_vstore(float *p, fresnel_i_vf x) { _mm512_storeu_ps(p, x); }
static inline fresnel_i_vf fresnel_i_vadd(fresnel_i_vf a, fresnel_i_vf b) { return _mm512_add_ps(a, b); }
static inline fresnel_i_vf fresnel_i_vsub(fresnel_i_vf a, fresnel_i_vf b) { return _mm512_sub_ps(a, b); }
static inline fresnel_i_vf fresnel_i_vmul(fresnel_i_vf a, fresnel_i_vf b) { return _mm512_mul_ps(a, b); }
static inline fresnel_i_vf fresnel_i_vdiv(fresnel_i_vf a, fresnel_i_vf b) { return _mm512_div_ps(a, b); }
static inline fresnel_i_vf fresnel_i_vsqrt(fresnel_i_vf a) { return _mm512_sqrt_ps(a); }
static inline fresnel_i_vf fresnel_i_vabs(fresnel_i_vf a) { return _mm512_abs_ps(a); }
static inline fresnel_i_vm fresnel_i_vge(fresnel_i_vf a, fresnel_i_vf b) { return _mm512_cmp_ps_mask(a, b, _CMP_GE_OQ); }
static inline fresnel_i_vf fresnel_i_vsel(fresnel_i_vm m, fresnel_i_vf a, fresnel_i_vf b) { return _mm512_mask_blend_ps(m, b, a); }
/* a > b ? a : b and a < b ? a : b, as written (NaN a gives b). */
static inline fresnel_i_vf fresnel_i_vmax(fresnel_i_vf a, fresnel_i_vf b) { return _mm512_max_ps(a, b); }
static inline fresnel_i_vf fresnel_i_vmin(fresnel_i_vf a, fresnel_i_vf b) { return _mm512_min_ps(a, b); }
static inline fresnel_i_vf fresnel_i_vsplit_hi(fresnel_i_vf a)
{
    return _mm512_castsi512_ps(_mm512_and_si512(_mm512_castps_si512(a), _mm512_set1_epi32((int)0xfffff000u)));
}
static inline __m256 fresnel_i_vhi256(fresnel_i_vf a)
{
    return _mm256_castpd_ps(_mm512_extractf64x4_pd(_mm512_castps_pd(a), 1));
}
static inline void fresnel_i_vstore3(float *p, fresnel_i_vf r, fresnel_i_vf g, fresnel_i_vf b)
{
    fresnel_i_store3_256(p, _mm512_castps512_ps256(r), _mm512_castps512_ps256(g), _mm512_castps512_ps256(b));
    fresnel_i_store3_256(p + 24, fresnel_i_vhi256(r), fresnel_i_vhi256(g), fresnel_i_vhi256(b));
}
#if FRESNEL_I_FAST_FMA
static inline fresnel_i_vf fresnel_i_vfms(fresnel_i_vf a, fresnel_i_vf b, fresnel_i_vf c) { return _mm512_fmsub_ps(a, b, c); }
static inline fresnel_i_vf fresnel_i_vfma(fresnel_i_vf a, fresnel_i_vf b, fresnel_i_vf c) { return _mm512_fmadd_ps(a, b, c); }
static inline fresnel_i_vf fresnel_i_vfnma(fresnel_i_vf a, fresnel_i_vf b, fresnel_i_vf c) { return _mm512_fnmadd_ps(a, b, c); }
#endif

#elif defined(__AVX__) || defined(FRESNEL_I_FORCE_AVX)
#include <immintrin.h>
#define FRESNEL_I_VW 8
typedef __m256 fresnel_i_vf;
typedef __m256 fresnel_i_vm;
static inline fresnel_i_vf fresnel_i_vset(float x) { return _mm256_set1_ps(x); }
static inline fresnel_i_vf fresnel_i_vload(const float *p) { return _mm256_loadu_ps(p); }
static inline void fresnel_i_vstore(float *p, fresnel_i_vf x) { _mm256_storeu_ps(p, x); }
static inline fresnel_i_vf fresnel_i_vadd(fresnel_i_vf a, fresnel_i_vf b) { return _mm256_add_ps(a, b); }
static inline fresnel_i_vf fresnel_i_vsub(fresnel_i_vf a, fresnel_i_vf b) { return _mm256_sub_ps(a, b); }
static inline fresnel_i_vf fresnel_i_vmul(fresnel_i_vf a, fresnel_i_vf b) { return _mm256_mul_ps(a, b); }
static inline fresnel_i_vf fresnel_i_vdiv(fresnel_i_vf a, fresnel_i_vf b) { return _mm256_div_ps(a, b); }
static inline fresnel_i_vf fresnel_i_vsqrt(fresnel_i_vf a) { return _mm256_sqrt_ps(a); }
static inline fresnel_i_vf fresnel_i_vabs(fresnel_i_vf a) { return _mm256_andnot_ps(_mm256_set1_ps(-0.0f), a); }
static inline fresnel_i_vm fresnel_i_vge(fresnel_i_vf a, fresnel_i_vf b) { return _mm256_cmp_ps(a, b, _CMP_GE_OQ); }
static inline fresnel_i_vf fresnel_i_vsel(fresnel_i_vm m, fresnel_i_vf a, fresnel_i_vf b) { return _mm256_blendv_ps(b, a, m); }
#if defined(__AVX2__) || defined(FRESNEL_I_FORCE_AVX)
/* a >= 0 ? p : n for a neither NaN nor -0: blendv reads a's sign bit
 * (with AVX alone gcc would test each lane's sign in integer registers). */
#define FRESNEL_I_VSEL_SIGN
static inline fresnel_i_vf fresnel_i_vsel_nonneg(fresnel_i_vf a, fresnel_i_vf p, fresnel_i_vf n) { return _mm256_blendv_ps(p, n, a); }
#endif
static inline fresnel_i_vf fresnel_i_vmax(fresnel_i_vf a, fresnel_i_vf b) { return _mm256_max_ps(a, b); }
static inline fresnel_i_vf fresnel_i_vmin(fresnel_i_vf a, fresnel_i_vf b) { return _mm256_min_ps(a, b); }
static inline fresnel_i_vf fresnel_i_vsplit_hi(fresnel_i_vf a)
{
    return _mm256_and_ps(a, _mm256_castsi256_ps(_mm256_set1_epi32((int)0xfffff000u)));
}
static inline void fresnel_i_vstore3(float *p, fresnel_i_vf r, fresnel_i_vf g, fresnel_i_vf b)
{
#if defined(__AVX2__) || defined(FRESNEL_I_FORCE_AVX)
    fresnel_i_store3_256(p, r, g, b);
#else
    fresnel_i_store3_128(p, _mm256_castps256_ps128(r), _mm256_castps256_ps128(g), _mm256_castps256_ps128(b));
    fresnel_i_store3_128(p + 12, _mm256_extractf128_ps(r, 1), _mm256_extractf128_ps(g, 1),
                         _mm256_extractf128_ps(b, 1));
#endif
}
#if FRESNEL_I_FAST_FMA || defined(FRESNEL_I_FORCE_AVX)
static inline fresnel_i_vf fresnel_i_vfms(fresnel_i_vf a, fresnel_i_vf b, fresnel_i_vf c) { return _mm256_fmsub_ps(a, b, c); }
#endif
#if FRESNEL_I_FAST_FMA
static inline fresnel_i_vf fresnel_i_vfma(fresnel_i_vf a, fresnel_i_vf b, fresnel_i_vf c) { return _mm256_fmadd_ps(a, b, c); }
static inline fresnel_i_vf fresnel_i_vfnma(fresnel_i_vf a, fresnel_i_vf b, fresnel_i_vf c) { return _mm256_fnmadd_ps(a, b, c); }
#endif

#elif defined(__SSE2__)
#include <emmintrin.h>
#define FRESNEL_I_VW 4
typedef __m128 fresnel_i_vf;
typedef __m128 fresnel_i_vm;
static inline fresnel_i_vf fresnel_i_vset(float x) { return _mm_set1_ps(x); }
static inline fresnel_i_vf fresnel_i_vload(const float *p) { return _mm_loadu_ps(p); }
static inline void fresnel_i_vstore(float *p, fresnel_i_vf x) { _mm_storeu_ps(p, x); }
static inline fresnel_i_vf fresnel_i_vadd(fresnel_i_vf a, fresnel_i_vf b) { return _mm_add_ps(a, b); }
static inline fresnel_i_vf fresnel_i_vsub(fresnel_i_vf a, fresnel_i_vf b) { return _mm_sub_ps(a, b); }
static inline fresnel_i_vf fresnel_i_vmul(fresnel_i_vf a, fresnel_i_vf b) { return _mm_mul_ps(a, b); }
static inline fresnel_i_vf fresnel_i_vdiv(fresnel_i_vf a, fresnel_i_vf b) { return _mm_div_ps(a, b); }
static inline fresnel_i_vf fresnel_i_vsqrt(fresnel_i_vf a) { return _mm_sqrt_ps(a); }
static inline fresnel_i_vf fresnel_i_vabs(fresnel_i_vf a) { return _mm_andnot_ps(_mm_set1_ps(-0.0f), a); }
static inline fresnel_i_vm fresnel_i_vge(fresnel_i_vf a, fresnel_i_vf b) { return _mm_cmpge_ps(a, b); }
static inline fresnel_i_vf fresnel_i_vsel(fresnel_i_vm m, fresnel_i_vf a, fresnel_i_vf b)
{
    return _mm_or_ps(_mm_and_ps(m, a), _mm_andnot_ps(m, b));
}
static inline fresnel_i_vf fresnel_i_vmax(fresnel_i_vf a, fresnel_i_vf b) { return _mm_max_ps(a, b); }
static inline fresnel_i_vf fresnel_i_vmin(fresnel_i_vf a, fresnel_i_vf b) { return _mm_min_ps(a, b); }
static inline fresnel_i_vf fresnel_i_vsplit_hi(fresnel_i_vf a)
{
    return _mm_and_ps(a, _mm_castsi128_ps(_mm_set1_epi32((int)0xfffff000u)));
}
static inline void fresnel_i_vstore3(float *p, fresnel_i_vf r, fresnel_i_vf g, fresnel_i_vf b)
{
    fresnel_i_store3_128(p, r, g, b);
}
#if FRESNEL_I_FAST_FMA
#include <immintrin.h>
static inline fresnel_i_vf fresnel_i_vfms(fresnel_i_vf a, fresnel_i_vf b, fresnel_i_vf c) { return _mm_fmsub_ps(a, b, c); }
static inline fresnel_i_vf fresnel_i_vfma(fresnel_i_vf a, fresnel_i_vf b, fresnel_i_vf c) { return _mm_fmadd_ps(a, b, c); }
static inline fresnel_i_vf fresnel_i_vfnma(fresnel_i_vf a, fresnel_i_vf b, fresnel_i_vf c) { return _mm_fnmadd_ps(a, b, c); }
#endif

#elif defined(__ARM_NEON) && defined(__aarch64__)
#include <arm_neon.h>
#define FRESNEL_I_VW 4
typedef float32x4_t fresnel_i_vf;
typedef uint32x4_t fresnel_i_vm;
static inline fresnel_i_vf fresnel_i_vset(float x) { return vdupq_n_f32(x); }
static inline fresnel_i_vf fresnel_i_vload(const float *p) { return vld1q_f32(p); }
static inline void fresnel_i_vstore(float *p, fresnel_i_vf x) { vst1q_f32(p, x); }
static inline fresnel_i_vf fresnel_i_vadd(fresnel_i_vf a, fresnel_i_vf b) { return vaddq_f32(a, b); }
static inline fresnel_i_vf fresnel_i_vsub(fresnel_i_vf a, fresnel_i_vf b) { return vsubq_f32(a, b); }
static inline fresnel_i_vf fresnel_i_vmul(fresnel_i_vf a, fresnel_i_vf b) { return vmulq_f32(a, b); }
static inline fresnel_i_vf fresnel_i_vdiv(fresnel_i_vf a, fresnel_i_vf b) { return vdivq_f32(a, b); }
static inline fresnel_i_vf fresnel_i_vsqrt(fresnel_i_vf a) { return vsqrtq_f32(a); }
static inline fresnel_i_vf fresnel_i_vabs(fresnel_i_vf a) { return vabsq_f32(a); }
static inline fresnel_i_vm fresnel_i_vge(fresnel_i_vf a, fresnel_i_vf b) { return vcgeq_f32(a, b); }
static inline fresnel_i_vf fresnel_i_vsel(fresnel_i_vm m, fresnel_i_vf a, fresnel_i_vf b) { return vbslq_f32(m, a, b); }
/* NEON's vmaxq/vminq propagate NaN: the comparisons are written out. */
static inline fresnel_i_vf fresnel_i_vmax(fresnel_i_vf a, fresnel_i_vf b) { return vbslq_f32(vcgtq_f32(a, b), a, b); }
static inline fresnel_i_vf fresnel_i_vmin(fresnel_i_vf a, fresnel_i_vf b) { return vbslq_f32(vcltq_f32(a, b), a, b); }
static inline fresnel_i_vf fresnel_i_vsplit_hi(fresnel_i_vf a)
{
    return vreinterpretq_f32_u32(vandq_u32(vreinterpretq_u32_f32(a), vdupq_n_u32(0xfffff000u)));
}
static inline void fresnel_i_vstore3(float *p, fresnel_i_vf r, fresnel_i_vf g, fresnel_i_vf b)
{
    float32x4x3_t v;
    v.val[0] = r;
    v.val[1] = g;
    v.val[2] = b;
    vst3q_f32(p, v);
}
#if FRESNEL_I_FAST_FMA
static inline fresnel_i_vf fresnel_i_vfms(fresnel_i_vf a, fresnel_i_vf b, fresnel_i_vf c) { return vnegq_f32(vfmsq_f32(c, a, b)); }
static inline fresnel_i_vf fresnel_i_vfma(fresnel_i_vf a, fresnel_i_vf b, fresnel_i_vf c) { return vfmaq_f32(c, a, b); }
static inline fresnel_i_vf fresnel_i_vfnma(fresnel_i_vf a, fresnel_i_vf b, fresnel_i_vf c) { return vfmsq_f32(c, a, b); }
#endif

#endif
#endif /* FRESNEL_HAS_FLOAT && FRESNEL_HAS_SIMD */

#ifndef FRESNEL_I_VW
#define FRESNEL_I_VW 0
#endif

#if FRESNEL_I_VW
#ifndef FRESNEL_I_VSEL_SIGN
/* a >= 0 ? p : n (a neither NaN nor -0, where the AVX form differs) */
static inline fresnel_i_vf fresnel_i_vsel_nonneg(fresnel_i_vf a, fresnel_i_vf p, fresnel_i_vf n)
{
    return fresnel_i_vsel(fresnel_i_vge(a, fresnel_i_vset(0.0f)), p, n);
}
#endif

/* x in [0, 1] as fresnel_i_unit: NaN and -Inf give 0, +Inf 1. */
static inline fresnel_i_vf fresnel_i_vunit(fresnel_i_vf x)
{
    return fresnel_i_vmin(fresnel_i_vmax(x, fresnel_i_vset(0.0f)), fresnel_i_vset(1.0f));
}

#if !FRESNEL_I_FAST_FMA
/* x*x = hi + lo exactly, as fresnel_i_square_exact: the same lo by a fused
 * multiply-add in the run-time AVX2 kernel (exact_avx.c, compiled for AVX2
 * and FMA) as by the split in the scalar code of the build around it. */
static inline fresnel_i_vf fresnel_i_vsquare_lo(fresnel_i_vf x, fresnel_i_vf hi)
{
#ifdef FRESNEL_I_FORCE_AVX
    return fresnel_i_vfms(x, x, hi);
#else
    fresnel_i_vf xh = fresnel_i_vsplit_hi(x);
    fresnel_i_vf xl = fresnel_i_vsub(x, xh);
    fresnel_i_vf t = fresnel_i_vadd(fresnel_i_vsub(fresnel_i_vmul(xh, xh), hi),
                                    fresnel_i_vmul(fresnel_i_vmul(fresnel_i_vset(2.0f), xh), xl));
    return fresnel_i_vadd(t, fresnel_i_vmul(xl, xl));
#endif
}
#endif
#endif

#endif /* FRESNEL_I_SIMD_PART */
#undef FRESNEL_I_SIMD_PART
