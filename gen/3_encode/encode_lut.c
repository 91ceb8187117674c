/* Stage 3, encode: the LUT tables the runtime interpolates (include/fresnel.h,
 * src/f32/lut.c). The node values are not the curve sampled at the nodes: they
 * are the least-squares fit, through the runtime's own interpolation, of the
 * ground truth (under the gamut policy) at every 0.05 degrees from 0 to 90 (the report
 * measures every degree). Sampling at the nodes puts all of the error between
 * them; the fit spreads it, and for 16 nodes on Hoffman's metals it lowers
 * the worst max CIEDE2000 by about a third (linear) and lets a Catmull-Rom
 * cubic reach 0.02 (`fresnel report`, the LUT section). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fresnel_q15_fast.h"
#include "3_encode/encode.h"
#include "common/reference.h"

#define FIT_STEPS 1800 /* samples at theta = k 90/FIT_STEPS degrees */

static const double half_pi = 1.57079632679489661923;

/* The runtime's position P(c) for LUT_GRAZING_PL in double: the knots of
 * fresnel_lut_pl_knots_q15 (fresnel_q15_fast.h), linear between them. */
static double pl_position(double c)
{
    double u = c * 64.0;
    int k = (int)u;
    if (k > 63)
        k = 63;
    return (fresnel_lut_pl_knots_q15[k] + (fresnel_lut_pl_knots_q15[k + 1] - fresnel_lut_pl_knots_q15[k]) * (u - k)) / 32768.0;
}

static double warp16(double c)
{
    double m = 1.0 - c, m2 = m * m, m4 = m2 * m2, m8 = m4 * m4;
    return 0.5 * (1.0 + c - m8 * m8);
}

double lut_position(lut_spacing spacing, double c)
{
    switch (spacing) {
    case LUT_UNIFORM: return c;
    case LUT_GRAZING_PL: return pl_position(c);
    case LUT_WARP2: return c * (2.0 - c);
    case LUT_WARP16: return warp16(c);
    default: return sqrt(c);
    }
}

double lut_node_cos(lut_spacing spacing, int i, int n)
{
    double w = (double)i / (n - 1), y = w * 32768.0, lo = 0.0, hi = 1.0;
    int k = 0;
    if (spacing == LUT_WARP2)
        return 1.0 - sqrt(1.0 - w);
    if (spacing == LUT_WARP16) { /* increasing: bisection to the last bit */
        for (k = 0; k < 64; k++) {
            double mid = 0.5 * (lo + hi);
            if (warp16(mid) < w)
                lo = mid;
            else
                hi = mid;
        }
        return i == n - 1 ? 1.0 : lo;
    }
    if (spacing != LUT_GRAZING_PL)
        return spacing == LUT_UNIFORM ? w : w * w; /* grazing: uniform in sqrt(c) */
    if (i == n - 1)
        return 1.0;
    while (k < 63 && fresnel_lut_pl_knots_q15[k + 1] <= y)
        k++;
    return (k + (y - fresnel_lut_pl_knots_q15[k]) / (fresnel_lut_pl_knots_q15[k + 1] - fresnel_lut_pl_knots_q15[k])) / 64.0;
}

/* The runtime's interpolation as weights on (at most) four nodes: idx[k]
 * gets weight w[k]. Linear uses two; Catmull-Rom four, the outer ones
 * clamped to the table's ends (src/f32/lut.c). */
static void lut_weights(lut_spacing spacing, lut_form form, int n, double c, int idx[4], double w[4])
{
    double pos = lut_position(spacing, c) * (n - 1), t;
    int j = (int)pos, k;
    if (j >= n - 1)
        j = n - 2;
    t = pos - j;
    for (k = 0; k < 4; k++) {
        int q = j - 1 + k;
        idx[k] = q < 0 ? 0 : (q > n - 1 ? n - 1 : q);
    }
    if (form == LUT_CUBIC) {
        w[0] = 0.5 * t * (-1.0 + t * (2.0 - t));
        w[1] = 1.0 + t * t * (-2.5 + 1.5 * t);
        w[2] = 0.5 * t * (1.0 + t * (4.0 - 3.0 * t));
        w[3] = 0.5 * t * t * (t - 1.0);
    } else {
        w[0] = w[3] = 0.0;
        w[1] = 1.0 - t;
        w[2] = t;
    }
}

