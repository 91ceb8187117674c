/* fresnel_q15.h -- integer-only Fresnel reflectance: the fixed-point API and its manual.
 *
 * WHAT IT IS
 *   Every model of fresnel.h, and the lookup tables, evaluated with 32-bit
 *   integer arithmetic only: no float, no double, no libm, no soft-float
 *   helper, no integer division instruction (divisions are bit-by-bit), no
 *   int64 anywhere. For microcontrollers without an FPU (Cortex-M0, RV32IMC).
 *   Sources: the folder src/q15/, self-contained: a vendoring project
 *   copies it and include/. This header does not need fresnel.h; a
 *   fixed-point-only build compiles src/q15/\*.c, or all of src/
 *   with -DFRESNEL_CONFIG='FRESNEL_CFG_NO_FLOAT|FRESNEL_CFG_NO_F16', which
 *   leaves the others empty (see fresnel_config.h, ports/README.md).
 *
 * USE
 *     #include "fresnel_q15.h"
 *     int32_t c = dot_q15(n, v);                         // any int32; clamped to [0, one]
 *     fresnel_q15 r = fresnel_schlick_q15(1311, c);      // F0 = 0.04: 1311/32768
 *     static const fresnel_ior_prep_q15 gold_r = {...};       // made on the host (LAYOUT)
 *     fresnel_q15 au = fresnel_conductor_q15(&gold_r, c);
 *
 * NUMBER FORMATS
 *   fresnel_q15  unsigned Q1.15 in uint16_t: value = code / 32768.
 *                FRESNEL_ONE_Q15 = 32768 = 0x8000 is 1.0; codes 32769..65535
 *                (up to 2 - 2^-15) are headroom that only the uint16_t
 *                curve tables use (the generator's keep policy, fresnel.h).
 *                Used for cos(theta), F0, F82, F90, Gulbrandsen r and g,
 *                and every result. Arguments are taken as int32_t so that a
 *                signed dot product can be passed as is: values below 0 are
 *                0, above 32768 are 32768 (the same clamping policy as
 *                fresnel.h; F0 above 1 is therefore evaluated as 1). Results
 *                are always in [0, 32768], the uint16_t curve tables'
 *                (_u16 plain and cubic) in [0, max(32768, largest node)].
 *   fresnel_q16  signed Q16.16 in int32_t: value = code / 65536, range
 *                [-32768, 32768). Used for eta, kappa, the generalized
 *                Schlick exponent p and the LSK exponent alpha when they are
 *                given at run time.
 *   fresnel_qf   a positive constant as mantissa and exponent,
 *                value = m * 2^e with m in [2^30, 2^31) (31 significant
 *                bits), or m = 0 for zero. Material constants of the exact,
 *                Cook-Torrance, approximate-conductor and LSK models are
 *                stored this way, because their range (gold's 2 eta kappa is
 *                0.5, aluminium's (eta^2+kappa^2)^2 is 3700) does not fit one
 *                Q format with the precision the results need. The same
 *                representation is used inside those models for intermediates
 *                ("block floating point", as CMSIS-DSP's arm_divide_q15
 *                returns a mantissa and a shift).
 *   A per-material "prepared" struct holds what a model needs; the host fills
 *   it (the generator, or gen/3_encode/q15_params.c from double eta and kappa), or
 *   the *_prepare functions below fill it at run time from Q16.16 inputs.
 *
 * ERROR BOUNDS
 *   FRESNEL_BOUND_*_Q15 are in LSB of Q15 (1 LSB = 2^-15 = 3.05e-5): bounds
 *   on |result/32768 - reference| for every cos code 0..32768 over the whole
 *   domain eta in [2^-10, 32767], kappa in [0, 32767], where "reference" is
 *   the double model (gen/common/reference.c) at the same parameters: the Q15 inputs
 *   (F0, F82, F90, r, g) and the Q16.16 ones (p, alpha) as the codes given,
 *   and eta, kappa as the double values the prepared constants were made
 *   from, so the rounding of the constants is part of the error. Rounding
 *   the exact value to the nearest code is already 0.5 LSB. Prepared on the
 *   host, eta or kappa above 46340 is outside the layout. The Cortex-M0,
 *   Cortex-M4F and RV32IMC builds give the host's results bit for bit.
 *   tests/README.md names the test and grid behind each bound.
 *
 * COST
 *   "mul" = 32x32->32 multiply (one MULS on Cortex-M0), "qf op" = one
 *   mantissa-exponent multiply/add (~30 instructions), "qf div/sqrt" ~ 200.
 *   Instructions per call on Cortex-M0, Cortex-M4F and RV32IMC are in
 *   ports/README.md (`make cross-count`).
 *
 * THREAD SAFETY
 *   No global or static mutable state, no allocation, no stdio: reentrant.
 *   Tables are const (flash).
 */
