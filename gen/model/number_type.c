/* The number type registry (number_type.h): one row per number type. */
#include "model/number_type.h"

#include <math.h>
#include <string.h>

#include "3_encode/q15_params.h"
#include "common/reference.h"
#include "fresnel.h"
#include "fresnel_f16.h"
#include "fresnel_q15.h"

static void eval_f32(const model_rgb *q, double c, double rgb[3])
{
    fresnel_rgb v = q->def->f32->scene(q, (float)c);
    rgb[0] = v.r;
    rgb[1] = v.g;
    rgb[2] = v.b;
}
static model_batch batch_f32(const model *row) { return row->f32->batch; }
static int has_f32(const model *row) { return (row->offered & MODEL_EVAL) && row->f32->scalar != NULL; }
static double params_f32(const model *row, const model_params *p, double c) { return row->f32->scalar(p, (float)c); }
static double bound_f32(const model *row) { return row->bound; }

/* c as its Q1.15 code: round(c 32768) */
static void eval_q15(const model_rgb *q, double c, double rgb[3])
{
    fresnel_rgb_q15 v = q->def->q15->scene(q, (int32_t)lround(c * 32768.0));
    rgb[0] = v.r / 32768.0;
    rgb[1] = v.g / 32768.0;
    rgb[2] = v.b / 32768.0;
}
static model_batch batch_q15(const model *row) { return row->q15->batch; }
static int has_q15(const model *row) { return (row->offered & MODEL_EVAL) && row->q15->scalar != NULL; }
static double params_q15(const model *row, const model_params *p, double c)
{
    model_q15 q;
    model_q15_from_params(p, &q);
    return row->q15->scalar(&q, q15_code(c)) / 32768.0;
}
static double bound_q15(const model *row) { return row->q15_bound / 32768.0; }

#if FRESNEL_HAS_F16
/* binary16: the row's scalar function channel by channel, as a shader would */
static void eval_f16(const model_rgb *q, double c, double rgb[3])
{
    int ch;
    for (ch = 0; ch < 3; ch++)
        rgb[ch] = q->def->f16->scene(q, ch, c);
}
static model_batch batch_f16(const model *row) { return row->f16->batch; }
static int has_f16(const model *row) { return (row->offered & MODEL_EVAL) && row->f16->scalar != NULL; }
static double params_f16(const model *row, const model_params *p, double c) { return row->f16->scalar(p, c); }
#define TYPE_EVALS_F16_AVAILABLE .eval = eval_f16, .batch = batch_f16, .has = has_f16, .round = model_params_round_f16, .eval_params = params_f16,
#else
#define TYPE_EVALS_F16_AVAILABLE
#endif
static double bound_f16(const model *row) { return row->f16_bound; }

/* ---- where each type's runtime clamps, how it takes a cosine, and the F82
 * model and Gulbrandsen called directly (`fresnel extremes`). */

static double direct_ref(int gulbrandsen, float a, float b, float c)
{
    return gulbrandsen ? ref_gulbrandsen(a, b, c) : ref_f82(a, b, c);
}

static int clamp_f32(model_params *p)
{
    (void)p; /* the binary32 functions take any eta, kappa and clamp inside */
    return 1;
}
static int cosine_f32(double x, double *seen)
{
    *seen = (float)x;
    return 1;
}
static double at_f32(const model *row, const model_params *p, const model_q15 *q, double seen)
{
    (void)q;
    return row->f32->scalar(p, (float)seen);
}
static int direct_f32(int gulbrandsen, float *a, float *b, float *c, double *got)
{
    *got = gulbrandsen ? fresnel_gulbrandsen(*a, *b, *c) : fresnel_f82(*a, *b, *c);
    return 1;
}

/* round(x 32768) saturated to int32 (+-Inf to the extreme codes). */
static int32_t saturated_q15_code(double x)
{
    if (x >= 2147483647.0 / 32768.0)
        return INT32_MAX;
    if (x <= -2147483648.0 / 32768.0)
        return INT32_MIN;
    return (int32_t)floor(x * 32768.0 + 0.5);
}
/* Gulbrandsen's r is clamped to the largest code below 0.9999, not to
 * 0.9999 itself: the reference gets the same r. */
static int clamp_q15(model_params *p)
{
    p->r = ref_clamp(p->r, 0.0, FRESNEL_GULBRANDSEN_R_MAX_Q15 / 32768.0);
    return 1;
}
static int cosine_q15(double x, double *seen)
{
    if (x != x)
        return 0;
    *seen = saturated_q15_code(x) / 32768.0;
    return 1;
}
static double at_q15(const model *row, const model_params *p, const model_q15 *q, double seen)
{
    (void)p;
    return row->q15->scalar(q, (int32_t)(seen * 32768.0)) / 32768.0;
}
static int direct_q15(int gulbrandsen, float *a, float *b, float *c, double *got)
{
    int32_t qa, qb, qc;
    if (*a != *a || *b != *b)
        return 0;
    qa = saturated_q15_code(*a), qb = saturated_q15_code(*b), qc = saturated_q15_code(*c);
    *got = (gulbrandsen ? fresnel_gulbrandsen_q15(qa, qb, qc) : fresnel_f82_q15(qa, qb, qc)) / 32768.0;
    /* Gulbrandsen: r clamped as the Q15 runtime clamps it */
    *a = (float)(ref_clamp(qa, 0.0, gulbrandsen ? FRESNEL_GULBRANDSEN_R_MAX_Q15 : 32768.0) / 32768.0);
    *b = (float)(ref_clamp(qb, 0.0, 32768.0) / 32768.0);
    *c = (float)(qc / 32768.0);
    return 1;
}

