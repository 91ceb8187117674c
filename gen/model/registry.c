/* The model registry (registry.h): one row per model. */
#include "model/registry.h"

#include <ctype.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <math.h>

#include "3_encode/fixed_params.h"
#include "fresnel.h"
#include "fresnel_f16.h"
#include "fresnel_film.h"
#include "common/reference.h"
#include "common/reference_film.h"

#define F(x) ((float)(x))

static double d_schlick(const model_params *m, double c) { return ref_schlick(m->f0, c); }
static float s_schlick(const model_params *m, float c) { return fresnel_schlick(F(m->f0), c); }

static double d_schlick_gen(const model_params *m, double c)
{
    return ref_schlick_gen(m->f0, m->f90, m->p, c);
}
static float s_schlick_gen(const model_params *m, float c)
{
    return fresnel_schlick_gen(F(m->f0), F(m->f90), F(m->p), c);
}

static double d_lsk(const model_params *m, double c) { return ref_lsk(m->eta, m->kappa, c); }
static float s_lsk(const model_params *m, float c) { return fresnel_lsk(F(m->eta), F(m->kappa), c); }

static double d_lsk_comp(const model_params *m, double c)
{
    return ref_lsk_comp(m->eta, m->kappa, m->a, m->alpha, c);
}
static float s_lsk_comp(const model_params *m, float c)
{
    return fresnel_lsk_comp(F(m->eta), F(m->kappa), F(m->a), F(m->alpha), c);
}

static double d_f82(const model_params *m, double c) { return ref_f82(m->f0, m->f82, c); }
static float s_f82(const model_params *m, float c) { return fresnel_f82(F(m->f0), F(m->f82), c); }

static double d_gulbrandsen(const model_params *m, double c) { return ref_gulbrandsen(m->r, m->g, c); }
static float s_gulbrandsen(const model_params *m, float c)
{
    return fresnel_gulbrandsen(F(m->r), F(m->g), c);
}

static double d_cook_torrance(const model_params *m, double c)
{
    return ref_cook_torrance(m->f0, m->eta, m->kappa, c);
}
static float s_cook_torrance(const model_params *m, float c)
{
    return fresnel_cook_torrance(F(m->f0), F(m->eta), F(m->kappa), c);
}

/* kappa = 0 takes the dielectric function, as a caller who knows it would. */
static double d_exact(const model_params *m, double c)
{
    return m->kappa > 0.0 ? ref_conductor(m->eta, m->kappa, c) : ref_dielectric(m->eta, c);
}
static float s_exact(const model_params *m, float c)
{
    return m->kappa > 0.0 ? fresnel_conductor(F(m->eta), F(m->kappa), c)
                          : fresnel_dielectric(F(m->eta), c);
}

static double d_conductor(const model_params *m, double c) { return ref_conductor(m->eta, m->kappa, c); }
static float s_conductor(const model_params *m, float c)
{
    return fresnel_conductor(F(m->eta), F(m->kappa), c);
}

static double d_dielectric(const model_params *m, double c) { return ref_dielectric(m->eta, c); }
static float s_dielectric(const model_params *m, float c) { return fresnel_dielectric(F(m->eta), c); }

static double d_approx(const model_params *m, double c)
{
    return ref_approx_conductor(m->eta, m->kappa, c);
}
static float s_approx(const model_params *m, float c)
{
    return fresnel_approx_conductor(F(m->eta), F(m->kappa), c);
}

static double d_internal(const model_params *m, double c)
{
    return ref_schlick_internal(m->f0, m->eta, c);
}
static float s_internal(const model_params *m, float c)
{
    return fresnel_schlick_internal(F(m->f0), F(m->eta), c);
}

/* ---- fixed point (fresnel_fixed.h); parameters prepared by model_fixed_from_params */
static int32_t q_schlick(const model_fixed *m, int32_t c) { return fresnel_schlick_q15(m->f0, c); }
static int32_t q_schlick_gen(const model_fixed *m, int32_t c)
{
    return fresnel_schlick_gen_q15(m->f0, m->f90, m->p, c);
}
static int32_t q_lsk(const model_fixed *m, int32_t c) { return fresnel_lsk_q15(&m->lsk, c); }
static int32_t q_lsk_comp(const model_fixed *m, int32_t c) { return fresnel_lsk_comp_q15(&m->lsk, c); }
static int32_t q_f82(const model_fixed *m, int32_t c) { return fresnel_f82_q15(m->f0, m->f82, c); }
/* fresnel_gulbrandsen_q15 maps r, g each call; the prepared n, k give the same codes */
static int32_t q_gulbrandsen(const model_fixed *m, int32_t c) { return fresnel_approx_conductor_q15(&m->gnk, c); }
static int32_t q_cook_torrance(const model_fixed *m, int32_t c)
{
    return fresnel_cook_torrance_q15(m->f0, &m->ior, c);
}
static int32_t q_exact(const model_fixed *m, int32_t c)
{
    return m->ior.b.m ? fresnel_conductor_q15(&m->ior, c) : fresnel_dielectric_q15(&m->ior, c);
}
static int32_t q_conductor(const model_fixed *m, int32_t c) { return fresnel_conductor_q15(&m->ior, c); }
static int32_t q_dielectric(const model_fixed *m, int32_t c) { return fresnel_dielectric_q15(&m->dior, c); }
static int32_t q_approx(const model_fixed *m, int32_t c) { return fresnel_approx_conductor_q15(&m->nk, c); }
static int32_t q_internal(const model_fixed *m, int32_t c)
{
    return fresnel_schlick_internal_q15(m->f0, &m->dior, c);
}

