/* The fast paths of fresnel_fixed.h (its "fast paths" section) against the
 * double reference, on every cos code 0..32768: results in [0, one] and
 * within the FRESNEL_BOUND_*_Q15_FAST each documents. Parameter sets:
 * Schlick, every 16th F0 code (every F0 code with FRESNEL_TEST_EXHAUSTIVE=1);
 * F82, F0 and F82 on a 1/32 grid and the (F0, F82) of every test material;
 * the LUT, the tables of test_fixed_bounds.c (exact conductor curves of
 * every 4th material, 2 to 1024 nodes uniform in sqrt(c)), against the
 * double interpolation at the exact sqrt(c). The position's square root is
 * checked on its own on every code. The maxima are printed (NOTE lines). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "1_spectral/spectral.h"
#include "fixed_materials.h"
#include "3_encode/fixed_params.h"
#include "3_encode/encode.h"
#include "fresnel_fixed.h"
#include "fresnel_fixed_fast.h"
#include "harness.h"
#include "worst.h"
#include "model/registry.h"
#include "model/reference.h"

#define ONE 32768

static void check_bound(const char *name, const worst *w, double bound, long bad_range)
{
    check_worst("fixed fast", name, w, bound, bad_range, 1);
}

static void check_schlick(void)
{
    const char *ex = getenv("FRESNEL_TEST_EXHAUSTIVE");
    int step = ex && ex[0] == '1' ? 1 : 16;
    worst w;
    long bad = 0, ends = 0;
    int32_t f0, c;
    memset(&w, 0, sizeof w);
    for (f0 = 0; f0 <= ONE; f0 += step) {
        char what[40];
        snprintf(what, sizeof what, "F0 %d", (int)f0);
        for (c = 0; c <= ONE; c++) {
            int32_t got = fresnel_schlick_q15_fast(f0, c);
            bad += got < 0 || got > ONE;
            note_worst(&w, fabs(got / 32768.0 - ref_schlick(f0 / 32768.0, c / 32768.0)) * 32768.0, what, c);
        }
        ends += fresnel_schlick_q15_fast(f0, 0) != ONE || fresnel_schlick_q15_fast(f0, ONE) != f0;
    }
    check_bound(step == 1 ? "schlick, every F0" : "schlick, every 16th F0", &w, FRESNEL_BOUND_SCHLICK_Q15_FAST,
                bad);
    CHECK("fixed fast schlick: c = 0 gives one, c = one gives F0", ends == 0, "%ld F0 codes differ", ends);
}

static void check_f82(const test_material *mat, int nmat)
{
    worst w;
    long bad = 0;
    int a, b, k;
    int32_t c;
    memset(&w, 0, sizeof w);
    for (a = 0; a <= 32; a++)
        for (b = 0; b <= 32; b++) {
            int32_t f0 = a * 1024, f82 = b * 1024;
            char what[40];
            snprintf(what, sizeof what, "F0 %d/32 F82 %d/32", a, b);
            for (c = 0; c <= ONE; c++) {
                int32_t got = fresnel_f82_q15_fast(f0, fixed_f82_a_q12(f0, f82), c);
                bad += got < 0 || got > ONE;
                note_worst(&w, fabs(got / 32768.0 - ref_f82(f0 / 32768.0, f82 / 32768.0, c / 32768.0)) * 32768.0,
                           what, c);
            }
        }
    check_bound("f82, F0/F82 on a 1/32 grid", &w, FRESNEL_BOUND_F82_Q15_FAST, bad);
    memset(&w, 0, sizeof w);
    bad = 0;
    for (k = 0; k < nmat; k++) {
        model_params mp;
        model_fixed mf;
        model_derive(mat[k].eta, mat[k].kappa, 1.0, 1.0, 5.0, &mp);
        model_params_round_fixed(&mp);
        model_fixed_from_params(&mp, &mf);
        for (c = 0; c <= ONE; c++) {
            int32_t got = fresnel_f82_q15_fast(mf.f0, fixed_f82_a_q12(mf.f0, mf.f82), c);
            bad += got < 0 || got > ONE;
            note_worst(&w, fabs(got / 32768.0 - ref_f82(mf.f0 / 32768.0, mf.f82 / 32768.0, c / 32768.0)) * 32768.0,
                       mat[k].name, c);
        }
    }
    check_bound("f82, test materials", &w, FRESNEL_BOUND_F82_Q15_FAST, bad);
    /* the ends of a_q12's domain (no F0, F82 gives them) with F0 at 0, one
     * half and one, c over every code the preconditions allow: the sum's
     * int32 range (UBSan in the sanitizer pass) and the clamp to [0, one] */
    bad = 0;
    for (a = 0; a < 2; a++)
        for (b = 0; b <= 2; b++)
            for (c = -2; c <= FRESNEL_C_MAX_Q15_FAST; c++) {
                int32_t got = fresnel_f82_q15_fast(b * (ONE / 2), a ? FRESNEL_F82_A_MAX_Q15_FAST : FRESNEL_F82_A_MIN_Q15_FAST, c);
                bad += got < 0 || got > ONE;
            }
    CHECK("fixed fast f82: a_q12 at both ends of its domain, F0 0, one half, one, every c code: results in [0, one]",
          bad == 0, "%ld results outside", bad);
}

