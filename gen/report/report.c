/* The report: every material x model x number type of a scene measured
 * against the spectral ground truth, timed, and written as report.md with
 * its plots (report.h). */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "common/cli.h"
#include "bench/bench.h"
#include "bench/speed_targets.h"
#include "common/reference.h"
#include "model/registry.h"
#include "report/report.h"
#include "scene/scene.h"

#define WHERE "fresnel report"
#define hoffman report_hoffman

/* Host instructions per RGB evaluation: callgrind counting only inside the
 * timed batch functions of `fresnel bench --runs 0` (one batch of count
 * evaluations), so start-up, data loading and fitting are not counted. */
static double callgrind_instructions(const char *scene_path, const char *material, const char *model,
                                     const char *type)
{
    const int count = 20000;
    char cmd[2048], line[512];
    double collected = NAN;
    FILE *p;
    snprintf(cmd, sizeof cmd,
             "valgrind --tool=callgrind --toggle-collect='batch_*' --callgrind-out-file=/dev/null "
             "/proc/%ld/exe bench --scene '%s' --material '%s' --model '%s' --type '%s' --count %d --runs 0 2>&1",
             (long)getpid(), scene_path, material, model, type, count);
    if (!(p = popen(cmd, "r")))
        return NAN;
    while (fgets(line, sizeof line, p)) {
        const char *k = strstr(line, "Collected : ");
        if (k)
            collected = strtod(k + 12, NULL);
    }
    if (pclose(p) != 0)
        return NAN;
    return collected / count;
}

/* Commits the run's outputs together (status 0) or removes them all. */
static int finish_outputs(report_run *r, int status)
{
    cli_outfile **all = r->out_count ? malloc((size_t)r->out_count * sizeof *all) : NULL;
    int i;
    if (r->out_count && !all) {
        for (i = 0; i < r->out_count; i++)
            cli_out_abort(&r->out[i]);
        return status ? status : cli_oom(WHERE);
    }
    for (i = 0; i < r->out_count; i++)
        all[i] = &r->out[i];
    if (status)
        cli_out_abort_all(all, r->out_count);
    else
        status = cli_out_commit_all(all, r->out_count);
    free(all);
    free(r->out);
    r->out = NULL;
    r->out_count = 0;
    return status;
}

/* Materials whose colour leaves the space's gamut: what each policy costs
 * and how far each model lands from the unclipped truth. */
static void write_gamut(report_run *r, FILE *f)
{
    int i, m, t, any = 0;
    fprintf(f, "\n## Colours outside the gamut\n\n"
               "The scene's gamut policy is `%s` (`gamut` in the scene, `--gamut` on the commands: map, clip or "
               "keep; README, \"Colours outside the gamut\"). Each policy's own cost: CIEDE2000 of its curve against "
               "the unclipped spectral ground truth (mean / max over 91 angles). keep is the truth itself, "
               "above 1 where the colour leaves the gamut.\n\n",
            gamut_policy_names[r->g->gamut]);
    for (i = 0; i < r->sc.material_count; i++) {
        const report_material *rm = &r->mats[i];
        if (!rm->out_of_gamut)
            continue;
        if (!any)
            fprintf(f, "| material | F0 unclipped | map | clip | keep |\n|---|---|---:|---:|---:|\n");
        any = 1;
        fprintf(f, "| %s | %.4f %.4f %.4f | %.3f / %.3f | %.3f / %.3f | %.3f / %.3f |\n", rm->p.info.id,
                rm->p.f0_unclamped[0], rm->p.f0_unclamped[1], rm->p.f0_unclamped[2], rm->policy_de_mean[GAMUT_MAP],
                rm->policy_de_max[GAMUT_MAP], rm->policy_de_mean[GAMUT_CLIP], rm->policy_de_max[GAMUT_CLIP],
                rm->policy_de_mean[GAMUT_KEEP], rm->policy_de_max[GAMUT_KEEP]);
    }
    if (!any) {
        fprintf(f, "Every material of the scene is inside the %s gamut at every angle: the policies agree.\n",
                r->sc.space);
        return;
    }
    fprintf(f, "\nEvery model of the scene under the `%s` policy against the unclipped truth (CIEDE2000 mean / "
               "max), for each material outside the gamut:\n\n| material | model | type | mean | max |\n"
               "|---|---|---|---:|---:|\n",
            gamut_policy_names[r->g->gamut]);
    for (i = 0; i < r->sc.material_count; i++)
        if (r->mats[i].out_of_gamut)
            for (m = 0; m < r->sc.model_count; m++)
                for (t = 0; t < number_types_available; t++) {
                    const report_cell *c = report_cell_at(r, i, m, t);
                    fprintf(f, "| %s | %s | %s | %.3f | %.3f |\n", r->mats[i].p.info.id, r->sc.models[m].name,
                            number_types[t].name, c->raw_de_mean, c->raw_de_max);
                }
}

