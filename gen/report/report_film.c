/* The thin film in the report: a scene's thin-film model measured over
 * thickness as well as angle against the film's own spectral truth, its
 * cost beside fresnel_schlick_rgb's in the same run, and its table sizes
 * (report.h). The film is taken out of the scene's model list, whose
 * tables measure models of angle alone against the bare material. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "bench/bench.h"
#include "common/reference.h"
#include "common/reference_film.h"
#include "report/report.h"

#define WHERE "fresnel report"

/* Thicknesses measured across the scene's range (one where it is one). */
#define FILM_THICKNESSES 201

/* The per-channel eta, kappa sets the polarised peer is given (relative to
 * the outside medium; the peer takes absolute indices): the report shows
 * the best of them, and says which. */
static const char *const polarised_input_name[FILM_POLARISED_INPUTS] = {
    "eta, kappa fitted to the material's RGB ground truth (fresnel_conductor_rgb's `eta`, `kappa`)",
    "Metzgar's Gaussian-window eta, kappa (`eta_gaussian`, `kappa_gaussian`)",
    "eta, kappa point-sampled at the dominant wavelengths (`eta_point`, `kappa_point`)"};
/* The angle bands of the film's breakdown: theta from each lower edge up to
 * the next (degrees), the last to 90 inclusive. */
static const int film_angle_band[4] = {0, 30, 60, 80};
static int angle_band(int theta)
{
    int b = 3;
    while (b > 0 && theta < film_angle_band[b])
        b--;
    return b;
}
static int thickness_band(const scene *sc, double d)
{
    double span = sc->film_d_hi - sc->film_d_lo;
    int b = span > 0.0 ? (int)(4.0 * (d - sc->film_d_lo) / span) : 0;
    return b < 0 ? 0 : (b > 3 ? 3 : b);
}

static void polarised_inputs(const material_params *p, int set, double eta[3], double kappa[3])
{
    const double *e = set == 0 ? p->eta_fit : set == 1 ? p->eta_gauss : p->eta_point;
    const double *k = set == 0 ? p->kappa_fit : set == 1 ? p->kappa_gauss : p->kappa_point;
    int ch;
    for (ch = 0; ch < 3; ch++)
        eta[ch] = e[ch] * p->n1, kappa[ch] = k[ch] * p->n1;
}

int report_film_take(report_run *r, const char *scene_path)
{
    report_film *f = &r->film;
    int m, i;
    memset(f, 0, sizeof *f);
    for (m = 0; m < r->sc.model_count && !(model_of(r->sc.models[m].row)->offered & MODEL_FILM); m++)
        ;
    if (m == r->sc.model_count)
        return 0;
    if (r->sc.model_count == 1) /* the report's other sections compare models of angle alone */
    {
        char where[1100];
        snprintf(where, sizeof where, "%s:%d", scene_path, r->sc.models_line);
        return cli_error(where, "expected a model besides %s in models (the report measures the film beside the bare "
                                "material's models)",
                         r->sc.models[m].name);
    }
    f->entry = r->sc.models[m];
    f->row = m;
    f->present = 1;
    f->film_n = calloc((size_t)r->sc.material_count, sizeof *f->film_n);
    f->models = calloc((size_t)r->sc.material_count, sizeof *f->models);
    f->cells = calloc((size_t)r->sc.material_count * number_types_available, sizeof *f->cells);
    f->peer_mean = calloc((size_t)r->sc.material_count, sizeof *f->peer_mean);
    f->peer_max = calloc((size_t)r->sc.material_count, sizeof *f->peer_max);
    f->pol_mean = calloc((size_t)r->sc.material_count * FILM_POLARISED_INPUTS, sizeof *f->pol_mean);
    f->pol_max = calloc((size_t)r->sc.material_count * FILM_POLARISED_INPUTS, sizeof *f->pol_max);
    if (!f->film_n || !f->models || !f->cells || !f->peer_mean || !f->peer_max || !f->pol_mean || !f->pol_max)
        return cli_oom(WHERE);
    for (i = 0; i < r->sc.material_count; i++)
        f->film_n[i] = scene_film_n(&r->sc, i);
    memmove(&r->sc.models[m], &r->sc.models[m + 1], (size_t)(r->sc.model_count - m - 1) * sizeof r->sc.models[0]);
    r->sc.model_count--;
    for (i = 0; i < NUMBER_TYPES; i++)
        f->ns[i] = NAN;
    f->schlick_ns = NAN;
    return 0;
}

void report_film_free(report_run *r)
{
    report_film *f = &r->film;
    free(f->models);
    free(f->film_n);
    free(f->cells);
    free(f->peer_mean);
    free(f->peer_max);
    free(f->pol_mean);
    free(f->pol_max);
    memset(f, 0, sizeof *f);
}

