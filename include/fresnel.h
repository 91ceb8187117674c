/* fresnel.h -- Fresnel reflectance for small devices: the public API and its manual.
 *
 * WHAT IT IS
 *   Allocation-free C99 functions that return how much light a smooth interface
 *   reflects at a given angle: Schlick and its generalisations, Lazanyi and
 *   Szirmay-Kalos (LSK), Hoffman's F82 model, Gulbrandsen's edge tint, Cook and
 *   Torrance's colour interpolation, and the exact Fresnel equations for
 *   conductors and dielectrics. Material constants (F0, F82, RGB eta and kappa,
 *   LSK a and alpha, ...) are made on the host by `build/fresnel gen` from
 *   measured spectral data; this header only evaluates them.
 *
 * USE
 *     #include "fresnel.h"
 *     float c = dot(n, v);                               // any float; clamped
 *     float r = fresnel_schlick(0.04f, c);               // glass-like
 *     fresnel_rgb cu = fresnel_conductor_rgb(eta, kappa, c);
 *   Link src/f32/\*.c (or the installed libfresnel.a) and -lm. Each number
 *   type's code is one self-contained folder: src/f32/ (this header),
 *   src/q15/ (fresnel_q15.h), src/f16/ (fresnel_f16.h). A vendoring
 *   project copies include/ and the folders of the types it uses.
 *
 * NAMING (the rule of every public name of include/\*.h; the word lists,
 * "slot = words;", are what tests/repo/test_public_names.sh checks names with)
 *   Functions: fresnel_<model>[_<form>...][_avg][_<storage>][_<type>][_rgb][_<call>]
 *     model = schlick lsk f82 gulbrandsen approx_conductor cook_torrance
 *             conductor dielectric f0 lut film;
 *     form = gen internal comp prepared from_ior in_medium nk rg linear
 *            residual cubic pl;
 *            the variant, none, one or several in this order;
 *     _avg   the hemispherical average instead of the value at c;
 *     storage = u16 u8 s16 s8;
 *            a table's element type where it is not the type;
 *     type = q15 f16;
 *            Q1.15 fixed point, binary16, none for binary32;
 *     _rgb   three channels;
 *     call = fast batch;
 *            an inline fast path, many cosines.
 *   e.g. fresnel_lut_linear_residual_s16_q15_rgb, fresnel_schlick_q15_rgb_fast,
 *   fresnel_lut_cubic_avg_u16_q15. The type comes after what is computed
 *   and before _rgb and the call, so that a model's variants and its types
 *   sort together and the type is read in one place.
 *   Prepared constants: fresnel_<what>_prepare[_<type>](eta, kappa, ...)
 *   returns a fresnel_<what>_prep[_<type>] by value, <what> the model or a
 *   quantity several models read (fresnel_conductor_prepare,
 *   fresnel_ior_prepare_q15); a fresnel_<what>_prep[_<type>]_fast holds a
 *   fast path's constants, which only the host makes (`fresnel gen`).
 *     quantity = ior nk rg rgb;
 *   Other types: fresnel_<model or quantity>[_node][_<type>] (fresnel_rgb,
 *   fresnel_rgb_q15, fresnel_film_node_f16); a number type is its word,
 *     number = q15 q16 qf f16;
 *   Constant tables: fresnel_<model>[_<form>...]_<table>_<type>,
 *     table = knots;
 *   Utilities name the operation and the integer type (fresnel_isqrt_u32),
 *     operation = isqrt udiv_frac recip;
 *     integer = u32 q16;
 *   Parameters: eta, kappa for a complex index, c for the cosine.
 *   Macros: FRESNEL_<NAME>[_<TYPE>][_FAST][_<QUALIFIER>], the binary32
 *   name with the type appended, so that the types' limits sit together
 *   (FRESNEL_ETA_MIN, FRESNEL_ETA_MIN_Q16, FRESNEL_ETA_MIN_F16);
 *     TYPE = Q15 Q16 F16;
 *     QUALIFIER = HEADROOM TIR DIELECTRIC NONCRITICAL 1024;
 *            where a second bound or limit of the same name applies.
 *   <NAME> is one of
 *     BOUND_<F>, DOMAIN_<F>: a function's error bound (DOMAIN_ over the
 *       whole domain where BOUND_ is over a material set, fresnel_f16.h),
 *       <F> its name without fresnel_, storage and _rgb, in capitals, the
 *       type and call in their slots (fresnel_lut_pl_u16_q15_fast:
 *       FRESNEL_BOUND_LUT_PL_Q15_FAST); a bound for a family leaves out
 *       the slot that varies (FRESNEL_BOUND_LUT_Q15 for every LUT,
 *       FRESNEL_BOUND_F16_NONCRITICAL for every model);
 *     [<MODEL>_]<QUANTITY>_<LIMIT>: a limit of a domain, the model's own
 *       where it has one (FRESNEL_GULBRANDSEN_R_MAX);
 *       QUANTITY = ETA KAPPA P ALPHA A C R N D MATCH;
 *       LIMIT = MIN MAX TINY;
 *     ONE, the number 1 in the type; VERSION; <MODEL>_<SIZE>, a size of a
 *       model's tables;
 *       SIZE = POLES NODES;
 *     CONFIG, CFG_<FLAG>, HAS_<FEATURE> (fresnel_config.h);
 *       FLAG = NO_FLOAT NO_F16 NO_Q15 NO_SIMD KNOWN_FLAGS;
 *       FEATURE = FLOAT F16 Q15 SIMD;
 *     <HEADER>_H, the include guard of fresnel_<header>.h (FRESNEL_H).
 *   The runtime's internal helpers are fresnel_i_* and FRESNEL_I_*
 *   (fresnel_config.h), not API. A header's ALIASES block #defines second
 *   names that code and generated headers may spell, each to its rule name.
 *
 * CONVENTIONS (every function)
 *   c        cosine of the angle of incidence, measured in the incident medium.
 *            Domain [0, 1]. Values outside are clamped (c > 1 -> 1, c < 0 -> 0);
 *            NaN and -Inf give 0, +Inf gives 1.
 *   eta, kappa
 *            complex index of refraction of the far side RELATIVE to the
 *            incident medium: for a metal seen from a medium of real index n1,
 *            pass eta/n1 and kappa/n1. Domain eta in [FRESNEL_ETA_MIN,
 *            FRESNEL_ETA_MAX], kappa in [0, FRESNEL_KAPPA_MAX]; values outside
 *            are clamped, NaN gives the lower end; kappa below
 *            FRESNEL_KAPPA_TINY is 0.
 *   f0, f82, f90, r, g
 *            reflectances or edge tints, domain [0, 1]; clamped, NaN gives 0.
 *            (Out-of-gamut F0 above 1 is therefore evaluated as 1.)
 *   result   always in [0, 1], never NaN or Inf, for every input including
 *            NaN and Inf; the curve tables (fresnel_lut, _linear, _cubic)
 *            are in [0, max(1, largest node)] (finite nodes).
 *   Colours outside the display's gamut: the generator's gamut policy
 *   (README) decides what the constants and tables hold. Under `keep`
 *   (values above 1 kept, for HDR and wide-gamut pipelines) only the curve
 *   tables carry them, here and in fresnel_q15.h (uint16_t nodes, up to
 *   2 - 2^-15) and fresnel_f16.h; every other function, the residual tables
 *   included, clamps F0 and its result to 1 as above, so gold's F0 of 1.04
 *   in linear sRGB is evaluated as 1 by them.
 *   Error bounds are absolute, against a double-precision evaluation of the
 *   SAME model with the same binary32 inputs (gen/common/reference.c). They hold for
 *   eta in [0.01, 100], kappa in {0} u [1e-3, 1000] (relative indices, such
 *   as eta/n1 for an incident medium n1) and every c; fresnel_lsk_comp's and
 *   fresnel_gulbrandsen_rg's over the whole eta, kappa domain. On the rest of
 *   the domain (eta in [2^-10, 0.01) or (100, 1e5], kappa above 1000) the
 *   result is in [0, 1]. tests/README.md names the test and grid behind
 *   each bound.
 *   How far each MODEL is from the exact Fresnel equations is a different
 *   question, answered by `build/fresnel accuracy` (see README).
 *   Cost counts binary32 operations: "flop" = add, sub or mul; div, sqrt and
 *   libm calls are named.
 *
 * THREAD SAFETY
 *   No global state, no allocation, no stdio, no errno: every function is
 *   reentrant. <math.h> is used: sqrtf everywhere, expf and log1pf
 *   (generalized Schlick with p != 5, LSK compensation), fmaf only where the target
 *   has the instruction (FP_FAST_FMAF, __FMA__, __ARM_FEATURE_FMA).
 *   Build src/ without -ffast-math, -ffinite-math-only, -fassociative-math
 *   and -Ofast: the NaN policy needs NaN comparisons, and the exact forms
 *   (critical angles) need IEEE rounding. src/f32/internal.h stops the build
 *   with #error where the compiler says it is on (__FAST_MATH__,
 *   __FINITE_MATH_ONLY__); a vendoring user with such a global flag compiles
 *   src/f32/\*.c with -fno-fast-math (gcc, clang) or without it.
 *   Nor with clang's -ffp-contract=fast, which disregards the pragma by which
 *   src/f32/internal.h keeps a * b + c from being fused (the batches then
 *   differ from fresnel_conductor_prepared in the last bit); every other
 *   mode is fine: gcc's GNU modes and its -ffp-contract=fast are overridden
 *   there, clang's default (on) honours the pragma.
 *
 * REFERENCES
 *   [Sch94]  C. Schlick, An inexpensive BRDF model for physically-based rendering, 1994.
 *   [LS05]   I. Lazanyi, L. Szirmay-Kalos, Fresnel term approximations for metals, WSCG 2005.
 *   [Gul14]  O. Gulbrandsen, Artist friendly metallic Fresnel, JCGT 3(4), 2014.
 *   [Hof20]  N. Hoffman, Some thoughts on the Fresnel term, SIGGRAPH 2020 course notes.
 *   [MS18]   J. Metzgar, S. Semwal, Optimizing spectral Fresnel reflectance for displays, 2018.
 */
