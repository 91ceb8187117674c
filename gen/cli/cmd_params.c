/* fresnel params: every parameter the generator derives for one material. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/commands.h"
#include "1_spectral/colour_difference.h"
#include "2_derive/targets.h"
#include "common/cli.h"
#include "cli/material_options.h"
#include "model/encoded_scene.h"
#include "scene/scene.h"

#define WHERE "fresnel params"

static const char *const option_names[] = {"--material", "--nk", "--name", "--format", "--space", "--gamut", "--sigma",
                                           "--n1", "--data", "--for", "--film", "--help", NULL};

static void row(const char *name, const double v[3])
{
    printf("%s,%.9g,%.9g,%.9g\n", name, v[0], v[1], v[2]);
}

/* --for's value: a target, or "all". */
static int target_option(const char *val)
{
    const char *names[16];
    char list[256] = "";
    size_t used = 0;
    const char *near;
    int i, n = target_names(names, 15);
    if (!strcmp(val, "all") || target_find(val))
        return 0;
    names[n++] = "all";
    names[n] = NULL;
    for (i = 0; names[i]; i++)
        used += (size_t)snprintf(list + used, sizeof list - used, "%s%s", i ? ", " : "", names[i]);
    near = cli_suggest(val, names);
    if (near)
        return cli_error(WHERE, "unknown target '%s' for --for (did you mean '%s'? expected one of: %s)", val, near,
                         list);
    return cli_error(WHERE, "unknown target '%s' for --for (expected one of: %s)", val, list);
}

/* A target's packed numbers as CSV rows, each prefixed by lead. */
static void target_rows(const target *t, const double *x, const char *lead)
{
    int i, k = 0;
    for (i = 0; i < t->param_count; i++) {
        double v[3];
        if (t->param[i].scalar) {
            v[0] = v[1] = v[2] = x[k++];
        } else {
            v[0] = x[k];
            v[1] = x[k + 1];
            v[2] = x[k + 2];
            k += 3;
        }
        printf("%s", lead);
        row(t->param[i].name, v);
    }
}

static void print_target(const target *t, const target_fit *f, const gen_context *g, const lab_space *ls,
                         const double (*raw)[3], int out_of_gamut)
{
    printf("# target %s: %s\n# formula: %s\n# source: %s\n# inputs: %s\n", t->name, t->title, t->formula, t->source,
           t->inputs);
    if (t->rec709 && strcmp(g->cs.id, "srgb"))
        printf("# this format takes linear Rec.709 (--space srgb); these values are in %s\n", g->cs.id);
    printf("parameter,r,g,b\n");
    target_rows(t, f->fitted, "");
    printf("# fitted: mean dE2000 %.4f, max %.4f (theta 0-90 deg in 1 deg steps, against the ground truth under the "
           "gamut policy %s)\n",
           f->fit_mean, f->fit_max, gamut_policy_names[g->gamut]);
    printf("# naive (%s): mean dE2000 %.4f, max %.4f\n", t->naive_rule, f->naive_mean, f->naive_max);
    target_rows(t, f->naive, "# naive ");
    printf("# gain of the fit: mean dE2000 %.4f lower (%.1fx), max %.4f %s (the fitted mean is never above the naive "
           "conversion's; the max is not minimised)\n",
           f->naive_mean - f->fit_mean, f->fit_mean > 0.0 ? f->naive_mean / f->fit_mean : 1.0,
           fabs(f->fit_max - f->naive_max), f->fit_max > f->naive_max ? "higher" : "lower");
    if (out_of_gamut) {
        double mean, max;
        target_curve_de(t, ls, raw, f->fitted, &mean, &max);
        printf("# against the unclipped ground truth (outside the %s gamut): mean dE2000 %.4f, max %.4f; %s\n",
               g->cs.id, mean, max,
               target_above_one(t) ? "this target's colours may exceed 1: --gamut keep fits the unclipped truth"
                                   : "this target's colours stop at 1");
    }
}

/* The renderer's thin-film inputs for a film of index n, d_nm thick, over
 * the metal printed before; then the metal's parameters refitted under the
 * film through the renderer's own film formula (target_film_fit) with the
 * fitted and the naive CIEDE2000. */
static int print_film(const target *t, double n, double d_nm, const encoded_scene *es)
{
    const char *names[4];
    double values[4];
    target_fit fit;
    int k, ch, x = 0, count = target_film_rows(t, n, d_nm, names, values);
    printf("# thin film: index %g, %g nm, laid by %s over the metal above (whose parameters are the bare metal's): "
           "%s\n",
           n, d_nm, t->name, t->film.where);
    for (k = 0; k < count; k++) {
        const double v[3] = {values[k], values[k], values[k]};
        row(names[k], v);
    }
    if (target_film_fit(t, es->spectra[0], es->g, &es->params[0], n, d_nm, d_nm, &fit))
        return cli_oom(WHERE);
    printf("# under the film, through %s's own film formula (%s), the metal's parameters refitted against the "
           "film's spectral truth on this material (theta 0-90 deg in 1 deg steps, held to [0, 1]):",
           t->name, t->film.formula);
    for (k = 0; k < t->param_count; k++) {
        printf(" %s", t->param[k].name);
        for (ch = 0; ch < (t->param[k].scalar ? 1 : 3); ch++, x++)
            printf("%s%.9g", ch ? "," : " ", fit.fitted[x]);
    }
    printf("\n# under the film, fitted: mean dE2000 %.4f, max %.4f; naive (%s): mean %.4f, max %.4f\n",
           fit.fit_mean, fit.fit_max, t->naive_rule, fit.naive_mean, fit.naive_max);
    return 0;
}