/* ---- binary16 (fresnel_f16.h): parameters and c converted to half here */
#if FRESNEL_HAS_F16
#define H(x) ((fresnel_f16)(x))
static double h_schlick(const model_params *m, double c) { return (double)fresnel_schlick_f16(H(m->f0), H(c)); }
static double h_schlick_gen(const model_params *m, double c)
{
    return (double)fresnel_schlick_gen_f16(H(m->f0), H(m->f90), H(m->p), H(c));
}
static double h_lsk(const model_params *m, double c) { return (double)fresnel_lsk_f16(H(m->eta), H(m->kappa), H(c)); }
static double h_lsk_comp(const model_params *m, double c)
{
    return (double)fresnel_lsk_comp_f16(H(m->eta), H(m->kappa), H(m->a), H(m->alpha), H(c));
}
static double h_f82(const model_params *m, double c) { return (double)fresnel_f82_f16(H(m->f0), H(m->f82), H(c)); }
static double h_gulbrandsen(const model_params *m, double c)
{
    return (double)fresnel_gulbrandsen_f16(H(m->r), H(m->g), H(c));
}
static double h_cook_torrance(const model_params *m, double c)
{
    return (double)fresnel_cook_torrance_f16(H(m->f0), H(m->eta), H(m->kappa), H(c));
}
static double h_exact(const model_params *m, double c)
{
    return m->kappa > 0.0 ? (double)fresnel_conductor_f16(H(m->eta), H(m->kappa), H(c))
                          : (double)fresnel_dielectric_f16(H(m->eta), H(c));
}
static double h_conductor(const model_params *m, double c)
{
    return (double)fresnel_conductor_f16(H(m->eta), H(m->kappa), H(c));
}
static double h_dielectric(const model_params *m, double c) { return (double)fresnel_dielectric_f16(H(m->eta), H(c)); }
static double h_approx(const model_params *m, double c)
{
    return (double)fresnel_approx_conductor_f16(H(m->eta), H(m->kappa), H(c));
}
static double h_internal(const model_params *m, double c)
{
    return (double)fresnel_schlick_internal_f16(H(m->f0), H(m->eta), H(c));
}
#define F16(fn) fn
#else
#define F16(fn) NULL
#endif


/* ---- as scene models: the encoder's values of one material (model_rgb) */
#define M (q->mat)
#define L (q->lut)
#define E (q->def->eta)
#define ETA(q) encoded_eta((q)->mat, (q)->def->eta, 0)
#define KAPPA(q) encoded_eta((q)->mat, (q)->def->eta, 1)
static double ch3(fresnel_rgb v, int ch) { return ch == 0 ? v.r : (ch == 1 ? v.g : v.b); }

static fresnel_rgb r_schlick(const model_rgb *q, float c) { return fresnel_schlick_rgb(M->f0, c); }
static fresnel_rgb_q15 rq_schlick(const model_rgb *q, int32_t c) { return fresnel_schlick_q15_rgb(M->q_f0, c); }
static double rr_schlick(const model_rgb *q, int ch, double c) { return ref_schlick(ch3(M->f0, ch), c); }

static fresnel_rgb r_lsk(const model_rgb *q, float c) { return fresnel_lsk_rgb(ETA(q), KAPPA(q), c); }
static fresnel_rgb_q15 rq_lsk(const model_rgb *q, int32_t c) { return fresnel_lsk_q15_rgb(M->q_lsk, c); }
static double rr_lsk(const model_rgb *q, int ch, double c) { return ref_lsk(ch3(ETA(q), ch), ch3(KAPPA(q), ch), c); }

static fresnel_rgb r_lsk_comp(const model_rgb *q, float c)
{
    return fresnel_lsk_comp_rgb(ETA(q), KAPPA(q), M->lsk_a, M->lsk_alpha, c);
}
static fresnel_rgb_q15 rq_lsk_comp(const model_rgb *q, int32_t c) { return fresnel_lsk_comp_q15_rgb(M->q_lsk_comp, c); }
static double rr_lsk_comp(const model_rgb *q, int ch, double c)
{
    return ref_lsk_comp(ch3(ETA(q), ch), ch3(KAPPA(q), ch), ch3(M->lsk_a, ch), ch3(M->lsk_alpha, ch), c);
}

static fresnel_rgb r_f82(const model_rgb *q, float c) { return fresnel_f82_rgb(M->f0, M->f82, c); }
static fresnel_rgb_q15 rq_f82(const model_rgb *q, int32_t c) { return fresnel_f82_q15_rgb(M->q_f0, M->q_f82, c); }
static double rr_f82(const model_rgb *q, int ch, double c) { return ref_f82(ch3(M->f0, ch), ch3(M->f82, ch), c); }

