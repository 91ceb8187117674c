/* Every model row in the binary32 runtime (fresnel.h, fresnel_film.h;
 * model/registry.h: model_eval_f32), one line per row in model_evals_f32. */
#include "model/registry.h"

#define F(x) ((float)(x))

static float s_schlick(const model_params *m, float c) { return fresnel_schlick(F(m->f0), c); }
static float s_schlick_gen(const model_params *m, float c)
{
    return fresnel_schlick_gen(F(m->f0), F(m->f90), F(m->p), c);
}
static float s_lsk(const model_params *m, float c) { return fresnel_lsk(F(m->eta), F(m->kappa), c); }
static float s_lsk_comp(const model_params *m, float c)
{
    return fresnel_lsk_comp(F(m->eta), F(m->kappa), F(m->a), F(m->alpha), c);
}
static float s_f82(const model_params *m, float c) { return fresnel_f82(F(m->f0), F(m->f82), c); }
static float s_gulbrandsen(const model_params *m, float c)
{
    return fresnel_gulbrandsen(F(m->r), F(m->g), c);
}
static float s_cook_torrance(const model_params *m, float c)
{
    return fresnel_cook_torrance(F(m->f0), F(m->eta), F(m->kappa), c);
}
/* kappa = 0 takes the dielectric function, as a caller who knows it would. */
static float s_exact(const model_params *m, float c)
{
    return m->kappa > 0.0 ? fresnel_conductor(F(m->eta), F(m->kappa), c)
                          : fresnel_dielectric(F(m->eta), c);
}
static float s_conductor(const model_params *m, float c)
{
    return fresnel_conductor(F(m->eta), F(m->kappa), c);
}
static float s_dielectric(const model_params *m, float c) { return fresnel_dielectric(F(m->eta), c); }
static float s_approx(const model_params *m, float c)
{
    return fresnel_approx_conductor(F(m->eta), F(m->kappa), c);
}
static float s_internal(const model_params *m, float c)
{
    return fresnel_schlick_internal(F(m->f0), F(m->eta), c);
}

/* ---- as scene models: the encoder's values of one material (model_rgb) */
#define M (q->mat)
#define L (q->lut)
#define E (q->def->eta)
#define FILM (q->film)
#define ETA(q) encoded_eta((q)->mat, (q)->def->eta, 0)
#define KAPPA(q) encoded_eta((q)->mat, (q)->def->eta, 1)
static fresnel_rgb r_schlick(const model_rgb *q, float c) { return fresnel_schlick_rgb(M->f0, c); }
static fresnel_rgb r_lsk(const model_rgb *q, float c) { return fresnel_lsk_rgb(ETA(q), KAPPA(q), c); }
static fresnel_rgb r_lsk_comp(const model_rgb *q, float c)
{
    return fresnel_lsk_comp_rgb(ETA(q), KAPPA(q), M->lsk_a, M->lsk_alpha, c);
}
static fresnel_rgb r_f82(const model_rgb *q, float c) { return fresnel_f82_rgb(M->f0, M->f82, c); }
static fresnel_rgb r_gulbrandsen(const model_rgb *q, float c) { return fresnel_gulbrandsen_rgb(M->gulb_r, M->gulb_g, c); }
static fresnel_rgb r_cook_torrance(const model_rgb *q, float c)
{
    return fresnel_cook_torrance_rgb(M->f0, M->ct_eta, M->ct_kappa, c);
}
static fresnel_rgb r_conductor(const model_rgb *q, float c) { return fresnel_conductor_rgb(ETA(q), KAPPA(q), c); }
static fresnel_rgb r_approx(const model_rgb *q, float c) { return fresnel_approx_conductor_rgb(ETA(q), KAPPA(q), c); }

