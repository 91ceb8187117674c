/* The generator's derived parameters and LUT encoding (issue 3, steps 6-7),
 * checked against the ground truth they come from. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "fresnel.h"
#include "generator.h"
#include "harness.h"
#include "reference.h"
#include "scene_eval.h"

static const char *const metals[] = {"ag", "cu", "au", "commercial_bronze", "brass", "al", "pd",
                                     "ni", "ti",  "hg", "pt", "fe", "zn", "cr", "pb", "w", NULL};

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
    for (i = 0; metals[i]; i++) {
        double gt[3], worst_rms = 0.0;
        int ok_f0 = 1, ok_dom = 1;
        char name[96];
        if (derive_parameters(g, metals[i], 25.0, 1.0, s, &p)) {
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
            /* LUT nodes reproduce the ground truth there, through the runtime */
            scene_model m;
            double worst = 0.0;
            int k;
            scene_model_prepare("lut16", LUT_GRAZING, s, g, &p, &m);
            for (k = 0; k < 16; k++) {
                double c = lut_node_cos(LUT_GRAZING, k, 16);
                float v[3];
                ground_truth_clamped(s, g, 1.0, c, gt);
                scene_model_eval(&m, &p, (float)c, v);
                for (ch = 0; ch < 3; ch++)
                    if (fabs(v[ch] - gt[ch]) > worst)
                        worst = fabs(v[ch] - gt[ch]);
            }
            scene_model_free(&m);
            snprintf(name, sizeof name, "%s: lut16 equals the ground truth at its nodes", metals[i]);
            CHECK(name, worst < 1e-6, "max %.3g", worst);
        }
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
        /* Gold's red leaves the sRGB gamut: the policy keeps it visible in
         * params (unclamped) and clamps what the runtime gets. */
        derive_parameters(g, "au", 25.0, 1.0, s, &p);
        CHECK("gold red F0 is out of the sRGB gamut (unclamped > 1) and clamped to 1",
              p.f0_unclamped[0] > 1.0 && p.f0[0] == 1.0, "F0 red %.6g / %.6g", p.f0_unclamped[0], p.f0[0]);
        NOTE("gold F0 in linear sRGB, unclamped: %.4f %.4f %.4f", p.f0_unclamped[0], p.f0_unclamped[1],
             p.f0_unclamped[2]);
    }
    free(g);
    free(s);
    return harness_exit();
}
