/* The fast paths of fresnel_fixed.h (its "fast paths" section) against the
 * double reference, on every cos code 0..32768: results in [0, one] and
 * within the FRESNEL_BOUND_*_Q15_FAST each documents. Parameter sets:
 * Schlick, every 16th F0 code (every F0 code with FRESNEL_TEST_EXHAUSTIVE=1);
 * F82, F0 and F82 on a 1/32 grid and the (F0, F82) of every test material;
 * the LUT, the tables of test_q15_bounds.c (exact conductor curves of
 * every 4th material, 2 to 1024 nodes uniform in sqrt(c)), against the
 * double interpolation at the exact sqrt(c). The position's square root is
 * checked on its own on every code. The exact conductor's sets are at
 * check_conductor and the functions after it. The maxima are printed (NOTE
 * lines). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "1_spectral/spectral.h"
#include "materials.h"
#include "3_encode/q15_params.h"
#include "3_encode/encode.h"
#include "fresnel_fixed.h"
#include "fresnel_fixed_fast.h"
#include "harness.h"
#include "worst.h"
#include "model/registry.h"
#include "common/reference.h"

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
                int32_t got = fresnel_f82_q15_fast(f0, q15_f82_a_q12(f0, f82), c);
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
        model_q15 mf;
        model_derive(mat[k].eta, mat[k].kappa, 1.0, 1.0, 5.0, &mp);
        model_params_round_q15(&mp);
        model_q15_from_params(&mp, &mf);
        for (c = 0; c <= ONE; c++) {
            int32_t got = fresnel_f82_q15_fast(mf.f0, q15_f82_a_q12(mf.f0, mf.f82), c);
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
            double at = fresnel_lut_pl_u16_q15_fast(ramp, 32, q15_code(lut_node_cos(LUT_GRAZING_PL, k, 32))) / 1024.0;
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

/* fresnel_conductor_q15_fast's helpers: the square root on every x >> 8
 * of [2^30, 2^32) (both ends of each step of 256: it reads no lower bit),
 * the reciprocal on every d of [2^15, 2^16], within the relative error the
 * header states, and their tables from the recipes it gives. */
#define FAST_HELPER_REL 2.0617e-5 /* 2^-15.6 */
static void check_conductor_helpers(void)
{
    const uint32_t nsq = sizeof fresnel_i_fast_sq / sizeof fresnel_i_fast_sq[0];
    const uint32_t nrc = sizeof fresnel_i_fast_rc / sizeof fresnel_i_fast_rc[0];
    double w = 0.0;
    uint32_t j, at = 0, bad_sq = 0, bad_rc = 0;
    for (j = 0; j < nsq; j++)
        bad_sq += fresnel_i_fast_sq[j] !=
                  (uint32_t)floor(65536.0 * sqrt(j + 64.0) + 1024.0 * pow(j + 64.0, -1.5) + 0.5) + 8u;
    for (j = 0; j < nrc; j++)
        bad_rc += fresnel_i_fast_rc[j] != (uint32_t)floor(134217728.0 / (j + 128.0) - 16777216.0 / pow(j + 128.0, 3.0) + 0.5) + 8u;
    CHECK("fixed fast conductor: the root and reciprocal tables follow their recipes (j = 64..256, 128..257)",
          nsq == 193 && nrc == 130 && bad_sq == 0 && bad_rc == 0, "%u, %u entries; %u root, %u reciprocal entries differ",
          (unsigned)nsq, (unsigned)nrc, (unsigned)bad_sq, (unsigned)bad_rc);
    for (j = 1u << 22; j < 1u << 24; j++) {
        uint32_t x = j << 8, k;
        for (k = 0; k < 2; k++, x += 255u) {
            double t = sqrt((double)x), e = fabs(fresnel_i_fast_sqrt32(x) - t) / t;
            if (e > w)
                w = e, at = x;
        }
    }
    printf("NOTE fixed fast conductor: sqrt32 max relative error 2^%.3f at %u\n", log2(w), (unsigned)at);
    CHECK("fixed fast conductor: sqrt32 within 2^-15.6 on [2^30, 2^32)", w <= FAST_HELPER_REL, "2^%.3f at %u", log2(w),
          (unsigned)at);
    w = 0.0;
    for (j = 32768; j <= (nrc > 129 ? 65536u : 65535u); j++) {
        double t = 2147483648.0 / j, e = fabs(fresnel_i_fast_recip16(j) - t) / t;
        if (e > w)
            w = e, at = j;
    }
    printf("NOTE fixed fast conductor: recip16 max relative error 2^%.3f at %u\n", log2(w), (unsigned)at);
    CHECK("fixed fast conductor: recip16 within 2^-15.6 on [2^15, 2^16]", w <= FAST_HELPER_REL, "2^%.3f at %u", log2(w),
          (unsigned)at);
}

