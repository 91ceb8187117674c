/* Stage 4, emit, fixed point: a scene's constants and tables in the formats of
 * include/fresnel_fixed.h (its LAYOUT section), as the encoder converted
 * them (3_encode/encode.h: encode_material, encode_table), which is what
 * every evaluation of the scene reads too.
 *
 * Every value is checked against its C type and the range the runtime
 * documents before it is written; one that does not fit stops the run with
 * the manifest's file:line (the caller removes the partial output), because
 * a wrapped or clamped constant compiles into a silently wrong reflectance.
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

/* Where a value that does not fit is reported, and whether one did. */
typedef struct fx_out {
    FILE *f;
    const emit_input *in;
    int bad;
} fx_out;

/* v must be an integer in [lo, hi]; else report it once (the first). */
static long fx_check(fx_out *o, double v, double lo, double hi, const char *type, const char *what, const char *id)
{
    if (!(v >= lo && v <= hi && v == floor(v))) {
        if (!o->bad) {
            char where[1100];
            snprintf(where, sizeof where, "%s:%d", o->in->manifest_path, o->in->sc->models_line);
            cli_error(where, "%s of %s is %.17g, which does not fit %s [%.17g, %.17g]; no header written", what, id, v,
                      type, lo, hi);
        }
        o->bad = 1;
        return 0;
    }
    return (long)v;
}

/* The value a constant derives from must be finite (NaN or an infinity
 * would turn into an arbitrary code). */
static void fx_finite(fx_out *o, double v, const char *what, const char *id)
{
    if (!(v - v == 0.0))
        fx_check(o, v, -1e300, 1e300, "a finite number", what, id);
}

/* A qf as the LAYOUT defines it: {0, 0}, or m in [2^30, 2^31). */
static void put_qf(fx_out *o, fresnel_qf q, const char *what, const char *id)
{
    if (q.m != 0 || q.e != 0)
        fx_check(o, (double)q.m, 1073741824.0, 2147483647.0, "fresnel_qf.m [2^30, 2^31)", what, id);
    fprintf(o->f, "{%lu, %ld}", (unsigned long)q.m, (long)q.e);
}

/* A reflectance-like value in Q1.15: round(v 32768) in [0, hi]; hi is
 * 65535 for values the keep policy may take above 1. */
static long q15_code(fx_out *o, double v, long hi, const char *what, const char *id)
{
    fx_finite(o, v, what, id);
    return fx_check(o, v - v == 0.0 ? floor(v * 32768.0 + 0.5) : 0.0, 0.0, (double)hi,
                    hi == 32768 ? "Q1.15 [0, one]" : "Q1.15 [0, 2)", what, id);
}

/* The encoder's codes of v (checked: v in the type's range, below hi). */
static void emit_q15_rgb(fx_out *o, const char *prefix, const char *name, const double v[3], fresnel_rgb_q15 code,
                         long hi, const char *why)
{
    char id[160];
    int ch;
    snprintf(id, sizeof id, "%s_%s_q15", prefix, name);
    for (ch = 0; ch < 3; ch++)
        q15_code(o, v[ch], hi, why, id);
    fprintf(o->f, "/* %s, Q1.15 (r, g, b) */\nstatic const fresnel_rgb_q15 %s FRESNEL_GEN_UNUSED = {%ld, %ld, %ld};\n",
            why, id, (long)code.r, (long)code.g, (long)code.b);
}

/* The encoder's q of eta, kappa (clamped to fresnel.h's domain by fixed_ior,
 * as the binary32 runtime clamps them). */
static void put_ior(fx_out *o, double eta, double kappa, fresnel_ior_prep_q15 q, const char *id)
{
    fx_finite(o, eta, "eta", id);
    fx_finite(o, kappa, "kappa", id);
    fx_check(o, q.shift, 0.0, 30.0, "shift [0, 30]", "the ior's shift", id);
    fx_check(o, (double)q.a0 + ldexp(1.0, 30 - (q.shift < 0 || q.shift > 30 ? 0 : (int)q.shift)),
             -2147483647.0 - 1.0, 2147483647.0, "int32_t (a0 + 2^(30 - shift))", "the ior's a0", id);
    fx_check(o, q.a0_lo, -536870912.0, 536870912.0, "a0_lo [-2^29, 2^29]", "the ior's a0_lo", id);
    fprintf(o->f, "{%ld, %ld, %ld, ", (long)q.a0, (long)q.a0_lo, (long)q.shift);
    put_qf(o, q.b, "the ior's b", id);
    fputs(", ", o->f);
    put_qf(o, q.n4, "the ior's n4", id);
    fputs(", ", o->f);
    put_qf(o, q.t1_inv, "the ior's t1_inv", id);
    fputs(", ", o->f);
    put_qf(o, q.inv_eta2, "the ior's inv_eta2", id);
    fputc('}', o->f);
}

