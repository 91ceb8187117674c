/* A header written by `fresnel gen` for a scene with types f32 and q15,
 * read back (tests/common/header_check.h: every value fits its C type and the
 * runtime's documented range), then every Q1.15 LUT table evaluated through
 * the fixed-point runtime against its binary32 twin through the binary32
 * runtime, at every cosine code below 2048 and every 4th above (RGB).
 * Driven by tests/gen/test_gen_matrix.sh over materials x models x n1 x spacing.
 *
 * The bound, in LSB of Q15, is what the runtime documents plus what turning
 * the double table into codes adds:
 *   linear     FRESNEL_BOUND_LUT_Q15 + 0.5 (nodes rounded to codes)
 *   residual   FRESNEL_BOUND_LUT_Q15 + 0.5 (F0 rounded to a code, weighted
 *              by 1 - (1-c)^5 <= 1) + 2^(14 - frac) (nodes rounded to 2^-frac)
 *   cubic      FRESNEL_BOUND_LUT_CUBIC_Q15 + 0.625 (rounded nodes times the
 *              Catmull-Rom weights' largest absolute sum, 1.25)
 * plus the binary32 runtime's rounding (fresnel.h: 3e-7 linear, 5e-7 cubic,
 * 3e-7 more for the residual's Schlick) times 32768. grazing-pl tables have
 * no binary32 twin (the spacing is Q15-only): they are held to
 * FRESNEL_BOUND_LUT_PL_Q15_FAST_TIR against the same interpolation in double
 * at the runtime's own position.
 *
 * With SCENE (the manifest the header was generated from), also the
 * header against the report (scene_mode below); with SCENE CURVE_CSV
 * MATERIAL TYPE [FILM_D] instead, against `fresnel curve --type TYPE`
 * (curve_mode; FILM_D: the thickness of its --film N:D).
 *
 * usage: gen_matrix_check HEADER SPACING LABEL [SCENE [CURVE_CSV MATERIAL
 * TYPE [FILM_D]]]   (SPACING grazing, uniform or grazing-pl) */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fresnel.h"
#include "fresnel_fixed.h"
#include "fresnel_film.h"
#include "fresnel_fixed_fast.h"
#include "header_check.h"
#include "common/reference.h"
#include "report/report.h"

static hc_header hh;

static char *read_all(const char *path)
{
    FILE *f = fopen(path, "rb");
    char *buf;
    long len;
    if (!f)
        return NULL;
    fseek(f, 0, SEEK_END);
    len = ftell(f);
    fseek(f, 0, SEEK_SET);
    buf = (char *)malloc((size_t)len + 1);
    if (buf && fread(buf, 1, (size_t)len, f) != (size_t)len) {
        free(buf);
        buf = NULL;
    }
    if (buf)
        buf[len] = '\0';
    fclose(f);
    return buf;
}

/* The interpolation fresnel_lut_pl_u16_q15_fast documents its bound
 * against: in double, at the runtime's own 15-bit P, of nodes t (values). */
static double pl_ref_d(const double *t, int n, int32_t c)
{
    uint32_t x = (uint32_t)c - ((uint32_t)c >> 15), j = x >> 9;
    uint32_t p = fresnel_lut_pl_knots_q15[j] +
                 (((uint32_t)(fresnel_lut_pl_knots_q15[j + 1] - fresnel_lut_pl_knots_q15[j]) * (x & 511u)) >> 9);
    double pos = p / 32768.0 * (n - 1), w;
    int i = (int)pos;
    if (i > n - 2)
        i = n - 2;
    w = pos - i;
    return t[i] + (t[i + 1] - t[i]) * w;
}

/* The same on a table of codes. */
static double pl_ref(const uint16_t *t, int n, int32_t c)
{
    double v[256];
    int i;
    for (i = 0; i < n; i++)
        v[i] = t[i] / 32768.0;
    return pl_ref_d(v, n, c);
}

/* The form from the table's name: what follows its last "_lutN". */
static int lut_form_of(const char *base)
{
    const char *p = base, *q;
    while ((q = strstr(p, "_lut")) != NULL)
        p = q + 4;
    return strstr(p, "_residual") ? 1 : (strstr(p, "_cubic") ? 2 : 0);
}

typedef struct worst {
    double excess, err, bound;
    char where[200];
    long tables;
} worst;

static void note(worst *w, double err, double bound, const char *table, int32_t c)
{
    if (err - bound > w->excess || !w->where[0]) {
        w->excess = err - bound;
        w->err = err;
        w->bound = bound;
        snprintf(w->where, sizeof w->where, "%.150s c=%ld", table, (long)c);
    }
}

/* ---- SCENE mode: the header against what `fresnel report` (and `curve`,
 * the viewer) evaluate for the same scene. Each material is derived and
 * each model prepared as the report prepares it (scene_model_prepare), then
 * evaluated by the report's own per-type evaluator (the number type
 * registry's eval, which `fresnel curve` calls too); the header's constants
 * and tables are evaluated through the runtime as a program that includes
 * it would. Both must give the same number at each cosine code of
 * scene_mode's grid, in every number type of the scene. Each Q15 LUT is also held, through the
 * report's evaluator, to the same interpolation in double of its fitted
 * double nodes (the encoder's input), within the runtime's documented
 * bound plus what rounding the nodes to codes adds (the bounds above), the
 * double held to [0, 1] (residual) or [0, max(one, the nodes)] (curve) as
 * the runtime holds its result; a binary16 LUT's distance from its own
 * binary16 nodes in double is printed beside fresnel_f16.h's bound. */

static fresnel_rgb hdr_rgb(const hc_decl *d)
{
    fresnel_rgb v;
    v.r = (float)d->v[0], v.g = (float)d->v[1], v.b = (float)d->v[2];
    return v;
}