/* fresnel_conductor_q15_fast on constants made by q15_conductor_fast, at
 * the codes lo..hi (cut to [0, one]), against ref_conductor at the double
 * eta, kappa the constants were made from. */
static void conductor_codes(worst *w, long *bad, double eta, double kappa, int32_t lo, int32_t hi, const char *what)
{
    fresnel_conductor_prep_q15_fast p;
    char where[96];
    int32_t c;
    q15_conductor_fast(eta, kappa, &p);
    snprintf(where, sizeof where, "%.36s eta %.17g kappa %.17g", what, eta, kappa);
    for (c = lo < 0 ? 0 : lo; c <= hi && c <= ONE; c++) {
        int32_t got = fresnel_conductor_q15_fast(&p, c);
        *bad += got < 0 || got > ONE;
        note_worst(w, fabs(got / 32768.0 - ref_conductor(eta, kappa, c / 32768.0)) * 32768.0, where, c);
    }
}

/* fresnel_conductor_q15_fast over its documented domain: eta on a
 * geometric grid (ratio 1.06) from FRESNEL_CONDUCTOR_ETA_MIN_Q15_FAST to
 * FRESNEL_CONDUCTOR_ETA_MAX_Q15_FAST, kappa at 0, 1e-8 .. 1e-3 and 24
 * values up to FRESNEL_CONDUCTOR_KAPPA_MAX_Q15_FAST, every pair in the
 * domain (kappa >= 0.1 below FRESNEL_CONDUCTOR_ETA_MIN_Q15_FAST_DIELECTRIC,
 * |eta^2 - kappa^2 - 1 + 2i eta kappa| >= FRESNEL_CONDUCTOR_MATCH_MIN_Q15_FAST); every
 * material of data/ at every 10 nm from 380 to 780 nm; and the test
 * materials inside the domain. Every cos code. */
#define conductor_in_domain q15_conductor_fast_in_domain

static void conductor_curve(worst *w, long *bad, long *n, double eta, double kappa, const char *what)
{
    conductor_codes(w, bad, eta, kappa, 0, ONE, what);
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
        fresnel_conductor_prep_q15_fast p;
        q15_conductor_fast(1.0, 0.0, &p);
        CHECK("fixed fast exact conductor: the matched index reflects 0 at every c, c = 0 included",
              fresnel_conductor_q15_fast(&p, 0) == 0 && fresnel_conductor_q15_fast(&p, 1) == 0 &&
                  fresnel_conductor_q15_fast(&p, ONE) == 0,
              "%d %d %d", fresnel_conductor_q15_fast(&p, 0), fresnel_conductor_q15_fast(&p, 1),
              fresnel_conductor_q15_fast(&p, ONE));
    }
}

/* Materials at the edges of the fast path's forms, every code: two whose
 * constants take one word everywhere (span 0) while a0 + c^2 is -32767 at
 * one code (4815, 25616), two conductors and three low-index dielectrics
 * near their critical angle near normal incidence. */
static void check_conductor_edges(void)
{
    static const double m[][2] = {{1.7668102256209994, 1.4640124426721695}, {6.552184082229366, 6.5225902857269098},
                                  {7.4082362219860336, 8.7293341103153441}, {4.09, 12.23},
                                  {0.072794403943372984, 1.0310499682974676e-07},
                                  {0.071556823005167636, 2.9802974677711449e-08}, {0.0703, 0.0}};
    worst w;
    long bad = 0;
    int i, in = 1;
    memset(&w, 0, sizeof w);
    for (i = 0; i < (int)(sizeof m / sizeof m[0]); i++) {
        in &= conductor_in_domain(m[i][0], m[i][1]);
        conductor_codes(&w, &bad, m[i][0], m[i][1], 0, ONE, "edge");
    }
    CHECK("fixed fast exact conductor: the edge materials lie in the domain", in, "one does not");
    check_bound("exact conductor, edge materials, every code", &w, FRESNEL_BOUND_CONDUCTOR_Q15_FAST, bad);
}