static double thickness(const scene *sc, int k)
{
    return sc->film_d_lo == sc->film_d_hi ? sc->film_d_lo
                                          : sc->film_d_lo + (sc->film_d_hi - sc->film_d_lo) * k / (FILM_THICKNESSES - 1);
}

int report_film_measure(report_run *r, int i)
{
    report_film *f = &r->film;
    report_material *rm = &r->mats[i];
    material_params p = rm->p;
    film_stack stack;
    model_rgb q;
    int a, k, t, set, nd = r->sc.film_d_lo == r->sc.film_d_hi ? 1 : FILM_THICKNESSES;
    int peer = !strcmp(r->g->cs.id, "srgb"); /* the peers write linear Rec. 709 */
    long n = 0;
    if (!f->present)
        return 0;
    f->peer_measured = peer;
    p.film_n = f->film_n[i];
    f->models[i] = *encoded_scene_model(&r->es, i, f->row);
    q = scene_model_rgb(&f->models[i]);
    stack.n1 = p.n1;
    stack.film = NULL;
    stack.film_n = p.film_n;
    stack.substrate = rm->s;
    for (a = 0; a < REPORT_ANGLES; a++) {
        double c = report_cos(a);
        film_optics_table *optics = film_truth_prepare(&stack, c);
        if (!optics)
            return cli_oom(WHERE);
        for (k = 0; k < nd; k++) {
            double truth[3], lab_truth[3];
            int ch;
            q.d_nm = thickness(&r->sc, k);
            film_truth_at(optics, &r->g->cm, &r->g->cs, q.d_nm, truth);
            for (ch = 0; ch < 3; ch++)
                truth[ch] = ref_clamp(truth[ch], 0.0, 1.0);
            lab_space_lab(&r->ls, truth, lab_truth);
            if (peer) { /* its best input: the material's F0 under the scene's gamut policy */
                double rgb[3], lab[3], de;
                int tb = thickness_band(&r->sc, q.d_nm), ab = angle_band(a);
                f->band_n[tb][ab]++;
                ref_film_khr_iridescence(p.n1, p.film_n, q.d_nm, c, p.f0, rgb);
                for (ch = 0; ch < 3; ch++)
                    rgb[ch] = ref_clamp(rgb[ch], 0.0, 1.0);
                lab_space_lab(&r->ls, rgb, lab);
                de = ciede2000(lab_truth, lab);
                f->peer_mean[i] += de;
                f->peer_max[i] = fmax(f->peer_max[i], de);
                f->band_de[1][tb][ab] += de;
                for (set = 0; set < FILM_POLARISED_INPUTS; set++) {
                    double eta[3], kappa[3];
                    int at = set * r->sc.material_count + i;
                    polarised_inputs(&p, set, eta, kappa);
                    ref_film_belcour_polarised(p.n1, p.film_n, q.d_nm, c, eta, kappa, rgb);
                    for (ch = 0; ch < 3; ch++)
                        rgb[ch] = ref_clamp(rgb[ch], 0.0, 1.0);
                    lab_space_lab(&r->ls, rgb, lab);
                    de = ciede2000(lab_truth, lab);
                    f->pol_mean[at] += de;
                    f->pol_max[at] = fmax(f->pol_max[at], de);
                    f->band_de[2 + set][tb][ab] += de;
                }
            }
            for (t = 0; t < number_types_available; t++) {
                report_film_cell *cell = &f->cells[i * number_types_available + t];
                double rgb[3], lab[3], de;
                number_types[t].eval(&q, c, rgb);
                lab_space_lab(&r->ls, rgb, lab);
                de = ciede2000(lab_truth, lab);
                if (peer && t == 0)
                    f->band_de[0][thickness_band(&r->sc, q.d_nm)][angle_band(a)] += de;
                cell->de_mean += de;
                if (de >= cell->de_max) {
                    cell->de_max = de;
                    cell->worst_theta = a;
                    cell->worst_d = q.d_nm;
                }
            }
            n++;
        }
        free(optics);
    }
    for (t = 0; t < number_types_available; t++)
        f->cells[i * number_types_available + t].de_mean /= (double)n;
    f->peer_mean[i] /= (double)n;
    for (set = 0; set < FILM_POLARISED_INPUTS; set++)
        f->pol_mean[set * r->sc.material_count + i] /= (double)n;
    f->samples = n;
    return 0;
}

