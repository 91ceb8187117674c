/* `fresnel gen --hlsl` (see emit_glsl.h): the scene for
 * ports/hlsl/fresnel.hlsl. The port compiles the GLSL port's source, so the
 * function and macro names, model expressions, LUT macro calls, literals and
 * identifier checks are emit_glsl.c's; what differs is the declaration
 * syntax (static const float3, array initialisers in braces) and that
 * every table is a static const array (no texture form). Output depends
 * only on the manifest and the data. */
#include "4_emit/emit_glsl.h"

#include <stdlib.h>

#include "common/cli.h"


static void hlsl_rgb(FILE *f, const char *prefix, const char *name, const double v[3], const char *why)
{
    emit_shader_const(f, "static const float3", "float3", prefix, name, v, 3, why);
}

static void hlsl_float(FILE *f, const char *prefix, const char *name, double v, const char *why)
{
    emit_shader_const(f, "static const float", NULL, prefix, name, &v, 1, why);
}

/* LUT model e of material i as a static const array. */
static void hlsl_lut(FILE *f, const emit_input *in, int i, int m, const char *prefix)
{
    const scene_entry *e = &in->sc->models[m];
    const float *t = emit_lut(in, i, m)->f32;
    int k, n = e->lut_n;
    fprintf(f, "/* %s: %d nodes per channel (red, then green, then blue), uniform in %s,\n"
               " * fitted to the ground truth through %s interpolation. */\n",
            e->ident, n, in->sc->spacing == LUT_UNIFORM ? "cos theta" : "sqrt(cos theta), from grazing to normal",
            model_of(e->row)->form == LUT_CUBIC ? "Catmull-Rom" : "linear");
    fprintf(f, "static const float %s_%s[%d] = {", prefix, e->ident, 3 * n);
    for (k = 0; k < 3 * n; k++) {
        fputs(k % 6 == 0 ? "\n    " : " ", f);
        emit_shader_float(f, t[k]);
        if (k + 1 < 3 * n)
            fputc(',', f);
    }
    fputs("\n};\n", f);
}

int emit_hlsl(FILE *f, const emit_input *in)
{
    const scene *sc = in->sc;
    char guard[96];
    int i, m;
    emit_shader_opening(f, in, guard);
    fprintf(f, " * HLSL for ports/hlsl/fresnel.hlsl: include it first. Each material and model has\n"
               " * float3 fresnel_%s_<material>_<model>_rgb(float c) (lsk-comp -> lsk_comp), computing\n"
               " * what the C runtime computes from the C header of the same manifest. Constants and\n"
               " * LUT tables are static const (binary32); a table could equally live in a cbuffer\n"
               " * (one float per 16-byte register there, or packed in float4 with the index split).\n"
               " */\n#ifndef FRESNEL_SCENE_%s_HLSL\n#define FRESNEL_SCENE_%s_HLSL\n",
            in->name, guard, guard);
    fprintf(f, "#ifndef FRESNEL_HLSL\n#error \"include ports/hlsl/fresnel.hlsl before this file\"\n#endif\n");

    for (i = 0; i < sc->material_count; i++) {
        const material_params *p = &in->params[i];
        char prefix[160];
        snprintf(prefix, sizeof prefix, "fresnel_%s_%s", in->name, p->info.id);
        emit_material_heading(f, in, i);
        emit_material_params(f, sc, &in->enc[i], prefix, hlsl_rgb, hlsl_float);
        for (m = 0; m < sc->model_count; m++) {
            const scene_entry *e = &sc->models[m];
            if (e->lut_n)
                hlsl_lut(f, in, i, m, prefix);
            if (model_of(e->row)->offered & MODEL_FILM)
                emit_shader_film_table(f, in, i, prefix, e, "static const float", "{", "}");
            fprintf(f, "float3 %s_%s_rgb(float c%s)\n{\n    %s", prefix, e->ident, emit_shader_more_params(e, "float"),
                    model_of(e->row)->offered & MODEL_FILM ? "" : "return "); /* the film's is a body */
            if (e->lut_n)
                emit_shader_lut_array_call(f, prefix, e->ident, e->lut_n, model_of(e->row)->form, sc->spacing);
            else
                emit_shader_model_expr(f, prefix, model_of(e->row));
            fputs(model_of(e->row)->offered & MODEL_FILM ? "\n}\n" : ";\n}\n", f);
        }
    }
    fprintf(f, "\n#endif\n");
    return 0;
}
