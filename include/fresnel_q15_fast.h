/* fresnel_q15_fast.h -- inline fixed-point fast paths: fewer instructions,
 * a larger bound, preconditions instead of clamps. Types, formats and the
 * clamping functions are those of fresnel_q15.h, which this header
 * includes. Nothing to link: every function here is static inline.
 */
#ifndef FRESNEL_Q15_FAST_H
#define FRESNEL_Q15_FAST_H

#include "fresnel_q15.h"

/* ================================================================ fast paths
 *
 * Inline fixed-point evaluations for a Cortex-M0-class core, traded against
 * the functions of fresnel_q15.h: fewer instructions (ports/README.md,
 * `make cross-count`), a larger error, and preconditions instead of clamps.
 * Integer only (int32/uint32, no int64, no division, no float); C99 static
 * inline, so a firmware that uses one of them links no library code for it.
 *
 * PRECONDITIONS (outside them the behaviour is undefined):
 *   f0 in [0, FRESNEL_ONE_Q15] (`fresnel gen` emits F0 at most one under
 *   every gamut policy; gamut = keep's F0 above 1 is held to one, which is
 *   also how fresnel_q15.h's functions read it); LUT entries any uint16_t (above
 *   FRESNEL_ONE_Q15: out-of-gamut headroom, as fresnel_q15.h's tables);
 *   Schlick and F82: c <= FRESNEL_C_MAX_Q15_FAST (one + 2435; any c < 0 is
 *   read as 0, c in [one, one + 2435] gives F0, the value at one), F82's
 *   a_q12 in [FRESNEL_F82_A_MIN_Q15_FAST, FRESNEL_F82_A_MAX_Q15_FAST];
 *   LUTs: any c (c <= 0 reads as 0, c > one as one) and any n (n <= 0 gives
 *   0, n = 1 table[0], n above 1024 (u16 fast) or 32768 (pl fast) is read
 *   as that many nodes; with n a compile-time constant these tests fold
 *   away). The table must hold min(n, that maximum) entries. The exact
 *   conductor: c in [0, one], and constants made by q15_conductor_fast
 *   (`fresnel gen` emits them as <prefix>_ior_fast_q15) from an eta, kappa
 *   inside its domain (FRESNEL_CONDUCTOR_*_Q15_FAST).
 * RESULTS are in [0, FRESNEL_ONE_Q15] for every input that meets them; a
 * LUT's in [0, max(FRESNEL_ONE_Q15, its largest entry)].
 * ERROR BOUNDS (LSB of Q15, FRESNEL_BOUND_*_Q15_FAST) bound
 * |result/32768 - reference| over every cos code 0..32768, against the
 * references of fresnel_q15.h's ERROR BOUNDS; tests/README.md names the
 * tests and parameter sets. Schlick's is the largest error over every
 * (F0, c) code pair; F82's and the exact conductor's the largest a search
 * for the worst case found over their domains, plus at least 10%
 * (tests/runtime/q15/test_q15_fast_search.c, make search).
 */
#if FRESNEL_HAS_Q15

/* Forced inline under GCC and Clang: at -Os they would otherwise keep a
 * helper used twice (fresnel_i_fast_pow5) out of line, a call per use. */
#if defined(__GNUC__)
#define FRESNEL_I_INLINE static inline __attribute__((always_inline))
#else
#define FRESNEL_I_INLINE static inline
#endif

#define FRESNEL_BOUND_SCHLICK_Q15_FAST 2.94
#define FRESNEL_BOUND_F82_Q15_FAST 5.7
#define FRESNEL_BOUND_LUT_Q15_FAST 1.0         /* 2 <= n <= 64 */
#define FRESNEL_BOUND_LUT_Q15_FAST_1024 2.8    /* n <= 1024 */
#define FRESNEL_BOUND_LUT_PL_Q15_FAST 3.4      /* n <= 64 */
#define FRESNEL_BOUND_LUT_PL_Q15_FAST_TIR 15.5 /* n <= 64 across a total-reflection edge */
#define FRESNEL_BOUND_CONDUCTOR_Q15_FAST 3.0     /* over its documented domain */

/* x^5 in Q15 for x in Q15, 0 <= x <= 2^15: x^2 rounded up, x^4 and x^5
 * truncated, so that the errors straddle zero with one constant (every
 * product <= 2^30; x = one gives one exactly). Three Q15 products with a
 * single rounding constant are about 2.8 LSB, where fresnel_schlick_q15's
 * split products keep 30 bits for 0.5 LSB at 3.5x the instructions; both
 * are far inside Schlick's own model error. */
FRESNEL_I_INLINE uint32_t fresnel_i_fast_pow5(uint32_t x)
{
    uint32_t x2 = (x * x + 32767u) >> 15, x4 = (x2 * x2) >> 15;
    return (x4 * x) >> 15;
}

/* c for the Schlick and F82 fast paths: c below 0 is 0, as c & ~(c >> 31)
 * where >> is arithmetic on negative values (GCC, Clang and the other
 * embedded compilers; two instructions on Cortex-M0, where the conditional
 * takes three), else by the conditional. c in (one, FRESNEL_C_MAX_Q15_FAST] needs
 * nothing: 1 - c wraps to 2^32 - k, whose square is k^2 mod 2^32, so x^2 is
 * ceil(k^2 / 2^15) < 182, x^4 = 0 and x^5 = x^6 = 0: the result is F0, the
 * value at c = one. */