static fresnel_rgb r_gulbrandsen(const model_rgb *q, float c) { return fresnel_gulbrandsen_rgb(M->gulb_r, M->gulb_g, c); }
static fresnel_rgb_q15 rq_gulbrandsen(const model_rgb *q, int32_t c) { return fresnel_gulbrandsen_q15_rgb(M->q_gulb_r, M->q_gulb_g, c); }
static double rr_gulbrandsen(const model_rgb *q, int ch, double c)
{
    return ref_gulbrandsen(ch3(M->gulb_r, ch), ch3(M->gulb_g, ch), c);
}

static fresnel_rgb r_cook_torrance(const model_rgb *q, float c)
{
    return fresnel_cook_torrance_rgb(M->f0, M->ct_eta, M->ct_kappa, c);
}
static fresnel_rgb_q15 rq_cook_torrance(const model_rgb *q, int32_t c)
{
    return fresnel_cook_torrance_q15_rgb(M->q_f0, &M->q_ct, c);
}
static double rr_cook_torrance(const model_rgb *q, int ch, double c)
{
    return ref_cook_torrance(ch3(M->f0, ch), M->ct_eta, M->ct_kappa, c);
}

static fresnel_rgb r_conductor(const model_rgb *q, float c) { return fresnel_conductor_rgb(ETA(q), KAPPA(q), c); }
static fresnel_rgb_q15 rq_conductor(const model_rgb *q, int32_t c) { return fresnel_conductor_q15_rgb(M->q_ior[E], c); }
static double rr_conductor(const model_rgb *q, int ch, double c)
{
    return ref_conductor(ch3(ETA(q), ch), ch3(KAPPA(q), ch), c);
}

static fresnel_rgb r_approx(const model_rgb *q, float c) { return fresnel_approx_conductor_rgb(ETA(q), KAPPA(q), c); }
static fresnel_rgb_q15 rq_approx(const model_rgb *q, int32_t c) { return fresnel_approx_conductor_q15_rgb(M->q_nk, c); }
static double rr_approx(const model_rgb *q, int ch, double c)
{
    return ref_approx_conductor(ch3(ETA(q), ch), ch3(KAPPA(q), ch), c);
}

/* LUTs: the table as the runtime reads it; the reference interpolates the
 * binary32-rounded nodes in double. */
static fresnel_rgb a_schlick(const model_rgb *q) { return fresnel_schlick_avg_rgb(M->f0); }
static fresnel_rgb a_f82(const model_rgb *q) { return fresnel_f82_avg_rgb(M->f0, M->f82); }
static fresnel_rgb a_lut(const model_rgb *q) { return fresnel_lut_avg_rgb(L->f32, L->n); }
static fresnel_rgb a_lut_lin(const model_rgb *q) { return fresnel_lut_linear_avg_rgb(L->f32, L->n); }
static fresnel_rgb a_lut_cubic(const model_rgb *q) { return fresnel_lut_cubic_avg_rgb(L->f32, L->n); }
static fresnel_rgb r_lut(const model_rgb *q, float c) { return fresnel_lut_rgb(L->f32, L->n, c); }
static fresnel_rgb r_lut_lin(const model_rgb *q, float c) { return fresnel_lut_linear_rgb(L->f32, L->n, c); }
static fresnel_rgb r_lut_res(const model_rgb *q, float c) { return fresnel_lut_residual_rgb(M->f0, L->f32, L->n, c); }
static fresnel_rgb r_lut_lin_res(const model_rgb *q, float c)
{
    return fresnel_lut_linear_residual_rgb(M->f0, L->f32, L->n, c);
}
static fresnel_rgb r_lut_cubic(const model_rgb *q, float c) { return fresnel_lut_cubic_rgb(L->f32, L->n, c); }
static fresnel_rgb_q15 rq_lut(const model_rgb *q, int32_t c) { return fresnel_lut_u16_q15_rgb(L->q15, L->n, c); }
static fresnel_rgb_q15 rq_lut_lin(const model_rgb *q, int32_t c)
{
    return fresnel_lut_linear_u16_q15_rgb(L->q15, L->n, c);
}
static fresnel_rgb_q15 rq_lut_res(const model_rgb *q, int32_t c)
{
    return fresnel_lut_residual_s16_q15_rgb(M->q_f0, L->q15_res, L->n, L->frac, c);
}
static fresnel_rgb_q15 rq_lut_lin_res(const model_rgb *q, int32_t c)
{
    return fresnel_lut_linear_residual_s16_q15_rgb(M->q_f0, L->q15_res, L->n, L->frac, c);
}
static fresnel_rgb_q15 rq_lut_cubic(const model_rgb *q, int32_t c)
{
    return fresnel_lut_cubic_u16_q15_rgb(L->q15, L->n, c);
}
static double ref_nodes(const model_rgb *q, int ch, double x, int cubic)
{
    double nodes[MODEL_LUT_NODES_MAX];
    int i;
    for (i = 0; i < L->n; i++) /* at the float-rounded node values */
        nodes[i] = L->f32[ch * L->n + i];
    return ref_lut(nodes, L->n, cubic, x);
}
static double rr_lut(const model_rgb *q, int ch, double c) { return ref_nodes(q, ch, sqrt(c), 0); }
static double rr_lut_lin(const model_rgb *q, int ch, double c) { return ref_nodes(q, ch, c, 0); }
static double rr_lut_res(const model_rgb *q, int ch, double c)
{
    return ref_nodes(q, ch, sqrt(c), 0) + ref_schlick(ch3(M->f0, ch), c);
}
static double rr_lut_lin_res(const model_rgb *q, int ch, double c)
{
    return ref_nodes(q, ch, c, 0) + ref_schlick(ch3(M->f0, ch), c);
}
static double rr_lut_cubic(const model_rgb *q, int ch, double c) { return ref_nodes(q, ch, sqrt(c), 1); }

