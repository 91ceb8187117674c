/* fresnel_fixed.h -- integer-only Fresnel reflectance: the fixed-point API and its manual.
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
 *     #include "fresnel_fixed.h"
 *     int32_t c = dot_q15(n, v);                         // any int32; clamped to [0, one]
 *     fresnel_q15 r = fresnel_schlick_q15(1311, c);      // F0 = 0.04: 1311/32768
 *     static const fresnel_q15_ior gold_r = {...};       // made on the host (LAYOUT)
 *     fresnel_q15 au = fresnel_conductor_q15(&gold_r, c);
 *
 * NUMBER FORMATS
 *   fresnel_q15  unsigned Q1.15 in uint16_t: value = code / 32768.
 *                FRESNEL_Q15_ONE = 32768 = 0x8000 is 1.0; codes 32769..65535
 *                (up to 2 - 2^-15) are headroom that no result uses.
 *                Used for cos(theta), F0, F82, F90, Gulbrandsen r and g,
 *                and every result. Arguments are taken as int32_t so that a
 *                signed dot product can be passed as is: values below 0 are
 *                0, above 32768 are 32768 (the same clamping policy as
 *                fresnel.h; F0 above 1 is therefore evaluated as 1). Results
 *                are always in [0, 32768].
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
 *   it (the generator, or gen/fixed_params.c from double eta and kappa), or
 *   the *_prepare functions below fill it at run time from Q16.16 inputs.
 *
 * ERROR BOUNDS
 *   FRESNEL_Q15_BOUND_* are in LSB of Q15 (1 LSB = 2^-15 = 3.05e-5): the
 *   largest |result/32768 - reference| measured by tests/test_fixed_bounds.c
 *   for EVERY cos code 0..32768 and every material of the test set (66:
 *   eta, kappa of au cu ag al cr fe pt ti ni zn at 450, 550 and 650 nm from
 *   data/\*.csv and the same metals under water, bk7 and water from both
 *   sides, and corners of the domain; tests/fixed_materials.h), where
 *   "reference" is the double model of gen/reference.c at the same c and
 *   parameters (model_params_round_fixed): the Q15 inputs (F0, F82, F90, r,
 *   g) as the codes given, the Q16.16 ones (p, alpha) as the codes given,
 *   and eta, kappa as the double values the prepared constants were made
 *   from, so the rounding of the constants is part of the measured error
 *   (eta is not adjusted: a0 and a0_lo hold eta^2 - kappa^2 - 1 to 60 bits,
 *   enough also at a dielectric's critical angle, where the reflectance is
 *   as sensitive to eta as the physics makes it). F82 and generalized Schlick are also measured on grids of
 *   their parameters, the LUTs on tables of 2 to 1024 nodes. The same bounds
 *   hold over the whole domain eta in [2^-10, 32767], kappa in [0, 32767]
 *   (check_domain: 304 eta, kappa pairs, log-uniform grids, dense toward
 *   eta -> 0, and random, every 5th code and every code within 64 of 0 and
 *   one: the largest maximum is LSK compensated's 0.50005; 4000 eta in
 *   [2^-10, 0.05] near normal incidence for the dielectric; Q16.16 eta
 *   codes from below 2^-10 and at every power of two of eta and kappa for
 *   fresnel_q15_ior_prepare), and the fuzzer (tests/fuzz/fuzz_fixed_models.c)
 *   holds every function to them there. Prepared on the host, eta or kappa
 *   above 46340 ((eta^2 - kappa^2 - 1) 2^-30 at shift 30 must fit int32)
 *   is outside the layout. Rounding the
 *   exact value to the nearest code is already 0.5 LSB. The test asserts
 *   each bound; `make test` prints the maxima. The same results, bit for
 *   bit, come out of the Cortex-M0, Cortex-M4F and RV32IMC builds
 *   (tests/test_cross.sh).
 *
 * COST
 *   "mul" = 32x32->32 multiply (one MULS on Cortex-M0), "qf op" = one
 *   mantissa-exponent multiply/add (~30 instructions), "qf div/sqrt" ~ 200.
 *   Instructions per call on Cortex-M0, measured under qemu, are in
 *   ports/README.md (`make cross-count`).
 *
 * THREAD SAFETY
 *   No global or static mutable state, no allocation, no stdio: reentrant.
 *   Tables are const (flash).
 */
