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
    double curve[REPORT_ANGLES][3], rms;
    gen_context other = *g;
    material_params mapped = rm->p;
    int a, pol;
    rm->out_of_gamut = 0;
    for (a = 0; a < REPORT_ANGLES; a++) {
        ground_truth(rm->s, &g->cm, &g->cs, rm->p.n1, report_cos(a), rm->gt_raw[a]);
        ground_truth_gamut(rm->s, g, &rm->p, report_cos(a), rm->gt[a]);
        rm->out_of_gamut |= !gamut_contains(rm->gt_raw[a]);
    }
    /* Every policy's own cost, whichever the scene uses (map needs its nodes). */
    other.gamut = GAMUT_MAP;
    gamut_map_build(rm->s, &other, &mapped);
    for (pol = 0; pol < 3; pol++) {
        other.gamut = (gamut_policy)pol;
        for (a = 0; a < REPORT_ANGLES; a++)
            ground_truth_gamut(rm->s, &other, &mapped, report_cos(a), curve[a]);
        report_curve_de(ls, (const double(*)[3])rm->gt_raw, (const double(*)[3])curve, &rm->policy_de_mean[pol], &rms,
                        &rm->policy_de_max[pol]);
    }
}

typedef struct model_curve {
    const model_rgb *q;
    const number_type *t;
} model_curve;

static void model_at(const void *ctx, double mu, double rgb[3])
{
    const model_curve *m = ctx;
    m->t->eval(m->q, mu, rgb);
}

void report_measure(const lab_space *ls, const report_material *rm, int model, const number_type *t,
                    report_cell *out)
{
    const scene_model *m = &rm->models[model];
    model_rgb q = scene_model_rgb(m);
    double rgb[REPORT_ANGLES][3], rms;
    int a, ch;
    out->abs_max[0] = out->abs_max[1] = out->abs_max[2] = 0.0;
    out->vs_ref_max = 0.0;
    for (a = 0; a < REPORT_ANGLES; a++) {
        double ref[3];
        t->eval(&q, report_cos(a), rgb[a]);
        scene_model_eval_ref(m, report_cos(a), ref);
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
    report_curve_de(ls, (const double(*)[3])rm->gt_raw, (const double(*)[3])rgb, &out->raw_de_mean, &rms,
                    &out->raw_de_max);
    {
        /* the model's F_avg in this type, by the rule the ground truth's uses */
        model_curve mc;
        mc.q = &q;
        mc.t = t;
        hemispherical_average(model_at, &mc, GEN_AVG_PANELS, out->avg);
    }
}
