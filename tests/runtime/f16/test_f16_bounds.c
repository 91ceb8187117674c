/* The binary16 runtime (fresnel_f16.h) against the double reference: every
 * binary16 cosine in [0, 1], the material set of tests/common/materials.h
 * (inside the binary16 domain), every model of the model table; results in
 * [0, 1] and within the documented bound. Also checks that the arithmetic
 * really is one binary16 rounding per operation. These are the numbers to
 * compare with a GPU's mediump. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fresnel_f16.h"
#include "harness.h"

#if FRESNEL_HAS_F16
#include "worst.h"
#include "f16/internal.h"
#include "materials.h"
#include "model/registry.h"
#include "common/reference.h"

#define NC 15361 /* binary16 values 0x0000 .. 0x3c00: every half in [0, 1] */

static fresnel_f16 half_from_bits(unsigned bits)
{
    union {
        unsigned short u;
        fresnel_f16 h;
    } v;
    v.u = (unsigned short)bits;
    return v.h;
}

static void check_bound(const char *name, const worst *w, double bound, long bad_range)
{
    check_worst("f16", name, w, bound, bad_range, 0);
}

static int in_f16_domain(const test_material *t)
{
    return t->eta >= FRESNEL_ETA_MIN_F16 && t->eta <= FRESNEL_ETA_MAX_F16 && t->kappa <= FRESNEL_KAPPA_MAX_F16;
}

static void check_arithmetic(void)
{
    fresnel_i_h a = fresnel_i_hc(1.0f + 1.0f / 1024.0f);
    fresnel_i_h r = fresnel_i_hsub(fresnel_i_hmul(a, a), fresnel_i_hc(1.0f));
    int i, differs = 0;
    /* (1 + 2^-10)^2 = 1 + 2^-9 + 2^-20: the square rounds to 1 + 2^-9 in
     * binary16, so the difference is 2^-9 exactly; with excess precision it
     * would keep the 2^-20. */
    CHECK("f16 helpers round each operation to binary16", (float)r == 1.0f / 512.0f, "got %.9g", (double)(float)r);
    /* and the library's Schlick differs from Schlick in float rounded once */
    for (i = 0; i < NC && !differs; i += 7) {
        fresnel_f16 c = half_from_bits((unsigned)i), f0 = fresnel_i_hc(0.04f);
        float x = 1.0f - (float)c, once = (float)f0 + (1.0f - (float)f0) * x * x * x * x * x;
        differs = (float)fresnel_schlick_f16(f0, c) != (float)(fresnel_f16)once;
    }
    CHECK("f16 Schlick is evaluated in binary16, not in float rounded once", differs, "no cosine differs");
}

/* Near a critical angle (eta < 1) binary16's rounding of eta^2 - sin^2 is
 * amplified without bound (the reflectance has an infinite slope there);
 * the second maximum leaves out cosines within 1/64 of it. */
static void check_models(const test_material *mat, int nmat)
{
    int mi, k, i;
    worst away_all;
    memset(&away_all, 0, sizeof away_all);
    for (mi = 0; mi < model_count; mi++) {
        const model *m = &model_table[mi];
        worst w, away;
        long bad = 0;
        memset(&w, 0, sizeof w);
        memset(&away, 0, sizeof away);
        if (!m->f16->scalar) /* the thin film, or no _Float16: tests/runtime/thin_film/test_film.c */
            continue;
        for (k = 0; k < nmat; k++) {
            model_params mp;
            if (!in_f16_domain(&mat[k]))
                continue;
            double ccrit;
            model_derive(mat[k].eta, mat[k].kappa, 1.0, 1.0, 5.0, &mp);
            model_params_round_f16(&mp);
            ccrit = mp.eta < 1.0 ? sqrt(1.0 - mp.eta * mp.eta) : -1.0;
            for (i = 0; i < NC; i++) {
                double c = (double)(float)half_from_bits((unsigned)i);
                double got = m->f16->scalar(&mp, c), ref = m->ref->scalar(&mp, c);
                if (!(got >= 0.0 && got <= 1.0))
                    bad++;
                note_worst(&w, fabs(got - ref), mat[k].name, c);
                if (fabs(c - ccrit) >= 1.0 / 64.0)
                    note_worst(&away, fabs(got - ref), mat[k].name, c);
            }
        }
        check_bound(m->name, &w, m->f16_bound, bad);
        printf("NOTE f16 %-20s away from critical angles: max|err| %.3e at %s\n", m->name, away.err, away.where);
        if (away.err > away_all.err)
            away_all = away;
    }
    CHECK("f16 every model at least 1/64 away from a critical angle", away_all.err <= FRESNEL_BOUND_F16_NONCRITICAL,
          "max|err| %.3e exceeds %.3e at %s", away_all.err, FRESNEL_BOUND_F16_NONCRITICAL, away_all.where);
}