#ifndef FRESNEL_Q15_H
#define FRESNEL_Q15_H

#include <stdint.h>

#include "fresnel_config.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef uint16_t fresnel_q15;
typedef int32_t fresnel_q16;
typedef struct fresnel_qf {
    uint32_t m; /* [2^30, 2^31), or 0 */
    int32_t e;
} fresnel_qf;
typedef struct fresnel_rgb_q15 {
    fresnel_q15 r, g, b;
} fresnel_rgb_q15;

#define FRESNEL_ONE_Q15 32768
#define FRESNEL_ONE_Q16 65536

/* Domains in fixed point (values outside are clamped, as in fresnel.h). */
#define FRESNEL_ETA_MIN_Q16 64                 /* eta of *_prepare: [1/1024, 32767]; kappa [0, 32767] */
#define FRESNEL_P_MIN_Q16 66                   /* generalized Schlick p: [0.001, 1000] as in fresnel.h */
#define FRESNEL_P_MAX_Q16 (1000 * 65536)
#define FRESNEL_ALPHA_MAX_Q16 (1000 * 65536)   /* LSK alpha: [0, 1000] */
#define FRESNEL_GULBRANDSEN_R_MAX_Q15 32764    /* largest code below 0.9999 */

/* Error bounds, LSB of Q15 (see ERROR BOUNDS). */
#define FRESNEL_BOUND_SCHLICK_Q15 0.501
#define FRESNEL_BOUND_SCHLICK_GEN_Q15 0.516 /* 0.501 for p <= 64 */
#define FRESNEL_BOUND_SCHLICK_INTERNAL_Q15 0.501
#define FRESNEL_BOUND_F0_FROM_IOR_Q15 0.501
#define FRESNEL_BOUND_F0_IN_MEDIUM_Q15 0.501
#define FRESNEL_BOUND_LSK_Q15 0.501
#define FRESNEL_BOUND_LSK_COMP_Q15 0.501
#define FRESNEL_BOUND_F82_Q15 0.501
#define FRESNEL_BOUND_GULBRANDSEN_Q15 0.501
#define FRESNEL_BOUND_APPROX_CONDUCTOR_Q15 0.501
#define FRESNEL_BOUND_COOK_TORRANCE_Q15 0.501
#define FRESNEL_BOUND_CONDUCTOR_Q15 0.501
#define FRESNEL_BOUND_DIELECTRIC_Q15 0.501
#define FRESNEL_BOUND_SCHLICK_AVG_Q15 0.51 /* against the exact average of the argument codes */
#define FRESNEL_BOUND_F82_AVG_Q15 0.55 /* 0.5 rounding + 0.05 from its Q18 constants */
#define FRESNEL_BOUND_LUT_Q15 1.01 /* nodes uniform in sqrt(c); 0.501 uniform in c */
#define FRESNEL_BOUND_LUT_CUBIC_Q15 2.2 /* on any table with nodes in [0, one] */
#define FRESNEL_BOUND_LUT_CUBIC_Q15_HEADROOM 4.8 /* on any table (nodes up to 65535) */
#define FRESNEL_BOUND_LUT_AVG_Q15 0.501 /* fresnel_lut_*_avg_u16_q15: rounded to nearest */

#if FRESNEL_HAS_Q15

/* ------------------------------------------------------------ prepared constants
 *
 * LAYOUT: the value of every field below, as `fresnel gen` emits it, is
 * specified in gen/4_emit/README.md.
 */
