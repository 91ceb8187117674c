/* Stage 4, emit: one C header per scene holding exactly the constants its
 * materials, models and number types need [design card: "leave out what a
 * scene does not need"]. Output depends only on the manifest and the data:
 * no dates, no absolute paths, fixed number formatting. */
#include <ctype.h>
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "4_emit/emit.h"
#include "scene/scene.h"

/* A binary32 literal that reads back to the same float: 9 significant
 * digits, always with a '.' or an exponent, and the 'f' suffix. (GLSL:
 * emit_glsl.c.) */
static void put_float(FILE *f, double v)
{
    char buf[40];
    snprintf(buf, sizeof buf, "%.9g", (double)(float)v);
    fputs(buf, f);
    if (!strpbrk(buf, ".e"))
        fputs(".0", f);
    fputc('f', f);
}

static void emit_rgb(FILE *f, const char *prefix, const char *name, const double v[3], const char *why)
{
    fprintf(f, "/* %s */\nstatic const fresnel_rgb %s_%s FRESNEL_GEN_UNUSED = {", why, prefix, name);
    put_float(f, v[0]);
    fputs(", ", f);
    put_float(f, v[1]);
    fputs(", ", f);
    put_float(f, v[2]);
    fputs("};\n", f);
}

static void emit_float(FILE *f, const char *prefix, const char *name, double v, const char *why)
{
    fprintf(f, "/* %s */\nstatic const float %s_%s FRESNEL_GEN_UNUSED = ", why, prefix, name);
    put_float(f, v);
    fputs(";\n", f);
}

static int emit_lut(FILE *f, const emit_input *in, const char *prefix, const char *model, const material_params *p, const spectrum *s,
                    const gen_context *g, lut_spacing spacing)
{
    int n, i, residual;
    lut_form form;
    char name[32];
    double *t = emit_lut_table(model, p, s, g, spacing, &n, &form, name);
    const char *suffix = form == LUT_RESIDUAL ? "_residual" : (form == LUT_CUBIC ? "_cubic" : "");
    if (!t)
        return cli_oom("fresnel gen");
    for (i = 0; i < 3 * n; i++)
        if (!(fabs(t[i]) <= FLT_MAX)) {
            char where[1100];
            snprintf(where, sizeof where, "%s:%d", in->manifest_path, in->sc->models_line);
            cli_error(where, "%s: %s node %d is %g, not a binary32 float; no header written", prefix, model, i, t[i]);
            free(t);
            return CLI_BAD_INPUT;
        }
    residual = form == LUT_RESIDUAL;
    fprintf(f, "/* %s: %d nodes per channel (red, then green, then blue), uniform in %s,\n"
               " * fitted to the ground truth through %s interpolation.\n",
            model, n, spacing == LUT_UNIFORM ? "cos theta" : "sqrt(cos theta), from grazing to normal",
            form == LUT_CUBIC ? "Catmull-Rom" : "linear");
    fprintf(f, " * Evaluate with fresnel_%s%s_rgb(%stable, %d, c). */\n", spacing == LUT_UNIFORM ? "lut_linear" : "lut",
            suffix, residual ? "f0, " : "", n);
    fprintf(f, "static const float %s_%s[%d] FRESNEL_GEN_UNUSED = {", prefix, name, 3 * n);
    for (i = 0; i < 3 * n; i++) {
        fputs(i % 6 == 0 ? "\n    " : " ", f);
        put_float(f, t[i]);
        if (i + 1 < 3 * n)
            fputc(',', f);
    }
    fprintf(f, "\n};\n");
    free(t);
    return 0;
}

/* Every derived constant the header may hold as a float must be a finite
 * binary32 (a literal beyond FLT_MAX would read inf.0f and not compile). */