/* The thin film: the material's table at the thickness model_rgb holds;
 * the reference evaluates the binary32 table in double. */
#define FILM (q->film)
static fresnel_rgb r_film(const model_rgb *q, float c) { return fresnel_film_rgb(&FILM->f32, c, (float)q->d_nm); }
/* d as Q16.16 nm, held to int32_t (the runtime clamps it to its range) */
static fresnel_rgb_q15 rq_film(const model_rgb *q, int32_t c)
{
    static const fresnel_rgb_q15 none = {0, 0, 0};
    double d = floor(q->d_nm * 65536.0 + 0.5);
    int32_t dq = d >= 2147483647.0 ? INT32_MAX : (d > 0.0 ? (int32_t)d : 0);
    return FILM->q15_ok ? fresnel_film_q15_rgb(&FILM->q15, c, dq) : none;
}
static double rr_film(const model_rgb *q, int ch, double c)
{
    double rgb[3];
    ref_film_model(&FILM->model_f32, c, q->d_nm, 1, rgb);
    return rgb[ch];
}

#if FRESNEL_HAS_F16
/* binary16: scalar functions, channel by channel as a shader would */
static double rh_film(const model_rgb *q, int ch, double c)
{
    fresnel_rgb_f16 v = fresnel_film_f16_rgb(&FILM->f16, H(c), H(q->d_nm));
    return (double)(ch == 0 ? v.r : (ch == 1 ? v.g : v.b));
}
#define HC(fn_args) return (double)(fn_args)
static double rh_schlick(const model_rgb *q, int ch, double c) { HC(fresnel_schlick_f16(M->h_f0[ch], H(c))); }
static double rh_lsk(const model_rgb *q, int ch, double c) { HC(fresnel_lsk_f16(encoded_eta_f16(M, E, 0)[ch], encoded_eta_f16(M, E, 1)[ch], H(c))); }
static double rh_lsk_comp(const model_rgb *q, int ch, double c)
{
    HC(fresnel_lsk_comp_f16(encoded_eta_f16(M, E, 0)[ch], encoded_eta_f16(M, E, 1)[ch], M->h_lsk_a[ch], M->h_lsk_alpha[ch], H(c)));
}
static double rh_f82(const model_rgb *q, int ch, double c) { HC(fresnel_f82_f16(M->h_f0[ch], M->h_f82[ch], H(c))); }
static double rh_gulbrandsen(const model_rgb *q, int ch, double c)
{
    HC(fresnel_gulbrandsen_f16(M->h_gulb_r[ch], M->h_gulb_g[ch], H(c)));
}
static double rh_cook_torrance(const model_rgb *q, int ch, double c)
{
    HC(fresnel_cook_torrance_f16(M->h_f0[ch], M->h_ct_eta, M->h_ct_kappa, H(c)));
}
static double rh_conductor(const model_rgb *q, int ch, double c)
{
    HC(fresnel_conductor_f16(encoded_eta_f16(M, E, 0)[ch], encoded_eta_f16(M, E, 1)[ch], H(c)));
}
static double rh_approx(const model_rgb *q, int ch, double c)
{
    HC(fresnel_approx_conductor_f16(encoded_eta_f16(M, E, 0)[ch], encoded_eta_f16(M, E, 1)[ch], H(c)));
}
static double rh_lut(const model_rgb *q, int ch, double c) { HC(fresnel_lut_f16(L->f16 + ch * L->n, L->n, H(c))); }
static double rh_lut_lin(const model_rgb *q, int ch, double c)
{
    HC(fresnel_lut_linear_f16(L->f16 + ch * L->n, L->n, H(c)));
}
static double rh_lut_res(const model_rgb *q, int ch, double c)
{
    HC(fresnel_lut_residual_f16(M->h_f0[ch], L->f16 + ch * L->n, L->n, H(c)));
}
static double rh_lut_lin_res(const model_rgb *q, int ch, double c)
{
    HC(fresnel_lut_linear_residual_f16(M->h_f0[ch], L->f16 + ch * L->n, L->n, H(c)));
}
static double rh_lut_cubic(const model_rgb *q, int ch, double c)
{
    HC(fresnel_lut_cubic_f16(L->f16 + ch * L->n, L->n, H(c)));
}
#endif