typedef struct fresnel_ior_prep_q15 {
    int32_t a0, a0_lo;
    int32_t shift;
    fresnel_qf b, n4, t1_inv, inv_eta2;
} fresnel_ior_prep_q15;

/* fresnel_conductor_q15_fast's constants (fresnel_q15_fast.h, beside the
 * function, gives each field's value; `fresnel gen` emits them as
 * <prefix>_ior_fast_q15). Made on the host only, as every fast path's. */
typedef struct fresnel_conductor_prep_q15_fast {
    int32_t a0, a0_lo, shift;
    int32_t b1, b2, bm, be;
    uint32_t span;
} fresnel_conductor_prep_q15_fast;

/* ALIASES: second names that code and generated headers may spell, each the
 * name of fresnel.h's NAMING rule it stands for (tests/repo/test_public_names.sh
 * reads this block). */
#define fresnel_conductor_prep_q15 fresnel_conductor_prep_q15_fast
/* end of ALIASES */

typedef struct fresnel_nk_prep_q15 {
    fresnel_qf n, nk2;
} fresnel_nk_prep_q15;

typedef struct fresnel_lsk_prep_q15 {
    uint32_t f0;
    fresnel_qf a;
    fresnel_q16 alpha;
} fresnel_lsk_prep_q15;

/* Run-time preparation of the constants above from Q16.16 eta and kappa
 * (clamped to [FRESNEL_ETA_MIN_Q16, 2^31 - 1] and [0, 2^31 - 1]), with
 * 31-bit mantissas: exact to the inputs, whose Q16.16 step is 1.5e-5 (a
 * 3e-4 relative change of silver's eta 0.05: prepare on the host from double
 * where that matters). Cost: ~10 qf ops, 2 qf div (ior). */
fresnel_ior_prep_q15 fresnel_ior_prepare_q15(fresnel_q16 eta, fresnel_q16 kappa);
fresnel_nk_prep_q15 fresnel_nk_prepare_q15(fresnel_q16 eta, fresnel_q16 kappa);
/* a and alpha are LSK's compensation constants (`fresnel params`);
 * a = 0 gives the rescaled model. */
fresnel_lsk_prep_q15 fresnel_lsk_prepare_q15(fresnel_q16 eta, fresnel_q16 kappa, fresnel_q16 a, fresnel_q16 alpha);

/* ---------------------------------------------------------------- schlick_q15.c */

/* Schlick:  F = F0 + (1 - F0)(1 - c)^5.
 * Error <= FRESNEL_BOUND_SCHLICK_Q15 LSB. Cost: 8 mul. */
fresnel_q15 fresnel_schlick_q15(int32_t f0, int32_t c);
fresnel_rgb_q15 fresnel_schlick_q15_rgb(fresnel_rgb_q15 f0, int32_t c);

/* Its hemispherical average 2 int_0^1 F c dc = F0 + (1 - F0)/21 (fresnel_schlick_avg).
 * Error <= FRESNEL_BOUND_SCHLICK_AVG_Q15 LSB. Cost: 1 mul. */
fresnel_q15 fresnel_schlick_avg_q15(int32_t f0);
fresnel_rgb_q15 fresnel_schlick_avg_q15_rgb(fresnel_rgb_q15 f0);

/* Generalized Schlick:  F = F0 + (F90 - F0)(1 - c)^p,  p Q16.16 in
 * [FRESNEL_P_MIN_Q16, FRESNEL_P_MAX_Q16] (clamped).
 * Error <= FRESNEL_BOUND_SCHLICK_GEN_Q15 LSB (0.501 for p <= 64).
 * Cost: p = 5: 9 mul; else ~2 log2(p) qf mul + ~25 mul. */
fresnel_q15 fresnel_schlick_gen_q15(int32_t f0, int32_t f90, fresnel_q16 p, int32_t c);
fresnel_rgb_q15 fresnel_schlick_gen_q15_rgb(fresnel_rgb_q15 f0, fresnel_rgb_q15 f90, fresnel_q16 p,
                                            int32_t c);

