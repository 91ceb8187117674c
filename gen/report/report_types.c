/* The number types the report measures: each scene model prepared once per
 * material in binary32, Q1.15 and binary16, evaluated for accuracy (one
 * cosine at a time) and timed (a batch loop per model kind, so no dispatch
 * sits inside the timed loop). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "bench/bench.h"
#include "3_encode/fixed_params.h"
#include "fresnel.h"
#include "fresnel_f16.h"
#include "fresnel_fixed.h"
#include "report/report.h"
#include "scene/scene.h"

enum kind { K_SCHLICK, K_LSK, K_LSK_COMP, K_F82, K_GULB, K_CT, K_EXACT, K_APPROX, K_LUT, K_LUT_LIN, K_LUT_RES, K_LUT_LIN_RES,
            K_LUT_CUBIC };

struct report_prepared {
    enum kind kind;
    int n; /* LUT nodes */
    /* binary32 */
    fresnel_rgb f0, f82, eta, kappa, a, alpha, r, g;
    float ct_eta, ct_kappa;
    const float *table;
    /* Q1.15 */
    fresnel_rgb_q15 q_f0, q_f82, q_r, q_g;
    fresnel_ior_prep_q15 q_ior[3], q_ct;
    fresnel_nk_prep_q15 q_nk[3];
    fresnel_lsk_prep_q15 q_lsk[3];
    uint16_t *q_table;
    int16_t *q_res;
    int q_frac;
#if FRESNEL_HAS_F16
    fresnel_f16 h_f0[3], h_f82[3], h_eta[3], h_kappa[3], h_a[3], h_alpha[3], h_r[3], h_g[3], h_ct_eta, h_ct_kappa;
    fresnel_f16 *h_table;
#endif
};

static fresnel_rgb rgb3(const double v[3])
{
    fresnel_rgb o;
    o.r = (float)v[0];
    o.g = (float)v[1];
    o.b = (float)v[2];
    return o;
}

static fresnel_rgb_q15 q15_3(const double v[3])
{
    fresnel_rgb_q15 o;
    o.r = (fresnel_q15)fixed_q15(v[0]);
    o.g = (fresnel_q15)fixed_q15(v[1]);
    o.b = (fresnel_q15)fixed_q15(v[2]);
    return o;
}

