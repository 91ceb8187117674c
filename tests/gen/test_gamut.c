/* The gamut policies (gen/2_derive/derive.h, gamut.c) on the 14 metals of
 * Hoffman's table in linear sRGB and Display-P3: CIEDE2000 over theta =
 * 0..90 in 1 degree steps against the UNCLIPPED spectral ground truth, of
 * the policy's own curve and of the lut16-cubic table fitted to it, through
 * the binary32 runtime and the Q1.15 runtime (uint16_t nodes).
 *   map:  its curve is the nearest in-gamut colour at every node angle:
 *         never further from the truth than the clip at any angle. Gold in
 *         sRGB through lut16-cubic within 0.50 mean / 0.80 max; every
 *         metal's table within 0.01 mean / 0.05 max of its own curve's cost.
 *   keep: the table follows the unclipped truth, above 1 too, within
 *         0.01 mean / 0.05 max in both runtimes.
 *   A material inside the gamut gets the same curve under every policy.
 * The gamut's boundary (gamut_contains, GAMUT_TOLERANCE): in linear
 * Rec.2020 every material's truth at grazing incidence is white a rounding
 * above 1; water, BK7 and four metals there are inside the gamut for the map
 * policy's nodes and the report, with the same curve under every policy,
 * while gold in sRGB (red F0 1.04) is outside; colours a tolerance outside
 * either end are inside, 1e-9 outside is outside; a step of the tolerance is
 * a CIEDE2000 below 1e-8 at black, white and the primaries. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "3_encode/q15_params.h"
#include "fresnel_fixed.h"
#include "harness.h"
#include "report/report.h"
#include "model/encoded_scene.h"

static const char *const metals[] = {"ag", "cu", "au", "commercial_bronze", "brass", "al", "pd",
                                     "ni", "ti", "hg", "pt", "fe", "zn", "cr", NULL};
static const char *const spaces[] = {"srgb", "display-p3", NULL};

typedef struct cost {
    double mean, max;
} cost;

static cost curve_cost(const lab_space *ls, const double (*truth)[3], const double (*v)[3])
{
    cost c;
    double rms;
    report_curve_de(ls, truth, v, &c.mean, &rms, &c.max);
    return c;
}

/* The policy's curve and its lut16-cubic (binary32 and Q15) against truth. */
static int measure(const gen_context *g, const lab_space *ls, const char *id, spectrum *s, material_params *p,
                   double (*truth)[3], cost *policy, cost *f32, cost *q15, double *table_max)
{
    double curve[REPORT_ANGLES][3], v32[REPORT_ANGLES][3], v15[REPORT_ANGLES][3];
    scene_model m;
    int a, k;
    if (derive_parameters(g, &(material_source){id, NULL, NK_FORMAT_AUTO, 0.0}, 25.0, 1.0, s, p) ||
        scene_model_prepare_name("lut16-cubic", LUT_GRAZING, s, g, p, &m))
        return -1;
    *table_max = 0.0;
    for (k = 0; k < 48; k++)
        *table_max = fmax(*table_max, m.lut.nodes[k]);
    for (a = 0; a < REPORT_ANGLES; a++) {
        float rgb[3];
        fresnel_rgb_q15 r = fresnel_lut_cubic_u16_q15_rgb(m.lut.q15, 16, q15_code(report_cos(a)));
        ground_truth(s, &g->cm, &g->cs, 1.0, report_cos(a), truth[a]);
        ground_truth_gamut(s, g, p, report_cos(a), curve[a]);
        scene_model_eval(&m, (float)report_cos(a), rgb);
        for (k = 0; k < 3; k++)
            v32[a][k] = rgb[k];
        v15[a][0] = r.r / 32768.0;
        v15[a][1] = r.g / 32768.0;
        v15[a][2] = r.b / 32768.0;
    }
    scene_model_free(&m);
    *policy = curve_cost(ls, (const double(*)[3])truth, (const double(*)[3])curve);
    *f32 = curve_cost(ls, (const double(*)[3])truth, (const double(*)[3])v32);
    *q15 = curve_cost(ls, (const double(*)[3])truth, (const double(*)[3])v15);
    return 0;
}

