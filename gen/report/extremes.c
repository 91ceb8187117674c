/* The extreme and stiff cases: what every model returns in every number type
 * on them, against the double reference, as the Markdown `fresnel extremes`
 * prints. The properties are asserted by tests/runtime/every_type/test_extremes.c
 * on the same cases (gen/report/extremes.h). */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "report/extremes.h"
#include "fresnel.h"
#include "fresnel_f16.h"
#include "fresnel_q15.h"
#include "model/registry.h"
#include "common/reference.h"

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
    {"0", 0.0f, 0},
    {"1 LSB", 0x1p-149f, 1},
    {"1e-30", 1e-30f, 0},
    {"1e-8", 1e-8f, 0},
    {"0.5", 0.5f, 0},
    {"1-1e-7", 1.0f - 1e-7f, 0},
    {"1", 1.0f, 0},
    {"-0", -0.0f, 0},
    {"-0.5", -0.5f, 0},
    {"1+1e-5", 1.00001f, 0},
    {"NaN", NAN, 0},
    {"+Inf", INFINITY, 0},
    {"-Inf", -INFINITY, 0},
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
    /* The bound grid's 0.01 and 100 are themselves rounded to each type. */
    return eta >= 0.01 * (1.0 - 1e-3) && eta <= 100.0 * (1.0 + 1e-3) && kappa <= 1000.0 * (1.0 + 1e-3);
}

double extreme_f82_unclamped(double f0, double f82, double c)
{
    double x = 1.0 - c, a;
    f0 = ref_clamp(f0, 0.0, 1.0);
    f82 = ref_clamp(f82, 0.0, 1.0);
    a = ref_f82_a(f0, f82);
    return f0 + (1.0 - f0) * pow(x, 5.0) - a * c * pow(x, 6.0);
}

/* ---- number types: every table has a row (or column) per available type
 * of the registry, whose rows say how each type clamps, takes a cosine and
 * evaluates (model/number_type.h). */

const extreme_type extreme_types[] = {
    {&number_types[TYPE_F32]},
    {&number_types[TYPE_Q15]},
#if FRESNEL_HAS_F16
    {&number_types[TYPE_F16]},
#endif
};
const int extreme_type_count = (int)(sizeof extreme_types / sizeof extreme_types[0]);

/* The parameters are rounded to the type and clamped where its runtime
 * clamps them (model_params_round_q15: the fixed-point formats, as
 * tests/runtime/q15/test_q15_bounds.c does); eta and kappa outside a type's
 * domain mark the case out of domain. */
void extreme_prepare(const extreme_type *ty, const extreme_case *e, extreme_typed *t)
{
    int inside;
    memset(t, 0, sizeof *t);
    model_derive(e->eta, e->kappa, e->n1, 1.0, 5.0, &t->p);
    ty->type->round(&t->p);
    model_q15_from_params(&t->p, &t->q);
    inside = ty->type->clamp(&t->p);
    t->in_domain = inside && extreme_in_measured_domain(&t->p);
}

int extreme_eval(const extreme_type *ty, const model *m, const extreme_typed *t, double x, double *got, double *ref_c)
{
    if (!ty->type->cosine(x, ref_c))
        return 0;
    *got = ty->type->at(m, &t->p, &t->q, *ref_c);
    return 1;
}

double extreme_cos_input(const extreme_type *ty, const extreme_cos *x)
{
    return x->lsb ? ty->type->lsb : (double)x->c;
}

#define GRID_MAX 2100

static void print_err(double err, double bound, int bad, int in_domain)
{
    if (bad)
        printf(" **NaN/range** |");
    else if (err > bound && in_domain)
        printf(" **%.1e** |", err);
    else
        printf(" %.1e%s |", err, in_domain ? "" : " \xe2\x80\xa0");
}

