/* fresnel extremes: what every model returns in every number type on the
 * extreme and stiff cases of issue 7, against the double reference, as
 * Markdown for README. The properties are asserted by tests/test_extremes.c
 * on the same cases (gen/extremes.h). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "cli.h"
#include "extremes.h"
#include "fresnel.h"
#include "models.h"
#include "reference.h"

const extreme_case extreme_cases[] = {
    {"eta -> 0", 0.01, 0.0, 1.0, "F0 = 0.96"},
    {"eta -> 0, kappa 1", 0.01, 1.0, 1.0, ""},
    {"matched index", 1.0, 0.0, 1.0, "0 at every c, c = 0 included"},
    {"matched, water/water", 1.33, 0.0, 1.33, "eta/n1 = 1 exactly: as above"},
    {"eta ~ n1", 1.0001, 0.0, 1.0, "R = 2.5e-9 at normal incidence"},
    {"eta ~ n1, kappa 1e-6", 1.0001, 1e-6, 1.0, ""},
    {"glass", 1.5, 0.0, 1.0, "F0 = 0.04"},
    {"glass, kappa 1e-6", 1.5, 1e-6, 1.0, "tiny absorption"},
    {"glass in water", 1.5, 0.0, 1.33, "n1 = 1.33"},
    {"diamond", 2.42, 0.0, 1.0, ""},
    {"glass -> air", 1.0, 0.0, 1.5, "TIR below c = 0.745"},
    {"water -> air", 1.0, 0.0, 1.33, "TIR below c = 0.659"},
    {"diamond -> glass", 1.5, 0.0, 2.42, "TIR below c = 0.785"},
    {"eta 100", 100.0, 0.0, 1.0, "edge of the measured range"},
    {"eta 1e4", 1e4, 0.0, 1.0, "outside the measured range"},
    {"gold, red", 0.17, 3.5, 1.0, "kappa >> eta"},
    {"gold, red, in water", 0.17, 3.5, 1.33, ""},
    {"gold, red, from diamond", 0.17, 3.5, 2.42, ""},
    {"kappa 1000", 1.0, 1000.0, 1.0, ""},
    {"kappa 1000, eta 0.17", 0.17, 1000.0, 1.0, "edge of the measured range"},
};
const int extreme_case_count = (int)(sizeof extreme_cases / sizeof extreme_cases[0]);

/* NAN and INFINITY are float constant expressions (C99 7.12). */
const extreme_cos extreme_cosines[] = {
    {"0", 0.0f},
    {"1 LSB", 0x1p-149f},
    {"1e-30", 1e-30f},
    {"1e-8", 1e-8f},
    {"0.5", 0.5f},
    {"1-1e-7", 1.0f - 1e-7f},
    {"1", 1.0f},
    {"-0", -0.0f},
    {"-0.5", -0.5f},
    {"1+1e-5", 1.00001f},
    {"NaN", NAN},
    {"+Inf", INFINITY},
    {"-Inf", -INFINITY},
};
const int extreme_cosine_count = (int)(sizeof extreme_cosines / sizeof extreme_cosines[0]);

const extreme_reflectance extreme_reflectances[] = {
    {"F0 0, F82 0", 0.0f, 0.0f},
    {"F0 1, F82 1", 1.0f, 1.0f},
    {"F0 1.04, F82 1.04 (gold, out of gamut)", 1.04f, 1.04f},
    {"F0 1.04, F82 0.95", 1.04f, 0.95f},
    {"F82 > F0: 0.2, 0.9", 0.2f, 0.9f},
    {"F82 > F0: 0, 1", 0.0f, 1.0f},
    {"F82 << F0: 0.9, 0", 0.9f, 0.0f},
    {"F82 << F0: 0.5, 0", 0.5f, 0.0f},
    {"NaN, NaN", NAN, NAN},
};
const int extreme_reflectance_count = (int)(sizeof extreme_reflectances / sizeof extreme_reflectances[0]);

int extreme_cos_grid(float *c, int max)
{
    int n = 0, i;
    for (i = 0; i < extreme_cosine_count && n < max; i++)
        if (extreme_cosines[i].c >= 0.0f && extreme_cosines[i].c <= 1.0f)
            c[n++] = extreme_cosines[i].c;
    for (i = 1; i < 1024 && n + 2 <= max; i++) {
        c[n++] = (float)(i / 1024.0);
        c[n++] = (float)cos(i / 1024.0 * 1.5707963267948966);
    }
    return n;
}