static fresnel_rgb_q15 hdr_rgb_q15(const hc_decl *d)
{
    fresnel_rgb_q15 v;
    v.r = (fresnel_q15)d->v[0], v.g = (fresnel_q15)d->v[1], v.b = (fresnel_q15)d->v[2];
    return v;
}

static fresnel_qf hdr_qf(const double *v)
{
    fresnel_qf q;
    q.m = (uint32_t)v[0], q.e = (int32_t)v[1];
    return q;
}

static void hdr_ior(const double *v, fresnel_ior_prep_q15 *o)
{
    o->a0 = (int32_t)v[0], o->a0_lo = (int32_t)v[1], o->shift = (int32_t)v[2];
    o->b = hdr_qf(v + 3), o->n4 = hdr_qf(v + 5), o->t1_inv = hdr_qf(v + 7), o->inv_eta2 = hdr_qf(v + 9);
}

/* A model name as the header's identifiers spell it (lsk-comp -> lsk_comp),
 * derived here rather than taken from the generator. */
static void ident_of(const char *model, char id[64])
{
    int i;
    for (i = 0; model[i] && i < 63; i++)
        id[i] = model[i] == '-' ? '_' : model[i];
    id[i] = '\0';
}

/* One header model for one material: its constants, found by name. */
typedef struct hdr_model {
    const hc_header *h;
    char prefix[HC_NAME];
    int missing;
    char what[HC_NAME + 32];
} hdr_model;

static const hc_decl *need(hdr_model *m, const char *suffix)
{
    char name[2 * HC_NAME];
    const hc_decl *d;
    snprintf(name, sizeof name, "%s_%s", m->prefix, suffix);
    if (!(d = hc_find(m->h, name)) && !m->missing) {
        m->missing = 1;
        snprintf(m->what, sizeof m->what, "%.150s", name);
    }
    return d;
}

#if FRESNEL_HAS_F16
/* Channel ch of a binary16 model of the header at the binary16 cosine c,
 * through the scalar function its comments name; -1 as hdr_eval. */
static int hdr_eval_f16(hdr_model *m, const char *model, const scene_model *sm, const char *id, int ch, fresnel_f16 c,
                        double *out)
{
    const hc_decl *d, *e, *a, *b;
    char name[96];
#define HV(decl) ((fresnel_f16)(float)(decl)->v[ch])
    if (sm->lut.n) {
        static fresnel_f16 t[256];
        int n = sm->lut.n, i, uniform = sm->lut.spacing == LUT_UNIFORM;
        snprintf(name, sizeof name, "%s_f16", id);
        if (!(d = need(m, name)) || d->count != 3 * n)
            return -1;
        for (i = 0; i < n; i++)
            t[i] = (fresnel_f16)(float)d->v[ch * n + i];
        if (sm->lut.form == LUT_RESIDUAL) {
            if (!(e = need(m, "f0_f16")))
                return -1;
            *out = (double)(uniform ? fresnel_lut_linear_residual_f16(HV(e), t, n, c)
                                    : fresnel_lut_residual_f16(HV(e), t, n, c));
        } else
            *out = (double)(sm->lut.form == LUT_CUBIC ? fresnel_lut_cubic_f16(t, n, c)
                                                     : (uniform ? fresnel_lut_linear_f16(t, n, c) : fresnel_lut_f16(t, n, c)));
    } else if (!strcmp(model, "schlick") && (d = need(m, "f0_f16")))
        *out = (double)fresnel_schlick_f16(HV(d), c);
    else if (!strcmp(model, "f82") && (d = need(m, "f0_f16")) && (e = need(m, "f82_f16")))
        *out = (double)fresnel_f82_f16(HV(d), HV(e), c);
    else if (!strcmp(model, "gulbrandsen") && (d = need(m, "gulbrandsen_r_f16")) && (e = need(m, "gulbrandsen_g_f16")))
        *out = (double)fresnel_gulbrandsen_f16(HV(d), HV(e), c);
    else if (!strcmp(model, "cook-torrance") && (d = need(m, "f0_f16")) && (a = need(m, "ct_eta_f16")) &&
             (b = need(m, "ct_kappa_f16")))
        *out = (double)fresnel_cook_torrance_f16(HV(d), (fresnel_f16)(float)a->v[0], (fresnel_f16)(float)b->v[0], c);
    else if (!strcmp(model, "lsk") && (d = need(m, "eta_f16")) && (e = need(m, "kappa_f16")))
        *out = (double)fresnel_lsk_f16(HV(d), HV(e), c);
    else if (!strcmp(model, "lsk-comp") && (d = need(m, "eta_f16")) && (e = need(m, "kappa_f16")) &&
             (a = need(m, "lsk_a_f16")) && (b = need(m, "lsk_alpha_f16")))
        *out = (double)fresnel_lsk_comp_f16(HV(d), HV(e), HV(a), HV(b), c);
    else if (!strcmp(model, "approx-conductor") && (d = need(m, "eta_f16")) && (e = need(m, "kappa_f16")))
        *out = (double)fresnel_approx_conductor_f16(HV(d), HV(e), c);
    else if (!strcmp(model, "exact") || !strcmp(model, "exact-gaussian") || !strcmp(model, "exact-point")) {
        const char *suffix = !strcmp(model, "exact") ? "" : (!strcmp(model, "exact-point") ? "_point" : "_gaussian");
        char kname[64];
        snprintf(name, sizeof name, "eta%s_f16", suffix);
        snprintf(kname, sizeof kname, "kappa%s_f16", suffix);
        if (!(d = need(m, name)) || !(e = need(m, kname)))
            return -1;
        *out = (double)fresnel_conductor_f16(HV(d), HV(e), c);
    } else
        return -1;
#undef HV
    return m->missing ? -1 : 0;
}
#endif