#define FRESNEL_C_MAX_Q15_FAST (32768 + 2435)
FRESNEL_I_INLINE uint32_t fresnel_i_fast_c(int32_t c)
{
    return (-1 >> 1) == -1 ? (uint32_t)c & ~(uint32_t)(c >> 31) : (uint32_t)(c < 0 ? 0 : c);
}

/* F0 + (1 - F0) x5 for f0, x5 in [0, one], truncated. */
FRESNEL_I_INLINE uint32_t fresnel_i_fast_blend(uint32_t f0, uint32_t x5)
{
    return f0 + (((32768u - f0) * x5) >> 15);
}

/* Schlick, F0 + (1 - F0)(1 - c)^5, for f0 in [0, one] and c as
 * PRECONDITIONS says; c = 0 gives exactly one, c = one exactly F0.
 * Error <= FRESNEL_BOUND_SCHLICK_Q15_FAST LSB. Cost: 4 mul. */
FRESNEL_I_INLINE fresnel_q15 fresnel_schlick_q15_fast(int32_t f0, int32_t c)
{
    return (fresnel_q15)fresnel_i_fast_blend((uint32_t)f0, fresnel_i_fast_pow5(32768u - fresnel_i_fast_c(c)));
}

/* The same for three channels; each channel equals fresnel_schlick_q15_fast's.
 * Cost: 6 mul (x^5 once, three blends). */
FRESNEL_I_INLINE fresnel_rgb_q15 fresnel_schlick_q15_rgb_fast(fresnel_rgb_q15 f0, int32_t c)
{
    uint32_t x5 = fresnel_i_fast_pow5(32768u - fresnel_i_fast_c(c));
    fresnel_rgb_q15 r;
    r.r = (fresnel_q15)fresnel_i_fast_blend(f0.r, x5);
    r.g = (fresnel_q15)fresnel_i_fast_blend(f0.g, x5);
    r.b = (fresnel_q15)fresnel_i_fast_blend(f0.b, x5);
    return r;
}

/* Hoffman's F82 model (fresnel_f82), F = F0 + (1 - F0) x^5 - a c x^6,
 * x = 1 - c, clamped to [0, one], with the per-material
 * a = (7^7/6^6)(F0 - F82) + (49/6)(1 - F0) prepared on the host as
 * a_q12 = round(4096 a) (`fresnel gen` emits it for scenes with f82 and q15;
 * any F0, F82 in [0, 1] give a in [-9.4847, 17.6514], a_q12 in
 * [-38849, 72300]). Domain: f0 and c as PRECONDITIONS says, a_q12 in
 * [FRESNEL_F82_A_MIN_Q15_FAST, FRESNEL_F82_A_MAX_Q15_FAST].
 * Error <= FRESNEL_BOUND_F82_Q15_FAST LSB against fresnel_f82 at the
 * unrounded a, reached only at unphysical corners (F0 = 0, F82 = 1:
 * a = -9.5). Cost: 7 mul. */
#define FRESNEL_F82_A_MIN_Q15_FAST (-72296)
#define FRESNEL_F82_A_MAX_Q15_FAST 144592
FRESNEL_I_INLINE fresnel_q15 fresnel_f82_q15_fast(int32_t f0, int32_t a_q12, int32_t c)
{
    /* x^5 as fresnel_schlick_q15_fast, x^6 = x^2 x^4 in Q18 (its relative
     * error matters: a c multiplies it), c x^6 in Q18 (at most 14852, at
     * c = 4654, so F0 = one with a_q12 below -72296 would overflow int32),
     * Schlick's blend and the sum in units of 2^-30 (|a_q12 c x^6| < 2^30.1,
     * the blend <= 2^30), truncated once; below 0 is 0 as in
     * fresnel_i_fast_c, without a branch. */
    uint32_t cu = fresnel_i_fast_c(c), x = 32768u - cu;
    uint32_t x2 = (x * x + 32767u) >> 15, x4 = (x2 * x2) >> 15, x5 = (x4 * x) >> 15;
    uint32_t cx6 = (cu * ((x2 * x4) >> 12)) >> 15; /* c x^6 <= 0.0567: c x6_q18 < 2^29 */
    int32_t v = (int32_t)(((uint32_t)f0 << 15) + (32768u - (uint32_t)f0) * x5) - a_q12 * (int32_t)cx6;
    uint32_t r = fresnel_i_fast_c(v) >> 15;
    return (fresnel_q15)(r < 32768u ? r : 32768u);
}

/* The same for three channels, on the constants `fresnel gen` emits for a
 * scene with f82 in q15: <prefix>_f0_q15 and <prefix>_f82_a_q12[3]. Each
 * channel equals fresnel_f82_q15_fast's. Cost: 21 mul. */
