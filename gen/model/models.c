/* The model table (see models.h). */
#include "model/models.h"

#include <string.h>

#include <math.h>

#include "3_encode/fixed_params.h"
#include "fresnel.h"
#include "fresnel_f16.h"
#include "model/reference.h"

#define F(x) ((float)(x))

static double d_schlick(const model_params *m, double c) { return ref_schlick(m->f0, c); }
static float s_schlick(const model_params *m, float c) { return fresnel_schlick(F(m->f0), c); }

static double d_schlick_gen(const model_params *m, double c)
{
    return ref_schlick_gen(m->f0, m->f90, m->p, c);
}
static float s_schlick_gen(const model_params *m, float c)
{
    return fresnel_schlick_gen(F(m->f0), F(m->f90), F(m->p), c);
}

static double d_lsk(const model_params *m, double c) { return ref_lsk(m->eta, m->kappa, c); }
static float s_lsk(const model_params *m, float c) { return fresnel_lsk(F(m->eta), F(m->kappa), c); }

static double d_lsk_comp(const model_params *m, double c)
{
    return ref_lsk_comp(m->eta, m->kappa, m->a, m->alpha, c);
}
static float s_lsk_comp(const model_params *m, float c)
{
    return fresnel_lsk_comp(F(m->eta), F(m->kappa), F(m->a), F(m->alpha), c);
}

static double d_f82(const model_params *m, double c) { return ref_f82(m->f0, m->f82, c); }
static float s_f82(const model_params *m, float c) { return fresnel_f82(F(m->f0), F(m->f82), c); }

static double d_gulbrandsen(const model_params *m, double c) { return ref_gulbrandsen(m->r, m->g, c); }
static float s_gulbrandsen(const model_params *m, float c)
{
    return fresnel_gulbrandsen(F(m->r), F(m->g), c);
}

static double d_cook_torrance(const model_params *m, double c)
{
    return ref_cook_torrance(m->f0, m->eta, m->kappa, c);
}
static float s_cook_torrance(const model_params *m, float c)
{
    return fresnel_cook_torrance(F(m->f0), F(m->eta), F(m->kappa), c);
}

/* kappa = 0 takes the dielectric function, as a caller who knows it would. */
static double d_exact(const model_params *m, double c)
{
    return m->kappa > 0.0 ? ref_conductor(m->eta, m->kappa, c) : ref_dielectric(m->eta, c);
}
static float s_exact(const model_params *m, float c)
{
    return m->kappa > 0.0 ? fresnel_conductor(F(m->eta), F(m->kappa), c)
                          : fresnel_dielectric(F(m->eta), c);
}

static double d_conductor(const model_params *m, double c) { return ref_conductor(m->eta, m->kappa, c); }
static float s_conductor(const model_params *m, float c)
{
    return fresnel_conductor(F(m->eta), F(m->kappa), c);
}

static double d_dielectric(const model_params *m, double c) { return ref_dielectric(m->eta, c); }
static float s_dielectric(const model_params *m, float c) { return fresnel_dielectric(F(m->eta), c); }

static double d_approx(const model_params *m, double c)
{
    return ref_approx_conductor(m->eta, m->kappa, c);
}
static float s_approx(const model_params *m, float c)
{
    return fresnel_approx_conductor(F(m->eta), F(m->kappa), c);
}

static double d_internal(const model_params *m, double c)
{
    return ref_schlick_internal(m->f0, m->eta, c);
}
static float s_internal(const model_params *m, float c)
{
    return fresnel_schlick_internal(F(m->f0), F(m->eta), c);
}