/* The scene's targets (one, or every one for "all"), as encode_scene
 * fitted them. */
static int print_targets(const char *which, const encoded_scene *es)
{
    const gen_context *g = es->g;
    double raw[TARGET_ANGLES][3];
    target_anchor a_raw;
    lab_space ls;
    int i, out_of_gamut = 0;
    lab_space_init(&ls, &g->cs);
    target_material_curve(es->spectra[0], g, &es->params[0], 0, raw, &a_raw);
    for (i = 0; i < TARGET_ANGLES; i++)
        out_of_gamut |= !gamut_contains(raw[i]);
    if (strcmp(which, "all")) {
        print_target(&target_table[es->sc->targets[0]], &es->fits[0], g, &ls, (const double(*)[3])raw, out_of_gamut);
        return 0;
    }
    printf("# every target's fitted and naive parameters through its own formula: CIEDE2000 over theta 0-90 deg in "
           "1 deg steps, against the ground truth under the gamut policy %s\n",
           gamut_policy_names[g->gamut]);
    printf("target,fitted_mean,fitted_max,naive_mean,naive_max%s\n", out_of_gamut ? ",fitted_mean_unclipped,fitted_max_unclipped" : "");
    for (i = 0; i < es->sc->target_count; i++) {
        const target_fit *f = &es->fits[i];
        printf("%s,%.4f,%.4f,%.4f,%.4f", target_table[es->sc->targets[i]].name, f->fit_mean, f->fit_max, f->naive_mean,
               f->naive_max);
        if (out_of_gamut) {
            double mean, max;
            target_curve_de(&target_table[es->sc->targets[i]], &ls, (const double(*)[3])raw, f->fitted, &mean, &max);
            printf(",%.4f,%.4f", mean, max);
        }
        printf("\n");
    }
    printf("# each target's parameters: fresnel params ... --for TARGET\n");
    return 0;
}

/* A parameter's row (catalog/parameters.h); one number repeated in r, g, b. */
/* Which rows each scene model's runtime call takes: its shader call
 * (catalog/models.h, the C call of the same name and arguments) with each
 * constant named by its row here. */
#define PARAM_NAMES(field, count, group, constant, name, why, q15, q15_why) {constant, name},
static void print_calls(void)
{
    static const struct {
        const char *constant, *row;
    } names[] = {DERIVED_PARAMETERS(PARAM_NAMES)};
    int i;
    size_t k;
    printf("# the runtime call each scene model makes, with these rows (the _rgb form; the Q1.15 and\n"
           "# binary16 calls take the same rows as `fresnel gen` encodes them):\n");
    for (i = 0; i < MODEL_ROWS; i++) {
        const char *g = model_catalog[i].glsl;
        if (!g || (model_catalog[i].offered & MODEL_FILM))
            continue;
        printf("#   %-16s ", model_catalog[i].name);
        while (*g) {
            if (*g != '@') {
                putchar(*g++);
                continue;
            }
            for (k = 0, g++; k < sizeof names / sizeof names[0]; k++) {
                size_t len = strlen(names[k].constant);
                if (!strncmp(g, names[k].constant, len) && !(g[len] == '_' || (g[len] >= 'a' && g[len] <= 'z'))) {
                    fputs(names[k].row, stdout);
                    g += len;
                    break;
                }
            }
        }
        putchar('\n');
    }
}
#undef PARAM_NAMES

#define PARAM_ROW_3(name, v) row(name, v);
#define PARAM_ROW_1(name, v)                                                                                           \
    {                                                                                                                  \
        const double rgb[3] = {v, v, v};                                                                               \
        row(name, rgb);                                                                                                \
    }
#define PARAM_ROW(field, count, group, constant, name, why, q15, q15_why) PARAM_ROW_##count(name, p.field)

