/* The edges of every fixed-point function's inputs (fresnel_fixed.h): each
 * precondition or clamp at its edge and one LSB past it, in every number
 * type the argument has. LUTs get tables allocated to exactly the entries
 * they may read (none for n <= 0: a null pointer), so that under the
 * sanitizer pass ASan reports any read past them; UBSan checks the signed
 * arithmetic of the fast paths at their stated limits. */
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fresnel_fixed.h"
#include "fresnel_fixed_fast.h"
#include "harness.h"

#define ONE 32768

static const int32_t cs[] = {INT32_MIN, -65536, -32768, -2, -1, 0, 1, 2, 16384, 32766, 32767, ONE, ONE + 1, ONE + 2,
                             ONE + 2435, 65535, 65536, INT32_MAX};
#define NCS ((int)(sizeof cs / sizeof cs[0]))
static const int ns[] = {INT_MIN, -1, 0, 1, 2, 3, 1024, 1025, 32767, 32768, 32769, INT_MAX};
#define NNS ((int)(sizeof ns / sizeof ns[0]))

static uint32_t rng_state = 0x2545f491u;
static uint32_t rng(void)
{
    rng_state = rng_state * 1664525u + 1013904223u;
    return rng_state >> 8;
}

/* Entries a table of n nodes per channel has, as the functions read it. */
static size_t entries(int n, int max)
{
    return n <= 0 ? 0 : (size_t)(n > max ? max : n);
}

static void *table_alloc(size_t count, size_t size)
{
    return count ? malloc(count * size) : NULL;
}

static int in_range(int32_t v) { return v >= 0 && v <= ONE; }

/* The scalar LUT forms at every n and c of the lists: in range, and the
 * defined value for n <= 0, n = 1 and n above the maximum. */
