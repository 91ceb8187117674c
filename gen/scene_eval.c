/* Scene models through the binary32 runtime (see scene_eval.h). */
#include "scene_eval.h"

#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "fresnel.h"
#include "scene.h"

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
    int residual = 0, n = scene_model_lut_size(name, &residual), i;
    memset(m, 0, sizeof *m);
    if (!scene_model_known(name) || strlen(name) >= sizeof m->name)
        return cli_error("scene model", "unknown model '%s'", name);
    strcpy(m->name, name);
    if (n == 0)
        return 0;
    {
        double *t = malloc(3 * (size_t)n * sizeof *t);
        m->table = malloc(3 * (size_t)n * sizeof *m->table);
        if (!t || !m->table) {
            free(t);
            scene_model_free(m);
            return cli_error("scene model", "out of memory");
        }
        encode_lut(s, g, p, spacing, n, residual, t);
        for (i = 0; i < 3 * n; i++)
            m->table[i] = (float)t[i];
        free(t);
    }
    m->lut_n = n;
    m->residual = residual;
    m->spacing = spacing;
    return 0;
}

void scene_model_free(scene_model *m)
{
    free(m->table);
    m->table = NULL;
}

void scene_model_eval(const scene_model *m, const material_params *p, float c, float out[3])
{
    fresnel_rgb f0 = rgb_of(p->f0), r;
    const char *name = m->name;
    if (m->lut_n) {
        if (m->residual)
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
    else /* approx-conductor: scene_model_prepare admitted only known names */
        r = fresnel_approx_conductor_rgb(rgb_of(p->eta_fit), rgb_of(p->kappa_fit), c);
    out[0] = r.r;
    out[1] = r.g;
    out[2] = r.b;
}