FRESNEL_I_INLINE fresnel_rgb_q15 fresnel_f82_q15_rgb_fast(fresnel_rgb_q15 f0, const int32_t a_q12[3], int32_t c)
{
    fresnel_rgb_q15 r;
    r.r = fresnel_f82_q15_fast(f0.r, a_q12[0], c);
    r.g = fresnel_f82_q15_fast(f0.g, a_q12[1], c);
    r.b = fresnel_f82_q15_fast(f0.b, a_q12[2], c);
    return r;
}

/* sqrt(j/128) in Q22 for j = 32..129, and 2^16 / (r_j + r_(j+1)) for
 * j = 32..128 (the chord slope of each segment): 586 bytes of flash in the
 * translation unit that uses fresnel_lut_u16_q15_fast. */
static const uint32_t fresnel_i_fast_sqrt_r[98] = {
    2097152u, 2129668u, 2161695u, 2193254u, 2224366u, 2255048u, 2285318u, 2315193u,
    2344687u, 2373815u, 2402589u, 2431023u, 2459129u, 2486916u, 2514397u, 2541580u,
    2568476u, 2595093u, 2621440u, 2647525u, 2673355u, 2698938u, 2724280u, 2749389u,
    2774271u, 2798932u, 2823377u, 2847613u, 2871644u, 2895475u, 2919112u, 2942559u,
    2965821u, 2988901u, 3011805u, 3034536u, 3057098u, 3079495u, 3101730u, 3123806u,
    3145728u, 3167498u, 3189119u, 3210595u, 3231928u, 3253121u, 3274178u, 3295099u,
    3315888u, 3336548u, 3357081u, 3377489u, 3397775u, 3417940u, 3437986u, 3457917u,
    3477733u, 3497437u, 3517031u, 3536516u, 3555894u, 3575168u, 3594337u, 3613406u,
    3632374u, 3651243u, 3670016u, 3688693u, 3707276u, 3725766u, 3744165u, 3762474u,
    3780695u, 3798827u, 3816874u, 3834836u, 3852714u, 3870510u, 3888224u, 3905858u,
    3923412u, 3940888u, 3958288u, 3975611u, 3992858u, 4010032u, 4027133u, 4044161u,
    4061117u, 4078004u, 4094820u, 4111568u, 4128248u, 4144861u, 4161407u, 4177888u,
    4194304u, 4210656u
};
static const uint16_t fresnel_i_fast_sqrt_k[97] = {
    65032u, 64054u, 63119u, 62223u, 61365u, 60541u, 59749u, 58988u, 58255u, 57549u, 56868u, 56211u,
    55575u, 54961u, 54367u, 53792u, 53234u, 52694u, 52169u, 51660u, 51166u, 50685u, 50218u, 49764u,
    49321u, 48891u, 48471u, 48062u, 47663u, 47274u, 46894u, 46523u, 46161u, 45808u, 45462u, 45124u,
    44793u, 44470u, 44153u, 43843u, 43540u, 43243u, 42952u, 42666u, 42386u, 42112u, 41843u, 41579u,
    41320u, 41066u, 40816u, 40571u, 40330u, 40093u, 39861u, 39633u, 39408u, 39187u, 38970u, 38757u,
    38547u, 38340u, 38136u, 37936u, 37739u, 37545u, 37354u, 37166u, 36981u, 36798u, 36618u, 36441u,
    36266u, 36094u, 35924u, 35756u, 35591u, 35428u, 35268u, 35109u, 34953u, 34798u, 34646u, 34496u,
    34347u, 34201u, 34056u, 33913u, 33772u, 33633u, 33496u, 33360u, 33225u, 33093u, 32962u, 32832u,
    32704u
};

/* sqrt(c / 2^15) in Q22 for c in [1, 32768]. c is scaled by 4^m into
 * [2^13, 2^15] (m = 0 for c >= 2^13, up to 7 for c = 1). On segment
 * j = c >> 8, with d = c & 255 and delta = sqrt(c) - r_j, which solves
 * delta = (d + delta (dh - delta)) k  (dh = r_(j+1) - r_j, k the chord slope):
 * delta1 = d k (the chord), delta2 = (d + delta1 (dh - delta1)) k (one
 * fixed-point step, contraction dh/(r_j + r_(j+1)) <= 2^-7). Every term is
 * non-negative (delta1 <= dh). |error| <= 2^-20.7. */
FRESNEL_I_INLINE uint32_t fresnel_i_fast_sqrt_q22(uint32_t c)
{
    uint32_t m = 0, j, d, k, r0, dh, d1;
    while (c < 8192u) {
        c <<= 2;
        m++;
    }
    j = (c >> 8) - 32u;
    d = c & 255u;
    k = fresnel_i_fast_sqrt_k[j];
    r0 = fresnel_i_fast_sqrt_r[j];
    dh = fresnel_i_fast_sqrt_r[j + 1] - r0;
    d1 = (d * k) >> 9;
    return (r0 + ((((d << 7) + ((d1 * (dh - d1)) >> 22)) * k) >> 16)) >> m;
}

/* fresnel_lut_u16_q15 (nodes uniform in sqrt(c), node i at c = (i/(n-1))^2)
 * with an approximate square root; n and c as PRECONDITIONS says.
 * Error against the double interpolation at the exact sqrt(c)
 * <= FRESNEL_BOUND_LUT_Q15_FAST LSB for n <= 64 and
 * FRESNEL_BOUND_LUT_Q15_FAST_1024 LSB for n <= 1024.
 * Cost: 5 mul (plus 2 shifts per halving of c below 1/4). */