#ifndef FRESNEL_FIXED_H
#define FRESNEL_FIXED_H

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
typedef struct fresnel_q15_rgb {
    fresnel_q15 r, g, b;
} fresnel_q15_rgb;

#define FRESNEL_Q15_ONE 32768
#define FRESNEL_Q16_ONE 65536

/* Domains in fixed point (values outside are clamped, as in fresnel.h). */
#define FRESNEL_Q16_ETA_MIN 64                 /* eta of *_prepare: [1/1024, 32767]; kappa [0, 32767] */
#define FRESNEL_Q16_P_MIN 66                   /* generalized Schlick p: [0.001, 1000] as in fresnel.h */
#define FRESNEL_Q16_P_MAX (1000 * 65536)
#define FRESNEL_Q16_ALPHA_MAX (1000 * 65536)   /* LSK alpha: [0, 1000] */
#define FRESNEL_Q15_GULBRANDSEN_R_MAX 32764    /* largest code below 0.9999 */

/* Measured error bounds, LSB of Q15 (see ERROR BOUNDS). Rounding to the
 * nearest code is 0.5 LSB by itself: every model but the LUTs (and
 * generalized Schlick beyond p = 64) is within 0.001 LSB of that (what
 * shows of the 30-bit intermediates). The LUTs add
 * the position's error times the table's steepest node-to-node change: half
 * a position step, 2^-16 of a segment (0.5 LSB for a two-node table spanning
 * [0, 1]), and for nodes uniform in sqrt(c) the floor of sqrt(c) in Q30,
 * (n-1) 2^-30 of a segment. Measured maxima
 * (tests/test_fixed_bounds.c): Schlick 0.50003, generalized Schlick 0.50029
 * for p <= 64 and 0.50090 for p in (64, 1000] (there (1-c)^p is ten
 * squarings, and the bound is 0.5 plus the power's asserted relative error
 * 2^-21 times 2^15: 0.516), internal 0.50007, F0 0.49992, F0 in medium 0.50004,
 * LSK 0.50002, LSK compensated 0.50004, F82 0.50074 (F0/F82 grid),
 * Gulbrandsen 0.50002, approximate conductor 0.50002, Cook-Torrance 0.50002,
 * conductor 0.50002, dielectric 0.50002, LUT 0.98526 (nodes uniform in
 * sqrt(c); a two-node water table) and 0.50004 (uniform in c). */
#define FRESNEL_Q15_BOUND_SCHLICK 0.501
#define FRESNEL_Q15_BOUND_SCHLICK_GEN 0.516 /* 0.501 for p <= 64; see below */
#define FRESNEL_Q15_BOUND_SCHLICK_INTERNAL 0.501
#define FRESNEL_Q15_BOUND_F0 0.501
#define FRESNEL_Q15_BOUND_F0_IN_MEDIUM 0.501
#define FRESNEL_Q15_BOUND_LSK 0.501
#define FRESNEL_Q15_BOUND_LSK_COMP 0.501
#define FRESNEL_Q15_BOUND_F82 0.501
#define FRESNEL_Q15_BOUND_GULBRANDSEN 0.501
#define FRESNEL_Q15_BOUND_APPROX_CONDUCTOR 0.501
#define FRESNEL_Q15_BOUND_COOK_TORRANCE 0.501
#define FRESNEL_Q15_BOUND_CONDUCTOR 0.501
#define FRESNEL_Q15_BOUND_DIELECTRIC 0.501
#define FRESNEL_Q15_BOUND_LUT 1.01
#define FRESNEL_Q15_BOUND_LUT_CUBIC 2.2 /* [2.1917 on any table: weights rounded to Q15; tests/test_lut_cubic] */

