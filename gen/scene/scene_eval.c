/* Scene models through the binary32 runtime (see scene_eval.h). */
#include "scene/scene_eval.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "fresnel.h"
#include "model/reference.h"
#include "scene/scene.h"

int scene_model_prepare(const char *name, lut_spacing spacing, const spectrum *s, const gen_context *g,
                        const material_params *p, scene_model *m)
{
    int form = LUT_PLAIN, n = scene_model_lut_size(name, &form), i;
    memset(m, 0, sizeof *m);
    if (!scene_model_known(name) || strlen(name) >= sizeof m->name || !(m->def = model_scene_row(name, spacing)))
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
    model_rgb q;
    fresnel_rgb r;
    model_rgb_prepare_f32(m->def, p, m->table, m->lut_n, m->spacing, &q);
    r = m->def->rgb_f32(&q, c);
    out[0] = r.r;
    out[1] = r.g;
    out[2] = r.b;
}

void scene_model_eval_ref(const scene_model *m, const material_params *p, double c, double out[3])
{
    model_rgb q;
    int ch;
    model_rgb_prepare_f32(m->def, p, m->table, m->lut_n, m->spacing, &q);
    c = ref_clamp(c, 0.0, 1.0);
    for (ch = 0; ch < 3; ch++)
        out[ch] = ref_clamp(m->def->ch_ref(&q, ch, c), 0.0, 1.0);
}