static void write_average_closed_forms(report_run *r, FILE *f)
{
    int i, m, t32 = TYPE_F32, header = 0;
    for (m = 0; m < r->sc.model_count; m++) {
        double sum = 0.0, worst = 0.0, vs_curve = 0.0;
        for (i = 0; i < r->sc.material_count; i++) {
            const report_material *rm = &r->mats[i];
            const scene_model *sm = &rm->models[m];
            const report_cell *c = report_cell_at(r, i, m, t32);
            model_rgb q = scene_model_rgb(sm);
            fresnel_rgb v;
            double e;
            if (!sm->def->f32->avg)
                break;
            v = sm->def->f32->avg(&q);

            e = fmax(fabs(v.r - rm->p.f_avg[0]), fmax(fabs(v.g - rm->p.f_avg[1]), fabs(v.b - rm->p.f_avg[2])));
            sum += e;
            worst = fmax(worst, e);
            vs_curve = fmax(vs_curve, fmax(fabs(v.r - c->avg[0]), fmax(fabs(v.g - c->avg[1]), fabs(v.b - c->avg[2]))));
        }
        if (i < r->sc.material_count || r->sc.material_count == 0)
            continue;
        if (!header)
            fprintf(f, "\nThe runtime's closed forms (`fresnel_schlick_avg`, `fresnel_f82_avg`, `fresnel_lut_avg`, "
                       "`fresnel_lut_cubic_avg`, `fresnel_lut_linear_avg`: binary32, from the scene's constants and "
                       "tables), against the "
                       "ground truth's F_avg and against the same model's curve integrated numerically (for the tables the "
                       "numerical rule is the less exact of the two: the tables' pieces, uniform in sqrt(c), do not "
                       "line up with its panels; tests/runtime/every_type/test_average.c holds the closed forms to the exact integral):\n\n"
                       "| model | mean abs error | worst | max vs the integrated curve |\n"
                       "|---|---:|---:|---:|\n");
        header = 1;
        fprintf(f, "| %s | %.2e | %.2e | %.1e |\n", r->sc.models[m].name, sum / r->sc.material_count, worst, vs_curve);
    }
}

/* F_avg of each model against the ground truth's, per material. */
static void write_average(report_run *r, FILE *f)
{
    int i, m, t, ch;
    fprintf(f, "\n## Hemispherical average F_avg\n\n"
               "F_avg = 2 int_0^1 F(mu) mu dmu per channel, the albedo a multiple-scattering compensation reads. "
               "The ground truth's (under the gamut policy; `fresnel params` prints it, `f_avg = yes` in a scene "
               "emits it) against each model's, the model's curve integrated in its type by the same "
               "5-point Gauss-Legendre rule on %d panels: mean over the materials of the largest channel's "
               "|difference|, and the worst.\n\n| model | type | mean abs error | worst | worst material |\n"
               "|---|---|---:|---:|---|\n",
            GEN_AVG_PANELS);
    for (m = 0; m < r->sc.model_count; m++)
        for (t = 0; t < number_types_available; t++) {
            double sum = 0.0, worst = -1.0;
            const char *at = "";
            for (i = 0; i < r->sc.material_count; i++) {
                const report_cell *c = report_cell_at(r, i, m, t);
                double e = 0.0;
                for (ch = 0; ch < 3; ch++)
                    e = fmax(e, fabs(c->avg[ch] - r->mats[i].p.f_avg[ch]));
                sum += e;
                if (e > worst) {
                    worst = e;
                    at = r->mats[i].p.info.id;
                }
            }
            fprintf(f, "| %s | %s | %.2e | %.2e | %s |\n", r->sc.models[m].name, number_types[t].name,
                    sum / r->sc.material_count, worst, at);
        }
    write_average_closed_forms(r, f);
}

