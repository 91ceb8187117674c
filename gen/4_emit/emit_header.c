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

#include "common/cli.h"
#include "4_emit/emit.h"
#include "scene/scene.h"

static void emit_rgb(FILE *f, const char *prefix, const char *name, const double v[3], const char *why)
{
    fprintf(f, "/* %s */\nstatic const fresnel_rgb %s_%s FRESNEL_GEN_UNUSED = {", why, prefix, name);
    emit_c_float(f, v[0]);
    fputs(", ", f);
    emit_c_float(f, v[1]);
    fputs(", ", f);
    emit_c_float(f, v[2]);
    fputs("};\n", f);
}

static void emit_float(FILE *f, const char *prefix, const char *name, double v, const char *why)
{
    fprintf(f, "/* %s */\nstatic const float %s_%s FRESNEL_GEN_UNUSED = ", why, prefix, name);
    emit_c_float(f, v);
    fputs(";\n", f);
}

static void emit_lut(FILE *f, const emit_input *in, const char *prefix, const scene_entry *e, const encoded_lut *t)
{
    int n = t->n, i, residual = t->form == LUT_RESIDUAL;
    lut_spacing spacing = in->sc->spacing;
    const char *suffix = residual ? "_residual" : (t->form == LUT_CUBIC ? "_cubic" : "");
    fprintf(f, "/* %s: %d nodes per channel (red, then green, then blue), uniform in %s,\n"
               " * fitted to the ground truth through %s interpolation.\n",
            e->name, n, spacing == LUT_UNIFORM ? "cos theta" : "sqrt(cos theta), from grazing to normal",
            t->form == LUT_CUBIC ? "Catmull-Rom" : "linear");
    fprintf(f, " * Evaluate with fresnel_%s%s_rgb(%stable, %d, c). */\n", spacing == LUT_UNIFORM ? "lut_linear" : "lut",
            suffix, residual ? "f0, " : "", n);
    fprintf(f, "static const float %s_%s[%d] FRESNEL_GEN_UNUSED = {", prefix, e->ident, 3 * n);
    for (i = 0; i < 3 * n; i++) {
        fputs(i % 6 == 0 ? "\n    " : " ", f);
        emit_c_float(f, t->f32[i]);
        if (i + 1 < 3 * n)
            fputc(',', f);
    }
    fprintf(f, "\n};\n");
}

