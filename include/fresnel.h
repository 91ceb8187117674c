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
 *   src/q15/ (fresnel_fixed.h), src/f16/ (fresnel_f16.h). A vendoring
 *   project copies include/ and the folders of the types it uses.
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
 *            NaN and Inf.
 *   Error bounds are absolute, against this project's double-precision
 *   reference of the SAME model with the same binary32 inputs (gen/reference.c),
 *   measured by tests/test_float_bounds.c over eta in [0.01, 100], kappa in
 *   {0} u [1e-3, 1000], incident index n1 in {1, 1.33, 1.5, 2.42} and a dense
 *   set of c including 0, 1 and points within 1e-6 of each
 *   (`make test`; the measured maxima are printed by `build/tests/test_float_bounds`);
 *   they hold there. fresnel_lsk_comp's and fresnel_gulbrandsen_rg's are
 *   measured over the whole eta, kappa domain as well (random points, the
 *   same test); the rest of the domain (eta in [2^-10, 0.01) or (100, 1e5],
 *   kappa above 1000) is checked for range only (tests/test_extremes.c,
 *   tests/fuzz/fuzz_float_models.c).
 *   How far each MODEL is from the exact Fresnel equations is a different
 *   question, answered by `build/fresnel accuracy` (see README).
 *   Cost counts binary32 operations: "flop" = add, sub or mul; div, sqrt and
 *   libm calls are named.
 *
 * THREAD SAFETY
 *   No global state, no allocation, no stdio, no errno: every function is
 *   reentrant. <math.h> is used: sqrtf everywhere, expf and log1pf
 *   (generalized Schlick with p != 5, LSK compensation), fmaf only where the compiler
 *   says it is fast (FP_FAST_FMAF).
 *   Build src/ without -ffast-math, -ffinite-math-only, -fassociative-math
 *   and -Ofast: the NaN policy needs NaN comparisons, and the exact forms
 *   (critical angles) need IEEE rounding. src/f32/internal.h stops the build
 *   with #error where the compiler says it is on (__FAST_MATH__,
 *   __FINITE_MATH_ONLY__); a vendoring user with such a global flag compiles
 *   src/f32/\*.c with -fno-fast-math (gcc, clang) or without it.
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

/* Measured error bounds of the binary32 functions: absolute, against the
 * double reference of the same model (see CONVENTIONS); tests/test_float_bounds.c
 * asserts them and prints the measured maxima. About 2-10 units in the last
 * place of 1 (binary32 ulp(1) = 1.19e-7). */
#define FRESNEL_BOUND_SCHLICK          3e-7f
#define FRESNEL_BOUND_SCHLICK_GEN      3e-7f
#define FRESNEL_BOUND_SCHLICK_INTERNAL 3e-7f
#define FRESNEL_BOUND_F0               3e-7f /* fresnel_f0_from_ior */
#define FRESNEL_BOUND_F0_IN_MEDIUM     5e-7f
#define FRESNEL_BOUND_LSK              5e-7f
#define FRESNEL_BOUND_LSK_COMP         6e-7f
#define FRESNEL_BOUND_F82              5e-7f
#define FRESNEL_BOUND_GULBRANDSEN      4e-7f
#define FRESNEL_BOUND_GULBRANDSEN_G    4e-7f /* g of fresnel_gulbrandsen_rg */
#define FRESNEL_BOUND_APPROX_CONDUCTOR 3e-7f
#define FRESNEL_BOUND_COOK_TORRANCE    6e-7f
#define FRESNEL_BOUND_CONDUCTOR        4e-7f
#define FRESNEL_BOUND_CONDUCTOR_PREPARED 4e-7f /* fresnel_conductor_prepared, _batch */
#define FRESNEL_BOUND_DIELECTRIC       3e-7f

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

/* Schlick [Sch94]:  F = F0 + (1 - F0) (1 - c)^5.
 * (1-c)^5 by three multiplications. Error <= FRESNEL_BOUND_SCHLICK. Cost: 6 flops. */