static uint64_t conductor_rng = 0x9e3779b97f4a7c15ull;
static double conductor_rnd(void) /* [0, 1), xorshift64 */
{
    conductor_rng ^= conductor_rng << 13;
    conductor_rng ^= conductor_rng >> 7;
    conductor_rng ^= conductor_rng << 17;
    return (double)(conductor_rng >> 11) * (1.0 / 9007199254740992.0);
}

/* eta for the given kappa such that A = eta^2 - kappa^2 - 1 + (c/one)^2 is
 * a 2^-30 at code c (eta^2 = 1 + kappa^2 + a 2^-30 - c^2 2^-30), or 0 when
 * no eta of the domain gives it. */
static double conductor_eta_for(double a, double kappa, int32_t c)
{
    double e2 = 1.0 + kappa * kappa + (a - (double)c * c) / 1073741824.0, eta = e2 > 0.0 ? sqrt(e2) : 0.0;
    return conductor_in_domain(eta, kappa) ? eta : 0.0;
}

/* The boundaries of the fast path's case split (fresnel_fixed_fast.h, "Why
 * every step holds"), each searched by solving for materials that put a
 * chosen code on it, the codes around it evaluated:
 * - one word or two: a0 + c^2 at -32768..-32766 and 32766..32768 at code
 *   c0, both with b large (span 0: one word however small a0 + c^2 is) and
 *   with b < 2^-15 (span 65535);
 * - two words down to A 2^46 = a0_lo in -3..3 and +-2^t (every
 *   normalisation shift, up to A = b = 0 at a dielectric's critical angle),
 *   kappa 0 or b2 in 1..3;
 * - A at +-2^-p (1 +- eps), p = -6..45: every leading-zero count of A, k
 *   across 17 (the scale r, q), the root's argument across 2^16 and 2^17;
 * - |A| = b (the two mantissas equal: their squares' sum across 2^32);
 * and c = 0 and one on each. */
