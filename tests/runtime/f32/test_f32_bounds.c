/* Every binary32 model against its double reference on the dense grid
 * (tests/common/grid.h): no NaN/Inf, results in [0, 1], and the absolute error
 * within the bound fresnel.h documents for it. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "fresnel.h"
#include "grid.h"
#include "harness.h"
#include "model/registry.h"
#include "common/reference.h"

struct worst {
    double err, eta, kappa, n1, c, ref, got;
};

/* The generalized Schlick's powf path, which the model table (p = 5) does not reach. */
static void check_schlick_gen_exponents(float *cs, int nc)
{
    static const float ps[] = {0.25f, 0.5f, 1.0f, 2.0f, 3.7f, 5.0f, 8.0f, 40.0f};
    static const float f90s[] = {0.0f, 0.5f, 1.0f};
    double worst = 0.0;
    int ip, i9, i0, ic;
    for (ip = 0; ip < 8; ip++)
        for (i9 = 0; i9 < 3; i9++)
            for (i0 = 0; i0 <= 64; i0++)
                for (ic = 0; ic < nc; ic++) {
                    float f0 = (float)(i0 / 64.0);
                    float got = fresnel_schlick_gen(f0, f90s[i9], ps[ip], cs[ic]);
                    double ref = ref_schlick_gen(f0, f90s[i9], ps[ip], cs[ic]);
                    double err = fabs(got - ref);
                    if (!(err <= worst))
                        worst = err;
                }
    NOTE("schlick-gen over p in [0.25, 40], F90 in {0, 0.5, 1}: max|err| %.3g", worst);
    CHECK("schlick-gen bound, every exponent", worst <= FRESNEL_BOUND_SCHLICK_GEN, "max %.3g > %.3g",
          worst, (double)FRESNEL_BOUND_SCHLICK_GEN);
}

/* F0 helpers, outside the model table. F0 runs over 0..1 in 1/64 steps, down
 * to 1e-8 in log steps (dielectrics in a denser medium) and up to 1 - 1e-6
 * (silver-like metals); the medium's index over a 4x denser eta grid plus
 * its lower end. */
static void check_f0_helpers(void)
{
    double w_ior = 0.0, w_med = 0.0;
    int ie, ik, i0;
    for (ie = 0; ie < GRID_ETA_N; ie++)
        for (ik = 0; ik < GRID_KAPPA_N; ik++) {
            float e = (float)grid_eta(ie), k = (float)grid_kappa(ik);
            double err = fabs(fresnel_f0_from_ior(e, k) - ref_f0_from_ior(e, k));
            if (!(err <= w_ior))
                w_ior = err;
        }
    for (ie = -1; ie < 4 * GRID_ETA_N; ie++) {
        float e = ie < 0 ? FRESNEL_ETA_MIN : (float)(0.01 * pow(1e4, ie / (4.0 * GRID_ETA_N - 4.0)));
        for (i0 = 0; i0 <= 64 + 80 + 60; i0++) {
            float f0 = i0 <= 64        ? (float)(i0 / 64.0)
                       : i0 <= 64 + 80 ? (float)pow(10.0, -8.0 + (i0 - 64) / 10.0)
                                       : (float)(1.0 - pow(10.0, -6.0 + (i0 - 144) / 15.0));
            double err = fabs(fresnel_f0_in_medium(f0, e) - ref_f0_in_medium(f0, e));
            if (!(err <= w_med))
                w_med = err;
        }
    }
    NOTE("f0_from_ior max|err| %.3g, f0_in_medium max|err| %.3g", w_ior, w_med);
    {
        /* Gulbrandsen near r = 1, where n reaches 4e4 and sqrt(r) - 1 cancels */
        double w_g = 0.0;
        int ir, ig, ic;
        for (ir = 0; ir <= 200; ir++)
            for (ig = 0; ig <= 64; ig++)
                for (ic = 0; ic <= 256; ic++) {
                    float r = 0.99f + ir * 5e-7f, g = (float)(ig / 64.0), c = (float)(ic / 256.0);
                    double err = fabs(fresnel_gulbrandsen(r, g, c) - ref_gulbrandsen(r, g, c));
                    if (!(err <= w_g))
                        w_g = err;
                }
        NOTE("gulbrandsen for r in [0.99, 0.9999], every g: max|err| %.3g", w_g);
        CHECK("gulbrandsen bound near r = 1", w_g <= FRESNEL_BOUND_GULBRANDSEN, "max %.3g", w_g);
    }
    CHECK("f0_from_ior bound", w_ior <= FRESNEL_BOUND_F0_FROM_IOR, "max %.3g", w_ior);
    CHECK("f0_in_medium bound", w_med <= FRESNEL_BOUND_F0_IN_MEDIUM, "max %.3g", w_med);
}