void report_film_time(report_run *r)
{
    report_film *f = &r->film;
    bench_batch fns[NUMBER_TYPES + 1];
    const void *ctxs[NUMBER_TYPES + 1];
    model_rgb q[NUMBER_TYPES + 1];
    double ns[NUMBER_TYPES + 1];
    int t;
    if (!f->present)
        return;
    for (t = 0; t < number_types_available; t++) {
        q[t] = scene_model_rgb(&f->models[r->timed_material]);
        q[t].d_nm = 0.5 * (r->sc.film_d_lo + r->sc.film_d_hi);
        fns[t] = number_types[t].batch(q[t].def);
        ctxs[t] = &q[t];
    }
    q[t] = scene_model_rgb(&f->models[r->timed_material]); /* the same material's F0 */
    q[t].def = model_schlick;
    q[t].film = NULL;
    fns[t] = model_schlick->f32->batch;
    ctxs[t] = &q[t];
    /* short samples (2048 evaluations) in many rounds: on a loaded machine a
     * long sample of the film would be preempted more often than Schlick's */
    if (bench_ns_per_eval_rounds(fns, ctxs, t + 1, 2048, 101, ns))
        return;
    for (t = 0; t < number_types_available; t++)
        f->ns[t] = ns[t];
    f->schlick_ns = ns[t];
}

