/* Every model row in the binary16 runtime (fresnel_f16.h, fresnel_film.h;
 * model/registry.h: model_eval_f16), one line per row in model_evals_f16:
 * parameters and c converted to binary16 here; scalar functions channel by
 * channel, as a shader would. Without _Float16 the table is empty. */
#include "model/registry.h"

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

/* ---- as scene models: the encoder's values of one material (model_rgb) */
#define M (q->mat)
#define L (q->lut)
#define E (q->def->eta)
#define FILM (q->film)
#define HC(fn_args) return (double)(fn_args)
static double rh_film(const model_rgb *q, int ch, double c)
{
    fresnel_rgb_f16 v = fresnel_film_f16_rgb(&FILM->f16, H(c), H(q->d_nm));
    return (double)(ch == 0 ? v.r : (ch == 1 ? v.g : v.b));
}
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

/* Timed loops, one per scene evaluator, channel by channel; the film's
 * runtime gives all three channels in one call. */
#define BATCH(id)                                                                                                      \
    static double batch_f16_##id(const void *x, const float *c, const int32_t *cq, int n)                              \
    {                                                                                                                  \
        const model_rgb *q = x;                                                                                        \
        double sum = 0.0;                                                                                              \
        int i, ch;                                                                                                     \
        (void)cq;                                                                                                      \
        for (i = 0; i < n; i++)                                                                                        \
            for (ch = 0; ch < 3; ch++)                                                                                 \
                sum += rh_##id(q, ch, c[i]);                                                                           \
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
#define SCENE(id) rh_##id, batch_f16_##id

const model_eval_f16 model_evals_f16[MODEL_ROWS] = {
    [MODEL_ROW_schlick] = {h_schlick, SCENE(schlick)},
    [MODEL_ROW_schlick_gen] = {h_schlick_gen, NULL, NULL},
    [MODEL_ROW_lsk] = {h_lsk, SCENE(lsk)},
    [MODEL_ROW_lsk_comp] = {h_lsk_comp, SCENE(lsk_comp)},
    [MODEL_ROW_f82] = {h_f82, SCENE(f82)},
    [MODEL_ROW_gulbrandsen] = {h_gulbrandsen, SCENE(gulbrandsen)},
    [MODEL_ROW_cook_torrance] = {h_cook_torrance, SCENE(cook_torrance)},
    [MODEL_ROW_exact] = {h_exact, SCENE(conductor)},
    [MODEL_ROW_exact_gaussian] = {h_conductor, SCENE(conductor)},
    [MODEL_ROW_exact_point] = {h_conductor, SCENE(conductor)},
    [MODEL_ROW_exact_conductor] = {h_conductor, NULL, NULL},
    [MODEL_ROW_exact_dielectric] = {h_dielectric, NULL, NULL},
    [MODEL_ROW_approx_conductor] = {h_approx, SCENE(approx)},
    [MODEL_ROW_schlick_internal] = {h_internal, NULL, NULL},
    [MODEL_ROW_thin_film] = {NULL, SCENE(film)},
    [MODEL_ROW_lut] = {NULL, SCENE(lut)},
    [MODEL_ROW_lut_linear] = {NULL, SCENE(lut_lin)},
    [MODEL_ROW_lut_residual] = {NULL, SCENE(lut_res)},
    [MODEL_ROW_lut_linear_residual] = {NULL, SCENE(lut_lin_res)},
    [MODEL_ROW_lut_cubic] = {NULL, SCENE(lut_cubic)},
};
#else
const model_eval_f16 model_evals_f16[MODEL_ROWS];
#endif
