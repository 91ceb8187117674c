/* The fixed-point runtime (fresnel_fixed.h) against the double reference:
 * every cos code 0..32768, every material of tests/common/materials.h, every
 * model of the model table; results within [0, one] and within the bound
 * the header documents. Built from range-checked copies of the fixed-point
 * sources (Makefile: FRESNEL_RANGE_CHECK), so every FRESNEL_I_RANGE of the range
 * analysis is checked on all of these inputs as well; under the sanitizer
 * pass, UBSan checks the signed arithmetic. */
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "materials.h"
#include "3_encode/q15_params.h"
#include "fresnel.h"
#include "fresnel_fixed.h"
#define FRESNEL_RANGE_CHECK /* the inline helpers in this file check too */
#include "q15/internal.h"
#include "harness.h"
#include "worst.h"
#include "model/registry.h"
#include "common/reference.h"

#define ONE 32768

static long range_failures;
static char range_first[160];

/* Called by FRESNEL_I_RANGE in the range-checked fixed-point objects. */
void fresnel_i_range_fail(const char *what, long long value);
void fresnel_i_range_fail(const char *what, long long value)
{
    if (range_failures++ == 0)
        snprintf(range_first, sizeof range_first, "%s = %lld", what, value);
}

static void check_bound(const char *name, const worst *w, double bound, long bad_range)
{
    check_worst("fixed", name, w, bound, bad_range, 1);
}

/* Every model of the table, every material, every code. */
static void check_models(const test_material *mat, int nmat)
{
    int mi, k;
    for (mi = 0; mi < model_count; mi++) {
        const model *m = &model_table[mi];
        worst w;
        long bad = 0;
        memset(&w, 0, sizeof w);
        if (!m->q15->scalar) /* the thin film: tests/runtime/thin_film/test_film.c */
            continue;
        for (k = 0; k < nmat; k++) {
            model_params mp;
            model_q15 mf;
            int32_t c;
            model_derive(mat[k].eta, mat[k].kappa, 1.0, 1.0, 5.0, &mp);
            model_params_round_q15(&mp);
            model_q15_from_params(&mp, &mf);
            for (c = 0; c <= ONE; c++) {
                int32_t got = m->q15->scalar(&mf, c);
                double ref = m->ref->scalar(&mp, c / 32768.0);
                if (got < 0 || got > ONE)
                    bad++;
                note_worst(&w, fabs(got / 32768.0 - ref) * 32768.0, mat[k].name, c / 32768.0);
            }
        }
        check_bound(m->name, &w, m->q15_bound, bad);
    }
}

/* Generalized Schlick away from p = 5 (the table only has p = 5). */
static void check_schlick_gen(void)
{
    static const double ps[] = {0.001, 0.25, 0.5, 1.0, 2.0, 3.7, 5.0, 8.0, 40.0, 1000.0};
    static const int32_t f90s[] = {0, 16384, ONE};
    static const int32_t f0s[] = {0, 1311, 16384, 31130, ONE};
    double worst64 = 0.0;
    worst w;
    long bad = 0;
    size_t ip, i9, i0;
    int32_t c;
    memset(&w, 0, sizeof w);
    for (ip = 0; ip < sizeof ps / sizeof ps[0]; ip++)
        for (i9 = 0; i9 < 3; i9++)
            for (i0 = 0; i0 < 5; i0++) {
                fresnel_q16 p = q16_code(ps[ip]);
                char what[64];
                snprintf(what, sizeof what, "p %g F90 %d F0 %d", ps[ip], (int)f90s[i9], (int)f0s[i0]);
                for (c = 0; c <= ONE; c++) {
                    int32_t got = fresnel_schlick_gen_q15(f0s[i0], f90s[i9], p, c);
                    double ref = ref_schlick_gen(f0s[i0] / 32768.0, f90s[i9] / 32768.0, p / 65536.0, c / 32768.0);
                    double err = fabs(got / 32768.0 - ref) * 32768.0;
                    bad += got < 0 || got > ONE;
                    note_worst(&w, err, what, c / 32768.0);
                    if (ps[ip] <= 64.0 && err > worst64)
                        worst64 = err;
                }
            }
    check_bound("schlick-gen, every p", &w, FRESNEL_BOUND_SCHLICK_GEN_Q15, bad);
    CHECK("fixed schlick-gen within 0.501 LSB for p <= 64", worst64 <= 0.501, "max|err| %.5f LSB", worst64);
    /* large exponents, where (1-c)^p is ten squarings: 500 p in (64, 1000],
     * the cosines where (1-c)^p is not negligible (c < 1/4) */
    memset(&w, 0, sizeof w);
    bad = 0;
    for (ip = 0; ip < 500; ip++) {
        fresnel_q16 p = (fresnel_q16)(64 * 65536 + (int32_t)((ip * 2654435761u) % (936u * 65536u)));
        char what[64];
        snprintf(what, sizeof what, "p %.5f", p / 65536.0);
        for (i9 = 0; i9 < 3; i9 += 2)
            for (c = 0; c <= 8192; c++) {
                int32_t got = fresnel_schlick_gen_q15(0, f90s[i9], p, c);
                double ref = ref_schlick_gen(0.0, f90s[i9] / 32768.0, p / 65536.0, c / 32768.0);
                bad += got < 0 || got > ONE;
                note_worst(&w, fabs(got / 32768.0 - ref) * 32768.0, what, c / 32768.0);
            }
    }
    check_bound("schlick-gen, p in (64, 1000]", &w, FRESNEL_BOUND_SCHLICK_GEN_Q15, bad);
}