/* Schlick for internal reflection (fresnel_schlick_internal), m prepared
 * from eta (kappa 0) relative to the incident side: eta >= 1, Schlick at c;
 * eta < 1, Schlick at ct, ct^2 = (eta^2 - 1 + c^2) / eta^2, and one where
 * ct^2 <= 0 (past the critical angle).
 * Error <= FRESNEL_BOUND_SCHLICK_INTERNAL_Q15 LSB. Cost: ~8 qf ops, 1 qf sqrt. */
fresnel_q15 fresnel_schlick_internal_q15(int32_t f0, const fresnel_ior_prep_q15 *m, int32_t c);
fresnel_rgb_q15 fresnel_schlick_internal_q15_rgb(fresnel_rgb_q15 f0, const fresnel_ior_prep_q15 *m,
                                                 int32_t c);

/* F0 = ((eta-1)^2 + kappa^2) / ((eta+1)^2 + kappa^2) from Q16.16 eta, kappa
 * (eta clamped to [FRESNEL_ETA_MIN_Q16, 2^31-1], kappa to [0, 2^31-1]).
 * Error <= FRESNEL_BOUND_F0_FROM_IOR_Q15 LSB. Cost: 4 qf ops, 1 qf div. */
fresnel_q15 fresnel_f0_from_ior_q15(fresnel_q16 eta, fresnel_q16 kappa);

/* Hoffman's external-medium adjustment of F0 (fresnel_f0_in_medium), etaE
 * Q16.16 clamped like eta, F0 Q15.
 * Error <= FRESNEL_BOUND_F0_IN_MEDIUM_Q15 LSB. Cost: ~8 qf ops, 2 qf div, 1 qf sqrt. */
fresnel_q15 fresnel_f0_in_medium_q15(int32_t f0, fresnel_q16 eta_e);

/* -------------------------------------------------------------------- lsk_q15.c */

/* LSK rescaled: Schlick with m->f0 (Q30). Error <= FRESNEL_BOUND_LSK_Q15 LSB. Cost: 10 mul. */
fresnel_q15 fresnel_lsk_q15(const fresnel_lsk_prep_q15 *m, int32_t c);
fresnel_rgb_q15 fresnel_lsk_q15_rgb(const fresnel_lsk_prep_q15 m[3], int32_t c);

/* LSK compensated:  F = LSK - a c (1 - c)^alpha, clamped to [0, 1].
 * Error <= FRESNEL_BOUND_LSK_COMP_Q15 LSB. Cost: LSK + pow (~2 log2(alpha) qf mul + ~20 mul) + 2 qf mul. */
fresnel_q15 fresnel_lsk_comp_q15(const fresnel_lsk_prep_q15 *m, int32_t c);
fresnel_rgb_q15 fresnel_lsk_comp_q15_rgb(const fresnel_lsk_prep_q15 m[3], int32_t c);

/* -------------------------------------------------------------------- f82_q15.c */

/* Hoffman's F82 model:  F = F0 + (1-F0)(1-c)^5 - a c (1-c)^6,
 * a = (7^7/6^6)(F0 - F82) + (49/6)(1 - F0), clamped to [0, 1] like fresnel_f82.
 * Error <= FRESNEL_BOUND_F82_Q15 LSB. Cost: ~16 mul. */
fresnel_q15 fresnel_f82_q15(int32_t f0, int32_t f82, int32_t c);
fresnel_rgb_q15 fresnel_f82_q15_rgb(fresnel_rgb_q15 f0, fresnel_rgb_q15 f82, int32_t c);

/* Its hemispherical average F0 + (1 - F0)/21 - a/126, clamped to [0, 1]
 * (fresnel_f82_avg). Error <= FRESNEL_BOUND_F82_AVG_Q15 LSB. Cost: 2 mul. */
fresnel_q15 fresnel_f82_avg_q15(int32_t f0, int32_t f82);
fresnel_rgb_q15 fresnel_f82_avg_q15_rgb(fresnel_rgb_q15 f0, fresnel_rgb_q15 f82);

/* -------------------------------------------------------- gulbrandsen_q15.c */

