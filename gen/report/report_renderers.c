/* The report's table of other renderers: how well each one's metal, with
 * the parameters `fresnel params --for TARGET` fits, shows each metal of the
 * scene (2_derive/targets.h), beside what the project's own models reach;
 * and, for a material outside the gamut, which renderers can show its
 * unclipped colour at all. */
#include <stdlib.h>
#include <string.h>

#include "2_derive/targets.h"
#include "report/report.h"

typedef struct renderer_cell {
    double fit_mean, fit_max, naive_mean, naive_max;
} renderer_cell;

static int scene_model_index(const report_run *r, const model *def)
{
    int m;
    for (m = 0; def && m < r->sc.model_count; m++)
        if (model_of(r->sc.models[m].row) == def)
            return m;
    return -1;
}

/* The scene's model with the lowest mean CIEDE2000 for material i (f32). */
static int best_model(report_run *r, int i)
{
    int m, best = 0;
    for (m = 1; m < r->sc.model_count; m++)
        if (report_cell_at(r, i, m, 0)->de_mean < report_cell_at(r, i, best, 0)->de_mean)
            best = m;
    return best;
}

static void header(FILE *f, const char *first, const char *const *extra)
{
    int k;
    fprintf(f, "| %s |", first);
    for (k = 0; k < target_count; k++)
        fprintf(f, " %s |", target_table[k].name);
    for (k = 0; extra[k]; k++)
        fprintf(f, " %s |", extra[k]);
    fprintf(f, "\n|---|");
    for (k = 0; k < target_count; k++)
        fprintf(f, "---:|");
    for (k = 0; extra[k]; k++)
        fprintf(f, "---:|");
    fprintf(f, "\n");
}

static void out_of_gamut(report_run *r, FILE *f, int i)
{
    report_material *rm = &r->mats[i];
    double raw[TARGET_ANGLES][3], truth[TARGET_ANGLES][3];
    target_anchor a_raw, a;
    int k;
    target_material_curve(rm->s, r->g, &rm->p, 0, raw, &a_raw);
    target_material_curve(rm->s, r->g, &rm->p, 1, truth, &a);
    fprintf(f, "\n%s leaves the %s gamut (F0 unclipped %.4f %.4f %.4f). Each renderer fitted to the unclipped "
               "truth itself (as `--gamut keep` does), and the parameters fitted under the `%s` policy, both "
               "measured against the unclipped truth (CIEDE2000 mean / max):\n\n"
               "| target | colours above 1 | fitted to the unclipped truth | fitted under the policy |\n"
               "|---|---|---:|---:|\n",
            rm->p.info.id, r->sc.space, rm->p.f0_unclamped[0], rm->p.f0_unclamped[1], rm->p.f0_unclamped[2],
            gamut_policy_names[r->g->gamut]);
    int can = 0;
    for (k = 0; k < target_count; k++) {
        const target *t = &target_table[k];
        target_fit keep, policy;
        double mean, max;
        target_fit_curve(t, &r->ls, (const double(*)[3])raw, &a_raw, &keep);
        target_fit_curve(t, &r->ls, (const double(*)[3])truth, &a, &policy);
        target_curve_de(t, &r->ls, (const double(*)[3])raw, policy.fitted, &mean, &max);
        fprintf(f, "| %s | %s | %.3f / %.3f | %.3f / %.3f |\n", t->name,
                target_above_one(t) ? "allowed (no range stated)" : "no", keep.fit_mean, keep.fit_max, mean, max);
    }
    fprintf(f, "\nOnly a renderer whose colour inputs may exceed 1 can hold this colour:");
    for (k = 0; k < target_count; k++)
        if (target_above_one(&target_table[k]))
            fprintf(f, "%s %s", can++ ? "," : "", target_table[k].name);
    fprintf(f, "%s; the others' fits to the unclipped truth are bounded by their ranges.\n", can ? "" : " none");
}

