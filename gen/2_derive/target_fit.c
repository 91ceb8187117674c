/* Fitting a renderer's metal parameters to the ground truth (targets.h).
 *
 * The cost is the mean CIEDE2000 over theta = 0..90 degrees: what the
 * report measures and what an artist sees, so it is minimised directly
 * rather than through a reflectance residual. Colour difference couples
 * the channels, the ranges are boxes, and a target's formula may be
 * clamped (kinks), so the search is derivative-free: a compass search with
 * pattern moves (Hooke and Jeeves 1961), every step clamped to the box,
 * started from the naive parameters. It accepts only improvements of the
 * mean, so the fitted mean is never above the naive conversion's. The max
 * is no part of the cost: it can end well above the naive max (chromium for
 * MaterialX in linear sRGB, `fresnel params --material cr --for materialx`;
 * tests/gen/test_renderer_targets.c counts the fits where it does). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "1_spectral/colour_difference.h"
#include "2_derive/targets.h"
#include "common/reference.h"

/* Steps are fractions of each number's range: from 1/64 down to 1e-6,
 * finer than a 16-bit texture resolves. */
#define STEP_START (1.0 / 64.0)
#define STEP_MIN 1e-6

typedef struct fit_ctx {
    const target *t;
    const film_cmfs *cmfs; /* not NULL: the curves are t's film formula */
    const lab_space *ls;
    int curves;            /* 1, or a film's thicknesses */
    int d_at;              /* where x holds the film's thickness */
    double d[TARGET_FILM_CURVES];
    double lab[TARGET_FILM_CURVES][TARGET_ANGLES][3];
    long evaluations;
} fit_ctx;

double target_cos(int i)
{
    return i >= TARGET_ANGLES - 1 ? 0.0 : cos(i * (3.14159265358979323846 / 180.0));
}

/* Mean (and max) CIEDE2000 over every curve's angles: a film's curves are
 * x's with the thickness set to each of c->d. */
static double curve_de(fit_ctx *c, const double *x, double *max)
{
    double sum = 0.0, worst = 0.0, xd[TARGET_MAX_X];
    int i, k;
    c->evaluations++;
    memcpy(xd, x, sizeof xd);
    for (k = 0; k < c->curves; k++) {
        if (c->cmfs)
            xd[c->d_at] = c->d[k];
        for (i = 0; i < TARGET_ANGLES; i++) {
            double rgb[3], lab[3], d;
            if (c->cmfs)
                c->t->film.eval(xd, target_cos(i), c->cmfs, rgb);
            else
                c->t->eval(x, target_cos(i), rgb);
            lab_space_lab(c->ls, rgb, lab);
            d = ciede2000(c->lab[k][i], lab);
            sum += d;
            worst = d > worst ? d : worst;
        }
    }
    if (max)
        *max = worst;
    return sum / (c->curves * TARGET_ANGLES);
}

static void ctx_init(fit_ctx *c, const target *t, const lab_space *ls, const double (*truth)[3])
{
    int i;
    c->t = t;
    c->cmfs = NULL;
    c->ls = ls;
    c->curves = 1;
    c->d_at = 0;
    c->evaluations = 0;
    for (i = 0; truth && i < TARGET_ANGLES; i++)
        lab_space_lab(ls, truth[i], c->lab[0][i]);
}

void target_curve_de(const target *t, const lab_space *ls, const double (*truth)[3], const double *x, double *mean,
                     double *max)
{
    fit_ctx c;
    ctx_init(&c, t, ls, truth);
    *mean = curve_de(&c, x, max);
}

/* The box of each number of x. */
static int box(const target *t, double *lo, double *hi)
{
    int i, ch, n = 0;
    for (i = 0; i < t->param_count; i++)
        for (ch = 0; ch < (t->param[i].scalar ? 1 : 3); ch++, n++) {
            lo[n] = t->param[i].lo;
            hi[n] = t->param[i].hi;
        }
    return n;
}

/* One exploratory sweep around x (value fx): each number moved by +-step
 * of its range, the first improvement kept. Returns the new value. */