float fresnel_schlick(float f0, float c);
fresnel_rgb fresnel_schlick_rgb(fresnel_rgb f0, float c);

/* Generalized Schlick [Hof20]:  F = F0 + (F90 - F0) (1 - c)^p.
 * p in [FRESNEL_P_MIN, FRESNEL_P_MAX] (clamped; NaN gives the minimum).
 * p == 5 takes the multiplication path of fresnel_schlick; other p evaluate
 * (1-c)^p as expf(p log1pf(-c)), so rounding 1 - c is not multiplied by p.
 * Error <= FRESNEL_BOUND_SCHLICK_GEN (expf, log1pf from glibc for p != 5).
 * Cost: 6 flops, or 4 flops + expf + log1pf. */
float fresnel_schlick_gen(float f0, float f90, float p, float c);
fresnel_rgb fresnel_schlick_gen_rgb(fresnel_rgb f0, fresnel_rgb f90, float p, float c);

/* Schlick for internal reflection [Hof20]. eta is the far side's index relative
 * to the incident side, as everywhere here, so light inside glass going out to
 * air has eta = 1/1.5 < 1. Then the transmitted cosine
 *   ct = sqrt(((eta-1)(eta+1) + c^2)) / eta
 * replaces c (the Fresnel curve is symmetric in the two angles, so Schlick is
 * used with the angle in the less dense medium); past the critical angle
 * ((eta-1)(eta+1) + c^2 < 0) the result is 1 (total internal reflection).
 * eta >= 1 is external reflection and c is used as is.
 * eta^2 - sin^2 is formed without cancellation (see fresnel_conductor), so
 * the bound holds up to the critical angle. Error <= FRESNEL_BOUND_SCHLICK_INTERNAL.
 * Cost: ~35 flops, div, sqrt. */
float fresnel_schlick_internal(float f0, float eta, float c);
fresnel_rgb fresnel_schlick_internal_rgb(fresnel_rgb f0, float eta, float c);

/* Hoffman's external-medium adjustment of F0 (dielectric form, [Hof20]):
 *   F0' = ((sqrt F0 - s) / (1 - sqrt F0 * s))^2,  s = (etaE - 1) / (etaE + 1),
 * etaE the index of the surrounding medium relative to vacuum (water 1.33).
 * etaE is clamped like eta. Symmetric: swapping the two media gives the same
 * F0'. Computed from 1 - s = 2/(etaE+1) and 1 - sqrt F0 = (1-F0)/(1+sqrt F0),
 * without the cancellation of 1 - sqrt F0 s (for etaE < 1, s < 0 and the
 * direct form has no cancellation). Error <= FRESNEL_BOUND_F0_IN_MEDIUM: the
 * test's grid peaks at 3.6e-7; a denser probe near F0 = 1 found 4.4e-7.
 * Cost: 9 flops, 3 div, sqrt. */
float fresnel_f0_in_medium(float f0, float eta_e);

/* Normal-incidence reflectance of a complex index:
 *   F0 = ((eta-1)^2 + kappa^2) / ((eta+1)^2 + kappa^2).
 * Error <= FRESNEL_BOUND_F0. Cost: 7 flops, div. */
float fresnel_f0_from_ior(float eta, float kappa);

/* -------------------------------------------------------------------- lsk.c */

/* LSK rescaled Schlick [LS05]:
 *   F = ((n-1)^2 + 4n (1-c)^5 + k^2) / ((n+1)^2 + k^2).
 * This equals fresnel_schlick(F0, c) with F0 = fresnel_f0_from_ior(n, k):
 * for one IOR the rescaling is exactly "Schlick with the exact F0".
 * Error <= FRESNEL_BOUND_LSK. Cost: 12 flops, div. */
float fresnel_lsk(float n, float k, float c);
fresnel_rgb fresnel_lsk_rgb(fresnel_rgb n, fresnel_rgb k, float c);