#if FRESNEL_HAS_F16
/* fresnel_gulbrandsen_f16 clamps r to the largest half below 1. */
#define F16_GULBRANDSEN_R_MAX (1.0 - 0x1p-11)
/* eta and kappa outside the binary16 domain are clamped to it, as
 * fresnel_f16.h's functions clamp them; and its domains of r, p, a, alpha. */
static int clamp_f16(model_params *p)
{
    double eta = ref_clamp(p->eta, FRESNEL_ETA_MIN_F16, FRESNEL_ETA_MAX_F16);
    double kappa = ref_clamp(p->kappa, 0.0, FRESNEL_KAPPA_MAX_F16);
    int inside = eta == p->eta && kappa == p->kappa;
    p->eta = eta;
    p->kappa = kappa;
    p->r = ref_clamp(p->r, 0.0, F16_GULBRANDSEN_R_MAX);
    p->p = ref_clamp(p->p, FRESNEL_P_MIN_F16, FRESNEL_P_MAX_F16);
    p->a = ref_clamp(p->a, 0.0, 64.0);
    p->alpha = ref_clamp(p->alpha, 0.0, FRESNEL_P_MAX_F16);
    return inside;
}
static int cosine_f16(double x, double *seen)
{
    *seen = (double)(fresnel_f16)x;
    return 1;
}
static double at_f16(const model *row, const model_params *p, const model_q15 *q, double seen)
{
    (void)q;
    return row->f16->scalar(p, seen);
}
static int direct_f16(int gulbrandsen, float *a, float *b, float *c, double *got)
{
    fresnel_f16 ha = (fresnel_f16)*a, hb = (fresnel_f16)*b, hc = (fresnel_f16)*c;
    *got = (double)(gulbrandsen ? fresnel_gulbrandsen_f16(ha, hb, hc) : fresnel_f82_f16(ha, hb, hc));
    *a = gulbrandsen ? (float)ref_clamp((float)ha, 0.0, F16_GULBRANDSEN_R_MAX) : (float)ha;
    *b = (float)hb;
    *c = (float)hc;
    return 1;
}
/* fresnel_gulbrandsen_f16 clamps n and k to the binary16 domain. */
static double direct_ref_f16(int gulbrandsen, float a, float b, float c)
{
    double n, k;
    if (!gulbrandsen)
        return ref_f82(a, b, c);
    ref_gulbrandsen_nk(a, b, &n, &k);
    return ref_approx_conductor(ref_clamp(n, FRESNEL_ETA_MIN_F16, FRESNEL_ETA_MAX_F16),
                                ref_clamp(k, 0.0, FRESNEL_KAPPA_MAX_F16), c);
}
#define TYPE_EXTREMES_F16 .clamp = clamp_f16, .cosine = cosine_f16, .at = at_f16, .direct = direct_f16, \
                          .direct_ref = direct_ref_f16,
#else
#define TYPE_EXTREMES_F16
#endif

#define TYPE_EVALS_F32                                                                                                 \
    .eval = eval_f32, .batch = batch_f32, .has = has_f32, .round = model_params_round_f32, .eval_params = params_f32, \
    .bound = bound_f32, .clamp = clamp_f32, .cosine = cosine_f32, .at = at_f32, .direct = direct_f32,              \
    .direct_ref = direct_ref
#define TYPE_EVALS_Q15                                                                                                 \
    .eval = eval_q15, .batch = batch_q15, .has = has_q15, .round = model_params_round_q15, .eval_params = params_q15, \
    .bound = bound_q15, .clamp = clamp_q15, .cosine = cosine_q15, .at = at_q15, .direct = direct_q15,              \
    .direct_ref = direct_ref
#define TYPE_EVALS_F16 TYPE_EVALS_F16_AVAILABLE TYPE_EXTREMES_F16 .bound = bound_f16
#define ROW(ID, ...) {.id = TYPE_##ID, __VA_ARGS__, TYPE_EVALS_##ID},
const number_type number_types[NUMBER_TYPES] = {NUMBER_TYPE_CATALOG(ROW)};
#undef ROW

const number_type *number_type_find(const char *name)
{
    int id = number_type_parse(name);
    return id < 0 ? NULL : &number_types[id];
}