#if FRESNEL_HAS_FIXED

/* ------------------------------------------------------------ prepared constants
 *
 * LAYOUT: the value of every field below, as `fresnel gen` emits it, is
 * specified in gen/4_emit/README.md.
 */
typedef struct fresnel_q15_ior {
    int32_t a0, a0_lo;
    int32_t shift;
    fresnel_qf b, n4, t1_inv, inv_eta2;
} fresnel_q15_ior;

typedef struct fresnel_q15_nk {
    fresnel_qf n, nk2;
} fresnel_q15_nk;

typedef struct fresnel_q15_lsk {
    uint32_t f0;
    fresnel_qf a;
    fresnel_q16 alpha;
} fresnel_q15_lsk;

/* Run-time preparation from Q16.16 eta and kappa (clamped to
 * [FRESNEL_Q16_ETA_MIN, 2^31 - 1] and [0, 2^31 - 1]). The constants are
 * computed from the Q16.16 codes with 31-bit mantissas, so they are as good
 * as the inputs; Q16.16 itself resolves eta to 1.5e-5, which for silver
 * (eta 0.05) is a 3e-4 relative change: prepare on the host from double
 * where that matters. Cost: ~10 qf ops, 2 qf div (ior). */
void fresnel_q15_ior_prepare(fresnel_q16 eta, fresnel_q16 kappa, fresnel_q15_ior *out);
void fresnel_q15_nk_prepare(fresnel_q16 n, fresnel_q16 k, fresnel_q15_nk *out);
/* a and alpha are LSK's compensation constants (ref_lsk_fit on the host);
 * a = 0 gives the rescaled model. */
void fresnel_q15_lsk_prepare(fresnel_q16 n, fresnel_q16 k, fresnel_q16 a, fresnel_q16 alpha,
                             fresnel_q15_lsk *out);

/* ---------------------------------------------------------------- schlick_q15.c */

/* Schlick:  F = F0 + (1 - F0)(1 - c)^5.
 * x = 1 - c exact in Q15; x^2 exact in Q30; x^4 and x^5 in Q30 through
 * 15-bit halves (no int64), so the only rounding that shows is the final one.
 * Error <= FRESNEL_Q15_BOUND_SCHLICK LSB. Cost: 8 mul. */
fresnel_q15 fresnel_schlick_q15(int32_t f0, int32_t c);
fresnel_q15_rgb fresnel_schlick_q15_rgb(fresnel_q15_rgb f0, int32_t c);

/* Generalized Schlick:  F = F0 + (F90 - F0)(1 - c)^p,  p Q16.16 in
 * [FRESNEL_Q16_P_MIN, FRESNEL_Q16_P_MAX] (clamped). p = 5 takes Schlick's
 * path. Other p: (1-c)^p = (1-c)^floor(p) by repeated squaring in qf, times
 * 2^(-frac(p) L), L = -log2(1-c): log2 from a 64-entry reciprocal table and
 * the series of log(1 + d), |d| < 2^-7, to the cubic term; 2^-y from a
 * 64-entry table and the series of exp to the cubic term. Relative error
 * < 2^-24 for p <= 64, < 2^-21 up to p = 1000 (the squarings of x^1000;
 * measured 2^-22.4) (tests/test_fixed_math.c). Error <=
 * FRESNEL_Q15_BOUND_SCHLICK_GEN LSB (0.501 for p <= 64), measured for p in
 * {0.001, 0.25, 0.5, 1, 2, 3.7, 5, 8, 40, 1000} and 500 p in (64, 1000], F90
 * in {0, 0.5, 1}. Cost: p = 5: 9 mul; else ~2 log2(p) qf mul + ~25 mul. */
fresnel_q15 fresnel_schlick_gen_q15(int32_t f0, int32_t f90, fresnel_q16 p, int32_t c);
fresnel_q15_rgb fresnel_schlick_gen_q15_rgb(fresnel_q15_rgb f0, fresnel_q15_rgb f90, fresnel_q16 p,
                                            int32_t c);