static void write_accuracy_tables(report_run *r, FILE *f)
{
    int i, m, t;
    fprintf(f, "## Summary over the metals\n\n"
               "Mean over the %s metals of each material's mean CIEDE2000 (theta 0-90 deg, 1 deg steps, "
               "against the spectral ground truth in %s under the gamut policy), the worst maximum, the largest deviation "
               "from the same model evaluated in double precision, and the cost.\n\n"
               "Cost: ns and host instructions (callgrind) per RGB evaluation of %s, one model and type at a "
               "time; %s.\n\n"
               "| model | type | mean dE2000 | worst max dE2000 | max vs own double | ns per RGB eval | instructions |\n"
               "|---|---|---:|---:|---:|---:|---:|\n",
            "report scene's", r->sc.space, r->mats[r->timed_material].p.info.id, bench_compiler());
    for (m = 0; m < r->sc.model_count; m++)
        for (t = 0; t < number_types_available; t++) {
            double mean, worst, vs = 0.0;
            report_metal_summary(r, m, t, &mean, &worst);
            for (i = 0; i < r->sc.material_count; i++)
                if (report_cell_at(r, i, m, t)->vs_ref_max > vs)
                    vs = report_cell_at(r, i, m, t)->vs_ref_max;
            fprintf(f, "| %s | %s | ", r->sc.models[m].name, number_types[t].name);
            if (isnan(mean)) /* a scene without metals: nothing to average */
                fprintf(f, "no metals | - | ");
            else
                fprintf(f, "%.3f | %.3f | ", mean, worst);
            fprintf(f, "%.1e | ", vs);
            if (isnan(r->ns[m * number_types_available + t]))
                fprintf(f, "not measured | ");
            else
                fprintf(f, "%.2f | ", r->ns[m * number_types_available + t]);
            if (isnan(r->instr[m * number_types_available + t]))
                fprintf(f, "not measured |\n");
            else
                fprintf(f, "%.0f |\n", r->instr[m * number_types_available + t]);
        }
    fprintf(f, "\n## Every material, model and type\n\n"
               "CIEDE2000 against the ground truth under the gamut policy (mean, RMS, max over 91 angles); max |error| per "
               "channel; max |this type - the same model in double|.\n\n"
               "| material | model | type | mean | RMS | max | max err r | g | b | vs own double |\n"
               "|---|---|---|---:|---:|---:|---:|---:|---:|---:|\n");
    for (i = 0; i < r->sc.material_count; i++)
        for (m = 0; m < r->sc.model_count; m++)
            for (t = 0; t < number_types_available; t++) {
                report_cell *c = report_cell_at(r, i, m, t);
                fprintf(f, "| %s | %s | %s | %.4f | %.4f | %.4f | %.2e | %.2e | %.2e | %.1e |\n", r->mats[i].p.info.id,
                        r->sc.models[m].name, number_types[t].name, c->de_mean, c->de_rms, c->de_max, c->abs_max[0],
                        c->abs_max[1], c->abs_max[2], c->vs_ref_max);
            }
    write_gamut(r, f);
    write_average(r, f);
}

/* Metzgar's Fig. 13 for every material: exact Fresnel on the Gaussian-window
 * eta', kappa' against the ground truth, as sigma grows. */

static void sigma_sweep(report_run *r, double (*de)[REPORT_SIGMAS], double (*err)[REPORT_SIGMAS])
{
    int i, k, a, ch;
    for (i = 0; i < r->sc.material_count; i++) {
        report_material *rm = &r->mats[i];
        for (k = 0; k < REPORT_SIGMAS; k++) {
            double eta[3], kappa[3], rgb[REPORT_ANGLES][3], rms, worst = 0.0;
            gaussian_window(rm->s, r->g->nm, report_sigmas[k], eta, kappa);
            for (a = 0; a < REPORT_ANGLES; a++)
                for (ch = 0; ch < 3; ch++) {
                    rgb[a][ch] = ref_conductor(eta[ch] / rm->p.n1, kappa[ch] / rm->p.n1, report_cos(a));
                    if (fabs(rgb[a][ch] - rm->gt[a][ch]) > worst)
                        worst = fabs(rgb[a][ch] - rm->gt[a][ch]);
                }
            report_curve_de(&r->ls, (const double(*)[3])rm->gt, (const double(*)[3])rgb, &de[i][k], &rms, &rms);
            err[i][k] = worst;
        }
    }
}

