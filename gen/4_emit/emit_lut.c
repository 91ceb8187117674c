/* A LUT model's table for one material, shared by the C, Q15 and GLSL
 * emitters (emit.h). */
#include <stdlib.h>

#include "4_emit/emit.h"
#include "scene/scene.h"

double *emit_lut_table(const char *model, const material_params *p, const spectrum *s, const gen_context *g,
                       lut_spacing spacing, int *n, lut_form *form, char name[32])
{
    double *t;
    int i, f = LUT_PLAIN;
    *n = scene_model_lut_size(model, &f);
    *form = (lut_form)f;
    if (!(t = malloc(3 * (size_t)*n * sizeof *t)))
        return NULL;
    if (encode_lut(s, g, p, spacing, *n, *form, t)) {
        free(t);
        return NULL;
    }
    for (i = 0; model[i] && i < 31; i++)
        name[i] = model[i] == '-' ? '_' : model[i];
    name[i] = '\0';
    return t;
}