/* Schlick for F0 on a 1/256 grid, every cos code. */
static void check_schlick_f0(void)
{
    worst w;
    long bad = 0;
    int a;
    int32_t c;
    memset(&w, 0, sizeof w);
    for (a = 0; a <= 256; a++)
        for (c = 0; c <= ONE; c++) {
            int32_t got = fresnel_schlick_q15(a * 128, c);
            bad += got < 0 || got > ONE;
            note_worst(&w, fabs(got / 32768.0 - ref_schlick(a / 256.0, c / 32768.0)) * 32768.0, "F0 grid", c / 32768.0);
        }
    check_bound("schlick, every F0", &w, FRESNEL_BOUND_SCHLICK_Q15, bad);
}

/* F82 on a 1/16 grid of (F0, F82) pairs, far apart ones included (the
 * materials only give pairs close together), every cos code. */
static void check_f82_pairs(void)
{
    worst w;
    long bad = 0;
    int a, b;
    int32_t c;
    memset(&w, 0, sizeof w);
    for (a = 0; a <= 16; a++)
        for (b = 0; b <= 16; b++) {
            int32_t f0 = a * 2048, f82 = b * 2048;
            char what[40];
            snprintf(what, sizeof what, "F0 %d/16 F82 %d/16", a, b);
            for (c = 0; c <= ONE; c++) {
                int32_t got = fresnel_f82_q15(f0, f82, c);
                bad += got < 0 || got > ONE;
                note_worst(&w, fabs(got / 32768.0 - ref_f82(f0 / 32768.0, f82 / 32768.0, c / 32768.0)) * 32768.0, what,
                           c / 32768.0);
            }
        }
    check_bound("f82, every F0/F82 pair", &w, FRESNEL_BOUND_F82_Q15, bad);
}

/* The F0 helpers: from Q16.16 eta, kappa on the float test grid, and the
 * medium adjustment for every F0 code. */
static void check_f0_helpers(void)
{
    static const double media[] = {0.5, 1.0, 1.2, 1.33, 1.5, 2.42, 10.0};
    worst w_ior, w_med;
    long bad = 0;
    int ie, ik;
    size_t im;
    int32_t f0;
    memset(&w_ior, 0, sizeof w_ior);
    memset(&w_med, 0, sizeof w_med);
    for (ie = 0; ie < 49; ie++)
        for (ik = 0; ik < 43; ik++) {
            fresnel_q16 e = q16_code(0.01 * pow(1e4, ie / 48.0));
            fresnel_q16 k = q16_code(ik == 0 ? 0.0 : 1e-3 * pow(1e5, (ik - 1) / 41.0));
            int32_t got = fresnel_f0_from_ior_q15(e, k);
            bad += got < 0 || got > ONE;
            note_worst(&w_ior, fabs(got / 32768.0 - ref_f0_from_ior(e / 65536.0, k / 65536.0)) * 32768.0, "grid", 1.0);
        }
    check_bound("f0_from_ior", &w_ior, FRESNEL_BOUND_F0_FROM_IOR_Q15, bad);
    bad = 0;
    for (im = 0; im < sizeof media / sizeof media[0]; im++) {
        fresnel_q16 e = q16_code(media[im]);
        char what[32];
        snprintf(what, sizeof what, "etaE %g F0", media[im]);
        for (f0 = 0; f0 <= ONE; f0++) {
            int32_t got = fresnel_f0_in_medium_q15(f0, e);
            bad += got < 0 || got > ONE;
            note_worst(&w_med, fabs(got / 32768.0 - ref_f0_in_medium(f0 / 32768.0, e / 65536.0)) * 32768.0, what,
                       f0 / 32768.0);
        }
    }
    check_bound("f0_in_medium", &w_med, FRESNEL_BOUND_F0_IN_MEDIUM_Q15, bad);
}

/* The layout of fresnel_fixed.h: shift in [0, 30], |a0| + 2^(30-shift) <=
 * 2^31 - 1 (a0 + c^2 fits int32), |a0_lo| <= 2^29. */
static int ior_layout_ok(const fresnel_ior_prep_q15 *m)
{
    return m->shift >= 0 && m->shift <= 30 &&
           fabs((double)m->a0) + ldexp(1.0, 30 - m->shift) <= 2147483647.0 && abs(m->a0_lo) <= (1 << 29);
}