static void table_cosines(const extreme_case *e)
{
    int mi, ti, ci;
    extreme_typed t;
    extreme_params(e, &t.p);
    printf("\n#### %s: eta %g, kappa %g, n1 %g (relative eta %.6g, kappa %.6g; F0 %.6g, F82 %.6g)\n\n",
           e->name, e->eta, e->kappa, e->n1, t.p.eta, t.p.kappa, t.p.f0, t.p.f82);
    printf("| model | type |");
    for (ci = 0; ci < extreme_cosine_count; ci++)
        printf(" c = %s |", extreme_cosines[ci].label);
    printf(" max abs err | bound |\n|---|---|");
    for (ci = 0; ci < extreme_cosine_count + 2; ci++)
        printf("---:|");
    printf("\n");
    for (mi = 0; mi < model_count; mi++) {
        const model *m = &model_table[mi];
        for (ti = 0; ti < extreme_type_count; ti++) {
            const extreme_type *ty = &extreme_types[ti];
            double worst = 0.0;
            int bad = 0;
            if (!ty->type->has(m))
                continue;
            extreme_prepare(ty, e, &t);
            printf("| %s | %s |", m->name, ty->type->name);
            for (ci = 0; ci < extreme_cosine_count; ci++) {
                double got, ref_c, err;
                if (!extreme_eval(ty, m, &t, extreme_cos_input(ty, &extreme_cosines[ci]), &got, &ref_c)) {
                    printf(" n/a |");
                    continue;
                }
                err = fabs(got - m->ref->scalar(&t.p, ref_c));
                bad |= !(got >= 0.0 && got <= 1.0);
                if (err > worst)
                    worst = err;
                printf(" %.7g |", got);
            }
            print_err(worst, ty->type->bound(m), bad, t.in_domain);
            printf(" %.1e |\n", ty->type->bound(m));
        }
    }
}

/* Max |result - reference| of one model, type and case over the cosine grid;
 * *bad set for a result that is not a number in [0, 1]. */
double extreme_max_err(const model *m, const extreme_type *ty, const extreme_typed *t, int *bad)
{
    static float grid[GRID_MAX];
    static int n;
    double worst = 0.0;
    int ci;
    if (!n)
        n = extreme_cos_grid(grid, GRID_MAX);
    *bad = 0;
    for (ci = 0; ci < n; ci++) {
        double got, ref_c, err;
        if (!extreme_eval(ty, m, t, grid[ci], &got, &ref_c))
            continue;
        err = fabs(got - m->ref->scalar(&t->p, ref_c));
        *bad |= !(got >= 0.0 && got <= 1.0);
        if (!(err <= worst))
            worst = err;
    }
    return worst;
}

static void table_cases(void)
{
    static float grid[GRID_MAX];
    int n = extreme_cos_grid(grid, GRID_MAX), ei, mi, ti;
    printf("\n### Every case, every model: max |result - reference| over %d cosines\n\n"
           "The cosines are the extremes above inside [0, 1] and points uniform in c and in\n"
           "the angle (for q15 rounded to codes, for f16 to binary16). Bold: above the\n"
           "documented bound of that model and type where it applies (eta/n1 in\n"
           "[0.01, 100], kappa/n1 <= 1000, the range the bounds were measured on; for f16\n"
           "also inside the binary16 domain eta <= %g, kappa <= %g). \xe2\x80\xa0: outside that range,\n"
           "not asserted (f16: compared at the clamped eta, kappa the runtime evaluates).\n\n"
           "| case | eta | kappa | n1 | type |",
           n, (double)FRESNEL_ETA_MAX_F16, (double)FRESNEL_KAPPA_MAX_F16);
    for (mi = 0; mi < model_count; mi++)
        if (model_table[mi].offered & MODEL_EVAL)
            printf(" %s |", model_table[mi].name);
    printf("\n|---|---:|---:|---:|---|");
    for (mi = 0; mi < model_count; mi++)
        if (model_table[mi].offered & MODEL_EVAL)
            printf("---:|");
    printf("\n");
    for (ei = 0; ei < extreme_case_count; ei++) {
        const extreme_case *e = &extreme_cases[ei];
        for (ti = 0; ti < extreme_type_count; ti++) {
            const extreme_type *ty = &extreme_types[ti];
            extreme_typed t;
            extreme_prepare(ty, e, &t);
            printf("| %s | %g | %g | %g | %s |", e->name, e->eta, e->kappa, e->n1, ty->type->name);
            for (mi = 0; mi < model_count; mi++) {
                const model *m = &model_table[mi];
                int bad;
                double worst;
                if (!(m->offered & MODEL_EVAL))
                    continue;
                if (!ty->type->has(m)) {
                    printf(" |");
                    continue;
                }
                worst = extreme_max_err(m, ty, &t, &bad);
                print_err(worst, ty->type->bound(m), bad, t.in_domain);
            }
            printf("\n");
        }
    }
    for (ti = 0; ti < extreme_type_count; ti++) {
        printf("| bound | | | | %s |", extreme_types[ti].type->name);
        for (mi = 0; mi < model_count; mi++)
            if (model_table[mi].offered & MODEL_EVAL)
                printf(" %.1e |",
                       extreme_types[ti].type->has(&model_table[mi]) ? extreme_types[ti].type->bound(&model_table[mi]) : 0.0);
        printf("\n");
    }
}