#define IOR_FIELDS "fields a0, a0_lo, shift, b, n4, t1_inv, inv_eta2 (fresnel_q15.h LAYOUT)"

static void emit_ior3(fx_out *o, const char *prefix, const char *name, const double *eta, const double *kappa,
                      const fresnel_ior_prep_q15 q[3], const char *why)
{
    char id[160];
    int ch;
    snprintf(id, sizeof id, "%s_%s_q15", prefix, name);
    fprintf(o->f, "/* %s: prepared complex index per channel (fresnel_conductor_q15_rgb);\n * " IOR_FIELDS " */\n"
                  "static const fresnel_ior_prep_q15 %s[3] FRESNEL_GEN_UNUSED = {\n",
            why, id);
    for (ch = 0; ch < 3; ch++) {
        fputs("    ", o->f);
        put_ior(o, eta[ch], kappa[ch], q[ch], id);
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
        fresnel_conductor_prep_q15_fast q = e->q_ior_fast[ch];
        fprintf(o->f, "    {%ld, %ld, %ld, %ld, %ld, %ld, %ld, %lu}%s\n", (long)q.a0, (long)q.a0_lo, (long)q.shift,
                (long)q.b1, (long)q.b2, (long)q.bm, (long)q.be, (unsigned long)q.span, ch < 2 ? "," : "\n};");
    }
}

static void emit_nk3(fx_out *o, const char *prefix, const material_params *p, const encoded_material *e)
{
    char id[160];
    int ch;
    snprintf(id, sizeof id, "%s_nk_q15", prefix);
    fprintf(o->f, "/* approximate conductor on the fitted eta, kappa (fresnel_approx_conductor_q15_rgb);\n"
                  " * fields n, nk2 */\n"
                  "static const fresnel_nk_prep_q15 %s[3] FRESNEL_GEN_UNUSED = {\n",
            id);
    for (ch = 0; ch < 3; ch++) {
        fresnel_nk_prep_q15 q = e->q_nk[ch];
        fx_finite(o, p->eta_fit[ch], "eta", id);
        fx_finite(o, p->kappa_fit[ch], "kappa", id);
        fputs("    {", o->f);
        put_qf(o, q.n, "n", id);
        fputs(", ", o->f);
        put_qf(o, q.nk2, "nk2", id);
        fputs(ch < 2 ? "},\n" : "}\n};\n", o->f);
    }
}