static int params_fit_float(const emit_input *in, const material_params *p)
{
    const struct {
        const char *what;
        const double *v;
        int count;
    } all[] = {{"F0", p->f0, 3},           {"F82", p->f82, 3},           {"F_avg", p->f_avg, 3},           {"eta", p->eta_fit, 3},
               {"kappa", p->kappa_fit, 3}, {"LSK a", p->lsk_a, 3},      {"LSK alpha", p->lsk_alpha, 3},
               {"eta'", p->eta_gauss, 3},  {"kappa'", p->kappa_gauss, 3}, {"eta point", p->eta_point, 3},
               {"kappa point", p->kappa_point, 3}, {"Gulbrandsen r", p->gulb_r, 3},
               {"Gulbrandsen g", p->gulb_g, 3}, {"Cook-Torrance eta", &p->ct_eta, 1},
               {"Cook-Torrance kappa", &p->ct_kappa, 1}};
    size_t i;
    int ch;
    for (i = 0; i < sizeof all / sizeof all[0]; i++)
        for (ch = 0; ch < all[i].count; ch++)
            if (!(fabs(all[i].v[ch]) <= FLT_MAX)) {
                char where[1100];
                snprintf(where, sizeof where, "%s:%d", in->manifest_path, in->sc->materials_line);
                return cli_error(where, "material %s: %s = %g does not fit a binary32 float; no header written",
                                 p->info.id, all[i].what, all[i].v[ch]);
            }
    return 0;
}

/* One material's floating-point parameters, those its scene's models need:
 * the same list in C and GLSL, each back end giving its own syntax. */
void emit_material_params(FILE *f, const scene *sc, const material_params *p, const char *prefix, emit_rgb_fn rgb,
                          emit_float_fn flt)
{
    unsigned reads = scene_reads(sc, 0);
    if (reads & MP_F0)
        rgb(f, prefix, "f0", p->f0, "F0: ground truth at normal incidence");
    if (sc->f_avg)
        rgb(f, prefix, "f_avg", p->f_avg, "F_avg: 2 int F(mu) mu dmu of the ground truth (multiple-scattering albedo)");
    if (reads & MP_F82)
        rgb(f, prefix, "f82", p->f82, "F82: ground truth at cos theta = 1/7 (fresnel_f82_rgb)");
    if (reads & MP_ETA_FIT) {
        rgb(f, prefix, "eta", p->eta_fit, "eta fitted to the ground truth (exact, lsk, approx-conductor)");
        rgb(f, prefix, "kappa", p->kappa_fit, "kappa fitted to the ground truth");
    }
    if (reads & MP_LSK) {
        rgb(f, prefix, "lsk_a", p->lsk_a, "LSK compensation weight a (fresnel_lsk_comp_rgb)");
        rgb(f, prefix, "lsk_alpha", p->lsk_alpha, "LSK compensation exponent alpha");
    }
    if (reads & MP_ETA_GAUSS) {
        rgb(f, prefix, "eta_gaussian", p->eta_gauss, "Metzgar: eta' in a Gaussian window (fresnel_conductor_rgb)");
        rgb(f, prefix, "kappa_gaussian", p->kappa_gauss, "Metzgar: kappa' in a Gaussian window");
    }
    if (reads & MP_ETA_POINT) {
        rgb(f, prefix, "eta_point", p->eta_point, "eta point-sampled at the dominant wavelengths (fresnel_conductor_rgb)");
        rgb(f, prefix, "kappa_point", p->kappa_point, "kappa point-sampled at the dominant wavelengths");
    }
    if (reads & MP_GULB) {
        rgb(f, prefix, "gulbrandsen_r", p->gulb_r, "Gulbrandsen reflectivity r = F0 (fresnel_gulbrandsen_rgb)");
        rgb(f, prefix, "gulbrandsen_g", p->gulb_g, "Gulbrandsen edge tint g from F0 and the fitted eta");
    }
    if (reads & MP_CT) {
        flt(f, prefix, "ct_eta", p->ct_eta,
            "Cook-Torrance representative IOR at the green wavelength (fresnel_cook_torrance_rgb)");
        flt(f, prefix, "ct_kappa", p->ct_kappa, "Cook-Torrance representative kappa");
    }
}

/* The ground truth's definition and the scene's gamut policy, for the C and
 * GLSL headers' opening comments. */
void emit_truth_comment(FILE *f, const scene *sc)
{
    static const char *const what[] = {"the in-gamut colour nearest in CIEDE2000", "each channel clamped to [0, 1]",
                                       "values above 1 kept"};
    fprintf(f, " * Ground truth: spectral Fresnel x D65 x CIE 1931 2-degree CMFs -> linear RGB, under the gamut\n"
               " * policy %s (%s; gen/2_derive/derive.h).\n",
            sc->gamut, what[scene_gamut(sc)]);
}

