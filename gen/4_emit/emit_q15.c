/* Stage 4, emit, fixed point: a scene's constants and tables in the formats of
 * include/fresnel_q15.h (its LAYOUT section), as the encoder converted
 * them (3_encode/encode.h: encode_material, encode_table), which is what
 * every evaluation of the scene reads too.
 *
 * Every value was checked against its C type and the range the runtime
 * documents when the scene was encoded (3_encode/encode_check.c), because a
 * wrapped or clamped constant compiles into a silently wrong reflectance.
 * Structs are written with positional initialisers in declaration order
 * (C++ before C++20 has no designated initialisers); a comment above each
 * table names the fields. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "common/cli.h"
#include "4_emit/emit.h"
#include "common/reference.h"
#include "scene/scene.h"

/* The output of one material. */
typedef struct fx_out {
    FILE *f;
    const emit_input *in;
} fx_out;

/* The prepared structs' initializers (emit.h). */
void emit_q15_qf(FILE *f, fresnel_qf q) { fprintf(f, "{%lu, %ld}", (unsigned long)q.m, (long)q.e); }

void emit_q15_ior(FILE *f, fresnel_ior_prep_q15 q)
{
    fprintf(f, "{%ld, %ld, %ld, ", (long)q.a0, (long)q.a0_lo, (long)q.shift);
    emit_q15_qf(f, q.b);
    fputs(", ", f);
    emit_q15_qf(f, q.n4);
    fputs(", ", f);
    emit_q15_qf(f, q.t1_inv);
    fputs(", ", f);
    emit_q15_qf(f, q.inv_eta2);
    fputc('}', f);
}

void emit_q15_nk(FILE *f, fresnel_nk_prep_q15 q)
{
    fputc('{', f);
    emit_q15_qf(f, q.n);
    fputs(", ", f);
    emit_q15_qf(f, q.nk2);
    fputc('}', f);
}

void emit_q15_lsk(FILE *f, fresnel_lsk_prep_q15 q)
{
    fprintf(f, "{%lu, ", (unsigned long)q.f0);
    emit_q15_qf(f, q.a);
    fprintf(f, ", %ld}", (long)q.alpha);
}

void emit_q15_conductor_fast(FILE *f, fresnel_conductor_prep_q15_fast q)
{
    fprintf(f, "{%ld, %ld, %ld, %ld, %ld, %ld, %ld, %lu}", (long)q.a0, (long)q.a0_lo, (long)q.shift, (long)q.b1,
            (long)q.b2, (long)q.bm, (long)q.be, (unsigned long)q.span);
}

/* The encoder's codes of a parameter. */
static void emit_q15_rgb(fx_out *o, const char *prefix, const char *name, fresnel_rgb_q15 code, const char *why)
{
    char id[160];
    snprintf(id, sizeof id, "%s_%s_q15", prefix, name);
    fprintf(o->f, "/* %s, Q1.15 (r, g, b) */\nstatic const fresnel_rgb_q15 %s FRESNEL_GEN_UNUSED = {%ld, %ld, %ld};\n",
            why, id, (long)code.r, (long)code.g, (long)code.b);
}


#define IOR_FIELDS "fields a0, a0_lo, shift, b, n4, t1_inv, inv_eta2 (fresnel_q15.h LAYOUT)"

static void emit_ior3(fx_out *o, const char *prefix, const char *name, const fresnel_ior_prep_q15 q[3],
                      const char *why)
{
    char id[160];
    int ch;
    snprintf(id, sizeof id, "%s_%s_q15", prefix, name);
    fprintf(o->f, "/* %s: prepared complex index per channel (fresnel_conductor_q15_rgb);\n * " IOR_FIELDS " */\n"
                  "static const fresnel_ior_prep_q15 %s[3] FRESNEL_GEN_UNUSED = {\n",
            why, id);
    for (ch = 0; ch < 3; ch++) {
        fputs("    ", o->f);
        emit_q15_ior(o->f, q[ch]);
        fputs(ch < 2 ? ",\n" : "\n};\n", o->f);
    }
}

/* The fitted eta, kappa for the inline fast path, where every channel lies
 * in its domain (its bound holds only there); else a comment says which
 * channel does not. */