static void write_sigma(report_run *r, FILE *f, double (*de)[REPORT_SIGMAS], double (*err)[REPORT_SIGMAS])
{
    int i, k;
    fprintf(f, "\n## Gaussian window width (Metzgar Fig. 13)\n\nExact Fresnel on the Gaussian-window eta', kappa' "
               "(sigma = 0 is point sampling at the dominant wavelengths) against the ground truth: mean CIEDE2000 "
               "and max |error| over the three channels. Plot: sigma.svg.\n\n| material |");
    for (k = 0; k < REPORT_SIGMAS; k++)
        fprintf(f, " sigma %g: mean dE | max err |", report_sigmas[k]);
    fprintf(f, "\n|---|");
    for (k = 0; k < REPORT_SIGMAS; k++)
        fprintf(f, "---:|---:|");
    fprintf(f, "\n");
    for (i = 0; i < r->sc.material_count; i++) {
        fprintf(f, "| %s |", r->mats[i].p.info.id);
        for (k = 0; k < REPORT_SIGMAS; k++)
            fprintf(f, " %.3f | %.4f |", de[i][k], err[i][k]);
        fprintf(f, "\n");
    }
}

static int model_index(report_run *r, const char *name)
{
    int m;
    for (m = 0; m < r->sc.model_count; m++)
        if (!strcmp(r->sc.models[m].name, name))
            return m;
    return -1;
}

static void write_approaches(report_run *r, FILE *f)
{
    const char *const *order = model_approaches_order;
    int i, k;
    fprintf(f, "\n## The approaches the papers argue about, side by side\n\n"
               "Mean CIEDE2000 per material (f32): Metzgar's exact Fresnel on Gaussian-window eta', kappa' "
               "(exact-gaussian, sigma %g nm); point-sampled eta, kappa (exact-point); Hoffman's Schlick and F82 "
               "with spectral F0/F82; exact Fresnel on fitted eta, kappa (exact); Gulbrandsen r/g; LSK rescaled "
               "and compensated; Cook-Torrance interpolation; the approximate conductor form; LUTs.\n\n| material |",
            r->sc.sigma);
    for (k = 0; order[k]; k++)
        if (model_index(r, order[k]) >= 0)
            fprintf(f, " %s |", order[k]);
    fprintf(f, "\n|---|");
    for (k = 0; order[k]; k++)
        if (model_index(r, order[k]) >= 0)
            fprintf(f, "---:|");
    fprintf(f, "\n");
    for (i = 0; i < r->sc.material_count; i++) {
        fprintf(f, "| %s |", r->mats[i].p.info.id);
        for (k = 0; order[k]; k++) {
            int m = model_index(r, order[k]);
            if (m >= 0)
                fprintf(f, " %.3f |", report_cell_at(r, i, m, 0)->de_mean);
        }
        fprintf(f, "\n");
    }
}

/* Hoffman's table recomputed in ACEScg: Schlick, fitted eta/kappa and point
 * sampling, RMS CIEDE2000 over 91 angles. */
static int compute_hoffman(report_run *r)
{
    scene *sc = malloc(sizeof *sc);
    encoded_scene es;
    lab_space ls;
    int i, a, ch, status = 0;
    memset(&es, 0, sizeof es);
    if (!sc) {
        status = cli_oom(WHERE);
        goto done;
    }
    scene_defaults(sc);
    strcpy(sc->space, "acescg");
    for (i = 0; i < REPORT_HOFFMAN; i++)
        strcpy(sc->materials[i], hoffman[i].id);
    sc->material_count = REPORT_HOFFMAN;
    if ((status = encode_scene(sc, NULL, WHERE, r->g->dir, &es)))
        goto done;
    lab_space_init(&ls, &es.g->cs);
    for (i = 0; i < REPORT_HOFFMAN; i++) {
        const material_params *p = &es.params[i];
        double gt[REPORT_ANGLES][3], sch[REPORT_ANGLES][3], fit[REPORT_ANGLES][3], ps[REPORT_ANGLES][3];
        double mean, max;
        r->hoffman_in_gamut[i] = gamut_contains(p->f0_unclamped);
        for (a = 0; a < REPORT_ANGLES; a++) {
            double c = report_cos(a);
            ground_truth_gamut(es.spectra[i], es.g, p, c, gt[a]);
            for (ch = 0; ch < 3; ch++) {
                sch[a][ch] = ref_schlick(p->f0[ch], c);
                fit[a][ch] = ref_conductor(p->eta_fit[ch], p->kappa_fit[ch], c);
                ps[a][ch] = ref_conductor(p->eta_point[ch], p->kappa_point[ch], c);
            }
        }
        report_curve_de(&ls, (const double(*)[3])gt, (const double(*)[3])sch, &mean, &r->hoffman_rms[i][0], &max);
        report_curve_de(&ls, (const double(*)[3])gt, (const double(*)[3])fit, &mean, &r->hoffman_rms[i][1], &max);
        report_curve_de(&ls, (const double(*)[3])gt, (const double(*)[3])ps, &mean, &r->hoffman_rms[i][2], &max);
    }
done:
    encoded_scene_free(&es);
    free(sc);
    return status;
}

