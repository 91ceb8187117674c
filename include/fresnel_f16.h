/* fresnel_f16.h -- Fresnel reflectance in IEEE binary16 (_Float16): GPU mediump behaviour.
 *
 * WHAT IT IS
 *   The models of fresnel.h evaluated with every arithmetic operation
 *   rounded to binary16 (11-bit significand, largest finite 65504, smallest
 *   normal 2^-14), as a mobile GPU evaluates a mediump shader. They exist to
 *   show, and to test, what GLSL/HLSL ports of this library get in fp16; the
 *   error bounds below are the numbers to compare with a GPU.
 *   Sources: the folder src/f16/, self-contained: a vendoring project
 *   copies it and include/. Scalar functions only: a shader applies the same
 *   scalar operations to each channel of a vec3.
 *
 * AVAILABILITY
 *   Declared when the compiler has _Float16 (gcc on x86-64, on Arm with
 *   -mfp16-format=ieee or an FP16 unit, on AArch64) and the build did not
 *   set FRESNEL_CFG_NO_F16 (fresnel_config.h); otherwise this header declares
 *   nothing and src/f16/\*.c compile to nothing, so the rest of the library
 *   builds with any C99 compiler (clang 14 on x86-64 has no _Float16).
 *
 * ARITHMETIC
 *   Each +, -, *, / is one binary16 operation, rounded to nearest even (the
 *   LUTs' interpolation aside, binary32 as in the GLSL port: see the LUTs
 *   below): the
 *   sources write every operation through a helper that returns _Float16,
 *   and a C99 return (like an assignment or a cast) removes any excess
 *   precision, whatever FLT_EVAL_METHOD the compiler uses for _Float16 (gcc
 *   12 evaluates _Float16 in _Float16 on x86-64 and Arm:
 *   __FLT_EVAL_METHOD_TS_18661_3__ == 0; clang may evaluate in float unless
 *   told otherwise). No fused multiply-add.
 *   sqrt is sqrtf of the half value rounded to half: that is the correctly
 *   rounded binary16 square root (binary32 has more than 2*11+2 bits, so the
 *   double rounding is harmless). (1-c)^p (generalized Schlick with p != 5,
 *   LSK compensation) is evaluated the way a GPU evaluates pow, as
 *   exp(p ln(1-c)) with ln(1-c) (log1pf), the product and exp (expf) each
 *   rounded to half: the intermediate product is where mediump pow loses
 *   its digits.
 *
 * CONVENTIONS
 *   As fresnel.h (relative eta, kappa; c clamped to [0, 1], NaN -> 0;
 *   results in [0, 1]); the domain is narrower so that no intermediate
 *   overflows 65504: eta in [FRESNEL_ETA_MIN_F16, FRESNEL_ETA_MAX_F16],
 *   kappa in [0, FRESNEL_KAPPA_MAX_F16], p and alpha in [1/1024, 64], LSK a in
 *   [0, 64]. The algorithms are those of the binary32 code, with its
 *   cancellation-free forms except the exact squares (no Dekker splitting:
 *   a shader would not do it, so near a dielectric's critical angle
 *   (eta-1)(eta+1) + c^2 carries binary16's rounding), and with scaling where
 *   binary16 would overflow: hypot as M sqrt(1 + (S/M)^2), and the p-polarised
 *   ratio of the conductor divided through by |z|^2.
 *
 * ERROR BOUNDS
 *   FRESNEL_BOUND_*_F16: absolute, against the double reference of the same
 *   model at the same binary16 inputs, on every binary16 cosine in [0, 1]
 *   and the materials of tests/common/materials.h (ten metals at 450, 550 and
 *   650 nm in air and under water, BK7 and water from both sides, corners of
 *   the domain); FRESNEL_DOMAIN_*_F16, one for every function: the same
 *   over the whole domain of CONVENTIONS, for the LUTs every n up to
 *   FRESNEL_LUT_N_MAX_F16 and every table with nodes in [0, 2] (curves) or
 *   [-1, 1] (residuals). binary16 ulp(1) = 9.8e-4, ulp(0.5) = 4.9e-4.
 *   tests/README.md names the test behind each figure; the fuzzer
 *   (tests/fuzz/fuzz_f16_models.c) fails on a result beyond its
 *   FRESNEL_DOMAIN_*_F16.
 */
#ifndef FRESNEL_F16_H
#define FRESNEL_F16_H

#include "fresnel_config.h"