FRESNEL_I_INLINE fresnel_q15 fresnel_lut_u16_q15_fast(const uint16_t *table, int n, int32_t c)
{
    uint32_t pos, i, t;
    int32_t v0, v1;
    if (n < 2)
        return n < 1 ? 0 : table[0];
    if (n > 1024)
        n = 1024;
    if (((uint32_t)c - 1u) >> 15) /* c <= 0, or c > one */
        return c <= 0 ? table[0] : table[n - 1];
    /* pos = round(sqrt(c) (n-1) 2^15), segment i = (pos - 1) >> 15, so that
     * c = one reads nodes n-2 and n-1 with weight one. The root's error,
     * below 2^-20.7 (n - 1) of a segment, shows times the steepest
     * node-to-node step (a 1024-node table across a critical angle). */
    pos = (fresnel_i_fast_sqrt_q22((uint32_t)c) * (uint32_t)(n - 1) + 64u) >> 7;
    i = (pos - 1u) >> 15;
    t = pos - (i << 15);
    v0 = table[i];
    v1 = table[i + 1];
    return (fresnel_q15)((v0 * 32768 + (v1 - v0) * (int32_t)t + 16384) >> 15);
}

/* The grazing-pl node position (lut_spacing = grazing-pl in a scene):
 * P(c), a 64-piece linear stand-in for sqrt(c), is the linear interpolation
 * of the knots fresnel_lut_pl_knots_q15[k] = round(32768 sqrt(k/64)) between
 * c = k/64 and (k+1)/64. A grazing-pl table's node i sits where
 * P(c) = i/(n-1); `fresnel gen` places its nodes through this table, and
 * fresnel_lut_pl_u16_q15_fast reads them through it. It needs no root and
 * still crowds the nodes toward grazing incidence (the first piece is 1/8
 * of the range, 1/64 of c). */
static const uint16_t fresnel_lut_pl_knots_q15[65] = {
    0u,     4096u,  5793u,  7094u,  8192u,  9159u,  10033u, 10837u, 11585u, 12288u, 12953u, 13585u, 14189u,
    14768u, 15326u, 15864u, 16384u, 16888u, 17378u, 17854u, 18318u, 18770u, 19212u, 19644u, 20066u, 20480u,
    20886u, 21283u, 21674u, 22058u, 22435u, 22806u, 23170u, 23530u, 23884u, 24232u, 24576u, 24915u, 25249u,
    25580u, 25905u, 26227u, 26545u, 26859u, 27170u, 27477u, 27780u, 28081u, 28378u, 28672u, 28963u, 29251u,
    29537u, 29819u, 30099u, 30377u, 30652u, 30924u, 31194u, 31462u, 31727u, 31991u, 32252u, 32511u, 32768u};

/* fresnel_lut_u16_q15 on nodes uniform in P(c) (S = fresnel_lut_pl_knots_q15):
 *   p = S[j] + ((S[j+1] - S[j]) (c mod 512)) >> 9, j = c >> 9  (c = one read
 *       as one - 2^-15, so that p < one and the last segment is n-2)
 *   pos = p (n-1), node i = pos >> 15, linear interpolation, truncated.
 * n and c as PRECONDITIONS says. Error against the same interpolation in
 * double at the same P <= FRESNEL_BOUND_LUT_PL_Q15_FAST LSB for
 * 2 <= n <= 64 (P has 15 bits: its truncation moves the position by up to
 * (n-1) 2^-15 of a segment), FRESNEL_BOUND_LUT_PL_Q15_FAST_TIR across a
 * total-reflection edge (a step of up to one between two nodes).
 * Cost: 3 mul, 4 loads. */
FRESNEL_I_INLINE fresnel_q15 fresnel_lut_pl_u16_q15_fast(const uint16_t *table, int n, int32_t c)
{
    uint32_t x, p, pos, t;
    const uint16_t *s, *v;
    if (n < 2)
        return n < 1 ? 0 : table[0];
    if (n > 32768)
        n = 32768;
    x = (uint32_t)c;
    if (x >> 15) /* c < 0, or c >= one: one is read as one - 2^-15 */
        x = c < 0 ? 0u : 32767u;
    s = fresnel_lut_pl_knots_q15 + (x >> 9);
    p = s[0] + (((uint32_t)(s[1] - s[0]) * (x & 511u)) >> 9);
    pos = p * (uint32_t)(n - 1);
    t = pos & 32767u;
    v = table + (pos >> 15);
    return (fresnel_q15)((v[0] * 32768 + (v[1] - v[0]) * (int32_t)t) >> 15);
}

/* ------------------------------------------------ exact conductor, fast path */