static void check_schlick_gen(void)
{
    static const float ps[] = {0.25f, 0.5f, 1.0f, 2.0f, 3.7f, 8.0f, 40.0f};
    static const float f90s[] = {0.0f, 0.5f, 1.0f};
    static const float f0s[] = {0.0f, 0.04f, 0.5f, 0.95f};
    worst w;
    long bad = 0;
    size_t ip, i9, i0;
    int i;
    memset(&w, 0, sizeof w);
    for (ip = 0; ip < sizeof ps / sizeof ps[0]; ip++)
        for (i9 = 0; i9 < 3; i9++)
            for (i0 = 0; i0 < 4; i0++) {
                fresnel_f16 p = (fresnel_f16)ps[ip], f0 = (fresnel_f16)f0s[i0], f90 = (fresnel_f16)f90s[i9];
                char what[64];
                snprintf(what, sizeof what, "p %g F90 %g F0 %g", (double)ps[ip], (double)f90s[i9], (double)f0s[i0]);
                for (i = 0; i < NC; i++) {
                    fresnel_f16 c = half_from_bits((unsigned)i);
                    double got = (double)fresnel_schlick_gen_f16(f0, f90, p, c);
                    double ref = ref_schlick_gen((double)f0, (double)f90, (double)p, (double)c);
                    bad += !(got >= 0.0 && got <= 1.0);
                    note_worst(&w, fabs(got - ref), what, (double)c);
                }
            }
    check_bound("schlick-gen, every p", &w, FRESNEL_BOUND_SCHLICK_GEN_F16, bad);
}

#if defined(__SANITIZE_ADDRESS__)
#define F82_PAIR_STEP 4
#else
#define F82_PAIR_STEP 1
#endif

/* Schlick for every 3rd binary16 F0 in [0, 1] (every 48th under the
 * sanitizers; every one with FRESNEL_TEST_EXHAUSTIVE=1 in the environment,
 * 25 s) and every cosine. */
static void check_schlick_f0(void)
{
    worst w;
    long bad = 0;
    int a, i, step = 3 * F82_PAIR_STEP * F82_PAIR_STEP;
    const char *all = getenv("FRESNEL_TEST_EXHAUSTIVE");
    if (all && !strcmp(all, "1"))
        step = 1;
    memset(&w, 0, sizeof w);
    for (a = 0; a < NC; a += step) {
        fresnel_f16 f0 = half_from_bits((unsigned)a);
        char what[32];
        snprintf(what, sizeof what, "F0 %.6g", (double)f0);
        for (i = 0; i < NC; i++) {
            fresnel_f16 c = half_from_bits((unsigned)i);
            double got = (double)fresnel_schlick_f16(f0, c);
            bad += !(got >= 0.0 && got <= 1.0);
            note_worst(&w, fabs(got - ref_schlick((double)f0, (double)c)), what, (double)c);
        }
    }
    check_bound("schlick, every F0", &w, FRESNEL_BOUND_SCHLICK_F16, bad);
}