/* fresnel_conductor_prepared and fresnel_conductor_batch (one prepared
 * material) on the same grid as the model table: every eta, kappa
 * (kappa = 0 included: the prepared form covers dielectrics too) and n1,
 * against ref_conductor. The batch runs over the whole cosine array and must
 * give exactly the prepared function's results; short batches check its
 * tail loop. */
static void check_conductor_prepared(const float *cs, int nc)
{
    static float out[2048];
    struct worst w;
    long bad_range = 0, differ = 0, count = 0;
    int ie, ik, in, ic, k;
    memset(&w, 0, sizeof w);
    for (in = 0; in < GRID_N1_N; in++)
        for (ie = 0; ie < GRID_ETA_N; ie++)
            for (ik = 0; ik < GRID_KAPPA_N; ik++) {
                float eta = (float)(grid_eta(ie) / grid_n1[in]), kappa = (float)(grid_kappa(ik) / grid_n1[in]);
                fresnel_conductor_prep p = fresnel_conductor_prepare(eta, kappa);
                fresnel_conductor_batch(&p, cs, out, nc);
                for (ic = 0; ic < nc; ic++) {
                    float got = fresnel_conductor_prepared(&p, cs[ic]);
                    double ref = ref_conductor(eta, kappa, cs[ic]);
                    double err = fabs((double)got - ref);
                    count++;
                    if (!(got >= 0.0f && got <= 1.0f))
                        bad_range++;
                    if (memcmp(&got, &out[ic], sizeof got))
                        differ++;
                    if (!(err <= w.err)) {
                        w.err = err;
                        w.eta = eta;
                        w.kappa = kappa;
                        w.n1 = grid_n1[in];
                        w.c = cs[ic];
                        w.ref = ref;
                        w.got = got;
                    }
                }
                for (k = 0; k <= 17 && ie % 8 == 0 && ik % 8 == 0; k++) {
                    int j;
                    out[k] = -1.0f;
                    fresnel_conductor_batch(&p, cs + 100, out, k);
                    for (j = 0; j < k; j++)
                        differ += out[j] != fresnel_conductor_prepared(&p, cs[100 + j]);
                    differ += out[k] != -1.0f; /* nothing written past n */
                }
            }
    printf("NOTE %-18s max|err| %.3g at eta %.4g kappa %.4g n1 %.3g c %.9g (ref %.9g got %.9g), %ld points\n",
           "conductor-prepared", w.err, w.eta, w.kappa, w.n1, w.c, w.ref, (double)w.got, count);
    CHECK("conductor-prepared and -batch: results in [0, 1]", bad_range == 0, "%ld outside or NaN", bad_range);
    CHECK("conductor-prepared and -batch bound", w.err <= FRESNEL_BOUND_CONDUCTOR_PREPARED,
          "max|err| %.3g exceeds %.3g", w.err, (double)FRESNEL_BOUND_CONDUCTOR_PREPARED);
    CHECK("conductor-batch: the prepared function's results, bit for bit, any n (tails 0..17)", differ == 0,
          "%ld differ", differ);
}


/* Deterministic uniform [0, 1) (64-bit LCG): the random part of a domain sweep. */
static double rnd(unsigned long long *st)
{
    *st = *st * 6364136223846793005ull + 1442695040888963407ull;
    return (double)(*st >> 11) / 9007199254740992.0;
}

/* log-uniform in [lo, hi] */
static double rnd_log(unsigned long long *st, double lo, double hi) { return lo * pow(hi / lo, rnd(st)); }