/* The thin film of the header: its table, by name, through the runtime at
 * cosine x and thickness d (each converted to the type as a caller would:
 * binary32, Q1.15 code round(x 32768) and Q16.16 round(d 65536), binary16). */
typedef char film_floats_in_order[sizeof(fresnel_film) == HC_FILM_FLOATS * sizeof(float) ? 1 : -1];
static int hdr_film(hdr_model *m, const char *id, number_type_id type, double x, double d, double out[3])
{
    char name[96];
    const hc_decl *t;
    const double *v;
    int i, j, k;
    snprintf(name, sizeof name, type == TYPE_F32 ? "%s" : (type == TYPE_Q15 ? "%s_q15" : "%s_f16"), id);
    if (!(t = need(m, name)))
        return -1;
    v = t->v;
    if (type == TYPE_F32) {
        static fresnel_film f;
        fresnel_rgb r;
        for (i = 0; i < HC_FILM_FLOATS; i++)
            ((float *)&f)[i] = (float)v[i];
        r = fresnel_film_rgb(&f, (float)x, (float)d);
        out[0] = r.r, out[1] = r.g, out[2] = r.b;
    } else if (type == TYPE_Q15) {
        static fresnel_film_q15 f;
        fresnel_rgb_q15 r;
        double dq = floor(d * 65536.0 + 0.5);
        for (j = 0; j < FRESNEL_FILM_POLES; j++) {
            f.turn_nu[j] = (uint32_t)v[j];
            f.turn_gamma[j] = (uint32_t)v[FRESNEL_FILM_POLES + j];
            f.octave_nu[j] = (uint32_t)v[2 * FRESNEL_FILM_POLES + j];
            f.octave_gamma[j] = (uint32_t)v[3 * FRESNEL_FILM_POLES + j];
        }
        v += 4 * FRESNEL_FILM_POLES;
        for (i = 0; i < 3; i++)
            for (j = 0; j < FRESNEL_FILM_POLES; j++) {
                f.weight[i][j][0] = (int16_t)v[2 * (i * FRESNEL_FILM_POLES + j)];
                f.weight[i][j][1] = (int16_t)v[2 * (i * FRESNEL_FILM_POLES + j) + 1];
            }
        v += 6 * FRESNEL_FILM_POLES;
        for (k = 0; k < FRESNEL_FILM_NODES; k++, v += HC_FILM_NODE) {
            fresnel_film_node_q15 *n = &f.node[k];
            int16_t *arrays[8];
            arrays[0] = n->a_re;
            arrays[1] = n->a_im;
            arrays[2] = n->b_re;
            arrays[3] = n->b_im;
            arrays[4] = n->p_re;
            arrays[5] = n->p_im;
            arrays[6] = n->q_re;
            arrays[7] = n->q_im;
            for (i = 0; i < 3; i++)
                n->a0[i] = (int16_t)v[i];
            n->opd = (uint16_t)v[3];
            n->decay = (uint16_t)v[4];
            for (i = 0; i < 8; i++)
                for (j = 0; j < FRESNEL_FILM_POLES; j++)
                    arrays[i][j] = (int16_t)v[5 + i * FRESNEL_FILM_POLES + j];
        }
        r = fresnel_film_q15_rgb(&f, (int32_t)lround(x * 32768.0),
                                 dq >= 2147483647.0 ? INT32_MAX : (dq > 0.0 ? (int32_t)dq : 0));
        out[0] = r.r / 32768.0, out[1] = r.g / 32768.0, out[2] = r.b / 32768.0;
    } else {
#if FRESNEL_HAS_F16
        static fresnel_film_f16 f;
        fresnel_rgb_f16 r;
        for (i = 0; i < HC_FILM_FLOATS; i++)
            ((fresnel_f16 *)&f)[i] = (fresnel_f16)(float)v[i];
        r = fresnel_film_f16_rgb(&f, (fresnel_f16)x, (fresnel_f16)d);
        out[0] = (double)r.r, out[1] = (double)r.g, out[2] = (double)r.b;
#else
        return -1;
#endif
    }
    return m->missing ? -1 : 0;
}

/* The header's model `name` at cosine x in number type `type` (x converted
 * to the type: rounded to binary32 or binary16, Q1.15 code round(x
 * 32768); results as doubles, Q1.15 codes / 32768), through the runtime
 * function the header's comments name; -1 when the checker knows no such
 * model (then the test must learn it) or a constant is missing. */
