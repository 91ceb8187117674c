/* Stage 2, derive: the parameters each model needs, derived from the spectral ground
 * truth [Hof20 "Computing RGB Parameter Values From Spectral IOR Data"] and
 * from Metzgar's Gaussian window [MS18]. */
#include <math.h>
#include <string.h>

#include "common/cli.h"
#include "1_spectral/colour_difference.h"
#include "2_derive/fit.h"
#include "2_derive/derive.h"
#include "common/reference.h"

int gen_context_load(const char *dir, const char *space, gen_context *g)
{
    g->dir = dir;
    if (colorimetry_load(dir, &g->cm) || colour_space_load(dir, space, &g->cm, &g->cs))
        return CLI_BAD_INPUT;
    dominant_wavelengths(&g->cm, &g->cs, g->nm);
    g->gamut = GAMUT_MAP;
    return 0;
}

/* The five-point Gauss-Legendre rule on [-1, 1]. */
static const double gl5_node[5] = {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831,
                                   0.9061798459386640};
static const double gl5_weight[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889,
                                     0.4786286704993665, 0.2369268850561891};

void hemispherical_average(void (*curve)(const void *ctx, double mu, double rgb[3]), const void *ctx, int panels,
                           double avg[3])
{
    int i, j, ch;
    for (ch = 0; ch < 3; ch++)
        avg[ch] = 0.0;
    for (i = 0; i < panels; i++)
        for (j = 0; j < 5; j++) {
            double mu = (i + 0.5 + 0.5 * gl5_node[j]) / panels, rgb[3];
            curve(ctx, mu, rgb);
            for (ch = 0; ch < 3; ch++)
                avg[ch] += gl5_weight[j] * rgb[ch] * mu / panels; /* 2 x (1/2 per panel width) */
        }
}

typedef struct truth_curve {
    const spectrum *s;
    const gen_context *g;
    const material_params *p;
    int under_policy;
} truth_curve;

static void truth_at(const void *ctx, double mu, double rgb[3])
{
    const truth_curve *t = ctx;
    if (t->under_policy)
        ground_truth_gamut(t->s, t->g, t->p, mu, rgb);
    else
        ground_truth(t->s, &t->g->cm, &t->g->cs, t->p->n1, mu, rgb);
}

void ground_truth_average(const spectrum *s, const gen_context *g, const material_params *p, int under_policy,
                          int panels, double avg[3])
{
    /* The unclipped integrand F(mu) mu is smooth on [0, 1] and the rule
     * converges to rounding at 16 panels; where a policy cuts a channel at
     * 1 (gold's red in sRGB under clip) the kink leaves an O(h^2) error,
     * 4e-9 at 64 panels (test_derive_encode measures both against 256 panels
     * and Simpson). */
    truth_curve t;
    t.s = s;
    t.g = g;
    t.p = p;
    t.under_policy = under_policy;
    hemispherical_average(truth_at, &t, panels, avg);
}

int derive_parameters(const gen_context *g, const material_source *m, double sigma, double n1, spectrum *s,
                      material_params *p)
{
    double cosines[GEN_FIT_ANGLES], target[3][GEN_FIT_ANGLES], weight[3][GEN_FIT_ANGLES], rgb[3], green[3], eta[3],
        kappa[3];
    lab_space ls;
    int i, ch;
    memset(p, 0, sizeof *p);
    if (material_load(g->dir, m, &p->info, s))
        return CLI_BAD_INPUT;
    p->measured_lo = s->measured_lo;
    p->measured_hi = s->measured_hi;
    p->n1 = n1;
    p->sigma = sigma;
    p->film_n = m->film_n;
    memcpy(p->nm, g->nm, sizeof p->nm);

    gamut_map_build(s, g, p);
    ground_truth(s, &g->cm, &g->cs, n1, 1.0, p->f0_unclamped);
    ground_truth_gamut(s, g, p, 1.0, p->f0);
    ground_truth_gamut(s, g, p, 1.0 / 7.0, p->f82);
    ground_truth_average(s, g, p, 1, GEN_AVG_PANELS, p->f_avg);
    ground_truth_average(s, g, p, 0, GEN_AVG_PANELS, p->f_avg_unclamped);

    gaussian_window(s, g->nm, sigma, eta, kappa);
    for (ch = 0; ch < 3; ch++) {
        p->eta_gauss[ch] = eta[ch] / n1;
        p->kappa_gauss[ch] = kappa[ch] / n1;
    }
    /* Hoffman's representative IOR is one sampled wavelength; green's
     * dominant wavelength is where the eye is most sensitive. */
    gaussian_window(s, g->nm, 0.0, eta, kappa);
    for (ch = 0; ch < 3; ch++) {
        p->eta_point[ch] = eta[ch] / n1;
        p->kappa_point[ch] = kappa[ch] / n1;
    }
    p->ct_eta = eta[1] / n1;
    p->ct_kappa = kappa[1] / n1;

    /* The fit minimises colour error, not reflectance error: each sample's
     * residual is weighted by how much CIEDE2000 one unit of reflectance in
     * that channel costs there (dark curves and blue are cheap in
     * reflectance and dear in dE). Hoffman's table measures RMS dE. */
    lab_space_init(&ls, &g->cs);
    for (i = 0; i < GEN_FIT_ANGLES; i++) {
        cosines[i] = cos(i * (3.14159265358979323846 / 180.0));
        ground_truth_gamut(s, g, p, cosines[i], rgb);
        for (ch = 0; ch < 3; ch++) {
            double moved[3], lab0[3], lab1[3], h = rgb[ch] > 0.5 ? -1e-4 : 1e-4;
            memcpy(moved, rgb, sizeof moved);
            moved[ch] += h;
            lab_space_lab(&ls, rgb, lab0);
            lab_space_lab(&ls, moved, lab1);
            target[ch][i] = rgb[ch];
            weight[ch][i] = fmax(ciede2000(lab0, lab1) / 1e-4, 1e-3);
        }
    }
    ground_truth_gamut(s, g, p, 0.15, green); /* LSK's matching point */
    for (ch = 0; ch < 3; ch++) {
        fit_report rep;
        if (fit_eta_kappa_weighted(cosines, target[ch], weight[ch], GEN_FIT_ANGLES, &p->eta_fit[ch],
                                   &p->kappa_fit[ch], &rep))
            return cli_error(m->id, "fitting eta, kappa to the ground truth failed");
        p->fit_rms[ch] = rep.rms;
        ref_lsk_fit_target(p->eta_fit[ch], p->kappa_fit[ch], green[ch], &p->lsk_a[ch], &p->lsk_alpha[ch]);
        p->gulb_r[ch] = fmin(p->f0[ch], 1.0); /* a reflectivity: below 1 under the keep policy too */
        p->gulb_g[ch] = ref_gulbrandsen_g(p->f0[ch], p->eta_fit[ch]);
    }
    return 0;
}

material_source scene_material(const scene *sc, int i)
{
    material_source m;
    m.id = sc->materials[i];
    m.path = sc->material_file[i][0] ? sc->material_file[i] : NULL;
    m.format = sc->material_format[i];
    m.film_n = scene_film_n(sc, i);
    return m;
}