/* F82 on a 1/64 grid of (F0, F82) pairs, far apart ones included (the
 * materials only give pairs close together). The sanitizer pass, which is
 * there for memory and undefined behaviour rather than for the bound, takes
 * every fourth pair of each. */
static void check_f82_pairs(void)
{
    worst w;
    long bad = 0;
    int a, b, i;
    memset(&w, 0, sizeof w);
    for (a = 0; a <= 64; a += F82_PAIR_STEP)
        for (b = 0; b <= 64; b += F82_PAIR_STEP) {
            fresnel_f16 f0 = (fresnel_f16)(a / 64.0f), f82 = (fresnel_f16)(b / 64.0f);
            char what[48];
            snprintf(what, sizeof what, "F0 %d/64 F82 %d/64", a, b);
            for (i = 0; i < NC; i++) {
                fresnel_f16 c = half_from_bits((unsigned)i);
                double got = (double)fresnel_f82_f16(f0, f82, c), ref = ref_f82((double)f0, (double)f82, (double)c);
                bad += !(got >= 0.0 && got <= 1.0);
                note_worst(&w, fabs(got - ref), what, (double)c);
            }
        }
    check_bound("f82, every F0/F82 pair", &w, FRESNEL_BOUND_F82_F16, bad);
}

static void check_f0_helpers(void)
{
    worst wi, wm;
    long bad = 0;
    int ie, ik, i;
    memset(&wi, 0, sizeof wi);
    memset(&wm, 0, sizeof wm);
    for (ie = 0; ie < 41; ie++)
        for (ik = 0; ik < 41; ik++) {
            fresnel_f16 e = (fresnel_f16)(FRESNEL_ETA_MIN_F16 * pow(1024.0, ie / 40.0));
            fresnel_f16 k = (fresnel_f16)(ik == 0 ? 0.0 : 1e-3 * pow(16000.0, (ik - 1) / 39.0));
            double got = (double)fresnel_f0_from_ior_f16(e, k);
            bad += !(got >= 0.0 && got <= 1.0);
            note_worst(&wi, fabs(got - ref_f0_from_ior((double)e, (double)k)), "grid", 1.0);
        }
    check_bound("f0_from_ior", &wi, FRESNEL_BOUND_F0_FROM_IOR_F16, bad);
    bad = 0;
    for (ie = 0; ie < 7; ie++) {
        static const float media[] = {0.5f, 1.0f, 1.2f, 1.33f, 1.5f, 2.42f, 10.0f};
        fresnel_f16 e = (fresnel_f16)media[ie];
        for (i = 0; i < NC; i++) {
            fresnel_f16 f0 = half_from_bits((unsigned)i);
            double got = (double)fresnel_f0_in_medium_f16(f0, e);
            bad += !(got >= 0.0 && got <= 1.0);
            note_worst(&wm, fabs(got - ref_f0_in_medium((double)f0, (double)e)), "etaE", (double)f0);
        }
    }
    check_bound("f0_in_medium", &wm, FRESNEL_BOUND_F0_IN_MEDIUM_F16, bad);
}