/* The run-time *_prepare functions from Q16.16 against the host's
 * preparation from the same Q16.16 values in double: the two sets of
 * constants must give results within one code of each other. */
static void check_prepare(const test_material *mat, int nmat)
{
    int k, worst_ior = 0, worst_nk = 0, worst_lsk = 0, worst_g = 0, worst_r = 0, layout_bad = 0;
    for (k = 0; k < nmat; k++) {
        fresnel_q16 e = q16_code(mat[k].eta), kk = q16_code(mat[k].kappa);
        double ed = e / 65536.0, kd = kk / 65536.0, a, alpha, r, g;
        fresnel_ior_prep_q15 ri, hi;
        fresnel_nk_prep_q15 rn, hn;
        fresnel_lsk_prep_q15 rl, hl;
        fresnel_q15 gr, gg;
        int32_t c;
        if (e < FRESNEL_ETA_MIN_Q16)
            continue;
        ref_lsk_fit(ed, kd, &a, &alpha);
        ri = fresnel_ior_prepare_q15(e, kk);
        q15_ior(ed, kd, &hi);
        layout_bad += !ior_layout_ok(&ri) + !ior_layout_ok(&hi);
        {
            fresnel_ior_prep_q15 dm;
            q15_ior(mat[k].eta, mat[k].kappa, &dm);
            layout_bad += !ior_layout_ok(&dm);
        }
        rn = fresnel_nk_prepare_q15(e, kk);
        q15_nk(ed, kd, &hn);
        rl = fresnel_lsk_prepare_q15(e, kk, q16_code(a), q16_code(alpha));
        q15_lsk(ed, kd, q16_code(a) / 65536.0, q16_code(alpha) / 65536.0, &hl);
        for (c = 0; c <= ONE; c += 7) {
            int d1 = abs(fresnel_conductor_q15(&ri, c) - fresnel_conductor_q15(&hi, c));
            int d2 = abs(fresnel_approx_conductor_q15(&rn, c) - fresnel_approx_conductor_q15(&hn, c));
            int d3 = abs(fresnel_lsk_comp_q15(&rl, c) - fresnel_lsk_comp_q15(&hl, c));
            if (d1 > worst_ior)
                worst_ior = d1;
            if (d2 > worst_nk)
                worst_nk = d2;
            if (d3 > worst_lsk)
                worst_lsk = d3;
        }
        { fresnel_rg_q15 rg_ = fresnel_gulbrandsen_rg_q15(e, kk); gr = rg_.r; gg = rg_.g; }
        ref_gulbrandsen_rg(ed, kd, &r, &g);
        if (abs((int)gr - q15_code(r)) > worst_r)
            worst_r = abs((int)gr - q15_code(r));
        if (abs((int)gg - q15_code(g)) > worst_g)
            worst_g = abs((int)gg - q15_code(g));
    }
    NOTE("prepare from Q16.16 vs host: ior %d, nk %d, lsk %d codes; gulbrandsen_rg r %d g %d codes",
         worst_ior, worst_nk, worst_lsk, worst_r, worst_g);
    CHECK("fresnel_ior_prepare_q15 matches the host preparation", worst_ior <= 1, "%d codes", worst_ior);
    CHECK("prepared a0, a0_lo, shift keep the layout (a0 + c^2 fits int32), host and run time", layout_bad == 0,
          "%d structs break it", layout_bad);
    CHECK("fresnel_nk_prepare_q15 matches the host preparation", worst_nk <= 1, "%d codes", worst_nk);
    CHECK("fresnel_lsk_prepare_q15 matches the host preparation", worst_lsk <= 1, "%d codes", worst_lsk);
    CHECK("fresnel_gulbrandsen_rg_q15 within one code of the reference", worst_r <= 1 && worst_g <= 1,
          "r %d g %d codes", worst_r, worst_g);
}

/* RGB forms are the scalar ones per channel; Gulbrandsen's per-call mapping
 * equals the prepared one; the clamping policy of the arguments. */