static void table_exact(void)
{
    static const float cs[] = {0.0f, 1e-8f, 0.1f, 0.5f, 1.0f};
    const model *m = model_exact;
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
            printf(" %.7g (%.7g) |", (double)m->f32->scalar(&p, cs[ci]), m->ref->scalar(&p, (double)cs[ci]));
        printf(" %s |\n", e->note);
    }
}

/* The F82 model and Gulbrandsen called directly with reflectance-like
 * parameters, in each type: f32 as given, Q15 as raw codes round(x 32768)
 * (so 1.04 is code 34079, clamped by the runtime), binary16 rounded. NaN has
 * no Q15 code. */
double extreme_direct_max_err(int kind, int ti, float a0, float b0, int *bad, int *na)
{
    const number_type *ty = extreme_types[ti].type;
    double worst = 0.0;
    int k;
    *bad = 0;
    *na = 0;
    for (k = 0; k <= 4096; k++) {
        float a = a0, b = b0, c = (float)(k / 4096.0);
        double got, err;
        if (!ty->direct(kind, &a, &b, &c, &got)) {
            *na = 1;
            return 0.0;
        }
        err = fabs(got - ty->direct_ref(kind, a, b, c));
        *bad |= !(got >= 0.0 && got <= 1.0);
        worst = err > worst ? err : worst;
    }
    return worst;
}

double extreme_direct_bound(int kind, int ti)
{
    const model *m = kind ? model_gulbrandsen : model_f82;
    return extreme_types[ti].type->bound(m);
}

static void print_direct_errs(int kind, float a, float b)
{
    int ti;
    for (ti = 0; ti < extreme_type_count; ti++) {
        int bad, na;
        double worst = extreme_direct_max_err(kind, ti, a, b, &bad, &na);
        if (na)
            printf(" n/a |");
        else
            print_err(worst, extreme_direct_bound(kind, ti), bad, 1);
    }
}

