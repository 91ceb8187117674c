/* Stage 4, emit, binary16: a material's constants and tables for the scalar
 * functions of include/fresnel_f16.h, per channel, as the encoder rounded
 * them (3_encode/encode.h), inside #if FRESNEL_HAS_F16 so that the header
 * still compiles where the compiler has no _Float16. */
#include <math.h>
#include <stdio.h>

#include "common/cli.h"
#include "4_emit/emit.h"

#if FRESNEL_HAS_F16
static void f16_rgb(FILE *f, const char *prefix, const char *name, const double v[3], const char *why)
{
    fprintf(f, "/* %s, binary16 (r, g, b) */\nstatic const fresnel_f16 %s_%s_f16[3] FRESNEL_GEN_UNUSED = {", why, prefix,
            name);
    emit_c_float(f, v[0]);
    fputs(", ", f);
    emit_c_float(f, v[1]);
    fputs(", ", f);
    emit_c_float(f, v[2]);
    fputs("};\n", f);
}

static void f16_scalar(FILE *f, const char *prefix, const char *name, double v, const char *why)
{
    fprintf(f, "/* %s, binary16 */\nstatic const fresnel_f16 %s_%s_f16 FRESNEL_GEN_UNUSED = ", why, prefix, name);
    emit_c_float(f, v);
    fputs(";\n", f);
}

static void h3(const fresnel_f16 h[3], double out[3])
{
    out[0] = (double)h[0];
    out[1] = (double)h[1];
    out[2] = (double)h[2];
}

static void emit_lut_f16(FILE *f, const emit_input *in, const char *prefix, const scene_entry *e, const encoded_lut *t)
{
    int i, n = t->n;
    const char *call = t->form == LUT_CUBIC ? "cubic_f16(" : (t->form == LUT_RESIDUAL ? "residual_f16(f0[ch], " : "f16(");
    fprintf(f, "/* %s in binary16: %d nodes per channel (red, then green, then blue). Evaluate channel\n"
               " * ch with fresnel_lut_%s%stable + ch * %d, %d, c). */\n"
               "static const fresnel_f16 %s_%s_f16[%d] FRESNEL_GEN_UNUSED = {",
            e->name, n, in->sc->spacing == LUT_UNIFORM ? "linear_" : "", call, n, n, prefix, e->ident, 3 * n);
    for (i = 0; i < 3 * n; i++) {
        fputs(i % 6 == 0 ? "\n    " : " ", f);
        emit_c_float(f, (double)t->f16[i]);
        if (i + 1 < 3 * n)
            fputc(',', f);
    }
    fputs("\n};\n", f);
}
#endif

#if FRESNEL_HAS_F16
#define AS_DOUBLE_3(h, out) h3(h, out)
#define AS_DOUBLE_1(h, out) (out = (double)(h))
#define AS_DOUBLE(field, count, group, constant, row, why, q15, q15_why) AS_DOUBLE_##count(e->h_##field, v.field);
#endif

int emit_f16_material(FILE *f, const emit_input *in, int mi, const char *prefix)
{
#if FRESNEL_HAS_F16
    const encoded_material *e = &in->enc[mi];
    emit_floats v;
    int m;
    DERIVED_PARAMETERS(AS_DOUBLE)
    fputs("#if FRESNEL_HAS_F16\n", f);
    emit_float_params(f, in->sc, &v, prefix, f16_rgb, f16_scalar);
    for (m = 0; m < in->sc->model_count; m++)
        if (emit_lut(in, mi, m)->n)
            emit_lut_f16(f, in, prefix, &in->sc->models[m], emit_lut(in, mi, m));
    m = emit_film(f, in, mi, prefix, TYPE_F16);
    fputs("#endif\n", f);
    return m;
#else
    (void)f, (void)in, (void)mi, (void)prefix;
    return 0; /* never asked: the registry's f16 row is not available here */
#endif
}