/* LUTs: the table as the runtime reads it. */
static fresnel_rgb r_lut(const model_rgb *q, float c) { return fresnel_lut_rgb(L->f32, L->n, c); }
static fresnel_rgb r_lut_lin(const model_rgb *q, float c) { return fresnel_lut_linear_rgb(L->f32, L->n, c); }
static fresnel_rgb r_lut_res(const model_rgb *q, float c) { return fresnel_lut_residual_rgb(M->f0, L->f32, L->n, c); }
static fresnel_rgb r_lut_lin_res(const model_rgb *q, float c)
{
    return fresnel_lut_linear_residual_rgb(M->f0, L->f32, L->n, c);
}
static fresnel_rgb r_lut_cubic(const model_rgb *q, float c) { return fresnel_lut_cubic_rgb(L->f32, L->n, c); }
/* The thin film: the material's table at the thickness model_rgb holds. */
static fresnel_rgb r_film(const model_rgb *q, float c) { return fresnel_film_rgb(&FILM->f32, c, (float)q->d_nm); }

/* The runtime's closed-form hemispherical averages. */
static fresnel_rgb a_schlick(const model_rgb *q) { return fresnel_schlick_avg_rgb(M->f0); }
static fresnel_rgb a_f82(const model_rgb *q) { return fresnel_f82_avg_rgb(M->f0, M->f82); }
static fresnel_rgb a_lut(const model_rgb *q) { return fresnel_lut_avg_rgb(L->f32, L->n); }
static fresnel_rgb a_lut_lin(const model_rgb *q) { return fresnel_lut_linear_avg_rgb(L->f32, L->n); }
static fresnel_rgb a_lut_cubic(const model_rgb *q) { return fresnel_lut_cubic_avg_rgb(L->f32, L->n); }

/* Timed loops, one per scene evaluator, calling it directly; named
 * batch_* because `fresnel report` counts instructions inside them
 * (callgrind --toggle-collect). */
#define BATCH(id)                                                                                                      \
    static double batch_f32_##id(const void *x, const float *c, const int32_t *cq, int n)                              \
    {                                                                                                                  \
        const model_rgb *q = x;                                                                                        \
        double sum = 0.0;                                                                                              \
        int i;                                                                                                         \
        (void)cq;                                                                                                      \
        for (i = 0; i < n; i++) {                                                                                      \
            fresnel_rgb v = r_##id(q, c[i]);                                                                           \
            sum += v.r + v.g + v.b;                                                                                    \
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
#define SCENE(id) r_##id, batch_f32_##id

const model_eval_f32 model_evals_f32[MODEL_ROWS] = {
    [MODEL_ROW_schlick] = {s_schlick, SCENE(schlick), a_schlick},
    [MODEL_ROW_schlick_gen] = {s_schlick_gen, NULL, NULL, NULL},
    [MODEL_ROW_lsk] = {s_lsk, SCENE(lsk), NULL},
    [MODEL_ROW_lsk_comp] = {s_lsk_comp, SCENE(lsk_comp), NULL},
    [MODEL_ROW_f82] = {s_f82, SCENE(f82), a_f82},
    [MODEL_ROW_gulbrandsen] = {s_gulbrandsen, SCENE(gulbrandsen), NULL},
    [MODEL_ROW_cook_torrance] = {s_cook_torrance, SCENE(cook_torrance), NULL},
    [MODEL_ROW_exact] = {s_exact, SCENE(conductor), NULL},
    [MODEL_ROW_exact_gaussian] = {s_conductor, SCENE(conductor), NULL},
    [MODEL_ROW_exact_point] = {s_conductor, SCENE(conductor), NULL},
    [MODEL_ROW_exact_conductor] = {s_conductor, NULL, NULL, NULL},
    [MODEL_ROW_exact_dielectric] = {s_dielectric, NULL, NULL, NULL},
    [MODEL_ROW_approx_conductor] = {s_approx, SCENE(approx), NULL},
    [MODEL_ROW_schlick_internal] = {s_internal, NULL, NULL, NULL},
    [MODEL_ROW_thin_film] = {NULL, SCENE(film), NULL},
    [MODEL_ROW_lut] = {NULL, SCENE(lut), a_lut},
    [MODEL_ROW_lut_linear] = {NULL, SCENE(lut_lin), a_lut_lin},
    [MODEL_ROW_lut_residual] = {NULL, SCENE(lut_res), NULL},
    [MODEL_ROW_lut_linear_residual] = {NULL, SCENE(lut_lin_res), NULL},
    [MODEL_ROW_lut_cubic] = {NULL, SCENE(lut_cubic), a_lut_cubic},
};