/* Schlick for internal reflection: m prepared from eta (kappa 0) relative
 * to the incident side, as fresnel_schlick_internal. eta >= 1 (a0 >= 0):
 * Schlick at c. eta < 1: ct^2 = (a0 + c^2) / eta^2; past the critical angle
 * (ct^2 <= 0) the result is one; otherwise Schlick at ct, evaluated from ct
 * in qf (not rounded to a Q15 cosine first).
 * Error <= FRESNEL_Q15_BOUND_SCHLICK_INTERNAL LSB. Cost: ~8 qf ops, 1 qf sqrt. */
fresnel_q15 fresnel_schlick_internal_q15(int32_t f0, const fresnel_q15_ior *m, int32_t c);
fresnel_q15_rgb fresnel_schlick_internal_q15_rgb(fresnel_q15_rgb f0, const fresnel_q15_ior *m,
                                                 int32_t c);

/* F0 = ((eta-1)^2 + kappa^2) / ((eta+1)^2 + kappa^2) from Q16.16 eta, kappa
 * (eta clamped to [FRESNEL_Q16_ETA_MIN, 2^31-1], kappa to [0, 2^31-1]).
 * Error <= FRESNEL_Q15_BOUND_F0 LSB against the double formula at the same
 * Q16.16 codes. Cost: 4 qf ops, 1 qf div. */
fresnel_q15 fresnel_f0_from_ior_q15(fresnel_q16 eta, fresnel_q16 kappa);

/* Hoffman's external-medium adjustment of F0 (fresnel_f0_in_medium), etaE
 * Q16.16 clamped like eta, F0 Q15. Same cancellation-free rearrangement.
 * Error <= FRESNEL_Q15_BOUND_F0_IN_MEDIUM LSB. Cost: ~8 qf ops, 2 qf div, 1 qf sqrt. */
fresnel_q15 fresnel_f0_in_medium_q15(int32_t f0, fresnel_q16 eta_e);

/* -------------------------------------------------------------------- lsk_q15.c */

/* LSK rescaled: Schlick with m->f0 (Q30). Error <= FRESNEL_Q15_BOUND_LSK LSB. Cost: 10 mul. */
fresnel_q15 fresnel_lsk_q15(const fresnel_q15_lsk *m, int32_t c);
fresnel_q15_rgb fresnel_lsk_q15_rgb(const fresnel_q15_lsk m[3], int32_t c);

/* LSK compensated:  F = LSK - a c (1 - c)^alpha, clamped to [0, 1].
 * (1-c)^alpha as in fresnel_schlick_gen_q15. Error <= FRESNEL_Q15_BOUND_LSK_COMP
 * LSB. Cost: LSK + pow (~2 log2(alpha) qf mul + ~20 mul) + 2 qf mul. */
fresnel_q15 fresnel_lsk_comp_q15(const fresnel_q15_lsk *m, int32_t c);
fresnel_q15_rgb fresnel_lsk_comp_q15_rgb(const fresnel_q15_lsk m[3], int32_t c);

/* -------------------------------------------------------------------- f82_q15.c */

/* Hoffman's F82 model:  F = F0 + (1-F0)(1-c)^5 - a c (1-c)^6,
 * a = (7^7/6^6)(F0 - F82) + (49/6)(1 - F0), clamped to [0, 1] like fresnel_f82.
 * Written as a c (1-c)^6 = g(c) [(F0 - F82) + (7/6)^-6 ... ] with
 * g(c) = (7^7/6^6) c (1-c)^6 in [0, 1] (its maximum is 1, at c = 1/7), so
 * every product stays inside int32 with 30 fractional bits.
 * Error <= FRESNEL_Q15_BOUND_F82 LSB. Cost: ~16 mul. */
fresnel_q15 fresnel_f82_q15(int32_t f0, int32_t f82, int32_t c);
fresnel_q15_rgb fresnel_f82_q15_rgb(fresnel_q15_rgb f0, fresnel_q15_rgb f82, int32_t c);