static void write_hoffman(report_run *r, FILE *f)
{
    int i;
    fprintf(f, "\n## Reproducing Hoffman's table (ACEScg)\n\n"
               "RMS CIEDE2000 over theta = 0..90 deg (1 deg steps) in ACEScg, ours beside Hoffman's published "
               "numbers [Hof20]. Differences have known causes: he lit with a D60 SPD, we light with D65 and adapt "
               "to the ACES white with Bradford (data/ has no D60); several metals come from other measurements "
               "than his (e.g. our zinc is REELS data the data pack flags as too reflective); "
               "his angle sampling and fitting error are not stated; our fit, per channel, weights each "
               "reflectance residual by its dE sensitivity, which ignores how the channels combine in dE.\n\n"
               "| metal | Schlick (ours) | Schlick (Hoffman) | fitted eta,kappa (ours) | fitted (Hoffman) | "
               "point-sampled (ours) | point-sampled (Hoffman) |\n|---|---:|---:|---:|---:|---:|---:|\n");
    for (i = 0; i < REPORT_HOFFMAN; i++)
        fprintf(f, "| %s (%s) | %.2f | %.2f | %.3f | %.2f | %.2f | %.2f |\n", hoffman[i].his_name, hoffman[i].id,
                r->hoffman_rms[i][0], hoffman[i].schlick, r->hoffman_rms[i][1], hoffman[i].fitted,
                r->hoffman_rms[i][2], hoffman[i].point_sampled);
}

/* "Which model for which budget": the models on the Pareto front of cost
 * against mean error over the metals, cheapest first, each with what it
 * costs and buys over the previous one. Cost is host instructions
 * (callgrind: deterministic) where measured, else time. */
/* A file's bytes into the report; 0, or CLI_FAILURE after a message. */
static int copy_file(FILE *f, const char *path)
{
    char buf[4096];
    size_t n;
    FILE *in;
    int status;
    if ((status = cli_open_input(path, &in)))
        return status;
    while ((n = fread(buf, 1, sizeof buf, in)) > 0)
        fwrite(buf, 1, n, f);
    if (ferror(in)) {
        int err = errno;
        fclose(in);
        return cli_read_failure(path, err);
    }
    fclose(in);
    return 0;
}

/* The cross-target sections, from the outputs of `make cross-count` and
 * `make size` (--cross, --size) as those commands print them. */
static int write_cross(const report_run *r, FILE *f)
{
    int status;
    if (r->cross_path) {
        fputs("\n## Cortex-M0, Cortex-M4F, Cortex-M55, RV32IMC and AArch64: instructions per call\n\n"
              "From qemu instruction traces (`make cross-count`; ports/README.md explains the method), and on the "
              "Cortex-M0 cycles from its timings; each section's header names its materials, cosines and columns."
              "\n\n```\n", f);
        if ((status = copy_file(f, r->cross_path)))
            return status;
        fputs("```\n", f);
    }
    if (r->size_path) {
        fputs("\n## Code size\n\nBytes one call of a model adds to an otherwise empty program (`make size`).\n\n", f);
        if ((status = copy_file(f, r->size_path)))
            return status;
    }
    if (r->spirv_path) {
        fputs("\n## GPU: SPIR-V instructions per call\n\n"
              "Instructions of each scene model's GLSL function on gold, compiled to SPIR-V and optimised "
              "(`make spirv-count`; ports/vulkan/spirv_count.sh says how). Counts of instructions, not cycles, "
              "and a table's size does not show in them: a LUT's const array is one instruction to SPIR-V, "
              "however many floats a driver copies; an extended instruction (exp, cos, sin) counts as one. "
              "The thin film's peers, khr-iridescence-peer and polarised-film-peer, are the viewer's GLSL of "
              "them (ports/webgl/viewer.html) on the same film and substrate: they call the GPU's cos, sin and "
              "exp, where the film computes cos and sin by the C runtime's polynomials.\n\n", f);
        if ((status = copy_file(f, r->spirv_path)))
            return status;
    }
    return 0;
}

/* A `make bench` output into the report as printed, less its targets (the
 * lines from "# target ID" on that start with "target ", and the "#" line
 * before them): the goals are targets.md's. 0, or CLI_FAILURE after a
 * message. */
