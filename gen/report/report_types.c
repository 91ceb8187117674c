/* The number types the report measures: each scene model's encoded
 * constants and tables (scene_model_rgb) in binary32, Q1.15 and binary16,
 * evaluated for accuracy (one cosine at a time) and timed (the registry
 * row's own batch loop, so no dispatch sits inside the timed loop). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "bench/bench.h"
#include "model/registry.h"
#include "report/report.h"

static void eval_f32(const model_rgb *q, double c, double rgb[3])
{
    fresnel_rgb v = q->def->rgb_f32(q, (float)c);
    rgb[0] = v.r;
    rgb[1] = v.g;
    rgb[2] = v.b;
}

static void eval_q15(const model_rgb *q, double c, double rgb[3])
{
    fresnel_rgb_q15 v = q->def->rgb_q15(q, (int32_t)lround(c * 32768.0));
    rgb[0] = v.r / 32768.0;
    rgb[1] = v.g / 32768.0;
    rgb[2] = v.b / 32768.0;
}

#if FRESNEL_HAS_F16
/* binary16: the row's scalar function channel by channel, as a shader would */
static void eval_f16(const model_rgb *q, double c, double rgb[3])
{
    int ch;
    for (ch = 0; ch < 3; ch++)
        rgb[ch] = q->def->ch_f16(q, ch, c);
}

static double batch_f16(const void *x, const float *c, const int32_t *cq, int n)
{
    const model_rgb *q = x;
    double sum = 0.0;
    int i, ch;
    (void)cq;
    for (i = 0; i < n; i++)
        for (ch = 0; ch < 3; ch++)
            sum += q->def->ch_f16(q, ch, c[i]);
    return sum;
}
#endif

double report_time(const report_type *t, const model_rgb *q, int n, int runs)
{
    bench_batch fn = !strcmp(t->name, "q15") ? q->def->batch_q15 : q->def->batch_f32;
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