/* Prepared constants of fresnel_conductor_q15_fast (the struct is in
 * fresnel_q15.h), made on the host from double eta, kappa:
 * q15_conductor_fast in gen/3_encode/q15_params.c is the reference of
 * this layout, and `fresnel gen` emits <prefix>_ior_fast_q15[3] for a scene
 * with the exact model in q15 whose three channels lie in the domain below
 * (else a comment names the channel outside it):
 *   D = eta^2 - kappa^2 - 1 (eta^2 in two doubles), b = 2 eta kappa;
 *   shift = the smallest s such that a0 + [0, 2^(30-s)] fits int32 and
 *   b 2^(30-s) < 2^31, where a0 = round(D 2^(30-s)) and
 *   a0_lo = round((D 2^(30-s) - a0) 2^16), in [-2^15, 2^15];
 *   b1 = round(b 2^(30-s)); where s = 0 and b1 < 2^15, b2 = round(b 2^46)
 *   and span = 65535 (ah = a0 + c^2 is then read in two words, ah 2^16 +
 *   a0_lo against b2, at the codes where |ah| < 2^15 too: a dielectric's
 *   critical angle), else b2 = 0 and span = 0 (one word at every code);
 *   b = bm 2^-be with bm in [2^15, 2^16) rounded (bm = 0, be = 255 for
 *   kappa = 0).
 * The domain of the fast path (FRESNEL_CONDUCTOR_*_Q15_FAST): eta in
 * [0.03, 8], kappa in [0, 16], eta >= 0.07 where kappa < 0.1 (a dielectric
 * of a smaller relative index is steeper at its critical angle than the
 * 16-bit mantissas resolve), and |eta^2 - kappa^2 - 1 + 2i eta kappa| >=
 * 0.001 (near the matched index the reflectance is a ratio of two tiny
 * numbers); eta = 1, kappa = 0 itself gives 0 at every c. Every material of
 * data/ at 380-780 nm lies inside it. */
#define FRESNEL_CONDUCTOR_ETA_MIN_Q15_FAST 0.03
#define FRESNEL_CONDUCTOR_ETA_MAX_Q15_FAST 8.0
#define FRESNEL_CONDUCTOR_KAPPA_MAX_Q15_FAST 16.0
#define FRESNEL_CONDUCTOR_ETA_MIN_Q15_FAST_DIELECTRIC 0.07 /* for kappa < 0.1 */
#define FRESNEL_CONDUCTOR_MATCH_MIN_Q15_FAST 0.001
/* fresnel_conductor_prep_q15_fast is declared in fresnel_q15.h, so that a
 * generated header can hold its constants without this header. */

/* sqrt(j) and 2^7 / j in Q16 (4 bits below the results' units), raised
 * (sqrt, concave) or lowered (1/j, convex) by half the chord's largest
 * deviation on a segment, plus 8 so that the final >> 4 rounds:
 * round(2^16 sqrt(j) + 2^10 j^-1.5) + 8 for j = 64..256, and
 * round(2^27 / j - 2^24 j^-3) + 8 for j = 128..257. */
static const uint32_t fresnel_i_fast_sq[193] = {
    524298u, 528378u, 532427u, 536445u, 540434u, 544393u, 548323u, 552226u, 556101u, 559949u,
    563772u, 567568u, 571339u, 575086u, 578808u, 582506u, 586181u, 589833u, 593463u, 597071u,
    600657u, 604221u, 607765u, 611288u, 614791u, 618275u, 621738u, 625183u, 628608u, 632015u,
    635404u, 638775u, 642128u, 645464u, 648782u, 652084u, 655369u, 658638u, 661890u, 665127u,
    668348u, 671553u, 674743u, 677919u, 681079u, 684225u, 687356u, 690473u, 693577u, 696666u,
    699742u, 702804u, 705853u, 708889u, 711912u, 714922u, 717920u, 720905u, 723878u, 726838u,
    729787u, 732723u, 735648u, 738562u, 741464u, 744355u, 747234u, 750102u, 752960u, 755807u,
    758643u, 761468u, 764283u, 767088u, 769882u, 772667u, 775441u, 778205u, 780960u, 783705u,
    786441u, 789167u, 791883u, 794590u, 797288u, 799977u, 802657u, 805328u, 807991u, 810644u,
    813289u, 815925u, 818553u, 821172u, 823783u, 826386u, 828981u, 831567u, 834146u, 836716u,
    839279u, 841834u, 844381u, 846920u, 849452u, 851976u, 854493u, 857003u, 859505u, 862000u,
    864488u, 866968u, 869442u, 871908u, 874368u, 876820u, 879266u, 881705u, 884137u, 886563u,
    888982u, 891394u, 893800u, 896200u, 898593u, 900979u, 903360u, 905734u, 908102u, 910464u,
    912819u, 915169u, 917512u, 919850u, 922182u, 924507u, 926827u, 929142u, 931450u, 933753u,
    936050u, 938341u, 940627u, 942907u, 945182u, 947451u, 949715u, 951974u, 954227u, 956475u,
    958717u, 960955u, 963187u, 965414u, 967636u, 969853u, 972064u, 974271u, 976473u, 978669u,
    980861u, 983048u, 985230u, 987408u, 989580u, 991748u, 993911u, 996069u, 998223u, 1000372u,
    1002516u, 1004656u, 1006791u, 1008922u, 1011048u, 1013170u, 1015288u, 1017401u, 1019509u, 1021613u,
    1023713u, 1025809u, 1027900u, 1029987u, 1032070u, 1034149u, 1036223u, 1038294u, 1040360u, 1042422u,
    1044480u, 1046534u, 1048584u};