/* The position's root on every code: |S 2^-22 - sqrt(c 2^-15)|. */
static void check_sqrt(void)
{
    double worst_e = 0.0;
    int32_t c, at = 0;
    for (c = 1; c <= ONE; c++) {
        double e = fabs(fresnel_i_fast_sqrt_q22((uint32_t)c) / 4194304.0 - sqrt(c / 32768.0));
        if (e > worst_e)
            worst_e = e, at = c;
    }
    printf("NOTE fast sqrt(c) in Q22: max|err| 2^%.2f at c %d\n", log2(worst_e), (int)at);
    CHECK("fixed fast sqrt(c) within 2^-20.7 on every code", worst_e <= ldexp(1.0, -20) / 1.6245,
          "max|err| 2^%.3f at c %d", log2(worst_e), (int)at);
}

/* n nodes of the material's exact curve at c = (i/(n-1))^2 in Q15 codes, and
 * the same codes as doubles. */
static void conductor_table(const test_material *m, int n, uint16_t *u16, double *dv)
{
    int i;
    for (i = 0; i < n; i++) {
        double x = i / (double)(n - 1);
        u16[i] = (uint16_t)floor(ref_conductor(m->eta, m->kappa, x * x) * 32768.0 + 0.5);
        dv[i] = u16[i] / 32768.0;
    }
}

static void check_lut(const test_material *mat, int nmat)
{
    static const int sizes[] = {2, 3, 5, 8, 16, 33, 64, 256, 1024};
    static double dv[1024];
    static uint16_t u16[1024];
    worst w, w64;
    long bad = 0, differ = 0, evals = 0;
    int k, is;
    memset(&w, 0, sizeof w);
    memset(&w64, 0, sizeof w64);
    for (k = 0; k < nmat; k += 4)
        for (is = 0; is < (int)(sizeof sizes / sizeof sizes[0]); is++) {
            int n = sizes[is];
            int32_t c;
            char what[64];
            conductor_table(&mat[k], n, u16, dv);
            snprintf(what, sizeof what, "%.31s n %d", mat[k].name, n);
            for (c = 0; c <= ONE; c++) {
                int32_t got = fresnel_lut_u16_q15_fast(u16, n, c);
                double err = fabs(got / 32768.0 - ref_lut(dv, n, 0, sqrt(c / 32768.0))) * 32768.0;
                bad += got < 0 || got > ONE;
                differ += got != fresnel_lut_u16_q15(u16, n, c);
                evals++;
                note_worst(&w, err, what, c);
                if (n <= 64)
                    note_worst(&w64, err, what, c);
            }
        }
    {
        static const uint16_t ramp[2] = {0, ONE};
        int32_t c;
        for (c = 0; c <= ONE; c++) {
            int32_t got = fresnel_lut_u16_q15_fast(ramp, 2, c);
            bad += got < 0 || got > ONE;
            double err = fabs(got / 32768.0 - sqrt(c / 32768.0)) * 32768.0;
            note_worst(&w, err, "ramp {0, one}", c);
            note_worst(&w64, err, "ramp {0, one}", c);
        }
    }
    printf("NOTE fast LUT differs from fresnel_lut_u16_q15 in %ld of %ld results\n", differ, evals);
    check_bound("LUT u16, sqrt(c) nodes, n <= 64", &w64, FRESNEL_BOUND_LUT_Q15_FAST, bad);
    check_bound("LUT u16, sqrt(c) nodes, n <= 1024", &w, FRESNEL_BOUND_LUT_Q15_FAST_1024, bad);
}

/* P(c) of fresnel_lut_pl_u16_q15_fast in double: the same knots and clamp,
 * no truncation. */
static double pl_position(int32_t c)
{
    int32_t x = c - (c >> 15), j = x >> 9;
    double s0 = fresnel_lut_pl_knots_q15[j], s1 = fresnel_lut_pl_knots_q15[j + 1];
    return (s0 + (s1 - s0) * (x & 511) / 512.0) / 32768.0;
}

