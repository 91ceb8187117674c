/* Every model of the model table (gen/model/registry.h) in every number
 * type, held to its stated bound by a search for the worst case
 * (tests/common/search.h) over the domain the header states, not over a grid or
 * a material set:
 *   binary32 (fresnel.h CONVENTIONS): eta in [0.01, 100], kappa 0 or in
 *     [1e-3, 1000], an incident medium n1 in [1, 2.42] (the grid's media),
 *     every c; bound FRESNEL_BOUND_<MODEL>;
 *   Q1.15 (fresnel_fixed.h ERROR BOUNDS): eta in [2^-10, 32767], kappa 0
 *     or in [1e-9, 32767], every cos code; FRESNEL_BOUND_<MODEL>_Q15 (LSB);
 *   binary16 (fresnel_f16.h): eta in [2^-10, 16], kappa 0 or in [1e-3,
 *     16], every binary16 c; FRESNEL_DOMAIN_<MODEL>_F16 (the rows whose
 *     domain bound is 1, the exact forms at a dielectric's critical angle,
 *     are held to their range only).
 * eta and kappa are searched in log10 (a kappa below the range's low end
 * stands for 0: a twelfth of the box), the parameters derived from them
 * as the generator derives them (model_derive) and rounded to the type.
 * And the binary32 functions outside the table, each over its bound's
 * domain: fresnel_f0_from_ior, fresnel_f0_in_medium (F0 from 1e-8 to
 * 1 - 1e-6), fresnel_gulbrandsen_rg's g (the whole eta, kappa domain),
 * fresnel_conductor_prepared; and in binary16 fresnel_f0_from_ior_f16 and
 * fresnel_f0_in_medium_f16 over the binary16 domain (FRESNEL_DOMAIN_*_F16).
 * Sweeps first: the matched index (where the error peaks in a narrow
 * band), and in the long pass the whole grid of tests/runtime/f32/test_f32_bounds.c.
 * Results outside [0, 1] count as an infinite error. The corpus
 * (tests/data/worst_inputs/models.txt) replays the worst points of the long
 * pass (SEARCH_LONG=1, make search). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "fresnel.h"
#include "fresnel_f16.h"
#include "fresnel_fixed.h"
#include "harness.h"
#include "grid.h"
#include "search.h"
#include "model/registry.h"
#include "common/reference.h"

#define CORPUS "tests/data/worst_inputs/models.txt"

enum { T_F32, T_Q15, T_F16 };
static const char *const type_key[] = {"f32", "q15", "f16"};

typedef struct model_case {
    const model *m;
    int type;
    double kappa_lo; /* log10 of the smallest non-zero kappa */
} model_case;

static double kappa_of(const model_case *k, double x)
{
    return x < k->kappa_lo ? 0.0 : pow(10.0, x);
}

/* x: log10 eta, log10 kappa (or below: 0), c (Q1.15: its code), n1 (binary32 only) */
static double model_error(void *ctx, const double *x)
{
    const model_case *k = ctx;
    model_params mp;
    double eta = pow(10.0, x[0]), kappa = kappa_of(k, x[1]);
    if (k->type == T_F32) {
        float c = (float)x[2], got;
        model_derive(eta, kappa, x[3], 1.0, 5.0, &mp);
        model_params_round_f32(&mp);
        got = k->m->f32->scalar(&mp, c);
        if (!(got >= 0.0f && got <= 1.0f))
            return HUGE_VAL;
        return fabs((double)got - k->m->ref->scalar(&mp, c));
    }
    if (k->type == T_Q15) {
        model_q15 mf;
        int32_t c = (int32_t)x[2], got;
        model_derive(eta, kappa, 1.0, 1.0, 5.0, &mp);
        model_params_round_q15(&mp);
        model_q15_from_params(&mp, &mf);
        got = k->m->q15->scalar(&mf, c);
        if (got < 0 || got > 32768)
            return HUGE_VAL;
        return fabs(got / 32768.0 - k->m->ref->scalar(&mp, c / 32768.0)) * 32768.0;
    }
#if FRESNEL_HAS_F16
    {
        double c = (double)(fresnel_f16)x[2], got;
        model_derive(eta, kappa, 1.0, 1.0, 5.0, &mp);
        model_params_round_f16(&mp);
        got = k->m->f16->scalar(&mp, c);
        if (!(got >= 0.0 && got <= 1.0))
            return HUGE_VAL;
        return fabs(got - k->m->ref->scalar(&mp, c));
    }
#else
    return 0.0;
#endif
}