/* LSK with error compensation [LS05]:
 *   F = fresnel_lsk(n, k, c) - a c (1 - c)^alpha,   clamped to [0, 1].
 * a and alpha are derived material constants made on the host
 * (`fresnel params`, ref_lsk_fit in gen/reference.c): a = 2n (the slope of
 * exact Fresnel at c = 0 for large k), alpha such that the term equals
 * exact - rescaled at c = 0.15. Where exact - rescaled >= 0 at 0.15, or the fit
 * would need alpha <= 0, the host sets a = 0: no compensation.
 * a in [0, FRESNEL_A_MAX], alpha in [0, FRESNEL_ALPHA_MAX] (clamped).
 * (1-c)^alpha is evaluated as expf(alpha log1pf(-c)) so the rounding of 1 - c
 * is not multiplied by alpha, and alpha ln(1-c) is formed exactly (two
 * floats). Error <= FRESNEL_BOUND_LSK_COMP for a <= 200 over the whole eta,
 * kappa, alpha domain (a = 2n with n <= 100, every measured material): the
 * result is the difference of the LSK value and a term of about the same
 * size when a = 200 and n is small, and keeps the roundings of both
 * (log1pf, expf and two products on the term); tests/test_float_bounds
 * prints the measured maximum ("lsk-comp over its domain"). For larger a the float
 * rounding of the exponent alpha ln(1-c) is multiplied by the term's size:
 * about 6e-8 |a c (1-c)^alpha alpha ln(1-c)| (1.2e-6 at a = 1e6).
 * Cost: 15 flops, div, expf, log1pf. */
float fresnel_lsk_comp(float n, float k, float a, float alpha, float c);
fresnel_rgb fresnel_lsk_comp_rgb(fresnel_rgb n, fresnel_rgb k, fresnel_rgb a,
                                 fresnel_rgb alpha, float c);

/* -------------------------------------------------------------------- f82.c */

/* Hoffman's F82 model (reparameterised Lazanyi, [Hof20]):
 *   F = F0 + (1 - F0)(1 - c)^5 - a c (1 - c)^6,
 *   a = (823543/46656)(F0 - F82) + (49/6)(1 - F0),
 * F82 the reflectance at c = 1/7 (about 82 degrees). Extreme F0/F82 pairs
 * (F82 well above or below F0) push the curve outside [0, 1]: the result is
 * clamped to [0, 1], which leaves a C1 kink there (as Hoffman notes).
 * Error <= FRESNEL_BOUND_F82. Cost: 14 flops. */
float fresnel_f82(float f0, float f82, float c);
fresnel_rgb fresnel_f82_rgb(fresnel_rgb f0, fresnel_rgb f82, float c);

/* ----------------------------------------------------------- gulbrandsen.c */

/* Gulbrandsen's reflectivity r and edge tint g <-> n, k [Gul14]:
 *   n = g (1-r)/(1+r) + (1-g) (1+sqrt r)/(1-sqrt r)
 *   k = sqrt((r (n+1)^2 - (n-1)^2) / (1-r))
 * r is clamped to [0, FRESNEL_GULBRANDSEN_R_MAX] first. k^2 is computed in the
 * factored form g (nmax - nmin)(sqrt r (n+1) + n - 1) / (1 + sqrt r), which is
 * the paper's expression without its cancellation (it loses every digit in
 * binary32 when r is near 1 and g near 0). Hoffman [Hof20] explains why this
 * parameterisation is unsound for colour; it is here because production
 * renderers use it.
 * The inverse: r = ((n-1)^2+k^2)/((n+1)^2+k^2), g = (nmax(r) - n)/(nmax(r) - nmin(r)),
 * with g clamped to [0, 1] (n outside [nmin, nmax] has no edge tint).
 * Cost: forward 14 flops, 3 div, 2 sqrt; inverse 12 flops, 4 div, sqrt. */
typedef struct fresnel_nk {
    float n, k;
} fresnel_nk;
typedef struct fresnel_rg {
    float r, g;
} fresnel_rg;
fresnel_nk fresnel_gulbrandsen_nk(float r, float g);
fresnel_rg fresnel_gulbrandsen_rg(float n, float k);