/* The boundary of the gamut: rounding is not a colour outside it. */
static void boundary(gen_context *g, spectrum *s)
{
    static const char *const inside[] = {"water", "bk7", "cu", "au", "ag", "al", NULL};
    static const double pts[][3] = {{0, 0, 0}, {1, 1, 1}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0.02, 0.02, 0.02}};
    static const char *const de_spaces[] = {"srgb", "display-p3", "rec2020", "acescg", NULL};
    const double tol = GAMUT_TOLERANCE;
    const double in[][3] = {{1.0 + tol, 0.5, 0.5}, {-tol, 0.5, 1.0}, {0.0, 1.0 + tol / 2.0, -tol / 2.0}},
                 out[][3] = {{1.0 + 1e-9, 0.5, 0.5}, {0.5, -1e-9, 0.5}, {0.5, 0.5, 2.0 * tol + 1.0}};
    double worst_excess = 0.0, worst_de = 0.0;
    int i, k, ch, ok_nodes = 1, ok_same = 1, ok_report = 1, ok_in = 1, ok_out = 1;
    char name[300];
    lab_space ls;
    material_params p;
    for (i = 0; i < 3; i++) {
        ok_in &= gamut_contains(in[i]);
        ok_out &= !gamut_contains(out[i]);
    }
    CHECK("gamut_contains: a colour within GAMUT_TOLERANCE outside 0 or 1 is inside", ok_in, "outside");
    {
        const double nan_rgb[3] = {0.5, nan(""), 0.5};
        ok_out &= !gamut_contains(nan_rgb);
    }
    CHECK("gamut_contains: 1e-9 below 0 or above 1, twice the tolerance above 1, and NaN are outside", ok_out,
          "inside");
    if (gen_context_load(data_dir(NULL), "rec2020", g) || lab_space_init(&ls, &g->cs)) {
        CHECK("load rec2020", 0, "cannot load");
        return;
    }
    for (i = 0; inside[i]; i++) {
        report_material rm;
        double raw[3];
        int a, pi;
        g->gamut = GAMUT_MAP;
        if (derive_parameters(g, &(material_source){inside[i], NULL, NK_FORMAT_AUTO, 0.0}, 25.0, 1.0, s, &p)) {
            CHECK(inside[i], 0, "cannot derive in rec2020");
            return;
        }
        ground_truth(s, &g->cm, &g->cs, 1.0, 0.0, raw);
        for (ch = 0; ch < 3; ch++)
            worst_excess = fmax(worst_excess, raw[ch] - 1.0);
        if (p.gamut_mapped) {
            ok_nodes = 0;
            NOTE("rec2020 %s: the map policy moved a node", inside[i]);
        }
        /* the same curve under map, clip and keep, at every 0.1 degree */
        for (a = 0; a <= 900; a++) {
            double c = a == 900 ? 0.0 : cos(a * 0.1 * 3.14159265358979323846 / 180.0), v[3][3];
            for (pi = 0; pi < 3; pi++) {
                g->gamut = (gamut_policy)pi;
                ground_truth_gamut(s, g, &p, c, v[pi]);
            }
            for (ch = 0; ch < 3; ch++)
                if (v[GAMUT_MAP][ch] != v[GAMUT_CLIP][ch] || v[GAMUT_MAP][ch] != v[GAMUT_KEEP][ch]) {
                    if (ok_same)
                        NOTE("rec2020 %s at theta %.1f: map %.17g, clip %.17g, keep %.17g", inside[i], a * 0.1,
                             v[GAMUT_MAP][ch], v[GAMUT_CLIP][ch], v[GAMUT_KEEP][ch]);
                    ok_same = 0;
                }
        }
        g->gamut = GAMUT_MAP;
        rm.p = p;
        rm.s = s;
        report_ground_truth(g, &ls, &rm);
        if (rm.out_of_gamut) {
            ok_report = 0;
            NOTE("rec2020 %s: the report calls it outside the gamut", inside[i]);
        }
    }
    NOTE("rec2020: the truth at grazing incidence is 1 + %.3g at most (GAMUT_TOLERANCE %g)", worst_excess, tol);
    CHECK("gamut rec2020: white at grazing incidence is within GAMUT_TOLERANCE of 1", worst_excess <= tol,
          "1 + %.3g", worst_excess);
    CHECK("gamut rec2020: the map policy moves no node of water, bk7, cu, au, ag, al", ok_nodes, "see NOTE lines");
    CHECK("gamut rec2020: water, bk7, cu, au, ag, al get the same curve under map, clip and keep (at 1, not above)",
          ok_same, "see NOTE lines");
    CHECK("gamut rec2020: the report calls none of water, bk7, cu, au, ag, al outside the gamut", ok_report,
          "see NOTE lines");
    /* a colour truly outside is still found */
    if (gen_context_load(data_dir(NULL), "srgb", g) || lab_space_init(&ls, &g->cs) ||
        derive_parameters(g, &(material_source){"au", NULL, NK_FORMAT_AUTO, 0.0}, 25.0, 1.0, s, &p)) {
        CHECK("load srgb, au", 0, "cannot derive");
        return;
    }
    {
        report_material rm;
        rm.p = p;
        rm.s = s;
        report_ground_truth(g, &ls, &rm);
        CHECK("gamut srgb: gold is outside (F0, the map policy's nodes, the report)",
              !gamut_contains(p.f0_unclamped) && p.gamut_mapped && rm.out_of_gamut, "red F0 %.4f, mapped %d, report %d",
              p.f0_unclamped[0], p.gamut_mapped, rm.out_of_gamut);
    }
    /* what a step of the tolerance is worth */
    for (k = 0; de_spaces[k]; k++) {
        if (gen_context_load(data_dir(NULL), de_spaces[k], g)) {
            CHECK("load", 0, "%s", de_spaces[k]);
            return;
        }
        for (i = 0; i < (int)(sizeof pts / sizeof pts[0]); i++)
            for (ch = 0; ch < 3; ch++) {
                double b[3];
                memcpy(b, pts[i], sizeof b);
                b[ch] += pts[i][ch] > 0.5 ? -tol : tol;
                worst_de = fmax(worst_de, delta_e2000_rgb(&g->cs, pts[i], b));
            }
    }
    snprintf(name, sizeof name,
             "GAMUT_TOLERANCE in one channel is a CIEDE2000 below 1e-8 at black, white, the primaries and dark grey "
             "(srgb, display-p3, rec2020, acescg: at most %.3g)",
             worst_de);
    CHECK(name, worst_de < 1e-8, "%.3g", worst_de);
}