/* The binary16 bound over the whole domain, by the row's function; 0: none
 * below 1 (held to its range only). */
static double f16_domain_bound(const model *m)
{
    static const struct {
        const char *name;
        double bound;
    } b[] = {{"schlick", FRESNEL_DOMAIN_SCHLICK_F16},
             {"schlick-gen", FRESNEL_DOMAIN_SCHLICK_GEN_F16},
             {"lsk", FRESNEL_DOMAIN_LSK_F16},
             {"lsk-comp", FRESNEL_DOMAIN_LSK_COMP_F16},
             {"f82", FRESNEL_DOMAIN_F82_F16},
             {"gulbrandsen", FRESNEL_DOMAIN_GULBRANDSEN_F16},
             {"approx-conductor", FRESNEL_DOMAIN_APPROX_CONDUCTOR_F16}};
    size_t i;
    for (i = 0; i < sizeof b / sizeof b[0]; i++)
        if (!strcmp(m->name, b[i].name))
            return b[i].bound;
    return 0.0;
}

/* ---- the binary32 functions outside the model table, each over the
 * domain of its bound (fresnel.h) */

static double pow10_or_zero(double x, double lo) { return x < lo ? 0.0 : pow(10.0, x); }

/* x: log10 eta in [-2, 2], log10 kappa in [-3.5, 3] (below -3: 0) */
static double f0_from_ior_error(void *ctx, const double *x)
{
    float e = (float)pow(10.0, x[0]), k = (float)pow10_or_zero(x[1], -3.0);
    (void)ctx;
    return fabs((double)fresnel_f0_from_ior(e, k) - ref_f0_from_ior(e, k));
}

/* x: F0 = 10^x0 for x0 <= 0, 1 - 10^-x0 above (F0 from 1e-8 to 1 - 1e-6),
 * log10 eta_e in [log10 FRESNEL_ETA_MIN, 2] */
static double f0_in_medium_error(void *ctx, const double *x)
{
    float f0 = (float)(x[0] <= 0.0 ? pow(10.0, x[0]) : 1.0 - pow(10.0, -x[0])), e = (float)pow(10.0, x[1]);
    float got = fresnel_f0_in_medium(f0, e);
    (void)ctx;
    return got >= 0.0f && got <= 1.0f ? fabs((double)got - ref_f0_in_medium(f0, e)) : HUGE_VAL;
}

/* g of Gulbrandsen's inverse over the whole domain: log10 n in
 * [log10 FRESNEL_ETA_MIN, 5], log10 k in [-20, 5] (below -19: 0) */
static double gulbrandsen_rg_error(void *ctx, const double *x)
{
    float n = (float)pow(10.0, x[0]), k = (float)pow10_or_zero(x[1], -19.0);
    fresnel_rg o = fresnel_gulbrandsen_rg(n, k);
    double r, g;
    (void)ctx;
    ref_gulbrandsen_rg(n, k, &r, &g);
    return fabs((double)o.g - g);
}

/* fresnel_conductor_prepared, as the exact model: log10 eta, log10 kappa
 * relative to an incident n1 in [1, 2.42], c */
