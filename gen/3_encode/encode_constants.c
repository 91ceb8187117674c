/* Stage 3, encode: a material's constants and a LUT's nodes in every number
 * type, the one conversion both the header and every evaluation read
 * (encode.h, THE ENCODER). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "2_derive/film_fit.h"
#include "3_encode/encode.h"
#include "3_encode/q15_params.h"

static fresnel_rgb f32_rgb(const double v[3])
{
    fresnel_rgb o;
    o.r = (float)v[0];
    o.g = (float)v[1];
    o.b = (float)v[2];
    return o;
}

static fresnel_rgb_q15 q15_rgb(const double v[3])
{
    fresnel_rgb_q15 o;
    o.r = (fresnel_q15)q15_code(v[0]);
    o.g = (fresnel_q15)q15_code(v[1]);
    o.b = (fresnel_q15)q15_code(v[2]);
    return o;
}

static const double *eta_source(const material_params *p, int source, int kappa)
{
    switch (source) {
    case ETA_GAUSS: return kappa ? p->kappa_gauss : p->eta_gauss;
    case ETA_POINT: return kappa ? p->kappa_point : p->eta_point;
    default: return kappa ? p->kappa_fit : p->eta_fit;
    }
}

#if FRESNEL_HAS_F16
static void f16_3(const double v[3], fresnel_f16 out[3])
{
    int ch;
    for (ch = 0; ch < 3; ch++)
        out[ch] = (fresnel_f16)v[ch];
}
#endif

/* One parameter in binary32, and in binary16 */
#define F32_3(v) f32_rgb(v)
#define F32_1(v) ((float)(v))
#define ENCODE_F32(field, count, group, constant, row, why, q15, q15_why) e->field = F32_##count(p->field);
#if FRESNEL_HAS_F16
#define F16_3(v, out) f16_3(v, out)
#define F16_1(v, out) (out = (fresnel_f16)(v))
#define ENCODE_F16(field, count, group, constant, row, why, q15, q15_why) F16_##count(p->field, e->h_##field);
#endif
/* The codes: held to one for Q15_CODE_HELD */
#define ENCODE_Q15_Q15_NONE(field)
#define ENCODE_Q15_Q15_CODE(field) e->q_##field = q15_rgb(p->field);
#define ENCODE_Q15_Q15_CODE_ONE(field) e->q_##field = q15_rgb(p->field);
#define ENCODE_Q15_Q15_CODE_HELD(field)                                                                                \
    {                                                                                                                  \
        double held[3];                                                                                                \
        for (ch = 0; ch < 3; ch++) {                                                                                   \
            held[ch] = p->field[ch] > 1.0 ? 1.0 : p->field[ch];                                                        \
            e->q_##field##_held |= p->field[ch] > 1.0;                                                                 \
        }                                                                                                              \
        e->q_##field = q15_rgb(held);                                                                                  \
    }
#define ENCODE_Q15(field, count, group, constant, row, why, q15, q15_why) ENCODE_Q15_##q15(field)

void encode_material(const material_params *p, encoded_material *e)
{
    int src, ch;
    memset(e, 0, sizeof *e);
    DERIVED_PARAMETERS(ENCODE_F32)
    DERIVED_PARAMETERS(ENCODE_Q15)
    q15_ior(p->ct_eta, p->ct_kappa, &e->q_ct);
    e->q_ior_fast_out = -1;
    for (ch = 0; ch < 3; ch++) {
        e->q_f82_a[ch] = q15_f82_a_q12(q15_code(p->f0[ch]), q15_code(p->f82[ch]));
        q15_lsk(p->eta_fit[ch], p->kappa_fit[ch], 0.0, 0.0, &e->q_lsk[ch]);
        q15_lsk(p->eta_fit[ch], p->kappa_fit[ch], p->lsk_a[ch], p->lsk_alpha[ch], &e->q_lsk_comp[ch]);
        q15_nk(p->eta_fit[ch], p->kappa_fit[ch], &e->q_nk[ch]);
        for (src = 0; src < ETA_SOURCES; src++)
            q15_ior(eta_source(p, src, 0)[ch], eta_source(p, src, 1)[ch], &e->q_ior[src][ch]);
        if (e->q_ior_fast_out < 0 && !q15_conductor_fast_in_domain(p->eta_fit[ch], p->kappa_fit[ch]))
            e->q_ior_fast_out = ch;
    }
    if (e->q_ior_fast_out < 0)
        for (ch = 0; ch < 3; ch++)
            q15_conductor_fast(p->eta_fit[ch], p->kappa_fit[ch], &e->q_ior_fast[ch]);

#if FRESNEL_HAS_F16
    DERIVED_PARAMETERS(ENCODE_F16)
#endif
}

void encode_curve_q15(const double *nodes, int count, uint16_t *codes)
{
    int i;
    for (i = 0; i < count; i++)
        codes[i] = (uint16_t)q15_code(nodes[i]);
}