static double explore(fit_ctx *c, int n, const double *lo, const double *hi, double step, double *x, double fx)
{
    int k, dir;
    for (k = 0; k < n; k++)
        for (dir = -1; dir <= 1; dir += 2) {
            double keep = x[k], f;
            x[k] = ref_clamp(keep + dir * step * (hi[k] - lo[k]), lo[k], hi[k]);
            if (x[k] == keep)
                continue;
            f = curve_de(c, x, NULL);
            if (f < fx) {
                fx = f;
                break;
            }
            x[k] = keep;
        }
    return fx;
}

static double search(fit_ctx *c, int n, const double *lo, const double *hi, double *x)
{
    double fx = curve_de(c, x, NULL), step = STEP_START;
    while (step >= STEP_MIN) {
        double base[TARGET_MAX_X], f;
        memcpy(base, x, (size_t)n * sizeof *x);
        f = explore(c, n, lo, hi, step, x, fx);
        if (!(f < fx)) {
            step *= 0.5;
            continue;
        }
        fx = f;
        /* Pattern moves: keep going the way the sweep went while it pays. */
        for (;;) {
            double trial[TARGET_MAX_X], ft;
            int k;
            for (k = 0; k < n; k++)
                trial[k] = ref_clamp(2.0 * x[k] - base[k], lo[k], hi[k]);
            ft = explore(c, n, lo, hi, step, trial, curve_de(c, trial, NULL));
            if (!(ft < fx))
                break;
            memcpy(base, x, (size_t)n * sizeof *x);
            memcpy(x, trial, (size_t)n * sizeof *x);
            fx = ft;
        }
    }
    return fx;
}

void target_fit_curve(const target *t, const lab_space *ls, const double (*truth)[3], const target_anchor *a,
                      target_fit *out)
{
    double start[TARGET_MAX_X] = {0};
    t->naive(a, start);
    target_fit_from(t, ls, truth, start, out);
}

static void fit_from(fit_ctx *c, const target *box_of, const double *start, target_fit *out)
{
    double lo[TARGET_MAX_X], hi[TARGET_MAX_X];
    int n = box(box_of, lo, hi);
    memset(out, 0, sizeof *out);
    out->t = c->t;
    memcpy(out->naive, start, (size_t)n * sizeof *start);
    out->naive_mean = curve_de(c, out->naive, &out->naive_max);
    memcpy(out->fitted, out->naive, sizeof out->fitted);
    search(c, n, lo, hi, out->fitted);
    out->fit_mean = curve_de(c, out->fitted, &out->fit_max);
    out->evaluations = c->evaluations;
}

void target_fit_from(const target *t, const lab_space *ls, const double (*truth)[3], const double *start,
                     target_fit *out)
{
    fit_ctx c;
    ctx_init(&c, t, ls, truth);
    fit_from(&c, t, start, out);
}

void target_material_curve(const spectrum *s, const gen_context *g, const material_params *p, int under_policy,
                           double (*truth)[3], target_anchor *a)
{
    int i;
    for (i = 0; i < TARGET_ANGLES; i++)
        if (under_policy)
            ground_truth_gamut(s, g, p, target_cos(i), truth[i]);
        else
            ground_truth(s, &g->cm, &g->cs, p->n1, target_cos(i), truth[i]);
    if (under_policy) {
        memcpy(a->f0, p->f0, sizeof a->f0);
        memcpy(a->f82, p->f82, sizeof a->f82);
    } else {
        ground_truth(s, &g->cm, &g->cs, p->n1, 1.0, a->f0);
        ground_truth(s, &g->cm, &g->cs, p->n1, 1.0 / 7.0, a->f82);
    }
    memcpy(a->eta, p->eta_fit, sizeof a->eta);
}