/* Timed loops, one per row and type, calling the row's evaluator directly;
 * named batch_* because `fresnel report` counts instructions inside them
 * (callgrind --toggle-collect). */
#define BATCHES(id)                                                                                \
    static double batch_f32_##id(const void *x, const float *c, const int32_t *cq, int n)                \
    {                                                                                              \
        const model_rgb *q = x;                                                                    \
        double sum = 0.0;                                                                          \
        int i;                                                                                     \
        (void)cq;                                                                                  \
        for (i = 0; i < n; i++) {                                                                  \
            fresnel_rgb v = r_##id(q, c[i]);                                                       \
            sum += v.r + v.g + v.b;                                                                \
        }                                                                                          \
        return sum;                                                                                \
    }                                                                                              \
    static double batch_q15_##id(const void *x, const float *c, const int32_t *cq, int n)                \
    {                                                                                              \
        const model_rgb *q = x;                                                                    \
        uint32_t sum = 0;                                                                          \
        int i;                                                                                     \
        (void)c;                                                                                   \
        for (i = 0; i < n; i++) {                                                                  \
            fresnel_rgb_q15 v = rq_##id(q, cq[i]);                                                 \
            sum += (uint32_t)v.r + v.g + v.b;                                                      \
        }                                                                                          \
        return sum;                                                                                \
    }
BATCHES(schlick)
BATCHES(lsk)
BATCHES(lsk_comp)
BATCHES(f82)
BATCHES(gulbrandsen)
BATCHES(cook_torrance)
BATCHES(conductor)
BATCHES(approx)
BATCHES(lut)
BATCHES(lut_lin)
BATCHES(lut_res)
BATCHES(lut_lin_res)
BATCHES(lut_cubic)
BATCHES(film)

#if FRESNEL_HAS_F16
/* binary16: the scalar function channel by channel, as a shader would; the
 * film's runtime gives all three channels in one call */
#define BATCH_F16(id)                                                                                  \
    static double batch_f16_##id(const void *x, const float *c, const int32_t *cq, int n)              \
    {                                                                                                  \
        const model_rgb *q = x;                                                                        \
        double sum = 0.0;                                                                              \
        int i, ch;                                                                                     \
        (void)cq;                                                                                      \
        for (i = 0; i < n; i++)                                                                        \
            for (ch = 0; ch < 3; ch++)                                                                 \
                sum += rh_##id(q, ch, c[i]);                                                           \
        return sum;                                                                                    \
    }
BATCH_F16(schlick)
BATCH_F16(lsk)
BATCH_F16(lsk_comp)
BATCH_F16(f82)
BATCH_F16(gulbrandsen)
BATCH_F16(cook_torrance)
BATCH_F16(conductor)
BATCH_F16(approx)
BATCH_F16(lut)
BATCH_F16(lut_lin)
BATCH_F16(lut_res)
BATCH_F16(lut_lin_res)
BATCH_F16(lut_cubic)
static double batch_f16_film(const void *x, const float *c, const int32_t *cq, int n)
{
    const model_rgb *q = x;
    double sum = 0.0;
    int i;
    (void)cq;
    for (i = 0; i < n; i++) {
        fresnel_rgb_f16 v = fresnel_film_f16_rgb(&FILM->f16, H(c[i]), H(q->d_nm));
        sum += (double)v.r + (double)v.g + (double)v.b;
    }
    return sum;
}
#define SCENE(id) r_##id, rq_##id, rh_##id, rr_##id, batch_f32_##id, batch_q15_##id, batch_f16_##id
#else
#define SCENE(id) r_##id, rq_##id, NULL, rr_##id, batch_f32_##id, batch_q15_##id, NULL
#endif
/* Rows offered in eval only carry no scene evaluators. */
#define NO_SCENE 0, 0, ETA_FIT, LUT_PLAIN, 0, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL
#define EVAL_SCENE (MODEL_EVAL | MODEL_SCENE)