void extreme_params(const extreme_case *e, model_params *m)
{
    model_derive(e->eta, e->kappa, e->n1, 1.0, 5.0, m);
    model_params_round_f32(m);
}

int extreme_in_measured_domain(const model_params *m)
{
    double eta = ref_clamp(m->eta, FRESNEL_ETA_MIN, FRESNEL_ETA_MAX);
    double kappa = ref_clamp(m->kappa, 0.0, FRESNEL_KAPPA_MAX);
    /* (float)0.01 is just below 0.01, and it is what the bound grid measured. */
    return eta >= (double)0.01f && eta <= 100.0 && kappa <= 1000.0;
}

double extreme_f82_unclamped(double f0, double f82, double c)
{
    double x = 1.0 - c, a;
    f0 = ref_clamp(f0, 0.0, 1.0);
    f82 = ref_clamp(f82, 0.0, 1.0);
    a = (823543.0 / 46656.0) * (f0 - f82) + (49.0 / 6.0) * (1.0 - f0);
    return f0 + (1.0 - f0) * pow(x, 5.0) - a * c * pow(x, 6.0);
}

/* ---- number types: one evaluator each; the table grows a column group per type. */

typedef struct num_type {
    const char *name;
    float (*eval)(const model *m, const model_params *p, float c);
} num_type;

static float eval_f32(const model *m, const model_params *p, float c) { return m->f32(p, c); }

static const num_type types[] = {{"f32", eval_f32}};
static const int type_count = (int)(sizeof types / sizeof types[0]);

#define GRID_MAX 2100

static void extremes_usage(FILE *out)
{
    fprintf(out,
            "usage: fresnel extremes\n\n"
            "Prints Markdown tables of what every model returns, in every number type\n"
            "the runtime has, on extreme and stiff inputs, against the double reference\n"
            "of the same model on the same rounded inputs: cosines 0, subnormal, 1e-8,\n"
            "1 - 1e-7, 1, outside [0, 1], NaN and +-Inf; eta -> 0, matched index, eta ~ n1,\n"
            "total internal reflection, eta 100 and 1e4, kappa 0, 1e-6 and 1000,\n"
            "incident media water, glass, diamond; F0 0, 1 and 1.04, F82 far from F0.\n"
            "tests/test_extremes.c asserts the properties on the same cases.\n");
}

/* "1.2e-07", or with a mark when the documented bound is exceeded or the
 * result is not a number in [0, 1]. */
static void print_err(double err, double bound, int bad)
{
    if (bad)
        printf(" **NaN/range** |");
    else if (err > bound)
        printf(" **%.1e** |", err);
    else
        printf(" %.1e |", err);
}

static void table_cosines(const extreme_case *e)
{
    model_params p;
    int mi, ti, ci;
    extreme_params(e, &p);
    printf("\n#### %s: eta %g, kappa %g, n1 %g (relative eta %.6g, kappa %.6g; F0 %.6g, F82 %.6g)\n\n",
           e->name, e->eta, e->kappa, e->n1, p.eta, p.kappa, p.f0, p.f82);
    printf("| model | type |");
    for (ci = 0; ci < extreme_cosine_count; ci++)
        printf(" c = %s |", extreme_cosines[ci].label);
    printf(" max abs err | bound |\n|---|---|");
    for (ci = 0; ci < extreme_cosine_count + 2; ci++)
        printf("---:|");
    printf("\n");
    for (mi = 0; mi < model_count; mi++) {
        const model *m = &model_table[mi];
        for (ti = 0; ti < type_count; ti++) {
            double worst = 0.0;
            int bad = 0;
            printf("| %s | %s |", m->name, types[ti].name);
            for (ci = 0; ci < extreme_cosine_count; ci++) {
                float c = extreme_cosines[ci].c;
                float got = types[ti].eval(m, &p, c);
                double err = fabs((double)got - m->f64(&p, (double)c));
                bad |= !(got >= 0.0f && got <= 1.0f);
                if (err > worst)
                    worst = err;
                printf(" %.7g |", (double)got);
            }
            print_err(worst, m->bound, bad);
            printf(" %.0e |\n", (double)m->bound);
        }
    }
}