report_prepared *report_prepare(const scene_model *m, const material_params *p)
{
    report_prepared *q = calloc(1, sizeof *q);
    const double *eta = p->eta_fit, *kappa = p->kappa_fit;
    int ch, i;
    if (!q)
        return NULL;
    if (m->lut_n && m->form == LUT_CUBIC)
        q->kind = K_LUT_CUBIC; /* scene_load admits it with grazing spacing only */
    else if (m->lut_n)
        q->kind = m->spacing == LUT_UNIFORM ? (m->form == LUT_RESIDUAL ? K_LUT_LIN_RES : K_LUT_LIN)
                                            : (m->form == LUT_RESIDUAL ? K_LUT_RES : K_LUT);
    else if (!strcmp(m->name, "schlick"))
        q->kind = K_SCHLICK;
    else if (!strcmp(m->name, "lsk"))
        q->kind = K_LSK;
    else if (!strcmp(m->name, "lsk-comp"))
        q->kind = K_LSK_COMP;
    else if (!strcmp(m->name, "f82"))
        q->kind = K_F82;
    else if (!strcmp(m->name, "gulbrandsen"))
        q->kind = K_GULB;
    else if (!strcmp(m->name, "cook-torrance"))
        q->kind = K_CT;
    else if (!strcmp(m->name, "approx-conductor"))
        q->kind = K_APPROX;
    else {
        q->kind = K_EXACT;
        if (!strcmp(m->name, "exact-gaussian")) {
            eta = p->eta_gauss;
            kappa = p->kappa_gauss;
        } else if (!strcmp(m->name, "exact-point")) {
            eta = p->eta_point;
            kappa = p->kappa_point;
        }
    }
    q->n = m->lut_n;
    q->f0 = rgb3(p->f0);
    q->f82 = rgb3(p->f82);
    q->eta = rgb3(eta);
    q->kappa = rgb3(kappa);
    q->a = rgb3(p->lsk_a);
    q->alpha = rgb3(p->lsk_alpha);
    q->r = rgb3(p->gulb_r);
    q->g = rgb3(p->gulb_g);
    q->ct_eta = (float)p->ct_eta;
    q->ct_kappa = (float)p->ct_kappa;
    q->table = m->table;
    q->q_f0 = q15_3(p->f0);
    q->q_f82 = q15_3(p->f82);
    q->q_r = q15_3(p->gulb_r);
    q->q_g = q15_3(p->gulb_g);
    fixed_ior(p->ct_eta, p->ct_kappa, &q->q_ct);
    for (ch = 0; ch < 3; ch++) {
        fixed_ior(eta[ch], kappa[ch], &q->q_ior[ch]);
        fixed_nk(eta[ch], kappa[ch], &q->q_nk[ch]);
        fixed_lsk(eta[ch], kappa[ch], q->kind == K_LSK_COMP ? p->lsk_a[ch] : 0.0,
                  q->kind == K_LSK_COMP ? p->lsk_alpha[ch] : 0.0, &q->q_lsk[ch]);
    }
    if (m->lut_n) {
        double big = 0.0;
        q->q_table = malloc(3 * (size_t)m->lut_n * sizeof *q->q_table);
        q->q_res = malloc(3 * (size_t)m->lut_n * sizeof *q->q_res);
        if (!q->q_table || !q->q_res) {
            report_prepared_free(q);
            return NULL;
        }
        for (i = 0; i < 3 * m->lut_n; i++)
            if (fabs(m->table_d[i]) > big)
                big = fabs(m->table_d[i]);
        /* residuals are small: as many fraction bits as int16 holds */
        for (q->q_frac = 15; q->q_frac < 30 && big * ldexp(1.0, q->q_frac + 1) <= 32767.0; q->q_frac++)
            ;
        for (i = 0; i < 3 * m->lut_n; i++) {
            q->q_table[i] = (uint16_t)fixed_q15(m->table_d[i]);
            q->q_res[i] = (int16_t)lround(m->table_d[i] * ldexp(1.0, q->q_frac));
        }
    }
#if FRESNEL_HAS_F16
    for (ch = 0; ch < 3; ch++) {
        q->h_f0[ch] = (fresnel_f16)p->f0[ch];
        q->h_f82[ch] = (fresnel_f16)p->f82[ch];
        q->h_eta[ch] = (fresnel_f16)eta[ch];
        q->h_kappa[ch] = (fresnel_f16)kappa[ch];
        q->h_a[ch] = (fresnel_f16)p->lsk_a[ch];
        q->h_alpha[ch] = (fresnel_f16)p->lsk_alpha[ch];
        q->h_r[ch] = (fresnel_f16)p->gulb_r[ch];
        q->h_g[ch] = (fresnel_f16)p->gulb_g[ch];
    }
    q->h_ct_eta = (fresnel_f16)p->ct_eta;
    q->h_ct_kappa = (fresnel_f16)p->ct_kappa;
    if (m->lut_n) {
        if (!(q->h_table = malloc(3 * (size_t)m->lut_n * sizeof *q->h_table))) {
            report_prepared_free(q);
            return NULL;
        }
        for (i = 0; i < 3 * m->lut_n; i++)
            q->h_table[i] = (fresnel_f16)m->table_d[i];
    }
#endif
    return q;
}

void report_prepared_free(report_prepared *q)
{
    if (!q)
        return;
    free(q->q_table);
    free(q->q_res);
#if FRESNEL_HAS_F16
    free(q->h_table);
#endif
    free(q);
}

/* ---- binary32 */
static fresnel_rgb eval_f32_rgb(const report_prepared *q, float c)
{
    switch (q->kind) {
    case K_SCHLICK: return fresnel_schlick_rgb(q->f0, c);
    case K_LSK: return fresnel_lsk_rgb(q->eta, q->kappa, c);
    case K_LSK_COMP: return fresnel_lsk_comp_rgb(q->eta, q->kappa, q->a, q->alpha, c);
    case K_F82: return fresnel_f82_rgb(q->f0, q->f82, c);
    case K_GULB: return fresnel_gulbrandsen_rgb(q->r, q->g, c);
    case K_CT: return fresnel_cook_torrance_rgb(q->f0, q->ct_eta, q->ct_kappa, c);
    case K_EXACT: return fresnel_conductor_rgb(q->eta, q->kappa, c);
    case K_APPROX: return fresnel_approx_conductor_rgb(q->eta, q->kappa, c);
    case K_LUT: return fresnel_lut_rgb(q->table, q->n, c);
    case K_LUT_LIN: return fresnel_lut_linear_rgb(q->table, q->n, c);
    case K_LUT_RES: return fresnel_lut_residual_rgb(q->f0, q->table, q->n, c);
    case K_LUT_CUBIC: return fresnel_lut_cubic_rgb(q->table, q->n, c);
    default: return fresnel_lut_linear_residual_rgb(q->f0, q->table, q->n, c);
    }
}