static int copy_speed_file(FILE *f, const char *path)
{
    char *line = NULL, *held = NULL;
    size_t cap = 0;
    FILE *in;
    int status, err;
    if ((status = cli_open_input(path, &in)))
        return status;
    while (getline(&line, &cap, in) != -1) {
        if (!strncmp(line, "target ", 7) || !strncmp(line, "# target ", 9)) {
            free(held);
            held = NULL;
            continue;
        }
        if (held) {
            fputs(held, f);
            free(held);
            held = NULL;
        }
        if (!strcmp(line, "#\n")) {
            if (!(held = malloc(3))) {
                status = cli_oom(WHERE);
                break;
            }
            memcpy(held, "#\n", 3);
        } else
            fputs(line, f);
    }
    err = errno;
    if (held)
        fputs(held, f);
    if (!status && ferror(in))
        status = cli_read_failure(path, err);
    free(held);
    free(line);
    fclose(in);
    return status;
}

/* The `make bench` outputs, as printed, less their targets. */
static int write_speed(const report_run *r, FILE *f)
{
    int i, status;
    if (!r->speed_count)
        return 0;
    fputs("\n## Host speed against other renderers' algorithms\n\n"
          "The output of `make bench` for each compiler and flag set (speed/speed.c; format in "
          "gen/bench/speed_targets.h), its rows: ns per evaluation, one channel, and the time over the "
          "schlick-f32 row of the same round. The mitsuba-* and pbrt-* rows are this project's binary32 "
          "transcriptions (gen/bench/peers.h), no code of theirs, of Mitsuba 3's fresnel_conductor "
          "(include/mitsuba/render/fresnel.h) and pbrt-v4's FrComplex (src/pbrt/util/scattering.h), each timed as "
          "an out-of-line call and inlined into the array loop.\n",
          f);
    for (i = 0; i < r->speed_count; i++) {
        fprintf(f, "\n`make bench OPT='%s'`, %s:\n\n```\n", r->speed[i]->opt,
                *r->speed[i]->compiler ? r->speed[i]->compiler : "compiler not named");
        if ((status = copy_speed_file(f, r->speed_paths[i])))
            return status;
        fputs("```\n", f);
    }
    return 0;
}

static void write_budget(report_run *r, FILE *f)
{
    int n = r->sc.model_count * number_types_available, k, j, nf = 0, a, b, use_instr = 1;
    int *front = malloc((size_t)n * sizeof *front);
    const double *cost;
    if (!front)
        return;
    {
        double mean, worst;
        report_metal_summary(r, 0, 0, &mean, &worst);
        if (isnan(mean)) {
            fprintf(f, "\n## Which model for which budget\n\nNo metals in this scene: no error over the metals to "
                       "rank the models by.\n");
            free(front);
            return;
        }
    }
    for (k = 0; k < n; k++)
        if (isnan(r->instr[k]))
            use_instr = 0;
    cost = use_instr ? r->instr : r->ns;
    for (k = 0; k < n; k++) {
        double mean_k, worst_k;
        int dominated = 0;
        if (isnan(cost[k]))
            continue;
        report_metal_summary(r, k / number_types_available, k % number_types_available, &mean_k, &worst_k);
        for (j = 0; j < n && !dominated; j++) {
            double mean_j, worst_j;
            if (j == k || isnan(cost[j]))
                continue;
            report_metal_summary(r, j / number_types_available, j % number_types_available, &mean_j, &worst_j);
            dominated = cost[j] <= cost[k] && mean_j <= mean_k && (cost[j] < cost[k] || mean_j < mean_k);
        }
        if (!dominated)
            front[nf++] = k;
    }
    for (a = 0; a < nf; a++)
        for (b = a + 1; b < nf; b++)
            if (cost[front[b]] < cost[front[a]]) {
                int tmp = front[a];
                front[a] = front[b];
                front[b] = tmp;
            }
    fprintf(f, "\n## Which model for which budget\n\nThe models no other model beats on both cost (%s per RGB "
               "evaluation on this host) and mean error over the metals, cheapest first, each with what it costs "
               "and buys over the one before (pareto.svg draws the same front against time).\n\n",
            use_instr ? "callgrind instructions" : "ns");
    for (a = 0; a < nf; a++) {
        double mean, worst, pm, pw;
        int k0 = front[a];
        report_metal_summary(r, k0 / number_types_available, k0 % number_types_available, &mean, &worst);
        fprintf(f, "- **%s (%s)**: %.0f %s", r->sc.models[k0 / number_types_available].name, number_types[k0 % number_types_available].name,
                cost[k0], use_instr ? "instructions" : "ns");
        if (use_instr && !isnan(r->ns[k0]))
            fprintf(f, ", %.2f ns", r->ns[k0]);
        fprintf(f, "; mean dE2000 %.3f, worst max %.3f", mean, worst);
        if (a > 0) {
            report_metal_summary(r, front[a - 1] / number_types_available, front[a - 1] % number_types_available, &pm, &pw);
            fprintf(f, " (%.1fx the cost of the previous, %.1fx lower mean error)", cost[k0] / cost[front[a - 1]],
                    mean > 0.0 ? pm / mean : INFINITY);
        }
        fprintf(f, ".\n");
    }
    if (!nf)
        fprintf(f, "(costs not measured in this run)\n");
    free(front);
}

