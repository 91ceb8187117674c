/* The generator's derived parameters and LUT encoding,
 * checked against the ground truth they come from. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "fresnel.h"
#include "3_encode/encode.h"
#include "harness.h"
#include "common/reference.h"
#include "model/encoded_scene.h"

static const char *const metals[] = {"ag", "cu", "au", "commercial_bronze", "brass", "al", "pd",
                                     "ni", "ti",  "hg", "pt", "fe", "zn", "cr", "pb", "w", NULL};

/* The LUT encoding is a least-squares fit through the runtime's
 * interpolation (gen/3_encode/encode_lut.c). Recomputed here independently: the
 * squared error over theta every 0.05 degrees and the nodes, in double at
 * the double node values. */
#define FIT_STEPS 1800

static double sq_error(const double *t, int n, int cubic, const double (*gt)[3], const double *cs, int count)
{
    double e = 0.0;
    int k, ch;
    for (k = 0; k < count; k++)
        for (ch = 0; ch < 3; ch++) {
            double d = ref_lut(t + ch * n, n, cubic, sqrt(cs[k])) - gt[k][ch];
            e += d * d;
        }
    return e;
}

static void check_lut_fit(const char *id, const spectrum *s, const gen_context *g, const material_params *p)
{
    enum { N = 16, COUNT = FIT_STEPS + 1 + N };
    static double gt[COUNT][3], cs[COUNT];
    int k, form;
    for (k = 0; k < COUNT; k++) {
        cs[k] = k < FIT_STEPS ? cos(k * 1.57079632679489661923 / FIT_STEPS)
                              : (k == FIT_STEPS ? 0.0 : lut_node_cos(LUT_GRAZING, k - FIT_STEPS - 1, N));
        ground_truth_gamut(s, g, p, cs[k], gt[k]);
    }
    for (form = 0; form < 2; form++) {
        const char *model = form ? "lut16-cubic" : "lut16";
        double sampled[3 * N], e_fit, e_sampled, e_best_neighbour = HUGE_VAL;
        int ch;
        char name[128];
        scene_model m;
        if (scene_model_prepare_name(model, LUT_GRAZING, s, g, p, &m)) {
            CHECK(model, 0, "prepare failed");
            return;
        }
        for (k = 0; k < N; k++) {
            double v[3];
            ground_truth_gamut(s, g, p, lut_node_cos(LUT_GRAZING, k, N), v);
            for (ch = 0; ch < 3; ch++)
                sampled[ch * N + k] = v[ch];
        }
        e_fit = sq_error(m.lut.nodes, N, form, (const double(*)[3])gt, cs, COUNT);
        e_sampled = sq_error(sampled, N, form, (const double(*)[3])gt, cs, COUNT);
        /* a minimum: moving any one node either way, within [0, 1], costs */
        for (k = 0; k < 3 * N; k++) {
            int sign;
            for (sign = -1; sign <= 1; sign += 2) {
                double e;
                if (m.lut.nodes[k] + sign * 1e-3 < 0.0 || m.lut.nodes[k] + sign * 1e-3 > 1.0)
                    continue; /* held at a bound: a constrained minimum */
                m.lut.nodes[k] += sign * 1e-3;
                e = sq_error(m.lut.nodes, N, form, (const double(*)[3])gt, cs, COUNT);
                m.lut.nodes[k] -= sign * 1e-3;
                if (e < e_best_neighbour)
                    e_best_neighbour = e;
            }
        }
        scene_model_free(&m);
        snprintf(name, sizeof name, "%s %s: fitted nodes beat nodes on the curve (%.3g vs %.3g) and are a minimum",
                 id, model, e_fit, e_sampled);
        CHECK(name, e_fit < e_sampled && e_fit < e_best_neighbour, "fit %.6g, sampled %.6g, best neighbour %.6g",
              e_fit, e_sampled, e_best_neighbour);
    }
}

