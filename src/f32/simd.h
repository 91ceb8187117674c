/* Binary32 vectors for the batch kernels of src/f32/ (not public): one set of
 * inline operations per instruction set, chosen at compile time from the
 * compiler's target macros, so a kernel is written once and built at the
 * width the target has:
 *   __AVX512F__  16 lanes    __AVX__ 8 lanes    __SSE2__ 4 lanes
 *   (FRESNEL_I_FORCE_AVX: the AVX2 kernel that exact_avx.c compiles for
 *   run-time selection in an SSE2 build)
 *   __ARM_NEON on AArch64 (which has vector sqrt and divide) 4 lanes.
 * FRESNEL_CFG_NO_SIMD, or none of these, gives FRESNEL_I_VW 0 and the
 * kernels' scalar loops. Every operation is the IEEE one of the scalar code
 * (sqrt and divide correctly rounded, no contraction), so a lane gives the
 * scalar function's result bit for bit; fresnel_i_vfms (a b - c, one
 * rounding) only where the scalar
 * code uses fmaf (FP_FAST_FMAF). */
#ifndef FRESNEL_SIMD_H
#define FRESNEL_SIMD_H

#include "internal.h"

/* 0: no run-time choice of kernel (the tests' way to reach the SSE2
 * kernel on a CPU with AVX; exact_batch.h). */
#ifndef FRESNEL_I_SIMD_DISPATCH
#define FRESNEL_I_SIMD_DISPATCH 1
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
#ifdef FP_FAST_FMAF
static inline fresnel_i_vf fresnel_i_vfms(fresnel_i_vf a, fresnel_i_vf b, fresnel_i_vf c) { return _mm512_fmsub_ps(a, b, c); }
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
#ifdef FP_FAST_FMAF
static inline fresnel_i_vf fresnel_i_vfms(fresnel_i_vf a, fresnel_i_vf b, fresnel_i_vf c) { return _mm256_fmsub_ps(a, b, c); }
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
#ifdef FP_FAST_FMAF
#include <immintrin.h>
static inline fresnel_i_vf fresnel_i_vfms(fresnel_i_vf a, fresnel_i_vf b, fresnel_i_vf c) { return _mm_fmsub_ps(a, b, c); }
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
#ifdef FP_FAST_FMAF
static inline fresnel_i_vf fresnel_i_vfms(fresnel_i_vf a, fresnel_i_vf b, fresnel_i_vf c) { return vnegq_f32(vfmsq_f32(c, a, b)); }
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

/* x*x = hi + lo exactly, as fresnel_i_square_exact. */
static inline fresnel_i_vf fresnel_i_vsquare_lo(fresnel_i_vf x, fresnel_i_vf hi)
{
#ifdef FP_FAST_FMAF
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