/* Gulbrandsen's r, g -> n, k (fresnel_gulbrandsen_nk), r clamped to
 * [0, FRESNEL_GULBRANDSEN_R_MAX_Q15], n clamped below at FRESNEL_ETA_MIN
 * (r -> 1, g = 1 gives n -> 0); the result is prepared for
 * fresnel_approx_conductor_q15. Cost: ~14 qf ops, 4 qf div, 1 qf sqrt. */
fresnel_nk_prep_q15 fresnel_gulbrandsen_nk_q15(int32_t r, int32_t g);
/* The inverse n, k (Q16.16) -> r, g (Q15), as fresnel_gulbrandsen_rg. */
typedef struct fresnel_rg_q15 {
    fresnel_q15 r, g;
} fresnel_rg_q15;
fresnel_rg_q15 fresnel_gulbrandsen_rg_q15(fresnel_q16 eta, fresnel_q16 kappa);
/* fresnel_approx_conductor_q15 at the n, k of fresnel_gulbrandsen_nk_q15(r, g).
 * Error <= FRESNEL_BOUND_GULBRANDSEN_Q15 LSB.
 * Cost: fresnel_gulbrandsen_nk_q15 + fresnel_approx_conductor_q15. */
fresnel_q15 fresnel_gulbrandsen_q15(int32_t r, int32_t g, int32_t c);
fresnel_rgb_q15 fresnel_gulbrandsen_q15_rgb(fresnel_rgb_q15 r, fresnel_rgb_q15 g, int32_t c);

/* --------------------------------------------------- approx_conductor_q15.c */

/* The approximate conductor form of fresnel_approx_conductor.
 * Error <= FRESNEL_BOUND_APPROX_CONDUCTOR_Q15 LSB. Cost: ~10 qf ops, 2 qf div. */
fresnel_q15 fresnel_approx_conductor_q15(const fresnel_nk_prep_q15 *m, int32_t c);
fresnel_rgb_q15 fresnel_approx_conductor_q15_rgb(const fresnel_nk_prep_q15 m[3], int32_t c);

/* ------------------------------------------------------- cook_torrance_q15.c */

/* Cook-Torrance colour interpolation (fresnel_cook_torrance):
 *   F = F0 + (1 - F0) max(0, 1 - T(c) / T(1)),  T = 1 - fresnel_conductor_q15(m, .).
 * Error <= FRESNEL_BOUND_COOK_TORRANCE_Q15 LSB. Cost: conductor + 1 qf mul. */
fresnel_q15 fresnel_cook_torrance_q15(int32_t f0, const fresnel_ior_prep_q15 *m, int32_t c);
fresnel_rgb_q15 fresnel_cook_torrance_q15_rgb(fresnel_rgb_q15 f0, const fresnel_ior_prep_q15 *m, int32_t c);

/* --------------------------------------------------------------- exact_q15.c */

/* Exact unpolarised Fresnel of eta + i kappa (the formula of
 * fresnel_conductor), m prepared. kappa = 0 with eta < 1 gives one past the
 * critical angle; the matched index (a0 = b = 0) gives 0 for every c.
 * Error <= FRESNEL_BOUND_CONDUCTOR_Q15 LSB, also at critical angles.
 * Cost: ~14 qf ops, 3 qf div, 2 qf sqrt. */
fresnel_q15 fresnel_conductor_q15(const fresnel_ior_prep_q15 *m, int32_t c);
fresnel_rgb_q15 fresnel_conductor_q15_rgb(const fresnel_ior_prep_q15 m[3], int32_t c);

/* Exact dielectric (fresnel_dielectric), m prepared with kappa = 0.
 * Error <= FRESNEL_BOUND_DIELECTRIC_Q15 LSB.
 * Cost: ~10 qf ops, 2 qf div, 1 qf sqrt. */
fresnel_q15 fresnel_dielectric_q15(const fresnel_ior_prep_q15 *m, int32_t c);

/* ----------------------------------------------------------------- lut_q15.c */