/* fresnel_lsk_comp over its documented region: eta in [FRESNEL_ETA_MIN,
 * FRESNEL_ETA_MAX], kappa in {0} u [1e-3, FRESNEL_KAPPA_MAX], a in [0, 200],
 * alpha in [0, FRESNEL_ALPHA_MAX], every c: random points (log-uniform
 * parameters, a and c also uniform) plus the known hard point. */
static void check_lsk_comp_domain(void)
{
    static const float hard[][5] = {{0x1.c63ed8p-7f, 0x1.1e702p-2f, 200.0f, 0x1.1b4898p+3f, 0x1.9331aep-2f}};
    unsigned long long st = 12345;
    double w = 0.0, wp[5] = {0};
    long i;
    for (i = -(long)(sizeof hard / sizeof hard[0]); i < 8000000; i++) {
        float p[5], got;
        double ref, err;
        int j;
        if (i < 0) {
            for (j = 0; j < 5; j++)
                p[j] = hard[-i - 1][j];
        } else {
            p[0] = (float)rnd_log(&st, FRESNEL_ETA_MIN, FRESNEL_ETA_MAX);
            p[1] = i % 5 == 0 ? 0.0f : (float)rnd_log(&st, 1e-3, FRESNEL_KAPPA_MAX);
            /* a = 200 with small n: the largest compensation term against
             * an LSK value near 1, where the difference keeps both errors */
            p[2] = i % 4 == 3 ? 200.0f : i % 2 ? (float)(200.0 * rnd(&st)) : (float)rnd_log(&st, 1e-3, 200.0);
            if (i % 4 == 3)
                p[0] = (float)rnd_log(&st, FRESNEL_ETA_MIN, 0.1);
            p[3] = i % 3 ? (float)rnd_log(&st, 1e-3, FRESNEL_ALPHA_MAX) : (float)(60.0 * rnd(&st));
            p[4] = i % 2 ? (float)rnd(&st) : (float)rnd_log(&st, 1e-6, 1.0);
        }
        got = fresnel_lsk_comp(p[0], p[1], p[2], p[3], p[4]);
        ref = ref_lsk_comp(p[0], p[1], p[2], p[3], p[4]);
        err = fabs((double)got - ref);
        if (!(err <= w)) {
            w = err;
            for (j = 0; j < 5; j++)
                wp[j] = p[j];
        }
    }
    NOTE("lsk-comp over its domain (a <= 200), 8e6 random points: max|err| %.3g at n %a k %a a %a alpha %a c %a", w,
         wp[0], wp[1], wp[2], wp[3], wp[4]);
    CHECK("lsk-comp bound over eta, kappa, alpha domain, a <= 200", w <= FRESNEL_BOUND_LSK_COMP, "max %.3g > %.3g", w,
          (double)FRESNEL_BOUND_LSK_COMP);
}

/* fresnel_gulbrandsen_rg's edge tint g over the whole domain: n in
 * [FRESNEL_ETA_MIN, FRESNEL_ETA_MAX], k in {0} u [1e-20, FRESNEL_KAPPA_MAX],
 * with n within 1e-12..0.5 of 1 and tiny k (r -> 0) and huge n or k
 * (r -> 1, the clamp at FRESNEL_GULBRANDSEN_R_MAX) as their own sets. */