static int hdr_eval(hdr_model *m, const char *model, const scene_model *sm, number_type_id type, double x,
                    double d_nm, double out[3])
{
    int q15 = type == TYPE_Q15;
    int32_t c = (int32_t)lround(x * 32768.0);
    float cf = (float)x;
    fresnel_rgb r = {0.0f, 0.0f, 0.0f};
    fresnel_rgb_q15 o = {0, 0, 0};
    const hc_decl *d, *e, *f0;
    char id[64];
    int i;
    ident_of(model, id);
    if (!strcmp(model, "thin-film"))
        return hdr_film(m, id, type, x, d_nm, out);
    if (type == TYPE_F16) {
#if FRESNEL_HAS_F16
        int ch;
        for (ch = 0; ch < 3; ch++)
            if (hdr_eval_f16(m, model, sm, id, ch, (fresnel_f16)x, &out[ch]))
                return -1;
        return 0;
#else
        return -1;
#endif
    }
    if (sm->lut.n) {
        static uint16_t u16[3 * 256];
        static int16_t s16[3 * 256];
        static float f32[3 * 256];
        char name[96];
        int n = sm->lut.n, uniform = sm->lut.spacing == LUT_UNIFORM;
        snprintf(name, sizeof name, q15 ? "%s_q15" : "%s", id);
        if (!(d = need(m, name)) || d->count != 3 * n)
            return -1;
        for (i = 0; i < 3 * n; i++)
            u16[i] = (uint16_t)d->v[i], s16[i] = (int16_t)d->v[i], f32[i] = (float)d->v[i];
        if (!q15) {
            if (sm->lut.form == LUT_RESIDUAL) {
                if (!(f0 = need(m, "f0")))
                    return -1;
                r = uniform ? fresnel_lut_linear_residual_rgb(hdr_rgb(f0), f32, n, cf)
                            : fresnel_lut_residual_rgb(hdr_rgb(f0), f32, n, cf);
            } else
                r = sm->lut.form == LUT_CUBIC ? fresnel_lut_cubic_rgb(f32, n, cf)
                                          : (uniform ? fresnel_lut_linear_rgb(f32, n, cf) : fresnel_lut_rgb(f32, n, cf));
        } else if (sm->lut.form == LUT_RESIDUAL) {
            snprintf(name, sizeof name, "%s_frac", id);
            if (!(f0 = need(m, "f0_q15")) || !(e = need(m, name)))
                return -1;
            o = uniform ? fresnel_lut_linear_residual_s16_q15_rgb(hdr_rgb_q15(f0), s16, n, (int)e->v[0], c)
                        : fresnel_lut_residual_s16_q15_rgb(hdr_rgb_q15(f0), s16, n, (int)e->v[0], c);
        } else if (sm->lut.spacing == LUT_GRAZING_PL) {
            o.r = fresnel_lut_pl_u16_q15_fast(u16, n, c);
            o.g = fresnel_lut_pl_u16_q15_fast(u16 + n, n, c);
            o.b = fresnel_lut_pl_u16_q15_fast(u16 + 2 * n, n, c);
        } else
            o = sm->lut.form == LUT_CUBIC ? fresnel_lut_cubic_u16_q15_rgb(u16, n, c)
                                      : (uniform ? fresnel_lut_linear_u16_q15_rgb(u16, n, c)
                                                 : fresnel_lut_u16_q15_rgb(u16, n, c));
    } else if (!q15) {
        const char *eta = "eta", *kappa = "kappa";
        if (!strcmp(model, "schlick") && (d = need(m, "f0")))
            r = fresnel_schlick_rgb(hdr_rgb(d), cf);
        else if (!strcmp(model, "f82") && (d = need(m, "f0")) && (e = need(m, "f82")))
            r = fresnel_f82_rgb(hdr_rgb(d), hdr_rgb(e), cf);
        else if (!strcmp(model, "gulbrandsen") && (d = need(m, "gulbrandsen_r")) && (e = need(m, "gulbrandsen_g")))
            r = fresnel_gulbrandsen_rgb(hdr_rgb(d), hdr_rgb(e), cf);
        else if (!strcmp(model, "cook-torrance") && (f0 = need(m, "f0")) && (d = need(m, "ct_eta")) &&
                 (e = need(m, "ct_kappa")))
            r = fresnel_cook_torrance_rgb(hdr_rgb(f0), (float)d->v[0], (float)e->v[0], cf);
        else if (!strcmp(model, "lsk") && (d = need(m, "eta")) && (e = need(m, "kappa")))
            r = fresnel_lsk_rgb(hdr_rgb(d), hdr_rgb(e), cf);
        else if (!strcmp(model, "lsk-comp") && (d = need(m, "eta")) && (e = need(m, "kappa")) &&
                 (f0 = need(m, "lsk_a")) && need(m, "lsk_alpha"))
            r = fresnel_lsk_comp_rgb(hdr_rgb(d), hdr_rgb(e), hdr_rgb(f0), hdr_rgb(need(m, "lsk_alpha")), cf);
        else if (!strcmp(model, "approx-conductor") && (d = need(m, "eta")) && (e = need(m, "kappa")))
            r = fresnel_approx_conductor_rgb(hdr_rgb(d), hdr_rgb(e), cf);
        else if (!strcmp(model, "exact") || !strcmp(model, "exact-gaussian") || !strcmp(model, "exact-point")) {
            if (!strcmp(model, "exact-gaussian"))
                eta = "eta_gaussian", kappa = "kappa_gaussian";
            else if (!strcmp(model, "exact-point"))
                eta = "eta_point", kappa = "kappa_point";
            if (!(d = need(m, eta)) || !(e = need(m, kappa)))
                return -1;
            r = fresnel_conductor_rgb(hdr_rgb(d), hdr_rgb(e), cf);
        } else
            return -1;
    } else {
        fresnel_ior_prep_q15 ior[3];
        fresnel_nk_prep_q15 nk[3];
        fresnel_lsk_prep_q15 lsk[3];
        const char *prep = NULL;
        if (!strcmp(model, "exact"))
            prep = "ior_q15";
        else if (!strcmp(model, "exact-gaussian"))
            prep = "ior_gaussian_q15";
        else if (!strcmp(model, "exact-point"))
            prep = "ior_point_q15";
        if (!strcmp(model, "schlick") && (d = need(m, "f0_q15")))
            o = fresnel_schlick_q15_rgb(hdr_rgb_q15(d), c);
        else if (!strcmp(model, "f82") && (d = need(m, "f0_q15")) && (e = need(m, "f82_q15")))
            o = fresnel_f82_q15_rgb(hdr_rgb_q15(d), hdr_rgb_q15(e), c);
        else if (!strcmp(model, "gulbrandsen") && (d = need(m, "gulbrandsen_r_q15")) &&
                 (e = need(m, "gulbrandsen_g_q15")))
            o = fresnel_gulbrandsen_q15_rgb(hdr_rgb_q15(d), hdr_rgb_q15(e), c);
        else if (!strcmp(model, "cook-torrance") && (f0 = need(m, "f0_q15")) && (d = need(m, "ct_ior_q15"))) {
            hdr_ior(d->v, &ior[0]);
            o = fresnel_cook_torrance_q15_rgb(hdr_rgb_q15(f0), &ior[0], c);
        } else if ((!strcmp(model, "lsk") && (d = need(m, "lsk_q15"))) ||
                   (!strcmp(model, "lsk-comp") && (d = need(m, "lsk_comp_q15")))) {
            for (i = 0; i < 3; i++) {
                lsk[i].f0 = (uint32_t)d->v[4 * i], lsk[i].a = hdr_qf(d->v + 4 * i + 1);
                lsk[i].alpha = (fresnel_q16)d->v[4 * i + 3];
            }
            o = strcmp(model, "lsk") ? fresnel_lsk_comp_q15_rgb(lsk, c) : fresnel_lsk_q15_rgb(lsk, c);
        } else if (!strcmp(model, "approx-conductor") && (d = need(m, "nk_q15"))) {
            for (i = 0; i < 3; i++)
                nk[i].n = hdr_qf(d->v + 4 * i), nk[i].nk2 = hdr_qf(d->v + 4 * i + 2);
            o = fresnel_approx_conductor_q15_rgb(nk, c);
        } else if (prep && (d = need(m, prep))) {
            for (i = 0; i < 3; i++)
                hdr_ior(d->v + 11 * i, &ior[i]);
            o = fresnel_conductor_q15_rgb(ior, c);
        } else
            return -1;
    }
    if (m->missing)
        return -1;
    if (q15)
        out[0] = o.r / 32768.0, out[1] = o.g / 32768.0, out[2] = o.b / 32768.0;
    else
        out[0] = r.r, out[1] = r.g, out[2] = r.b;
    return 0;
}