static void check_luts(const test_material *mat, int nmat)
{
    static const int sizes[] = {2, 5, 16, 64, 256};
    static fresnel_f16 tab[256], res[256];
    static double dtab[256], dres[256];
    worst w[2];
    long bad[2] = {0, 0};
    int k, is, sp, i;
    memset(w, 0, sizeof w);
    for (k = 0; k < nmat; k += 4)
        for (is = 0; is < 5; is++)
            for (sp = 0; sp < 2; sp++) {
                int n = sizes[is];
                fresnel_f16 f0 = (fresnel_f16)ref_f0_from_ior(mat[k].eta, mat[k].kappa);
                char what[64];
                if (!in_f16_domain(&mat[k]))
                    continue;
                for (i = 0; i < n; i++) {
                    double x = i / (double)(n - 1), cn = sp == 0 ? x * x : x;
                    double gt = ref_conductor(mat[k].eta, mat[k].kappa, cn);
                    tab[i] = (fresnel_f16)gt;
                    res[i] = (fresnel_f16)(gt - ref_schlick((double)f0, cn));
                    dtab[i] = (double)tab[i];
                    dres[i] = (double)res[i];
                }
                snprintf(what, sizeof what, "%.31s n %d %s", mat[k].name, n, sp ? "linear" : "sqrt");
                for (i = 0; i < NC; i++) {
                    fresnel_f16 c = half_from_bits((unsigned)i);
                    double cd = (double)c, x = sp == 0 ? sqrt(cd) : cd, r1, r2, g1, g2;
                    g1 = (double)(sp == 0 ? fresnel_lut_f16(tab, n, c) : fresnel_lut_linear_f16(tab, n, c));
                    g2 = (double)(sp == 0 ? fresnel_lut_residual_f16(f0, res, n, c)
                                          : fresnel_lut_linear_residual_f16(f0, res, n, c));
                    r1 = ref_clamp(ref_lut(dtab, n, 0, x), 0.0, 1.0);
                    r2 = ref_clamp(ref_schlick((double)f0, cd) + ref_lut(dres, n, 0, x), 0.0, 1.0);
                    bad[sp] += !(g1 >= 0.0 && g1 <= 1.0) + !(g2 >= 0.0 && g2 <= 1.0);
                    note_worst(&w[sp], fabs(g1 - r1), what, cd);
                    note_worst(&w[sp], fabs(g2 - r2), what, cd);
                }
            }
    check_bound("LUT, sqrt(c) nodes", &w[0], FRESNEL_BOUND_LUT_F16, bad[0]);
    check_bound("LUT, linear nodes", &w[1], FRESNEL_BOUND_LUT_F16, bad[1]);
}


/* Deterministic uniform [0, 1) (64-bit LCG) for the domain sweep. */
static double rnd16(unsigned long long *st)
{
    *st = *st * 6364136223846793005ull + 1442695040888963407ull;
    return (double)(*st >> 11) / 9007199254740992.0;
}

/* A half in [lo, hi]: log-uniform, uniform, or an end, by turns. */
static fresnel_f16 rnd_half(unsigned long long *st, double lo, double hi, long i)
{
    switch (i % 5) {
    case 0: return (fresnel_f16)(lo * pow(hi / lo, rnd16(st)));
    case 1: return (fresnel_f16)(lo + (hi - lo) * rnd16(st));
    case 2: return (fresnel_f16)(i & 8 ? lo : hi);
    default: return (fresnel_f16)(lo * pow(hi / lo, rnd16(st)));
    }
}

/* Every bound over the documented binary16 domain, not the material set:
 * eta in [FRESNEL_ETA_MIN_F16, FRESNEL_ETA_MAX_F16], kappa 0 or in
 * [1e-3, FRESNEL_KAPPA_MAX_F16], F0, r, g in [0, 1], LSK a in [0, 64],
 * alpha in [1/1024, 64], F90 and F82 in [0, 1], p in [1/1024, 64], c a
 * random half in [0, 1] (subnormals included) or an end; 1e6
 * deterministic points per function, and the worst points fuzzing found.
 * The maxima are FRESNEL_DOMAIN_*_F16;
 * the exact forms and Cook-Torrance are measured for conductors
 * (kappa >= 1e-3), away from any critical angle. */
