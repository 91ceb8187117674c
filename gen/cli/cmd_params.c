/* fresnel params: every parameter the generator derives for one material. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "common/cli.h"
#include "cli/material_options.h"

#define WHERE "fresnel params"

static void row(const char *name, const double v[3])
{
    printf("%s,%.9g,%.9g,%.9g\n", name, v[0], v[1], v[2]);
}

int cmd_params(int argc, char **argv)
{
    material_options o;
    gen_context *g = NULL;
    spectrum *s = NULL;
    material_params p;
    const char *val;
    int i, status = 0;
    material_options_init(&o);
    for (i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
            printf("usage: fresnel params (--material ID | --nk FILE [--name ID]) [--space NAME] [--gamut POLICY]\n"
                   "                      [--sigma S] [--n1 X] [--data DIR]\n\n"
                   "Prints, as CSV parameter,r,g,b, every parameter the generator derives for one\n"
                   "material from its spectral ground truth (GT) in a colour space: dominant\n"
                   "wavelengths, F0 (unclipped, and under the --gamut policy), F82, the\n"
                   "hemispherical average F_avg = 2 int F(mu) mu dmu (unclipped, and under the policy),\n"
                   "Metzgar's Gaussian-window eta', kappa', the black-box fitted eta, kappa and\n"
                   "the fit's RMS, LSK a and alpha (on the fitted eta, kappa), Gulbrandsen r and g,\n"
                   "and Cook-Torrance's representative IOR (scalar, repeated in r, g, b). eta and\n"
                   "kappa are relative to the incident medium n1. Lines starting with # describe\n"
                   "the run.\n\n%s",
                   material_options_help);
            return 0;
        }
        if (!cli_in_list(argv[i], material_option_names))
            return cli_bad_argument(WHERE, argv[i], material_option_names);
        if (!(val = cli_option_value(WHERE, argc, argv, &i)))
            return CLI_BAD_INPUT;
        if (material_option(WHERE, argv[i - 1], val, &o) == CLI_BAD_INPUT)
            return CLI_BAD_INPUT;
    }
    if (!(g = malloc(sizeof *g)) || !(s = malloc(sizeof *s))) {
        status = cli_oom(WHERE);
        goto done;
    }
    if ((status = material_options_derive(WHERE, &o, g, s, &p)))
        goto done;
    {
        double ct_eta[3] = {p.ct_eta, p.ct_eta, p.ct_eta}, ct_kappa[3] = {p.ct_kappa, p.ct_kappa, p.ct_kappa};
        printf("# material %s (%s; %s), measured %.1f-%.1f nm\n", p.info.id, p.info.name, p.info.dataset,
               p.measured_lo, p.measured_hi);
        printf("# space %s, sigma %g nm, n1 %g\n", g->cs.id, p.sigma, p.n1);
        printf("parameter,r,g,b\n");
        row("dominant_nm", p.nm);
        row("f0_unclamped", p.f0_unclamped);
        row("f0", p.f0);
        row("f82", p.f82);
        row("f_avg_unclamped", p.f_avg_unclamped);
        row("f_avg", p.f_avg);
        row("eta_gaussian", p.eta_gauss);
        row("kappa_gaussian", p.kappa_gauss);
        row("eta_point", p.eta_point);
        row("kappa_point", p.kappa_point);
        row("eta_fit", p.eta_fit);
        row("kappa_fit", p.kappa_fit);
        row("fit_rms", p.fit_rms);
        row("lsk_a", p.lsk_a);
        row("lsk_alpha", p.lsk_alpha);
        row("gulbrandsen_r", p.gulb_r);
        row("gulbrandsen_g", p.gulb_g);
        row("cook_torrance_eta", ct_eta);
        row("cook_torrance_kappa", ct_kappa);
    }
done:
    free(g);
    free(s);
    return status;
}