/* Solve the symmetric positive definite a x = b (n x n, row-major) in place
 * by Cholesky; b becomes x. */
static void solve_spd(double *a, double *b, int n)
{
    int i, j, k;
    for (j = 0; j < n; j++) {
        double d = a[j * n + j];
        for (k = 0; k < j; k++)
            d -= a[j * n + k] * a[j * n + k];
        d = sqrt(d > 0.0 ? d : 1e-300);
        a[j * n + j] = d;
        for (i = j + 1; i < n; i++) {
            double s = a[i * n + j];
            for (k = 0; k < j; k++)
                s -= a[i * n + k] * a[j * n + k];
            a[i * n + j] = s / d;
        }
    }
    for (i = 0; i < n; i++) {
        for (k = 0; k < i; k++)
            b[i] -= a[i * n + k] * b[k];
        b[i] /= a[i * n + i];
    }
    for (i = n - 1; i >= 0; i--) {
        for (k = i + 1; k < n; k++)
            b[i] -= a[k * n + i] * b[k];
        b[i] /= a[i * n + i];
    }
}

/* One sample of the fit: its weights and the three channels' targets. */
typedef struct fit_sample {
    int idx[4];
    double w[4], y[3];
} fit_sample;

/* truth: the ground truth at c when already known, else NULL. */
static void sample_at(const spectrum *s, const gen_context *g, const material_params *p, lut_spacing spacing,
                      lut_form form, int n, double c, const double *truth, fit_sample *out)
{
    int ch;
    if (truth)
        memcpy(out->y, truth, sizeof out->y);
    else
        ground_truth_gamut(s, g, p, c, out->y);
    for (ch = 0; ch < 3; ch++)
        if (form == LUT_RESIDUAL)
            out->y[ch] -= ref_schlick(p->f0[ch], c);
    lut_weights(spacing, form, n, c, out->idx, out->w);
}

/* The ground truth on the theta grid is the same for every table of one
 * material (every size, form and spacing): the last one is kept, keyed by
 * the full content it depends on (spectrum, colorimetry, colour space, n1),
 * so that a scene with many LUT models integrates each material's spectrum
 * once per angle instead of once per model. */
static struct {
    int valid;
    spectrum s;
    colorimetry cm;
    colour_space cs;
    double n1;
    gamut_policy gamut;
    double y[FIT_STEPS + 1][3];
} gt_cache;

static const double *grid_truth(const spectrum *s, const gen_context *g, const material_params *p, int k)
{
    if (k == 0 && !(gt_cache.valid && gt_cache.n1 == p->n1 && gt_cache.gamut == g->gamut &&
                    !memcmp(&gt_cache.s, s, sizeof *s) &&
                    !memcmp(&gt_cache.cm, &g->cm, sizeof g->cm) && !memcmp(&gt_cache.cs, &g->cs, sizeof g->cs))) {
        int j;
        gt_cache.valid = 0;
        for (j = 0; j <= FIT_STEPS; j++)
            ground_truth_gamut(s, g, p, j == FIT_STEPS ? 0.0 : cos(j * half_pi / FIT_STEPS), gt_cache.y[j]);
        gt_cache.s = *s;
        gt_cache.cm = g->cm;
        gt_cache.cs = g->cs;
        gt_cache.n1 = p->n1;
        gt_cache.gamut = g->gamut;
        gt_cache.valid = 1;
    }
    return gt_cache.y[k];
}