/* ---- Q1.15 */
static fresnel_rgb_q15 eval_q15_rgb(const report_prepared *q, int32_t c)
{
    fresnel_rgb_q15 o;
    switch (q->kind) {
    case K_SCHLICK: return fresnel_schlick_q15_rgb(q->q_f0, c);
    case K_LSK:
    case K_LSK_COMP: return fresnel_lsk_comp_q15_rgb(q->q_lsk, c);
    case K_F82: return fresnel_f82_q15_rgb(q->q_f0, q->q_f82, c);
    case K_GULB: return fresnel_gulbrandsen_q15_rgb(q->q_r, q->q_g, c);
    case K_CT: return fresnel_cook_torrance_q15_rgb(q->q_f0, &q->q_ct, c);
    case K_EXACT: return fresnel_conductor_q15_rgb(q->q_ior, c);
    case K_APPROX: return fresnel_approx_conductor_q15_rgb(q->q_nk, c);
    case K_LUT: return fresnel_lut_u16_q15_rgb(q->q_table, q->n, c);
    case K_LUT_LIN: return fresnel_lut_linear_u16_q15_rgb(q->q_table, q->n, c);
    case K_LUT_RES: return fresnel_lut_residual_s16_q15_rgb(q->q_f0, q->q_res, q->n, q->q_frac, c);
    case K_LUT_CUBIC: return fresnel_lut_cubic_u16_q15_rgb(q->q_table, q->n, c);
    default: return fresnel_lut_linear_residual_s16_q15_rgb(q->q_f0, q->q_res, q->n, q->q_frac, c);
    }
    return o;
}

#if FRESNEL_HAS_F16
/* ---- binary16: scalar functions, channel by channel as a shader would */
static fresnel_f16 eval_f16_channel(const report_prepared *q, int ch, fresnel_f16 c)
{
    switch (q->kind) {
    case K_SCHLICK: return fresnel_schlick_f16(q->h_f0[ch], c);
    case K_LSK: return fresnel_lsk_f16(q->h_eta[ch], q->h_kappa[ch], c);
    case K_LSK_COMP: return fresnel_lsk_comp_f16(q->h_eta[ch], q->h_kappa[ch], q->h_a[ch], q->h_alpha[ch], c);
    case K_F82: return fresnel_f82_f16(q->h_f0[ch], q->h_f82[ch], c);
    case K_GULB: return fresnel_gulbrandsen_f16(q->h_r[ch], q->h_g[ch], c);
    case K_CT: return fresnel_cook_torrance_f16(q->h_f0[ch], q->h_ct_eta, q->h_ct_kappa, c);
    case K_EXACT: return fresnel_conductor_f16(q->h_eta[ch], q->h_kappa[ch], c);
    case K_APPROX: return fresnel_approx_conductor_f16(q->h_eta[ch], q->h_kappa[ch], c);
    case K_LUT: return fresnel_lut_f16(q->h_table + ch * q->n, q->n, c);
    case K_LUT_LIN: return fresnel_lut_linear_f16(q->h_table + ch * q->n, q->n, c);
    case K_LUT_RES: return fresnel_lut_residual_f16(q->h_f0[ch], q->h_table + ch * q->n, q->n, c);
    case K_LUT_CUBIC: return fresnel_lut_cubic_f16(q->h_table + ch * q->n, q->n, c);
    default: return fresnel_lut_linear_residual_f16(q->h_f0[ch], q->h_table + ch * q->n, q->n, c);
    }
}
#endif

static void eval_f32(const report_prepared *q, double c, double rgb[3])
{
    fresnel_rgb v = eval_f32_rgb(q, (float)c);
    rgb[0] = v.r;
    rgb[1] = v.g;
    rgb[2] = v.b;
}

static void eval_q15(const report_prepared *q, double c, double rgb[3])
{
    fresnel_rgb_q15 v = eval_q15_rgb(q, (int32_t)lround(c * 32768.0));
    rgb[0] = v.r / 32768.0;
    rgb[1] = v.g / 32768.0;
    rgb[2] = v.b / 32768.0;
}