static void check_lut_n(void)
{
    long bad_range = 0, bad_value = 0, bad_rgb = 0;
    int in, ic;
    char first[160] = "";
    for (in = 0; in < NNS; in++) {
        int n = ns[in];
        size_t m = entries(n, 32768), k;
        uint16_t *u16 = table_alloc(3 * m, sizeof *u16);
        uint8_t *u8 = table_alloc(3 * m, sizeof *u8);
        int16_t *s16 = table_alloc(3 * m, sizeof *s16);
        int8_t *s8 = table_alloc(3 * m, sizeof *s8);
        int nref = n > 32768 ? 32768 : n;
        if (m && !(u16 && u8 && s16 && s8)) {
            CHECK("fixed LUT edge tables allocate", 0, "n %d", n);
            return;
        }
        for (k = 0; k < 3 * m; k++) {
            uint32_t u = rng();
            u16[k] = (uint16_t)(u % 32769u);
            u8[k] = (uint8_t)u;
            s16[k] = (int16_t)(u >> 4);
            s8[k] = (int8_t)(u >> 12);
        }
        for (ic = 0; ic < NCS; ic++) {
            int32_t c = cs[ic], f0 = 1311;
            int32_t r[13], want[13];
            fresnel_rgb_q15 f03, rgb[10];
            int j;
            f03.r = f03.g = f03.b = (fresnel_q15)f0;
            r[0] = fresnel_lut_u16_q15(u16, n, c);
            r[1] = fresnel_lut_linear_u16_q15(u16, n, c);
            r[2] = fresnel_lut_u8_q15(u8, n, c);
            r[3] = fresnel_lut_linear_u8_q15(u8, n, c);
            r[4] = fresnel_lut_residual_s16_q15(f0, s16, n, 20, c);
            r[5] = fresnel_lut_linear_residual_s16_q15(f0, s16, n, 20, c);
            r[6] = fresnel_lut_residual_s8_q15(f0, s8, n, 12, c);
            r[7] = fresnel_lut_linear_residual_s8_q15(f0, s8, n, 12, c);
            r[8] = fresnel_lut_cubic_u16_q15(u16, n, c);
            r[9] = fresnel_lut_u16_q15_fast(u16, n, c);
            r[10] = fresnel_lut_pl_u16_q15_fast(u16, n, c);
            rgb[0] = fresnel_lut_u16_q15_rgb(u16, n, c);
            rgb[1] = fresnel_lut_linear_u16_q15_rgb(u16, n, c);
            rgb[2] = fresnel_lut_u8_q15_rgb(u8, n, c);
            rgb[3] = fresnel_lut_linear_u8_q15_rgb(u8, n, c);
            rgb[4] = fresnel_lut_residual_s16_q15_rgb(f03, s16, n, 20, c);
            rgb[5] = fresnel_lut_linear_residual_s16_q15_rgb(f03, s16, n, 20, c);
            rgb[6] = fresnel_lut_residual_s8_q15_rgb(f03, s8, n, 12, c);
            rgb[7] = fresnel_lut_linear_residual_s8_q15_rgb(f03, s8, n, 12, c);
            rgb[8] = fresnel_lut_cubic_u16_q15_rgb(u16, n, c);
            for (j = 0; j < 11; j++)
                bad_range += !in_range(r[j]);
            for (j = 0; j < 9; j++)
                bad_range += !in_range(rgb[j].r) + !in_range(rgb[j].g) + !in_range(rgb[j].b);
            /* the red channel is the scalar form on the first n entries */
            for (j = 0; j < 9; j++)
                bad_rgb += rgb[j].r != r[j];
            /* the defined values */
            if (n <= 0) {
                int32_t s = fresnel_schlick_q15(f0, c);
                for (j = 0; j < 11; j++)
                    want[j] = (j >= 4 && j < 8) ? s : 0;
            } else if (n == 1) {
                int32_t v16 = u16[0], v8 = (int32_t)((u8[0] * 32768u * 2u + 255u) / 510u);
                int16_t t16[2];
                int8_t t8[2];
                t16[0] = t16[1] = s16[0];
                t8[0] = t8[1] = s8[0];
                want[0] = want[1] = want[8] = want[9] = want[10] = v16;
                want[2] = want[3] = v8;
                /* a one-node residual is the two-node table of that value */
                want[4] = fresnel_lut_residual_s16_q15(f0, t16, 2, 20, c);
                want[5] = fresnel_lut_linear_residual_s16_q15(f0, t16, 2, 20, c);
                want[6] = fresnel_lut_residual_s8_q15(f0, t8, 2, 12, c);
                want[7] = fresnel_lut_linear_residual_s8_q15(f0, t8, 2, 12, c);
            } else {
                int nf = n > 1024 ? 1024 : n;
                want[0] = fresnel_lut_u16_q15(u16, nref, c);
                want[1] = fresnel_lut_linear_u16_q15(u16, nref, c);
                want[2] = fresnel_lut_u8_q15(u8, nref, c);
                want[3] = fresnel_lut_linear_u8_q15(u8, nref, c);
                want[4] = fresnel_lut_residual_s16_q15(f0, s16, nref, 20, c);
                want[5] = fresnel_lut_linear_residual_s16_q15(f0, s16, nref, 20, c);
                want[6] = fresnel_lut_residual_s8_q15(f0, s8, nref, 12, c);
                want[7] = fresnel_lut_linear_residual_s8_q15(f0, s8, nref, 12, c);
                want[8] = fresnel_lut_cubic_u16_q15(u16, nref, c);
                want[9] = fresnel_lut_u16_q15_fast(u16, nf, c);
                want[10] = fresnel_lut_pl_u16_q15_fast(u16, nref, c);
                /* c past [0, one] is c clamped */
                if (c < 0 || c > ONE) {
                    int32_t cc = c < 0 ? 0 : ONE;
                    want[0] = fresnel_lut_u16_q15(u16, nref, cc);
                    want[9] = fresnel_lut_u16_q15_fast(u16, nf, cc);
                    want[10] = fresnel_lut_pl_u16_q15_fast(u16, nref, cc);
                }
            }
            for (j = 0; j < 11; j++)
                if (r[j] != want[j]) {
                    if (bad_value++ == 0)
                        snprintf(first, sizeof first, "function %d, n %d, c %ld: %ld, expected %ld", j, n, (long)c,
                                 (long)r[j], (long)want[j]);
                }
        }
        free(u16);
        free(u8);
        free(s16);
        free(s8);
    }
    CHECK("fixed LUTs (every form, fast paths too) in [0, one] for every n and c edge", bad_range == 0,
          "%ld out of range", bad_range);
    CHECK("fixed LUTs: n <= 0 is 0 (residual: Schlick), n = 1 table[0], n above the maximum the maximum, c clamped",
          bad_value == 0, "%ld differ, first %s", bad_value, first);
    CHECK("fixed LUT RGB forms: red channel equals the scalar form at every n edge", bad_rgb == 0, "%ld differ",
          bad_rgb);
}