/* Gulbrandsen's Fresnel: fresnel_approx_conductor at the n, k given by r, g.
 * nmax is formed as (1 + sqrt r)^2 / (1 - r), which keeps its digits as r -> 1.
 * Error <= FRESNEL_BOUND_GULBRANDSEN.
 * Cost: forward mapping + fresnel_approx_conductor. */
float fresnel_gulbrandsen(float r, float g, float c);
fresnel_rgb fresnel_gulbrandsen_rgb(fresnel_rgb r, fresnel_rgb g, float c);

/* ------------------------------------------------------ approx_conductor.c */

/* The approximate conductor form used by Gulbrandsen and Metzgar (Glassner):
 *   rs = (n^2+k^2 - 2nc + c^2) / (n^2+k^2 + 2nc + c^2)
 *   rp = ((n^2+k^2)c^2 - 2nc + 1) / ((n^2+k^2)c^2 + 2nc + 1),  F = (rs+rp)/2,
 * with numerators in the cancellation-free forms (n-c)^2 + k^2 and
 * (nc-1)^2 + (kc)^2. Exact at c = 1; not exact elsewhere (good for large k).
 * Error <= FRESNEL_BOUND_APPROX_CONDUCTOR. Cost: 17 flops, 2 div. */
float fresnel_approx_conductor(float n, float k, float c);
fresnel_rgb fresnel_approx_conductor_rgb(fresnel_rgb n, fresnel_rgb k, float c);

/* -------------------------------------------------------- cook_torrance.c */

/* Cook-Torrance colour interpolation, Hoffman's modified form [Hof20]:
 *   F = F0 + (1 - F0) max(0, F'(c) - F'(1)) / (1 - F'(1)),
 * F' = exact Fresnel (fresnel_conductor) of ONE representative complex IOR
 * (eta, kappa) shared by the three channels; F0 is the RGB colour. 1 - F'(1)
 * is computed as 4 eta / ((eta+1)^2 + kappa^2), without cancellation.
 * Error <= FRESNEL_BOUND_COOK_TORRANCE.
 * Cost: fresnel_conductor + 12 flops + div. */
float fresnel_cook_torrance(float f0, float eta, float kappa, float c);
fresnel_rgb fresnel_cook_torrance_rgb(fresnel_rgb f0, float eta, float kappa, float c);

/* ------------------------------------------------------------------ exact.c */

/* Exact unpolarised Fresnel reflectance of a conductor (eta + i kappa,
 * relative to the incident medium): F = (Rs + Rp)/2 with
 *   u + iv = sqrt((eta + i kappa)^2 - sin^2 theta)   (decaying branch, u, v >= 0)
 *   m = u^2 + v^2 = |(eta + i kappa)^2 - sin^2 theta|,  s^2 = sin^2 theta = (1-c)(1+c)
 *   Rs = (m + c^2 - 2cu) / (m + c^2 + 2cu)
 *   Rp = Rs (c^2 m + s^4 - 2cu s^2) / (c^2 m + s^4 + 2cu s^2)
 * (the a^2 + b^2 / 2ac arrangement of Moeller's Optics that Mitsuba and
 * MaterialX use, a = u). Written so binary32 keeps its digits where their
 * binary32 evaluation loses them (3.6e-5 on eta 0.1..5, kappa 0..10; see
 * `fresnel bench --targets`): A = eta^2 - kappa^2 - sin^2 = (eta-1)(eta+1) -
 * kappa^2 + c^2 (no 1 - c^2 near grazing, eta^2 and c^2 formed exactly and
 * summed with their rounding error, so no cancellation near the critical
 * angle); u^2 = (m + A)/2 only for A >= 0, else u = eta kappa / v with
 * v^2 = (m - A)/2 (never the difference of m and |A|); the division for u is
 * folded into the ratios (numerator and denominator times v), and
 * F = Rs (1 + Rp/Rs)/2 is one division: 2 sqrt, 1 div, no tan theta. The
 * numerators cancel only where Rs or Rp is near 0, which costs a few ulp of
 * the denominator. kappa = 0 and eta < 1 gives total internal reflection
 * (F = 1 past the critical angle). Matched index (eta = 1, kappa = 0) gives 0
 * for every c, including c = 0 (the binary32 textbook form gives 1 at
 * c = 1e-4 and NaN at c = 0).
 * Error <= FRESNEL_BOUND_CONDUCTOR (the target was 1e-6).
 * Cost: ~60 flops, div, 2 sqrt (kappa = 0: one sqrt); per call it also
 * clamps and squares eta exactly, which fresnel_conductor_prepared does once. */