/* ---- fixed point (fresnel_fixed.h); parameters prepared by model_fixed_from_params */
static int32_t q_schlick(const model_fixed *m, int32_t c) { return fresnel_schlick_q15(m->f0, c); }
static int32_t q_schlick_gen(const model_fixed *m, int32_t c)
{
    return fresnel_schlick_gen_q15(m->f0, m->f90, m->p, c);
}
static int32_t q_lsk(const model_fixed *m, int32_t c) { return fresnel_lsk_q15(&m->lsk, c); }
static int32_t q_lsk_comp(const model_fixed *m, int32_t c) { return fresnel_lsk_comp_q15(&m->lsk, c); }
static int32_t q_f82(const model_fixed *m, int32_t c) { return fresnel_f82_q15(m->f0, m->f82, c); }
/* fresnel_gulbrandsen_q15 maps r, g each call; the prepared n, k give the same codes */
static int32_t q_gulbrandsen(const model_fixed *m, int32_t c) { return fresnel_approx_conductor_q15(&m->gnk, c); }
static int32_t q_cook_torrance(const model_fixed *m, int32_t c)
{
    return fresnel_cook_torrance_q15(m->f0, &m->ior, c);
}
static int32_t q_exact(const model_fixed *m, int32_t c)
{
    return m->ior.b.m ? fresnel_conductor_q15(&m->ior, c) : fresnel_dielectric_q15(&m->ior, c);
}
static int32_t q_conductor(const model_fixed *m, int32_t c) { return fresnel_conductor_q15(&m->ior, c); }
static int32_t q_dielectric(const model_fixed *m, int32_t c) { return fresnel_dielectric_q15(&m->dior, c); }
static int32_t q_approx(const model_fixed *m, int32_t c) { return fresnel_approx_conductor_q15(&m->nk, c); }
static int32_t q_internal(const model_fixed *m, int32_t c)
{
    return fresnel_schlick_internal_q15(m->f0, &m->dior, c);
}

/* ---- binary16 (fresnel_f16.h): parameters and c converted to half here */
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
#define F16(fn) fn
#else
#define F16(fn) NULL
#endif

const model model_table[] = {
    {"schlick", "F0", d_schlick, s_schlick, FRESNEL_BOUND_SCHLICK,
     q_schlick, FRESNEL_BOUND_SCHLICK_Q15, F16(h_schlick), FRESNEL_BOUND_SCHLICK_F16},
    {"schlick-gen", "F0, --f90, --p", d_schlick_gen, s_schlick_gen, FRESNEL_BOUND_SCHLICK_GEN,
     q_schlick_gen, FRESNEL_BOUND_SCHLICK_GEN_Q15, F16(h_schlick_gen), FRESNEL_BOUND_SCHLICK_GEN_F16},
    {"lsk", "eta, kappa", d_lsk, s_lsk, FRESNEL_BOUND_LSK,
     q_lsk, FRESNEL_BOUND_LSK_Q15, F16(h_lsk), FRESNEL_BOUND_LSK_F16},
    {"lsk-comp", "eta, kappa, LSK a and alpha", d_lsk_comp, s_lsk_comp, FRESNEL_BOUND_LSK_COMP,
     q_lsk_comp, FRESNEL_BOUND_LSK_COMP_Q15, F16(h_lsk_comp), FRESNEL_BOUND_LSK_COMP_F16},
    {"f82", "F0, F82", d_f82, s_f82, FRESNEL_BOUND_F82,
     q_f82, FRESNEL_BOUND_F82_Q15, F16(h_f82), FRESNEL_BOUND_F82_F16},
    {"gulbrandsen", "r = F0, edge tint g", d_gulbrandsen, s_gulbrandsen, FRESNEL_BOUND_GULBRANDSEN,
     q_gulbrandsen, FRESNEL_BOUND_GULBRANDSEN_Q15, F16(h_gulbrandsen), FRESNEL_BOUND_GULBRANDSEN_F16},
    {"cook-torrance", "F0 and the same eta, kappa as representative IOR", d_cook_torrance,
     s_cook_torrance, FRESNEL_BOUND_COOK_TORRANCE,
     q_cook_torrance, FRESNEL_BOUND_COOK_TORRANCE_Q15, F16(h_cook_torrance), FRESNEL_BOUND_COOK_TORRANCE_F16},
    {"exact", "eta, kappa (dielectric form when kappa = 0)", d_exact, s_exact, FRESNEL_BOUND_CONDUCTOR,
     q_exact, FRESNEL_BOUND_CONDUCTOR_Q15, F16(h_exact), FRESNEL_BOUND_CONDUCTOR_F16},
    {"exact-conductor", "eta, kappa (conductor form always)", d_conductor, s_conductor, FRESNEL_BOUND_CONDUCTOR,
     q_conductor, FRESNEL_BOUND_CONDUCTOR_Q15, F16(h_conductor), FRESNEL_BOUND_CONDUCTOR_F16},
    {"exact-dielectric", "eta (kappa ignored)", d_dielectric, s_dielectric, FRESNEL_BOUND_DIELECTRIC,
     q_dielectric, FRESNEL_BOUND_DIELECTRIC_Q15, F16(h_dielectric), FRESNEL_BOUND_DIELECTRIC_F16},
    {"approx-conductor", "eta, kappa", d_approx, s_approx, FRESNEL_BOUND_APPROX_CONDUCTOR,
     q_approx, FRESNEL_BOUND_APPROX_CONDUCTOR_Q15, F16(h_approx), FRESNEL_BOUND_APPROX_CONDUCTOR_F16},
    {"schlick-internal", "F0, eta (eta < 1: from inside the denser medium)", d_internal,
     s_internal, FRESNEL_BOUND_SCHLICK_INTERNAL,
     q_internal, FRESNEL_BOUND_SCHLICK_INTERNAL_Q15, F16(h_internal), FRESNEL_BOUND_SCHLICK_INTERNAL_F16},
};
const int model_count = (int)(sizeof model_table / sizeof model_table[0]);

