/* The report's plots: the Pareto front of error against time, the Gaussian
 * window sweep, and per-material curves with colour strips as in Hoffman's
 * talk. Written with gen/report/svg.c; deterministic for identical measurements. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "common/cli.h"
#include "report/report.h"
#include "report/svg.h"

static const char *const channel_colour[3] = {"#c0392b", "#27ae60", "#2e5fd8"};

static int end_file(svg_doc *d)
{
    svg_end(d); /* a write error stays in the stream's error flag, which the commit checks */
    return 0;
}

static int write_pareto(report_run *r)
{
    FILE *f;
    svg_doc d;
    svg_panel p;
    svg_axis xa = {0.1, 1000.0, SVG_LOG10, 0.0, "ns per RGB evaluation (this host)", NULL};
    svg_axis ya = {1e-4, 100.0, SVG_LOG10, 0.0, "mean CIEDE2000 over the metals (log)", NULL};
    int n = r->sc.model_count * number_types_available, k, j, front[256], nf = 0, measured = 0;
    if (!(f = report_out_open(r, "pareto.svg", &k)))
        return k;
    svg_begin(&d, f, 900, 620, "Fresnel models: error against run time");
    if (svg_panel_begin(&p, &d, 0, 0, 900, 620, &xa, &ya, "Error against run time; Pareto front in black") == 0) {
        for (k = 0; k < n && k < 256; k++) {
            double mean, worst, mj, wj;
            int m = k / number_types_available, t = k % number_types_available, dominated = 0;
            char label[64];
            if (isnan(r->ns[k]))
                continue;
            report_metal_summary(r, m, t, &mean, &worst);
            if (isnan(mean)) /* no metals in the scene: no error to plot */
                continue;
            measured++;
            snprintf(label, sizeof label, "%s %s", r->sc.models[m].name, number_types[t].name);
            svg_point(&p, r->ns[k], mean, SVG_CIRCLE, 6, svg_palette(m), label, SVG_LABEL_RIGHT);
            for (j = 0; j < n && !dominated; j++) {
                if (j == k || isnan(r->ns[j]))
                    continue;
                report_metal_summary(r, j / number_types_available, j % number_types_available, &mj, &wj);
                dominated = r->ns[j] <= r->ns[k] && mj <= mean && (r->ns[j] < r->ns[k] || mj < mean);
            }
            if (!dominated)
                front[nf++] = k;
        }
        if (nf > 1) {
            double x[256], y[256], w;
            int a, b;
            for (a = 0; a < nf; a++) /* by cost */
                for (b = a + 1; b < nf; b++)
                    if (r->ns[front[b]] < r->ns[front[a]]) {
                        int tmp = front[a];
                        front[a] = front[b];
                        front[b] = tmp;
                    }
            for (a = 0; a < nf; a++) {
                x[a] = r->ns[front[a]];
                report_metal_summary(r, front[a] / number_types_available, front[a] % number_types_available, &y[a], &w);
            }
            {
                svg_style s = {"black", 1.5, NULL};
                svg_polyline(&p, x, y, nf, &s);
            }
        }
        if (!measured)
            svg_text(&d, 450, 300, 16, SVG_MIDDLE, "black", "timings not measured (--no-timing)");
    }
    return end_file(&d);
}

static int write_sigma(report_run *r, const double (*de)[REPORT_SIGMAS])
{
    FILE *f;
    svg_doc d;
    svg_panel p;
    svg_legend l;
    svg_axis xa = {0.0, 50.0, SVG_LINEAR, 12.5, "Gaussian window sigma (nm); 0 = point sampling", NULL};
    svg_axis ya = {1e-3, 30.0, SVG_LOG10, 0.0, "mean CIEDE2000 against the ground truth", NULL};
    int i, k;
    if (!(f = report_out_open(r, "sigma.svg", &k)))
        return k;
    svg_begin(&d, f, 900, 560, "Exact Fresnel on Gaussian-window eta', kappa'");
    if (svg_panel_begin(&p, &d, 0, 0, 700, 560, &xa, &ya, "Metzgar's window width against error") == 0) {
        svg_legend_begin(&l, &d, 710, 40);
        for (i = 0; i < r->sc.material_count; i++) {
            double x[REPORT_SIGMAS], y[REPORT_SIGMAS];
            svg_style s;
            s.colour = svg_palette(i);
            s.width = 1.5;
            s.dash = svg_dash(i / 8);
            for (k = 0; k < REPORT_SIGMAS; k++) {
                x[k] = report_sigmas[k];
                y[k] = de[i][k];
            }
            svg_polyline(&p, x, y, REPORT_SIGMAS, &s);
            for (k = 0; k < REPORT_SIGMAS; k++)
                svg_point(&p, x[k], y[k], SVG_CIRCLE, 4, s.colour, NULL, SVG_LABEL_RIGHT);
            svg_legend_entry(&l, &s, SVG_CIRCLE, NULL, r->mats[i].p.info.id);
        }
    }
    return end_file(&d);
}

/* One material: a row per model with the full range, a zoom on 70-90
 * degrees, and colour strips of the ground truth and the model. */
#define CURVE_N 181  /* 0.5 degree steps */
#define ZOOM_N 201   /* 0.1 degree steps over 70-90 */

