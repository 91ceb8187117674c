/* Stage 4, emit: each material's heading in the generated header and, for
 * a scene with the `targets` key, the parameters other renderers' metals
 * take (2_derive/targets.h) as a comment under it: the same in C, GLSL and
 * HLSL, values to type into those renderers that compile into nothing (a
 * fixed-point header stays free of floats). Fixed formatting and a
 * deterministic fit keep the header byte-identical for identical input. */
#include <stdio.h>
#include <string.h>

#include "2_derive/targets.h"
#include "4_emit/emit.h"

/* The renderer's thin-film inputs over the metal (fresnel params --for
 * TARGET --film N:D), the thickness as the scene's range (one value when
 * the range is one thickness; glTF's minimum and maximum are the range).
 * Under them, the metal refitted through the renderer's film formula over
 * the range (target_film_fit), as params prints it for one thickness. */
static void film_rows(FILE *f, const target *t, double n, double d_lo, double d_hi)
{
    const char *names[4];
    double lo[4], hi[4];
    int k, count = target_film_rows(t, n, d_lo, names, lo);
    target_film_rows(t, n, d_hi, names, hi);
    for (k = 0; k < count; k++) {
        int is_min = t->film.thickness_min && !strcmp(names[k], t->film.thickness_min);
        fprintf(f, " *   %-12s %-16s %.6g", "", names[k], is_min ? lo[k] : hi[k]);
        if (lo[k] != hi[k] && !t->film.thickness_min)
            fprintf(f, " (the scene's range %.6g-%.6g: set per use)", lo[k], hi[k]);
        fputc('\n', f);
    }
}

static void targets_comment(FILE *f, const emit_input *in, int material)
{
    const scene *sc = in->sc;
    const material_params *p = &in->params[material];
    int i, k, n, ch;
    fprintf(f, "/* Other renderers' parameters for %s (fresnel params --for TARGET), fitted through each one's\n"
               " * Fresnel formula to the ground truth above; CIEDE2000 over theta 0-90 deg, mean / max:\n",
            p->info.id);
    for (i = 0; i < sc->target_count; i++) {
        const target *t = &target_table[sc->targets[i]];
        const target_fit *fit = &in->fits[material * sc->target_count + i];
        for (k = n = 0; k < t->param_count; k++) {
            fprintf(f, " *   %-12s %-16s", k ? "" : t->name, t->param[k].name);
            for (ch = 0; ch < 3; ch++)
                fprintf(f, " %.6f", fit->fitted[t->param[k].scalar ? n : n + ch]);
            fputc('\n', f);
            n += t->param[k].scalar ? 1 : 3;
        }
        fprintf(f, " *   %-12s dE2000 %.4f / %.4f (naive conversion %.4f / %.4f)\n", "", fit->fit_mean, fit->fit_max,
                fit->naive_mean, fit->naive_max);
        if (in->films && t->film.thickness) {
            const target_fit *ff = in->film_fits ? &in->film_fits[material * sc->target_count + i] : NULL;
            fprintf(f, " *   %-12s and the thin film over that metal:\n", "");
            film_rows(f, t, in->films[material].n_film, sc->film_d_lo, sc->film_d_hi);
            if (ff && ff->t) {
                fprintf(f, " *   %-12s under that film, the metal refitted through %s's own film formula:\n", "",
                        t->name);
                for (k = n = 0; k < t->param_count; k++) {
                    fprintf(f, " *   %-12s %-16s", "", t->param[k].name);
                    for (ch = 0; ch < 3; ch++)
                        fprintf(f, " %.6f", ff->fitted[t->param[k].scalar ? n : n + ch]);
                    fputc('\n', f);
                    n += t->param[k].scalar ? 1 : 3;
                }
                fprintf(f, " *   %-12s dE2000 %.4f / %.4f against the film's truth%s (naive conversion %.4f / "
                           "%.4f)\n",
                        "", ff->fit_mean, ff->fit_max,
                        sc->film_d_hi > sc->film_d_lo ? " over the thickness range" : "", ff->naive_mean,
                        ff->naive_max);
            }
        } else if (in->films) {
            fprintf(f, " *   %-12s (no thin-film input known: the film is not carried)\n", "");
        }
    }
    fprintf(f, " */\n");
}

void emit_material_heading(FILE *f, const emit_input *in, int material)
{
    const material_params *p = &in->params[material];
    fprintf(f, "\n/* ---- %s: %s */\n", p->info.id, p->info.name);
    if (in->sc->target_count)
        targets_comment(f, in, material);
}