void report_renderers(report_run *r, FILE *f)
{
    static const char *const ours[] = {"ours: f82", "ours: exact", "ours: best of the scene", NULL};
    int f82 = scene_model_index(r, model_f82), exact = scene_model_index(r, model_exact), i, k;
    renderer_cell *cells = malloc((size_t)r->sc.material_count * (size_t)target_count * sizeof *cells);
    if (!cells) {
        fprintf(f, "\n## How well each renderer shows each metal\n\nNot measured: out of memory.\n");
        return;
    }
    for (i = 0; i < r->sc.material_count; i++) {
        report_material *rm = &r->mats[i];
        double truth[TARGET_ANGLES][3];
        target_anchor a;
        if (!report_is_metal(rm))
            continue;
        target_material_curve(rm->s, r->g, &rm->p, 1, truth, &a);
        for (k = 0; k < target_count; k++) {
            target_fit fit;
            renderer_cell *c = &cells[i * target_count + k];
            target_fit_curve(&target_table[k], &r->ls, (const double(*)[3])truth, &a, &fit);
            c->fit_mean = fit.fit_mean;
            c->fit_max = fit.fit_max;
            c->naive_mean = fit.naive_mean;
            c->naive_max = fit.naive_max;
        }
    }
    fprintf(f, "\n## How well each renderer shows each metal\n\n"
               "Each renderer's own metal Fresnel formula (gen/common/reference_targets.c, transcribed from its "
               "specification or source) with the parameters `fresnel params --material ID --for TARGET` prints: "
               "fitted to the ground truth under the gamut policy by mean CIEDE2000 over theta 0-90 deg in 1 deg "
               "steps, inside the ranges the renderer takes (MaterialX states none: the fit keeps its colours in "
               "[0, 2] and its exponent in [1, 10]). Cells: mean / max CIEDE2000 (%s). Blender's and "
               "Unreal's formulas are OpenPBR's F82-tint with clamps, and Filament's is glTF's Schlick wherever "
               "its f90 is 1 (F0's channels summing to at least 1/16.5); MaterialX's curves include OpenPBR's. Beside "
               "them, the project's own: the F82 model on spectral F0 and F82, exact Fresnel on the fitted eta, "
               "kappa, and the scene's best model for the material (binary32 runtime).\n\n",
            r->sc.space);
    header(f, "metal", ours);
    for (i = 0; i < r->sc.material_count; i++) {
        int best = best_model(r, i);
        if (!report_is_metal(&r->mats[i]))
            continue;
        fprintf(f, "| %s |", r->mats[i].p.info.id);
        for (k = 0; k < target_count; k++)
            fprintf(f, " %.3f / %.3f |", cells[i * target_count + k].fit_mean, cells[i * target_count + k].fit_max);
        if (f82 >= 0)
            fprintf(f, " %.3f / %.3f |", report_cell_at(r, i, f82, 0)->de_mean, report_cell_at(r, i, f82, 0)->de_max);
        else
            fprintf(f, " - |");
        if (exact >= 0)
            fprintf(f, " %.3f / %.3f |", report_cell_at(r, i, exact, 0)->de_mean,
                    report_cell_at(r, i, exact, 0)->de_max);
        else
            fprintf(f, " - |");
        fprintf(f, " %.3f / %.3f (%s) |\n", report_cell_at(r, i, best, 0)->de_mean,
                report_cell_at(r, i, best, 0)->de_max, r->sc.models[best].name);
    }
    fprintf(f, "\nThe naive conversion (F0 at normal incidence; an edge parameter from the curve at cos theta = "
               "1/7, \"82 degrees\", clamped to the renderer's range; Gulbrandsen's g from F0 and the fitted eta), "
               "mean / max CIEDE2000, and the fit's gain in mean CIEDE2000 (naive minus fitted):\n\n");
    {
        static const char *const none[] = {NULL};
        header(f, "metal", none);
    }
    for (i = 0; i < r->sc.material_count; i++) {
        if (!report_is_metal(&r->mats[i]))
            continue;
        fprintf(f, "| %s |", r->mats[i].p.info.id);
        for (k = 0; k < target_count; k++) {
            const renderer_cell *c = &cells[i * target_count + k];
            fprintf(f, " %.3f / %.3f, gain %.3f |", c->naive_mean, c->naive_max, c->naive_mean - c->fit_mean);
        }
        fprintf(f, "\n");
    }
    for (i = 0; i < r->sc.material_count; i++)
        if (r->mats[i].out_of_gamut && report_is_metal(&r->mats[i]))
            out_of_gamut(r, f, i);
    free(cells);
}
