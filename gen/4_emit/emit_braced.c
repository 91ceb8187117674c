/* `fresnel gen --hlsl` and `--msl` (see emit_glsl.h): the scene for
 * ports/hlsl/fresnel.hlsl or ports/msl/fresnel.metal. Both ports compile the
 * GLSL port's source, so the function and macro names, model expressions,
 * LUT macro calls, literals and identifier checks are emit_glsl.c's; what
 * differs is the declaration syntax (a qualifier before the type, array
 * initialisers in braces: one dialect row each) and that every table is a
 * program-scope constant array (no texture form). Output depends only on
 * the manifest and the data. */
#include "4_emit/emit_glsl.h"

#include <stdlib.h>

#include "common/cli.h"

/* What tells the two languages apart in the output. */
typedef struct braced_dialect {
    const char *language;   /* in the opening comment */
    const char *port;       /* the port file, from the top of the tree */
    const char *port_macro; /* the macro the port defines */
    const char *guard_tail; /* of the scene's include guard */
    const char *qualifier;  /* before a program-scope constant's type */
    const char *use;        /* the lines of the opening comment after the first */
} braced_dialect;

static const braced_dialect hlsl = {
    "HLSL", "ports/hlsl/fresnel.hlsl", "FRESNEL_HLSL", "HLSL", "static const",
    " * float3 fresnel_%s_<material>_<model>_rgb(float c) (lsk-comp -> lsk_comp), computing\n"
    " * what the C runtime computes from the C header of the same manifest. Constants and\n"
    " * LUT tables are static const (binary32); a table could equally live in a cbuffer\n"
    " * (one float per 16-byte register there, or packed in float4 with the index split).\n"};
static const braced_dialect msl = {
    "MSL", "ports/msl/fresnel.metal", "FRESNEL_METAL", "METAL", "constant",
    " * float3 fresnel_%s_<material>_<model>_rgb(float c) (lsk-comp -> lsk_comp), computing\n"
    " * what the C runtime computes from the C header of the same manifest. Constants and\n"
    " * LUT tables are program-scope constant (binary32), in the constant address space\n"
    " * every thread reads without a copy.\n"};

/* LUT model e of material i as a constant array. */
static void braced_lut(FILE *f, const braced_dialect *d, const emit_input *in, int i, int m, const char *prefix)
{
    const scene_entry *e = &in->sc->models[m];
    const float *t = emit_lut(in, i, m)->f32;
    int k, n = e->lut_n;
    fprintf(f, "/* %s: %d nodes per channel (red, then green, then blue), uniform in %s,\n"
               " * fitted to the ground truth through %s interpolation. */\n",
            e->ident, n, in->sc->spacing == LUT_UNIFORM ? "cos theta" : "sqrt(cos theta), from grazing to normal",
            model_of(e->row)->form == LUT_CUBIC ? "Catmull-Rom" : "linear");
    fprintf(f, "%s float %s_%s[%d] = {", d->qualifier, prefix, e->ident, 3 * n);
    for (k = 0; k < 3 * n; k++) {
        fputs(k % 6 == 0 ? "\n    " : " ", f);
        emit_shader_float(f, t[k]);
        if (k + 1 < 3 * n)
            fputc(',', f);
    }
    fputs("\n};\n", f);
}

/* The constants printers of emit_material_params take no context: one pair
 * per dialect. */
#define BRACED_PRINTERS(d, qual)                                                                                       \
    static void d##_rgb(FILE *f, const char *prefix, const char *name, const double v[3], const char *why)            \
    {                                                                                                                  \
        emit_shader_const(f, qual " float3", "float3", prefix, name, v, 3, why);                                      \
    }                                                                                                                  \
    static void d##_float(FILE *f, const char *prefix, const char *name, double v, const char *why)                   \
    {                                                                                                                  \
        emit_shader_const(f, qual " float", NULL, prefix, name, &v, 1, why);                                          \
    }
BRACED_PRINTERS(hlsl, "static const")
BRACED_PRINTERS(msl, "constant")

static int emit_braced(FILE *f, const emit_input *in, const braced_dialect *d, emit_rgb_fn rgb, emit_float_fn flt)
{
    const scene *sc = in->sc;
    char guard[96], qualified[32];
    int i, m;
    emit_shader_opening(f, in, guard);
    fprintf(f, " * %s for %s: include it first. Each material and model has\n", d->language, d->port);
    fprintf(f, d->use, in->name);
    fprintf(f, " */\n#ifndef FRESNEL_SCENE_%s_%s\n#define FRESNEL_SCENE_%s_%s\n", guard, d->guard_tail, guard,
            d->guard_tail);
    fprintf(f, "#ifndef %s\n#error \"include %s before this file\"\n#endif\n", d->port_macro, d->port);
    snprintf(qualified, sizeof qualified, "%s float", d->qualifier);

    for (i = 0; i < sc->material_count; i++) {
        const material_params *p = &in->params[i];
        char prefix[160];
        snprintf(prefix, sizeof prefix, "fresnel_%s_%s", in->name, p->info.id);
        emit_material_heading(f, in, i);
        emit_material_params(f, sc, &in->enc[i], prefix, rgb, flt);
        for (m = 0; m < sc->model_count; m++) {
            const scene_entry *e = &sc->models[m];
            const model *row = model_of(e->row);
            if (e->lut_n)
                braced_lut(f, d, in, i, m, prefix);
            if (row->offered & MODEL_FILM)
                emit_shader_film_table(f, in, i, prefix, e, qualified, "{", "}");
            fprintf(f, "float3 %s_%s_rgb(float c%s)\n{\n    %s", prefix, e->ident, emit_shader_more_params(e, "float"),
                    row->offered & MODEL_FILM ? "" : "return "); /* the film's is a body */
            if (e->lut_n)
                emit_shader_lut_array_call(f, prefix, e->ident, e->lut_n, row->form, sc->spacing);
            else
                emit_shader_model_expr(f, prefix, row);
            fputs(row->offered & MODEL_FILM ? "\n}\n" : ";\n}\n", f);
        }
    }
    fprintf(f, "\n#endif\n");
    return 0;
}

int emit_hlsl(FILE *f, const emit_input *in) { return emit_braced(f, in, &hlsl, hlsl_rgb, hlsl_float); }
int emit_msl(FILE *f, const emit_input *in) { return emit_braced(f, in, &msl, msl_rgb, msl_float); }