/* Lookup tables (fresnel_lut and friends) in integers. table[i], i = 0..n-1,
 * is the reflectance at node i; the result interpolates linearly between
 * the two nodes around c, clamped to [0, one] (_u16: to [0, max(one, the
 * two nodes)], so nodes above one carry out-of-gamut values as in
 * fresnel.h). Nodes as fresnel.h's:
 *   fresnel_lut_*        uniform in sqrt(c), node i at c = (i/(n-1))^2
 *   fresnel_lut_linear_* uniform in c, node i at c = i/(n-1)
 * Encodings:
 *   _u16  uint16_t, F = v / 32768 (v above 32768: headroom, up to 2 - 2^-15)
 *   _u8   uint8_t,  F = v / 255
 *   residual (F = Schlick(F0, c) + interpolated residual):
 *   _s16  int16_t, residual = v / 2^frac, frac in [14, 30]
 *   _s8   int8_t,  residual = v / 2^frac, frac in [6, 22]
 * n: 2 <= n <= 32768. n <= 0 reads no entry and gives 0 (the _residual
 * forms: Schlick alone), n = 1 is the constant table[0], n above 32768 is
 * read as 32768 nodes (the _rgb forms: 3 x 32768 entries, the channels at
 * 0, 32768, 65536); no entry past the table is read.
 * Error <= FRESNEL_BOUND_LUT_Q15 LSB against the same interpolation in
 * double; between two nodes that differ by s > 1 (a residual table's nodes
 * may span [-1, 1]) <= 0.51 + 0.5 s LSB.
 * Cost: uniform in c, 3 mul, no division; uniform in sqrt(c), 7 mul more:
 * the exact square root from two const tables (1168 bytes, shared by every
 * form), no loop; the _residual forms add Schlick's 8 mul. On a Cortex-M0
 * with a 64-node table (`make cross-count`, rows lut u16 and lut-linear
 * u16): 187 instructions per call (_u16), 96 uniform in c. */
fresnel_q15 fresnel_lut_u16_q15(const uint16_t *table, int n, int32_t c);
fresnel_q15 fresnel_lut_linear_u16_q15(const uint16_t *table, int n, int32_t c);
fresnel_q15 fresnel_lut_u8_q15(const uint8_t *table, int n, int32_t c);
fresnel_q15 fresnel_lut_linear_u8_q15(const uint8_t *table, int n, int32_t c);
fresnel_q15 fresnel_lut_residual_s16_q15(int32_t f0, const int16_t *table, int n, int frac, int32_t c);
fresnel_q15 fresnel_lut_linear_residual_s16_q15(int32_t f0, const int16_t *table, int n, int frac,
                                                int32_t c);
fresnel_q15 fresnel_lut_residual_s8_q15(int32_t f0, const int8_t *table, int n, int frac, int32_t c);
fresnel_q15 fresnel_lut_linear_residual_s8_q15(int32_t f0, const int8_t *table, int n, int frac,
                                               int32_t c);
fresnel_rgb_q15 fresnel_lut_u16_q15_rgb(const uint16_t *table, int n, int32_t c);
fresnel_rgb_q15 fresnel_lut_linear_u16_q15_rgb(const uint16_t *table, int n, int32_t c);
fresnel_rgb_q15 fresnel_lut_u8_q15_rgb(const uint8_t *table, int n, int32_t c);
fresnel_rgb_q15 fresnel_lut_linear_u8_q15_rgb(const uint8_t *table, int n, int32_t c);
fresnel_rgb_q15 fresnel_lut_residual_s16_q15_rgb(fresnel_rgb_q15 f0, const int16_t *table, int n,
                                                 int frac, int32_t c);
fresnel_rgb_q15 fresnel_lut_linear_residual_s16_q15_rgb(fresnel_rgb_q15 f0, const int16_t *table,
                                                        int n, int frac, int32_t c);
fresnel_rgb_q15 fresnel_lut_residual_s8_q15_rgb(fresnel_rgb_q15 f0, const int8_t *table, int n,
                                                int frac, int32_t c);
fresnel_rgb_q15 fresnel_lut_linear_residual_s8_q15_rgb(fresnel_rgb_q15 f0, const int8_t *table,
                                                       int n, int frac, int32_t c);

