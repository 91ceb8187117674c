/* The model table (see models.h). */
#include "models.h"

#include <string.h>

#include "fresnel.h"
#include "reference.h"

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

const model model_table[] = {
    {"schlick", "F0", d_schlick, s_schlick, FRESNEL_BOUND_SCHLICK},
    {"schlick-gen", "F0, --f90, --p", d_schlick_gen, s_schlick_gen, FRESNEL_BOUND_SCHLICK_GEN},
    {"lsk", "eta, kappa", d_lsk, s_lsk, FRESNEL_BOUND_LSK},
    {"lsk-comp", "eta, kappa, LSK a and alpha", d_lsk_comp, s_lsk_comp, FRESNEL_BOUND_LSK_COMP},
    {"f82", "F0, F82", d_f82, s_f82, FRESNEL_BOUND_F82},
    {"gulbrandsen", "r = F0, edge tint g", d_gulbrandsen, s_gulbrandsen, FRESNEL_BOUND_GULBRANDSEN},
    {"cook-torrance", "F0 and the same eta, kappa as representative IOR", d_cook_torrance,
     s_cook_torrance, FRESNEL_BOUND_COOK_TORRANCE},
    {"exact", "eta, kappa (dielectric form when kappa = 0)", d_exact, s_exact, FRESNEL_BOUND_CONDUCTOR},
    {"exact-conductor", "eta, kappa (conductor form always)", d_conductor, s_conductor, FRESNEL_BOUND_CONDUCTOR},
    {"exact-dielectric", "eta (kappa ignored)", d_dielectric, s_dielectric, FRESNEL_BOUND_DIELECTRIC},
    {"approx-conductor", "eta, kappa", d_approx, s_approx, FRESNEL_BOUND_APPROX_CONDUCTOR},
    {"schlick-internal", "F0, eta (eta < 1: from inside the denser medium)", d_internal,
     s_internal, FRESNEL_BOUND_SCHLICK_INTERNAL},
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