const model model_table[] = {
    {"schlick", EVAL_SCENE, "F0", d_schlick, s_schlick, FRESNEL_BOUND_SCHLICK,
     q_schlick, FRESNEL_BOUND_SCHLICK_Q15, F16(h_schlick), FRESNEL_BOUND_SCHLICK_F16,
     MP_F0, 0, ETA_FIT, LUT_PLAIN, 0, "fresnel_schlick_rgb(@f0, c)", SCENE(schlick), a_schlick, "schlick"},
    {"schlick-gen", MODEL_EVAL, "F0, --f90, --p", d_schlick_gen, s_schlick_gen, FRESNEL_BOUND_SCHLICK_GEN,
     q_schlick_gen, FRESNEL_BOUND_SCHLICK_GEN_Q15, F16(h_schlick_gen), FRESNEL_BOUND_SCHLICK_GEN_F16, NO_SCENE},
    {"lsk", EVAL_SCENE, "eta, kappa", d_lsk, s_lsk, FRESNEL_BOUND_LSK,
     q_lsk, FRESNEL_BOUND_LSK_Q15, F16(h_lsk), FRESNEL_BOUND_LSK_F16,
     MP_ETA_FIT, MQ_LSK, ETA_FIT, LUT_PLAIN, 0, "fresnel_lsk_rgb(@eta, @kappa, c)", SCENE(lsk), NULL, "lsk"},
    {"lsk-comp", EVAL_SCENE, "eta, kappa, LSK a and alpha", d_lsk_comp, s_lsk_comp, FRESNEL_BOUND_LSK_COMP,
     q_lsk_comp, FRESNEL_BOUND_LSK_COMP_Q15, F16(h_lsk_comp), FRESNEL_BOUND_LSK_COMP_F16,
     MP_ETA_FIT | MP_LSK, MQ_LSK_COMP, ETA_FIT, LUT_PLAIN, 0,
     "fresnel_lsk_comp_rgb(@eta, @kappa, @lsk_a, @lsk_alpha, c)", SCENE(lsk_comp), NULL, "lsk-comp"},
    {"f82", EVAL_SCENE, "F0, F82", d_f82, s_f82, FRESNEL_BOUND_F82,
     q_f82, FRESNEL_BOUND_F82_Q15, F16(h_f82), FRESNEL_BOUND_F82_F16,
     MP_F0 | MP_F82, 0, ETA_FIT, LUT_PLAIN, 0, "fresnel_f82_rgb(@f0, @f82, c)", SCENE(f82), a_f82, "f82"},
    {"gulbrandsen", EVAL_SCENE, "r = F0, edge tint g", d_gulbrandsen, s_gulbrandsen, FRESNEL_BOUND_GULBRANDSEN,
     q_gulbrandsen, FRESNEL_BOUND_GULBRANDSEN_Q15, F16(h_gulbrandsen), FRESNEL_BOUND_GULBRANDSEN_F16,
     MP_GULB, 0, ETA_FIT, LUT_PLAIN, 0, "fresnel_gulbrandsen_rgb(@gulbrandsen_r, @gulbrandsen_g, c)",
     SCENE(gulbrandsen), NULL, "gulbrandsen"},
    {"cook-torrance", EVAL_SCENE, "F0 and the same eta, kappa as representative IOR", d_cook_torrance,
     s_cook_torrance, FRESNEL_BOUND_COOK_TORRANCE,
     q_cook_torrance, FRESNEL_BOUND_COOK_TORRANCE_Q15, F16(h_cook_torrance), FRESNEL_BOUND_COOK_TORRANCE_F16,
     MP_F0 | MP_CT, MQ_CT, ETA_FIT, LUT_PLAIN, 0, "fresnel_cook_torrance_rgb(@f0, @ct_eta, @ct_kappa, c)",
     SCENE(cook_torrance), NULL, "cook-torrance"},
    {"exact", EVAL_SCENE | MODEL_EXACT, "eta, kappa (dielectric form when kappa = 0)", d_exact, s_exact,
     FRESNEL_BOUND_CONDUCTOR, q_exact, FRESNEL_BOUND_CONDUCTOR_Q15, F16(h_exact), FRESNEL_BOUND_CONDUCTOR_F16,
     MP_ETA_FIT, MQ_IOR, ETA_FIT, LUT_PLAIN, 0, "fresnel_conductor_rgb(@eta, @kappa, c)", SCENE(conductor), NULL, "exact-conductor"},
    /* Metzgar's Gaussian-window and point-sampled eta, kappa: scene models
     * only; as functions of eta, kappa they are the exact conductor. */
    {"exact-gaussian", MODEL_SCENE | MODEL_EXACT, "eta', kappa' in a Gaussian window", d_conductor, s_conductor,
     FRESNEL_BOUND_CONDUCTOR, q_conductor, FRESNEL_BOUND_CONDUCTOR_Q15, F16(h_conductor), FRESNEL_BOUND_CONDUCTOR_F16,
     MP_ETA_GAUSS, MQ_IOR_GAUSS, ETA_GAUSS, LUT_PLAIN, 0, "fresnel_conductor_rgb(@eta_gaussian, @kappa_gaussian, c)",
     SCENE(conductor), NULL, "exact-conductor"},
    {"exact-point", MODEL_SCENE | MODEL_EXACT, "eta, kappa point-sampled", d_conductor, s_conductor,
     FRESNEL_BOUND_CONDUCTOR, q_conductor, FRESNEL_BOUND_CONDUCTOR_Q15, F16(h_conductor), FRESNEL_BOUND_CONDUCTOR_F16,
     MP_ETA_POINT, MQ_IOR_POINT, ETA_POINT, LUT_PLAIN, 0, "fresnel_conductor_rgb(@eta_point, @kappa_point, c)",
     SCENE(conductor), NULL, "exact-conductor"},
    {"exact-conductor", MODEL_EVAL | MODEL_EXACT, "eta, kappa (conductor form always)", d_conductor, s_conductor,
     FRESNEL_BOUND_CONDUCTOR, q_conductor, FRESNEL_BOUND_CONDUCTOR_Q15, F16(h_conductor), FRESNEL_BOUND_CONDUCTOR_F16,
     NO_SCENE},
    {"exact-dielectric", MODEL_EVAL | MODEL_EXACT, "eta (kappa ignored)", d_dielectric, s_dielectric,
     FRESNEL_BOUND_DIELECTRIC, q_dielectric, FRESNEL_BOUND_DIELECTRIC_Q15, F16(h_dielectric),
     FRESNEL_BOUND_DIELECTRIC_F16, NO_SCENE},
    {"approx-conductor", EVAL_SCENE, "eta, kappa", d_approx, s_approx, FRESNEL_BOUND_APPROX_CONDUCTOR,
     q_approx, FRESNEL_BOUND_APPROX_CONDUCTOR_Q15, F16(h_approx), FRESNEL_BOUND_APPROX_CONDUCTOR_F16,
     MP_ETA_FIT, MQ_NK, ETA_FIT, LUT_PLAIN, 0, "fresnel_approx_conductor_rgb(@eta, @kappa, c)", SCENE(approx), NULL, "approx-conductor"},
    {"schlick-internal", MODEL_EVAL, "F0, eta (eta < 1: from inside the denser medium)", d_internal,
     s_internal, FRESNEL_BOUND_SCHLICK_INTERNAL,
     q_internal, FRESNEL_BOUND_SCHLICK_INTERNAL_Q15, F16(h_internal), FRESNEL_BOUND_SCHLICK_INTERNAL_F16, NO_SCENE},
    /* A scene model only: a function of the film's index and thickness too. */
    {"thin-film", MODEL_SCENE | MODEL_FILM, "a film: its index (the scene's film key), its thickness (run time)",
     NULL, NULL, FRESNEL_BOUND_FILM, NULL, FRESNEL_BOUND_FILM_Q15, NULL, FRESNEL_BOUND_FILM_F16, 0, 0, ETA_FIT,
     LUT_PLAIN, 0, "FRESNEL_FILM_RGB_BODY(@thin_film, c, d_nm)", SCENE(film), NULL, "thin-film"},
};
const int model_count = (int)(sizeof model_table / sizeof model_table[0]);