int report_write(const report_options *o)
{
    report_run r;
    const char *scene_path = o->scene_path;
    int timing = o->timing, instructions = o->instructions, i, m, t, status = 0;
    double (*sig_de)[REPORT_SIGMAS] = NULL, (*sig_err)[REPORT_SIGMAS] = NULL;
    FILE *f;
    char curves[CLI_PATH_MAX];
    int made_dir = 0, made_curves = 0;
    memset(&r, 0, sizeof r);
    r.out_dir = o->out_dir;
    r.scene_path = o->scene_path;
    r.cross_path = o->cross_path;
    r.size_path = o->size_path;
    r.spirv_path = o->spirv_path;
    for (i = 0; i < o->speed_count && i < REPORT_MAX_SPEED; i++) { /* bad input: an error before anything is written */
        speed_file *sf = malloc(sizeof *sf);
        char where[1100];
        const char *what;
        FILE *in;
        int got, err;
        if (!sf) {
            status = cli_oom(WHERE);
            break;
        }
        r.speed[i] = sf;
        r.speed_paths[i] = o->speed_paths[i];
        r.speed_count = i + 1;
        if ((status = cli_open_input(o->speed_paths[i], &in)))
            break;
        got = speed_file_read(in, o->speed_paths[i], sf, where, (int)sizeof where, &what);
        err = errno;
        fclose(in);
        if (got) {
            status = got > 0 ? cli_read_failure(o->speed_paths[i], err) : cli_error(where, "%s", what);
            break;
        }
    }
    if (!status && !(status = scene_load(scene_path, &r.full))) {
        if (o->gamut_given)
            r.full.gamut = o->gamut;
        r.sc = r.full;
    }
    if (status) {
        for (i = 0; i < r.speed_count; i++)
            free((void *)r.speed[i]);
        return status;
    }
    r.timing = timing;
    if (r.sc.spacing == LUT_GRAZING_PL)
        return cli_error(scene_path, "lut_spacing grazing-pl tables are Q15-only and the report measures every number "
                                     "type; its targets table measures them itself");
    if ((status = report_film_take(&r, scene_path)))
        goto done;
    r.mats = calloc((size_t)r.sc.material_count, sizeof *r.mats);
    r.cells = calloc((size_t)r.sc.material_count * r.sc.model_count * number_types_available, sizeof *r.cells);
    r.ns = malloc((size_t)r.sc.model_count * number_types_available * sizeof *r.ns);
    r.instr = malloc((size_t)r.sc.model_count * number_types_available * sizeof *r.instr);
    sig_de = calloc((size_t)r.sc.material_count, sizeof *sig_de);
    sig_err = calloc((size_t)r.sc.material_count, sizeof *sig_err);
    if (!r.mats || !r.cells || !r.ns || !r.instr || !sig_de || !sig_err) {
        status = cli_oom(WHERE);
        goto done;
    }
    if ((status = encode_scene(&r.full, scene_path, WHERE, o->data_dir, &r.es)))
        goto done;
    r.g = r.es.g;
    lab_space_init(&r.ls, &r.g->cs);
    for (i = 0; i < r.sc.material_count; i++) {
        report_material *rm = &r.mats[i];
        if (!(rm->models = calloc((size_t)r.sc.model_count + 1, sizeof *rm->models))) {
            status = cli_oom(WHERE);
            goto done;
        }
        rm->p = r.es.params[i];
        rm->s = r.es.spectra[i];
        report_ground_truth(r.g, &r.ls, rm);
        for (m = 0; m < r.sc.model_count; m++) {
            /* the report's models are the scene's without the film's row */
            rm->models[m] = *encoded_scene_model(&r.es, i, r.film.present && m >= r.film.row ? m + 1 : m);
            for (t = 0; t < number_types_available; t++)
                report_measure(&r.ls, rm, m, &number_types[t], report_cell_at(&r, i, m, t));
        }
        if ((status = report_film_measure(&r, i)))
            goto done;
    }
    for (i = 0; i < r.sc.model_count * number_types_available; i++)
        r.ns[i] = r.instr[i] = NAN;
    /* Costs barely depend on the material: gold if the scene has it. */
    for (i = 0; i < r.sc.material_count; i++)
        if (!strcmp(r.mats[i].p.info.id, "au"))
            r.timed_material = i;
    if (instructions && system("valgrind --version >/dev/null 2>&1") != 0) {
        fprintf(stderr, "%s: valgrind not found: instruction counts not measured\n", WHERE);
        instructions = 0;
    }
    for (m = 0; m < r.sc.model_count; m++)
        for (t = 0; t < number_types_available; t++) {
            int k = m * number_types_available + t;
            model_rgb q = scene_model_rgb(&r.mats[r.timed_material].models[m]);
            if (timing)
                r.ns[k] = report_time(&number_types[t], &q, 1 << 20, 5);
            if (instructions)
                r.instr[k] = callgrind_instructions(scene_path, r.mats[r.timed_material].p.info.id, r.sc.models[m].name,
                                                    number_types[t].name);
            if (timing || instructions)
                fprintf(stderr, "%s: %s %s: %.2f ns, %.0f instructions\n", WHERE, r.sc.models[m].name,
                        number_types[t].name, r.ns[k], r.instr[k]);
        }
    if (timing)
        report_film_time(&r);
    sigma_sweep(&r, sig_de, sig_err);
    if ((status = compute_hoffman(&r)))
        goto done;

    /* Every file is committed at the end, together; on failure the
     * directories this run created go too. */
    r.out_cap = r.sc.material_count + 4;
    if (!(r.out = calloc((size_t)r.out_cap, sizeof *r.out))) {
        status = cli_oom(WHERE);
        goto done;
    }
    if ((made_dir = mkdir(r.out_dir, 0777) == 0) == 0 && errno != EEXIST) {
        status = cli_error(r.out_dir, "cannot create the directory: %s", strerror(errno));
        goto done;
    }
    if ((size_t)snprintf(curves, sizeof curves, "%s/curves", r.out_dir) >= sizeof curves) {
        status = cli_error(r.out_dir, "path too long");
        goto done;
    }
    if ((made_curves = mkdir(curves, 0777) == 0) == 0 && errno != EEXIST) {
        status = cli_error(curves, "cannot create the directory: %s", strerror(errno));
        goto done;
    }
    if (!(f = report_out_open(&r, "report.md", &status)))
        goto done;
    fprintf(f, "# Fresnel models: error against run time\n\nWritten by `build/fresnel report --scene %s` "
                   "(`make report`). Colour space %s, Gaussian window sigma %g nm, incident medium n1 %g; "
                   "ground truth: spectral Fresnel x D65 x CIE 1931 2-degree CMFs, under the gamut policy `%s` "
                   "(\"Colours outside the gamut\" below).\n\n",
            scene_path, r.sc.space, r.sc.sigma, r.sc.n1, gamut_policy_names[r.g->gamut]);
    write_accuracy_tables(&r, f);
    report_film_write(&r, f);
    write_sigma(&r, f, sig_de, sig_err);
    write_approaches(&r, f);
    report_renderers(&r, f);
    write_hoffman(&r, f);
    write_budget(&r, f);
    if ((status = write_cross(&r, f)) || (status = write_speed(&r, f)))
        goto done;
    if (!(f = report_out_open(&r, "targets.md", &status)))
        goto done;
    report_targets(&r, f);
    if ((status = report_plots(&r, (const double(*)[REPORT_SIGMAS])sig_de)))
        goto done;
    if ((status = finish_outputs(&r, 0)))
        goto done;
    printf("fresnel report: wrote %s/report.md, %s/pareto.svg, %s/sigma.svg, %s/curves/*.svg, %s/targets.md\n", r.out_dir,
           r.out_dir, r.out_dir, r.out_dir, r.out_dir);
done:
    if (r.out)
        status = finish_outputs(&r, status);
    if (status && made_curves)
        rmdir(curves);
    if (status && made_dir)
        rmdir(r.out_dir);
    if (r.mats)
        for (i = 0; i < r.sc.material_count; i++)
            free(r.mats[i].models);
    report_film_free(&r);
    free(r.mats);
    free(r.cells);
    free(r.ns);
    free(r.instr);
    encoded_scene_free(&r.es);
    for (i = 0; i < r.speed_count; i++)
        free((void *)r.speed[i]);
    free(sig_de);
    free(sig_err);
    return status;
}