static void check_conductor_boundaries(void)
{
    static const int32_t ah_at[] = {-32768, -32767, -32766, 32766, 32767, 32768};
    worst w[4];
    long bad = 0, hit[2][6], tiny = 0, pow2 = 0, carry = 0;
    int i, t, kind;
    memset(w, 0, sizeof w);
    memset(hit, 0, sizeof hit);
    for (i = 0; i < 4000; i++)
        for (kind = 0; kind < 2; kind++)
            for (t = 0; t < 6; t++) {
                int32_t c0 = 1 + (int32_t)(conductor_rnd() * 32767.0);
                double kappa = kind == 0 ? 0.001 + 0.7 * conductor_rnd()
                                         : (conductor_rnd() < 0.3 ? 0.0 : 1e-12 * pow(1e7, conductor_rnd()));
                double eta = conductor_eta_for(ah_at[t] + 0.8 * conductor_rnd() - 0.4, kappa, c0);
                fresnel_conductor_prep_q15_fast p;
                if (eta == 0.0)
                    continue;
                q15_conductor_fast(eta, kappa, &p);
                if (p.shift != 0 || p.a0 + c0 * c0 != ah_at[t] || (p.span != 0) != kind)
                    continue;
                hit[kind][t]++;
                conductor_codes(&w[0], &bad, eta, kappa, c0 - 2, c0 + 2, kind ? "span 65535, ah at the edge" : "span 0, ah at the edge");
                conductor_codes(&w[0], &bad, eta, kappa, 0, 0, "c = 0");
                conductor_codes(&w[0], &bad, eta, kappa, ONE, ONE, "c = one");
            }
    for (i = 0; i < 400; i++) {
        static const int32_t lo_at[] = {0, 1, -1, 2, -2, 3, -3, 64, -64, 4096, -4096, 32767, -32767};
        int32_t c0 = 2000 + (int32_t)(conductor_rnd() * 30500.0), b2 = (int32_t)(conductor_rnd() * 4.0);
        for (t = 0; t < (int)(sizeof lo_at / sizeof lo_at[0]); t++) {
            /* b2 = round(2 eta kappa 2^46): kappa from an estimate of eta */
            double eta0 = conductor_eta_for(lo_at[t] / 65536.0, 0.0, c0);
            double kappa = eta0 > 0.0 ? b2 / (2.0 * eta0 * 70368744177664.0) : 0.0;
            double eta = conductor_eta_for(lo_at[t] / 65536.0, kappa, c0);
            fresnel_conductor_prep_q15_fast p;
            if (eta == 0.0)
                continue;
            q15_conductor_fast(eta, kappa, &p);
            if (p.span == 0 || p.a0 + c0 * c0 != 0 || p.a0_lo != lo_at[t] || p.b2 != b2)
                continue;
            tiny++;
            conductor_codes(&w[1], &bad, eta, kappa, c0 - 2, c0 + 2, "A 2^46 tiny");
        }
    }
    for (i = 0; i < 60; i++) {
        int32_t c0 = 1 + (int32_t)(conductor_rnd() * 32767.0), pp;
        for (pp = -6; pp <= 45; pp++) {
            static const double eps[] = {-1e-3, -3e-5, -1e-9, 1e-9, 3e-5, 1e-3};
            for (t = 0; t < 12; t++) {
                double kappa = i % 3 == 0 ? 0.0 : (i % 3 == 1 ? 1e-9 : 1e-4);
                double a = (t < 6 ? 1.0 : -1.0) * ldexp(1.0 + eps[t % 6], 30 - pp);
                double eta = conductor_eta_for(a, kappa, c0);
                if (eta == 0.0)
                    continue;
                pow2++;
                conductor_codes(&w[2], &bad, eta, kappa, c0 - 2, c0 + 2, "A at a power of two");
            }
        }
    }
    for (i = 0; i < 3000; i++) {
        /* A = s b: eta^2 - kappa^2 - 1 + c^2 = 2 s eta kappa */
        int32_t c0 = 1 + (int32_t)(conductor_rnd() * 32767.0);
        double eta = 0.03 * pow(8.0 / 0.03, conductor_rnd()), cc = (double)c0 * c0 / 1073741824.0;
        double q = 2.0 * eta * eta - 1.0 + cc, kappa = q < 0.0 ? -1.0 : (i & 1 ? -eta : eta) + sqrt(q);
        if (!(kappa >= 0.0) || !conductor_in_domain(eta, kappa))
            continue;
        carry++;
        conductor_codes(&w[3], &bad, eta, kappa, c0 - 16, c0 + 16, "|A| = b");
    }
    printf("NOTE fixed fast exact conductor: a0 + c^2 at -32768..-32766, 32766..32768 with span 0: %ld %ld %ld %ld %ld %ld; "
           "with span 65535: %ld %ld %ld %ld %ld %ld; A 2^46 tiny: %ld; A at a power of two: %ld; |A| = b: %ld\n",
           hit[0][0], hit[0][1], hit[0][2], hit[0][3], hit[0][4], hit[0][5], hit[1][0], hit[1][1], hit[1][2], hit[1][3],
           hit[1][4], hit[1][5], tiny, pow2, carry);
    for (kind = 0, t = 1; kind < 2; kind++)
        for (i = 0; i < 6; i++)
            t &= hit[kind][i] >= 20;
    CHECK("fixed fast exact conductor: the search puts 20 codes or more on each edge of one and two words", t,
          "too few");
    CHECK("fixed fast exact conductor: the search reaches tiny A, powers of two and |A| = b",
          tiny >= 1000 && pow2 >= 10000 && carry >= 1000, "%ld %ld %ld", tiny, pow2, carry);
    check_bound("exact conductor, one word or two", &w[0], FRESNEL_BOUND_CONDUCTOR_Q15_FAST, bad);
    check_bound("exact conductor, A 2^46 tiny", &w[1], FRESNEL_BOUND_CONDUCTOR_Q15_FAST, bad);
    check_bound("exact conductor, A at powers of two", &w[2], FRESNEL_BOUND_CONDUCTOR_Q15_FAST, bad);
    check_bound("exact conductor, |A| = b", &w[3], FRESNEL_BOUND_CONDUCTOR_Q15_FAST, bad);
}

/* Seeded random materials of the domain (eta log-uniform; kappa 0,
 * log-uniform from 1e-9, or uniform to 16; a quarter of them low-index
 * dielectrics, eta 0.07..0.2 with kappa below 1e-4): 300 at every code,
 * then 300000 at one random code each. */