#define FRESNEL_ETA_MIN_F16 0.0009765625f /* 2^-10, as fresnel.h */
#define FRESNEL_ETA_MAX_F16 16.0f
#define FRESNEL_KAPPA_MAX_F16 16.0f
#define FRESNEL_P_MIN_F16 0.0009765625f
#define FRESNEL_P_MAX_F16 64.0f
/* Most nodes a binary16 LUT uses: n - 1 <= 2048 is an exact half. */
#define FRESNEL_LUT_N_MAX_F16 2049

/* Error bounds on the material set (see ERROR BOUNDS). The exact models,
 * Cook-Torrance and Schlick internal have no bound near a dielectric's
 * critical angle (eta < 1, kappa 0): there the bound is 1, and
 * FRESNEL_BOUND_F16_NONCRITICAL holds for every model at least 1/64 in c
 * away from a critical angle. */
#define FRESNEL_BOUND_SCHLICK_F16 2.6e-3 /* also every binary16 F0 */
#define FRESNEL_BOUND_SCHLICK_GEN_F16 2.6e-3
#define FRESNEL_BOUND_SCHLICK_INTERNAL_F16 1.0 /* critical angle */
#define FRESNEL_BOUND_F0_FROM_IOR_F16 1.8e-3
#define FRESNEL_BOUND_F0_IN_MEDIUM_F16 2.5e-3
#define FRESNEL_BOUND_LSK_F16 2.8e-3
#define FRESNEL_BOUND_LSK_COMP_F16 2.9e-3
#define FRESNEL_BOUND_F82_F16 4.0e-3 /* also a 1/64 grid of F0, F82 pairs */
#define FRESNEL_BOUND_GULBRANDSEN_F16 1.8e-3
#define FRESNEL_BOUND_APPROX_CONDUCTOR_F16 1.6e-3
#define FRESNEL_BOUND_COOK_TORRANCE_F16 1.0 /* critical angle */
#define FRESNEL_BOUND_CONDUCTOR_F16 1.0 /* critical angle */
#define FRESNEL_BOUND_DIELECTRIC_F16 1.0 /* critical angle */
#define FRESNEL_BOUND_LUT_CUBIC_F16 5.0e-4 /* reflectance curves, n <= 256 */
#define FRESNEL_BOUND_LUT_F16 2.3e-3 /* tables with a total-reflection edge included */
#define FRESNEL_BOUND_F16_NONCRITICAL 4.5e-3
/* Error bounds over the whole domain of CONVENTIONS (eta in [2^-10, 16],
 * kappa 0 or in [1e-3, 16], F0, F82, F90, r, g in [0, 1], p, a and alpha
 * in [2^-10, 64], every half c), larger than the above for tiny eta with
 * tiny c (approximate conductor: at eta 2^-10 and a subnormal c, eta^2 and
 * 2 eta c are binary16 subnormals of a few bits), F0 near 0 in a dense
 * medium (F0 in medium), Gulbrandsen with g near 0 and r near 1 (k
 * clamped to 16), F0 and F82 far apart (F82), and near-dielectric
 * conductors (kappa 1e-3) at their critical angle. They are measured
 * maxima rounded up, not proven, but for the LUTs': the models' and the
 * F0 helpers' at least 10% above the largest error a search for the worst
 * case or the fuzzer found over the domain (tests/runtime/every_type/test_model_search.c;
 * make search, make fuzz). */
#define FRESNEL_DOMAIN_SCHLICK_F16 2.8e-3
#define FRESNEL_DOMAIN_SCHLICK_GEN_F16 2.8e-3
#define FRESNEL_DOMAIN_F82_F16 4.9e-3
#define FRESNEL_DOMAIN_SCHLICK_INTERNAL_F16 1.0
#define FRESNEL_DOMAIN_F0_FROM_IOR_F16 2.3e-3
#define FRESNEL_DOMAIN_F0_IN_MEDIUM_F16 6.1e-3
#define FRESNEL_DOMAIN_LSK_F16 4.1e-3
#define FRESNEL_DOMAIN_LSK_COMP_F16 4.5e-3
#define FRESNEL_DOMAIN_GULBRANDSEN_F16 0.15
#define FRESNEL_DOMAIN_APPROX_CONDUCTOR_F16 3.0e-2
#define FRESNEL_DOMAIN_COOK_TORRANCE_F16 1.0
#define FRESNEL_DOMAIN_CONDUCTOR_F16 1.0
#define FRESNEL_DOMAIN_DIELECTRIC_F16 1.0
/* The LUTs' bounds over any table hold by construction: half an ulp of
 * the result (4.9e-4 below 2, 2.4e-4 below 1) plus the binary32 position's
 * error (1.9e-4 of a segment at 2049 nodes) times the steepest slope of the
 * interpolant (2 a segment for nodes in [0, 2] or [-1, 1], 3.5 for the
 * cubic), and for the residual forms FRESNEL_DOMAIN_SCHLICK_F16. */
