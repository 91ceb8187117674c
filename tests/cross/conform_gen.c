/* Writes the C data of tests/cross/conform.h to stdout: the material set of
 * tests/fixed_materials.h prepared by model_fixed_from_params after
 * model_params_round_fixed, as tests/test_fixed_bounds.c does, LUTs of one
 * curve, and a thin film's table. Host only. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cross/conform.h"
#include "fixed_materials.h"
#include "2_derive/film_fit.h"
#include "3_encode/film_encode.h"
#include "3_encode/fixed_params.h"
#include "model/registry.h"
#include "common/reference.h"

static void qf(const char *name, fresnel_qf v) { printf(" .%s = {%uu, %d},", name, (unsigned)v.m, (int)v.e); }

static void ior(const char *name, const fresnel_ior_prep_q15 *m)
{
    printf(" .%s = {%d, %d, %d,", name, (int)m->a0, (int)m->a0_lo, (int)m->shift);
    printf(" {%uu, %d}, {%uu, %d}, {%uu, %d}, {%uu, %d}},", (unsigned)m->b.m, (int)m->b.e, (unsigned)m->n4.m,
           (int)m->n4.e, (unsigned)m->t1_inv.m, (int)m->t1_inv.e, (unsigned)m->inv_eta2.m, (int)m->inv_eta2.e);
}

static void ints(const char *open, const void *v, int n, int is16, int is_signed)
{
    int i;
    printf("%s{", open);
    for (i = 0; i < n; i++) {
        long x = is16 ? (is_signed ? (long)((const int16_t *)v)[i] : (long)((const uint16_t *)v)[i])
                      : (long)((const uint32_t *)v)[i];
        printf("%ld%s", x, is16 ? "" : "u");
        printf(i + 1 < n ? ", " : "}");
    }
}

/* a binary32 value as a C float constant that reads back exactly */
static void flt(const char *before, float v)
{
    char b[40];
    snprintf(b, sizeof b, "%.9g", (double)v);
    printf("%s%s%sf", before, b, strpbrk(b, ".e") ? "" : ".0");
}

static void floats(const char *open, const float *v, int n)
{
    int i;
    printf("%s{", open);
    for (i = 0; i < n; i++)
        flt(i ? ", " : "", v[i]);
    printf("}");
}

/* The thin film's tables (fresnel_film.h): a 2.5 film on gold in air,
 * sRGB, as `fresnel gen` fits and encodes it, in Q1.15 and in binary32
 * (the AArch64 count's row). */