int main(void)
{
    gen_context *g = malloc(sizeof *g);
    spectrum *s = malloc(sizeof *s);
    int sp, i;
    if (!g || !s) {
        CHECK("allocate", 0, "out of memory");
        return harness_exit();
    }
    for (sp = 0; spaces[sp]; sp++) {
        lab_space ls;
        int out_of_gamut = 0, ok_map_vs_clip = 1, ok_map_table = 1, ok_keep = 1, ok_inside = 1, ok_range = 1;
        double worst_map_excess = 0.0, worst_keep_mean = 0.0, worst_keep_max = 0.0;
        char name[200];
        if (gen_context_load(data_dir(NULL), spaces[sp], g) || lab_space_init(&ls, &g->cs)) {
            CHECK("load colour science", 0, "cannot load %s", spaces[sp]);
            return harness_exit();
        }
        for (i = 0; metals[i]; i++) {
            static double truth[REPORT_ANGLES][3];
            material_params p;
            cost pol[3], f32[3], q15[3];
            double tmax[3];
            int pi, a, ch, outside = 0;
            for (pi = 0; pi < 3; pi++) {
                g->gamut = (gamut_policy)pi;
                if (measure(g, &ls, metals[i], s, &p, truth, &pol[pi], &f32[pi], &q15[pi], &tmax[pi])) {
                    CHECK(metals[i], 0, "cannot derive or prepare lut16-cubic");
                    return harness_exit();
                }
                if (pi == GAMUT_MAP) { /* map: in [0, 1] everywhere, and per angle no worse than the clip */
                    for (a = 0; a <= 900; a++) {
                        double c = a == 900 ? 0.0 : cos(a * 0.1 * 3.14159265358979323846 / 180.0), raw[3], v[3];
                        ground_truth(s, &g->cm, &g->cs, 1.0, c, raw);
                        ground_truth_gamut(s, g, &p, c, v);
                        outside |= !gamut_contains(raw);
                        for (ch = 0; ch < 3; ch++)
                            ok_range &= v[ch] >= 0.0 && v[ch] <= 1.0;
                    }
                }
            }
            g->gamut = GAMUT_MAP;
            if (!outside) {
                ok_inside &= pol[GAMUT_MAP].max == 0.0 && pol[GAMUT_CLIP].max == 0.0 && pol[GAMUT_KEEP].max == 0.0 &&
                             f32[GAMUT_MAP].max == f32[GAMUT_KEEP].max && q15[GAMUT_MAP].max == q15[GAMUT_CLIP].max;
                continue;
            }
            out_of_gamut++;
            NOTE("%s %s: CIEDE2000 mean/max vs the unclipped truth: clip %.3f/%.3f (lut16-cubic %.3f/%.3f), "
                 "map %.3f/%.3f (f32 %.3f/%.3f, q15 %.3f/%.3f), keep lut16-cubic f32 %.4f/%.4f q15 %.4f/%.4f "
                 "(largest node %.4f)",
                 spaces[sp], metals[i], pol[GAMUT_CLIP].mean, pol[GAMUT_CLIP].max, f32[GAMUT_CLIP].mean,
                 f32[GAMUT_CLIP].max, pol[GAMUT_MAP].mean, pol[GAMUT_MAP].max, f32[GAMUT_MAP].mean, f32[GAMUT_MAP].max,
                 q15[GAMUT_MAP].mean, q15[GAMUT_MAP].max, f32[GAMUT_KEEP].mean, f32[GAMUT_KEEP].max,
                 q15[GAMUT_KEEP].mean, q15[GAMUT_KEEP].max, tmax[GAMUT_KEEP]);
            ok_map_vs_clip &= pol[GAMUT_MAP].mean <= pol[GAMUT_CLIP].mean && pol[GAMUT_MAP].max <= pol[GAMUT_CLIP].max;
            for (pi = 0; pi < 2; pi++) {
                const cost *t = pi ? &q15[GAMUT_MAP] : &f32[GAMUT_MAP];
                worst_map_excess = fmax(worst_map_excess, t->mean - pol[GAMUT_MAP].mean);
                ok_map_table &= t->mean <= pol[GAMUT_MAP].mean + 0.01 && t->max <= pol[GAMUT_MAP].max + 0.05;
            }
            worst_keep_mean = fmax(worst_keep_mean, fmax(f32[GAMUT_KEEP].mean, q15[GAMUT_KEEP].mean));
            worst_keep_max = fmax(worst_keep_max, fmax(f32[GAMUT_KEEP].max, q15[GAMUT_KEEP].max));
            ok_keep &= f32[GAMUT_KEEP].mean <= 0.01 && f32[GAMUT_KEEP].max <= 0.05 && q15[GAMUT_KEEP].mean <= 0.01 &&
                       q15[GAMUT_KEEP].max <= 0.05;
            if (!strcmp(metals[i], "au") && !strcmp(spaces[sp], "srgb")) {
                snprintf(name, sizeof name,
                         "gamut map: gold in sRGB through lut16-cubic within 0.50 mean / 0.80 max CIEDE2000 of its "
                         "unclipped truth (f32 %.3f/%.3f, q15 %.3f/%.3f; clip %.3f/%.3f)",
                         f32[GAMUT_MAP].mean, f32[GAMUT_MAP].max, q15[GAMUT_MAP].mean, q15[GAMUT_MAP].max,
                         f32[GAMUT_CLIP].mean, f32[GAMUT_CLIP].max);
                CHECK(name,
                      f32[GAMUT_MAP].mean <= 0.50 && f32[GAMUT_MAP].max <= 0.80 && q15[GAMUT_MAP].mean <= 0.50 &&
                          q15[GAMUT_MAP].max <= 0.80,
                      "over the goal");
                CHECK("gamut: gold leaves the sRGB gamut (its red F0 above 1)", p.f0_unclamped[0] > 1.0, "red %.4f",
                      p.f0_unclamped[0]);
            }
        }
        NOTE("%s: %d of 14 metals leave the gamut somewhere on 0..90 degrees", spaces[sp], out_of_gamut);
        snprintf(name, sizeof name, "gamut %s: map's curve is in [0, 1] at every 0.1 degree", spaces[sp]);
        CHECK(name, ok_range, "a channel outside [0, 1]");
        snprintf(name, sizeof name, "gamut %s: map's curve is no further from the truth than clip's (mean and max)",
                 spaces[sp]);
        CHECK(name, ok_map_vs_clip, "map worse than clip");
        snprintf(name, sizeof name,
                 "gamut %s: map's lut16-cubic within 0.01 mean / 0.05 max of its curve's own cost (worst +%.4f mean)",
                 spaces[sp], worst_map_excess);
        CHECK(name, ok_map_table, "a table far from its curve");
        snprintf(name, sizeof name,
                 "gamut %s: keep's lut16-cubic (f32, q15) within 0.01 mean / 0.05 max of the unclipped truth "
                 "(worst %.4f / %.4f)",
                 spaces[sp], worst_keep_mean, worst_keep_max);
        CHECK(name, ok_keep, "worst %.4f / %.4f", worst_keep_mean, worst_keep_max);
        snprintf(name, sizeof name, "gamut %s: a metal inside the gamut gets the same curve under every policy",
                 spaces[sp]);
        CHECK(name, ok_inside, "curves differ");
    }
    {
        /* The nearest colour to an in-gamut colour is itself; to one outside,
         * it is inside and no further than the clip. */
        lab_space ls;
        double in[3] = {0.3, 0.6, 0.2}, outc[3] = {1.2, 0.5, -0.05}, got[3], clip[3] = {1.0, 0.5, 0.0};
        double lab_in[3], lab_got[3], d, dclip;
        gen_context_load(data_dir(NULL), "srgb", g);
        lab_space_init(&ls, &g->cs);
        d = gamut_nearest(&ls, in, got);
        lab_space_lab(&ls, in, lab_in);
        lab_space_lab(&ls, got, lab_got);
        CHECK("gamut_nearest: an in-gamut colour maps to itself", d < 1e-9 && ciede2000(lab_in, lab_got) < 1e-9,
              "moved by %.3g", d);
        d = gamut_nearest(&ls, outc, got);
        dclip = delta_e2000_rgb(&g->cs, outc, clip);
        CHECK("gamut_nearest: an out-of-gamut colour maps inside, no further than the clip",
              d <= dclip && got[0] >= 0.0 && got[0] <= 1.0 && got[1] >= 0.0 && got[1] <= 1.0 && got[2] >= 0.0 &&
                  got[2] <= 1.0,
              "%.4f vs clip %.4f", d, dclip);
    }
    boundary(g, s);
    free(g);
    free(s);
    return harness_exit();
}
