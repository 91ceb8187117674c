/* Scene models through the binary32 runtime (see scene_eval.h). */
#include "scene/scene_eval.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "fresnel.h"
#include "model/reference.h"
#include "scene/scene.h"

static fresnel_rgb rgb_of(const double v[3])
{
    fresnel_rgb out;
    out.r = (float)v[0];
    out.g = (float)v[1];
    out.b = (float)v[2];
    return out;
}

int scene_model_prepare(const char *name, lut_spacing spacing, const spectrum *s, const gen_context *g,
                        const material_params *p, scene_model *m)
{
    int form = LUT_PLAIN, n = scene_model_lut_size(name, &form), i;
    memset(m, 0, sizeof *m);
    if (!scene_model_known(name) || strlen(name) >= sizeof m->name)
        return cli_error("scene model", "unknown model '%s'", name);
    strcpy(m->name, name);
    if (n == 0)
        return 0;
    m->table_d = malloc(3 * (size_t)n * sizeof *m->table_d);
    m->table = malloc(3 * (size_t)n * sizeof *m->table);
    if (!m->table_d || !m->table) {
        scene_model_free(m);
        return cli_oom("scene model");
    }
    if (encode_lut(s, g, p, spacing, n, (lut_form)form, m->table_d)) {
        scene_model_free(m);
        return cli_oom("scene model");
    }
    for (i = 0; i < 3 * n; i++)
        m->table[i] = (float)m->table_d[i];
    m->lut_n = n;
    m->form = (lut_form)form;
    m->spacing = spacing;
    return 0;
}

void scene_model_free(scene_model *m)
{
    free(m->table);
    free(m->table_d);
    m->table = NULL;
    m->table_d = NULL;
}

void scene_model_eval(const scene_model *m, const material_params *p, float c, float out[3])
{
    fresnel_rgb f0 = rgb_of(p->f0), r;
    const char *name = m->name;
    if (m->lut_n) {
        if (m->form == LUT_CUBIC)
            r = fresnel_lut_cubic_rgb(m->table, m->lut_n, c);
        else if (m->form == LUT_RESIDUAL)
            r = m->spacing == LUT_UNIFORM ? fresnel_lut_linear_residual_rgb(f0, m->table, m->lut_n, c)
                                          : fresnel_lut_residual_rgb(f0, m->table, m->lut_n, c);
        else
            r = m->spacing == LUT_UNIFORM ? fresnel_lut_linear_rgb(m->table, m->lut_n, c)
                                          : fresnel_lut_rgb(m->table, m->lut_n, c);
    } else if (!strcmp(name, "schlick"))
        r = fresnel_schlick_rgb(f0, c);
    else if (!strcmp(name, "lsk"))
        r = fresnel_lsk_rgb(rgb_of(p->eta_fit), rgb_of(p->kappa_fit), c);
    else if (!strcmp(name, "lsk-comp"))
        r = fresnel_lsk_comp_rgb(rgb_of(p->eta_fit), rgb_of(p->kappa_fit), rgb_of(p->lsk_a), rgb_of(p->lsk_alpha),
                                 c);
    else if (!strcmp(name, "f82"))
        r = fresnel_f82_rgb(f0, rgb_of(p->f82), c);
    else if (!strcmp(name, "gulbrandsen"))
        r = fresnel_gulbrandsen_rgb(rgb_of(p->gulb_r), rgb_of(p->gulb_g), c);
    else if (!strcmp(name, "cook-torrance"))
        r = fresnel_cook_torrance_rgb(f0, (float)p->ct_eta, (float)p->ct_kappa, c);
    else if (!strcmp(name, "exact"))
        r = fresnel_conductor_rgb(rgb_of(p->eta_fit), rgb_of(p->kappa_fit), c);
    else if (!strcmp(name, "exact-gaussian"))
        r = fresnel_conductor_rgb(rgb_of(p->eta_gauss), rgb_of(p->kappa_gauss), c);
    else if (!strcmp(name, "exact-point"))
        r = fresnel_conductor_rgb(rgb_of(p->eta_point), rgb_of(p->kappa_point), c);
    else /* approx-conductor: scene_model_prepare admitted only known names */
        r = fresnel_approx_conductor_rgb(rgb_of(p->eta_fit), rgb_of(p->kappa_fit), c);
    out[0] = r.r;
    out[1] = r.g;
    out[2] = r.b;
}

static double f32(double x) { return (double)(float)x; }


void scene_model_eval_ref(const scene_model *m, const material_params *p, double c, double out[3])
{
    const char *name = m->name;
    int ch;
    c = ref_clamp(c, 0.0, 1.0);
    for (ch = 0; ch < 3; ch++) {
        double f0 = f32(p->f0[ch]), eta = f32(p->eta_fit[ch]), kappa = f32(p->kappa_fit[ch]), v;
        if (m->lut_n) {
            double x = m->spacing == LUT_UNIFORM ? c : sqrt(c), nodes[SCENE_LUT_MAX];
            int i;
            for (i = 0; i < m->lut_n; i++) /* at the float-rounded node values */
                nodes[i] = m->table[ch * m->lut_n + i];
            v = ref_lut(nodes, m->lut_n, m->form == LUT_CUBIC, x) + (m->form == LUT_RESIDUAL ? ref_schlick(f0, c) : 0.0);
        } else if (!strcmp(name, "schlick"))
            v = ref_schlick(f0, c);
        else if (!strcmp(name, "lsk"))
            v = ref_lsk(eta, kappa, c);
        else if (!strcmp(name, "lsk-comp"))
            v = ref_lsk_comp(eta, kappa, f32(p->lsk_a[ch]), f32(p->lsk_alpha[ch]), c);
        else if (!strcmp(name, "f82"))
            v = ref_f82(f0, f32(p->f82[ch]), c);
        else if (!strcmp(name, "gulbrandsen"))
            v = ref_gulbrandsen(f32(p->gulb_r[ch]), f32(p->gulb_g[ch]), c);
        else if (!strcmp(name, "cook-torrance"))
            v = ref_cook_torrance(f0, f32(p->ct_eta), f32(p->ct_kappa), c);
        else if (!strcmp(name, "exact"))
            v = ref_conductor(eta, kappa, c);
        else if (!strcmp(name, "exact-gaussian"))
            v = ref_conductor(f32(p->eta_gauss[ch]), f32(p->kappa_gauss[ch]), c);
        else if (!strcmp(name, "exact-point"))
            v = ref_conductor(f32(p->eta_point[ch]), f32(p->kappa_point[ch]), c);
        else
            v = ref_approx_conductor(eta, kappa, c);
        out[ch] = ref_clamp(v, 0.0, 1.0);
    }
}