int emit_f32_material(FILE *f, const emit_input *in, int mi, const char *prefix, const encoded_lut *luts)
{
    int m;
    emit_material_params(f, in->sc, &in->enc[mi], prefix, emit_rgb, emit_float);
    for (m = 0; m < in->sc->model_count; m++)
        if (luts[m].n)
            emit_lut(f, in, prefix, &in->sc->models[m], &luts[m]);
    return emit_film(f, in, mi, prefix, TYPE_F32);
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

/* The ground truth's definition and the scene's gamut policy, for the C and
 * GLSL headers' opening comments. */
void emit_truth_comment(FILE *f, const scene *sc)
{
    static const char *const what[] = {"the in-gamut colour nearest in CIEDE2000", "each channel clamped to [0, 1]",
                                       "values above 1 kept"};
    fprintf(f, " * Ground truth: spectral Fresnel x D65 x CIE 1931 2-degree CMFs -> linear RGB, under the gamut\n"
               " * policy %s (%s; gen/2_derive/derive.h).\n",
            gamut_policy_names[sc->gamut], what[sc->gamut]);
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

/* Each number type's back end, in the order a material's constants are
 * written; every row of the number type registry has one. */
static const struct {
    number_type_id type;
    emit_type_fn emit;
} emit_types[] = {{TYPE_Q15, emit_fixed_material}, {TYPE_F32, emit_f32_material}, {TYPE_F16, emit_f16_material}};
typedef char emit_types_cover_the_registry[sizeof emit_types / sizeof emit_types[0] == NUMBER_TYPES ? 1 : -1];

/* Every LUT of material i, encoded once for all its types (luts[m].n 0 for
 * the other models): 0, or CLI_* after a message (then nothing is held). */
static int encode_luts(const emit_input *in, int i, const char *prefix, encoded_lut *luts)
{
    const scene *sc = in->sc;
    int m, k;
    for (m = 0; m < sc->model_count; m++) {
        memset(&luts[m], 0, sizeof luts[m]);
        if (!sc->models[m].lut_n)
            continue;
        if (emit_lut_encode(in, &sc->models[m], i, &luts[m])) {
            for (k = 0; k < m; k++)
                encoded_lut_free(&luts[k]);
            return cli_oom("fresnel gen");
        }
        if (luts[m].bad >= 0) {
            char where[1100];
            snprintf(where, sizeof where, "%s:%d", in->manifest_path, sc->models_line);
            cli_error(where, "%s: %s node %d is %g, which no %s table holds; no header written", prefix,
                      sc->models[m].name, luts[m].bad, luts[m].nodes[luts[m].bad],
                      luts[m].form == LUT_RESIDUAL ? "Q1.15 residual (int16_t at 14 fraction bits)" : "Q1.15 [0, 2)");
            for (k = 0; k <= m; k++)
                encoded_lut_free(&luts[k]);
            return CLI_BAD_INPUT;
        }
    }
    return 0;
}

/* #include "name" unless its guard (FRESNEL_FIXED_H for fresnel_fixed.h)
 * is defined already. */
static void include_guarded(FILE *f, const char *name)
{
    const char *c;
    fputs("#ifndef ", f);
    for (c = name; *c; c++)
        fputc(*c == '.' ? '_' : toupper((unsigned char)*c), f);
    fprintf(f, "\n#include \"%s\"\n#endif\n", name);
}

int emit_header(FILE *f, const emit_input *in)
{
    const scene *sc = in->sc;
    const gen_context *g = in->g;
    char guard[96];
    int i, m, k, status = 0;
    encoded_lut *luts = calloc((size_t)sc->model_count, sizeof *luts);
    if (!luts)
        return cli_oom("fresnel gen");
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
        fprintf(f, " %s", sc->models[m].name);
    fprintf(f, "; number types:");
    for (m = 0; m < sc->type_count; m++)
        fprintf(f, " %s", sc->types[m]->name);
    fprintf(f, ".\n");
    emit_material_list(f, in);
    fprintf(f, " */\n#ifndef FRESNEL_SCENE_%s_H\n#define FRESNEL_SCENE_%s_H\n\n", guard, guard);
    /* The runtime headers of the scene's types only, each skipped where it
     * is already in (a single-file runtime, ports/single.sh, holds it). */
    for (k = 0; k < NUMBER_TYPES; k++)
        if (scene_has_type(sc, emit_types[k].type))
            include_guarded(f, number_types[emit_types[k].type].header);
    if (in->films)
        include_guarded(f, "fresnel_film.h");
    fputc('\n', f);
    fprintf(f, "#ifndef FRESNEL_GEN_UNUSED\n#if defined(__GNUC__)\n#define FRESNEL_GEN_UNUSED __attribute__((unused))\n"
               "#else\n#define FRESNEL_GEN_UNUSED\n#endif\n#endif\n");

    for (i = 0; i < sc->material_count && !status; i++) {
        const material_params *p = &in->params[i];
        char prefix[96];
        snprintf(prefix, sizeof prefix, "fresnel_%s_%s", in->name, p->info.id);
        if (params_fit_float(in, p) || (status = encode_luts(in, i, prefix, luts))) {
            status = CLI_BAD_INPUT;
            break;
        }
        emit_material_heading(f, in, i);
        for (k = 0; k < NUMBER_TYPES && !status; k++)
            if (scene_has_type(sc, emit_types[k].type))
                status = emit_types[k].emit(f, in, i, prefix, luts);
        for (m = 0; m < sc->model_count; m++)
            encoded_lut_free(&luts[m]);
    }
    free(luts);
    if (status)
        return status;
    fprintf(f, "\n#endif\n");
    return 0;
}