static void check_lut_pl(const test_material *mat, int nmat)
{
    static const int sizes[] = {2, 3, 5, 8, 16, 32, 33, 64};
    static double dv[64];
    static uint16_t u16[64];
    worst w, tir;
    long bad = 0;
    int k, is, knots_ok = 1;
    memset(&w, 0, sizeof w);
    memset(&tir, 0, sizeof tir);
    for (k = 0; k <= 64; k++)
        knots_ok &= fresnel_lut_pl_knots_q15[k] == (uint16_t)floor(32768.0 * sqrt(k / 64.0) + 0.5);
    CHECK("fixed fast LUT pl: knots are round(32768 sqrt(k/64))", knots_ok, "a knot differs");
    for (k = 0; k < nmat; k += 4)
        for (is = 0; is < (int)(sizeof sizes / sizeof sizes[0]); is++) {
            int n = sizes[is];
            int32_t c;
            char what[64];
            conductor_table(&mat[k], n, u16, dv); /* any table will do for the P position */
            snprintf(what, sizeof what, "%.31s n %d", mat[k].name, n);
            for (c = 0; c <= ONE; c++) {
                int32_t got = fresnel_lut_pl_u16_q15_fast(u16, n, c);
                double err = fabs(got / 32768.0 - ref_lut(dv, n, 0, pl_position(c))) * 32768.0;
                bad += got < 0 || got > ONE;
                /* a total-reflection edge: a step of up to one between two nodes */
                note_worst(mat[k].kappa == 0.0 && mat[k].eta < 1.0 ? &tir : &w, err, what, c);
            }
        }
    {
        /* the generator's node cosines are where the runtime's position hits the nodes */
        static uint16_t ramp[32];
        double far = 0.0;
        for (k = 0; k < 32; k++)
            ramp[k] = (uint16_t)(k * 1024);
        for (k = 0; k < 32; k++) {
            double at = fresnel_lut_pl_u16_q15_fast(ramp, 32, fixed_q15(lut_node_cos(LUT_GRAZING_PL, k, 32))) / 1024.0;
            if (fabs(at - k) > far)
                far = fabs(at - k);
        }
        CHECK("fixed fast LUT pl: generator node cosines land on the runtime's nodes (within 0.02 node)", far <= 0.02,
              "%.4f node", far);
    }
    check_bound("LUT u16, grazing-pl nodes, n <= 64", &w, FRESNEL_BOUND_LUT_PL_Q15_FAST, bad);
    check_bound("LUT u16, grazing-pl nodes, n <= 64, a total-reflection edge", &tir, FRESNEL_BOUND_LUT_PL_Q15_FAST_TIR,
                bad);
}

/* fresnel_conductor_q15_fast over its documented domain: eta on a
 * geometric grid (ratio 1.06) from FRESNEL_CONDUCTOR_ETA_MIN_Q15_FAST to
 * FRESNEL_CONDUCTOR_ETA_MAX_Q15_FAST, kappa at 0, 1e-8 .. 1e-3 and 24
 * values up to FRESNEL_CONDUCTOR_KAPPA_MAX_Q15_FAST, every pair in the
 * domain (kappa >= 0.1 below FRESNEL_CONDUCTOR_ETA_MIN_DIELECTRIC_Q15_FAST,
 * |eta^2 - kappa^2 - 1 + 2i eta kappa| >= FRESNEL_CONDUCTOR_MATCH_MIN_Q15_FAST); every
 * material of data/ at every 10 nm from 380 to 780 nm; and the test
 * materials inside the domain. Every cos code, against ref_conductor at the
 * double eta, kappa the constants were made from. */
#define conductor_in_domain fixed_conductor_fast_in_domain

static void conductor_curve(worst *w, long *bad, long *n, double eta, double kappa, const char *what)
{
    fresnel_conductor_prep_q15 p;
    char where[96];
    int32_t c;
    fixed_conductor_fast(eta, kappa, &p);
    snprintf(where, sizeof where, "%.40s eta %.6g kappa %.6g", what, eta, kappa);
    for (c = 0; c <= ONE; c++) {
        int32_t got = fresnel_conductor_q15_fast(&p, c);
        *bad += got < 0 || got > ONE;
        note_worst(w, fabs(got / 32768.0 - ref_conductor(eta, kappa, c / 32768.0)) * 32768.0, where, c);
    }
    ++*n;
}