/* round(v 2^frac) in int16_t, or 0 where it is not a number there. */
static int residual_code(double v, int frac, int16_t *code)
{
    double x = floor(v * ldexp(1.0, frac) + 0.5);
    if (!(x >= -32768.0 && x <= 32767.0)) {
        *code = 0;
        return -1;
    }
    *code = (int16_t)x;
    return 0;
}

void encoded_lut_free(encoded_lut *t)
{
    free(t->nodes);
    free(t->f32);
    free(t->q15);
    free(t->q15_res);
#if FRESNEL_HAS_F16
    free(t->f16);
#endif
    memset(t, 0, sizeof *t);
    t->bad = -1;
}

int encode_table(const spectrum *s, const gen_context *g, const material_params *p, lut_spacing spacing, int n,
                 lut_form form, encoded_lut *t)
{
    int count = 3 * n, i, residual = form == LUT_RESIDUAL;
    int16_t code;
    memset(t, 0, sizeof *t);
    t->n = n;
    t->form = form;
    t->spacing = spacing;
    t->bad = -1;
    t->nodes = malloc((size_t)count * sizeof *t->nodes);
    t->f32 = malloc((size_t)count * sizeof *t->f32);
    if (residual)
        t->q15_res = malloc((size_t)count * sizeof *t->q15_res);
    else
        t->q15 = malloc((size_t)count * sizeof *t->q15);
#if FRESNEL_HAS_F16
    t->f16 = malloc((size_t)count * sizeof *t->f16);
    if (!t->f16) {
        encoded_lut_free(t);
        return -1;
    }
#endif
    if (!t->nodes || !t->f32 || !(t->q15 || t->q15_res) || encode_lut(s, g, p, spacing, n, form, t->nodes)) {
        encoded_lut_free(t);
        return -1;
    }
    for (i = 0; i < count; i++) {
        double v = t->nodes[i];
        t->f32[i] = (float)v;
#if FRESNEL_HAS_F16
        t->f16[i] = (fresnel_f16)v;
#endif
        if (t->bad < 0 && (!isfinite(v) || (residual ? residual_code(v, 14, &code) != 0
                                                     : !(floor(v * 32768.0 + 0.5) >= 0.0 &&
                                                         floor(v * 32768.0 + 0.5) <= 65535.0))))
            t->bad = i;
    }
    if (!residual) {
        encode_curve_q15(t->nodes, count, t->q15);
        return 0;
    }
    /* the most fraction bits, in fresnel_q15.h's [14, 30], that keep every
     * rounded node inside int16_t; encode_lut holds the nodes to [-1, 1],
     * which frac 14 always holds */
    for (t->frac = 30; t->frac > 14; t->frac--) {
        for (i = 0; i < count && residual_code(t->nodes[i], t->frac, &code) == 0; i++)
            ;
        if (i == count)
            break;
    }
    for (i = 0; i < count; i++)
        residual_code(t->nodes[i], t->frac, &t->q15_res[i]);
    return 0;
}

/* The film tables are arrays of one type each (fresnel_film.h): a literal
 * of a float type must be finite (inf.0f does not compile). */
static int floats_finite(const float *v, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++)
        if (!isfinite(v[i]))
            return 0;
    return 1;
}
#if FRESNEL_HAS_F16
static int halves_finite(const fresnel_f16 *v, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++)
        if (!isfinite((double)v[i]))
            return 0;
    return 1;
}
#endif

int encode_film(const spectrum *s, const gen_context *g, const material_params *p, const film_model *poles,
                encoded_film *out)
{
    film_stack f;
    memset(out, 0, sizeof *out);
    if (!(p->film_n > 0.0))
        return -1;
    out->n_film = p->film_n;
    f.n1 = p->n1;
    f.film = NULL;
    f.film_n = p->film_n;
    f.substrate = s;
    if (film_stack_domain(&f, out->why, sizeof out->why))
        return -1;
    if (poles) {
        memcpy(out->model.nu, poles->nu, sizeof out->model.nu);
        memcpy(out->model.gamma, poles->gamma, sizeof out->model.gamma);
        memcpy(out->model.weight, poles->weight, sizeof out->model.weight);
    } else if (film_fit_poles(&g->cm, &g->cs, &out->model, NULL))
        return -1;
    if (film_fit_material(&f, &g->cm, &g->cs, &out->model))
        return -1;
    film_encode_f32(&out->model, &out->f32);
    film_decode_f32(&out->f32, &out->model_f32);
    out->q15_ok = film_encode_q15(&out->model, &out->q15) == 0;
    out->f32_finite = floats_finite((const float *)(const void *)&out->f32, sizeof out->f32 / sizeof(float));
#if FRESNEL_HAS_F16
    film_encode_f16(&out->model, &out->f16);
    out->f16_finite = halves_finite((const fresnel_f16 *)(const void *)&out->f16, sizeof out->f16 / sizeof(fresnel_f16));
#endif
    return 0;
}