/* The LUT forms: a family of scene models named by pattern, lutN (plain),
 * lutN-residual (from Schlick's F0) and lutN-cubic; one row per form and
 * node spacing, as the runtime has one function for each. */
#define LUT_ROW(name, reads, form, uniform, id, avg, cross) \
    {name, MODEL_SCENE | MODEL_LUT, "", NULL, NULL, 0.0f, NULL, 0.0, NULL, 0.0, reads, 0, ETA_FIT, form, uniform, NULL, SCENE(id), avg, cross}
static const model lut_table[] = {
    LUT_ROW("lutN", 0, LUT_PLAIN, 0, lut, a_lut, "lut u16"),
    LUT_ROW("lutN", 0, LUT_PLAIN, 1, lut_lin, a_lut_lin, "lut-linear u16"),
    LUT_ROW("lutN-residual", MP_F0, LUT_RESIDUAL, 0, lut_res, NULL, "lut-residual s16"),
    LUT_ROW("lutN-residual", MP_F0, LUT_RESIDUAL, 1, lut_lin_res, NULL, NULL),
    LUT_ROW("lutN-cubic", 0, LUT_CUBIC, 0, lut_cubic, a_lut_cubic, "lut-cubic u16"),
};
const char model_lut_patterns[] = "lutN lutN-residual lutN-cubic";

const char model_curve_default[] =
    "schlick lsk lsk-comp f82 gulbrandsen cook-torrance exact exact-gaussian approx-conductor lut16 lut32";
const char model_curve_film[] = "thin-film";
const char *const model_approaches_order[] = {"exact-gaussian", "exact-point", "schlick", "f82", "exact",
                                              "gulbrandsen", "lsk", "lsk-comp", "cook-torrance",
                                              "approx-conductor", "lut8", "lut16", "lut32", "lut16-residual",
                                              "lut16-cubic", "lut32-cubic", NULL};

const model *const model_schlick = &model_table[0];
const model *const model_exact = &model_table[7];
const model *const model_f82 = &model_table[4];
const model *const model_gulbrandsen = &model_table[5];
const model *const model_schlick_internal = &model_table[13];

const model *model_find_offered(const char *name, unsigned offered)
{
    int i;
    for (i = 0; i < model_count; i++)
        if ((model_table[i].offered & offered) == offered && !strcmp(model_table[i].name, name))
            return &model_table[i];
    return NULL;
}

const model *model_find(const char *name) { return model_find_offered(name, MODEL_EVAL); }

/* N for a LUT name (N in lo..hi), setting *form; 0 for every other string. */
static int lut_size(const char *name, int lo, int hi, lut_form *form)
{
    const char *p;
    int n = 0, digits = 0;
    size_t i;
    if (name == NULL || strncmp(name, "lut", 3) != 0)
        return 0;
    p = name + 3;
    if (*p == '0') /* one spelling per size, so duplicates are caught by name */
        return 0;
    while (isdigit((unsigned char)*p) && digits < 4) {
        n = n * 10 + (*p - '0');
        p++;
        digits++;
    }
    if (digits == 0 || n < lo || n > hi)
        return 0;
    /* the rest must be a LUT row's name after its "lutN" */
    for (i = 0; i < sizeof lut_table / sizeof lut_table[0]; i++)
        if (!strcmp(p, lut_table[i].name + 4)) {
            *form = lut_table[i].form;
            return n;
        }
    return 0;
}