static void check_variants(const test_material *mat, int nmat)
{
    long mismatch = 0, clamp_bad = 0;
    int k;
    static const int32_t odd_c[] = {INT32_MIN, -1, ONE + 1, 65535, INT32_MAX};
    for (k = 0; k + 2 < nmat; k += 3) {
        fresnel_ior_prep_q15 ior[3];
        fresnel_nk_prep_q15 nk[3];
        fresnel_lsk_prep_q15 lsk[3];
        fresnel_rgb_q15 f0, f82, r, g, o;
        int32_t c;
        int j;
        model_params mp[3];
        for (j = 0; j < 3; j++) {
            model_derive(mat[k + j].eta, mat[k + j].kappa, 1.0, 1.0, 5.0, &mp[j]);
            q15_ior(mp[j].eta, mp[j].kappa, &ior[j]);
            q15_nk(mp[j].eta, mp[j].kappa, &nk[j]);
            q15_lsk(mp[j].eta, mp[j].kappa, mp[j].a, mp[j].alpha, &lsk[j]);
        }
        f0.r = (fresnel_q15)q15_code(mp[0].f0), f0.g = (fresnel_q15)q15_code(mp[1].f0), f0.b = (fresnel_q15)q15_code(mp[2].f0);
        f82.r = (fresnel_q15)q15_code(mp[0].f82), f82.g = (fresnel_q15)q15_code(mp[1].f82), f82.b = (fresnel_q15)q15_code(mp[2].f82);
        r.r = (fresnel_q15)q15_code(mp[0].r), r.g = (fresnel_q15)q15_code(mp[1].r), r.b = (fresnel_q15)q15_code(mp[2].r);
        g.r = (fresnel_q15)q15_code(mp[0].g), g.g = (fresnel_q15)q15_code(mp[1].g), g.b = (fresnel_q15)q15_code(mp[2].g);
        for (c = 0; c <= ONE; c += 97) {
            fresnel_nk_prep_q15 gnk;
#define SAME3(rgb, fr, fg, fb) mismatch += (rgb).r != (fr) || (rgb).g != (fg) || (rgb).b != (fb)
            o = fresnel_schlick_q15_rgb(f0, c);
            SAME3(o, fresnel_schlick_q15(f0.r, c), fresnel_schlick_q15(f0.g, c), fresnel_schlick_q15(f0.b, c));
            o = fresnel_schlick_gen_q15_rgb(f0, f82, 7 << 16, c);
            SAME3(o, fresnel_schlick_gen_q15(f0.r, f82.r, 7 << 16, c), fresnel_schlick_gen_q15(f0.g, f82.g, 7 << 16, c),
                  fresnel_schlick_gen_q15(f0.b, f82.b, 7 << 16, c));
            o = fresnel_schlick_internal_q15_rgb(f0, &ior[0], c);
            SAME3(o, fresnel_schlick_internal_q15(f0.r, &ior[0], c), fresnel_schlick_internal_q15(f0.g, &ior[0], c),
                  fresnel_schlick_internal_q15(f0.b, &ior[0], c));
            o = fresnel_lsk_q15_rgb(lsk, c);
            SAME3(o, fresnel_lsk_q15(&lsk[0], c), fresnel_lsk_q15(&lsk[1], c), fresnel_lsk_q15(&lsk[2], c));
            o = fresnel_lsk_comp_q15_rgb(lsk, c);
            SAME3(o, fresnel_lsk_comp_q15(&lsk[0], c), fresnel_lsk_comp_q15(&lsk[1], c), fresnel_lsk_comp_q15(&lsk[2], c));
            o = fresnel_f82_q15_rgb(f0, f82, c);
            SAME3(o, fresnel_f82_q15(f0.r, f82.r, c), fresnel_f82_q15(f0.g, f82.g, c), fresnel_f82_q15(f0.b, f82.b, c));
            o = fresnel_gulbrandsen_q15_rgb(r, g, c);
            SAME3(o, fresnel_gulbrandsen_q15(r.r, g.r, c), fresnel_gulbrandsen_q15(r.g, g.g, c),
                  fresnel_gulbrandsen_q15(r.b, g.b, c));
            gnk = fresnel_gulbrandsen_nk_q15(r.r, g.r);
            mismatch += fresnel_gulbrandsen_q15(r.r, g.r, c) != fresnel_approx_conductor_q15(&gnk, c);
            o = fresnel_approx_conductor_q15_rgb(nk, c);
            SAME3(o, fresnel_approx_conductor_q15(&nk[0], c), fresnel_approx_conductor_q15(&nk[1], c),
                  fresnel_approx_conductor_q15(&nk[2], c));
            o = fresnel_cook_torrance_q15_rgb(f0, &ior[1], c);
            SAME3(o, fresnel_cook_torrance_q15(f0.r, &ior[1], c), fresnel_cook_torrance_q15(f0.g, &ior[1], c),
                  fresnel_cook_torrance_q15(f0.b, &ior[1], c));
            o = fresnel_conductor_q15_rgb(ior, c);
            SAME3(o, fresnel_conductor_q15(&ior[0], c), fresnel_conductor_q15(&ior[1], c), fresnel_conductor_q15(&ior[2], c));
        }
        /* arguments outside [0, one] behave as the nearest end */
        for (j = 0; j < 5; j++) {
            int32_t cc = odd_c[j] < 0 ? 0 : ONE;
            clamp_bad += fresnel_schlick_q15(f0.r, odd_c[j]) != fresnel_schlick_q15(f0.r, cc);
            clamp_bad += fresnel_conductor_q15(&ior[0], odd_c[j]) != fresnel_conductor_q15(&ior[0], cc);
            clamp_bad += fresnel_f82_q15(f0.r, f82.r, odd_c[j]) != fresnel_f82_q15(f0.r, f82.r, cc);
            clamp_bad += fresnel_schlick_q15(odd_c[j], 1000) != fresnel_schlick_q15(cc, 1000);
            clamp_bad += fresnel_f82_q15(odd_c[j], odd_c[4 - j], 5000) > ONE;
        }
    }
    CHECK("fixed RGB forms equal the scalar forms per channel; gulbrandsen_q15 equals the prepared n, k",
          mismatch == 0, "%ld mismatches", mismatch);
    CHECK("fixed arguments outside [0, one] evaluate as the nearest end", clamp_bad == 0, "%ld", clamp_bad);
}