/* What a user ships when they ship generated constants (C and GLSL). */
void emit_material_list(FILE *f, const emit_input *in)
{
    int i;
    fprintf(f, " * Materials (file in the data pack, dataset, measured range; outside it the end values are held):\n");
    for (i = 0; i < in->sc->material_count; i++) {
        const material_params *p = &in->params[i];
        const nk_file_info *file = &p->info.file;
        if (file->file[0])
            fprintf(f, " *   %-18s %s (a user's file: %s, %ld bytes), %.1f-%.1f nm\n *   %-18s sha256 %s\n",
                    p->info.id, file->file, file->format, file->bytes, p->measured_lo, p->measured_hi, "",
                    file->sha256);
        else
            fprintf(f, " *   %-18s %s.csv, %s, %s, %.1f-%.1f nm\n", p->info.id, p->info.id, p->info.name,
                    p->info.dataset, p->measured_lo, p->measured_hi);
    }
}

void emit_licence_comment(FILE *f)
{
    fprintf(f, " * Licence: the numbers below are facts derived from refractiveindex.info data (CC0 1.0) and the\n"
               " * CIE 1931 2-degree colour-matching functions and illuminant D65 (CIE tables, CC BY-SA 4.0),\n"
               " * see data/SOURCES.md; this generated header may be used under the project's MIT licence.\n");
}

int emit_header(FILE *f, const emit_input *in)
{
    const scene *sc = in->sc;
    const gen_context *g = in->g;
    lut_spacing spacing = scene_lut_spacing(sc);
    char guard[96];
    int i, m;
    for (i = 0; in->name[i] && i < (int)sizeof guard - 1; i++)
        guard[i] = (char)toupper((unsigned char)in->name[i]);
    guard[i] = '\0';

    fprintf(f, "/* Fresnel scene \"%s\", generated by fresnel gen %s from %s. Do not edit: regenerate.\n", in->name,
            GEN_VERSION, in->manifest_name);
    emit_licence_comment(f);
    fprintf(f, " * Colour space %s (white x %.4f y %.4f); dominant wavelengths R %.2f G %.2f B %.2f nm;\n", sc->space,
            g->cs.white[0], g->cs.white[1], g->nm[0], g->nm[1], g->nm[2]);
    fprintf(f, " * Gaussian window sigma %g nm; incident medium n1 %g (eta, kappa below are relative to it).\n",
            sc->sigma, sc->n1);
    emit_truth_comment(f, in->sc);
    fprintf(f, " * Models:");
    for (m = 0; m < sc->model_count; m++)
        fprintf(f, " %s", sc->models[m]);
    fprintf(f, "; number types:");
    for (m = 0; m < sc->type_count; m++)
        fprintf(f, " %s", sc->types[m]);
    fprintf(f, ".\n");
    emit_material_list(f, in);
    fprintf(f, " */\n#ifndef FRESNEL_SCENE_%s_H\n#define FRESNEL_SCENE_%s_H\n\n", guard, guard);
    /* The runtime headers of the scene's types only, each skipped where it
     * is already in (a single-file runtime, ports/single.sh, holds it). */
    if (scene_has_type(sc, "f32"))
        fprintf(f, "#ifndef FRESNEL_H\n#include \"fresnel.h\"\n#endif\n");
    if (scene_has_type(sc, "q15"))
        fprintf(f, "#ifndef FRESNEL_FIXED_H\n#include \"fresnel_fixed.h\"\n#endif\n");
    fputc('\n', f);
    fprintf(f, "#ifndef FRESNEL_GEN_UNUSED\n#if defined(__GNUC__)\n#define FRESNEL_GEN_UNUSED __attribute__((unused))\n"
               "#else\n#define FRESNEL_GEN_UNUSED\n#endif\n#endif\n");

    for (i = 0; i < sc->material_count; i++) {
        const material_params *p = &in->params[i];
        char prefix[96];
        snprintf(prefix, sizeof prefix, "fresnel_%s_%s", in->name, p->info.id);
        if (params_fit_float(in, p))
            return CLI_BAD_INPUT;
        emit_material_heading(f, in, i);
        if (scene_has_type(sc, "q15") && emit_fixed_material(f, in, i, prefix))
            return CLI_BAD_INPUT;
        if (!scene_has_type(sc, "f32"))
            continue;
        emit_material_params(f, sc, p, prefix, emit_rgb, emit_float);
        for (m = 0; m < sc->model_count; m++)
            if (scene_model_lut_size(sc->models[m], NULL) &&
                emit_lut(f, in, prefix, sc->models[m], p, in->spectra[i], g, spacing))
                return CLI_BAD_INPUT;
    }
    fprintf(f, "\n#endif\n");
    return 0;
}