/* -------------------------------------------------------- gulbrandsen_q15.c */

/* Gulbrandsen's r, g -> n, k (fresnel_gulbrandsen_nk), r clamped to
 * [0, FRESNEL_Q15_GULBRANDSEN_R_MAX], in qf; the result is prepared for
 * fresnel_approx_conductor_q15, with n clamped below at fresnel.h's
 * FRESNEL_ETA_MIN as fresnel_gulbrandsen does (r -> 1, g = 1 gives n -> 0). k^2 = q (q + 4 (1-g) sqrt(r) nmax / (1-r)),
 * q = 2 g sqrt(r) / (1+r): fresnel.h's factored k^2 with its last difference
 * (sqrt r (n+1) + n - 1, which cancels as r -> 1, g -> 1) expanded into
 * positive terms. Cost: ~14 qf ops, 4 qf div, 1 qf sqrt. */
void fresnel_gulbrandsen_nk_q15(int32_t r, int32_t g, fresnel_q15_nk *out);
/* The inverse n, k (Q16.16) -> r, g (Q15), as fresnel_gulbrandsen_rg. */
void fresnel_gulbrandsen_rg_q15(fresnel_q16 n, fresnel_q16 k, fresnel_q15 *r, fresnel_q15 *g);
/* fresnel_approx_conductor_q15 at the n, k of r, g (mapping each call;
 * prepare once with fresnel_gulbrandsen_nk_q15 when r, g are constant).
 * Error <= FRESNEL_Q15_BOUND_GULBRANDSEN LSB. */
fresnel_q15 fresnel_gulbrandsen_q15(int32_t r, int32_t g, int32_t c);
fresnel_q15_rgb fresnel_gulbrandsen_q15_rgb(fresnel_q15_rgb r, fresnel_q15_rgb g, int32_t c);

/* --------------------------------------------------- approx_conductor_q15.c */

/* Approximate conductor form, as fresnel_approx_conductor, in its
 * transmittance form: 1 - rs = 4nc / (N + 2nc + c^2) and
 * 1 - rp = 4nc / (N c^2 + 2nc + 1), N = n^2 + k^2: sums of positive terms
 * only, so qf keeps ~30 bits and only the final rounding shows.
 * Error <= FRESNEL_Q15_BOUND_APPROX_CONDUCTOR LSB. Cost: ~10 qf ops, 2 qf div. */
fresnel_q15 fresnel_approx_conductor_q15(const fresnel_q15_nk *m, int32_t c);
fresnel_q15_rgb fresnel_approx_conductor_q15_rgb(const fresnel_q15_nk m[3], int32_t c);

/* ------------------------------------------------------- cook_torrance_q15.c */

/* Cook-Torrance colour interpolation (fresnel_cook_torrance):
 *   F = F0 + (1 - F0) max(0, 1 - T(c) / T(1)),  T = 1 - exact Fresnel of m,
 * T(c) from the conductor's transmittance form, 1/T(1) = m->t1_inv.
 * Error <= FRESNEL_Q15_BOUND_COOK_TORRANCE LSB. Cost: conductor + 1 qf mul. */
fresnel_q15 fresnel_cook_torrance_q15(int32_t f0, const fresnel_q15_ior *m, int32_t c);
fresnel_q15_rgb fresnel_cook_torrance_q15_rgb(fresnel_q15_rgb f0, const fresnel_q15_ior *m, int32_t c);

/* --------------------------------------------------------------- exact_q15.c */

