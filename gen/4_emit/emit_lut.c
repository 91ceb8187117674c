/* A LUT model's table for one material, shared by the C, Q15, GLSL and
 * HLSL emitters (emit.h). */
#include <stdlib.h>

#include "4_emit/emit.h"
#include "scene/scene.h"

int emit_lut_encode(const char *model, const material_params *p, const spectrum *s, const gen_context *g,
                    lut_spacing spacing, encoded_lut *t, char name[32])
{
    int i, form = LUT_PLAIN, n = scene_model_lut_size(model, &form);
    for (i = 0; model[i] && i < 31; i++)
        name[i] = model[i] == '-' ? '_' : model[i];
    name[i] = '\0';
    return encode_table(s, g, p, spacing, n, (lut_form)form, t);
}

double *emit_lut_table(const char *model, const material_params *p, const spectrum *s, const gen_context *g,
                       lut_spacing spacing, int *n, lut_form *form, char name[32])
{
    encoded_lut t;
    double *v;
    int i;
    if (emit_lut_encode(model, p, s, g, spacing, &t, name))
        return NULL;
    if ((v = malloc(3 * (size_t)t.n * sizeof *v)) != NULL)
        for (i = 0; i < 3 * t.n; i++)
            v[i] = t.f32[i];
    *n = t.n;
    *form = t.form;
    encoded_lut_free(&t);
    return v;
}
