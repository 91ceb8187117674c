/* Scene models through the runtime (see scene_eval.h). */
#include "scene/scene_eval.h"

#include <stdlib.h>
#include <string.h>

#include "common/cli.h"
#include "common/reference.h"

int scene_model_prepare(const scene_entry *e, lut_spacing spacing, const spectrum *s, const gen_context *g,
                        const material_params *p, scene_model *m)
{
    memset(m, 0, sizeof *m);
    m->lut.bad = -1;
    m->def = e->row;
    strcpy(m->name, e->name);
    encode_material(p, &m->mat);
    if (e->lut_n && encode_table(s, g, p, spacing, e->lut_n, e->row->form, &m->lut))
        return cli_oom("scene model");
    if (e->row->offered & MODEL_FILM) {
        if (!(p->film_n > 0.0))
            return cli_error(p->info.id, "%s needs a film (a scene's film key, curve's --film N:D)", e->name);
        if (!(m->film = malloc(sizeof *m->film)))
            return cli_oom("scene model");
        if (encode_film(s, g, p, m->film)) {
            int status = m->film->why[0] ? cli_error(p->info.id, "under a %g film in n1 %g: %s", p->film_n, p->n1,
                                                     m->film->why)
                                         : cli_error(p->info.id, "fitting the thin-film model of a %g film in n1 %g failed",
                                                     p->film_n, p->n1);
            scene_model_free(m);
            return status;
        }
    }
    return 0;
}

int scene_model_prepare_name(const char *name, lut_spacing spacing, const spectrum *s, const gen_context *g,
                             const material_params *p, scene_model *m)
{
    scene_entry e;
    memset(m, 0, sizeof *m);
    m->lut.bad = -1;
    if (scene_entry_parse(name, spacing, &e))
        return cli_error("scene model", "unknown model '%s' (fresnel gen --help lists the models)", name);
    return scene_model_prepare(&e, spacing, s, g, p, m);
}

void scene_model_free(scene_model *m)
{
    encoded_lut_free(&m->lut);
    free(m->film);
    m->film = NULL;
}

model_rgb scene_model_rgb(const scene_model *m)
{
    model_rgb q;
    q.def = m->def;
    q.mat = &m->mat;
    q.lut = m->lut.n ? &m->lut : NULL;
    q.film = m->film;
    q.d_nm = 0.0;
    return q;
}

void scene_model_eval(const scene_model *m, float c, float out[3])
{
    model_rgb q = scene_model_rgb(m);
    fresnel_rgb r = m->def->rgb_f32(&q, c);
    out[0] = r.r;
    out[1] = r.g;
    out[2] = r.b;
}

void scene_model_eval_ref(const scene_model *m, double c, double out[3])
{
    model_rgb q = scene_model_rgb(m);
    int ch;
    c = ref_clamp(c, 0.0, 1.0);
    for (ch = 0; ch < 3; ch++)
        out[ch] = ref_clamp(m->def->ch_ref(&q, ch, c), 0.0, 1.0);
}