/* ------------------------------------------------------------------ LUTs */

static double sat_unit(double x) { return x < 0.0 ? 0.0 : (x > 1.0 ? 1.0 : x); }

/* Tables of the exact curve of a material, encoded the four ways, both
 * spacings; the reference interpolates the decoded table in double at the
 * same c. */
static void check_luts(const test_material *mat, int nmat)
{
    static const int sizes[] = {2, 3, 5, 8, 16, 33, 64, 256, 1024};
    static double dv[4][1024], rv[1024];
    static uint16_t u16[1024 * 3];
    static uint8_t u8[1024 * 3];
    static int16_t s16[1024 * 3];
    static int8_t s8[1024 * 3];
    worst w[2];
    long bad[2] = {0, 0}, rgb_mismatch = 0;
    int k, is, sp;
    memset(w, 0, sizeof w);
    for (k = 0; k < nmat; k += 4)
        for (is = 0; is < (int)(sizeof sizes / sizeof sizes[0]); is++)
            for (sp = 0; sp < 2; sp++) {
                int n = sizes[is], i, f16b = 15, f8b = 7;
                double f0d = ref_f0_from_ior(mat[k].eta, mat[k].kappa), maxr = 0.0;
                int32_t f0 = q15_code(f0d), c;
                char what[96];
                /* nodes: uniform in sqrt(c) (c = x^2), or in c */
                for (i = 0; i < n; i++) {
                    double x = i / (double)(n - 1);
                    double cn = sp == 0 ? x * x : x;
                    double gt = ref_conductor(mat[k].eta, mat[k].kappa, cn);
                    double res = gt - ref_schlick(f0 / 32768.0, cn);
                    u16[i] = (uint16_t)floor(gt * 32768.0 + 0.5);
                    u8[i] = (uint8_t)floor(gt * 255.0 + 0.5);
                    rv[i] = res;
                    if (fabs(res) > maxr)
                        maxr = fabs(res);
                }
                while (f16b < 30 && maxr * ldexp(1.0, f16b + 1) <= 32767.0)
                    f16b++;
                while (f8b < 22 && maxr * ldexp(1.0, f8b + 1) <= 127.0)
                    f8b++;
                for (i = 0; i < n; i++) {
                    s16[i] = (int16_t)floor(rv[i] * ldexp(1.0, f16b) + 0.5);
                    s8[i] = (int8_t)floor(rv[i] * ldexp(1.0, f8b) + 0.5);
                    dv[0][i] = u16[i] / 32768.0;
                    dv[1][i] = u8[i] / 255.0;
                    dv[2][i] = ldexp(s16[i], -f16b);
                    dv[3][i] = ldexp(s8[i], -f8b);
                }
                /* RGB copies: the same curve three times, the result per channel must match */
                memcpy(u16 + n, u16, n * sizeof *u16), memcpy(u16 + 2 * n, u16, n * sizeof *u16);
                memcpy(u8 + n, u8, n), memcpy(u8 + 2 * n, u8, n);
                memcpy(s16 + n, s16, n * sizeof *s16), memcpy(s16 + 2 * n, s16, n * sizeof *s16);
                memcpy(s8 + n, s8, n), memcpy(s8 + 2 * n, s8, n);
                for (c = 0; c <= ONE; c++) {
                    double cd = c / 32768.0, x = sp == 0 ? sqrt(cd) : cd;
                    double sch = ref_schlick(f0 / 32768.0, cd), ref;
                    int32_t got[4];
                    int e;
                    if (sp == 0) {
                        got[0] = fresnel_lut_u16_q15(u16, n, c);
                        got[1] = fresnel_lut_u8_q15(u8, n, c);
                        got[2] = fresnel_lut_residual_s16_q15(f0, s16, n, f16b, c);
                        got[3] = fresnel_lut_residual_s8_q15(f0, s8, n, f8b, c);
                    } else {
                        got[0] = fresnel_lut_linear_u16_q15(u16, n, c);
                        got[1] = fresnel_lut_linear_u8_q15(u8, n, c);
                        got[2] = fresnel_lut_linear_residual_s16_q15(f0, s16, n, f16b, c);
                        got[3] = fresnel_lut_linear_residual_s8_q15(f0, s8, n, f8b, c);
                    }
                    for (e = 0; e < 4; e++) {
                        ref = sat_unit(ref_lut(dv[e], n, 0, x) + (e >= 2 ? sch : 0.0));
                        double err = fabs(got[e] / 32768.0 - ref) * 32768.0;
                        bad[sp] += got[e] < 0 || got[e] > ONE;
                        if (err > w[sp].err) {
                            snprintf(what, sizeof what, "%.31s n %d %s %s", mat[k].name, n, sp ? "linear" : "sqrt",
                                     e == 0 ? "u16" : e == 1 ? "u8" : e == 2 ? "s16" : "s8");
                            note_worst(&w[sp], err, what, cd);
                        }
                    }
                    if ((c & 255) == 0) {
                        fresnel_rgb_q15 f0rgb, o;
                        f0rgb.r = f0rgb.g = f0rgb.b = (fresnel_q15)f0;
                        o = sp == 0 ? fresnel_lut_u16_q15_rgb(u16, n, c) : fresnel_lut_linear_u16_q15_rgb(u16, n, c);
                        rgb_mismatch += o.r != got[0] || o.g != got[0] || o.b != got[0];
                        o = sp == 0 ? fresnel_lut_u8_q15_rgb(u8, n, c) : fresnel_lut_linear_u8_q15_rgb(u8, n, c);
                        rgb_mismatch += o.r != got[1] || o.g != got[1] || o.b != got[1];
                        o = sp == 0 ? fresnel_lut_residual_s16_q15_rgb(f0rgb, s16, n, f16b, c)
                                    : fresnel_lut_linear_residual_s16_q15_rgb(f0rgb, s16, n, f16b, c);
                        rgb_mismatch += o.r != got[2] || o.g != got[2] || o.b != got[2];
                        o = sp == 0 ? fresnel_lut_residual_s8_q15_rgb(f0rgb, s8, n, f8b, c)
                                    : fresnel_lut_linear_residual_s8_q15_rgb(f0rgb, s8, n, f8b, c);
                        rgb_mismatch += o.r != got[3] || o.g != got[3] || o.b != got[3];
                    }
                }
            }
    /* The position's square root is exact before its one rounding: on the
     * two-node table {0, one} the result is sqrt(c) rounded to a code. */
    {
        static const uint16_t ramp[2] = {0, ONE};
        long off = 0;
        int32_t c;
        for (c = 0; c <= ONE; c++)
            off += fresnel_lut_u16_q15(ramp, 2, c) != (int32_t)floor(sqrt(c / 32768.0) * 32768.0 + 0.5);
        CHECK("fixed LUT on {0, one} is round(sqrt(c) 2^15) for every code", off == 0, "%ld codes differ", off);
    }
    check_bound("LUT (u16 u8 s16 s8), nodes uniform in sqrt(c)", &w[0], FRESNEL_BOUND_LUT_Q15, bad[0]);
    check_bound("LUT (u16 u8 s16 s8), nodes uniform in c", &w[1], FRESNEL_BOUND_LUT_Q15, bad[1]);
    CHECK("fixed LUT RGB forms equal the scalar forms", rgb_mismatch == 0, "%ld mismatches", rgb_mismatch);
}