void target_film_cmfs(const gen_context *g, film_cmfs *k)
{
    double lo = 1.0 / (SPEC_LO_NM + CMF_N - 1), hi = 1.0 / SPEC_LO_NM, sum[3] = {0.0, 0.0, 0.0};
    int j, ch;
    k->nu0 = lo;
    k->dnu = (hi - lo) / (FILM_CMF_SAMPLES - 1);
    for (j = 0; j < FILM_CMF_SAMPLES; j++) {
        double nu = lo + j * k->dnu, at = 1.0 / nu - SPEC_LO_NM, f, xyz[3];
        int i = (int)at;
        i = i < 0 ? 0 : (i > CMF_N - 2 ? CMF_N - 2 : i);
        f = ref_clamp(at - i, 0.0, 1.0);
        xyz[0] = g->cm.xbar[i] + (g->cm.xbar[i + 1] - g->cm.xbar[i]) * f;
        xyz[1] = g->cm.ybar[i] + (g->cm.ybar[i + 1] - g->cm.ybar[i]) * f;
        xyz[2] = g->cm.zbar[i] + (g->cm.zbar[i + 1] - g->cm.zbar[i]) * f;
        for (ch = 0; ch < 3; ch++) {
            /* d lambda = d nu / nu^2; the ends weigh half (trapezoid) */
            double w = (g->cs.xyz_to_rgb[ch][0] * xyz[0] + g->cs.xyz_to_rgb[ch][1] * xyz[1] +
                        g->cs.xyz_to_rgb[ch][2] * xyz[2]) / (nu * nu) * (j == 0 || j == FILM_CMF_SAMPLES - 1 ? 0.5 : 1.0);
            k->w[j][ch] = w;
            sum[ch] += w;
        }
    }
    for (j = 0; j < FILM_CMF_SAMPLES; j++)
        for (ch = 0; ch < 3; ch++)
            k->w[j][ch] /= sum[ch];
}

/* The film's fit: t's metal with two more numbers, the film's index and
 * thickness, the index held in a box of one point and the thickness set to
 * each curve's, so the search moves the metal's alone. */
int target_film_fit(const target *t, const spectrum *s, const gen_context *g, const material_params *p, double n,
                    double d_lo, double d_hi, target_fit *out)
{
    double truth[TARGET_ANGLES][3], start[TARGET_MAX_X] = {0};
    target_anchor a;
    target with_film = *t;
    film_stack stack;
    fit_ctx *c = malloc(sizeof *c);
    film_cmfs *cmfs = malloc(sizeof *cmfs);
    lab_space ls;
    int i, k, ch, m = target_x_count(t);
    if (!c || !cmfs || !t->film.eval || t->param_count + 2 > TARGET_MAX_PARAMS || m + 2 > TARGET_MAX_X) {
        free(c);
        free(cmfs);
        return -1;
    }
    target_film_cmfs(g, cmfs);
    with_film.param[with_film.param_count].name = t->film.ior;
    with_film.param[with_film.param_count].scalar = 1;
    with_film.param[with_film.param_count].lo = with_film.param[with_film.param_count].hi = n;
    with_film.param_count++;
    with_film.param[with_film.param_count].name = t->film.thickness;
    with_film.param[with_film.param_count].scalar = 1;
    with_film.param[with_film.param_count].lo = with_film.param[with_film.param_count].hi = d_hi;
    with_film.param_count++;
    lab_space_init(&ls, &g->cs);
    ctx_init(c, t, &ls, NULL);
    c->cmfs = cmfs;
    c->d_at = m + 1;
    c->curves = d_hi > d_lo ? TARGET_FILM_CURVES : 1;
    stack.n1 = p->n1;
    stack.film = NULL;
    stack.film_n = n;
    stack.substrate = s;
    for (k = 0; k < c->curves; k++) {
        c->d[k] = c->curves > 1 ? d_lo + (d_hi - d_lo) * k / (TARGET_FILM_CURVES - 1) : d_lo;
        for (i = 0; i < TARGET_ANGLES; i++) {
            film_truth(&stack, &g->cm, &g->cs, target_cos(i), c->d[k], truth[i]);
            for (ch = 0; ch < 3; ch++)
                truth[i][ch] = ref_clamp(truth[i][ch], 0.0, 1.0);
            lab_space_lab(&ls, truth[i], c->lab[k][i]);
        }
    }
    memcpy(a.f0, p->f0, sizeof a.f0);
    memcpy(a.f82, p->f82, sizeof a.f82);
    memcpy(a.eta, p->eta_fit, sizeof a.eta);
    t->naive(&a, start);
    start[m] = n;
    start[m + 1] = d_hi;
    fit_from(c, &with_film, start, out);
    free(c);
    free(cmfs);
    return 0;
}
