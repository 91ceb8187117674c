/* fresnel_conductor_batch's 8-lane kernel for x86-64 builds whose target
 * has no AVX (exact_batch.h): the same kernel source, compiled for AVX2 and
 * FMA by a target pragma and called only where the CPU has both. The
 * formula stays the build's own (internal.h is read before the pragma, so
 * FRESNEL_I_FAST_FMA is the target's, 0): FMA forms only the exact low
 * part of c^2, which Dekker's split gives the scalar code bit for bit. */
#include "fresnel_config.h"

#if FRESNEL_HAS_FLOAT && FRESNEL_HAS_SIMD && defined(__x86_64__) && defined(__SSE2__) && !defined(__AVX__) && \
    defined(__GNUC__) && (!defined(FRESNEL_I_SIMD_DISPATCH) || FRESNEL_I_SIMD_DISPATCH)
#include "internal.h"
#define FRESNEL_I_FORCE_AVX 1
#ifdef __clang__
#pragma clang attribute push(__attribute__((target("avx2,fma"))), apply_to = function)
#else
#pragma GCC push_options
#pragma GCC target("avx2,fma")
#endif
#include "exact_batch.h"

FRESNEL_I_VBATCH(fresnel_i_batch_avx_diel, FRESNEL_I_DIEL)
FRESNEL_I_VBATCH(fresnel_i_batch_avx_cond1, FRESNEL_I_COND1)
FRESNEL_I_VBATCH(fresnel_i_batch_avx_cond2, FRESNEL_I_COND2)

void fresnel_i_conductor_batch_avx(const fresnel_conductor_prep *p, const float *c, float *out, int n)
{
    switch (p->kind) {
    case FRESNEL_I_DIEL: fresnel_i_batch_avx_diel(p, c, out, n); break;
    case FRESNEL_I_COND1: fresnel_i_batch_avx_cond1(p, c, out, n); break;
    default: fresnel_i_batch_avx_cond2(p, c, out, n); break; /* the caller handles the matched index */
    }
}

FRESNEL_I_VBATCH_RGB(fresnel_i_rgb_batch_avx_diel, FRESNEL_I_DIEL)
FRESNEL_I_VBATCH_RGB(fresnel_i_rgb_batch_avx_cond1, FRESNEL_I_COND1)
FRESNEL_I_VBATCH_RGB(fresnel_i_rgb_batch_avx_cond2, FRESNEL_I_COND2)

void fresnel_i_conductor_rgb_batch_avx(const fresnel_conductor_prep p[3], const float *c, float *out, int n)
{
    switch (p[0].kind) {
    case FRESNEL_I_DIEL: fresnel_i_rgb_batch_avx_diel(p, c, out, n); break;
    case FRESNEL_I_COND1: fresnel_i_rgb_batch_avx_cond1(p, c, out, n); break;
    default: fresnel_i_rgb_batch_avx_cond2(p, c, out, n); break; /* the caller handles the matched index */
    }
}
#ifdef __clang__
#pragma clang attribute pop
#else
#pragma GCC pop_options
#endif
#else
typedef int fresnel_i_exact_avx_disabled; /* ISO C wants a declaration */
#endif
