/* Every model row in the Q1.15 runtime (fresnel_q15.h, fresnel_film.h;
 * model/registry.h: model_eval_q15), one line per row in model_evals_q15:
 * as a function of eta, kappa, c on the prepared constants
 * model_q15_from_params gives, and as a scene model on the encoder's
 * codes and tables. */
#include <math.h>

#include "model/registry.h"

static int32_t q_schlick(const model_q15 *m, int32_t c) { return fresnel_schlick_q15(m->f0, c); }
static int32_t q_schlick_gen(const model_q15 *m, int32_t c)
{
    return fresnel_schlick_gen_q15(m->f0, m->f90, m->p, c);
}
static int32_t q_lsk(const model_q15 *m, int32_t c) { return fresnel_lsk_q15(&m->lsk, c); }
static int32_t q_lsk_comp(const model_q15 *m, int32_t c) { return fresnel_lsk_comp_q15(&m->lsk, c); }
static int32_t q_f82(const model_q15 *m, int32_t c) { return fresnel_f82_q15(m->f0, m->f82, c); }
/* fresnel_gulbrandsen_q15 maps r, g each call; the prepared n, k give the same codes */
static int32_t q_gulbrandsen(const model_q15 *m, int32_t c) { return fresnel_approx_conductor_q15(&m->gnk, c); }
static int32_t q_cook_torrance(const model_q15 *m, int32_t c)
{
    return fresnel_cook_torrance_q15(m->f0, &m->ior, c);
}
static int32_t q_exact(const model_q15 *m, int32_t c)
{
    return m->ior.b.m ? fresnel_conductor_q15(&m->ior, c) : fresnel_dielectric_q15(&m->ior, c);
}
static int32_t q_conductor(const model_q15 *m, int32_t c) { return fresnel_conductor_q15(&m->ior, c); }
static int32_t q_dielectric(const model_q15 *m, int32_t c) { return fresnel_dielectric_q15(&m->dior, c); }
static int32_t q_approx(const model_q15 *m, int32_t c) { return fresnel_approx_conductor_q15(&m->nk, c); }
static int32_t q_internal(const model_q15 *m, int32_t c)
{
    return fresnel_schlick_internal_q15(m->f0, &m->dior, c);
}

/* ---- as scene models: the encoder's values of one material (model_rgb) */
#define M (q->mat)
#define L (q->lut)
#define E (q->def->eta)
#define FILM (q->film)
static fresnel_rgb_q15 rq_schlick(const model_rgb *q, int32_t c) { return fresnel_schlick_q15_rgb(M->q_f0, c); }
static fresnel_rgb_q15 rq_lsk(const model_rgb *q, int32_t c) { return fresnel_lsk_q15_rgb(M->q_lsk, c); }
static fresnel_rgb_q15 rq_lsk_comp(const model_rgb *q, int32_t c) { return fresnel_lsk_comp_q15_rgb(M->q_lsk_comp, c); }
static fresnel_rgb_q15 rq_f82(const model_rgb *q, int32_t c) { return fresnel_f82_q15_rgb(M->q_f0, M->q_f82, c); }
static fresnel_rgb_q15 rq_gulbrandsen(const model_rgb *q, int32_t c) { return fresnel_gulbrandsen_q15_rgb(M->q_gulb_r, M->q_gulb_g, c); }
static fresnel_rgb_q15 rq_cook_torrance(const model_rgb *q, int32_t c)
{
    return fresnel_cook_torrance_q15_rgb(M->q_f0, &M->q_ct, c);
}
static fresnel_rgb_q15 rq_conductor(const model_rgb *q, int32_t c) { return fresnel_conductor_q15_rgb(M->q_ior[E], c); }
static fresnel_rgb_q15 rq_approx(const model_rgb *q, int32_t c) { return fresnel_approx_conductor_q15_rgb(M->q_nk, c); }
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
/* The film at d as Q16.16 nm, held to int32_t (the runtime clamps it to its range) */
static fresnel_rgb_q15 rq_film(const model_rgb *q, int32_t c)
{
    static const fresnel_rgb_q15 none = {0, 0, 0};
    double d = floor(q->d_nm * 65536.0 + 0.5);
    int32_t dq = d >= 2147483647.0 ? INT32_MAX : (d > 0.0 ? (int32_t)d : 0);
    return FILM->q15_ok ? fresnel_film_q15_rgb(&FILM->q15, c, dq) : none;
}

/* Timed loops, one per scene evaluator, calling it directly; named
 * batch_* because `fresnel report` counts instructions inside them
 * (callgrind --toggle-collect). */
#define BATCH(id)                                                                                                      \
    static double batch_q15_##id(const void *x, const float *c, const int32_t *cq, int n)                              \
    {                                                                                                                  \
        const model_rgb *q = x;                                                                                        \
        uint32_t sum = 0;                                                                                              \
        int i;                                                                                                         \
        (void)c;                                                                                                       \
        for (i = 0; i < n; i++) {                                                                                      \
            fresnel_rgb_q15 v = rq_##id(q, cq[i]);                                                                     \
            sum += (uint32_t)v.r + v.g + v.b;                                                                          \
        }                                                                                                              \
        return sum;                                                                                                    \
    }
BATCH(schlick)
BATCH(lsk)
BATCH(lsk_comp)
BATCH(f82)
BATCH(gulbrandsen)
BATCH(cook_torrance)
BATCH(conductor)
BATCH(approx)
BATCH(lut)
BATCH(lut_lin)
BATCH(lut_res)
BATCH(lut_lin_res)
BATCH(lut_cubic)
BATCH(film)
#define SCENE(id) rq_##id, batch_q15_##id

const model_eval_q15 model_evals_q15[MODEL_ROWS] = {
    [MODEL_ROW_schlick] = {q_schlick, SCENE(schlick)},
    [MODEL_ROW_schlick_gen] = {q_schlick_gen, NULL, NULL},
    [MODEL_ROW_lsk] = {q_lsk, SCENE(lsk)},
    [MODEL_ROW_lsk_comp] = {q_lsk_comp, SCENE(lsk_comp)},
    [MODEL_ROW_f82] = {q_f82, SCENE(f82)},
    [MODEL_ROW_gulbrandsen] = {q_gulbrandsen, SCENE(gulbrandsen)},
    [MODEL_ROW_cook_torrance] = {q_cook_torrance, SCENE(cook_torrance)},
    [MODEL_ROW_exact] = {q_exact, SCENE(conductor)},
    [MODEL_ROW_exact_gaussian] = {q_conductor, SCENE(conductor)},
    [MODEL_ROW_exact_point] = {q_conductor, SCENE(conductor)},
    [MODEL_ROW_exact_conductor] = {q_conductor, NULL, NULL},
    [MODEL_ROW_exact_dielectric] = {q_dielectric, NULL, NULL},
    [MODEL_ROW_approx_conductor] = {q_approx, SCENE(approx)},
    [MODEL_ROW_schlick_internal] = {q_internal, NULL, NULL},
    [MODEL_ROW_thin_film] = {NULL, SCENE(film)},
    [MODEL_ROW_lut] = {NULL, SCENE(lut)},
    [MODEL_ROW_lut_linear] = {NULL, SCENE(lut_lin)},
    [MODEL_ROW_lut_residual] = {NULL, SCENE(lut_res)},
    [MODEL_ROW_lut_linear_residual] = {NULL, SCENE(lut_lin_res)},
    [MODEL_ROW_lut_cubic] = {NULL, SCENE(lut_cubic)},
};