static const uint32_t fresnel_i_fast_rc[130] = {
    1048576u, 1040448u, 1032444u, 1024563u, 1016802u, 1009157u, 1001626u, 994207u, 986896u, 979693u,
    972594u, 965597u, 958700u, 951901u, 945197u, 938588u, 932070u, 925642u, 919302u, 913048u,
    906879u, 900793u, 894788u, 888862u, 883015u, 877243u, 871547u, 865924u, 860374u, 854894u,
    849483u, 844140u, 838865u, 833654u, 828509u, 823426u, 818405u, 813445u, 808545u, 803703u,
    798920u, 794192u, 789521u, 784904u, 780340u, 775830u, 771371u, 766963u, 762606u, 758297u,
    754037u, 749825u, 745659u, 741540u, 737465u, 733435u, 729449u, 725507u, 721606u, 717747u,
    713930u, 710152u, 706415u, 702716u, 699056u, 695434u, 691850u, 688302u, 684790u, 681314u,
    677873u, 674467u, 671095u, 667756u, 664450u, 661177u, 657936u, 654727u, 651548u, 648401u,
    645284u, 642196u, 639138u, 636109u, 633109u, 630136u, 627192u, 624275u, 621385u, 618521u,
    615684u, 612873u, 610087u, 607326u, 604591u, 601880u, 599193u, 596530u, 593890u, 591274u,
    588681u, 586110u, 583562u, 581036u, 578531u, 576048u, 573587u, 571146u, 568726u, 566326u,
    563947u, 561587u, 559247u, 556927u, 554626u, 552343u, 550080u, 547834u, 545607u, 543398u,
    541207u, 539034u, 536878u, 534739u, 532617u, 530512u, 528423u, 526351u, 524295u, 522255u};

/* sqrt(x) for x in [2^30, 2^32), in [2^15, 2^16]: the chord of one of 192
 * segments, rounded; relative error below 2^-15.6 (tests/runtime/q15/test_q15_fast.c,
 * every x >> 8). */
FRESNEL_I_INLINE uint32_t fresnel_i_fast_sqrt32(uint32_t x)
{
    const uint32_t *t = fresnel_i_fast_sq + ((x >> 24) - 64u);
    return (t[0] + (((t[1] - t[0]) * ((x >> 8) & 0xffffu)) >> 16)) >> 4;
}

/* 2^31 / d for d in [2^15, 2^16], in [2^15, 2^16]: the chord of one of 129
 * segments, rounded; relative error below 2^-15.6 (tests/runtime/q15/test_q15_fast.c,
 * every d). */
FRESNEL_I_INLINE uint32_t fresnel_i_fast_recip16(uint32_t d)
{
    const uint32_t *t = fresnel_i_fast_rc + ((d >> 8) - 128u);
    return (t[0] - (((t[0] - t[1]) * (d & 255u)) >> 8)) >> 4;
}

/* The number of leading zeros of x > 0 (Cortex-M0 has no CLZ): a byte
 * table, the top nonzero byte first (one compare for x >= 2^24). */
static const uint8_t fresnel_i_fast_clz8[256] = {
    8u, 7u, 6u, 6u, 5u, 5u, 5u, 5u, 4u, 4u, 4u, 4u, 4u, 4u, 4u, 4u, 3u, 3u, 3u, 3u, 3u, 3u, 3u, 3u, 3u, 3u, 3u, 3u, 3u, 3u, 3u, 3u,
    2u, 2u, 2u, 2u, 2u, 2u, 2u, 2u, 2u, 2u, 2u, 2u, 2u, 2u, 2u, 2u, 2u, 2u, 2u, 2u, 2u, 2u, 2u, 2u, 2u, 2u, 2u, 2u, 2u, 2u, 2u, 2u,
    1u, 1u, 1u, 1u, 1u, 1u, 1u, 1u, 1u, 1u, 1u, 1u, 1u, 1u, 1u, 1u, 1u, 1u, 1u, 1u, 1u, 1u, 1u, 1u, 1u, 1u, 1u, 1u, 1u, 1u, 1u, 1u,
    1u, 1u, 1u, 1u, 1u, 1u, 1u, 1u, 1u, 1u, 1u, 1u, 1u, 1u, 1u, 1u, 1u, 1u, 1u, 1u, 1u, 1u, 1u, 1u, 1u, 1u, 1u, 1u, 1u, 1u, 1u, 1u,
    0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u,
    0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u,
    0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u,
    0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u};
FRESNEL_I_INLINE uint32_t fresnel_i_fast_lz(uint32_t x)
{
    if (x >> 24)
        return fresnel_i_fast_clz8[x >> 24];
    if (x >> 16)
        return 8u + fresnel_i_fast_clz8[x >> 16];
    if (x >> 8)
        return 16u + fresnel_i_fast_clz8[x >> 8];
    return 24u + fresnel_i_fast_clz8[x];
}

/* x c / 2^15 for x < 2^32, c <= 2^16 with x c / 2^15 < 2^32, from 15-bit halves. */
FRESNEL_I_INLINE uint32_t fresnel_i_fast_mul15(uint32_t x, uint32_t c)
{
    return (x >> 15) * c + (((x & 32767u) * c) >> 15);
}