static void emit_lsk3(fx_out *o, const char *prefix, const char *name, const material_params *p, int comp,
                      const fresnel_lsk_prep_q15 prep[3])
{
    char id[160];
    int ch;
    snprintf(id, sizeof id, "%s_%s_q15", prefix, name);
    fprintf(o->f, "/* LSK%s on the fitted eta, kappa (fresnel_lsk%s_q15_rgb); fields f0, a, alpha */\n"
                  "static const fresnel_lsk_prep_q15 %s[3] FRESNEL_GEN_UNUSED = {\n",
            comp ? " with compensation" : " rescaled", comp ? "_comp" : "", id);
    for (ch = 0; ch < 3; ch++) {
        fresnel_lsk_prep_q15 q = prep[ch];
        double f0;
        fx_finite(o, p->eta_fit[ch], "eta", id);
        fx_finite(o, p->kappa_fit[ch], "kappa", id);
        if (comp) {
            fx_finite(o, p->lsk_a[ch], "the compensation weight a", id);
            fx_finite(o, p->lsk_alpha[ch], "the compensation exponent alpha", id);
        }
        f0 = floor(ref_f0_from_ior(p->eta_fit[ch], p->kappa_fit[ch]) * 1073741824.0 + 0.5);
        fx_check(o, f0 == f0 ? f0 : -1.0, 0.0, 1073741824.0, "Q30 F0 [0, 2^30]", "LSK f0", id);
        fx_check(o, q.alpha, 0.0, FRESNEL_ALPHA_MAX_Q16, "Q16.16 alpha [0, 1000]", "LSK alpha", id);
        fprintf(o->f, "    {%lu, ", (unsigned long)q.f0);
        put_qf(o, q.a, "LSK a", id);
        fprintf(o->f, ", %ld%s", (long)q.alpha, ch < 2 ? "},\n" : "}\n};\n");
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

int emit_fixed_material(FILE *f, const emit_input *in, int mi, const char *prefix, const encoded_lut *luts)
{
    const scene *sc = in->sc;
    const material_params *p = &in->params[mi];
    const encoded_material *e = &in->enc[mi];
    unsigned reads = scene_reads(sc, 0), q15_reads = scene_reads(sc, 1);
    int m;
    fx_out o;
    o.f = f;
    o.in = in;
    o.bad = 0;
    if (reads & MP_F0)
        emit_q15_rgb(&o, prefix, "f0", p->f0, e->q_f0, 65535,
                     e->q_f0_held ? "F0, held to one where the gamut policy keeps it above (every Q1.15 function reads it\n"
                                    " * so, and the fast paths of fresnel_q15_fast.h take f0 only up to one)"
                                  : "F0");
    if (sc->f_avg)
        emit_q15_rgb(&o, prefix, "f_avg", p->f_avg, e->q_f_avg, 65535, "F_avg = 2 int F(mu) mu dmu of the ground truth");
    if (reads & MP_F82) {
        int ch;
        char id[160];
        long a[3];
        emit_q15_rgb(&o, prefix, "f82", p->f82, e->q_f82, 65535, "F82");
        snprintf(id, sizeof id, "%s_f82_a_q12", prefix);
        for (ch = 0; ch < 3; ch++) {
            fx_finite(&o, p->f0[ch], "F0", id);
            fx_finite(&o, p->f82[ch], "F82", id);
            /* fresnel_f82_q15_fast documents |a_q12| <= 73000 */
            a[ch] = fx_check(&o, (double)e->q_f82_a[ch], -73000.0, 73000.0, "a_q12 [-73000, 73000]", "F82's a", id);
        }
        fprintf(f, "/* F82's a = (7^7/6^6)(F0 - F82) + (49/6)(1 - F0) times 4096, from the Q1.15 F0 and F82\n"
                   " * (fresnel_f82_q15_rgb_fast(f0, a, c) in fresnel_q15_fast.h) */\n"
                   "static const int32_t %s[3] FRESNEL_GEN_UNUSED = {%ld, %ld, %ld};\n",
                id, a[0], a[1], a[2]);
    }
    if (reads & MP_GULB) {
        emit_q15_rgb(&o, prefix, "gulbrandsen_r", p->gulb_r, e->q_gulb_r, 32768, "Gulbrandsen r");
        emit_q15_rgb(&o, prefix, "gulbrandsen_g", p->gulb_g, e->q_gulb_g, 32768, "Gulbrandsen g");
    }
    if (q15_reads & MQ_LSK)
        emit_lsk3(&o, prefix, "lsk", p, 0, e->q_lsk);
    if (q15_reads & MQ_LSK_COMP)
        emit_lsk3(&o, prefix, "lsk_comp", p, 1, e->q_lsk_comp);
    if (q15_reads & MQ_IOR) {
        emit_ior3(&o, prefix, "ior", p->eta_fit, p->kappa_fit, e->q_ior[ETA_FIT], "eta, kappa fitted to the ground truth");
        emit_ior_fast3(&o, prefix, p->eta_fit, p->kappa_fit, e);
    }
    if (q15_reads & MQ_IOR_GAUSS)
        emit_ior3(&o, prefix, "ior_gaussian", p->eta_gauss, p->kappa_gauss, e->q_ior[ETA_GAUSS],
                  "Metzgar's Gaussian-window eta', kappa'");
    if (q15_reads & MQ_IOR_POINT)
        emit_ior3(&o, prefix, "ior_point", p->eta_point, p->kappa_point, e->q_ior[ETA_POINT], "eta, kappa point-sampled");
    if (q15_reads & MQ_NK)
        emit_nk3(&o, prefix, p, e);
    if (q15_reads & MQ_CT) {
        char id[160];
        snprintf(id, sizeof id, "%s_ct_ior_q15", prefix);
        fprintf(f, "/* Cook-Torrance's representative IOR (fresnel_cook_torrance_q15_rgb);\n * " IOR_FIELDS " */\n"
                   "static const fresnel_ior_prep_q15 %s FRESNEL_GEN_UNUSED = ",
                id);
        put_ior(&o, p->ct_eta, p->ct_kappa, e->q_ct, id);
        fputs(";\n", f);
    }
    for (m = 0; m < sc->model_count && !o.bad; m++)
        if (luts[m].n)
            emit_lut_q15(&o, prefix, &sc->models[m], &luts[m]);
    return o.bad ? CLI_BAD_INPUT : emit_film(f, in, mi, prefix, TYPE_Q15);
}
