/* The number type registry (number_type.h): one row per number type. */
#include "model/number_type.h"

#include <math.h>
#include <string.h>

#include "3_encode/q15_params.h"
#include "fresnel_f16.h"

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

#define TYPE_EVALS_F32                                                                                                 \
    .eval = eval_f32, .batch = batch_f32, .has = has_f32, .round = model_params_round_f32, .eval_params = params_f32, \
    .bound = bound_f32
#define TYPE_EVALS_Q15                                                                                                 \
    .eval = eval_q15, .batch = batch_q15, .has = has_q15, .round = model_params_round_q15, .eval_params = params_q15, \
    .bound = bound_q15
#define TYPE_EVALS_F16 TYPE_EVALS_F16_AVAILABLE .bound = bound_f16
#define ROW(ID, ...) {.id = TYPE_##ID, __VA_ARGS__, TYPE_EVALS_##ID},
const number_type number_types[NUMBER_TYPES] = {NUMBER_TYPE_CATALOG(ROW)};
#undef ROW

const number_type *number_type_find(const char *name)
{
    int id = number_type_parse(name);
    return id < 0 ? NULL : &number_types[id];
}