/* Exact unpolarised Fresnel of eta + i kappa (fresnel_conductor), in the
 * transmittance form, every term a sum of positive quantities:
 *   A = a0 + c^2 (= eta^2 - kappa^2 - sin^2, exact c^2 in Q30),
 *   w = u + iv = sqrt(A + i b), m = |w|^2 = sqrt(A^2 + b^2) (u or v from
 *   (m + |A|)/2, the other from u v = b/2),
 *   Ts = 4cu / (c^2 + 2cu + m),
 *   Tp = 4cu (m + s^2) / (|z|^4 c^2 + 2cu (m + s^2) + m),  s^2 = 1 - c^2,
 *   F = 1 - (Ts + Tp)/2.
 * (The p-numerator identity Re(z^2 conj w) = u (m + s^2) is what removes the
 * differences of the textbook form.) kappa = 0 with eta < 1 gives total
 * internal reflection (u = 0, F = one) past the critical angle; a0 = b = 0
 * (matched index) gives 0 for every c.
 * Error <= FRESNEL_Q15_BOUND_CONDUCTOR LSB. Cost: ~14 qf ops, 3 qf div, 2 qf sqrt. */
fresnel_q15 fresnel_conductor_q15(const fresnel_q15_ior *m, int32_t c);
fresnel_q15_rgb fresnel_conductor_q15_rgb(const fresnel_q15_ior m[3], int32_t c);

/* Exact dielectric (b = 0 in m): w = sqrt(A) or TIR; the same formulas with
 * v = 0, one square root fewer. Error <= FRESNEL_Q15_BOUND_DIELECTRIC LSB.
 * Cost: ~10 qf ops, 2 qf div, 1 qf sqrt. */
fresnel_q15 fresnel_dielectric_q15(const fresnel_q15_ior *m, int32_t c);

/* ----------------------------------------------------------------- lut_q15.c */

/* Lookup tables (fresnel_lut and friends) in integers. table[i], i = 0..n-1,
 * 2 <= n <= 32768, is the reflectance at node i; the result interpolates
 * linearly between the two nodes around c. Node spacing, as fresnel.h's
 * (the tables of `fresnel gen` are read at the positions they were made for):
 *   fresnel_lut_*        uniform in sqrt(c) (node i at c = (i/(n-1))^2): the
 *                        position is sqrt(c) (n-1), sqrt(c) the exact floor
 *                        in Q30 (fresnel_isqrt_u32 on c 2^15, then 15 more
 *                        digits), rounded to a 15-bit fraction of a segment
 *   fresnel_lut_linear_* uniform in c (node i at c = i/(n-1)), exact
 * Encodings:
 *   _u16  uint16_t, F = v / 32768 (v <= 32768)
 *   _u8   uint8_t,  F = v / 255   (each node decoded to Q15 first, +-0.5 LSB)
 *   residual (F = Schlick(F0, c) + interpolated residual):
 *   _s16  int16_t, residual = v / 2^frac, frac in [14, 30]
 *   _s8   int8_t,  residual = v / 2^frac, frac in [6, 22]
 *         (frac 14 / 6 hold a residual of 1: the generator's residual nodes
 *         are in [-1, 1])
 * n outside [2, 32768] (any int): n <= 0 reads no entry and gives 0 (the
 * _residual forms: Schlick alone), n = 1 is the constant table[0], n above
 * 32768 is read as 32768 nodes (the _rgb forms: 3 x 32768 entries, the
 * channels at 0, 32768, 65536), so no entry past the table is read.
 * Results are clamped to [0, one]. Error <= FRESNEL_Q15_BOUND_LUT LSB against
 * the same interpolation in double (the table's own error is the
 * generator's business); between two nodes that differ by s > 1 (a
 * residual table's nodes may span [-1, 1]) the position's part grows with
 * the step: <= 0.51 + 0.5 s LSB (tests/test_lut_residual_range.c). Cost: uniform in c, 3 mul, no division (~100
 * instructions on Cortex-M0); uniform in sqrt(c), the square root's 31
 * digit steps and 1 mul more (~400; ports/README.md). The _residual forms
 * add Schlick's 8 mul. */
