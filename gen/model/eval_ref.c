/* Every model row's double reference (model/registry.h: model_eval_ref),
 * one line per row in model_evals_ref: as a function of eta, kappa, c, and
 * as a scene model on the binary32-rounded constants and nodes (the
 * difference from the binary32 evaluation is the runtime's rounding, not
 * the model's error). */
#include <math.h>

#include "common/reference.h"
#include "common/reference_film.h"
#include "model/registry.h"

static double d_schlick(const model_params *m, double c) { return ref_schlick(m->f0, c); }
static double d_schlick_gen(const model_params *m, double c)
{
    return ref_schlick_gen(m->f0, m->f90, m->p, c);
}
static double d_lsk(const model_params *m, double c) { return ref_lsk(m->eta, m->kappa, c); }
static double d_lsk_comp(const model_params *m, double c)
{
    return ref_lsk_comp(m->eta, m->kappa, m->a, m->alpha, c);
}
static double d_f82(const model_params *m, double c) { return ref_f82(m->f0, m->f82, c); }
static double d_gulbrandsen(const model_params *m, double c) { return ref_gulbrandsen(m->r, m->g, c); }
static double d_cook_torrance(const model_params *m, double c)
{
    return ref_cook_torrance(m->f0, m->eta, m->kappa, c);
}
/* kappa = 0 takes the dielectric function, as a caller who knows it would. */
static double d_exact(const model_params *m, double c)
{
    return m->kappa > 0.0 ? ref_conductor(m->eta, m->kappa, c) : ref_dielectric(m->eta, c);
}
static double d_conductor(const model_params *m, double c) { return ref_conductor(m->eta, m->kappa, c); }
static double d_dielectric(const model_params *m, double c) { return ref_dielectric(m->eta, c); }
static double d_approx(const model_params *m, double c)
{
    return ref_approx_conductor(m->eta, m->kappa, c);
}
static double d_internal(const model_params *m, double c)
{
    return ref_schlick_internal(m->f0, m->eta, c);
}

/* ---- as scene models: the encoder's values of one material (model_rgb) */
#define M (q->mat)
#define L (q->lut)
#define E (q->def->eta)
#define FILM (q->film)
#define ETA(q) encoded_eta((q)->mat, (q)->def->eta, 0)
#define KAPPA(q) encoded_eta((q)->mat, (q)->def->eta, 1)
static double ch3(fresnel_rgb v, int ch) { return ch == 0 ? v.r : (ch == 1 ? v.g : v.b); }
static double rr_schlick(const model_rgb *q, int ch, double c) { return ref_schlick(ch3(M->f0, ch), c); }
static double rr_lsk(const model_rgb *q, int ch, double c) { return ref_lsk(ch3(ETA(q), ch), ch3(KAPPA(q), ch), c); }
static double rr_lsk_comp(const model_rgb *q, int ch, double c)
{
    return ref_lsk_comp(ch3(ETA(q), ch), ch3(KAPPA(q), ch), ch3(M->lsk_a, ch), ch3(M->lsk_alpha, ch), c);
}
static double rr_f82(const model_rgb *q, int ch, double c) { return ref_f82(ch3(M->f0, ch), ch3(M->f82, ch), c); }
static double rr_gulbrandsen(const model_rgb *q, int ch, double c)
{
    return ref_gulbrandsen(ch3(M->gulb_r, ch), ch3(M->gulb_g, ch), c);
}
static double rr_cook_torrance(const model_rgb *q, int ch, double c)
{
    return ref_cook_torrance(ch3(M->f0, ch), M->ct_eta, M->ct_kappa, c);
}
static double rr_conductor(const model_rgb *q, int ch, double c)
{
    return ref_conductor(ch3(ETA(q), ch), ch3(KAPPA(q), ch), c);
}
static double rr_approx(const model_rgb *q, int ch, double c)
{
    return ref_approx_conductor(ch3(ETA(q), ch), ch3(KAPPA(q), ch), c);
}

/* LUTs: the reference interpolates the binary32-rounded nodes in double. */
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

/* The thin film: the binary32 table evaluated in double. */
static double rr_film(const model_rgb *q, int ch, double c)
{
    double rgb[3];
    ref_film_model(&FILM->model_f32, c, q->d_nm, 1, rgb);
    return rgb[ch];
}

const model_eval_ref model_evals_ref[MODEL_ROWS] = {
    [MODEL_ROW_schlick] = {d_schlick, rr_schlick},
    [MODEL_ROW_schlick_gen] = {d_schlick_gen, NULL},
    [MODEL_ROW_lsk] = {d_lsk, rr_lsk},
    [MODEL_ROW_lsk_comp] = {d_lsk_comp, rr_lsk_comp},
    [MODEL_ROW_f82] = {d_f82, rr_f82},
    [MODEL_ROW_gulbrandsen] = {d_gulbrandsen, rr_gulbrandsen},
    [MODEL_ROW_cook_torrance] = {d_cook_torrance, rr_cook_torrance},
    [MODEL_ROW_exact] = {d_exact, rr_conductor},
    [MODEL_ROW_exact_gaussian] = {d_conductor, rr_conductor},
    [MODEL_ROW_exact_point] = {d_conductor, rr_conductor},
    [MODEL_ROW_exact_conductor] = {d_conductor, NULL},
    [MODEL_ROW_exact_dielectric] = {d_dielectric, NULL},
    [MODEL_ROW_approx_conductor] = {d_approx, rr_approx},
    [MODEL_ROW_schlick_internal] = {d_internal, NULL},
    [MODEL_ROW_thin_film] = {NULL, rr_film},
    [MODEL_ROW_lut] = {NULL, rr_lut},
    [MODEL_ROW_lut_linear] = {NULL, rr_lut_lin},
    [MODEL_ROW_lut_residual] = {NULL, rr_lut_res},
    [MODEL_ROW_lut_linear_residual] = {NULL, rr_lut_lin_res},
    [MODEL_ROW_lut_cubic] = {NULL, rr_lut_cubic},
};