static double conductor_prepared_error(void *ctx, const double *x)
{
    float eta = (float)(pow(10.0, x[0]) / x[3]), kappa = (float)(pow10_or_zero(x[1], -3.0) / x[3]), c = (float)x[2];
    fresnel_conductor_prep p = fresnel_conductor_prepare(eta, kappa);
    float got = fresnel_conductor_prepared(&p, c);
    (void)ctx;
    return got >= 0.0f && got <= 1.0f ? fabs((double)got - ref_conductor(eta, kappa, c)) : HUGE_VAL;
}

#if FRESNEL_HAS_F16
/* The binary16 helpers over the binary16 domain: x as above, rounded to halves */
static double f0_from_ior_f16_error(void *ctx, const double *x)
{
    fresnel_f16 e = (fresnel_f16)pow(10.0, x[0]), k = (fresnel_f16)pow10_or_zero(x[1], -3.0);
    double got = (double)fresnel_f0_from_ior_f16(e, k);
    (void)ctx;
    return got >= 0.0 && got <= 1.0 ? fabs(got - ref_f0_from_ior((double)e, (double)k)) : HUGE_VAL;
}

static double f0_in_medium_f16_error(void *ctx, const double *x)
{
    fresnel_f16 f0 = (fresnel_f16)(x[0] <= 0.0 ? pow(10.0, x[0]) : 1.0 - pow(10.0, -x[0]));
    fresnel_f16 e = (fresnel_f16)pow(10.0, x[1]);
    double got = (double)fresnel_f0_in_medium_f16(f0, e);
    (void)ctx;
    return got >= 0.0 && got <= 1.0 ? fabs(got - ref_f0_in_medium((double)f0, (double)e)) : HUGE_VAL;
}
#endif

static void search_helpers(int longpass)
{
    static const struct {
        const char *name;
        search_error_fn *fn;
        int dims;
        double lo[SEARCH_DIMS], hi[SEARCH_DIMS];
        double bound;
    } h[] = {{"f0_from_ior", f0_from_ior_error, 2, {-2.0, -3.5}, {2.0, 3.0}, FRESNEL_BOUND_F0_FROM_IOR},
             {"f0_in_medium", f0_in_medium_error, 2, {-8.0, -3.0103}, {6.0, 2.0}, FRESNEL_BOUND_F0_IN_MEDIUM},
             {"gulbrandsen_rg", gulbrandsen_rg_error, 2, {-3.0103, -20.0}, {5.0, 5.0}, FRESNEL_BOUND_GULBRANDSEN_RG},
             {"conductor_prepared", conductor_prepared_error, 4, {-2.0, -3.5, 0.0, 1.0}, {2.0, 3.0, 1.0, 2.42},
              FRESNEL_BOUND_CONDUCTOR_PREPARED},
#if FRESNEL_HAS_F16
             /* binary16: eta in [2^-10, 16], kappa 0 or in [1e-3, 16]; F0 from 2^-14 */
             {"f16 f0_from_ior", f0_from_ior_f16_error, 2, {-3.0103, -3.4}, {1.2041, 1.2041},
              FRESNEL_DOMAIN_F0_FROM_IOR_F16},
             {"f16 f0_in_medium", f0_in_medium_f16_error, 2, {-4.2144, -3.0103}, {3.0, 1.2041},
              FRESNEL_DOMAIN_F0_IN_MEDIUM_F16},
#endif
    };
    size_t i;
    for (i = 0; i < sizeof h / sizeof h[0]; i++) {
        search_space sp;
        search_state s;
        char key[64], label[160];
        int d;
        memset(&sp, 0, sizeof sp);
        sp.dims = h[i].dims;
        for (d = 0; d < sp.dims; d++)
            sp.lo[d] = h[i].lo[d], sp.hi[d] = h[i].hi[d];
        search_init(&s, &sp, h[i].fn, NULL, 0x4E1Fu + (uint64_t)i);
        snprintf(key, sizeof key, "%s%s", strncmp(h[i].name, "f16 ", 4) ? "f32:" : "f16:",
                 strncmp(h[i].name, "f16 ", 4) ? h[i].name : h[i].name + 4);
        search_corpus(&s, CORPUS, key);
        search_random(&s, longpass ? 2000000 : 60000);
        search_climb(&s, longpass ? 12 : 6, 48);
        search_corpus_write(&s, key, 3);
        printf("NOTE search %-6s %-18s max|err| %.4g at", strncmp(h[i].name, "f16 ", 4) ? "f32" : "f16",
               strncmp(h[i].name, "f16 ", 4) ? h[i].name : h[i].name + 4, s.top[0].err);
        for (d = 0; d < sp.dims; d++)
            printf(" %.9g", s.top[0].x[d]);
        printf(" (search coordinates), %ld evaluations\n", s.evals);
        snprintf(label, sizeof label, "%s%s: within the stated bound (searched)",
                 strncmp(h[i].name, "f16 ", 4) ? "f32 " : "", h[i].name);
        CHECK(label, s.top[0].err <= h[i].bound, "max|err| %.4g, bound %.4g", s.top[0].err, h[i].bound);
    }
}