/* The bottom of the eta domain is the same number in the Q16.16 API
 * (FRESNEL_ETA_MIN_Q16 codes) and in the double reference (FRESNEL_ETA_MIN):
 * eta codes from below the domain (clamped by both) through 1e-3 and a
 * little beyond, prepared at run time, against the reference at the same
 * eta, every 3rd cos code and the last 64. */
static void check_eta_min(void)
{
    static const int32_t codes[] = {INT32_MIN, -1, 0, 1, 32, 63, 64, 65, 66, 67, 70, 80, 100, 131};
    worst w, wd, wf;
    long bad = 0;
    size_t i;
    memset(&w, 0, sizeof w);
    memset(&wd, 0, sizeof wd);
    memset(&wf, 0, sizeof wf);
    CHECK("FRESNEL_ETA_MIN_Q16 is FRESNEL_ETA_MIN in Q16.16", FRESNEL_ETA_MIN_Q16 / 65536.0 == (double)FRESNEL_ETA_MIN,
          "%.9g vs %.9g", FRESNEL_ETA_MIN_Q16 / 65536.0, (double)FRESNEL_ETA_MIN);
    for (i = 0; i < sizeof codes / sizeof codes[0]; i++) {
        static const double kappas[] = {0.0, 1e-3, 0.5};
        double eta = codes[i] / 65536.0;
        char what[48];
        int ik;
        for (ik = 0; ik < 3; ik++) {
            fresnel_ior_prep_q15 m;
            fresnel_q16 kq = q16_code(kappas[ik]);
            int32_t c, f0 = fresnel_f0_from_ior_q15(codes[i], kq);
            snprintf(what, sizeof what, "eta code %ld kappa %g", (long)codes[i], kappas[ik]);
            m = fresnel_ior_prepare_q15(codes[i], kq);
            bad += f0 < 0 || f0 > ONE;
            note_worst(&wf, fabs(f0 / 32768.0 - ref_f0_from_ior(eta, kq / 65536.0)) * 32768.0, what, 1.0);
            for (c = 0; c <= ONE; c += (c >= ONE - 64) ? 1 : 3) {
                int32_t got = fresnel_conductor_q15(&m, c);
                bad += got < 0 || got > ONE;
                note_worst(&w, fabs(got / 32768.0 - ref_conductor(eta, kq / 65536.0, c / 32768.0)) * 32768.0, what,
                           c / 32768.0);
                if (ik == 0) {
                    got = fresnel_dielectric_q15(&m, c);
                    bad += got < 0 || got > ONE;
                    note_worst(&wd, fabs(got / 32768.0 - ref_dielectric(eta, c / 32768.0)) * 32768.0, what,
                               c / 32768.0);
                }
            }
        }
    }
    check_bound("conductor, eta at and below the domain's bottom (Q16.16 prepare)", &w, FRESNEL_BOUND_CONDUCTOR_Q15, bad);
    check_bound("dielectric, eta at and below the domain's bottom (Q16.16 prepare)", &wd, FRESNEL_BOUND_DIELECTRIC_Q15,
                0);
    check_bound("f0_from_ior, eta at and below the domain's bottom", &wf, FRESNEL_BOUND_F0_FROM_IOR_Q15, 0);
}