#ifndef FRESNEL_H
#define FRESNEL_H

#include "fresnel_config.h"

#ifdef __cplusplus
extern "C" {
#endif

#define FRESNEL_VERSION "0.1.0"

/* Domain limits for material parameters (see CONVENTIONS). Beyond these the
 * binary32 formulas would overflow or lose all meaning; no measured material
 * comes near them. */
#define FRESNEL_ETA_MIN   0.0009765625f /* 2^-10, as binary16 and Q15 */
#define FRESNEL_ETA_MAX   1e5f
#define FRESNEL_KAPPA_MAX 1e5f
#define FRESNEL_KAPPA_TINY 1e-18f /* kappa below this is taken as 0 */
#define FRESNEL_P_MIN     1e-3f   /* generalized Schlick exponent */
#define FRESNEL_P_MAX     1e3f
#define FRESNEL_ALPHA_MAX 1e3f    /* LSK compensation exponent, domain [0, max] */
#define FRESNEL_A_MAX     1e6f    /* LSK compensation weight, domain [0, max] */
/* Most nodes a binary32 LUT uses (lut.c): n - 1 and every position stay
 * exact binary32 integers; the Q15 LUTs have the same limit. */
#define FRESNEL_LUT_N_MAX 32768
/* Gulbrandsen's inverse needs r < 1; r is clamped to this first. */
#define FRESNEL_GULBRANDSEN_R_MAX 0.9999f

/* Error bounds of the binary32 functions (see CONVENTIONS): about 2-10
 * units in the last place of 1 (binary32 ulp(1) = 1.19e-7). Each is at
 * least 10% above the largest error a search for the worst case found over
 * its domain (tests/runtime/every_type/test_model_search.c; make search), rounded up. */
#define FRESNEL_BOUND_SCHLICK          3.6e-7f
#define FRESNEL_BOUND_SCHLICK_GEN      3.6e-7f
#define FRESNEL_BOUND_SCHLICK_INTERNAL 3.5e-7f
#define FRESNEL_BOUND_F0_FROM_IOR               3e-7f /* fresnel_f0_from_ior */
#define FRESNEL_BOUND_F0_IN_MEDIUM     5.3e-7f
#define FRESNEL_BOUND_LSK              5.2e-7f
#define FRESNEL_BOUND_LSK_COMP         6e-7f
#define FRESNEL_BOUND_F82              5.5e-7f
#define FRESNEL_BOUND_GULBRANDSEN      4e-7f
#define FRESNEL_BOUND_GULBRANDSEN_RG    4e-7f /* g of fresnel_gulbrandsen_rg */
#define FRESNEL_BOUND_APPROX_CONDUCTOR 3.6e-7f
#define FRESNEL_BOUND_COOK_TORRANCE    6.4e-7f
#define FRESNEL_BOUND_CONDUCTOR        4e-7f
#define FRESNEL_BOUND_CONDUCTOR_PREPARED 4e-7f /* fresnel_conductor_prepared, _batch */
#define FRESNEL_BOUND_DIELECTRIC       3.7e-7f
/* The hemispherical averages (fresnel_*_avg) against the double closed form. */
#define FRESNEL_BOUND_SCHLICK_AVG      2e-7f
#define FRESNEL_BOUND_SCHLICK_GEN_AVG  3e-7f
#define FRESNEL_BOUND_F82_AVG          2e-7f
#define FRESNEL_BOUND_LUT_AVG          6.2e-8f /* fresnel_lut_*_avg: half an ulp below 2, plus 2.04 2^-30 */

/* Three channels of one quantity (reflectance, eta or kappa). */
typedef struct fresnel_rgb {
    float r, g, b;
} fresnel_rgb;

/* The functions below are left out by -DFRESNEL_CONFIG=FRESNEL_CFG_NO_FLOAT
 * (fresnel_config.h), with their code in src/f32/: a fixed-point-only build
 * can compile all of src/ and contains no binary32 function. The limits,
 * bounds and fresnel_rgb above stay, for code that only describes materials. */
#if FRESNEL_HAS_FLOAT

/* ---------------------------------------------------------------- schlick.c */

/* Schlick [Sch94]:  F = F0 + (1 - F0)(1 - c)^5.
 * Error <= FRESNEL_BOUND_SCHLICK. Cost: 6 flops. */
float fresnel_schlick(float f0, float c);
fresnel_rgb fresnel_schlick_rgb(fresnel_rgb f0, float c);

/* Generalized Schlick [Hof20]:  F = F0 + (F90 - F0)(1 - c)^p,
 * p in [FRESNEL_P_MIN, FRESNEL_P_MAX] (clamped; NaN gives the minimum).
 * Error <= FRESNEL_BOUND_SCHLICK_GEN.
 * Cost: p = 5: 6 flops; other p: 4 flops, expf, log1pf. */
float fresnel_schlick_gen(float f0, float f90, float p, float c);
fresnel_rgb fresnel_schlick_gen_rgb(fresnel_rgb f0, fresnel_rgb f90, float p, float c);

/* Hemispherical averages F_avg = 2 int_0^1 F(c) c dc of the two Schlick
 * forms (the albedo a multiple-scattering compensation needs [Kulla-Conty]):
 *   fresnel_schlick_avg:      F0 + (1 - F0) / 21,
 *   fresnel_schlick_gen_avg:  F0 + (F90 - F0) 2 / ((p + 1)(p + 2)),
 * arguments clamped as the curves clamp them. Error <= FRESNEL_BOUND_SCHLICK_AVG,
 * FRESNEL_BOUND_SCHLICK_GEN_AVG. Cost: 2 flops; 6 flops, div. */
float fresnel_schlick_avg(float f0);
fresnel_rgb fresnel_schlick_avg_rgb(fresnel_rgb f0);
float fresnel_schlick_gen_avg(float f0, float f90, float p);

/* Schlick for internal reflection [Hof20], eta relative to the incident side
 * (1/1.5 from glass out into air):
 *   eta >= 1:  F = fresnel_schlick(F0, c);
 *   eta < 1:   F = fresnel_schlick(F0, ct),  ct = sqrt((eta-1)(eta+1) + c^2) / eta,
 *              and F = 1 where (eta-1)(eta+1) + c^2 < 0 (past the critical angle).
 * Error <= FRESNEL_BOUND_SCHLICK_INTERNAL, up to the critical angle.
 * Cost: ~35 flops, div, sqrt. */
float fresnel_schlick_internal(float f0, float eta, float c);
fresnel_rgb fresnel_schlick_internal_rgb(fresnel_rgb f0, float eta, float c);

/* Hoffman's external-medium adjustment of F0 (dielectric form, [Hof20]):
 *   F0' = ((sqrt F0 - s) / (1 - sqrt F0 s))^2,  s = (etaE - 1) / (etaE + 1),
 * etaE the index of the surrounding medium relative to vacuum (water 1.33),
 * clamped like eta. Error <= FRESNEL_BOUND_F0_IN_MEDIUM.
 * Cost: 9 flops, 3 div, sqrt. */
float fresnel_f0_in_medium(float f0, float eta_e);

/* Normal-incidence reflectance of a complex index:
 *   F0 = ((eta-1)^2 + kappa^2) / ((eta+1)^2 + kappa^2).
 * Error <= FRESNEL_BOUND_F0_FROM_IOR. Cost: 7 flops, div. */
float fresnel_f0_from_ior(float eta, float kappa);

/* -------------------------------------------------------------------- lsk.c */

/* LSK rescaled Schlick [LS05]:
 *   F = ((eta-1)^2 + 4 eta (1-c)^5 + kappa^2) / ((eta+1)^2 + kappa^2)
 *     = fresnel_schlick(fresnel_f0_from_ior(eta, kappa), c).
 * Error <= FRESNEL_BOUND_LSK. Cost: 12 flops, div. */
float fresnel_lsk(float eta, float kappa, float c);
fresnel_rgb fresnel_lsk_rgb(fresnel_rgb eta, fresnel_rgb kappa, float c);

/* LSK with error compensation [LS05]:
 *   F = fresnel_lsk(eta, kappa, c) - a c (1 - c)^alpha,   clamped to [0, 1],
 * a in [0, FRESNEL_A_MAX], alpha in [0, FRESNEL_ALPHA_MAX] (clamped), made
 * on the host (`fresnel params`); a = 0 is no compensation.
 * Error <= FRESNEL_BOUND_LSK_COMP for a <= 200 (every measured material:
 * a = 2 eta, eta <= 100), over the whole eta, kappa, alpha domain; above,
 * about 6e-8 |a c (1-c)^alpha alpha ln(1-c)| more (1.2e-6 at a = 1e6).
 * Cost: 15 flops, div, expf, log1pf. */
float fresnel_lsk_comp(float eta, float kappa, float a, float alpha, float c);
fresnel_rgb fresnel_lsk_comp_rgb(fresnel_rgb eta, fresnel_rgb kappa, fresnel_rgb a,
                                 fresnel_rgb alpha, float c);

/* -------------------------------------------------------------------- f82.c */

/* Hoffman's F82 model (reparameterised Lazanyi, [Hof20]):
 *   F = F0 + (1 - F0)(1 - c)^5 - a c (1 - c)^6,
 *   a = (823543/46656)(F0 - F82) + (49/6)(1 - F0),
 * F82 the reflectance at c = 1/7 (about 82 degrees); clamped to [0, 1].
 * Error <= FRESNEL_BOUND_F82. Cost: 14 flops. */
float fresnel_f82(float f0, float f82, float c);
fresnel_rgb fresnel_f82_rgb(fresnel_rgb f0, fresnel_rgb f82, float c);

/* Its hemispherical average, the integral of the curve above (a c (1-c)^6
 * integrates to a / 126):
 *   F_avg = F0 + (1 - F0) / 21 - a / 126,   clamped to [0, 1];
 * equal to the average of fresnel_f82 wherever its curve stays inside [0, 1]
 * (every measured material's does; tests/runtime/every_type/test_average.c).
 * Error <= FRESNEL_BOUND_F82_AVG. Cost: 6 flops. */
float fresnel_f82_avg(float f0, float f82);
fresnel_rgb fresnel_f82_avg_rgb(fresnel_rgb f0, fresnel_rgb f82);

/* ----------------------------------------------------------- gulbrandsen.c */

/* Gulbrandsen's reflectivity r and edge tint g <-> n, k [Gul14]:
 *   n = g (1-r)/(1+r) + (1-g) (1+sqrt r)/(1-sqrt r)
 *   k = sqrt((r (n+1)^2 - (n-1)^2) / (1-r)),
 * r clamped to [0, FRESNEL_GULBRANDSEN_R_MAX]; the inverse
 *   r = fresnel_f0_from_ior(eta, kappa),  g = (nmax(r) - eta)/(nmax(r) - nmin(r)),
 * g clamped to [0, 1] (eta outside [nmin, nmax] has no edge tint).
 * Error of the inverse's g <= FRESNEL_BOUND_GULBRANDSEN_RG.
 * Cost: forward 14 flops, 3 div, 2 sqrt; inverse 12 flops, 4 div, sqrt. */
typedef struct fresnel_nk {
    float n, k;
} fresnel_nk;
typedef struct fresnel_rg {
    float r, g;
} fresnel_rg;
fresnel_nk fresnel_gulbrandsen_nk(float r, float g);
fresnel_rg fresnel_gulbrandsen_rg(float eta, float kappa);

/* Gulbrandsen's Fresnel: fresnel_approx_conductor at the n, k of
 * fresnel_gulbrandsen_nk(r, g). Error <= FRESNEL_BOUND_GULBRANDSEN.
 * Cost: fresnel_gulbrandsen_nk + fresnel_approx_conductor. */
float fresnel_gulbrandsen(float r, float g, float c);
fresnel_rgb fresnel_gulbrandsen_rgb(fresnel_rgb r, fresnel_rgb g, float c);

/* ------------------------------------------------------ approx_conductor.c */

/* The approximate conductor form used by Gulbrandsen and Metzgar (Glassner):
 *   N = eta^2 + kappa^2,
 *   rs = (N - 2 eta c + c^2) / (N + 2 eta c + c^2)
 *   rp = (N c^2 - 2 eta c + 1) / (N c^2 + 2 eta c + 1),  F = (rs+rp)/2;
 * equal to fresnel_conductor at c = 1 only.
 * Error <= FRESNEL_BOUND_APPROX_CONDUCTOR. Cost: 17 flops, 2 div. */
float fresnel_approx_conductor(float eta, float kappa, float c);
fresnel_rgb fresnel_approx_conductor_rgb(fresnel_rgb eta, fresnel_rgb kappa, float c);

/* -------------------------------------------------------- cook_torrance.c */

/* Cook-Torrance colour interpolation, Hoffman's modified form [Hof20]:
 *   F = F0 + (1 - F0) max(0, F'(c) - F'(1)) / (1 - F'(1)),
 * F' = fresnel_conductor(eta, kappa, .) of ONE representative index shared
 * by the three channels; F0 is the RGB colour.
 * Error <= FRESNEL_BOUND_COOK_TORRANCE. Cost: fresnel_conductor + 12 flops, div. */
float fresnel_cook_torrance(float f0, float eta, float kappa, float c);
fresnel_rgb fresnel_cook_torrance_rgb(fresnel_rgb f0, float eta, float kappa, float c);

/* ------------------------------------------------------------------ exact.c */

/* Exact unpolarised Fresnel reflectance of a conductor (eta + i kappa,
 * relative to the incident medium):  F = (Rs + Rp)/2,
 *   u + iv = sqrt((eta + i kappa)^2 - sin^2 theta)   (decaying branch, u, v >= 0)
 *   m = u^2 + v^2,  s^2 = sin^2 theta = (1-c)(1+c)
 *   Rs = (m + c^2 - 2cu) / (m + c^2 + 2cu)
 *   Rp = Rs (c^2 m + s^4 - 2cu s^2) / (c^2 m + s^4 + 2cu s^2).
 * kappa = 0 and eta < 1: F = 1 past the critical angle. eta = 1, kappa = 0:
 * F = 0 for every c. Error <= FRESNEL_BOUND_CONDUCTOR, also at critical
 * angles. Cost: ~45 flops (6 of them in binary64 where the target has it
 * in hardware: x86-64, AArch64), div, 2 sqrt (kappa = 0: one sqrt). */
float fresnel_conductor(float eta, float kappa, float c);
fresnel_rgb fresnel_conductor_rgb(fresnel_rgb eta, fresnel_rgb kappa, float c);

/* fresnel_conductor with one material's constants prepared once:
 *   fresnel_conductor_prep p = fresnel_conductor_prepare(eta, kappa);
 *   r = fresnel_conductor_prepared(&p, c);              one cosine
 *   fresnel_conductor_batch(&p, cos_array, out, n);     out[i] for c[i], i < n
 *   fresnel_conductor_prep rgb[3] = {prepare(eta.r, kappa.r), ..g.., ..b..};
 *   fresnel_conductor_rgb_batch(rgb, cos_array, rgb_out, n);
 *               rgb_out[i] for c[i]: one fresnel_rgb per cosine, as
 *               fresnel_conductor_rgb returns it; channel j from rgb[j]
 * The same formula, clamps and NaN policy as fresnel_conductor; results
 * within the bound, not bit-identical to fresnel_conductor's. Both batches
 * give fresnel_conductor_prepared's results bit for bit, in every lane and
 * for any n, alignment or form (checked on each kernel, built by gcc and
 * clang in ISO C and the GNU modes, by tests/runtime/f32/test_batch_simd.sh; see THREAD
 * SAFETY for the one flag that breaks it); c and out must not overlap; n <= 0 writes
 * nothing, nothing at or past n is read or written.
 * SIMD, chosen at compile time from the target: AVX-512F 16 lanes (compiled
 * by the tests, run only on a CPU that has it), AVX/AVX2 8, SSE2 4, AArch64
 * NEON 4; an x86-64 build without AVX (the -O2 default) has the AVX2 kernel
 * too and takes it where the CPU has AVX2 and FMA (gcc, clang); portable C
 * elsewhere and with FRESNEL_CFG_NO_SIMD (fresnel_config.h).
 * Error <= FRESNEL_BOUND_CONDUCTOR_PREPARED.
 * rgb_batch, three channels of one form (the forms: kappa = 0, eta != 1;
 * eta kappa >= 2^-30; 0 < eta kappa < 2^-30), so three conductors or three
 * dielectrics in practice, with SIMD: each vector of cosines is loaded
 * once, its clamp, c^2 (exact split), sin^2 and 2c terms are shared by the
 * channels, and the rows are written by vector shuffles;
 * other mixes, and portable C, go channel by channel over blocks of 64
 * cosines (768 bytes of stack), then interleave.
 * Cost: prepare ~40 flops; per cosine ~40 flops, div, 2 sqrt (kappa = 0: one
 * sqrt), a vector's worth at a time in the batches, and in rgb_batch ~10 of
 * the 40 once for the three channels; `build/fresnel bench --targets` times
 * the batch against other renderers' forms, `make bench` (rows
 * conductor-batch, conductor-rgb-batch) both batches against Mitsuba's
 * formula inlined. */
typedef struct fresnel_conductor_prep {
    float a0, a0_lo; /* eta^2 - kappa^2 - 1 = a0 + a0_lo */
    float ek;        /* eta kappa */
    float ek4;       /* 4 (eta kappa)^2 */
    int kind;        /* which form: internal, set by prepare */
} fresnel_conductor_prep;
fresnel_conductor_prep fresnel_conductor_prepare(float eta, float kappa);
float fresnel_conductor_prepared(const fresnel_conductor_prep *p, float c);
void fresnel_conductor_batch(const fresnel_conductor_prep *p, const float *c, float *out, int n);
void fresnel_conductor_rgb_batch(const fresnel_conductor_prep p[3], const float *c, fresnel_rgb *out, int n);

/* Exact dielectric Fresnel (kappa = 0) from either side, eta = n_transmitted /
 * n_incident:
 *   w = sqrt(eta^2 - 1 + c^2),  Rs = ((c-w)/(c+w))^2,  Rp = ((eta^2 c - w)/(eta^2 c + w))^2,
 *   F = (Rs + Rp)/2, and F = 1 where eta^2 - 1 + c^2 < 0 (eta < 1, past the
 *   critical angle); eta = 1 gives 0 for every c.
 * Error <= FRESNEL_BOUND_DIELECTRIC. Cost: ~35 flops, 2 div, sqrt. */
float fresnel_dielectric(float eta, float c);

/* -------------------------------------------------------------------- lut.c */

/* Tabulated curves made by `fresnel gen`: table[i], i = 0..n-1, is the
 * reflectance at node i, and F interpolates linearly between the two nodes
 * around c; table values are trusted (generated). A curve table's result is
 * clamped to [0, max(1, the two nodes)]: nodes above 1 (the keep policy's
 * out-of-gamut colours) are kept, a table inside [0, 1] gives [0, 1]. The
 * residual forms are clamped to [0, 1].
 *   fresnel_lut:         nodes uniform in sqrt(c), c_i = (i/(n-1))^2
 *   fresnel_lut_linear:  nodes uniform in c, c_i = i/(n-1)
 *   _residual:           F = fresnel_schlick(f0, c) + the interpolated
 *                        table of GT - Schlick(F0)
 *   _rgb:                n red nodes, then n green, then n blue.
 * n: 2 <= n <= FRESNEL_LUT_N_MAX; nothing outside table[0 .. n-1] (per
 * channel) is read. n < 1 is an empty table, which contributes 0; n = 1 the
 * constant table[0]; n above FRESNEL_LUT_N_MAX is its first
 * FRESNEL_LUT_N_MAX nodes.
 * Error: the table's own (`fresnel curve`) plus <= 3e-7.
 * Cost: 6-10 flops (+ sqrtf for fresnel_lut), no division. */
float fresnel_lut(const float *table, int n, float c);
float fresnel_lut_linear(const float *table, int n, float c);
float fresnel_lut_residual(float f0, const float *table, int n, float c);
float fresnel_lut_linear_residual(float f0, const float *table, int n, float c);
fresnel_rgb fresnel_lut_rgb(const float *table, int n, float c);
fresnel_rgb fresnel_lut_linear_rgb(const float *table, int n, float c);
fresnel_rgb fresnel_lut_residual_rgb(fresnel_rgb f0, const float *table, int n, float c);
fresnel_rgb fresnel_lut_linear_residual_rgb(fresnel_rgb f0, const float *table, int n, float c);

/* Catmull-Rom on the nodes of fresnel_lut (uniform in sqrt(c)), the outer
 * nodes clamped to the table's ends: with x = sqrt(c), t = frac(x (n-1)),
 *   F = p1 + t/2 (p2 - p0 + t (2p0 - 5p1 + 4p2 - p3 + t (3 (p1 - p2) + p3 - p0))),
 * clamped to [0, max(1, p1, p2)]. Tables are fitted for it (lutN-cubic in a scene), not
 * interchangeable with fresnel_lut's; n as fresnel_lut.
 * Error: the table's own plus <= 5e-7 on reflectance curves (n <= 256); on
 * arbitrary tables up to about (n-1) 2^-24 times the largest step between
 * nodes. Cost: sqrtf + 12 flops, no division. */
float fresnel_lut_cubic(const float *table, int n, float c);
fresnel_rgb fresnel_lut_cubic_rgb(const float *table, int n, float c);

/* ---------------------------------------------------------------- lut_avg.c */

/* The hemispherical average F_avg = 2 int_0^1 F(c) c dc of a curve table's
 * interpolant (fresnel_lut, fresnel_lut_cubic, fresnel_lut_linear), exact:
 * a weighted sum of the nodes, sum_i w_i table[i], with N = n - 1,
 * h = 1/N, x_i = i h:
 *   fresnel_lut_avg          w_0 = h^4/5, w_i = 4h x_i^3 + 2h^3 x_i,
 *                            w_N = 4h (1/2 - h/2 + h^2/4 - h^3/20)
 *   fresnel_lut_cubic_avg    w_i = 4h x_i^3 for 2 <= i <= N-2; the end
 *                            nodes' weights in lut_avg.c
 *   fresnel_lut_linear_avg   w_0 = h^2/3, w_i = 2h x_i, w_N = h - h^2/3
 * (the weights sum to 1). Equal to the average of the clamped curve
 * wherever the interpolant stays inside [0, max(1, nodes)], which fitted
 * tables do. n as fresnel_lut; result in [0, max(1, largest node)]; a
 * NaN node gives 0. The sum is exact (integer weights over one integer
 * denominator, multi-word integers, nodes read to 2^-30 of the largest):
 * error <= FRESNEL_BOUND_LUT_AVG against the interpolant's integral held
 * to that range, every n and every table with nodes up to 2. Cost per
 * node: about 24 16x16-bit integer multiplies; then one 32-step division
 * (a material's average is made once). */
float fresnel_lut_avg(const float *table, int n);
float fresnel_lut_cubic_avg(const float *table, int n);
float fresnel_lut_linear_avg(const float *table, int n);
fresnel_rgb fresnel_lut_avg_rgb(const float *table, int n);
fresnel_rgb fresnel_lut_cubic_avg_rgb(const float *table, int n);
fresnel_rgb fresnel_lut_linear_avg_rgb(const float *table, int n);

#endif /* FRESNEL_HAS_FLOAT */

#ifdef __cplusplus
}
#endif
#endif /* FRESNEL_H */
