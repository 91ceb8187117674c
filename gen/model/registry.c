/* The model registry (registry.h): one row per model. */
#include "model/registry.h"

#include <ctype.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <math.h>

#include "3_encode/q15_params.h"
#include "fresnel.h"
#include "fresnel_f16.h"
#include "fresnel_film.h"
#include "common/reference.h"
#include "common/reference_film.h"

/* A catalog row (catalog/models.h) and its evaluators in every type. */
#define ROW(id, ...)                                                                                                   \
    {__VA_ARGS__, .ref = &model_evals_ref[MODEL_ROW_##id], .f32 = &model_evals_f32[MODEL_ROW_##id],                   \
     .q15 = &model_evals_q15[MODEL_ROW_##id], .f16 = &model_evals_f16[MODEL_ROW_##id]},

const model model_table[MODEL_ROWS] = {MODEL_CATALOG(ROW) LUT_CATALOG(ROW)};
const int model_count = MODEL_ROW_FIRST_LUT;

const char model_lut_patterns[] = "lutN lutN-residual lutN-cubic";

const char model_curve_default[] =
    "schlick lsk lsk-comp f82 gulbrandsen cook-torrance exact exact-gaussian approx-conductor lut16 lut32";
const char model_curve_film[] = "thin-film";
const char *const model_approaches_order[] = {"exact-gaussian", "exact-point", "schlick", "f82", "exact",
                                              "gulbrandsen", "lsk", "lsk-comp", "cook-torrance",
                                              "approx-conductor", "lut8", "lut16", "lut32", "lut16-residual",
                                              "lut16-cubic", "lut32-cubic", NULL};

const model *const model_schlick = &model_table[MODEL_ROW_schlick];
const model *const model_exact = &model_table[MODEL_ROW_exact];
const model *const model_f82 = &model_table[MODEL_ROW_f82];
const model *const model_gulbrandsen = &model_table[MODEL_ROW_gulbrandsen];
const model *const model_schlick_internal = &model_table[MODEL_ROW_schlick_internal];

const model *model_find_offered(const char *name, unsigned offered)
{
    int i;
    for (i = 0; i < model_count; i++)
        if ((model_table[i].offered & offered) == offered && !strcmp(model_table[i].name, name))
            return &model_table[i];
    return NULL;
}

const model *model_find(const char *name) { return model_find_offered(name, MODEL_EVAL); }

const model *model_of(model_row_id id) { return &model_table[id]; }

const char *model_shader_lacks(const model *row, lut_spacing spacing)
{
    if (row->offered & MODEL_LUT)
        return spacing == LUT_GRAZING_PL ? "grazing-pl tables are read by fresnel_lut_pl_u16_q15_fast, which the "
                                           "shader ports do not have"
                                         : NULL;
    return row->glsl ? NULL : "the shader ports have no function for it";
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

void model_params_round_q15(model_params *m)
{
    fresnel_qf a;
    m->f0 = q15_code(m->f0) / 32768.0;
    m->f82 = q15_code(m->f82) / 32768.0;
    m->f90 = q15_code(m->f90) / 32768.0;
    /* r at its code, and at the fixed-point clamp (32764, the largest code
     * below fresnel.h's 0.9999) where the code is above it */
    m->r = (q15_code(m->r) < FRESNEL_GULBRANDSEN_R_MAX_Q15 ? q15_code(m->r) : FRESNEL_GULBRANDSEN_R_MAX_Q15) / 32768.0;
    m->g = q15_code(m->g) / 32768.0;
    m->p = q16_code(m->p) / 65536.0;
    m->alpha = q16_code(ref_clamp(m->alpha, 0.0, FRESNEL_ALPHA_MAX)) / 65536.0;
    a = q15_qf(ref_clamp(m->a, 0.0, FRESNEL_A_MAX));
    m->a = q15_qf_value(a);
}

void model_q15_from_params(const model_params *m, model_q15 *out)
{
    memset(out, 0, sizeof *out);
    out->f0 = q15_code(m->f0);
    out->f82 = q15_code(m->f82);
    out->f90 = q15_code(m->f90);
    out->r = q15_code(m->r);
    out->g = q15_code(m->g);
    out->p = q16_code(m->p);
    q15_ior(m->eta, m->kappa, &out->ior);
    q15_ior(m->eta, 0.0, &out->dior);
    q15_nk(m->eta, m->kappa, &out->nk);
    out->gnk = fresnel_gulbrandsen_nk_q15(out->r, out->g);
    q15_lsk(m->eta, m->kappa, m->a, m->alpha, &out->lsk);
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
