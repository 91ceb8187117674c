/* Step 8 for fixed point: a scene's constants and tables in the formats of
 * include/fresnel_fixed.h (its LAYOUT section), converted from the derived
 * double parameters by gen/fixed_params.c. Designated initialisers name every
 * field, so the output does not depend on the structs' field order. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "emit.h"
#include "fixed_params.h"
#include "scene.h"

static void put_qf(FILE *f, fresnel_qf q) { fprintf(f, "{%lu, %ld}", (unsigned long)q.m, (long)q.e); }

static void emit_q15_rgb(FILE *f, const char *prefix, const char *name, const double v[3], const char *why)
{
    fprintf(f, "/* %s, Q1.15 */\nstatic const fresnel_q15_rgb %s_%s_q15 FRESNEL_GEN_UNUSED = {%ld, %ld, %ld};\n", why,
            prefix, name, (long)fixed_q15(v[0]), (long)fixed_q15(v[1]), (long)fixed_q15(v[2]));
}

static void put_ior(FILE *f, double eta, double kappa)
{
    fresnel_q15_ior q;
    fixed_ior(eta, kappa, &q);
    fprintf(f, "{.a0 = %ld, .a0_lo = %ld, .shift = %ld, .b = ", (long)q.a0, (long)q.a0_lo, (long)q.shift);
    put_qf(f, q.b);
    fputs(", .n4 = ", f);
    put_qf(f, q.n4);
    fputs(", .t1_inv = ", f);
    put_qf(f, q.t1_inv);
    fputs(", .inv_eta2 = ", f);
    put_qf(f, q.inv_eta2);
    fputc('}', f);
}

static void emit_ior3(FILE *f, const char *prefix, const char *name, const double *eta, const double *kappa,
                      const char *why)
{
    int ch;
    fprintf(f, "/* %s: prepared complex index per channel (fresnel_conductor_q15_rgb) */\n"
               "static const fresnel_q15_ior %s_%s_q15[3] FRESNEL_GEN_UNUSED = {\n",
            why, prefix, name);
    for (ch = 0; ch < 3; ch++) {
        fputs("    ", f);
        put_ior(f, eta[ch], kappa[ch]);
        fputs(ch < 2 ? ",\n" : "\n};\n", f);
    }
}

static void emit_nk3(FILE *f, const char *prefix, const material_params *p)
{
    int ch;
    fprintf(f, "/* approximate conductor on the fitted eta, kappa (fresnel_approx_conductor_q15_rgb) */\n"
               "static const fresnel_q15_nk %s_nk_q15[3] FRESNEL_GEN_UNUSED = {\n",
            prefix);
    for (ch = 0; ch < 3; ch++) {
        fresnel_q15_nk q;
        fixed_nk(p->eta_fit[ch], p->kappa_fit[ch], &q);
        fputs("    {.n = ", f);
        put_qf(f, q.n);
        fputs(", .nk2 = ", f);
        put_qf(f, q.nk2);
        fputs(ch < 2 ? "},\n" : "}\n};\n", f);
    }
}

static void emit_lsk3(FILE *f, const char *prefix, const char *name, const material_params *p, int comp)
{
    int ch;
    fprintf(f, "/* LSK%s on the fitted eta, kappa (fresnel_lsk%s_q15_rgb) */\n"
               "static const fresnel_q15_lsk %s_%s_q15[3] FRESNEL_GEN_UNUSED = {\n",
            comp ? " with compensation" : " rescaled", comp ? "_comp" : "", prefix, name);
    for (ch = 0; ch < 3; ch++) {
        fresnel_q15_lsk q;
        fixed_lsk(p->eta_fit[ch], p->kappa_fit[ch], comp ? p->lsk_a[ch] : 0.0, comp ? p->lsk_alpha[ch] : 0.0, &q);
        fprintf(f, "    {.f0 = %lu, .a = ", (unsigned long)q.f0);
        put_qf(f, q.a);
        fprintf(f, ", .alpha = %ld%s", (long)q.alpha, ch < 2 ? "},\n" : "}\n};\n");
    }
}