/* x y / 2^16 for y <= 2^16 with x y / 2^16 < 2^32, from 16-bit halves. */
FRESNEL_I_INLINE uint32_t fresnel_i_fast_mul16(uint32_t x, uint32_t y)
{
    return (x >> 16) * y + (((x & 0xffffu) * y) >> 16);
}

/* x 2^d for d of either sign (0 when d <= -32). */
FRESNEL_I_INLINE uint32_t fresnel_i_fast_shift(uint32_t x, int32_t d)
{
    return d >= 0 ? x << d : (d > -32 ? x >> -d : 0u);
}

/* The exact unpolarised reflectance of eta + i kappa (fresnel_conductor,
 * the form of src/f32/exact.c) with p prepared by q15_conductor_fast, for
 * c in [0, one] (PRECONDITIONS; any c outside is undefined):
 *   A = eta^2 - kappa^2 - s^2, s^2 = 1 - c^2, b = 2 eta kappa,
 *   m = sqrt(A^2 + b^2), B = sqrt((m + |A|)/2),
 *   u = B for A >= 0; for A < 0, u = (b/2)/B, folded into the ratios
 *   (H and H s^2 taken with u B = b/2, G and G2 times B),
 *   Rs = (G - H)/(G + H), P = (G2 - H s^2)/(G2 + H s^2),
 *   G = m + c^2, G2 = c^2 m + s^4, H = 2 c u,
 *   F = Rs (1 + P)/2 = Ns (Dp + Np) / (2 Ds Dp),
 * in block floating point with 16-bit mantissas: the two square roots and
 * the one reciprocal are table chords (192 and 129 segments, relative error
 * below 2^-15.6), normalisations a byte table of leading zeros (Cortex-M0
 * has no CLZ), every product 32 x 32 -> 32. c = 0 gives one (0 for the
 * matched index).
 * Error <= FRESNEL_BOUND_CONDUCTOR_Q15_FAST LSB over the domain above, every
 * c code (tests/runtime/q15/test_q15_fast.c); results in [0, one].
 * Cost: 22 mul (26 for A < 0); on Cortex-M0 -Os under 300 instructions
 * (`make cross-count`, ports/README.md: about a tenth of
 * fresnel_conductor_q15's), 1548 bytes of tables.
 *
 * Why every step holds for every (p, c) q15_conductor_fast makes from the
 * domain (tests/runtime/q15/test_q15_fast.c searches each boundary below):
 *   shift <= 8 (|D|, b <= 257), and a0 + [0, 2^(30-shift)] fits int32, so ah does.
 *   Two words iff ah + 32767 < span as uint32: span is 65535 only where
 *     shift = 0 and b1 < 2^15, and then it takes exactly |ah| <= 32767
 *     (ah = -32767 wraps to 0, and span 0 takes nothing). There
 *     a = A 2^46 to half a unit (c^2 >> 0 is exact), |a| < 2^31, b2 < 2^31.
 *     In one word |a| < 2^31 and max(|a|, b1) >= 2^15: b1 >= 2^15, or
 *     |ah| > 32767 (shift > 0 only for D >= 1 or D < -2, where |A| >= 1).
 *   x = 0 only in two words, A 2^46 and b2 rounding to 0: a dielectric at
 *     its critical angle, where F = 1.
 *   n = lz(x) in [1, 31] puts max(ak, bk) in [2^15, 2^16): k is in [7, 30]
 *     in one word, [31, 61] in two.
 *   ak (ak + 1) + bk (bk + 1) (the truncated halves added back) is in
 *     [2^30, 2^33): x < s is its bit 32; mk < 92682.
 *   mk + ak is in [2^15, 3 2^16): x << (15 - (x >> 16)) is in [2^30, 2^31),
 *     one more for an even k + 1 + e below 2^32.
 *   r = max(k - 17, 0) and q = max(17 - k, 0) <= 10 set the scale 2^e of
 *     G and G2, e = 30 - q = k + 13 - r, where both are below 2^30.8; r is
 *     cut to 31, where the terms it shifts (< 2^29.5) are 0 anyway.
 *   he = c um 2^(16 - q - eu) is H at that scale (times B for A < 0); H <=
 *     G (G - H >= (sqrt m - c)^2, u <= sqrt m), so he < 2^31 and a left
 *     shift is below 16 (c um >= 2^15 where um > 0).
 *   G >= max(|D|, b) >= 0.0007 and G2 >= (eta^2 - kappa^2)^2 >= 2.3e-5 in
 *     the domain, so g, g2 >= 2^9 at e >= 20 (B halves them at most): lz
 *     never sees 0.
 *   Ns = Ds - 2H and Np = Dp - 2 H s^2, the small term rounded at the same
 *     normalisation (Rs, P near one keep half a unit), clamped at 0.
 *   ds dp is in [2^30, 2^32); its top 16 bits rounded, in [2^15, 2^16], are
 *     recip16's domain; ns (dp + np)/2 <= ds dp, so its product with the
 *     reciprocal (<= 2^16) stays below 2^32 and F below one + 2^-14, cut
 *     to one. */