/* Schlick and F82 fast: every c from -64 through FRESNEL_C_MAX_Q15_FAST
 * and every 7th F0 code. c < 0 gives the value at 0, c in (one, C_MAX] the
 * value at one; C_MAX + 1 is where x^4 stops being 0 (its square is 2436^2
 * mod 2^32, 182 after the shift). */
static void check_fast_c(void)
{
    long bad = 0, bad_rgb = 0;
    int32_t f0, c;
    for (f0 = 0; f0 <= ONE; f0 += 7) {
        int32_t at0 = fresnel_schlick_q15_fast(f0, 0), at1 = fresnel_schlick_q15_fast(f0, ONE);
        int32_t a = (int32_t)((ONE - f0) * 2);
        int32_t g0 = fresnel_f82_q15_fast(f0, a, 0), g1 = fresnel_f82_q15_fast(f0, a, ONE);
        for (c = -64; c <= FRESNEL_C_MAX_Q15_FAST; c++) {
            int32_t want = c <= 0 ? at0 : at1, s;
            if (c > 0 && c < ONE)
                continue;
            s = fresnel_schlick_q15_fast(f0, c);
            bad += s != want;
            bad += fresnel_f82_q15_fast(f0, a, c) != (c <= 0 ? g0 : g1);
        }
        for (c = INT32_MIN; c < 0; c /= 2)
            bad += fresnel_schlick_q15_fast(f0, c) != at0 || fresnel_f82_q15_fast(f0, a, c) != g0;
        {
            fresnel_rgb_q15 x3, rgb;
            x3.r = x3.g = x3.b = (fresnel_q15)f0;
            rgb = fresnel_schlick_q15_rgb_fast(x3, -1);
            bad_rgb += rgb.r != at0;
            rgb = fresnel_schlick_q15_rgb_fast(x3, ONE + 1);
            bad_rgb += rgb.g != at1;
        }
    }
    CHECK("fixed fast schlick, f82: c < 0 is c = 0, c in (one, FRESNEL_C_MAX_Q15_FAST] is c = one", bad == 0,
          "%ld differ", bad);
    CHECK("fixed fast schlick_rgb: the same at c = -1 and one + 1", bad_rgb == 0, "%ld differ", bad_rgb);
    {
        /* the exact edge: 1 - c = 2^32 - 2436 has x^4 = 1 */
        uint32_t x = 0u - 2436u, x2 = (x * x + 32767u) >> 15, x4 = (x2 * x2) >> 15;
        uint32_t y = 0u - 2435u, y2 = (y * y + 32767u) >> 15, y4 = (y2 * y2) >> 15;
        CHECK("FRESNEL_C_MAX_Q15_FAST is the last c with (1 - c)^4 = 0", y4 == 0 && x4 != 0, "x4 %u at C_MAX, %u past",
              (unsigned)y4, (unsigned)x4);
    }
}

/* F82 fast: c x^6 (Q18) over every c, and the a_q12 interval where
 * F0 2^30 - a_q12 c x^6 fits int32 (computed in int64 here): its ends are the
 * header's, one past each end overflows. At the ends, every c, F0 0 and
 * one: results in [0, one] (and UBSan checks the arithmetic). */