static void table_reflectances(void)
{
    static const float cs[] = {0.0f, 1.0f / 7.0f, 0.5f, 1.0f};
    int ri, ci, k, ti;
    printf("\n### F0 and F82 at and beyond the ends of [0, 1]\n\n"
           "The runtime clamps F0 and F82 to [0, 1] (so F0 1.04 is evaluated as 1) and the\n"
           "F82 model's result to [0, 1]. 'unclamped range' is the F82 curve's minimum\n"
           "and maximum over c before that last clamp (double). Values are f32; the\n"
           "errors are max |result - reference| over 4097 cosines in each type (q15: raw\n"
           "codes, so 1.04 is code 34079; NaN has no code).\n\n"
           "| F0, F82 | schlick c = 0 / 0.5 / 1 | f82 c = 0 | c = 1/7 | c = 0.5 | c = 1 | unclamped range |");
    for (ti = 0; ti < extreme_type_count; ti++)
        printf(" err %s |", extreme_types[ti].type->name);
    printf("\n|---|---|---:|---:|---:|---:|---|");
    for (ti = 0; ti < extreme_type_count; ti++)
        printf("---:|");
    printf("\n");
    for (ri = 0; ri < extreme_reflectance_count; ri++) {
        const extreme_reflectance *x = &extreme_reflectances[ri];
        double lo = 1e300, hi = -1e300;
        printf("| %s | %.7g / %.7g / %.7g |", x->name, (double)fresnel_schlick(x->f0, 0.0f),
               (double)fresnel_schlick(x->f0, 0.5f), (double)fresnel_schlick(x->f0, 1.0f));
        for (ci = 0; ci < (int)(sizeof cs / sizeof cs[0]); ci++)
            printf(" %.7g |", (double)fresnel_f82(x->f0, x->f82, cs[ci]));
        for (k = 0; k <= 4096; k++) {
            double u = extreme_f82_unclamped(x->f0, x->f82, k / 4096.0);
            lo = u < lo ? u : lo;
            hi = u > hi ? u : hi;
        }
        printf(" [%.4g, %.4g]%s |", lo, hi, lo < 0.0 || hi > 1.0 ? " clamped" : "");
        print_direct_errs(0, x->f0, x->f82);
        printf("\n");
    }
    printf("| bound | | | | | | |");
    for (ti = 0; ti < extreme_type_count; ti++)
        printf(" %.1e |", extreme_direct_bound(0, ti));
    printf("\n");
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
    int ri, ci, ti;
    printf("\n### Gulbrandsen's r and g at the ends of [0, 1]\n\n"
           "r is clamped to [0, %g] before the inverse mapping (Q15: code %d, 0.99988;\n"
           "f16: the largest half below 1, 0.99951, and n, k to the binary16 domain; the\n"
           "reference is given r, n, k clamped the same way), g to [0, 1]. The n, k and\n"
           "results are f32; the errors are\n"
           "max |result - reference| over 4097 cosines in each type.\n\n"
           "| r, g | n | k | c = 0 | c = 0.5 | c = 0.9 | c = 1 |",
           (double)FRESNEL_GULBRANDSEN_R_MAX, FRESNEL_GULBRANDSEN_R_MAX_Q15);
    for (ti = 0; ti < extreme_type_count; ti++)
        printf(" err %s |", extreme_types[ti].type->name);
    printf("\n|---|---:|---:|---:|---:|---:|---:|");
    for (ti = 0; ti < extreme_type_count; ti++)
        printf("---:|");
    printf("\n");
    for (ri = 0; ri < extreme_gulbrandsen_count; ri++) {
        const extreme_reflectance *x = &extreme_gulbrandsen[ri];
        fresnel_nk nk = fresnel_gulbrandsen_nk(x->f0, x->f82);
        printf("| %s | %.7g | %.7g |", x->name, (double)nk.n, (double)nk.k);
        for (ci = 0; ci < (int)(sizeof cs / sizeof cs[0]); ci++)
            printf(" %.7g |", (double)fresnel_gulbrandsen(x->f0, x->f82, cs[ci]));
        print_direct_errs(1, x->f0, x->f82);
        printf("\n");
    }
    printf("| bound | | | | | | |");
    for (ti = 0; ti < extreme_type_count; ti++)
        printf(" %.1e |", extreme_direct_bound(1, ti));
    printf("\n");
}

void extremes_print(void)
{
    int i;
    printf("## Extreme cases\n\n"
           "Produced by `build/fresnel extremes`; tests/runtime/every_type/test_extremes.c asserts the properties.\n"
           "Every model in every number type (");
    for (i = 0; i < extreme_type_count; i++)
        printf("%s%s", i ? ", " : "", extreme_types[i].type->name);
    printf(") against the double reference of the same\n"
           "model on the same rounded inputs. Parameters (F0, F82, LSK a and alpha,\n"
           "Gulbrandsen r and g) are derived from eta, kappa and n1 by the reference, as\n"
           "`fresnel eval` does, and rounded to each type's formats. Inputs outside the\n"
           "domain follow fresnel.h: c is clamped to [0, 1], NaN and -Inf give c = 0, +Inf\n"
           "gives c = 1. q15 takes cosine codes (c 32768, saturated to int32; +-Inf are\n"
           "the extreme codes, NaN has none: n/a); '1 LSB' is each type's smallest\n"
           "positive cosine (f32 2^-149, q15 2^-15, f16 2^-24).\n");
    printf("\n### Cosines at and beyond the ends of [0, 1]\n");
    for (i = 0; i < extreme_case_count; i++)
        if (!strcmp(extreme_cases[i].name, "gold, red") || !strcmp(extreme_cases[i].name, "glass -> air"))
            table_cosines(&extreme_cases[i]);
    table_cases();
    table_exact();
    table_reflectances();
    table_gulbrandsen();
}