int cmd_params(int argc, char **argv)
{
    material_options o;
    scene *sc = NULL;
    encoded_scene es;
    const gen_context *g;
    const char *val, *for_target = NULL;
    double film_n = 0.0, film_d = 0.0;
    int i, k, status = 0;
    material_options_init(&o);
    for (i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
            const char *names[16];
            int n = target_names(names, 16), k;
            printf("usage: fresnel params (--material ID | --nk FILE [--name ID]) [--space NAME] [--gamut POLICY]\n"
                   "                      [--sigma S] [--n1 X] [--data DIR] [--for TARGET [--film N:D]]\n\n"
                   "Prints, as CSV parameter,r,g,b, every parameter the generator derives for one\n"
                   "material from its spectral ground truth (GT) in a colour space: dominant\n"
                   "wavelengths, F0 (unclipped, and under the --gamut policy), F82, the\n"
                   "hemispherical average F_avg = 2 int F(mu) mu dmu (unclipped, and under the policy),\n"
                   "Metzgar's Gaussian-window eta', kappa', the black-box fitted eta, kappa and\n"
                   "the fit's RMS, LSK a and alpha (on the fitted eta, kappa), Gulbrandsen r and g,\n"
                   "and Cook-Torrance's representative IOR (scalar, repeated in r, g, b). eta and\n"
                   "kappa are relative to the incident medium n1. Lines starting with # describe\n"
                   "the run and name the rows each runtime call takes (fresnel_conductor_rgb: the\n"
                   "fitted eta_fit, kappa_fit for the exact model; eta_gaussian, kappa_gaussian for\n"
                   "exact-gaussian; eta_point, kappa_point for exact-point).\n\n%s"
                   "  --for TARGET    instead, the parameters another renderer's metal takes, fitted\n"
                   "                  through that renderer's own Fresnel formula to the GT under the\n"
                   "                  --gamut policy (mean CIEDE2000 over theta 0-90 deg, inside the\n"
                   "                  renderer's ranges, started from the naive conversion, so the\n"
                   "                  fitted mean is never above the naive one's; the max is not\n"
                   "                  minimised and can be): rows name,r,g,b (a scalar repeated), then\n"
                   "                  # lines with the fit's mean and max dE2000, the naive conversion\n"
                   "                  (F0; an edge parameter from the GT at cos theta = 1/7, or\n"
                   "                  Gulbrandsen's g), its dE2000 and the gain.\n"
                   "                  --for all prints one row per target: target,fitted_mean,\n"
                   "                  fitted_max,naive_mean,naive_max (and the fit against the\n"
                   "                  unclipped GT where the material leaves the gamut).\n"
                   "  --film N:D      with --for TARGET: also that renderer's thin-film inputs, in its\n"
                   "                  names and units, for a film of index N (1..4) and thickness D nm\n"
                   "                  (0..5000) over the metal, for the targets that have them\n"
                   "Targets:         ",
                   material_options_help);
            for (k = 0; k < n; k++)
                printf(" %s", names[k]);
            printf(" all\n");
            return 0;
        }
        if (!cli_in_list(argv[i], option_names))
            return cli_bad_argument(WHERE, argv[i], option_names);
        if (!(val = cli_option_value(WHERE, argc, argv, &i)))
            return CLI_BAD_INPUT;
        if (!strcmp(argv[i - 1], "--for")) {
            if (target_option(val))
                return CLI_BAD_INPUT;
            for_target = val;
        } else if (!strcmp(argv[i - 1], "--film")) {
            if (film_option(WHERE, val, &film_n, &film_d))
                return CLI_BAD_INPUT;
        } else if (material_option(WHERE, argv[i - 1], val, &o) == CLI_BAD_INPUT)
            return CLI_BAD_INPUT;
    }
    if (film_n > 0.0 && (!for_target || !strcmp(for_target, "all")))
        return cli_error(WHERE, "--film needs --for TARGET, one renderer: its thin-film inputs are printed in its "
                                "names and units");
    if (film_n > 0.0 && !target_find(for_target)->film.thickness) {
        char list[128] = "";
        for (k = 0; k < target_count; k++)
            if (target_table[k].film.thickness)
                snprintf(list + strlen(list), sizeof list - strlen(list), " %s", target_table[k].name);
        return cli_error(WHERE, "--film: target %s has no thin-film input this tool knows (those that have:%s)",
                         for_target, list);
    }
    memset(&es, 0, sizeof es);
    if (!(sc = malloc(sizeof *sc))) {
        status = cli_oom(WHERE);
        goto done;
    }
    if ((status = material_options_scene(WHERE, &o, sc)))
        goto done;
    if (for_target)
        for (k = 0; k < target_count; k++)
            if (!strcmp(for_target, "all") || !strcmp(for_target, target_table[k].name))
                sc->targets[sc->target_count++] = (target_id)k;
    if ((status = encode_scene(sc, NULL, WHERE, o.data, &es)))
        goto done;
    g = es.g;
    {
        const material_params p = es.params[0];
        printf("# material %s (%s; %s), measured %.1f-%.1f nm\n", p.info.id, p.info.name, p.info.dataset,
               p.measured_lo, p.measured_hi);
        printf("# space %s, sigma %g nm, n1 %g\n", g->cs.id, p.sigma, p.n1);
        if (for_target) {
            status = print_targets(for_target, &es);
            if (!status && film_n > 0.0)
                status = print_film(target_find(for_target), film_n, film_d, &es);
            goto done;
        }
        print_calls();
        printf("parameter,r,g,b\n");
        row("dominant_nm", p.nm);
        row("f0_unclamped", p.f0_unclamped);
        row("f_avg_unclamped", p.f_avg_unclamped);
        DERIVED_PARAMETERS(PARAM_ROW)
        row("fit_rms", p.fit_rms);
    }
done:
    encoded_scene_free(&es);
    free(sc);
    return status;
}