static void table_cases(void)
{
    static float grid[GRID_MAX];
    int n = extreme_cos_grid(grid, GRID_MAX), ei, mi, ti, ci;
    printf("\n### Every case, every model: max |result - reference| over %d cosines\n\n"
           "The cosines are the extremes above inside [0, 1] and points uniform in c and in\n"
           "the angle. Bold: above the documented bound (only asserted where eta/n1 is in\n"
           "[0.01, 100] and kappa/n1 <= 1000, the measured range).\n\n| case | eta | kappa | n1 | type |",
           n);
    for (mi = 0; mi < model_count; mi++)
        printf(" %s |", model_table[mi].name);
    printf("\n|---|---:|---:|---:|---|");
    for (mi = 0; mi < model_count; mi++)
        printf("---:|");
    printf("\n");
    for (ei = 0; ei < extreme_case_count; ei++) {
        const extreme_case *e = &extreme_cases[ei];
        model_params p;
        extreme_params(e, &p);
        for (ti = 0; ti < type_count; ti++) {
            printf("| %s | %g | %g | %g | %s |", e->name, e->eta, e->kappa, e->n1, types[ti].name);
            for (mi = 0; mi < model_count; mi++) {
                const model *m = &model_table[mi];
                double worst = 0.0;
                int bad = 0;
                for (ci = 0; ci < n; ci++) {
                    float got = types[ti].eval(m, &p, grid[ci]);
                    double err = fabs((double)got - m->f64(&p, (double)grid[ci]));
                    bad |= !(got >= 0.0f && got <= 1.0f);
                    if (err > worst)
                        worst = err;
                }
                print_err(worst, m->bound, bad);
            }
            printf("\n");
        }
    }
    printf("| bound | | | | |");
    for (mi = 0; mi < model_count; mi++)
        printf(" %.0e |", (double)model_table[mi].bound);
    printf("\n");
}

static void table_exact(void)
{
    static const float cs[] = {0.0f, 1e-8f, 0.1f, 0.5f, 1.0f};
    const model *m = model_find("exact");
    int ei, ci;
    if (!m)
        return;
    printf("\n### Exact Fresnel (dielectric form when kappa = 0), f32, and the reference\n\n"
           "| case | eta/n1 | kappa/n1 | c = 0 | c = 1e-8 | c = 0.1 | c = 0.5 | c = 1 | note |\n"
           "|---|---:|---:|---:|---:|---:|---:|---:|---|\n");
    for (ei = 0; ei < extreme_case_count; ei++) {
        const extreme_case *e = &extreme_cases[ei];
        model_params p;
        extreme_params(e, &p);
        printf("| %s | %.6g | %.6g |", e->name, p.eta, p.kappa);
        for (ci = 0; ci < (int)(sizeof cs / sizeof cs[0]); ci++)
            printf(" %.7g (%.7g) |", (double)m->f32(&p, cs[ci]), m->f64(&p, (double)cs[ci]));
        printf(" %s |\n", e->note);
    }
}

static void table_reflectances(void)
{
    static const float cs[] = {0.0f, 1.0f / 7.0f, 0.5f, 1.0f};
    int ri, ci, k;
    printf("\n### F0 and F82 at and beyond the ends of [0, 1]\n\n"
           "The runtime clamps F0 and F82 to [0, 1] (so F0 1.04 is evaluated as 1) and the\n"
           "F82 model's result to [0, 1]. 'unclamped range' is the F82 curve's minimum\n"
           "and maximum over c before that last clamp (double).\n\n"
           "| F0, F82 | schlick c = 0 / 0.5 / 1 | f82 c = 0 | c = 1/7 | c = 0.5 | c = 1 | unclamped range | max abs err | bound |\n"
           "|---|---|---:|---:|---:|---:|---|---:|---:|\n");
    for (ri = 0; ri < extreme_reflectance_count; ri++) {
        const extreme_reflectance *x = &extreme_reflectances[ri];
        double lo = 1e300, hi = -1e300, worst = 0.0;
        int bad = 0;
        printf("| %s | %.7g / %.7g / %.7g |", x->name, (double)fresnel_schlick(x->f0, 0.0f),
               (double)fresnel_schlick(x->f0, 0.5f), (double)fresnel_schlick(x->f0, 1.0f));
        for (ci = 0; ci < (int)(sizeof cs / sizeof cs[0]); ci++)
            printf(" %.7g |", (double)fresnel_f82(x->f0, x->f82, cs[ci]));
        for (k = 0; k <= 4096; k++) {
            float c = (float)(k / 4096.0);
            double u = extreme_f82_unclamped(x->f0, x->f82, c);
            float got = fresnel_f82(x->f0, x->f82, c);
            double err = fabs((double)got - ref_f82(x->f0, x->f82, c));
            lo = u < lo ? u : lo;
            hi = u > hi ? u : hi;
            bad |= !(got >= 0.0f && got <= 1.0f);
            worst = err > worst ? err : worst;
        }
        printf(" [%.4g, %.4g]%s |", lo, hi, lo < 0.0 || hi > 1.0 ? " clamped" : "");
        print_err(worst, FRESNEL_BOUND_F82, bad);
        printf(" %.0e |\n", (double)FRESNEL_BOUND_F82);
    }
}