/* Near the matched index (eta = n1, small kappa) the reflectance is the
 * ratio of small differences and the error peaks in a narrow band the
 * random points rarely reach: relative eta 1 +- 1e-4..0.2, kappa 0 and
 * 1e-3..0.1, 64 cosines, each incident medium of the box's corners. */
static void matched_index_sweep(search_state *s, int type)
{
    static const double n1s[] = {1.0, 1.33, 1.5, 2.42};
    int in, id, ik, ic;
    for (in = 0; in < (type == T_F32 ? 4 : 1); in++)
        for (id = 0; id < 16; id++)
            for (ik = 0; ik < 5; ik++)
                for (ic = 0; ic <= 64; ic++) {
                    double x[SEARCH_DIMS], rel = 1.0 + (id % 2 ? -1.0 : 1.0) * 1e-4 * pow(2000.0, (id / 2) / 7.0);
                    double kappa_log[] = {-99.0, -3.0, -2.5, -2.0, -1.0};
                    x[0] = log10(rel * n1s[in]);
                    x[1] = kappa_log[ik] < -10.0 ? s->sp.lo[1] : kappa_log[ik];
                    x[2] = ic / 64.0 * s->sp.hi[2];
                    x[3] = n1s[in];
                    search_eval(s, x);
                }
}

/* The long pass starts from the whole grid of tests/runtime/f32/test_f32_bounds.c
 * (tests/common/grid.h: 8.7 million points), so a bound it holds is never below
 * the grid's maximum, and the local searches climb from the grid's peaks. */
static void grid_sweep(search_state *s)
{
    static float cs[2048];
    int nc = grid_cos(cs, 2048), in, ie, ik, ic;
    for (in = 0; in < GRID_N1_N; in++)
        for (ie = 0; ie < GRID_ETA_N; ie++)
            for (ik = 0; ik < GRID_KAPPA_N; ik++)
                for (ic = 0; ic < nc; ic++) {
                    double x[SEARCH_DIMS];
                    x[0] = log10(grid_eta(ie));
                    x[1] = ik == 0 ? s->sp.lo[1] : log10(grid_kappa(ik));
                    x[2] = cs[ic];
                    x[3] = grid_n1[in];
                    search_eval(s, x);
                }
}

static int duplicate_row(int mi)
{
    int j;
    for (j = 0; j < mi; j++)
        if (model_table[j].f32 == model_table[mi].f32 && model_table[j].q15 == model_table[mi].q15)
            return 1;
    return 0;
}