int encode_lut(const spectrum *s, const gen_context *g, const material_params *p, lut_spacing spacing, int n,
               lut_form form, double *table)
{
    /* The theta grid, plus every node itself, so that each node has a
     * sample of its own however many nodes crowd between two angles. */
    int count = FIT_STEPS + 1 + n, k, ch, a, b;
    fit_sample *sm = malloc((size_t)count * sizeof *sm);
    double *ata = malloc((size_t)n * n * sizeof *ata), *atb = malloc((size_t)n * sizeof *atb);
    double *fixed = malloc((size_t)n * sizeof *fixed); /* held node values */
    char *held = malloc((size_t)n);
    if (!sm || !ata || !atb || !fixed || !held) {
        free(sm);
        free(ata);
        free(atb);
        free(fixed);
        free(held);
        return -1;
    }
    for (k = 0; k <= FIT_STEPS; k++) {
        double c = k == FIT_STEPS ? 0.0 : cos(k * half_pi / FIT_STEPS);
        const double *y = grid_truth(s, g, p, k);
        sample_at(s, g, p, spacing, form, n, c, y, &sm[k]);
    }
    for (k = 0; k < n; k++)
        sample_at(s, g, p, spacing, form, n, lut_node_cos(spacing, k, n), NULL, &sm[FIT_STEPS + 1 + k]);
    for (ch = 0; ch < 3; ch++) {
        /* A curve's nodes must stay reflectances: the fit overshoots 1 at
         * grazing incidence for some metals. Nodes that leave [0, 1] are
         * held at the bound and the rest refitted, until none leaves. Under
         * the keep policy the top is the curve's own maximum where that is
         * above 1 (at most ENCODE_LUT_KEEP_MAX, the most a Q15 node holds),
         * so that a material inside the gamut gets the same table under
         * every policy. A
         * residual is a difference of two reflectances, in [-1, 1], but its
         * fit overshoots that at a total-reflection edge (water under
         * n1 = 1.5); its nodes are held to [-1, 1], the range the Q15
         * residual encodings of fresnel_q15.h hold. */
        int nheld = 0, again = 1;
        double hi = 1.0;
        if (form != LUT_RESIDUAL && g->gamut == GAMUT_KEEP)
            for (k = 0; k < count; k++)
                hi = fmin(fmax(hi, sm[k].y[ch]), ENCODE_LUT_KEEP_MAX);
        for (k = 0; k < n; k++)
            held[k] = 0;
        while (again) {
            for (k = 0; k < n * n; k++)
                ata[k] = 0.0;
            for (k = 0; k < n; k++) {
                atb[k] = held[k] ? fixed[k] : 0.0;
                if (held[k])
                    ata[k * n + k] = 1.0;
            }
            for (k = 0; k < count; k++) {
                double y = sm[k].y[ch];
                for (b = 0; b < 4; b++)
                    if (held[sm[k].idx[b]])
                        y -= sm[k].w[b] * fixed[sm[k].idx[b]];
                for (a = 0; a < 4; a++) {
                    if (held[sm[k].idx[a]])
                        continue;
                    atb[sm[k].idx[a]] += sm[k].w[a] * y;
                    for (b = 0; b < 4; b++)
                        if (!held[sm[k].idx[b]])
                            ata[sm[k].idx[a] * n + sm[k].idx[b]] += sm[k].w[a] * sm[k].w[b];
                }
            }
            solve_spd(ata, atb, n);
            again = 0;
            for (k = 0; k < n && nheld < n; k++) {
                double lo = form == LUT_RESIDUAL ? -1.0 : 0.0;
                if (!held[k] && (atb[k] < lo || atb[k] > hi)) {
                    fixed[k] = atb[k] < lo ? lo : hi;
                    held[k] = 1;
                    nheld++;
                    again = 1;
                }
            }
        }
        for (k = 0; k < n; k++)
            table[ch * n + k] = atb[k];
    }
    free(sm);
    free(ata);
    free(atb);
    free(fixed);
    free(held);
    return 0;
}