static void check_domain(void)
{
    enum { D_SCHLICK, D_SCHLICK_GEN, D_F82, D_F0, D_F0_MEDIUM, D_LSK, D_LSK_COMP, D_GULB, D_APPROX, D_COOK,
           D_COND, D_N };
    static const char *names[D_N] = {"domain schlick", "domain schlick_gen", "domain f82", "domain f0_from_ior",
                                     "domain f0_in_medium", "domain lsk", "domain lsk_comp", "domain gulbrandsen",
                                     "domain approx_conductor", "domain cook_torrance (kappa>=1e-3)",
                                     "domain conductor (kappa>=1e-3)"};
    static const double bounds[D_N] = {FRESNEL_DOMAIN_SCHLICK_F16, FRESNEL_DOMAIN_SCHLICK_GEN_F16,
                                       FRESNEL_DOMAIN_F82_F16, FRESNEL_DOMAIN_F0_FROM_IOR_F16,
                                       FRESNEL_DOMAIN_F0_IN_MEDIUM_F16, FRESNEL_DOMAIN_LSK_F16,
                                       FRESNEL_DOMAIN_LSK_COMP_F16, FRESNEL_DOMAIN_GULBRANDSEN_F16,
                                       FRESNEL_DOMAIN_APPROX_CONDUCTOR_F16, FRESNEL_DOMAIN_COOK_TORRANCE_F16,
                                       FRESNEL_DOMAIN_CONDUCTOR_F16};
    worst w[D_N];
    long bad[D_N] = {0}, i;
    unsigned long long st = 4242;
    int f;
    memset(w, 0, sizeof w);
    for (i = 0; i < 1000000; i++) {
        fresnel_f16 c = rnd_half(&st, 0x1p-24, 1.0, i + 1), e = rnd_half(&st, FRESNEL_ETA_MIN_F16, 16.0, i + 2);
        fresnel_f16 k = i % 7 == 0 ? (fresnel_f16)0.0f : rnd_half(&st, 1e-3, 16.0, i + 3);
        fresnel_f16 kc = k > (fresnel_f16)0.0f ? k : (fresnel_f16)1e-3f;
        fresnel_f16 f0 = rnd_half(&st, 1.0 / 16384.0, 1.0, i + 4), a = rnd_half(&st, 1.0 / 1024.0, 64.0, i);
        fresnel_f16 al = rnd_half(&st, 1.0 / 1024.0, 64.0, i + 1), g = rnd_half(&st, 1.0 / 16384.0, 1.0, i + 2);
        double cd = (double)c, ed = (double)e, kd = (double)k, got[D_N], ref[D_N], rn, rk;
        char what[120];
        if (i % 11 == 0)
            c = (fresnel_f16)(i & 16 ? 0.0f : 1.0f), cd = (double)c;
        if (i == 0) { /* the worst point `make fuzz` found for LSK (alpha 0: no exponent) */
            c = (fresnel_f16)0x1.e3cp-6f, e = (fresnel_f16)0x1.0a4p+0f, k = (fresnel_f16)0x1.cfp-4f;
            a = (fresnel_f16)0x1.47cp-5f, al = (fresnel_f16)0.0f;
            cd = (double)c, ed = (double)e, kd = (double)k;
        }
        if (i == 1) { /* the approximate conductor's worst: eta 2^-10, a subnormal c */
            c = (fresnel_f16)0x1.eep-17f, e = (fresnel_f16)FRESNEL_ETA_MIN_F16, k = (fresnel_f16)0.0f;
            cd = (double)c, ed = (double)e, kd = (double)k;
        }
        got[D_SCHLICK] = (double)fresnel_schlick_f16(f0, c);
        ref[D_SCHLICK] = ref_schlick((double)f0, cd);
        /* F90 and F82 as g, p as alpha: any half of their domains */
        got[D_SCHLICK_GEN] = (double)fresnel_schlick_gen_f16(f0, g, al, c);
        ref[D_SCHLICK_GEN] = ref_schlick_gen((double)f0, (double)g, (double)al, cd);
        got[D_F82] = (double)fresnel_f82_f16(f0, g, c);
        ref[D_F82] = ref_f82((double)f0, (double)g, cd);
        got[D_F0] = (double)fresnel_f0_from_ior_f16(e, k);
        ref[D_F0] = ref_f0_from_ior(ed, kd);
        got[D_F0_MEDIUM] = (double)fresnel_f0_in_medium_f16(f0, e);
        ref[D_F0_MEDIUM] = ref_f0_in_medium((double)f0, ed);
        got[D_LSK] = (double)fresnel_lsk_f16(e, k, c);
        ref[D_LSK] = ref_lsk(ed, kd, cd);
        got[D_LSK_COMP] = (double)fresnel_lsk_comp_f16(e, k, a, al, c);
        ref[D_LSK_COMP] = ref_lsk_comp(ed, kd, (double)a, (double)al, cd);
        got[D_GULB] = (double)fresnel_gulbrandsen_f16(f0, g, c);
        {
            double r = (double)f0 < 1.0 - 1.0 / 2048.0 ? (double)f0 : 1.0 - 1.0 / 2048.0;
            ref_gulbrandsen_nk(r, (double)g, &rn, &rk);
            ref[D_GULB] = ref_approx_conductor(rn < FRESNEL_ETA_MIN_F16 ? FRESNEL_ETA_MIN_F16 : rn > 16.0 ? 16.0 : rn,
                                               rk > 16.0 ? 16.0 : rk, cd);
        }
        got[D_APPROX] = (double)fresnel_approx_conductor_f16(e, k, c);
        ref[D_APPROX] = ref_approx_conductor(ed, kd, cd);
        got[D_COOK] = (double)fresnel_cook_torrance_f16(f0, e, kc, c);
        ref[D_COOK] = ref_cook_torrance((double)f0, ed, (double)kc, cd);
        got[D_COND] = (double)fresnel_conductor_f16(e, kc, c);
        ref[D_COND] = ref_conductor(ed, (double)kc, cd);
        snprintf(what, sizeof what, "eta %a kappa %a f0 %a a %a alpha %a g %a", ed, kd, (double)f0, (double)a,
                 (double)al, (double)g);
        for (f = 0; f < D_N; f++) {
            bad[f] += !(got[f] >= 0.0 && got[f] <= 1.0);
            note_worst(&w[f], fabs(got[f] - ref[f]), what, cd);
        }
    }
    for (f = 0; f < D_N; f++)
        check_bound(names[f], &w[f], bounds[f], bad[f]);
}