#define FRESNEL_DOMAIN_LUT_F16 8.6e-4
#define FRESNEL_DOMAIN_LUT_RESIDUAL_F16 3.3e-3
#define FRESNEL_DOMAIN_LUT_CUBIC_F16 1.2e-3

#if FRESNEL_HAS_F16

#ifdef __cplusplus
extern "C" {
#endif

/* __extension__: _Float16 is ISO/IEC TS 18661-3, not C99; this keeps
 * -Wpedantic quiet for code that only includes the header. */
__extension__ typedef _Float16 fresnel_f16;

/* Every function is the fresnel.h function of the same name without _f16:
 * the same formula, clamps and NaN policy, on the domain of CONVENTIONS.
 * Error <= FRESNEL_BOUND_<MODEL>_F16 on the material set and
 * FRESNEL_DOMAIN_<MODEL>_F16 over the domain.
 * Cost: the binary32 function's operation counts, in binary16 operations;
 * expf, log1pf and sqrtf on the half value, rounded to half. */
fresnel_f16 fresnel_schlick_f16(fresnel_f16 f0, fresnel_f16 c);
/* p = 5 multiplies; other p: exp(p ln(1-c)) as a GPU's pow. */
fresnel_f16 fresnel_schlick_gen_f16(fresnel_f16 f0, fresnel_f16 f90, fresnel_f16 p, fresnel_f16 c);
fresnel_f16 fresnel_schlick_internal_f16(fresnel_f16 f0, fresnel_f16 eta, fresnel_f16 c);
fresnel_f16 fresnel_f0_in_medium_f16(fresnel_f16 f0, fresnel_f16 eta_e);
fresnel_f16 fresnel_f0_from_ior_f16(fresnel_f16 eta, fresnel_f16 kappa);
fresnel_f16 fresnel_lsk_f16(fresnel_f16 eta, fresnel_f16 kappa, fresnel_f16 c);
fresnel_f16 fresnel_lsk_comp_f16(fresnel_f16 eta, fresnel_f16 kappa, fresnel_f16 a, fresnel_f16 alpha, fresnel_f16 c);
fresnel_f16 fresnel_f82_f16(fresnel_f16 f0, fresnel_f16 f82, fresnel_f16 c);
/* r clamped to 1 - 2^-11 = 0.99951 (the largest half below 1); n and k
 * clamped to the binary16 domain. */
fresnel_f16 fresnel_gulbrandsen_f16(fresnel_f16 r, fresnel_f16 g, fresnel_f16 c);
fresnel_f16 fresnel_approx_conductor_f16(fresnel_f16 eta, fresnel_f16 kappa, fresnel_f16 c);
fresnel_f16 fresnel_cook_torrance_f16(fresnel_f16 f0, fresnel_f16 eta, fresnel_f16 kappa, fresnel_f16 c);
fresnel_f16 fresnel_conductor_f16(fresnel_f16 eta, fresnel_f16 kappa, fresnel_f16 c);
fresnel_f16 fresnel_dielectric_f16(fresnel_f16 eta, fresnel_f16 c);
/* Lookup tables with binary16 nodes; n as fresnel.h's LUTs with
 * FRESNEL_LUT_N_MAX_F16 for FRESNEL_LUT_N_MAX. The interpolation is
 * binary32 on the binary16 nodes (the position of c among the nodes, its
 * index and fraction, the blend), the result rounded to half: what the
 * GLSL port computes in highp and returns in mediump (in binary16 the
 * position would keep fewer than 3 fraction bits above 256 nodes; the
 * residual forms add fresnel_schlick_f16). Curve tables clamp to
 * [0, max(1, the nodes around c)] (nodes above 1 carry out-of-gamut values,
 * fresnel.h), residual ones to [0, 1]. */
fresnel_f16 fresnel_lut_f16(const fresnel_f16 *table, int n, fresnel_f16 c);
fresnel_f16 fresnel_lut_linear_f16(const fresnel_f16 *table, int n, fresnel_f16 c);
fresnel_f16 fresnel_lut_residual_f16(fresnel_f16 f0, const fresnel_f16 *table, int n, fresnel_f16 c);
fresnel_f16 fresnel_lut_linear_residual_f16(fresnel_f16 f0, const fresnel_f16 *table, int n, fresnel_f16 c);
fresnel_f16 fresnel_lut_cubic_f16(const fresnel_f16 *table, int n, fresnel_f16 c);

#ifdef __cplusplus
}
#endif

#endif /* FRESNEL_HAS_F16 */
#endif /* FRESNEL_F16_H */