FRESNEL_I_INLINE fresnel_q15 fresnel_conductor_q15_fast(const fresnel_conductor_prep_q15_fast *p, int32_t c_in)
{
    uint32_t c = (uint32_t)c_in, c2, ak, bk, x, s, mk, um, he, g, g2, ds, ns, dp, np, n, r, q;
    int32_t ah, a, k, e, eb2, eu;
    int neg;
    if (c == 0)
        return (fresnel_q15)((p->a0 | p->a0_lo | p->b1) ? 32768 : 0);
    c2 = c * c;
    /* A = a0 + c^2 and b = 2 eta kappa at one scale, in two words where
     * both are small; m = sqrt(ak^2 + bk^2) 2^-k */
    ah = p->a0 + (int32_t)(c2 >> p->shift);
    if ((uint32_t)ah + 32767u < p->span) {
        a = (int32_t)((uint32_t)ah << 16) + p->a0_lo;
        bk = (uint32_t)p->b2;
        k = 30 - p->shift;
    } else {
        a = ah;
        bk = (uint32_t)p->b1;
        k = 14 - p->shift;
    }
    neg = a < 0;
    ak = neg ? 0u - (uint32_t)a : (uint32_t)a;
    x = ak > bk ? ak : bk;
    if (x == 0)
        return 32768; /* A = b = 0: at the critical angle */
    n = fresnel_i_fast_lz(x);
    ak = (ak << n) >> 16;
    bk = (bk << n) >> 16;
    k += (int32_t)n;
    s = ak * (ak + 1u);
    x = s + bk * (bk + 1u);
    if (x < s)
        mk = fresnel_i_fast_sqrt32((x >> 2) | 0x40000000u) << 1;
    else
        mk = fresnel_i_fast_sqrt32(x); /* m = mk 2^-k */
    /* B = sqrt((m + |A|)/2) = s 2^-eb2; u = B for A >= 0, (b/2)/B for A < 0 */
    x = mk + ak;
    e = 15 - (int32_t)(x >> 16);
    e += (k + 1 + e) & 1;
    s = fresnel_i_fast_sqrt32(x << e);
    eb2 = (k + 1 + e) >> 1;
    if (!neg) {
        um = s;
        eu = eb2;
    } else { /* u B = eta kappa: H B = 2 c eta kappa, at the scale of G B 2^(eb2-16) */
        um = (uint32_t)p->bm;
        eu = p->be + 17 - eb2;
    }
    /* G 2^e and G2 2^e, e = 30 - q = k + 13 - r */
    e = k - 17;
    r = e > 0 ? (uint32_t)e : 0u;
    q = r - (uint32_t)e;
    if (r > 31u)
        r = 31u;
    g = ((mk << 13) >> r) + (c2 >> q);
    x = fresnel_i_fast_mul15(fresnel_i_fast_mul15(32768u * 32768u - c2, 32768u + c), 32768u - c); /* s^4 in Q30 */
    g2 = ((fresnel_i_fast_mul15(mk * c, c) >> 2) >> r) + (x >> q);
    if (neg) {
        g = fresnel_i_fast_mul16(g, s);
        g2 = fresnel_i_fast_mul16(g2, s);
    }
    he = fresnel_i_fast_shift(c * um, 16 - (int32_t)q - eu); /* H = 2 c u */
    ds = g + he;
    n = fresnel_i_fast_lz(ds);
    ds = (ds << n) >> 16;
    x = (((he << n) >> 14) + 1u) >> 1;
    ns = ds > x ? ds - x : 0u;
    he = fresnel_i_fast_mul15(fresnel_i_fast_mul15(he, 32768u + c), 32768u - c); /* H s^2 */
    dp = g2 + he;
    n = fresnel_i_fast_lz(dp);
    dp = (dp << n) >> 16;
    x = (((he << n) >> 14) + 1u) >> 1;
    np = dp > x ? dp - x : 0u;
    /* F = Rs (1 + P)/2 = Ns (Dp + Np) / (2 Ds Dp), one reciprocal */
    x = ds * dp;
    np = ns * ((dp + np) >> 1);
    n = 14u + (x >> 31);
    x = ((x >> n) + 1u) >> 1;
    np = ((fresnel_i_fast_mul16(np, fresnel_i_fast_recip16(x)) >> n) + 1u) >> 1;
    return (fresnel_q15)(np >> 15 ? 32768u : np);
}

/* The same for three channels, on <prefix>_ior_fast_q15[3] as `fresnel gen`
 * emits it; each channel equals fresnel_conductor_q15_fast's. The channels
 * go round one loop, so the body is inlined once, not three times: the RGB
 * call costs one channel's code (`make size`, exact-conductor-rgb-fast). */
FRESNEL_I_INLINE fresnel_rgb_q15 fresnel_conductor_q15_rgb_fast(const fresnel_conductor_prep_q15_fast p[3], int32_t c)
{
    fresnel_q15 v[3];
    fresnel_rgb_q15 r;
    int ch;
    for (ch = 0; ch < 3; ch++)
        v[ch] = fresnel_conductor_q15_fast(&p[ch], c);
    r.r = v[0];
    r.g = v[1];
    r.b = v[2];
    return r;
}

#endif /* FRESNEL_HAS_Q15: fast paths */

#endif /* FRESNEL_Q15_FAST_H */