/* The LUTs over their documented domain: every n from 2 to
 * FRESNEL_LUT_N_MAX_F16 (log-uniform, and both ends), curve tables with
 * nodes anywhere in [0, 2] (random, a zigzag between the ends, or a
 * conductor's or a dielectric's exact curve, total reflection included)
 * and residual tables in [-1, 1] (random, a zigzag, or a curve less
 * Schlick at its F0); 400 random half cosines
 * and the ends per table, 3000 tables. Against the same interpolation in
 * double at the table's values, clamped as the runtime clamps. */
static void check_lut_domain(void)
{
    static fresnel_f16 tab[FRESNEL_LUT_N_MAX_F16], res[FRESNEL_LUT_N_MAX_F16];
    static double dtab[FRESNEL_LUT_N_MAX_F16], dres[FRESNEL_LUT_N_MAX_F16];
    worst w[3];
    long bad[3] = {0, 0, 0};
    unsigned long long st = 1717;
    int it, i, j, sp;
    memset(w, 0, sizeof w);
    for (it = 0; it < 3000; it++) {
        int n = it % 10 == 0 ? 2 : it % 10 == 1 ? FRESNEL_LUT_N_MAX_F16
                                                : 2 + (int)((FRESNEL_LUT_N_MAX_F16 - 2) * pow(rnd16(&st), 2.0));
        /* 0 random, 1 conductor, 2 dielectric (total reflection for eta < 1), 3 random to 2, 4 a zigzag
         * between 0 and 2 - 2^-10 (residual: -1 and 1), the steepest table */
        int kind = it % 5;
        double eta = 1.0 / 64.0 * pow(1024.0, rnd16(&st)), kappa = kind == 2 ? 0.0 : 1e-3 * pow(16000.0, rnd16(&st));
        double f0 = ref_f0_from_ior(eta, kappa);
        fresnel_f16 hf0 = (fresnel_f16)f0;
        char what[96];
        sp = it & 1; /* nodes uniform in sqrt(c) or in c */
        for (i = 0; i < n; i++) {
            double u = i / (double)(n - 1), cn = sp == 0 ? u * u : u, curve, r;
            curve = kind == 0 ? rnd16(&st) : kind == 3 ? 2.0 * rnd16(&st) : kind == 4 ? (i & 1) * (2.0 - 0x1p-10)
                                                                                  : ref_conductor(eta, kappa, cn);
            r = kind == 0 || kind == 3 ? 2.0 * rnd16(&st) - 1.0 : kind == 4 ? (i & 1) * 2.0 - 1.0
                                                                                : curve - ref_schlick((double)hf0, cn);
            tab[i] = (fresnel_f16)curve;
            res[i] = (fresnel_f16)r;
            dtab[i] = (double)tab[i];
            dres[i] = (double)res[i];
        }
        snprintf(what, sizeof what, "%s table n %d, %s, eta %.4g kappa %.4g",
                 kind == 4 ? "zigzag" : kind == 0 || kind == 3 ? "random" : "curve",
                 n, sp ? "linear" : "sqrt", eta, kappa);
        for (j = 0; j < 402; j++) {
            fresnel_f16 c = j < 2 ? (fresnel_f16)(float)j : (fresnel_f16)rnd16(&st);
            double cd = (double)c, x = sp == 0 ? sqrt(cd) : cd, pos = x * (n - 1), got[3], ref[3], top;
            int k = (int)pos < n - 1 ? (int)pos : n - 2, f;
            top = dtab[k] > dtab[k + 1] ? dtab[k] : dtab[k + 1];
            top = top > 1.0 ? top : 1.0;
            got[0] = (double)(sp == 0 ? fresnel_lut_f16(tab, n, c) : fresnel_lut_linear_f16(tab, n, c));
            ref[0] = ref_clamp(ref_lut(dtab, n, 0, x), 0.0, top);
            got[1] = (double)(sp == 0 ? fresnel_lut_residual_f16(hf0, res, n, c)
                                      : fresnel_lut_linear_residual_f16(hf0, res, n, c));
            ref[1] = ref_clamp(ref_schlick((double)hf0, cd) + ref_lut(dres, n, 0, x), 0.0, 1.0);
            got[2] = 0.0, ref[2] = 0.0;
            if (sp == 0) {
                got[2] = (double)fresnel_lut_cubic_f16(tab, n, c);
                ref[2] = ref_clamp(ref_lut(dtab, n, 1, x), 0.0, top);
            }
            for (f = 0; f < 3; f++) {
                bad[f] += !(got[f] >= 0.0 && got[f] <= (f == 1 ? 1.0 : top));
                note_worst(&w[f], fabs(got[f] - ref[f]), what, cd);
            }
        }
    }
    check_bound("domain lut, lut_linear", &w[0], FRESNEL_DOMAIN_LUT_F16, bad[0]);
    check_bound("domain lut_residual, lut_linear_residual", &w[1], FRESNEL_DOMAIN_LUT_RESIDUAL_F16, bad[1]);
    check_bound("domain lut_cubic", &w[2], FRESNEL_DOMAIN_LUT_CUBIC_F16, bad[2]);
}

int main(void)
{
    static test_material mat[TM_MAX];
    int nmat = test_materials(mat);
    if (nmat <= 0) {
        CHECK("f16 test materials load from data/", 0, "spectrum_load failed");
        return harness_exit();
    }
    check_arithmetic();
    check_models(mat, nmat);
    check_schlick_gen();
    check_schlick_f0();
    check_f82_pairs();
    check_f0_helpers();
    check_luts(mat, nmat);
    check_domain();
    check_lut_domain();
    return harness_exit();
}

#else
int main(void)
{
    NOTE("no _Float16 in this compiler: the binary16 runtime is not built");
    return harness_exit();
}
#endif