/* fresnel_lut_cubic (fresnel.h) on uint16_t nodes, n as fresnel_lut_u16_q15,
 * clamped to [0, max(one, p1, p2)]; tables fitted for the cubic (lutN-cubic).
 * Error <= FRESNEL_BOUND_LUT_CUBIC_Q15 LSB (nodes in [0, one];
 * FRESNEL_BOUND_LUT_CUBIC_Q15_HEADROOM with nodes above) against the same cubic in double
 * at the table's values. Cost: the position of fresnel_lut_u16_q15, 7 mul
 * for the weights, 4 per channel; 252 Cortex-M0 instructions per call with a
 * 64-node table (`make cross-count`, row lut-cubic u16). */
fresnel_q15 fresnel_lut_cubic_u16_q15(const uint16_t *table, int n, int32_t c);
fresnel_rgb_q15 fresnel_lut_cubic_u16_q15_rgb(const uint16_t *table, int n, int32_t c);

/* ------------------------------------------------------------- lut_avg_q15.c */

/* fresnel_lut_avg, fresnel_lut_cubic_avg, fresnel_lut_linear_avg (fresnel.h):
 * the exact F_avg of a uint16_t table's interpolant, its nodes' weighted
 * sum: integer weights over one integer denominator, summed exactly in
 * multi-word integers and divided once (no division instruction, no
 * int64), so the result is the integral rounded to the nearest code. n as
 * fresnel_lut_u16_q15; result in [0, max(one, largest node)]. Error <=
 * FRESNEL_BOUND_LUT_AVG_Q15 LSB against the interpolant's integral in
 * double at the table's values, held to that range, every n and table.
 * Cost per node: about 20 16x16-bit multiplies; then one 32-step division
 * (a material's average is made once, not per pixel). */
fresnel_q15 fresnel_lut_avg_u16_q15(const uint16_t *table, int n);
fresnel_q15 fresnel_lut_cubic_avg_u16_q15(const uint16_t *table, int n);
fresnel_q15 fresnel_lut_linear_avg_u16_q15(const uint16_t *table, int n);
fresnel_rgb_q15 fresnel_lut_avg_u16_q15_rgb(const uint16_t *table, int n);
fresnel_rgb_q15 fresnel_lut_cubic_avg_u16_q15_rgb(const uint16_t *table, int n);
fresnel_rgb_q15 fresnel_lut_linear_avg_u16_q15_rgb(const uint16_t *table, int n);

/* ------------------------------------------------------------------ batches */

/* A scanline of one material at a time: out[i] is the scalar call's result
 * for cosine c[i], i < n, bit for bit (so within the same bound):
 *   fresnel_schlick_q15_batch(f0, c, out, n)            fresnel_schlick_q15
 *   fresnel_schlick_gen_q15_batch(f0, f90, p, c, out, n) fresnel_schlick_gen_q15
 *   fresnel_f82_q15_batch(f0, f82, c, out, n)            fresnel_f82_q15
 *   fresnel_lut_u16_q15_batch(table, nodes, c, out, n)   fresnel_lut_u16_q15
 *   (and _linear_, _cubic_), and the _rgb_batch forms, one fresnel_rgb_q15
 *   per cosine as the _rgb call returns it.
 * c: Q15 cosine codes, as a scanline's N.V holds them (0..65535; a code
 * above one reads as one, as the scalar calls' clamp reads it). out must
 * not overlap c; n <= 0 writes nothing; nothing at or past n is read or
 * written. Reentrant, no state, no allocation.
 * The body is chosen at compile time from the target:
 *   Helium (__ARM_FEATURE_MVE: Cortex-M55, M85): Schlick, generalized
 *     Schlick at p = 5, F82 and their _rgb forms, and the one-channel u16
 *     LUTs (the square root too), four cosines per step in 32-bit lanes,
 *     the last step predicated (no scalar tail);
 *   a 32 x 32 -> 64-bit multiply in one instruction (Arm but Armv6-M and
 *     Armv8-M Baseline, so Cortex-M3, M4, M7, M33; RISC-V with M; x86-64;
 *     AArch64): each Q30 product one multiply, where the scalar calls take
 *     four of 15-bit halves (they keep to 32-bit products for the
 *     Cortex-M0);
 *   otherwise (Cortex-M0, M0+, M23) the scalar calls' arithmetic, with
 *     their per-call clamps and set-up done once.
 * The Armv7E-M DSP extension's 16-bit lane instructions are not used: the
 * Q30 intermediates that keep the bound need 32-bit lanes, which is what
 * the long multiply gives. Every body takes the same exact floors, so all
 * agree bit for bit: tests/runtime/q15/test_q15_batch.c checks every cos
 * code on the host against the scalar calls, `make cross-test` the
 * Cortex-M0, M4F and M55 under qemu against the host. The power of
 * p != 5 and the cubic LUT are the scalar calls' in every body. The sqrt
 * LUT's position with the long multiply: the root's last two corrections
 * are taken only where they can move the position (about 2 (nodes - 1) in
 * 2^15 cosines, every cosine from 2^14 + 1 nodes), so its time per cosine
 * varies with c, where the scalar call's does not.
 * Cost per cosine: `make cross-count` (rows ending in "batch", against the
 * scalar call's rows; ports/README.md). */