static void emit_ior_fast3(fx_out *o, const char *prefix, const double *eta, const double *kappa,
                           const encoded_material *e)
{
    static const char *const channel[3] = {"red", "green", "blue"};
    char id[160];
    int ch = e->q_ior_fast_out;
    snprintf(id, sizeof id, "%s_ior_fast_q15", prefix);
    if (ch >= 0) {
        fprintf(o->f, "/* no %s: the %s channel's eta %.6g, kappa %.6g lie outside\n * fresnel_conductor_q15_fast's "
                      "domain (fresnel_q15_fast.h) */\n",
                id, channel[ch], eta[ch], kappa[ch]);
        return;
    }
    fprintf(o->f, "/* the same eta, kappa for fresnel_conductor_q15_rgb_fast (fresnel_q15_fast.h; one\n"
                  " * channel: fresnel_conductor_q15_fast); fields a0, a0_lo, shift, b1, b2, bm, be, span */\n"
                  "static const fresnel_conductor_prep_q15_fast %s[3] FRESNEL_GEN_UNUSED = {\n",
            id);
    for (ch = 0; ch < 3; ch++) {
        fputs("    ", o->f);
        emit_q15_conductor_fast(o->f, e->q_ior_fast[ch]);
        fputs(ch < 2 ? ",\n" : "\n};\n", o->f);
    }
}

static void emit_nk3(fx_out *o, const char *prefix, const encoded_material *e)
{
    char id[160];
    int ch;
    snprintf(id, sizeof id, "%s_nk_q15", prefix);
    fprintf(o->f, "/* approximate conductor on the fitted eta, kappa (fresnel_approx_conductor_q15_rgb);\n"
                  " * fields n, nk2 */\n"
                  "static const fresnel_nk_prep_q15 %s[3] FRESNEL_GEN_UNUSED = {\n",
            id);
    for (ch = 0; ch < 3; ch++) {
        fputs("    ", o->f);
        emit_q15_nk(o->f, e->q_nk[ch]);
        fputs(ch < 2 ? ",\n" : "\n};\n", o->f);
    }
}

static void emit_lsk3(fx_out *o, const char *prefix, const char *name, int comp,
                      const fresnel_lsk_prep_q15 prep[3])
{
    char id[160];
    int ch;
    snprintf(id, sizeof id, "%s_%s_q15", prefix, name);
    fprintf(o->f, "/* LSK%s on the fitted eta, kappa (fresnel_lsk%s_q15_rgb); fields f0, a, alpha */\n"
                  "static const fresnel_lsk_prep_q15 %s[3] FRESNEL_GEN_UNUSED = {\n",
            comp ? " with compensation" : " rescaled", comp ? "_comp" : "", id);
    for (ch = 0; ch < 3; ch++) {
        fputs("    ", o->f);
        emit_q15_lsk(o->f, prep[ch]);
        fputs(ch < 2 ? ",\n" : "\n};\n", o->f);
    }
}

static void emit_lut_q15(fx_out *o, const char *prefix, const scene_entry *e, const encoded_lut *t)
{
    FILE *f = o->f;
    lut_spacing spacing = o->in->sc->spacing;
    const char *model = e->name, *name = e->ident;
    int n = t->n, i;
    char id[160];
    snprintf(id, sizeof id, "%s_%s_q15", prefix, name);
    if (t->form == LUT_RESIDUAL)
        fprintf(f, "/* %s in Q1.15: residual (GT - Schlick(F0)) * 2^%d as int16. Evaluate with\n"
                   " * fresnel_lut_%sresidual_s16_q15_rgb(f0_q15, table, %d, %s_%s_frac, c). */\n"
                   "enum { %s_%s_frac = %d };\n"
                   "static const int16_t %s[%d] FRESNEL_GEN_UNUSED = {",
                model, t->frac, spacing == LUT_UNIFORM ? "linear_" : "", n, prefix, name, prefix, name, t->frac, id,
                3 * n);
    else if (spacing == LUT_GRAZING_PL)
        fprintf(f, "/* %s in Q1.15 (uint16 codes, 32768 = 1), nodes uniform in fresnel_q15_fast.h's\n"
                   " * piecewise-linear sqrt(c). Evaluate per channel with\n"
                   " * fresnel_lut_pl_u16_q15_fast(table + ch * %d, %d, c). */\n"
                   "static const uint16_t %s[%d] FRESNEL_GEN_UNUSED = {",
                model, n, n, id, 3 * n);
    else
        fprintf(f, "/* %s in Q1.15 (uint16 codes, 32768 = 1). Evaluate with\n"
                   " * fresnel_lut_%su16_q15_rgb(table, %d, c). */\n"
                   "static const uint16_t %s[%d] FRESNEL_GEN_UNUSED = {",
                model, t->form == LUT_CUBIC ? "cubic_" : (spacing == LUT_UNIFORM ? "linear_" : ""), n, id, 3 * n);
    for (i = 0; i < 3 * n; i++)
        fprintf(f, "%s%ld%s", i % 12 == 0 ? "\n    " : " ", t->form == LUT_RESIDUAL ? (long)t->q15_res[i] : (long)t->q15[i],
                i + 1 < 3 * n ? "," : "");
    fprintf(f, "\n};\n");
}