/* The interpolation the runtime documents its Q15 bound against, in double
 * on the encoder's double nodes, at the double position of c (at the
 * runtime's own 15-bit position for grazing-pl): Q1.15 LSB. */
/* top: max(one, the channel's nodes), a curve's upper clamp */
static double own_double(const scene_model *sm, const material_params *p, int ch, int32_t c, double top)
{
    const double *t = sm->lut.nodes + ch * sm->lut.n;
    double x = c / 32768.0, v;
    if (sm->lut.spacing == LUT_GRAZING_PL)
        return pl_ref_d(t, sm->lut.n, c) * 32768.0;
    v = ref_lut(t, sm->lut.n, sm->lut.form == LUT_CUBIC, sm->lut.spacing == LUT_UNIFORM ? x : sqrt(x));
    if (sm->lut.form == LUT_RESIDUAL)
        return fmin(fmax(v + ref_schlick(p->f0[ch], x), 0.0), 1.0) * 32768.0;
    return fmin(fmax(v, 0.0), top) * 32768.0;
}

#if FRESNEL_HAS_F16
/* The same for a binary16 table: the interpolation in double of its own
 * binary16 nodes (and F0) at the binary16 cosine, the reference
 * fresnel_f16.h's bounds are measured against. */
static double own_double_f16(const scene_model *sm, const double *t16, int ch, int32_t c, double top)
{
    double x = (double)(fresnel_f16)(c / 32768.0), v;
    int n = sm->lut.n;
    const double *t = t16 + ch * n;
    v = ref_lut(t, n, sm->lut.form == LUT_CUBIC, sm->lut.spacing == LUT_UNIFORM ? x : sqrt(x));
    if (sm->lut.form == LUT_RESIDUAL)
        return fmin(fmax(v + ref_schlick((double)sm->mat.h_f0[ch], x), 0.0), 1.0);
    return fmin(fmax(v, 0.0), top);
}
#endif

/* A film's thicknesses: the scene's range's ends, then across the runtime's
 * range, its end and beyond it (the runtime clamps). */
#define FILM_THICKNESSES 9
static double film_thickness(const scene *sc, int i)
{
    static const double d[FILM_THICKNESSES - 2] = {0.0, 0.5, 137.25, 480.0, 2999.9, 5000.0, 7000.0};
    return i < 2 ? (i ? sc->film_d_hi : sc->film_d_lo) : d[i - 2];
}

/* Every material and model of the scene at every cosine code below 256,
 * every 4th below 2048 and every 16th above (several per segment of the
 * finest table): the report's figure against the header's, in each number
 * type the header holds and the report measures. */