void fresnel_schlick_q15_batch(int32_t f0, const fresnel_q15 *c, fresnel_q15 *out, int n);
void fresnel_schlick_q15_rgb_batch(fresnel_rgb_q15 f0, const fresnel_q15 *c, fresnel_rgb_q15 *out, int n);
void fresnel_schlick_gen_q15_batch(int32_t f0, int32_t f90, fresnel_q16 p, const fresnel_q15 *c, fresnel_q15 *out,
                                   int n);
void fresnel_schlick_gen_q15_rgb_batch(fresnel_rgb_q15 f0, fresnel_rgb_q15 f90, fresnel_q16 p, const fresnel_q15 *c,
                                       fresnel_rgb_q15 *out, int n);
void fresnel_f82_q15_batch(int32_t f0, int32_t f82, const fresnel_q15 *c, fresnel_q15 *out, int n);
void fresnel_f82_q15_rgb_batch(fresnel_rgb_q15 f0, fresnel_rgb_q15 f82, const fresnel_q15 *c, fresnel_rgb_q15 *out,
                               int n);
void fresnel_lut_u16_q15_batch(const uint16_t *table, int nodes, const fresnel_q15 *c, fresnel_q15 *out, int n);
void fresnel_lut_linear_u16_q15_batch(const uint16_t *table, int nodes, const fresnel_q15 *c, fresnel_q15 *out, int n);
void fresnel_lut_cubic_u16_q15_batch(const uint16_t *table, int nodes, const fresnel_q15 *c, fresnel_q15 *out, int n);
void fresnel_lut_u16_q15_rgb_batch(const uint16_t *table, int nodes, const fresnel_q15 *c, fresnel_rgb_q15 *out, int n);
void fresnel_lut_linear_u16_q15_rgb_batch(const uint16_t *table, int nodes, const fresnel_q15 *c, fresnel_rgb_q15 *out,
                                          int n);
void fresnel_lut_cubic_u16_q15_rgb_batch(const uint16_t *table, int nodes, const fresnel_q15 *c, fresnel_rgb_q15 *out,
                                         int n);

/* ------------------------------------------------------------- math_q15.c */

/* floor(sqrt(x)) for every uint32_t x. Exact.
 * Cost: 16 digit steps, no multiply, no division. */
uint32_t fresnel_isqrt_u32(uint32_t x);

/* floor(n * 2^k / d) for 1 <= d < 2^31, n < 2d, 0 <= k <= 31: a quotient of
 * k + 1 bits. Exact. Cost: k + 1 steps, no division instruction. */
uint32_t fresnel_udiv_frac_u32(uint32_t n, uint32_t d, int k);

/* Reciprocal in Q16.16: round(2^32 / x) for x in [2, 2^31); x = 1 and
 * below saturate to 2^31 - 1. Exact. Cost: 32 steps. */
fresnel_q16 fresnel_recip_q16(fresnel_q16 x);

#endif /* FRESNEL_HAS_Q15 */

#ifdef __cplusplus
}
#endif
#endif /* FRESNEL_Q15_H */
