/* A LUT model's table for one material, shared by the C, Q15, GLSL and
 * HLSL emitters (emit.h). */
#include <stdlib.h>

#include "4_emit/emit.h"

int emit_lut_encode(const emit_input *in, const scene_entry *e, int i, encoded_lut *t)
{
    return encode_table(in->spectra[i], in->g, &in->params[i], in->sc->spacing, e->lut_n, e->row->form, t);
}

double *emit_lut_table(const emit_input *in, const scene_entry *e, int i)
{
    encoded_lut t;
    double *v;
    int k;
    if (emit_lut_encode(in, e, i, &t))
        return NULL;
    if ((v = malloc(3 * (size_t)t.n * sizeof *v)) != NULL)
        for (k = 0; k < 3 * t.n; k++)
            v[k] = t.f32[k];
    encoded_lut_free(&t);
    return v;
}
