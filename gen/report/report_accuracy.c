/* Accuracy of each model against the spectral ground truth, in CIEDE2000
 * over theta = 0..90 degrees in 1 degree steps, and against the same model
 * in double precision (which isolates rounding from model error). */
#include <math.h>

#include "report/report.h"

double report_cos(int angle)
{
    return angle >= 90 ? 0.0 : cos(angle * (3.14159265358979323846 / 180.0));
}

void report_curve_de(const lab_space *ls, const double (*gt)[3], const double (*rgb)[3], double *mean,
                     double *rms, double *max)
{
    double sum = 0.0, sum2 = 0.0, worst = 0.0;
    int a;
    for (a = 0; a < REPORT_ANGLES; a++) {
        double l1[3], l2[3], de;
        lab_space_lab(ls, gt[a], l1);
        lab_space_lab(ls, rgb[a], l2);
        de = ciede2000(l1, l2);
        sum += de;
        sum2 += de * de;
        if (de > worst)
            worst = de;
    }
    *mean = sum / REPORT_ANGLES;
    *rms = sqrt(sum2 / REPORT_ANGLES);
    *max = worst;
}

void report_ground_truth(const gen_context *g, const lab_space *ls, report_material *rm)
{
    double rms;
    int a, ch;
    for (a = 0; a < REPORT_ANGLES; a++) {
        ground_truth(rm->s, &g->cm, &g->cs, rm->p.n1, report_cos(a), rm->gt_raw[a]);
        for (ch = 0; ch < 3; ch++)
            rm->gt[a][ch] = rm->gt_raw[a][ch] < 0.0 ? 0.0 : rm->gt_raw[a][ch] > 1.0 ? 1.0 : rm->gt_raw[a][ch];
    }
    report_curve_de(ls, (const double(*)[3])rm->gt_raw, (const double(*)[3])rm->gt, &rm->clamp_de_mean, &rms,
                    &rm->clamp_de_max);
}

void report_measure(const lab_space *ls, const report_material *rm, int model, const report_type *t,
                    report_cell *out)
{
    const scene_model *m = &rm->models[model];
    double rgb[REPORT_ANGLES][3];
    int a, ch;
    out->abs_max[0] = out->abs_max[1] = out->abs_max[2] = 0.0;
    out->vs_ref_max = 0.0;
    for (a = 0; a < REPORT_ANGLES; a++) {
        double ref[3];
        t->eval(rm->prepared[model], report_cos(a), rgb[a]);
        scene_model_eval_ref(m, &rm->p, report_cos(a), ref);
        for (ch = 0; ch < 3; ch++) {
            double e = fabs(rgb[a][ch] - rm->gt[a][ch]), r = fabs(rgb[a][ch] - ref[ch]);
            if (e > out->abs_max[ch])
                out->abs_max[ch] = e;
            if (r > out->vs_ref_max)
                out->vs_ref_max = r;
        }
    }
    report_curve_de(ls, (const double(*)[3])rm->gt, (const double(*)[3])rgb, &out->de_mean, &out->de_rms,
                    &out->de_max);
}