static int scene_mode(const char *scene_path, const char *label)
{
    scene sc;
    gen_context *g = malloc(sizeof *g);
    spectrum *s = malloc(sizeof *s);
    char scene_name[SCENE_PREFIX_SIZE];
    int i, m, t, ch, fails = 0;
    long compared = 0, luts = 0, luts16 = 0;
    double lut_excess = -1e9, lut_err = 0.0, lut_bound = 0.0, h_excess = -1e9, h_err = 0.0, h_bound = 0.0;
    char lut_where[200] = "", h_where[200] = "";
#if FRESNEL_HAS_F16
    static double nodes16[3 * 256];
#endif
    double top[3], top16[3];
    if (!g || !s || scene_load(scene_path, &sc) || gen_context_load(data_dir(NULL), sc.space, g)) {
        printf("FAIL gen matrix %s: cannot load the scene %s\n", label, scene_path);
        free(g);
        free(s);
        return 1;
    }
    g->gamut = sc.gamut;
    if (sc.name[0])
        snprintf(scene_name, sizeof scene_name, "%s", sc.name);
    else
        scene_name_from_path(scene_path, scene_name);
    for (i = 0; i < sc.material_count && !fails; i++) {
        material_source src = scene_material(&sc, i);
        material_params p;
        if (derive_parameters(g, &src, sc.sigma, sc.n1, s, &p)) {
            printf("FAIL gen matrix %s: cannot derive %s\n", label, sc.materials[i]);
            fails++;
            break;
        }
        for (m = 0; m < sc.model_count && !fails; m++) {
            scene_model sm;
            model_rgb rp;
            hdr_model hm;
            memset(&hm, 0, sizeof hm);
            hm.h = &hh;
            snprintf(hm.prefix, sizeof hm.prefix, "fresnel_%s_%s", scene_name, sc.materials[i]);
            if (scene_model_prepare(&sc.models[m], sc.spacing, s, g, &p, &sm)) {
                printf("FAIL gen matrix %s: cannot prepare %s for %s as the report does\n", label, sc.models[m].name,
                       sc.materials[i]);
                fails++;
                break;
            }
            rp = scene_model_rgb(&sm);
            {
                int k;
                for (ch = 0; ch < 3; ch++) {
                    top[ch] = top16[ch] = 1.0;
                    for (k = 0; k < sm.lut.n; k++) {
                        top[ch] = fmax(top[ch], sm.lut.nodes[ch * sm.lut.n + k]);
#if FRESNEL_HAS_F16
                        nodes16[ch * sm.lut.n + k] = (double)sm.lut.f16[ch * sm.lut.n + k];
                        top16[ch] = fmax(top16[ch], nodes16[ch * sm.lut.n + k]);
#endif
                    }
                }
            }
            for (t = 0; t < number_types_available && !fails; t++) {
                int q15 = number_types[t].id == TYPE_Q15;
                int32_t c;
                if (!scene_has_type(&sc, number_types[t].id))
                    continue;
                /* a film at thicknesses across its range, the ends of the
                 * runtime's and beyond; the other models at d 0 */
                int film = sm.film != NULL, di, nd = film ? FILM_THICKNESSES : 1;
                for (di = 0; di < nd && !fails; di++) {
                rp.d_nm = film ? film_thickness(&sc, di) : 0.0;
                for (c = 0; c <= 32768 && !fails; c += film ? (c < 2048 ? 16 : 128) : (c < 256 ? 1 : (c < 2048 ? 4 : 16))) {
                    double got[3], want[3];
                    if (hdr_eval(&hm, sc.models[m].name, &sm, number_types[t].id, c / 32768.0, rp.d_nm, want)) {
                        printf("FAIL gen matrix %s: %s %s %s: %s\n", label, sc.materials[i], sc.models[m].name,
                               number_types[t].name,
                               hm.missing ? "missing from the header" : "a model the checker cannot evaluate");
                        if (hm.missing)
                            printf("    (%s)\n", hm.what);
                        fails++;
                        break;
                    }
                    if (sm.lut.spacing == LUT_GRAZING_PL) { /* the report measures no grazing-pl scene */
                        memcpy(got, want, sizeof got);
                    } else {
                        number_types[t].eval(&rp, c / 32768.0, got);
                        compared++;
                    }
                    for (ch = 0; ch < 3; ch++)
                        if (got[ch] != want[ch]) {
                            printf("FAIL gen matrix %s: %s %s %s at c = %ld/32768: the report evaluates %.9g, "
                                   "the header %.9g (channel %d)\n",
                                   label, sc.materials[i], sc.models[m].name, number_types[t].name, (long)c, got[ch],
                                   want[ch], ch);
                            fails++;
                            break;
                        }
#if FRESNEL_HAS_F16
                    if (number_types[t].id == TYPE_F16 && sm.lut.n && !fails) {
                        /* the bounds of any table in the node range (fresnel_f16.h) */
                        double bound = sm.lut.form == LUT_CUBIC      ? FRESNEL_DOMAIN_LUT_CUBIC_F16
                                       : sm.lut.form == LUT_RESIDUAL ? FRESNEL_DOMAIN_LUT_RESIDUAL_F16
                                                                     : FRESNEL_DOMAIN_LUT_F16;
                        for (ch = 0; ch < 3; ch++) {
                            double err = fabs(got[ch] - own_double_f16(&sm, nodes16, ch, c, top16[ch]));
                            if (err - bound > h_excess) {
                                h_excess = err - bound, h_err = err, h_bound = bound;
                                snprintf(h_where, sizeof h_where, "%s %s c=%ld", sc.materials[i], sc.models[m].name,
                                         (long)c);
                            }
                        }
                    }
#endif
                    if (q15 && sm.lut.n && !fails) {
                        const hc_decl *frac = NULL;
                        double bound = sm.lut.form == LUT_CUBIC ? FRESNEL_BOUND_LUT_CUBIC_Q15 + 0.625
                                                            : FRESNEL_BOUND_LUT_Q15 + 0.5;
                        if (sm.lut.spacing == LUT_GRAZING_PL)
                            bound = FRESNEL_BOUND_LUT_PL_Q15_FAST_TIR + 0.5;
                        if (sm.lut.form == LUT_RESIDUAL) {
                            char name[HC_NAME + 80], id[64];
                            ident_of(sc.models[m].name, id);
                            snprintf(name, sizeof name, "%s_%s_frac", hm.prefix, id);
                            frac = hc_find(&hh, name);
                            bound += 0.5 + ldexp(1.0, 14 - (frac ? (int)frac->v[0] : 14));
                        }
                        for (ch = 0; ch < 3; ch++) {
                            double err = fabs(got[ch] * 32768.0 - own_double(&sm, &p, ch, c, top[ch]));
                            if (err - bound > lut_excess) {
                                lut_excess = err - bound, lut_err = err, lut_bound = bound;
                                snprintf(lut_where, sizeof lut_where, "%s %s c=%ld", sc.materials[i], sc.models[m].name,
                                         (long)c);
                            }
                        }
                    }
                }
                }
                if (q15 && sm.lut.n)
                    luts++;
                if (number_types[t].id == TYPE_F16 && sm.lut.n)
                    luts16++;
            }
            scene_model_free(&sm);
        }
    }
    if (!fails)
        printf("PASS gen matrix %s: the report evaluates exactly what the header holds (%ld RGB evaluations, %d "
               "materials x %d models)\n",
               label, compared, sc.material_count, sc.model_count);
    if (luts && !fails) {
        if (lut_excess > 0.0)
            fails++;
        printf("%s gen matrix %s: %ld Q15 LUT rows within their bound of their own double nodes, worst %.4f LSB "
               "(bound %.4f) at %s\n",
               lut_excess > 0.0 ? "FAIL" : "PASS", label, luts, lut_err, lut_bound, lut_where);
    }
    if (luts16 && !fails) {
        if (h_excess > 0.0)
            fails++;
        printf("%s gen matrix %s: %ld binary16 LUT rows within their bound of their own binary16 nodes in double, "
               "worst %.3g (bound %.3g) at %s\n",
               h_excess > 0.0 ? "FAIL" : "PASS", label, luts16, h_err, h_bound, h_where);
    }
    free(g);
    free(s);
    return fails;
}