/* fresnel_ior_prepare_q15 where eta^2 - kappa^2 - 1 crosses a power of
 * two (the shift's choice, and a quotient that rounds up past 32 bits):
 * eta and kappa codes 2^j + d, d in [-3, 3], j up to 30, each with kappa (or
 * eta) 0, 2^-10, 1 and 2, against the reference at the same Q16.16 values,
 * cos codes 0, 1, every 97th and the last 16. */
static void check_prepare_powers(void)
{
    static const int32_t others[] = {0, 64, 65536, 131072};
    worst w;
    long bad = 0, layout_bad = 0;
    int j, d, which;
    size_t io;
    memset(&w, 0, sizeof w);
    for (j = 6; j <= 30; j++)
        for (d = -3; d <= 3; d++)
            for (io = 0; io < 4; io++)
                for (which = 0; which < 2; which++) {
                    int64_t v = ((int64_t)1 << j) + d;
                    int32_t code = v > INT32_MAX ? INT32_MAX : (int32_t)v;
                    int32_t e = which ? others[io] : code, k = which ? code : others[io], c;
                    fresnel_ior_prep_q15 m;
                    char what[48];
                    double ed = (e < FRESNEL_ETA_MIN_Q16 ? FRESNEL_ETA_MIN_Q16 : e) / 65536.0, kd = k / 65536.0;
                    if (ed > 32767.0 || kd > 32767.0)
                        continue;
                    snprintf(what, sizeof what, "eta code %ld kappa code %ld", (long)e, (long)k);
                    m = fresnel_ior_prepare_q15(e, k);
                    layout_bad += !ior_layout_ok(&m);
                    for (c = 0; c <= ONE; c += (c < 1 || c >= ONE - 16) ? 1 : 97) {
                        int32_t got = fresnel_conductor_q15(&m, c);
                        bad += got < 0 || got > ONE;
                        note_worst(&w, fabs(got / 32768.0 - ref_conductor(ed, kd, c / 32768.0)) * 32768.0, what,
                                   c / 32768.0);
                    }
                }
    check_bound("conductor, Q16.16 prepare at powers of two of eta, kappa", &w, FRESNEL_BOUND_CONDUCTOR_Q15, bad);
    CHECK("fresnel_ior_prepare_q15 keeps the layout at powers of two", layout_bad == 0, "%ld break it", layout_bad);
}

/* eta -> 0 near normal incidence, where eta^2 at the prepared scale is a
 * small number: 4000 eta in [FRESNEL_ETA_MIN, 0.05], the 512 codes below one. */
static void check_small_eta(const model *m)
{
    worst w;
    long bad = 0;
    int k;
    memset(&w, 0, sizeof w);
    for (k = 0; k < 4000; k++) {
        model_params mp;
        model_q15 mf;
        int32_t c;
        char name[32];
        double eta = FRESNEL_ETA_MIN * pow(0.05 / FRESNEL_ETA_MIN, k / 3999.0);
        snprintf(name, sizeof name, "eta %.6g", eta);
        model_derive(eta, 0.0, 1.0, 1.0, 5.0, &mp);
        model_params_round_q15(&mp);
        model_q15_from_params(&mp, &mf);
        for (c = ONE - 511; c <= ONE; c++) {
            int32_t got = m->q15->scalar(&mf, c);
            bad += got < 0 || got > ONE;
            note_worst(&w, fabs(got / 32768.0 - m->ref->scalar(&mp, c / 32768.0)) * 32768.0, name, c / 32768.0);
        }
    }
    check_bound("exact-dielectric, eta -> 0 near normal incidence", &w, m->q15_bound, bad);
}

