/* Stage 4, emit: one C header per scene holding exactly the constants its
 * materials, models and number types need [design card: "leave out what a
 * scene does not need"]. Output depends only on the manifest and the data:
 * no dates, no absolute paths, fixed number formatting. */
#include <ctype.h>
#include <stdio.h>
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

static void emit_f32_lut(FILE *f, const emit_input *in, const char *prefix, const scene_entry *e, const encoded_lut *t)
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

int emit_f32_material(FILE *f, const emit_input *in, int mi, const char *prefix)
{
    int m;
    emit_material_params(f, in->sc, &in->enc[mi], prefix, emit_rgb, emit_float);
    for (m = 0; m < in->sc->model_count; m++)
        if (emit_lut(in, mi, m)->n)
            emit_f32_lut(f, in, prefix, &in->sc->models[m], emit_lut(in, mi, m));
    return emit_film(f, in, mi, prefix, TYPE_F32);
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
            fprintf(f, " *   %-18s %s (supplied by the user: %s, %ld bytes), %.1f-%.1f nm\n *   %-18s sha256 %s\n",
                    p->info.id, file->file, file->format, file->bytes, p->measured_lo, p->measured_hi, "",
                    file->sha256);
        else
            fprintf(f, " *   %-18s %s.csv, %s, %s, %.1f-%.1f nm\n", p->info.id, p->info.id, p->info.name,
                    p->info.dataset, p->measured_lo, p->measured_hi);
    }
}

/* The data's terms as they are: the data pack's (data/SOURCES.md) for its
 * materials; for a user's own file, only that it was supplied by the user
 * (named with its SHA-256 in the material list), whose terms the tool
 * cannot know. */
void emit_licence_comment(FILE *f, const emit_input *in)
{
    int i, pack = 0, user = 0;
    for (i = 0; i < in->sc->material_count; i++) {
        if (in->params[i].info.file.file[0])
            user++;
        else
            pack++;
    }
    fprintf(f, " * Data: ");
    if (pack)
        fprintf(f, "%s facts derived from refractiveindex.info data (CC0 1.0;\n * data/SOURCES.md)",
                user ? "the data pack's materials are" : "the numbers below are");
    if (pack && user)
        fprintf(f, ";");
    if (user) {
        int listed = 0;
        fprintf(f, "%s", pack ? "\n * " : "");
        for (i = 0; i < in->sc->material_count; i++)
            if (in->params[i].info.file.file[0])
                fprintf(f, "%s%s", listed++ ? ", " : "", in->params[i].info.id);
        fprintf(f, ": derived from %s supplied by the user (named with %s SHA-256 in the\n"
                   " * material list), under whatever terms %s came with",
                user > 1 ? "files" : "a file", user > 1 ? "their" : "its", user > 1 ? "they" : "it");
    }
    fprintf(f, ".\n * Colour: the CIE 1931 2-degree colour-matching functions and illuminant D65 (CIE tables,\n"
               " * CC BY-SA 4.0). The header's code may be used under the project's MIT licence.\n");
}

/* Each number type's back end, in the order a material's constants are
 * written; every row of the number type registry has one. */
static const struct {
    number_type_id type;
    emit_type_fn emit;
} emit_types[] = {{TYPE_Q15, emit_q15_material}, {TYPE_F32, emit_f32_material}, {TYPE_F16, emit_f16_material}};
typedef char emit_types_cover_the_registry[sizeof emit_types / sizeof emit_types[0] == NUMBER_TYPES ? 1 : -1];

/* #include "name" unless its guard (FRESNEL_Q15_H for fresnel_q15.h)
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
    for (i = 0; in->name[i] && i < (int)sizeof guard - 1; i++)
        guard[i] = (char)toupper((unsigned char)in->name[i]);
    guard[i] = '\0';

    fprintf(f, "/* Fresnel scene \"%s\", generated by fresnel gen %s from %s. Do not edit: regenerate.\n", in->name,
            GEN_VERSION, in->manifest_name);
    emit_licence_comment(f, in);
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
        fprintf(f, " %s", number_type_catalog[sc->types[m]].name);
    fprintf(f, ".\n");
    emit_material_list(f, in);
    fprintf(f, " */\n#ifndef FRESNEL_SCENE_%s_H\n#define FRESNEL_SCENE_%s_H\n\n", guard, guard);
    /* The runtime headers of the scene's types only, each skipped where it
     * is already in (a single-file runtime, ports/single.sh, holds it). */
    for (k = 0; k < NUMBER_TYPES; k++)
        if (scene_has_type(sc, emit_types[k].type))
            include_guarded(f, number_type_catalog[emit_types[k].type].header);
    if (in->films)
        include_guarded(f, "fresnel_film.h");
    fputc('\n', f);
    fprintf(f, "#ifndef FRESNEL_GEN_UNUSED\n#if defined(__GNUC__)\n#define FRESNEL_GEN_UNUSED __attribute__((unused))\n"
               "#else\n#define FRESNEL_GEN_UNUSED\n#endif\n#endif\n");

    for (i = 0; i < sc->material_count && !status; i++) {
        const material_params *p = &in->params[i];
        char prefix[96];
        snprintf(prefix, sizeof prefix, "fresnel_%s_%s", in->name, p->info.id);
        emit_material_heading(f, in, i);
        for (k = 0; k < NUMBER_TYPES && !status; k++)
            if (scene_has_type(sc, emit_types[k].type))
                status = emit_types[k].emit(f, in, i, prefix);
    }
    if (status)
        return status;
    fprintf(f, "\n#endif\n");
    return 0;
}