static void check_conductor(const test_material *mat, int nmat)
{
    static const double kappas[] = {0.0, 1e-8, 1e-6, 1e-4, 1e-3, 0.01, 0.05, 0.1, 0.2, 0.3, 0.5, 0.7,
                                    1.0, 1.5, 2.0, 3.0, 4.0, 5.0, 6.0, 8.0, 10.0, 12.0, 14.0, 16.0};
    static material_info info[128];
    static spectrum sp;
    worst grid, data;
    long bad = 0, ngrid = 0, ndata = 0;
    double eta;
    int i, j, nid;
    memset(&grid, 0, sizeof grid);
    memset(&data, 0, sizeof data);
    for (eta = FRESNEL_CONDUCTOR_ETA_MIN_Q15_FAST;; eta *= 1.06) {
        if (eta > FRESNEL_CONDUCTOR_ETA_MAX_Q15_FAST)
            eta = FRESNEL_CONDUCTOR_ETA_MAX_Q15_FAST;
        for (j = 0; j < (int)(sizeof kappas / sizeof kappas[0]); j++)
            if (conductor_in_domain(eta, kappas[j]))
                conductor_curve(&grid, &bad, &ngrid, eta, kappas[j], "grid");
        if (eta == FRESNEL_CONDUCTOR_ETA_MAX_Q15_FAST)
            break;
    }
    for (i = 0; i < nmat; i++)
        if (conductor_in_domain(mat[i].eta, mat[i].kappa))
            conductor_curve(&grid, &bad, &ngrid, mat[i].eta, mat[i].kappa, mat[i].name);
    nid = material_list(data_dir(NULL), info, (int)(sizeof info / sizeof info[0]));
    for (i = 0; i < nid; i++) {
        int wl;
        if (spectrum_load(data_dir(NULL), info[i].id, &sp))
            continue;
        for (wl = 380; wl <= 780; wl += 10) {
            int at = (int)((wl - SPEC_LO_NM) / SPEC_STEP_NM + 0.5);
            char what[48];
            snprintf(what, sizeof what, "%.31s %d nm", info[i].id, wl);
            if (conductor_in_domain(sp.n[at], sp.k[at]))
                conductor_curve(&data, &bad, &ndata, sp.n[at], sp.k[at], what);
        }
    }
    printf("NOTE fixed fast exact conductor: %ld grid and test materials, %ld data/ materials x wavelengths, every cos code\n",
           ngrid, ndata);
    CHECK("fixed fast exact conductor: every material of data/ loads", nid >= 10 && ndata >= 10 * 41,
          "%d materials, %ld curves", nid, ndata);
    check_bound("exact conductor, domain grid", &grid, FRESNEL_BOUND_CONDUCTOR_Q15_FAST, bad);
    check_bound("exact conductor, data/ 380-780 nm", &data, FRESNEL_BOUND_CONDUCTOR_Q15_FAST, bad);
    {
        fresnel_conductor_prep_q15 p;
        fixed_conductor_fast(1.0, 0.0, &p);
        CHECK("fixed fast exact conductor: the matched index reflects 0 at every c, c = 0 included",
              fresnel_conductor_q15_fast(&p, 0) == 0 && fresnel_conductor_q15_fast(&p, 1) == 0 &&
                  fresnel_conductor_q15_fast(&p, ONE) == 0,
              "%d %d %d", fresnel_conductor_q15_fast(&p, 0), fresnel_conductor_q15_fast(&p, 1),
              fresnel_conductor_q15_fast(&p, ONE));
    }
}

static void check_schlick_rgb(void)
{
    int32_t c, ok = 1;
    for (c = 0; c <= 32768; c++) {
        fresnel_rgb_q15 f0 = {(fresnel_q15)(c % 32769), (fresnel_q15)(32768 - c), (fresnel_q15)((c * 7) % 32769)};
        fresnel_rgb_q15 r = fresnel_schlick_q15_rgb_fast(f0, c);
        ok &= r.r == fresnel_schlick_q15_fast(f0.r, c) && r.g == fresnel_schlick_q15_fast(f0.g, c) &&
              r.b == fresnel_schlick_q15_fast(f0.b, c);
    }
    CHECK("fresnel_schlick_q15_rgb_fast equals the scalar fast path per channel", ok, "differs");
}

int main(void)
{
    static test_material mat[TM_MAX];
    int nmat = test_materials(mat);
    if (nmat <= 0) {
        CHECK("fixed test materials load from data/", 0, "spectrum_load failed");
        return harness_exit();
    }
    check_schlick();
    check_f82(mat, nmat);
    check_sqrt();
    check_lut(mat, nmat);
    check_schlick_rgb();
    check_lut_pl(mat, nmat);
    check_conductor(mat, nmat);
    return harness_exit();
}
