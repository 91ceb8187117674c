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
#define F16_EVAL eval_f16, batch_f16, has_f16, model_params_round_f16, params_f16
#else
#define F16_EVAL NULL, NULL, NULL, NULL, NULL
#endif
static double bound_f16(const model *row) { return row->f16_bound; }

const number_type number_types[NUMBER_TYPES] = {
    {TYPE_F32, "f32", NULL, "fresnel.h", "binary32 (fresnel.h)", 1, 0x1p-149, eval_f32, batch_f32, has_f32,
     model_params_round_f32, params_f32, bound_f32},
    {TYPE_Q15, "q15", "fixed", "fresnel_q15.h", "Q1.15 fixed point (fresnel_q15.h)", 1, 0x1p-15, eval_q15,
     batch_q15, has_q15, model_params_round_q15, params_q15, bound_q15},
    {TYPE_F16, "f16", NULL, "fresnel_f16.h", "binary16 (fresnel_f16.h; where the compiler has _Float16)",
     FRESNEL_HAS_F16, 0x1p-24, F16_EVAL, bound_f16},
};
const int number_types_available = NUMBER_TYPES - !FRESNEL_HAS_F16;

const number_type *number_type_find(const char *name)
{
    int i;
    for (i = 0; name && i < NUMBER_TYPES; i++)
        if (!strcmp(number_types[i].name, name) || (number_types[i].alias && !strcmp(number_types[i].alias, name)))
            return &number_types[i];
    return NULL;
}

int number_type_names(const char **out, int max)
{
    int i, n = 0;
    for (i = 0; i < number_types_available && n < max - 1; i++)
        out[n++] = number_types[i].name;
    out[n] = NULL;
    return n;
}