/* F82's fast coefficient, after F82's codes (fresnel_f82_q15_rgb_fast
 * reads both). */
static void emit_f82_a(fx_out *o, const char *prefix, const encoded_material *e)
{
    int ch;
    char id[160];
    long a[3];
    snprintf(id, sizeof id, "%s_f82_a_q12", prefix);
    for (ch = 0; ch < 3; ch++)
        a[ch] = e->q_f82_a[ch];
    fprintf(o->f, "/* F82's a = (7^7/6^6)(F0 - F82) + (49/6)(1 - F0) times 4096, from the Q1.15 F0 and F82\n"
                  " * (fresnel_f82_q15_rgb_fast(f0, a, c) in fresnel_q15_fast.h) */\n"
                  "static const int32_t %s[3] FRESNEL_GEN_UNUSED = {%ld, %ld, %ld};\n",
            id, a[0], a[1], a[2]);
}

/* The parameters held as codes (catalog/parameters.h), each where its
 * models read it; F0 says when it is held to one. */
#define EMIT_CODE_Q15_NONE(field, constant, why)
#define EMIT_CODE_Q15_CODE(field, constant, why) emit_q15_rgb(&o, prefix, constant, e->q_##field, why);
#define EMIT_CODE_Q15_CODE_ONE(field, constant, why) emit_q15_rgb(&o, prefix, constant, e->q_##field, why);
#define EMIT_CODE_Q15_CODE_HELD(field, constant, why)                                                                  \
    emit_q15_rgb(&o, prefix, constant, e->q_##field,                                                                   \
                 e->q_##field##_held ? why ", held to one where the gamut policy keeps it above (every Q1.15 function " \
                                       "reads it\n * so, and the fast paths of fresnel_q15_fast.h take f0 only up to one)" \
                                     : why);
#define EMIT_CODE(field, count, group, constant, row, why, q15, q15_why)                                               \
    if (reads & (group)) {                                                                                             \
        EMIT_CODE_##q15(field, constant, q15_why)                                                                      \
        if (PARAM_ADDRESS_##count(p->field) == p->f82)                                                                 \
            emit_f82_a(&o, prefix, e);                                                                              \
    }

int emit_q15_material(FILE *f, const emit_input *in, int mi, const char *prefix)
{
    const scene *sc = in->sc;
    const material_params *p = &in->params[mi];
    const encoded_material *e = &in->enc[mi];
    unsigned reads = scene_reads(sc, 0) | (sc->f_avg ? MP_F_AVG : 0u), q15_reads = scene_reads(sc, 1);
    int m;
    fx_out o;
    o.f = f;
    o.in = in;
    DERIVED_PARAMETERS(EMIT_CODE)
    if (q15_reads & MQ_LSK)
        emit_lsk3(&o, prefix, "lsk", 0, e->q_lsk);
    if (q15_reads & MQ_LSK_COMP)
        emit_lsk3(&o, prefix, "lsk_comp", 1, e->q_lsk_comp);
    if (q15_reads & MQ_IOR) {
        emit_ior3(&o, prefix, "ior", e->q_ior[ETA_FIT], "eta, kappa fitted to the ground truth");
        emit_ior_fast3(&o, prefix, p->eta_fit, p->kappa_fit, e);
    }
    if (q15_reads & MQ_IOR_GAUSS)
        emit_ior3(&o, prefix, "ior_gaussian", e->q_ior[ETA_GAUSS],
                  "Metzgar's Gaussian-window eta', kappa'");
    if (q15_reads & MQ_IOR_POINT)
        emit_ior3(&o, prefix, "ior_point", e->q_ior[ETA_POINT], "eta, kappa point-sampled");
    if (q15_reads & MQ_NK)
        emit_nk3(&o, prefix, e);
    if (q15_reads & MQ_CT) {
        char id[160];
        snprintf(id, sizeof id, "%s_ct_ior_q15", prefix);
        fprintf(f, "/* Cook-Torrance's representative IOR (fresnel_cook_torrance_q15_rgb);\n * " IOR_FIELDS " */\n"
                   "static const fresnel_ior_prep_q15 %s FRESNEL_GEN_UNUSED = ",
                id);
        emit_q15_ior(o.f, e->q_ct);
        fputs(";\n", f);
    }
    for (m = 0; m < sc->model_count; m++)
        if (emit_lut(in, mi, m)->n)
            emit_lut_q15(&o, prefix, &sc->models[m], emit_lut(in, mi, m));
    return emit_film(f, in, mi, prefix, TYPE_Q15);
}
