/* A material's floating-point constants, the same list in every
 * floating-point number type and back end (emit.h: emit_float_params), and
 * the C float literal. */
#include <stdio.h>
#include <string.h>

#include "4_emit/emit.h"

/* A binary32 literal that reads back to the same float (GLSL and HLSL:
 * emit_glsl.c's emit_shader_float). */
void emit_c_float(FILE *f, double v)
{
    char buf[40];
    snprintf(buf, sizeof buf, "%.9g", (double)(float)v);
    fputs(buf, f);
    if (!strpbrk(buf, ".e"))
        fputs(".0", f);
    fputc('f', f);
}

static void d3(fresnel_rgb v, double out[3])
{
    out[0] = v.r;
    out[1] = v.g;
    out[2] = v.b;
}

#define AS_DOUBLE_3(v, out) d3(v, out)
#define AS_DOUBLE_1(v, out) (out = (v))
#define AS_DOUBLE(field, count, group, constant, row, why, q15, q15_why) AS_DOUBLE_##count(e->field, v.field);

void emit_material_params(FILE *f, const scene *sc, const encoded_material *e, const char *prefix, emit_rgb_fn rgb,
                          emit_float_fn flt)
{
    emit_floats v;
    DERIVED_PARAMETERS(AS_DOUBLE)
    emit_float_params(f, sc, &v, prefix, rgb, flt);
}

/* One parameter, as its back end spells a triple or a number. */
#define EMIT_PARAM_3(constant, v, why) rgb(f, prefix, constant, v, why)
#define EMIT_PARAM_1(constant, v, why) flt(f, prefix, constant, v, why)
#define EMIT_PARAM(field, count, group, constant, row, why, q15, q15_why)                                              \
    if (reads & (group))                                                                                               \
        EMIT_PARAM_##count(constant, v->field, why);

/* One material's floating-point parameters, those its scene's models need
 * (and F_avg where the scene asks for it): the same list in every
 * floating-point type and back end, each giving its own syntax. */
void emit_float_params(FILE *f, const scene *sc, const emit_floats *v, const char *prefix, emit_rgb_fn rgb,
                       emit_float_fn flt)
{
    unsigned reads = scene_reads(sc, 0) | (sc->f_avg ? MP_F_AVG : 0u);
    DERIVED_PARAMETERS(EMIT_PARAM)
}
