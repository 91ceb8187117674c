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
/* simd.h's and exact_batch.h's vector names, for this kernel: suffixed, so
 * that it can share a translation unit with exact.c's kernel at the build's
 * own width (simd.h). */
#define fresnel_i_store3_256 fresnel_i_store3_256_avx
#define fresnel_i_vabs fresnel_i_vabs_avx
#define fresnel_i_vadd fresnel_i_vadd_avx
#define fresnel_i_vcos fresnel_i_vcos_avx
#define fresnel_i_vcos_terms fresnel_i_vcos_terms_avx
#define fresnel_i_vdiv fresnel_i_vdiv_avx
#define fresnel_i_vexact fresnel_i_vexact_avx
#define fresnel_i_vexact_terms fresnel_i_vexact_terms_avx
#define fresnel_i_vf fresnel_i_vf_avx
#define fresnel_i_vfms fresnel_i_vfms_avx
#define fresnel_i_vge fresnel_i_vge_avx
#define fresnel_i_vhi256 fresnel_i_vhi256_avx
#define fresnel_i_vload fresnel_i_vload_avx
#define fresnel_i_vm fresnel_i_vm_avx
#define fresnel_i_vmax fresnel_i_vmax_avx
#define fresnel_i_vmin fresnel_i_vmin_avx
#define fresnel_i_vmul fresnel_i_vmul_avx
#define fresnel_i_vprep fresnel_i_vprep_avx
#define fresnel_i_vprep_set fresnel_i_vprep_set_avx
#define fresnel_i_vsel fresnel_i_vsel_avx
#define fresnel_i_vsel_nonneg fresnel_i_vsel_nonneg_avx
#define fresnel_i_vset fresnel_i_vset_avx
#define fresnel_i_vsplit_hi fresnel_i_vsplit_hi_avx
#define fresnel_i_vsqrt fresnel_i_vsqrt_avx
#define fresnel_i_vsquare_lo fresnel_i_vsquare_lo_avx
#define fresnel_i_vstore fresnel_i_vstore_avx
#define fresnel_i_vstore3 fresnel_i_vstore3_avx
#define fresnel_i_vsub fresnel_i_vsub_avx
#define fresnel_i_vunit fresnel_i_vunit_avx
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