int main(void)
{
    int longpass = search_long(), mi, ty;
    long random_n = longpass ? 2000000 : 60000;
    for (mi = 0; mi < model_count; mi++) {
        const model *m = &model_table[mi];
        if (!m->f32->scalar || !(m->offered & MODEL_EVAL) || duplicate_row(mi))
            continue; /* the thin film: tests/runtime/thin_film/test_film_search.c */
        for (ty = T_F32; ty <= T_F16; ty++) {
            model_case k;
            search_space sp;
            search_state s;
            char key[96], label[160];
            double bound;
            static const double sweep_c[] = {0.0, 1.0, 0.5, 1.0 / 7.0, 1e-3, 0.999};
            int i, j;
            memset(&sp, 0, sizeof sp);
            k.m = m;
            k.type = ty;
            if (ty == T_F16 && !(FRESNEL_HAS_F16 && m->f16->scalar))
                continue;
            if (ty == T_F32) {
                sp.dims = 4;
                sp.lo[0] = -2.0, sp.hi[0] = 2.0;
                k.kappa_lo = -3.0, sp.lo[1] = -3.5, sp.hi[1] = 3.0;
                sp.hi[2] = 1.0;
                sp.lo[3] = 1.0, sp.hi[3] = 2.42;
                bound = m->bound;
            } else if (ty == T_Q15) {
                sp.dims = 3;
                sp.lo[0] = -10.0 * log10(2.0), sp.hi[0] = log10(32767.0);
                k.kappa_lo = -9.0, sp.lo[1] = -10.2, sp.hi[1] = log10(32767.0);
                sp.hi[2] = 32768.0, sp.quantum[2] = 1.0;
                bound = m->q15_bound;
            } else {
                sp.dims = 3;
                sp.lo[0] = -10.0 * log10(2.0), sp.hi[0] = log10(16.0);
                k.kappa_lo = -3.0, sp.lo[1] = -3.4, sp.hi[1] = log10(16.0);
                sp.hi[2] = 1.0;
                bound = f16_domain_bound(m);
            }
            search_init(&s, &sp, model_error, &k, 0xF5E5u + (uint64_t)(mi * 3 + ty));
            snprintf(key, sizeof key, "%s:%s", type_key[ty], m->name);
            search_corpus(&s, CORPUS, key);
            /* the ends and the marked cosines at the corners and the middle of the box */
            for (i = 0; i < 6; i++)
                for (j = 0; j < 9; j++) {
                    double x[SEARCH_DIMS];
                    x[0] = sp.lo[0] + (sp.hi[0] - sp.lo[0]) * (j % 3) / 2.0;
                    x[1] = sp.lo[1] + (sp.hi[1] - sp.lo[1]) * (j / 3) / 2.0;
                    x[2] = sweep_c[i] * sp.hi[2];
                    x[3] = 1.0;
                    search_eval(&s, x);
                }
            matched_index_sweep(&s, ty);
            if (longpass && ty == T_F32)
                grid_sweep(&s);
            search_random(&s, random_n);
            search_climb(&s, longpass ? 12 : 6, 48);
            search_corpus_write(&s, key, 3);
            if (ty == T_Q15)
                printf("NOTE search %-6s %-18s max|err| %.4g LSB at eta %.6g kappa %.6g c %.0f, %ld evaluations\n",
                       type_key[ty], m->name, s.top[0].err, pow(10.0, s.top[0].x[0]),
                       kappa_of(&k, s.top[0].x[1]), s.top[0].x[2], s.evals);
            else
                printf("NOTE search %-6s %-18s max|err| %.4g at eta %.6g kappa %.6g c %.9g%s, %ld evaluations\n",
                       type_key[ty], m->name, s.top[0].err, pow(10.0, s.top[0].x[0]), kappa_of(&k, s.top[0].x[1]),
                       s.top[0].x[2], ty == T_F32 ? " (n1 given)" : "", s.evals);
            snprintf(label, sizeof label, "%s %s: results in [0, 1]%s (searched)", type_key[ty], m->name,
                     bound > 0.0 ? " and within the stated bound" : "");
            CHECK(label, bound > 0.0 ? s.top[0].err <= bound : s.top[0].err < HUGE_VAL, "max|err| %.4g, bound %.4g",
                  s.top[0].err, bound);
        }
    }
    search_helpers(longpass);
    return harness_exit();
}
