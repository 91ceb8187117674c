/* The report's measurements are self-consistent: the ground truth
 * against itself is 0 dE, every model's error is finite and >= 0, a model
 * that reproduces the ground truth scores ~0, and the f32 runtime agrees with
 * its own double reference within the documented bounds. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fresnel.h"
#include "harness.h"
#include "report/report.h"

int main(void)
{
    static const char *const models[] = {"schlick", "f82", "exact", "lut32", "lut256", "lut16-residual"};
    gen_context *g = malloc(sizeof *g);
    report_material rm;
    lab_space ls;
    scene_model sm[6];
    double mean, rms, max;
    int m, t, a, ok;
    memset(&rm, 0, sizeof rm);
    rm.s = malloc(sizeof *rm.s);
    if (!g || !rm.s || gen_context_load(data_dir(NULL), "srgb", g) || lab_space_init(&ls, &g->cs) ||
        derive_parameters(g, &(material_source){"cu", NULL, NK_FORMAT_AUTO, 0.0}, 25.0, 1.0, rm.s, &rm.p)) {
        CHECK("report: load copper", 0, "cannot load");
        return harness_exit();
    }
    report_ground_truth(g, &ls, &rm);
    report_curve_de(&ls, (const double(*)[3])rm.gt, (const double(*)[3])rm.gt, &mean, &rms, &max);
    CHECK("report: ground truth against itself is 0 dE2000", mean == 0.0 && rms == 0.0 && max == 0.0, "%g %g %g",
          mean, rms, max);
    CHECK("report: copper is inside the sRGB gamut (no policy costs anything)",
          !rm.out_of_gamut && rm.policy_de_max[GAMUT_MAP] == 0.0 && rm.policy_de_max[GAMUT_CLIP] == 0.0 &&
              rm.policy_de_max[GAMUT_KEEP] == 0.0,
          "%g %g %g", rm.policy_de_max[0], rm.policy_de_max[1], rm.policy_de_max[2]);
    rm.models = sm;
    for (m = 0; m < 6; m++) {
        scene_model_prepare_name(models[m], LUT_GRAZING, rm.s, g, &rm.p, &sm[m]);
        for (t = 0; t < number_types_available; t++) {
            report_cell c;
            char name[96];
            report_measure(&ls, &rm, m, &number_types[t], &c);
            ok = isfinite(c.de_mean) && isfinite(c.de_rms) && isfinite(c.de_max) && c.de_mean >= 0.0 &&
                 c.de_rms >= c.de_mean - 1e-12 && c.de_max >= c.de_rms - 1e-12 && c.vs_ref_max >= 0.0;
            for (a = 0; a < 3; a++)
                ok &= isfinite(c.abs_max[a]) && c.abs_max[a] >= 0.0;
            snprintf(name, sizeof name, "report: %s %s errors finite, >= 0, mean <= RMS <= max", models[m],
                     number_types[t].name);
            CHECK(name, ok, "mean %g rms %g max %g", c.de_mean, c.de_rms, c.de_max);
            if (number_types[t].id == TYPE_F32) {
                snprintf(name, sizeof name, "report: %s f32 agrees with its double reference (%.2g)", models[m],
                         c.vs_ref_max);
                CHECK(name, c.vs_ref_max <= 1e-6, "%g", c.vs_ref_max);
            }
            if (!strcmp(models[m], "lut256") && number_types[t].id == TYPE_F32) {
                CHECK("report: a 256-node table reproduces the ground truth (mean dE < 1e-3)", c.de_mean < 1e-3,
                      "%g", c.de_mean);
            }
        }
    }
    {
        model_rgb q = scene_model_rgb(&sm[0]);
        double ns = report_time(&number_types[0], &q, 1000, 1);
        CHECK("report: the timing harness returns a positive finite time", ns > 0.0 && isfinite(ns), "%g", ns);
    }
    for (m = 0; m < 6; m++) {
        scene_model_free(&sm[m]);
    }
    free(rm.s);
    free(g);
    return harness_exit();
}