float fresnel_conductor(float eta, float kappa, float c);
fresnel_rgb fresnel_conductor_rgb(fresnel_rgb eta, fresnel_rgb kappa, float c);

/* The same exact conductor with one material's constants prepared once
 * (for shading many cosines of one material):
 *   fresnel_conductor_prep p = fresnel_conductor_prepare(eta, kappa);
 *   r = fresnel_conductor_prepared(&p, c);              one cosine
 *   fresnel_conductor_batch(&p, cos_array, out, n);     out[i] for c[i], i < n
 * prepare clamps eta and kappa as everywhere and stores eta^2 - kappa^2 - 1
 * in two words (to about 2^-48 of its size: exact squares, TwoSums), so that
 * per cosine A = (a0 + c^2) + (a0_lo + c^2's low part) keeps its digits at a
 * critical angle with one exact square (of c); then the formulas of
 * fresnel_conductor. The batch runs one loop per form (matched index,
 * kappa = 0, conductor) with no branch inside but the selects of the clamps
 * and of A's sign; it gives fresnel_conductor_prepared's results bit for
 * bit; c and out must not overlap; n <= 0 writes nothing. gcc -O2
 * vectorises its loops only with -fno-math-errno -fno-trapping-math
 * (otherwise sqrtf may set errno): then 2.4x faster per cosine on x86-64
 * SSE2 (10.5 -> 4.4 ns, gcc 12, `fresnel bench --targets`).
 * Same policy as fresnel_conductor (c clamped, NaN -> 0, result in [0, 1],
 * matched index 0 at every c); results within the bound of the reference,
 * not bit-identical to fresnel_conductor's. eta kappa below 2^-30 takes two
 * divisions instead of one, so every intermediate stays a normal number.
 * Error <= FRESNEL_BOUND_CONDUCTOR_PREPARED (2.98e-7 measured on the bound
 * grid, 2.2e-7 on the extreme cases and across critical angles).
 * Cost: prepare ~40 flops; per cosine ~50 flops, div, 2 sqrt (kappa = 0: one
 * sqrt); on x86-64 gcc -O2 about Mitsuba's binary32 form and half the
 * complex-arithmetic form's time (`fresnel bench --targets`). */
typedef struct fresnel_conductor_prep {
    float a0, a0_lo; /* eta^2 - kappa^2 - 1 = a0 + a0_lo */
    float ek;        /* eta kappa */
    float ek4;       /* 4 (eta kappa)^2 */
    int kind;        /* which form: internal, set by prepare */
} fresnel_conductor_prep;
fresnel_conductor_prep fresnel_conductor_prepare(float eta, float kappa);
float fresnel_conductor_prepared(const fresnel_conductor_prep *p, float c);
void fresnel_conductor_batch(const fresnel_conductor_prep *p, const float *c, float *out, int n);

/* Exact dielectric Fresnel (kappa = 0) from either side: eta = n_transmitted /
 * n_incident, so eta < 1 is internal reflection, with F = 1 past the critical
 * angle (continuous there). eta = 1 gives 0 for every c.
 *   w = sqrt(eta^2 - 1 + c^2),  Rs = ((c-w)/(c+w))^2,  Rp = ((eta^2 c - w)/(eta^2 c + w))^2.
 * Error <= FRESNEL_BOUND_DIELECTRIC. Cost: ~35 flops, 2 div, sqrt. */
float fresnel_dielectric(float eta, float c);

/* -------------------------------------------------------------------- lut.c */