static int write_curves(report_run *r, int mi)
{
    report_material *rm = &r->mats[mi];
    FILE *f;
    svg_doc d;
    char name[128], title[256];
    const double row_h = 230.0;
    double th[CURVE_N], gt[CURVE_N][3], zt[ZOOM_N], zgt[ZOOM_N][3];
    int m, a, ch, status;
    snprintf(name, sizeof name, "curves/%s.svg", rm->p.info.id);
    if (!(f = report_out_open(r, name, &status)))
        return status;
    snprintf(title, sizeof title, "%s (%s) in %s: ground truth (dashed) and each model (solid)", rm->p.info.name,
             rm->p.info.id, r->sc.space);
    svg_begin(&d, f, 960, 40 + row_h * r->sc.model_count, title);
    svg_text(&d, 10, 24, 16, SVG_START, "black", title);
    for (a = 0; a < CURVE_N; a++) {
        th[a] = a * 0.5;
        ground_truth_gamut(rm->s, r->g, &rm->p, a == CURVE_N - 1 ? 0.0 : cos(th[a] * 3.14159265358979323846 / 180.0),
                             gt[a]);
    }
    for (a = 0; a < ZOOM_N; a++) {
        zt[a] = 70.0 + a * 0.1;
        ground_truth_gamut(rm->s, r->g, &rm->p,
                             a == ZOOM_N - 1 ? 0.0 : cos(zt[a] * 3.14159265358979323846 / 180.0), zgt[a]);
    }
    for (m = 0; m < r->sc.model_count; m++) {
        double y0 = 40 + row_h * m, mv[CURVE_N][3], zv[ZOOM_N][3], y1[ZOOM_N], x2[ZOOM_N], y2[ZOOM_N];
        svg_axis xa = {0.0, 90.0, SVG_LINEAR, 15.0, "theta (deg)", NULL};
        svg_axis za = {70.0, 90.0, SVG_LINEAR, 5.0, "theta (deg)", NULL};
        svg_axis ya = {0.0, 1.0, SVG_LINEAR, 0.25, "reflectance", NULL};
        svg_panel p;
        char ptitle[96];
        model_rgb q = scene_model_rgb(&rm->models[m]);
        for (a = 0; a < CURVE_N; a++)
            number_types[0].eval(&q, a == CURVE_N - 1 ? 0.0 : cos(th[a] * 3.14159265358979323846 / 180.0),
                                 mv[a]);
        for (a = 0; a < ZOOM_N; a++)
            number_types[0].eval(&q, a == ZOOM_N - 1 ? 0.0 : cos(zt[a] * 3.14159265358979323846 / 180.0),
                                 zv[a]);
        snprintf(ptitle, sizeof ptitle, "%s (mean dE2000 %.3f)", r->sc.models[m].name,
                 report_cell_at(r, mi, m, 0)->de_mean);
        if (svg_panel_begin(&p, &d, 0, y0, 420, row_h - 40, &xa, &ya, ptitle) == 0)
            for (ch = 0; ch < 3; ch++) {
                svg_style dashed = {channel_colour[ch], 1.2, "5 3"}, solid = {channel_colour[ch], 1.6, NULL};
                {
                    double xs[CURVE_N], g1[CURVE_N], v1[CURVE_N];
                    for (a = 0; a < CURVE_N; a++) {
                        xs[a] = th[a];
                        g1[a] = gt[a][ch];
                        v1[a] = mv[a][ch];
                    }
                    svg_polyline(&p, xs, g1, CURVE_N, &dashed);
                    svg_polyline(&p, xs, v1, CURVE_N, &solid);
                }
            }
        {
            double lo = 1.0;
            svg_axis zy;
            for (a = 0; a < ZOOM_N; a++)
                for (ch = 0; ch < 3; ch++) {
                    if (zgt[a][ch] < lo)
                        lo = zgt[a][ch];
                    if (zv[a][ch] < lo)
                        lo = zv[a][ch];
                }
            zy.lo = floor(lo * 10.0) / 10.0;
            zy.hi = 1.0;
            zy.scale = SVG_LINEAR;
            zy.tick = 0.0;
            zy.label = NULL;
            zy.format = NULL;
            if (zy.lo >= 1.0)
                zy.lo = 0.9;
            if (svg_panel_begin(&p, &d, 420, y0, 300, row_h - 40, &za, &zy, "zoom: 70-90 deg") == 0)
                for (ch = 0; ch < 3; ch++) {
                    svg_style dashed = {channel_colour[ch], 1.2, "5 3"}, solid = {channel_colour[ch], 1.6, NULL};
                    for (a = 0; a < ZOOM_N; a++) {
                        x2[a] = zt[a];
                        y1[a] = zgt[a][ch];
                        y2[a] = zv[a][ch];
                    }
                    svg_polyline(&p, x2, y1, ZOOM_N, &dashed);
                    svg_polyline(&p, x2, y2, ZOOM_N, &solid);
                }
        }
        svg_text(&d, 735, y0 + 40, 11, SVG_START, "black", "ground truth, 0 -> 90 deg");
        svg_strip(&d, 735, y0 + 46, 215, 22, (const double(*)[3])gt, CURVE_N);
        svg_text(&d, 735, y0 + 86, 11, SVG_START, "black", r->sc.models[m].name);
        svg_strip(&d, 735, y0 + 92, 215, 22, (const double(*)[3])mv, CURVE_N);
        svg_text(&d, 735, y0 + 132, 11, SVG_START, "black", "80 -> 90 deg: ground truth, model");
        svg_strip(&d, 735, y0 + 138, 215, 14, (const double(*)[3])(zgt + 100), ZOOM_N - 100);
        svg_strip(&d, 735, y0 + 154, 215, 14, (const double(*)[3])(zv + 100), ZOOM_N - 100);
    }
    return end_file(&d);
}

int report_plots(report_run *r, const double (*sigma_de)[REPORT_SIGMAS])
{
    int i, status;
    if ((status = write_pareto(r)) || (status = write_sigma(r, sigma_de)))
        return status;
    for (i = 0; i < r->sc.material_count; i++)
        if ((status = write_curves(r, i)))
            return status;
    return 0;
}