int main(void)
{
    gen_context *g = malloc(sizeof *g);
    spectrum *s = malloc(sizeof *s);
    material_params p;
    int i, ch;
    if (!g || !s || gen_context_load(data_dir(NULL), "srgb", g)) {
        CHECK("load colour science", 0, "cannot load data");
        return harness_exit();
    }
    /* The checks below are of the clip policy (per-channel clamp), whose
     * result is known in closed form; tests/gen/test_gamut.c checks map and keep. */
    g->gamut = GAMUT_CLIP;
    for (i = 0; metals[i]; i++) {
        double gt[3], worst_rms = 0.0;
        int ok_f0 = 1, ok_dom = 1;
        char name[96];
        if (derive_parameters(g, &(material_source){metals[i], NULL, NK_FORMAT_AUTO, 0.0}, 25.0, 1.0, s, &p)) {
            CHECK(metals[i], 0, "derive_parameters failed");
            continue;
        }
        ground_truth(s, &g->cm, &g->cs, 1.0, 1.0, gt);
        for (ch = 0; ch < 3; ch++) {
            ok_f0 &= p.f0_unclamped[ch] == gt[ch] && p.f0[ch] == ref_clamp(gt[ch], 0.0, 1.0);
            ok_dom &= p.eta_fit[ch] > 0.0 && p.kappa_fit[ch] >= 0.0 && p.lsk_a[ch] >= 0.0 &&
                      p.gulb_g[ch] >= 0.0 && p.gulb_g[ch] <= 1.0 && p.f82[ch] >= 0.0 && p.f82[ch] <= 1.0;
            if (p.fit_rms[ch] > worst_rms)
                worst_rms = p.fit_rms[ch];
        }
        ground_truth(s, &g->cm, &g->cs, 1.0, 1.0 / 7.0, gt);
        for (ch = 0; ch < 3; ch++)
            ok_f0 &= p.f82[ch] == ref_clamp(gt[ch], 0.0, 1.0);
        snprintf(name, sizeof name, "%s: F0 = GT(0 deg) clamped, F82 = GT(arccos 1/7)", metals[i]);
        CHECK(name, ok_f0, "F0/F82 differ from the ground truth");
        snprintf(name, sizeof name, "%s: derived parameters in their domains", metals[i]);
        CHECK(name, ok_dom, "a parameter is out of its domain");
        /* The fit is to the clamped GT; gold's red is clipped at 1, which no
         * exact curve follows exactly, hence its larger residual. */
        snprintf(name, sizeof name, "%s: fitted eta, kappa follow the ground truth (RMS %.2g)", metals[i], worst_rms);
        CHECK(name, worst_rms < 0.01, "fit RMS %.3g", worst_rms);
        {
            /* F_avg: the Gauss rule at 64 panels against itself at 256 and
             * against Simpson's rule on 2000 intervals of the same curve. */
            double fine[3], simpson[3] = {0.0, 0.0, 0.0}, worst_gauss = 0.0, worst_simpson = 0.0;
            int k;
            ground_truth_average(s, g, &p, 1, 256, fine);
            for (k = 0; k <= 2000; k++) {
                double mu = k / 2000.0, w = (k == 0 || k == 2000) ? 1.0 : (k % 2 ? 4.0 : 2.0);
                ground_truth_gamut(s, g, &p, mu, gt);
                for (ch = 0; ch < 3; ch++)
                    simpson[ch] += 2.0 * w * gt[ch] * mu / (3.0 * 2000.0);
            }
            for (ch = 0; ch < 3; ch++) {
                worst_gauss = fmax(worst_gauss, fabs(p.f_avg[ch] - fine[ch]));
                worst_simpson = fmax(worst_simpson, fabs(p.f_avg[ch] - simpson[ch]));
            }
            snprintf(name, sizeof name, "%s: F_avg converged (64 vs 256 Gauss panels %.1e, vs Simpson 2000 %.1e)",
                     metals[i], worst_gauss, worst_simpson);
            CHECK(name, worst_gauss < 1e-7 && worst_simpson < 1e-6, "F_avg %.6g %.6g %.6g", p.f_avg[0], p.f_avg[1],
                  p.f_avg[2]);
        }
        if (i == 1 || i == 13) /* copper, chromium: the LUT fit (below) */
            check_lut_fit(metals[i], s, g, &p);
    }
    {
        int ok = 1, k;
        for (k = 1; k < 32; k++)
            ok &= lut_node_cos(LUT_GRAZING, k, 32) > lut_node_cos(LUT_GRAZING, k - 1, 32) &&
                  lut_node_cos(LUT_UNIFORM, k, 32) > lut_node_cos(LUT_UNIFORM, k - 1, 32);
        ok &= lut_node_cos(LUT_GRAZING, 0, 32) == 0.0 && lut_node_cos(LUT_GRAZING, 31, 32) == 1.0;
        /* the runtime's index mapping and the generator's node positions agree */
        for (k = 0; k < 32; k++) {
            float c = (float)lut_node_cos(LUT_GRAZING, k, 32), t[32];
            int j;
            for (j = 0; j < 32; j++)
                t[j] = (float)j / 31.0f; /* results are clamped to [0, 1] */
            ok &= fabs(fresnel_lut(t, 32, c) * 31.0f - k) < 1e-3;
        }
        CHECK("LUT nodes: increasing from c = 0 to 1; runtime index matches generator nodes", ok, "mismatch");
    }
    {
        /* the root-free warps: node i sits where the position is i/(n-1) */
        static const lut_spacing warps[] = {LUT_GRAZING, LUT_WARP2, LUT_WARP16};
        double worst = 0.0;
        int ok = 1, k, w;
        for (w = 0; w < 3; w++)
            for (k = 0; k < 16; k++) {
                double c = lut_node_cos(warps[w], k, 16);
                worst = fmax(worst, fabs(lut_position(warps[w], c) * 15.0 - k));
                ok &= c >= 0.0 && c <= 1.0 && (k == 0 || c > lut_node_cos(warps[w], k - 1, 16));
            }
        ok &= lut_node_cos(LUT_WARP16, 0, 16) == 0.0 && lut_node_cos(LUT_WARP16, 15, 16) == 1.0;
        CHECK("LUT warps c(2-c), (1+c-(1-c)^16)/2: nodes increasing from 0 to 1, each at its position", ok && worst < 1e-12,
              "position off by %.3g nodes", worst);
    }
    {
        /* Gold's red leaves the sRGB gamut: the policy keeps it visible in
         * params (unclamped) and clamps what the runtime gets. */
        derive_parameters(g, &(material_source){"au", NULL, NK_FORMAT_AUTO, 0.0}, 25.0, 1.0, s, &p);
        CHECK("gold red F0 is out of the sRGB gamut (unclamped > 1) and clamped to 1",
              p.f0_unclamped[0] > 1.0 && p.f0[0] == 1.0, "F0 red %.6g / %.6g", p.f0_unclamped[0], p.f0[0]);
        NOTE("gold F0 in linear sRGB, unclamped: %.4f %.4f %.4f", p.f0_unclamped[0], p.f0_unclamped[1],
             p.f0_unclamped[2]);
    }
    free(g);
    free(s);
    return harness_exit();
}