static int print_film(void)
{
    gen_context *g = malloc(sizeof *g);
    film_model *m = malloc(sizeof *m);
    spectrum *s = malloc(sizeof *s);
    fresnel_film_q15 *q = malloc(sizeof *q);
    static fresnel_film f32;
    film_stack f;
    int ch, j, k;
    if (!g || !m || !s || !q || gen_context_load(data_dir(NULL), "srgb", g) || spectrum_load(data_dir(NULL), "au", s) ||
        film_fit_poles(&g->cm, &g->cs, m, NULL))
        return 1;
    f.n1 = 1.0;
    f.film = NULL;
    f.film_n = 2.5;
    f.substrate = s;
    if (film_fit_material(&f, &g->cm, &g->cs, m) || film_encode_q15(m, q))
        return 1;
    film_encode_f32(m, &f32);
    printf("\n#if FRESNEL_HAS_FLOAT\n/* a 2.5 film on gold in air, sRGB */\nconst fresnel_film conform_film_f32 = {\n");
    floats("    ", f32.freq, FRESNEL_FILM_POLES);
    floats(", ", f32.damp, FRESNEL_FILM_POLES);
    printf(",\n    {");
    for (ch = 0; ch < 3; ch++) {
        printf(ch ? ", {" : "{");
        for (j = 0; j < FRESNEL_FILM_POLES; j++)
            floats(j ? ", " : "", f32.weight[ch][j], 2);
        printf("}");
    }
    printf("},\n    {");
    for (k = 0; k < FRESNEL_FILM_NODES; k++) {
        const fresnel_film_node *n = &f32.node[k];
        floats(k ? ",\n     {" : "{", n->a0, 3);
        flt(", ", n->opd);
        flt(", ", n->decay);
        floats(", ", n->a_re, FRESNEL_FILM_POLES);
        floats(", ", n->a_im, FRESNEL_FILM_POLES);
        floats(", ", n->b_re, FRESNEL_FILM_POLES);
        floats(", ", n->b_im, FRESNEL_FILM_POLES);
        floats(", ", n->p_re, FRESNEL_FILM_POLES);
        floats(", ", n->p_im, FRESNEL_FILM_POLES);
        floats(", ", n->q_re, FRESNEL_FILM_POLES);
        floats(", ", n->q_im, FRESNEL_FILM_POLES);
        printf("}");
    }
    printf("}\n};\n#endif\n");
    printf("\n/* a 2.5 film on gold in air, sRGB */\nconst fresnel_film_q15 conform_film = {\n");
    ints("    ", q->turn_nu, FRESNEL_FILM_POLES, 0, 0);
    ints(", ", q->turn_gamma, FRESNEL_FILM_POLES, 0, 0);
    ints(", ", q->octave_nu, FRESNEL_FILM_POLES, 0, 0);
    ints(", ", q->octave_gamma, FRESNEL_FILM_POLES, 0, 0);
    printf(",\n    {");
    for (ch = 0; ch < 3; ch++) {
        printf(ch ? ", {" : "{");
        for (j = 0; j < FRESNEL_FILM_POLES; j++)
            ints(j ? ", " : "", q->weight[ch][j], 2, 1, 1);
        printf("}");
    }
    printf("},\n    {");
    for (k = 0; k < FRESNEL_FILM_NODES; k++) {
        const fresnel_film_node_q15 *n = &q->node[k];
        ints(k ? ",\n     {" : "{", n->a0, 3, 1, 1);
        printf(", %u, %u", (unsigned)n->opd, (unsigned)n->decay);
        ints(", ", n->a_re, FRESNEL_FILM_POLES, 1, 1);
        ints(", ", n->a_im, FRESNEL_FILM_POLES, 1, 1);
        ints(", ", n->b_re, FRESNEL_FILM_POLES, 1, 1);
        ints(", ", n->b_im, FRESNEL_FILM_POLES, 1, 1);
        ints(", ", n->p_re, FRESNEL_FILM_POLES, 1, 1);
        ints(", ", n->p_im, FRESNEL_FILM_POLES, 1, 1);
        ints(", ", n->q_re, FRESNEL_FILM_POLES, 1, 1);
        ints(", ", n->q_im, FRESNEL_FILM_POLES, 1, 1);
        printf("}");
    }
    printf("}\n};\n");
    free(g);
    free(m);
    free(s);
    free(q);
    return 0;
}