/* CURVE mode: `fresnel curve --type TYPE` of one material of the scene
 * (its CSV), every model column against the header at the same cosines
 * (curve's: theta = 90 r / (rows - 1) degrees), the same %.9g text. */
static int curve_mode(const char *scene_path, const char *csv_path, const char *material, const char *type_name,
                      double film_d, const char *label)
{
    scene sc;
    const number_type *type = number_type_find(type_name);
    char *csv = read_all(csv_path), *line, *save = NULL, scene_name[SCENE_PREFIX_SIZE];
    int rows = 0, r, m, ch, fails = 0;
    long compared = 0;
    hdr_model hm;
    if (!csv || !type || scene_load(scene_path, &sc)) {
        printf("FAIL gen matrix %s: cannot read %s, type %s or the scene\n", label, csv_path, type_name);
        free(csv);
        return 1;
    }
    for (line = csv; *line; line++)
        rows += *line == '\n';
    rows--; /* the column names */
    if (sc.name[0])
        snprintf(scene_name, sizeof scene_name, "%s", sc.name);
    else
        scene_name_from_path(scene_path, scene_name);
    memset(&hm, 0, sizeof hm);
    hm.h = &hh;
    snprintf(hm.prefix, sizeof hm.prefix, "fresnel_%s_%s", scene_name, material);
    line = strtok_r(csv, "\n", &save); /* column names: 8, then 3 per model in the scene's order */
    for (r = 0; r < rows && !fails && (line = strtok_r(NULL, "\n", &save)); r++) {
        double theta = 90.0 * r / (rows - 1), c = r == rows - 1 ? 0.0 : cos(theta * (3.14159265358979323846 / 180.0));
        char *field[8 + 3 * SCENE_MAX_MODELS], *p = line;
        int nf = 0;
        while (p && nf < (int)(sizeof field / sizeof field[0])) {
            field[nf++] = p;
            if ((p = strchr(p, ',')))
                *p++ = '\0';
        }
        if (nf != 8 + 3 * sc.model_count) {
            printf("FAIL gen matrix %s: %s row %d has %d columns, expected %d\n", label, csv_path, r, nf,
                   8 + 3 * sc.model_count);
            fails++;
            break;
        }
        for (m = 0; m < sc.model_count && !fails; m++) {
            scene_model sm;
            double want[3];
            memset(&sm, 0, sizeof sm);
            sm.lut.n = sc.models[m].lut_n;
            sm.lut.form = model_of(sc.models[m].row)->form;
            sm.lut.spacing = sc.spacing;
            if (hdr_eval(&hm, sc.models[m].name, &sm, type->id, c, film_d, want)) {
                printf("FAIL gen matrix %s: %s %s: not in the header or not known to the checker\n", label,
                       sc.models[m].name, type->name);
                fails++;
                break;
            }
            for (ch = 0; ch < 3; ch++) {
                char text[40];
                snprintf(text, sizeof text, "%.9g", want[ch]);
                compared++;
                if (strcmp(text, field[8 + 3 * m + ch])) {
                    printf("FAIL gen matrix %s: fresnel curve --type %s prints %s for %s %s at theta %g, the header "
                           "%s (channel %d)\n",
                           label, type->name, field[8 + 3 * m + ch], material, sc.models[m].name, theta, text, ch);
                    fails++;
                    break;
                }
            }
        }
    }
    if (!fails)
        printf("PASS gen matrix %s: fresnel curve --type %s prints what the header computes for %s (%ld values, %d "
               "models)\n",
               label, type->name, material, compared, sc.model_count);
    free(csv);
    return fails;
}