static int emit_lut_q15(FILE *f, const char *prefix, const char *model, const material_params *p,
                        const spectrum *s, const gen_context *g, lut_spacing spacing)
{
    int residual, n, i, frac = 15;
    lut_form form;
    char name[32];
    double big = 0.0, *t = emit_lut_table(model, p, s, g, spacing, &n, &form, name);
    if (!t)
        return cli_oom("fresnel gen");
    residual = form == LUT_RESIDUAL;
    if (residual) {
        /* as many fraction bits as int16 holds for the largest residual */
        for (i = 0; i < 3 * n; i++)
            if (fabs(t[i]) > big)
                big = fabs(t[i]);
        while (frac < 30 && big * ldexp(1.0, frac + 1) <= 32767.0)
            frac++;
        fprintf(f, "/* %s in Q1.15: residual (GT - Schlick(F0)) * 2^%d as int16. Evaluate with\n"
                   " * fresnel_lut_%sresidual_q15_s16_rgb(f0_q15, table, %d, %s_%s_frac, c). */\n"
                   "enum { %s_%s_frac = %d };\n"
                   "static const int16_t %s_%s_q15[%d] FRESNEL_GEN_UNUSED = {",
                model, frac, spacing == LUT_UNIFORM ? "linear_" : "", n, prefix, name, prefix, name, frac, prefix,
                name, 3 * n);
    } else {
        if (spacing == LUT_GRAZING_PL)
            fprintf(f, "/* %s in Q1.15 (uint16 codes, 32768 = 1), nodes uniform in fresnel_fixed.h's\n"
                       " * piecewise-linear sqrt(c). Evaluate per channel with\n"
                       " * fresnel_lut_q15_u16_pl_fast(table + ch * %d, %d, c). */\n"
                       "static const uint16_t %s_%s_q15[%d] FRESNEL_GEN_UNUSED = {",
                    model, n, n, prefix, name, 3 * n);
        else
            fprintf(f, "/* %s in Q1.15 (uint16 codes, 32768 = 1). Evaluate with\n"
                       " * fresnel_lut_%sq15_u16_rgb(table, %d, c). */\n"
                       "static const uint16_t %s_%s_q15[%d] FRESNEL_GEN_UNUSED = {",
                    model, form == LUT_CUBIC ? "cubic_" : (spacing == LUT_UNIFORM ? "linear_" : ""), n, prefix, name,
                    3 * n);
    }
    for (i = 0; i < 3 * n; i++)
        fprintf(f, "%s%ld%s", i % 12 == 0 ? "\n    " : " ",
                residual ? lround(t[i] * ldexp(1.0, frac)) : (long)fixed_q15(t[i]), i + 1 < 3 * n ? "," : "");
    fprintf(f, "\n};\n");
    free(t);
    return 0;
}

int emit_fixed_material(FILE *f, const emit_input *in, int mi, const char *prefix)
{
    const scene *sc = in->sc;
    const material_params *p = &in->params[mi];
    lut_spacing spacing = scene_lut_spacing(sc);
    int m, residual_lut = 0;
    for (m = 0; m < sc->model_count; m++) {
        int form = LUT_PLAIN;
        if (scene_model_lut_size(sc->models[m], &form) && form == LUT_RESIDUAL)
            residual_lut = 1;
    }
    if (scene_has_model(sc, "schlick") || scene_has_model(sc, "f82") || scene_has_model(sc, "cook-torrance") || residual_lut)
        emit_q15_rgb(f, prefix, "f0", p->f0, "F0");
    if (scene_has_model(sc, "f82")) {
        int ch;
        emit_q15_rgb(f, prefix, "f82", p->f82, "F82");
        fprintf(f, "/* F82's a = (7^7/6^6)(F0 - F82) + (49/6)(1 - F0) times 4096, from the Q1.15 F0 and F82\n"
                   " * (fresnel_f82_q15_fast(f0.r, a[0], c)) */\n"
                   "static const int32_t %s_f82_a_q12[3] FRESNEL_GEN_UNUSED = {",
                prefix);
        for (ch = 0; ch < 3; ch++)
            fprintf(f, "%ld%s", (long)fixed_f82_a_q12(fixed_q15(p->f0[ch]), fixed_q15(p->f82[ch])),
                    ch < 2 ? ", " : "};\n");
    }
    if (scene_has_model(sc, "gulbrandsen")) {
        emit_q15_rgb(f, prefix, "gulbrandsen_r", p->gulb_r, "Gulbrandsen r");
        emit_q15_rgb(f, prefix, "gulbrandsen_g", p->gulb_g, "Gulbrandsen g");
    }
    if (scene_has_model(sc, "lsk"))
        emit_lsk3(f, prefix, "lsk", p, 0);
    if (scene_has_model(sc, "lsk-comp"))
        emit_lsk3(f, prefix, "lsk_comp", p, 1);
    if (scene_has_model(sc, "exact"))
        emit_ior3(f, prefix, "ior", p->eta_fit, p->kappa_fit, "eta, kappa fitted to the ground truth");
    if (scene_has_model(sc, "exact-gaussian"))
        emit_ior3(f, prefix, "ior_gaussian", p->eta_gauss, p->kappa_gauss, "Metzgar's Gaussian-window eta', kappa'");
    if (scene_has_model(sc, "exact-point"))
        emit_ior3(f, prefix, "ior_point", p->eta_point, p->kappa_point, "eta, kappa point-sampled");
    if (scene_has_model(sc, "approx-conductor"))
        emit_nk3(f, prefix, p);
    if (scene_has_model(sc, "cook-torrance")) {
        fprintf(f, "/* Cook-Torrance's representative IOR (fresnel_cook_torrance_q15_rgb) */\n"
                   "static const fresnel_q15_ior %s_ct_ior_q15 FRESNEL_GEN_UNUSED = ",
                prefix);
        put_ior(f, p->ct_eta, p->ct_kappa);
        fputs(";\n", f);
    }
    for (m = 0; m < sc->model_count; m++)
        if (scene_model_lut_size(sc->models[m], NULL) &&
            emit_lut_q15(f, prefix, sc->models[m], p, in->spectra[mi], in->g, spacing))
            return CLI_BAD_INPUT;
    return 0;
}