#if FRESNEL_HAS_F16
static void eval_f16(const report_prepared *q, double c, double rgb[3])
{
    int ch;
    for (ch = 0; ch < 3; ch++)
        rgb[ch] = (double)eval_f16_channel(q, ch, (fresnel_f16)c);
}
#endif

/* Timed loops: the switch is hoisted by making the kind a compile-time
 * constant of each instantiation. */
#define BATCH_F32(K)                                                                               \
    static double batch_f32_##K(const void *x, const float *c, const int32_t *cq, int n)         \
    {                                                                                              \
        report_prepared q = *(const report_prepared *)x;                                           \
        double sum = 0.0;                                                                          \
        int i;                                                                                     \
        (void)cq;                                                                                  \
        q.kind = K;                                                                                \
        for (i = 0; i < n; i++) {                                                                  \
            fresnel_rgb v = eval_f32_rgb(&q, c[i]);                                                \
            sum += v.r + v.g + v.b;                                                                \
        }                                                                                          \
        return sum;                                                                                \
    }
#define BATCH_Q15(K)                                                                               \
    static double batch_q15_##K(const void *x, const float *c, const int32_t *cq, int n)         \
    {                                                                                              \
        report_prepared q = *(const report_prepared *)x;                                           \
        uint32_t sum = 0;                                                                          \
        int i;                                                                                     \
        (void)c;                                                                                   \
        q.kind = K;                                                                                \
        for (i = 0; i < n; i++) {                                                                  \
            fresnel_rgb_q15 v = eval_q15_rgb(&q, cq[i]);                                           \
            sum += (uint32_t)v.r + v.g + v.b;                                                      \
        }                                                                                          \
        return sum;                                                                                \
    }
#define BATCHES(K) BATCH_F32(K) BATCH_Q15(K)
BATCHES(K_SCHLICK)
BATCHES(K_LSK)
BATCHES(K_LSK_COMP)
BATCHES(K_F82)
BATCHES(K_GULB)
BATCHES(K_CT)
BATCHES(K_EXACT)
BATCHES(K_APPROX)
BATCHES(K_LUT)
BATCHES(K_LUT_LIN)
BATCHES(K_LUT_RES)
BATCHES(K_LUT_LIN_RES)
BATCHES(K_LUT_CUBIC)

static const bench_batch f32_batches[] = {batch_f32_K_SCHLICK, batch_f32_K_LSK,     batch_f32_K_LSK_COMP,
                                          batch_f32_K_F82,     batch_f32_K_GULB,    batch_f32_K_CT,
                                          batch_f32_K_EXACT,   batch_f32_K_APPROX,  batch_f32_K_LUT,
                                          batch_f32_K_LUT_LIN, batch_f32_K_LUT_RES, batch_f32_K_LUT_LIN_RES,
                                          batch_f32_K_LUT_CUBIC};
static const bench_batch q15_batches[] = {batch_q15_K_SCHLICK, batch_q15_K_LSK,     batch_q15_K_LSK_COMP,
                                          batch_q15_K_F82,     batch_q15_K_GULB,    batch_q15_K_CT,
                                          batch_q15_K_EXACT,   batch_q15_K_APPROX,  batch_q15_K_LUT,
                                          batch_q15_K_LUT_LIN, batch_q15_K_LUT_RES, batch_q15_K_LUT_LIN_RES,
                                          batch_q15_K_LUT_CUBIC};

#if FRESNEL_HAS_F16
static double batch_f16(const void *x, const float *c, const int32_t *cq, int n)
{
    const report_prepared *q = x;
    double sum = 0.0;
    int i, ch;
    (void)cq;
    for (i = 0; i < n; i++)
        for (ch = 0; ch < 3; ch++)
            sum += (double)eval_f16_channel(q, ch, (fresnel_f16)c[i]);
    return sum;
}
#endif

double report_time(const report_type *t, const report_prepared *q, int n, int runs)
{
    bench_batch fn = !strcmp(t->name, "q15") ? q15_batches[q->kind] : f32_batches[q->kind];
#if FRESNEL_HAS_F16
    if (!strcmp(t->name, "f16"))
        fn = batch_f16;
#endif
    return bench_ns_per_eval(fn, q, n, runs);
}

const report_type report_types[] = {
    {"f32", eval_f32},
    {"q15", eval_q15},
#if FRESNEL_HAS_F16
    {"f16", eval_f16},
#endif
};
const int report_type_count = (int)(sizeof report_types / sizeof report_types[0]);