const extreme_reflectance extreme_gulbrandsen[] = {
    {"r 0, g 0", 0.0f, 0.0f},         {"r 0, g 1", 0.0f, 1.0f},
    {"r 0.5, g 0", 0.5f, 0.0f},       {"r 0.5, g 1", 0.5f, 1.0f},
    {"r 0.999, g 1", 0.999f, 1.0f},   {"r 0.9999, g 0", 0.9999f, 0.0f},
    {"r 0.9999, g 1", 0.9999f, 1.0f}, {"r 1.04, g 0.5", 1.04f, 0.5f},
    {"r 1.04, g 1", 1.04f, 1.0f},     {"NaN, NaN", NAN, NAN},
};
const int extreme_gulbrandsen_count = (int)(sizeof extreme_gulbrandsen / sizeof extreme_gulbrandsen[0]);

static void table_gulbrandsen(void)
{
    static const float cs[] = {0.0f, 0.5f, 0.9f, 1.0f};
    int ri, ci, k;
    printf("\n### Gulbrandsen's r and g at the ends of [0, 1]\n\n"
           "r is clamped to [0, %g] before the inverse mapping, g to [0, 1]. The n, k the\n"
           "runtime maps them to, the result (f32), and max abs err over 4097 cosines.\n\n"
           "| r, g | n | k | c = 0 | c = 0.5 | c = 0.9 | c = 1 | max abs err | bound |\n"
           "|---|---:|---:|---:|---:|---:|---:|---:|---:|\n",
           (double)FRESNEL_GULBRANDSEN_R_MAX);
    for (ri = 0; ri < extreme_gulbrandsen_count; ri++) {
        const extreme_reflectance *x = &extreme_gulbrandsen[ri];
        fresnel_nk nk = fresnel_gulbrandsen_nk(x->f0, x->f82);
        double worst = 0.0;
        int bad = 0;
        printf("| %s | %.7g | %.7g |", x->name, (double)nk.n, (double)nk.k);
        for (ci = 0; ci < (int)(sizeof cs / sizeof cs[0]); ci++)
            printf(" %.7g |", (double)fresnel_gulbrandsen(x->f0, x->f82, cs[ci]));
        for (k = 0; k <= 4096; k++) {
            float c = (float)(k / 4096.0), got = fresnel_gulbrandsen(x->f0, x->f82, c);
            double err = fabs((double)got - ref_gulbrandsen(x->f0, x->f82, c));
            bad |= !(got >= 0.0f && got <= 1.0f);
            worst = err > worst ? err : worst;
        }
        print_err(worst, FRESNEL_BOUND_GULBRANDSEN, bad);
        printf(" %.0e |\n", (double)FRESNEL_BOUND_GULBRANDSEN);
    }
}

int cmd_extremes(int argc, char **argv)
{
    int i;
    for (i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
            extremes_usage(stdout);
            return 0;
        }
        return cli_error("fresnel extremes", "unknown argument '%s' (see fresnel extremes --help)", argv[i]);
    }
    printf("## Extreme cases\n\n"
           "Produced by `build/fresnel extremes`; tests/test_extremes.c asserts the properties.\n"
           "Every model in every number type (");
    for (i = 0; i < type_count; i++)
        printf("%s%s", i ? ", " : "", types[i].name);
    printf(") against the double reference of the same\n"
           "model on the same rounded inputs. Parameters (F0, F82, LSK a and alpha,\n"
           "Gulbrandsen r and g) are derived from eta, kappa and n1 by the reference, as\n"
           "`fresnel eval` does. Inputs outside the domain follow fresnel.h: c is clamped\n"
           "to [0, 1], NaN and -Inf give c = 0, +Inf gives c = 1.\n");
    printf("\n### Cosines at and beyond the ends of [0, 1]\n");
    for (i = 0; i < extreme_case_count; i++)
        if (!strcmp(extreme_cases[i].name, "gold, red") || !strcmp(extreme_cases[i].name, "glass") ||
            !strcmp(extreme_cases[i].name, "glass -> air"))
            table_cosines(&extreme_cases[i]);
    table_cases();
    table_exact();
    table_reflectances();
    table_gulbrandsen();
    return 0;
}