/* The documented domain beyond the test materials: eta log-uniform over
 * [FRESNEL_ETA_MIN, 32767] (the Q16.16 domain of *_prepare; dense toward eta -> 0, where eta^2
 * has few bits at the prepared scale), kappa 0 and log-uniform over
 * [1e-4, 32767], every 5th cos code and every code within 64 of
 * 0 and of one (normal incidence: c -> 1), every model against the bound
 * its table row documents. */
static void check_domain(void)
{
    const double Q15_ETA_MAX = 32767.0;
    enum { NGRID = 160, NSMALL = 48, NRAND = 96 };
    int mi, k;
    uint32_t seed = 12345u;
    static test_material t[NGRID + NSMALL + NRAND];
    int n = 0;
    for (k = 0; k < NGRID; k++, n++) {
        t[n].eta = FRESNEL_ETA_MIN * pow(Q15_ETA_MAX / FRESNEL_ETA_MIN, k / (NGRID - 1.0));
        t[n].kappa = 0.0;
    }
    for (k = 0; k < NSMALL; k++, n++) { /* [1/1024, 0.05], kappa 0 or small */
        t[n].eta = FRESNEL_ETA_MIN * pow(0.05 / FRESNEL_ETA_MIN, k / (NSMALL - 1.0));
        t[n].kappa = (k & 1) ? 0.0 : 1e-3 * (k + 1);
    }
    for (k = 0; k < NRAND; k++, n++) {
        double u, v;
        seed = seed * 1664525u + 1013904223u;
        u = (seed >> 8) / 16777216.0;
        seed = seed * 1664525u + 1013904223u;
        v = (seed >> 8) / 16777216.0;
        t[n].eta = FRESNEL_ETA_MIN * pow(Q15_ETA_MAX / FRESNEL_ETA_MIN, u);
        t[n].kappa = 1e-4 * pow(Q15_ETA_MAX / 1e-4, v);
    }
    for (mi = 0; mi < model_count; mi++)
        if (!strcmp(model_table[mi].name, "exact-dielectric"))
            check_small_eta(&model_table[mi]);
    for (k = 0; k < n; k++)
        snprintf(t[k].name, sizeof t[k].name, "eta %.6g k %.3g", t[k].eta, t[k].kappa);
    for (mi = 0; mi < model_count; mi++) {
        const model *m = &model_table[mi];
        worst w;
        long bad = 0;
        char what[96];
        memset(&w, 0, sizeof w);
        if (!m->q15->scalar) /* the thin film: tests/runtime/thin_film/test_film.c */
            continue;
        for (k = 0; k < n; k++) {
            model_params mp;
            model_q15 mf;
            int32_t c;
            model_derive(t[k].eta, t[k].kappa, 1.0, 1.0, 5.0, &mp);
            model_params_round_q15(&mp);
            model_q15_from_params(&mp, &mf);
            for (c = 0; c <= ONE; c += (c < 64 || c >= ONE - 64) ? 1 : 5) {
                int32_t got = m->q15->scalar(&mf, c);
                double ref = m->ref->scalar(&mp, c / 32768.0);
                if (got < 0 || got > ONE)
                    bad++;
                note_worst(&w, fabs(got / 32768.0 - ref) * 32768.0, t[k].name, c / 32768.0);
            }
        }
        snprintf(what, sizeof what, "%s over the eta, kappa domain", m->name);
        check_bound(what, &w, m->q15_bound, bad);
    }
}

int main(void)
{
    static test_material mat[TM_MAX];
    int nmat = test_materials(mat);
    if (nmat <= 0) {
        CHECK("fixed test materials load from data/", 0, "spectrum_load failed");
        return harness_exit();
    }
    NOTE("fixed-point bounds over %d materials x 32769 cos codes", nmat);
    check_models(mat, nmat);
    check_domain();
    check_eta_min();
    check_prepare_powers();
    check_schlick_gen();
    check_schlick_f0();
    check_f82_pairs();
    check_f0_helpers();
    check_prepare(mat, nmat);
    check_variants(mat, nmat);
    check_luts(mat, nmat);
    CHECK("every intermediate inside the range its FRESNEL_I_RANGE states", range_failures == 0,
          "%ld violations, first: %s", range_failures, range_first);
    /* and the checks do fire: a product outside fresnel_i_mul_q30's domain */
    {
        volatile uint32_t big = 1u << 31;
        long before = range_failures;
        (void)fresnel_i_mul_q30(big, 5u);
        CHECK("FRESNEL_I_RANGE reports an argument outside its stated range", range_failures == before + 1,
              "%ld reports", range_failures - before);
    }
    return harness_exit();
}