const model *model_lut_row(lut_form form, lut_spacing spacing)
{
    int uniform = spacing == LUT_UNIFORM;
    size_t i;
    for (i = 0; i < sizeof lut_table / sizeof lut_table[0]; i++)
        if (lut_table[i].form == form && (lut_table[i].uniform == uniform || form == LUT_CUBIC))
            return &lut_table[i];
    return NULL;
}

const model *model_scene_parse(const char *name, lut_spacing spacing, int lo, int hi, int *lut_n)
{
    lut_form form;
    *lut_n = lut_size(name, lo, hi, &form);
    if (!name)
        return NULL;
    return *lut_n ? model_lut_row(form, spacing) : model_find_offered(name, MODEL_SCENE);
}

const char *model_shader_lacks(const model *row, lut_spacing spacing)
{
    if (row->offered & MODEL_LUT)
        return spacing == LUT_GRAZING_PL ? "grazing-pl tables are read by fresnel_lut_pl_u16_q15_fast, which the "
                                           "shader ports do not have"
                                         : NULL;
    return row->glsl ? NULL : "the shader ports have no function for it";
}

int model_names(unsigned offered, const char **out, int max)
{
    int i, n = 0;
    for (i = 0; i < model_count && n < max - 1; i++)
        if ((model_table[i].offered & offered) == offered)
            out[n++] = model_table[i].name;
    out[n] = NULL;
    return n;
}

void model_derive(double eta, double kappa, double n1, double f90, double p, model_params *out)
{
    memset(out, 0, sizeof *out);
    out->eta = eta / n1;
    out->kappa = kappa / n1;
    out->f0 = ref_f0_from_ior(out->eta, out->kappa);
    out->f82 = ref_conductor(out->eta, out->kappa, 1.0 / 7.0);
    out->f90 = f90;
    out->p = p;
    ref_lsk_fit(out->eta, out->kappa, &out->a, &out->alpha);
    ref_gulbrandsen_rg(out->eta, out->kappa, &out->r, &out->g);
}

void model_params_round_f32(model_params *m)
{
    double *fields[] = {&m->eta, &m->kappa, &m->f0, &m->f82, &m->f90,
                        &m->p,   &m->a,     &m->alpha, &m->r, &m->g};
    size_t i;
    for (i = 0; i < sizeof fields / sizeof fields[0]; i++)
        *fields[i] = (double)(float)*fields[i];
}

void model_params_round_fixed(model_params *m)
{
    fresnel_qf a;
    m->f0 = fixed_q15(m->f0) / 32768.0;
    m->f82 = fixed_q15(m->f82) / 32768.0;
    m->f90 = fixed_q15(m->f90) / 32768.0;
    /* r at its code, and at the fixed-point clamp (32764, the largest code
     * below fresnel.h's 0.9999) where the code is above it */
    m->r = (fixed_q15(m->r) < FRESNEL_GULBRANDSEN_R_MAX_Q15 ? fixed_q15(m->r) : FRESNEL_GULBRANDSEN_R_MAX_Q15) / 32768.0;
    m->g = fixed_q15(m->g) / 32768.0;
    m->p = fixed_q16(m->p) / 65536.0;
    m->alpha = fixed_q16(ref_clamp(m->alpha, 0.0, FRESNEL_ALPHA_MAX)) / 65536.0;
    a = fixed_qf(ref_clamp(m->a, 0.0, FRESNEL_A_MAX));
    m->a = fixed_qf_value(a);
}

void model_fixed_from_params(const model_params *m, model_fixed *out)
{
    memset(out, 0, sizeof *out);
    out->f0 = fixed_q15(m->f0);
    out->f82 = fixed_q15(m->f82);
    out->f90 = fixed_q15(m->f90);
    out->r = fixed_q15(m->r);
    out->g = fixed_q15(m->g);
    out->p = fixed_q16(m->p);
    fixed_ior(m->eta, m->kappa, &out->ior);
    fixed_ior(m->eta, 0.0, &out->dior);
    fixed_nk(m->eta, m->kappa, &out->nk);
    out->gnk = fresnel_gulbrandsen_nk_q15(out->r, out->g);
    fixed_lsk(m->eta, m->kappa, m->a, m->alpha, &out->lsk);
}

void model_params_round_f16(model_params *m)
{
#if FRESNEL_HAS_F16
    double *fields[] = {&m->eta, &m->kappa, &m->f0, &m->f82, &m->f90,
                        &m->p,   &m->a,     &m->alpha, &m->r, &m->g};
    size_t i;
    for (i = 0; i < sizeof fields / sizeof fields[0]; i++)
        *fields[i] = (double)(fresnel_f16)*fields[i];
#else
    (void)m;
#endif
}