int main(void)
{
    static test_material mat[TM_MAX];
    int n = test_materials(mat), k, i, sp, bench = 0, frac16 = 15, frac8 = 7;
    double maxr = 0.0, res[2][64], gt[2][64];
    model_params bench_mp = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
    int32_t f0;
    if (n <= 0)
        return 1;
    printf("/* Generated by tests/cross/conform_gen.c: do not edit. */\n#include \"conform.h\"\n\n");
    printf("const conform_material conform_materials[] = {\n");
    for (k = 0; k < n; k++) {
        model_params mp;
        model_fixed mf;
        fresnel_conductor_prep_q15_fast cf;
        model_derive(mat[k].eta, mat[k].kappa, 1.0, 1.0, 5.0, &mp);
        model_params_round_fixed(&mp);
        model_fixed_from_params(&mp, &mf);
        printf("    /* %s */ {%d, %d, %d, %d, %d, %d,", mat[k].name, (int)mf.f0, (int)mf.f82, (int)mf.f90,
               (int)mf.r, (int)mf.g, (int)mf.p);
        ior("ior", &mf.ior);
        ior("dior", &mf.dior);
        printf(" .nk = {");
        qf("n", mf.nk.n);
        qf("nk2", mf.nk.nk2);
        printf("}, .gnk = {");
        qf("n", mf.gnk.n);
        qf("nk2", mf.gnk.nk2);
        printf("}, .lsk = {%uu, {%uu, %d}, %d},", (unsigned)mf.lsk.f0, (unsigned)mf.lsk.a.m, (int)mf.lsk.a.e,
               (int)mf.lsk.alpha);
        fixed_conductor_fast(mat[k].eta, mat[k].kappa, &cf);
        printf(" .eta = %d, .kappa = %d, .f82_a = %d, .cfast = {%d, %d, %d, %d, %d, %d, %d, %uu}},\n",
               (int)fixed_q16(mat[k].eta), (int)fixed_q16(mat[k].kappa), (int)fixed_f82_a_q12(mf.f0, mf.f82), (int)cf.a0,
               (int)cf.a0_lo, (int)cf.shift, (int)cf.b1, (int)cf.b2, (int)cf.bm, (int)cf.be, (unsigned)cf.span);
        if (!strcmp(mat[k].name, "cu 550")) {
            bench = k;
            bench_mp = mp;
        }
    }
    printf("};\nconst int conform_material_count = %d;\nconst int conform_bench_material = %d;\n\n", n, bench);
    {
        static const char *const names[CONFORM_BENCH_MATERIALS] = {"cu 550", "al 550", "bk7 550"};
        int b, j;
        printf("const int conform_bench_materials[CONFORM_BENCH_MATERIALS] = {");
        for (b = 0; b < CONFORM_BENCH_MATERIALS; b++) {
            for (j = 0; j < n && strcmp(mat[j].name, names[b]); j++)
                ;
            if (j == n)
                return 1;
            printf("%d, ", j);
        }
        printf("};\nconst char *const conform_bench_material_names[CONFORM_BENCH_MATERIALS] = {\"cu 550\", \"al 550\", "
               "\"bk7 550\"};\n");
        printf("const char *const conform_bench_set_names[CONFORM_BENCH_SETS] = {\"uniform in c\", \"uniform in angle\", "
               "\"near grazing (c <= 1/32)\"};\n");
        printf("const int32_t conform_bench_cos[CONFORM_BENCH_SETS][CONFORM_BENCH_CODES] = {{");
        for (j = 0; j < CONFORM_BENCH_CODES; j++) /* c = j/16 */
            printf("%d, ", j * 2048);
        printf("}, {");
        for (j = 0; j < CONFORM_BENCH_CODES; j++) /* theta = j 90/16 degrees */
            printf("%d, ", (int)floor(32768.0 * cos(j * 3.14159265358979323846 / 32.0) + 0.5));
        printf("}, {");
        for (j = 0; j < CONFORM_BENCH_CODES; j++) /* c = j/512 */
            printf("%d, ", j * 64);
        printf("}};\n\n");
    }
    printf("const float conform_bench_float[8] = {%.9gf, %.9gf, %.9gf, %.9gf, %.9gf, %.9gf, %.9gf, %.9gf};\n\n",
           bench_mp.eta, bench_mp.kappa, bench_mp.f0, bench_mp.f82, bench_mp.a, bench_mp.alpha, bench_mp.r, bench_mp.g);
    /* gold at 550 nm */
    for (k = 0; k < n && strcmp(mat[k].name, "au 550"); k++)
        ;
    f0 = fixed_q15(ref_f0_from_ior(mat[k].eta, mat[k].kappa));
    for (sp = 0; sp < 2; sp++)
        for (i = 0; i < 64; i++) {
            double x = i / 63.0, c = sp == 0 ? x * x : x;
            gt[sp][i] = ref_conductor(mat[k].eta, mat[k].kappa, c);
            res[sp][i] = gt[sp][i] - ref_schlick(f0 / 32768.0, c);
            if (fabs(res[sp][i]) > maxr)
                maxr = fabs(res[sp][i]);
        }
    while (frac16 < 30 && maxr * ldexp(1.0, frac16 + 1) <= 32767.0)
        frac16++;
    while (frac8 < 22 && maxr * ldexp(1.0, frac8 + 1) <= 127.0)
        frac8++;
    printf("const int32_t conform_lut_f0 = %d;\nconst int conform_lut_frac16 = %d, conform_lut_frac8 = %d;\n", (int)f0,
           frac16, frac8);
    printf("const uint16_t conform_lut_u16[2][CONFORM_LUT_N] = {");
    for (sp = 0; sp < 2; sp++) {
        printf("{");
        for (i = 0; i < 64; i++)
            printf("%d,", (int)floor(gt[sp][i] * 32768.0 + 0.5));
        printf("},");
    }
    printf("};\nconst uint8_t conform_lut_u8[2][CONFORM_LUT_N] = {");
    for (sp = 0; sp < 2; sp++) {
        printf("{");
        for (i = 0; i < 64; i++)
            printf("%d,", (int)floor(gt[sp][i] * 255.0 + 0.5));
        printf("},");
    }
    printf("};\nconst int16_t conform_lut_s16[2][CONFORM_LUT_N] = {");
    for (sp = 0; sp < 2; sp++) {
        printf("{");
        for (i = 0; i < 64; i++)
            printf("%d,", (int)floor(res[sp][i] * ldexp(1.0, frac16) + 0.5));
        printf("},");
    }
    printf("};\nconst int8_t conform_lut_s8[2][CONFORM_LUT_N] = {");
    for (sp = 0; sp < 2; sp++) {
        printf("{");
        for (i = 0; i < 64; i++)
            printf("%d,", (int)floor(res[sp][i] * ldexp(1.0, frac8) + 0.5));
        printf("},");
    }
    printf("};\n");
    return print_film();
}