fresnel_q15 fresnel_lut_q15_u16(const uint16_t *table, int n, int32_t c);
fresnel_q15 fresnel_lut_linear_q15_u16(const uint16_t *table, int n, int32_t c);
fresnel_q15 fresnel_lut_q15_u8(const uint8_t *table, int n, int32_t c);
fresnel_q15 fresnel_lut_linear_q15_u8(const uint8_t *table, int n, int32_t c);
fresnel_q15 fresnel_lut_residual_q15_s16(int32_t f0, const int16_t *table, int n, int frac, int32_t c);
fresnel_q15 fresnel_lut_linear_residual_q15_s16(int32_t f0, const int16_t *table, int n, int frac,
                                                int32_t c);
fresnel_q15 fresnel_lut_residual_q15_s8(int32_t f0, const int8_t *table, int n, int frac, int32_t c);
fresnel_q15 fresnel_lut_linear_residual_q15_s8(int32_t f0, const int8_t *table, int n, int frac,
                                               int32_t c);
fresnel_q15_rgb fresnel_lut_q15_u16_rgb(const uint16_t *table, int n, int32_t c);
fresnel_q15_rgb fresnel_lut_linear_q15_u16_rgb(const uint16_t *table, int n, int32_t c);
fresnel_q15_rgb fresnel_lut_q15_u8_rgb(const uint8_t *table, int n, int32_t c);
fresnel_q15_rgb fresnel_lut_linear_q15_u8_rgb(const uint8_t *table, int n, int32_t c);
fresnel_q15_rgb fresnel_lut_residual_q15_s16_rgb(fresnel_q15_rgb f0, const int16_t *table, int n,
                                                 int frac, int32_t c);
fresnel_q15_rgb fresnel_lut_linear_residual_q15_s16_rgb(fresnel_q15_rgb f0, const int16_t *table,
                                                        int n, int frac, int32_t c);
fresnel_q15_rgb fresnel_lut_residual_q15_s8_rgb(fresnel_q15_rgb f0, const int8_t *table, int n,
                                                int frac, int32_t c);
fresnel_q15_rgb fresnel_lut_linear_residual_q15_s8_rgb(fresnel_q15_rgb f0, const int8_t *table,
                                                       int n, int frac, int32_t c);

/* fresnel_lut_cubic (fresnel.h) on uint16_t nodes: the position as
 * fresnel_lut_q15_u16, Catmull-Rom weights in Q15 (shared by the three
 * channels of the _rgb form), a 4-term sum in Q30, rounded and clamped.
 * Tables must be fitted for the cubic (lutN-cubic). Error <=
 * FRESNEL_Q15_BOUND_LUT_CUBIC LSB against the same cubic in double at the
 * table's values. Cost: the position of fresnel_lut_q15_u16, 7 mul for the
 * weights, 4 per channel. */
fresnel_q15 fresnel_lut_cubic_q15_u16(const uint16_t *table, int n, int32_t c);
fresnel_q15_rgb fresnel_lut_cubic_q15_u16_rgb(const uint16_t *table, int n, int32_t c);

/* ------------------------------------------------------------- math_q15.c */

/* floor(sqrt(x)) for every uint32_t x, digit by digit (16 steps, no
 * multiply, no division). Tested on every x < 2^24 and at k^2 - 1, k^2 for
 * every k < 2^16 (tests/test_fixed_math.c). */
uint32_t fresnel_isqrt_u32(uint32_t x);

/* floor(n * 2^k / d), bit by bit (k + 1 steps, no division instruction), for
 * 1 <= d < 2^31, n < 2d, 0 <= k <= 31: a quotient of k + 1 bits. Tested on
 * every (n, d) with d < 2^12 for k = 0, 15, 31, and on 10^7 random ones. */
uint32_t fresnel_udiv_frac_u32(uint32_t n, uint32_t d, int k);

/* Reciprocal in Q16.16: round(2^32 / x) for x in [2, 2^31) (x = 1 and
 * below saturate to 2^31 - 1). Tested on every x < 2^24 and 10^7 random
 * ones. Cost: 32 steps. */
fresnel_q16 fresnel_recip_q16(fresnel_q16 x);

#endif /* FRESNEL_HAS_FIXED */

#ifdef __cplusplus
}
#endif
#endif /* FRESNEL_FIXED_H */