static void check_f82_a(void)
{
    long long mx = 0, lo, hi;
    int32_t c, f0;
    long bad = 0;
    for (c = 0; c <= FRESNEL_C_MAX_Q15_FAST; c++) {
        uint32_t x = 32768u - (uint32_t)c, x2 = (x * x + 32767u) >> 15, x4 = (x2 * x2) >> 15;
        long long cx6 = (long long)(((uint32_t)c * ((x2 * x4) >> 12)) >> 15);
        if (cx6 > mx)
            mx = cx6;
    }
    lo = -((2147483647LL - (1LL << 30)) / mx);
    hi = 2147483647LL / mx;
    NOTE("fixed fast f82: max c x^6 %lld (Q18); a_q12 in [%lld, %lld]", mx, lo, hi);
    CHECK("FRESNEL_F82_A_MIN_Q15_FAST/MAX are the exact ends of the int32-safe a_q12",
          lo == FRESNEL_F82_A_MIN_Q15_FAST && hi == FRESNEL_F82_A_MAX_Q15_FAST &&
              (1LL << 30) - (lo - 1) * mx > 2147483647LL && (hi + 1) * mx > 2147483647LL,
          "computed [%lld, %lld]", lo, hi);
    CHECK("the physical a of any F0, F82 in [0, 1] (a_q12 -38849 .. 72300) is inside",
          FRESNEL_F82_A_MIN_Q15_FAST <= -38849 && FRESNEL_F82_A_MAX_Q15_FAST >= 72300, "[%d, %d]",
          FRESNEL_F82_A_MIN_Q15_FAST, FRESNEL_F82_A_MAX_Q15_FAST);
    for (f0 = 0; f0 <= ONE; f0 += ONE)
        for (c = -2; c <= FRESNEL_C_MAX_Q15_FAST; c++) {
            bad += !in_range(fresnel_f82_q15_fast(f0, FRESNEL_F82_A_MIN_Q15_FAST, c));
            bad += !in_range(fresnel_f82_q15_fast(f0, FRESNEL_F82_A_MAX_Q15_FAST, c));
        }
    CHECK("fixed fast f82 in [0, one] at both a_q12 ends, every c", bad == 0, "%ld out of range", bad);
}

/* Every other public function at the c and parameter edges: in [0, one]. */
static void check_others(void)
{
    static const int32_t q16s[] = {INT32_MIN, -1, 0, 1, 63, FRESNEL_ETA_MIN_Q16, 65, 65535, 65536, 65537,
                                   (int32_t)32767 * 65536, INT32_MAX};
    long bad = 0;
    size_t ie, ik;
    int ic, j;
    for (ie = 0; ie < sizeof q16s / sizeof q16s[0]; ie++)
        for (ik = 0; ik < sizeof q16s / sizeof q16s[0]; ik++) {
            fresnel_ior_prep_q15 ior;
            fresnel_nk_prep_q15 nk;
            fresnel_lsk_prep_q15 lsk;
            fresnel_q15 gr, gg;
            fresnel_q16 e = q16s[ie], k = q16s[ik];
            ior = fresnel_ior_prepare_q15(e, k);
            nk = fresnel_nk_prepare_q15(e, k);
            lsk = fresnel_lsk_prepare_q15(e, k, q16s[(ie + ik) % 12], q16s[(ie * 5 + ik) % 12]);
            { fresnel_rg_q15 rg_ = fresnel_gulbrandsen_rg_q15(e, k); gr = rg_.r; gg = rg_.g; }
            bad += !in_range(gr) + !in_range(gg);
            bad += !in_range(fresnel_f0_from_ior_q15(e, k));
            bad += !in_range(fresnel_f0_in_medium_q15(cs[ik % NCS], e));
            for (ic = 0; ic < NCS; ic++) {
                int32_t c = cs[ic], v[16];
                v[0] = fresnel_conductor_q15(&ior, c);
                v[1] = fresnel_dielectric_q15(&ior, c);
                v[2] = fresnel_cook_torrance_q15(cs[ie % NCS], &ior, c);
                v[3] = fresnel_schlick_internal_q15(cs[ik % NCS], &ior, c);
                v[4] = fresnel_approx_conductor_q15(&nk, c);
                v[5] = fresnel_lsk_q15(&lsk, c);
                v[6] = fresnel_lsk_comp_q15(&lsk, c);
                v[7] = fresnel_schlick_gen_q15(cs[ie % NCS], cs[ik % NCS], e, c);
                v[8] = fresnel_schlick_q15(cs[ie % NCS], c);
                v[9] = fresnel_f82_q15(cs[ie % NCS], cs[ik % NCS], c);
                v[10] = fresnel_gulbrandsen_q15(cs[ie % NCS], cs[ik % NCS], c);
                for (j = 0; j < 11; j++)
                    bad += !in_range(v[j]);
            }
        }
    CHECK("every Q15 function in [0, one] at the int32 edges of c, codes and Q16.16 parameters", bad == 0,
          "%ld out of range", bad);
}

int main(void)
{
    check_lut_n();
    check_fast_c();
    check_f82_a();
    check_others();
    return harness_exit();
}