const model *model_find(const char *name)
{
    int i;
    for (i = 0; i < model_count; i++)
        if (!strcmp(model_table[i].name, name))
            return &model_table[i];
    return NULL;
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

void model_params_round_fixed(model_params *m)
{
    fresnel_qf a;
    m->f0 = fixed_q15(m->f0) / 32768.0;
    m->f82 = fixed_q15(m->f82) / 32768.0;
    m->f90 = fixed_q15(m->f90) / 32768.0;
    /* r at its code, and at the fixed-point clamp (32764, the largest code
     * below fresnel.h's 0.9999) where the code is above it */
    m->r = (fixed_q15(m->r) < FRESNEL_GULBRANDSEN_R_MAX_Q15 ? fixed_q15(m->r) : FRESNEL_GULBRANDSEN_R_MAX_Q15) / 32768.0;
    m->g = fixed_q15(m->g) / 32768.0;
    m->p = fixed_q16(m->p) / 65536.0;
    m->alpha = fixed_q16(ref_clamp(m->alpha, 0.0, FRESNEL_ALPHA_MAX)) / 65536.0;
    a = fixed_qf(ref_clamp(m->a, 0.0, FRESNEL_A_MAX));
    m->a = fixed_qf_value(a);
}

void model_fixed_from_params(const model_params *m, model_fixed *out)
{
    memset(out, 0, sizeof *out);
    out->f0 = fixed_q15(m->f0);
    out->f82 = fixed_q15(m->f82);
    out->f90 = fixed_q15(m->f90);
    out->r = fixed_q15(m->r);
    out->g = fixed_q15(m->g);
    out->p = fixed_q16(m->p);
    fixed_ior(m->eta, m->kappa, &out->ior);
    fixed_ior(m->eta, 0.0, &out->dior);
    fixed_nk(m->eta, m->kappa, &out->nk);
    out->gnk = fresnel_gulbrandsen_nk_q15(out->r, out->g);
    fixed_lsk(m->eta, m->kappa, m->a, m->alpha, &out->lsk);
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