int main(int argc, char **argv)
{
    char *text;
    const char *spacing, *label;
    int i, uniform, pl, fails = 0;
    worst w[4]; /* linear, residual, cubic, pl */
    static const char *const form_name[4] = {"linear", "residual", "cubic", "grazing-pl"};
    if (argc != 4 && argc != 5 && argc != 8 && argc != 9) {
        fprintf(stderr, "usage: gen_matrix_check HEADER SPACING LABEL [SCENE [CURVE_CSV MATERIAL TYPE [FILM_D]]]\n");
        return 2;
    }
    spacing = argv[2];
    label = argv[3];
    uniform = !strcmp(spacing, "uniform");
    pl = !strcmp(spacing, "grazing-pl");
    memset(w, 0, sizeof w);
    w[0].excess = w[1].excess = w[2].excess = w[3].excess = -1e9;
    if (!(text = read_all(argv[1]))) {
        printf("FAIL gen matrix %s: cannot read %s\n", label, argv[1]);
        return 1;
    }
    if (hc_parse(text, &hh))
        printf("FAIL gen matrix %s: header values in their types and ranges: %s\n", label, hh.err), fails++;
    else
        printf("PASS gen matrix %s: %d declarations, every value in its C type and documented range\n", label,
               hh.n);
    for (i = 0; i < hh.n; i++) {
        const hc_decl *q = &hh.d[i], *twin, *f0q = NULL, *f0f = NULL, *frac = NULL;
        char base[HC_NAME], name[HC_NAME + 8];
        size_t len = strlen(q->name);
        int n, form, ch;
        int32_t c;
        static uint16_t u16[3 * 256];
        static int16_t s16[3 * 256];
        static float f32[3 * 256];
        fresnel_rgb_q15 f0_q15 = {0, 0, 0};
        fresnel_rgb f0_f32 = {0.0f, 0.0f, 0.0f};
        if ((strcmp(q->type, "uint16_t") && strcmp(q->type, "int16_t")) || len < 5 ||
            strcmp(q->name + len - 4, "_q15"))
            continue;
        memcpy(base, q->name, len - 4);
        base[len - 4] = '\0';
        form = pl ? 3 : lut_form_of(base);
        n = q->count / 3;
        if (q->count % 3 || n < 2 || n > 256) {
            printf("FAIL gen matrix %s: %s has %d values\n", label, q->name, q->count), fails++;
            continue;
        }
        twin = hc_find(&hh, base);
        if (!pl && (!twin || twin->count != q->count || strcmp(twin->type, "float"))) {
            printf("FAIL gen matrix %s: %s has no binary32 twin %s of %d floats\n", label, q->name, base, q->count);
            fails++;
            continue;
        }
        for (ch = 0; ch < 3 * n; ch++) {
            u16[ch] = (uint16_t)q->v[ch];
            s16[ch] = (int16_t)q->v[ch];
            if (twin)
                f32[ch] = (float)twin->v[ch];
        }
        if (form == 1) {
            snprintf(name, sizeof name, "%s_frac", base);
            frac = hc_find(&hh, name);
            {
                const char *lut = base, *q2;
                while ((q2 = strstr(lut + 1, "_lut")) != NULL)
                    lut = q2;
                snprintf(name, sizeof name, "%.*s_f0_q15", (int)(lut - base), base);
                f0q = hc_find(&hh, name);
                snprintf(name, sizeof name, "%.*s_f0", (int)(lut - base), base);
            }
            f0f = hc_find(&hh, name);
            if (!frac || !f0q || !f0f) {
                printf("FAIL gen matrix %s: %s without its frac, Q15 F0 or binary32 F0\n", label, q->name), fails++;
                continue;
            }
            f0_q15.r = (fresnel_q15)f0q->v[0], f0_q15.g = (fresnel_q15)f0q->v[1], f0_q15.b = (fresnel_q15)f0q->v[2];
            f0_f32.r = (float)f0f->v[0], f0_f32.g = (float)f0f->v[1], f0_f32.b = (float)f0f->v[2];
        }
        w[form].tables++;
        for (c = 0; c <= 32768; c += c < 2048 ? 1 : 4) {
            float cf = (float)c / 32768.0f;
            fresnel_rgb_q15 o;
            fresnel_rgb r;
            double bound, got[3], ref[3];
            if (form == 3) {
                for (ch = 0; ch < 3; ch++) {
                    got[ch] = fresnel_lut_pl_u16_q15_fast(u16 + ch * n, n, c);
                    ref[ch] = pl_ref(u16 + ch * n, n, c);
                }
                bound = FRESNEL_BOUND_LUT_PL_Q15_FAST_TIR;
            } else {
                if (form == 0) {
                    o = uniform ? fresnel_lut_linear_u16_q15_rgb(u16, n, c) : fresnel_lut_u16_q15_rgb(u16, n, c);
                    r = uniform ? fresnel_lut_linear_rgb(f32, n, cf) : fresnel_lut_rgb(f32, n, cf);
                    bound = FRESNEL_BOUND_LUT_Q15 + 0.5 + 32768.0 * 3e-7;
                } else if (form == 1) {
                    int fr = (int)frac->v[0];
                    o = uniform ? fresnel_lut_linear_residual_s16_q15_rgb(f0_q15, s16, n, fr, c)
                                : fresnel_lut_residual_s16_q15_rgb(f0_q15, s16, n, fr, c);
                    r = uniform ? fresnel_lut_linear_residual_rgb(f0_f32, f32, n, cf)
                                : fresnel_lut_residual_rgb(f0_f32, f32, n, cf);
                    bound = FRESNEL_BOUND_LUT_Q15 + 0.5 + ldexp(1.0, 14 - fr) + 32768.0 * 6e-7;
                } else {
                    o = fresnel_lut_cubic_u16_q15_rgb(u16, n, c);
                    r = fresnel_lut_cubic_rgb(f32, n, cf);
                    bound = FRESNEL_BOUND_LUT_CUBIC_Q15 + 0.625 + 32768.0 * 5e-7;
                }
                got[0] = o.r, got[1] = o.g, got[2] = o.b;
                ref[0] = r.r, ref[1] = r.g, ref[2] = r.b;
            }
            for (ch = 0; ch < 3; ch++) {
                double err = fabs(got[ch] - ref[ch] * 32768.0);
                if (got[ch] < 0 || got[ch] > 32768)
                    err = 1e9;
                note(&w[form], err, bound, q->name, c);
            }
        }
    }
    for (i = 0; i < 4; i++) {
        if (!w[i].tables)
            continue;
        if (w[i].excess > 0.0)
            fails++;
        printf("%s gen matrix %s: %ld %s Q15 tables %s, worst %.4f LSB (bound %.4f) at %s\n",
               w[i].excess > 0.0 ? "FAIL" : "PASS", label, w[i].tables, form_name[i],
               i == 3 ? "against double at the runtime's position" : "against their binary32 twins", w[i].err,
               w[i].bound, w[i].where);
    }
    if (argc == 5)
        fails += scene_mode(argv[4], label);
    if (argc >= 8)
        fails += curve_mode(argv[4], argv[5], argv[6], argv[7], argc == 9 ? atof(argv[8]) : 0.0, label);
    hc_free(&hh);
    free(text);
    return fails != 0;
}