/* Tabulated curves made by `fresnel gen` from the spectral ground truth:
 * table[i], i = 0..n-1 (n >= 2), is the reflectance at the i-th node, and
 * the result interpolates linearly between the two nodes around c.
 *
 * fresnel_lut: nodes uniform in sqrt(c), c_i = (i/(n-1))^2: they crowd
 *   toward grazing incidence, where Fresnel curves bend (the first interval
 *   is 1/(n-1)^2 wide), and still cover normal incidence. Node 0 is c = 0
 *   (90 degrees), node n-1 is c = 1. On the 14 metals of Hoffman's table,
 *   16 fitted nodes, it cuts the worst mean colour error of nodes uniform in
 *   c by 3x and the worst maximum by 11x (`make report`, the LUT ablation).
 * fresnel_lut_linear: nodes uniform in c, c_i = i/(n-1).
 * The _residual forms add the table to Schlick: F = fresnel_schlick(f0, c) +
 *   interpolated (GT - Schlick(F0)), so the table holds only what Schlick
 *   misses.
 * Results are clamped to [0, 1]; table values are trusted (generated).
 * Error: the table's own (see `fresnel curve`, the report) plus <= 3e-7
 * rounding. Cost: 6-10 flops (+ sqrtf for fresnel_lut), no division.
 * n, every LUT function here: supported 2 <= n <= FRESNEL_LUT_N_MAX; no n
 * reads outside table[0 .. n-1] (per channel for RGB). n < 1 is an empty
 * table: it contributes 0 (plain forms give 0, residual forms
 * fresnel_schlick(f0, c)); n = 1 is the constant table[0]; n above
 * FRESNEL_LUT_N_MAX uses the first FRESNEL_LUT_N_MAX nodes as the table. */
float fresnel_lut(const float *table, int n, float c);
float fresnel_lut_linear(const float *table, int n, float c);
float fresnel_lut_residual(float f0, const float *table, int n, float c);
float fresnel_lut_linear_residual(float f0, const float *table, int n, float c);
/* RGB: table holds n red nodes, then n green, then n blue. */
fresnel_rgb fresnel_lut_rgb(const float *table, int n, float c);
fresnel_rgb fresnel_lut_linear_rgb(const float *table, int n, float c);
fresnel_rgb fresnel_lut_residual_rgb(fresnel_rgb f0, const float *table, int n, float c);
fresnel_rgb fresnel_lut_linear_residual_rgb(fresnel_rgb f0, const float *table, int n, float c);

/* fresnel_lut_cubic: the nodes of fresnel_lut (uniform in sqrt(c)), a
 *   Catmull-Rom cubic through the four nodes around x = sqrt(c) instead of a
 *   line through two (the outer nodes clamped to the table's ends):
 *     t = frac(x (n-1)), F = p1 + t/2 (p2 - p0 + t (2p0 - 5p1 + 4p2 - p3
 *         + t (3 (p1 - p2) + p3 - p0))).
 *   Interpolation error falls as the 4th power of the node spacing instead of
 *   the 2nd: `fresnel gen` fits 16 nodes to the Hoffman metals within 0.01
 *   mean / 0.05 max CIEDE2000 in Q15 (the report's targets section), which
 *   linear interpolation needs about 32 for. Tables for it are fitted for
 *   it (lutN-cubic in a scene): they are not interchangeable with
 *   fresnel_lut's. Results clamped to [0, 1]. Error: the table's own plus
 *   <= 5e-7 rounding on reflectance curves (1.7e-7 measured, n <= 256,
 *   tests/test_lut_cubic); on arbitrary tables the binary32 position adds up
 *   to about (n-1) 2^-24 times the largest step between nodes. Cost: sqrtf +
 *   12 flops, no division. */
float fresnel_lut_cubic(const float *table, int n, float c);
fresnel_rgb fresnel_lut_cubic_rgb(const float *table, int n, float c);

#endif /* FRESNEL_HAS_FLOAT */

#ifdef __cplusplus
}
#endif
#endif /* FRESNEL_H */