static void check_gulbrandsen_rg_domain(void)
{
    static const float edge_n[] = {FRESNEL_ETA_MIN, 0.5f, 1.0f - 0x1p-24f, 1.0f, 1.0f + 0x1p-23f, 2.0f, 39999.0f,
                                   40000.0f, FRESNEL_ETA_MAX};
    static const float edge_k[] = {0.0f, FRESNEL_KAPPA_TINY, 1e-12f, 2.98e-9f, 1e-4f, 1.0f, 100.0f, 1e4f,
                                   FRESNEL_KAPPA_MAX};
    unsigned long long st = 777;
    double w = 0.0, wn = 0, wk = 0, r, g;
    long i;
    int a, b;
    for (i = 0; i < 4000000; i++) {
        float n, k;
        fresnel_rg o;
        switch (i % 4) {
        case 0: /* r -> 0 */
            n = (float)(1.0 + (rnd(&st) - 0.5) * pow(10.0, -12.0 * rnd(&st)));
            k = (float)rnd_log(&st, 1e-20, 1.0);
            break;
        case 1:
            n = (float)rnd_log(&st, FRESNEL_ETA_MIN, FRESNEL_ETA_MAX);
            k = (float)rnd_log(&st, 1e-20, FRESNEL_KAPPA_MAX);
            break;
        case 2:
            n = (float)rnd_log(&st, FRESNEL_ETA_MIN, FRESNEL_ETA_MAX);
            k = 0.0f;
            break;
        default: /* r -> 1 */
            n = (float)rnd_log(&st, 1.0, FRESNEL_ETA_MAX);
            k = (float)rnd_log(&st, 1.0, FRESNEL_KAPPA_MAX);
            break;
        }
        if (i < (long)(sizeof edge_n / sizeof edge_n[0] * sizeof edge_k / sizeof edge_k[0])) {
            a = (int)(i % (long)(sizeof edge_n / sizeof edge_n[0]));
            b = (int)(i / (long)(sizeof edge_n / sizeof edge_n[0]));
            n = edge_n[a];
            k = edge_k[b];
        }
        o = fresnel_gulbrandsen_rg(n, k);
        ref_gulbrandsen_rg(n, k, &r, &g);
        if (!(fabs(o.g - g) <= w)) {
            w = fabs(o.g - g);
            wn = n;
            wk = k;
        }
    }
    NOTE("gulbrandsen_rg edge tint over the domain, 4e6 points: max|g err| %.3g at n %a k %a", w, wn, wk);
    CHECK("gulbrandsen_rg: g within FRESNEL_BOUND_GULBRANDSEN_RG of the reference, r -> 0 and r -> 1 included",
          w <= FRESNEL_BOUND_GULBRANDSEN_RG, "max %.3g > %.3g", w, (double)FRESNEL_BOUND_GULBRANDSEN_RG);
}

int main(void)
{
    float cs[2048];
    int nc = grid_cos(cs, 2048);
    int mi;
    for (mi = 0; mi < model_count; mi++) {
        const model *m = &model_table[mi];
        struct worst w;
        long bad_range = 0, count = 0;
        int ie, ik, in, ic;
        memset(&w, 0, sizeof w);
        if (!m->f32->scalar) /* the thin film: tests/runtime/thin_film/test_film.c */
            continue;
        for (in = 0; in < GRID_N1_N; in++)
            for (ie = 0; ie < GRID_ETA_N; ie++)
                for (ik = 0; ik < GRID_KAPPA_N; ik++) {
                    model_params mp;
                    model_derive(grid_eta(ie), grid_kappa(ik), grid_n1[in], 1.0, 5.0, &mp);
                    model_params_round_f32(&mp);
                    for (ic = 0; ic < nc; ic++) {
                        float got = m->f32->scalar(&mp, cs[ic]);
                        double ref = m->ref->scalar(&mp, (double)cs[ic]);
                        double err = fabs((double)got - ref);
                        count++;
                        if (!(got >= 0.0f && got <= 1.0f))
                            bad_range++;
                        if (!(err <= w.err)) {
                            w.err = err;
                            w.eta = grid_eta(ie);
                            w.kappa = grid_kappa(ik);
                            w.n1 = grid_n1[in];
                            w.c = cs[ic];
                            w.ref = ref;
                            w.got = got;
                        }
                    }
                }
        printf("NOTE %-18s max|err| %.3g at eta %.4g kappa %.4g n1 %.3g c %.9g (ref %.9g got %.9g), %ld points\n",
               m->name, w.err, w.eta, w.kappa, w.n1, w.c, w.ref, (double)w.got, count);
        CHECK(m->name, bad_range == 0, "%ld results outside [0,1] or NaN", bad_range);
        CHECK(m->name, w.err <= m->bound, "max|err| %.3g exceeds the documented bound %.3g",
              w.err, (double)m->bound);
    }
    check_schlick_gen_exponents(cs, nc);
    check_f0_helpers();
    check_conductor_prepared(cs, nc);
    check_lsk_comp_domain();
    check_gulbrandsen_rg_domain();
    return harness_exit();
}