static void conductor_random_material(double *eta, double *kappa)
{
    do {
        int r = (int)(conductor_rnd() * 4.0);
        *eta = FRESNEL_CONDUCTOR_ETA_MIN_Q15_FAST *
               pow(FRESNEL_CONDUCTOR_ETA_MAX_Q15_FAST / FRESNEL_CONDUCTOR_ETA_MIN_Q15_FAST, conductor_rnd());
        if (r == 0)
            *kappa = 0.0;
        else if (r == 1)
            *kappa = 1e-9 * pow(FRESNEL_CONDUCTOR_KAPPA_MAX_Q15_FAST / 1e-9, conductor_rnd());
        else if (r == 2) {
            *eta = 0.07 + 0.13 * conductor_rnd();
            *kappa = 1e-4 * conductor_rnd();
        } else
            *kappa = FRESNEL_CONDUCTOR_KAPPA_MAX_Q15_FAST * conductor_rnd();
    } while (!conductor_in_domain(*eta, *kappa));
}

/* The largest error at codes lo..hi, and where. */
static double conductor_err(double eta, double kappa, int32_t lo, int32_t hi, int32_t *at)
{
    fresnel_conductor_prep_q15_fast p;
    double w = 0.0;
    int32_t c;
    q15_conductor_fast(eta, kappa, &p);
    for (c = lo < 0 ? 0 : lo; c <= hi && c <= ONE; c++) {
        double e = fabs(fresnel_conductor_q15_fast(&p, c) / 32768.0 - ref_conductor(eta, kappa, c / 32768.0)) * 32768.0;
        if (e > w)
            w = e, *at = c;
    }
    return w;
}

/* Then from the 8 worst of those, a local search for a larger error: eta
 * and kappa moved by a relative 1e-9 .. 1e-3 (which reshuffles every
 * mantissa's truncation), kept where the largest error within 6 codes
 * grows, 3000 steps each. */
typedef struct conductor_case {
    double eta, kappa, err;
    int32_t c;
} conductor_case;

static void conductor_keep(conductor_case *top, int n, double eta, double kappa, int32_t c, double err)
{
    int i, low = 0;
    for (i = 0; i < n; i++) {
        if (top[i].eta == eta && top[i].kappa == kappa) {
            if (err > top[i].err)
                top[i].err = err, top[i].c = c;
            return;
        }
        if (top[i].err < top[low].err)
            low = i;
    }
    if (err > top[low].err) {
        top[low].eta = eta;
        top[low].kappa = kappa;
        top[low].c = c;
        top[low].err = err;
    }
}

static void check_conductor_random(void)
{
    conductor_case top[8];
    worst w, climb;
    long bad = 0;
    int i, step;
    memset(&w, 0, sizeof w);
    memset(&climb, 0, sizeof climb);
    memset(top, 0, sizeof top);
    for (i = 0; i < 300; i++) {
        double eta, kappa, e;
        int32_t at = 0;
        conductor_random_material(&eta, &kappa);
        e = conductor_err(eta, kappa, 0, ONE, &at);
        conductor_keep(top, 8, eta, kappa, at, e);
        conductor_codes(&w, &bad, eta, kappa, 0, ONE, "random");
    }
    for (i = 0; i < 300000; i++) {
        double eta, kappa;
        int32_t c = (int32_t)(conductor_rnd() * 32769.0), at = c;
        conductor_random_material(&eta, &kappa);
        conductor_keep(top, 8, eta, kappa, c, conductor_err(eta, kappa, c, c, &at));
        conductor_codes(&w, &bad, eta, kappa, c, c, "random");
    }
    check_bound("exact conductor, random materials", &w, FRESNEL_BOUND_CONDUCTOR_Q15_FAST, bad);
    for (i = 0; i < 8; i++) {
        conductor_case best = top[i];
        for (step = 0; step < 3000; step++) {
            double scale = pow(10.0, -3.0 - 6.0 * conductor_rnd());
            double eta = best.eta * (1.0 + scale * (2.0 * conductor_rnd() - 1.0));
            double kappa = best.kappa * (1.0 + scale * (2.0 * conductor_rnd() - 1.0)), e;
            int32_t at = best.c;
            if (!conductor_in_domain(eta, kappa))
                continue;
            e = conductor_err(eta, kappa, best.c - 6, best.c + 6, &at);
            if (e > best.err) {
                best.eta = eta;
                best.kappa = kappa;
                best.c = at;
                best.err = e;
            }
        }
        conductor_codes(&climb, &bad, best.eta, best.kappa, best.c - 6, best.c + 6, "local search");
    }
    check_bound("exact conductor, local search from the worst random", &climb, FRESNEL_BOUND_CONDUCTOR_Q15_FAST, bad);
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
    check_conductor_helpers();
    check_conductor(mat, nmat);
    check_conductor_edges();
    check_conductor_boundaries();
    check_conductor_random();
    return harness_exit();
}