void report_film_write(report_run *r, FILE *out)
{
    const report_film *f = &r->film;
    const scene *sc = &r->sc;
    int i, t, nd = sc->film_d_lo == sc->film_d_hi ? 1 : FILM_THICKNESSES;
    double m0;
    static const size_t bytes[NUMBER_TYPES] = {sizeof(fresnel_film), sizeof(fresnel_film_q15),
#if FRESNEL_HAS_F16
                                                sizeof(fresnel_film_f16)
#else
                                                0
#endif
    };
    char range[96];
    if (!f->present)
        return;
    m0 = r->cross_path && model_of(f->entry.row)->cross_row ? report_m0_count(r->cross_path, model_of(f->entry.row)->cross_row) : NAN;
    if (nd > 1)
        snprintf(range, sizeof range, "%d thicknesses %g-%g nm", nd, sc->film_d_lo, sc->film_d_hi);
    else
        snprintf(range, sizeof range, "the thickness %g nm", sc->film_d_lo);
    fprintf(out, "\n## Thin film\n\n`%s` (include/fresnel_film.h): a transparent film on each material, its "
                 "thickness a run-time input. CIEDE2000 of the runtime of each type, on the tables `fresnel gen` "
                 "writes for this scene, against the film's spectral truth (Airy's sum at every nanometre, held "
                 "to [0, 1] per channel as the runtime holds its result), over theta 0-90 degrees every degree x "
                 "%s (%ld samples per material):\n\n| material | film n |",
            f->entry.name, range, f->samples);
    for (t = 0; t < number_types_available; t++)
        fprintf(out, " %s mean | %s max |", number_types[t].name, number_types[t].name);
    fprintf(out, " worst (%s) at |\n|---|---:|", number_types[0].name);
    for (t = 0; t < number_types_available; t++)
        fprintf(out, "---:|---:|");
    fprintf(out, "---|\n");
    for (i = 0; i < sc->material_count; i++) {
        const report_film_cell *c0 = &f->cells[i * number_types_available];
        fprintf(out, "| %s | %g |", r->mats[i].p.info.id, f->film_n[i]);
        for (t = 0; t < number_types_available; t++)
            fprintf(out, " %.3f | %.3f |", c0[t].de_mean, c0[t].de_max);
        fprintf(out, " theta %d, d %.0f nm |\n", c0->worst_theta, c0->worst_d);
    }
    fprintf(out, "| all | |");
    for (t = 0; t < number_types_available; t++) {
        double mean = 0.0, max = 0.0;
        for (i = 0; i < sc->material_count; i++) {
            mean += f->cells[i * number_types_available + t].de_mean / sc->material_count;
            max = fmax(max, f->cells[i * number_types_available + t].de_max);
        }
        fprintf(out, " %.3f | %.3f |", mean, max);
    }
    fprintf(out, " |\n");
    if (f->peer_measured) {
        double mean = 0.0, max = 0.0, own_mean = 0.0, own_max = 0.0, pol_all[FILM_POLARISED_INPUTS] = {0}, pmean = 0.0,
               pmax = 0.0;
        int best = report_film_best_polarised(f, sc->material_count), set, a, b;
        for (set = 0; set < FILM_POLARISED_INPUTS; set++)
            for (i = 0; i < sc->material_count; i++)
                pol_all[set] += f->pol_mean[set * sc->material_count + i] / sc->material_count;
        fprintf(out, "\nBeside the real-time standard, in double precision (gen/common/reference_film.h), on the same "
                     "samples against the same truth, each result held to [0, 1]: KHR_materials_iridescence as glTF "
                     "2.0 specifies it and the Khronos glTF Sample Viewer evaluates it (Belcour and Barla 2017 with "
                     "Schlick at both interfaces, orders m <= 2), given its best input for a measured substrate, the "
                     "material's F0 under the scene's gamut policy; and the same family with the exact polarised "
                     "Fresnel equations at both interfaces (Belcour and Barla's own form, orders m <= 2) on a base of "
                     "per-channel eta, kappa, given the best of three sets on this scene (mean over its materials): "
                     "%s.\n\n"
                     "| material | %s %s mean | max | KHR_materials_iridescence mean | max | polarised mean | max |\n"
                     "|---|---:|---:|---:|---:|---:|---:|\n",
                polarised_input_name[best], f->entry.name, number_types[0].name);
        for (i = 0; i < sc->material_count; i++) {
            const report_film_cell *c0 = &f->cells[i * number_types_available];
            int at = best * sc->material_count + i;
            fprintf(out, "| %s | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f |\n", r->mats[i].p.info.id, c0->de_mean,
                    c0->de_max, f->peer_mean[i], f->peer_max[i], f->pol_mean[at], f->pol_max[at]);
            mean += f->peer_mean[i] / sc->material_count;
            max = fmax(max, f->peer_max[i]);
            pmean += f->pol_mean[at] / sc->material_count;
            pmax = fmax(pmax, f->pol_max[at]);
            own_mean += c0->de_mean / sc->material_count;
            own_max = fmax(own_max, c0->de_max);
        }
        fprintf(out, "| all | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f |\n", own_mean, own_max, mean, max, pmean, pmax);
        fprintf(out, "\nThe polarised form's mean CIEDE2000 over the materials with each input set:");
        for (set = 0; set < FILM_POLARISED_INPUTS; set++)
            fprintf(out, "%s %s %.3f", set ? ";" : "", set == 0 ? "fitted" : set == 1 ? "Gaussian window" : "point-sampled",
                    pol_all[set]);
        fprintf(out, ".\n\nWhere they differ: mean CIEDE2000 over the materials by thickness and angle, %s %s / "
                     "KHR_materials_iridescence / polarised:\n\n| thickness \\ theta |",
                f->entry.name, number_types[0].name);
        for (a = 0; a < 4; a++)
            fprintf(out, a < 3 ? " %d-%d deg |" : " %d-90 deg |", film_angle_band[a], a < 3 ? film_angle_band[a + 1] - 1 : 90);
        fprintf(out, "\n|---|---:|---:|---:|---:|\n");
        for (b = 0; b < (nd > 1 ? 4 : 1); b++) {
            double span = sc->film_d_hi - sc->film_d_lo;
            if (nd > 1)
                fprintf(out, "| %g-%g nm |", sc->film_d_lo + span * b / 4.0, sc->film_d_lo + span * (b + 1) / 4.0);
            else
                fprintf(out, "| %g nm |", sc->film_d_lo);
            for (a = 0; a < 4; a++) {
                double n = (double)f->band_n[b][a];
                if (n > 0.0)
                    fprintf(out, " %.3f / %.2f / %.2f |", f->band_de[0][b][a] / n, f->band_de[1][b][a] / n,
                            f->band_de[2 + best][b][a] / n);
                else
                    fprintf(out, " |");
            }
            fprintf(out, "\n");
        }
    }
    fprintf(out, "\n| type | table bytes per material | ns per RGB evaluation | x fresnel_schlick_rgb |\n"
                 "|---|---:|---:|---:|\n");
    for (t = 0; t < number_types_available; t++) {
        fprintf(out, "| %s | %lu |", number_types[t].name, (unsigned long)bytes[number_types[t].id]);
        if (isnan(f->ns[t]))
            fprintf(out, " not timed | |\n");
        else
            fprintf(out, " %.1f | %.1f |\n", f->ns[t], f->ns[t] / f->schlick_ns);
    }
    if (!isnan(f->schlick_ns))
        fprintf(out, "\nTimes: %s, the film at %g nm on %s and fresnel_schlick_rgb on the same 2048 cosines, 101 "
                     "interleaved rounds in one process, medians; every compiler and flag set: rows film-f32 "
                     "and schlick-rgb-f32 of `make bench` (below).\n",
                bench_compiler(), 0.5 * (sc->film_d_lo + sc->film_d_hi), r->mats[r->timed_material].p.info.id);
    if (!isnan(m0))
        fprintf(out, "\nCortex-M0 (`make cross-count`): %.0f instructions per RGB evaluation of fresnel_film_q15_rgb.\n",
                m0);
}

