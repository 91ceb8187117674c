/* The thin-film runtime (fresnel_film.h): hostile inputs, the fixed-point tables, and CIEDE2000 against the
 * film's spectral truth over the goal matrix: films n_f 1.2-2.5 on Au, Cu,
 * Al, Ti, Fe and BK7 in air, theta 0-89 degrees, d 0-1000 nm.
 *
 * The default run samples that matrix: films 1.2, 1.8 and 2.5 (the ends
 * and the middle: the error grows with n_f, whose reflection at the film's
 * top makes the fringes deep), theta every 10 degrees and 89, from 0 for the films 1.2
 * and 2.5 and from 5 for 1.8 (the table's nodes, every 1/31 in
 * sqrt(cos(theta)), lie 3 to 10 degrees apart below 60 degrees and closer
 * towards grazing, so these angles fall between nodes as often as on
 * them), d every 10 nm (a seventh of the fastest fringe period, 76 nm at
 * n_f 2.5 and 380 nm). FILM_FULL=1 runs the
 * whole matrix (n_f every 0.1, every degree, every 5 nm: minutes). Each
 * type against the double evaluation of its own constants is
 * tests/runtime/thin_film/test_film_search.c. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "harness.h"
#include "1_spectral/colour_difference.h"
#include "2_derive/derive.h"
#include "2_derive/film_fit.h"
#include "3_encode/film_encode.h"
#include "q15/internal.h"

static const char *const substrates[] = {"au", "cu", "al", "ti", "fe", "bk7"};
#define N_SUB 6

typedef struct de_stats {
    double sum, max;
    long n;
    char worst[96];
} de_stats;

static void de_add(de_stats *s, double de, const char *sub, double nf, double theta, double d)
{
    s->sum += de;
    s->n++;
    if (!(de <= s->max)) {
        s->max = de;
        snprintf(s->worst, sizeof s->worst, "%s n_f %.1f theta %g d %g", sub, nf, theta, d);
    }
}

static double clamp01(double x) { return x > 0.0 ? (x < 1.0 ? x : 1.0) : 0.0; }

/* The films of the default run, each fitted once for every check below. */
static const double films[] = {1.2, 1.8, 2.5};
#define N_FILMS 3
static film_model *fitted[N_SUB][N_FILMS];

static const film_model *fit_of(const gen_context *g, const film_model *poles, spectrum *const *s, int sub, int k)
{
    if (!fitted[sub][k]) {
        film_stack f;
        film_model *m = malloc(sizeof *m);
        f.n1 = 1.0;
        f.film = NULL;
        f.film_n = films[k];
        f.substrate = s[sub];
        if (!m)
            return NULL;
        *m = *poles;
        if (film_fit_material(&f, &g->cm, &g->cs, m)) {
            free(m);
            return NULL;
        }
        fitted[sub][k] = m;
    }
    return fitted[sub][k];
}

enum { T_MODEL, T_F32, T_Q15, T_F16, T_TYPES };
static const char *const type_names[] = {"double model", "binary32", "Q1.15", "binary16"};

static void de_matrix(const gen_context *g, const film_model *poles, spectrum *const *s, int full)
{
    lab_space ls;
    de_stats st[T_TYPES];
    film_model *m = malloc(sizeof *m), *m32 = malloc(sizeof *m32);
    fresnel_film *f32 = malloc(sizeof *f32);
    fresnel_film_q15 *q15 = malloc(sizeof *q15);
#if FRESNEL_HAS_F16
    fresnel_film_f16 *f16 = malloc(sizeof *f16);
#endif
    int n_films = full ? 14 : 3, theta_step = full ? 1 : 10, i, a, k, ty;
    double d_step = full ? 5.0 : 10.0;
    memset(st, 0, sizeof st);
    if (!m || !m32 || !f32 || !q15 || lab_space_init(&ls, &g->cs)) {
        CHECK("film: memory", 0, "out of memory");
        return;
    }
    for (i = 0; i < N_SUB; i++)
        for (k = 0; k < n_films; k++) {
            film_stack f;
            double nf = full ? 1.2 + 0.1 * k : films[k];
            const film_model *cached = full ? NULL : fit_of(g, poles, s, i, k);
            f.n1 = 1.0;
            f.film = NULL;
            f.film_n = nf;
            f.substrate = s[i];
            *m = *poles;
            if ((cached ? (*m = *cached, 0) : film_fit_material(&f, &g->cm, &g->cs, m)) || film_encode_q15(m, q15)) {
                CHECK("film: goal materials fit and encode", 0, "%s n_f %.1f", substrates[i], nf);
                continue;
            }
            film_encode_f32(m, f32);
#if FRESNEL_HAS_F16
            film_encode_f16(m, f16);
#endif
            for (a = full ? 0 : 5 * (k % 2); a <= 89; a = a + theta_step > 89 ? (a == 89 ? 90 : 89) : a + theta_step) {
                double c = cos(a * 3.14159265358979323846 / 180.0);
                film_optics_table *t = film_truth_prepare(&f, c);
                int n;
                for (n = 0; n * d_step <= 1000.0 && t; n++) {
                    double d = n * d_step, truth[3], rgb[T_TYPES][3], lab0[3], lab[3];
                    fresnel_rgb r32 = fresnel_film_rgb(f32, (float)c, (float)d);
                    fresnel_rgb_q15 rq = fresnel_film_q15_rgb(q15, (int32_t)floor(c * 32768.0 + 0.5),
                                                              (fresnel_q16)floor(d * 65536.0 + 0.5));
                    film_truth_at(t, &g->cm, &g->cs, d, truth);
                    for (ty = 0; ty < 3; ty++)
                        truth[ty] = clamp01(truth[ty]);
                    ref_film_model(m, c, d, 1, rgb[T_MODEL]);
                    rgb[T_F32][0] = r32.r;
                    rgb[T_F32][1] = r32.g;
                    rgb[T_F32][2] = r32.b;
                    rgb[T_Q15][0] = rq.r / 32768.0;
                    rgb[T_Q15][1] = rq.g / 32768.0;
                    rgb[T_Q15][2] = rq.b / 32768.0;
#if FRESNEL_HAS_F16
                    {
                        fresnel_rgb_f16 rh = fresnel_film_f16_rgb(f16, (fresnel_f16)c, (fresnel_f16)d);
                        rgb[T_F16][0] = (double)rh.r;
                        rgb[T_F16][1] = (double)rh.g;
                        rgb[T_F16][2] = (double)rh.b;
                    }
#else
                    memcpy(rgb[T_F16], rgb[T_MODEL], sizeof rgb[T_F16]); /* not reported */
#endif
                    lab_space_lab(&ls, truth, lab0);
                    for (ty = 0; ty < T_TYPES; ty++) {
                        lab_space_lab(&ls, rgb[ty], lab);
                        de_add(&st[ty], ciede2000(lab0, lab), substrates[i], nf, a, d);
                    }
                }
                free(t);
            }
        }
    for (ty = 0; ty < (FRESNEL_HAS_F16 ? T_TYPES : T_F16); ty++)
        NOTE("film CIEDE2000 vs spectral truth (clip policy), %s: mean %.3f max %.3f (%s) over %ld samples%s",
             type_names[ty], st[ty].sum / (double)(st[ty].n ? st[ty].n : 1), st[ty].max, st[ty].worst, st[ty].n,
             full ? " (full matrix)" : "");
    CHECK("film binary32: CIEDE2000 mean <= 0.5 and max <= 2.0 against the spectral truth",
          st[T_F32].sum / st[T_F32].n <= 0.5 && st[T_F32].max <= 2.0, "mean %.3f max %.3f",
          st[T_F32].sum / st[T_F32].n, st[T_F32].max);
#if FRESNEL_HAS_F16
    CHECK("film binary16: CIEDE2000 mean <= 1.0 against the spectral truth", st[T_F16].sum / st[T_F16].n <= 1.0,
          "mean %.3f", st[T_F16].sum / st[T_F16].n);
#endif
    CHECK("film Q1.15: CIEDE2000 mean <= 0.6 and max <= 2.5 against the spectral truth",
          st[T_Q15].sum / st[T_Q15].n <= 0.6 && st[T_Q15].max <= 2.5, "mean %.3f max %.3f",
          st[T_Q15].sum / st[T_Q15].n, st[T_Q15].max);
    free(m);
    free(m32);
    free(f32);
    free(q15);
#if FRESNEL_HAS_F16
    free(f16);
#endif
}

/* ---- hostile inputs: every type's result is in [0, 1] and equals the
 * result at the documented clamp of its input (c: NaN and -Inf as 0, +Inf
 * as 1; d: NaN and negative as 0, above FRESNEL_FILM_D_MAX as the
 * maximum); grazing light (c = 0) reflects (1, 1, 1) */

static int rgb_same(fresnel_rgb a, fresnel_rgb b) { return a.r == b.r && a.g == b.g && a.b == b.b; }
static int rgb_unit(fresnel_rgb a)
{
    return a.r >= 0.0f && a.r <= 1.0f && a.g >= 0.0f && a.g <= 1.0f && a.b >= 0.0f && a.b <= 1.0f;
}

static void test_hostile(const film_model *gold)
{
    static const float cs[] = {-INFINITY, -1.0f, -0.0f, 0.3f, 1.0f, 2.0f, INFINITY};
    static const float ds[] = {-INFINITY, -5.0f, -0.0f, 1e-30f, 400.0f, 5000.0f, 1e9f, INFINITY};
    film_model *m = malloc(sizeof *m);
    fresnel_film *f32 = malloc(sizeof *f32);
    fresnel_film_q15 *q15 = malloc(sizeof *q15);
    int ok32 = 1, okq = 1, i, k;
    double grazing = 0.0;
    if (!m || !f32 || !q15)
        return;
    if (!gold || film_encode_q15(gold, q15)) {
        CHECK("film hostile inputs: gold fits", 0, "fit failed");
        return;
    }
    *m = *gold;
    film_encode_f32(m, f32);
    for (i = 0; i < 7; i++)
        for (k = 0; k < 8; k++) {
            float c = cs[i], d = ds[k];
            float cc = c > 0.0f ? (c < 1.0f ? c : 1.0f) : 0.0f;
            float dc = d > 0.0f ? (d < FRESNEL_FILM_D_MAX ? d : FRESNEL_FILM_D_MAX) : 0.0f;
            fresnel_rgb o = fresnel_film_rgb(f32, c, d);
            ok32 &= rgb_unit(o) && rgb_same(o, fresnel_film_rgb(f32, cc, dc));
        }
    ok32 &= rgb_same(fresnel_film_rgb(f32, NAN, 300.0f), fresnel_film_rgb(f32, 0.0f, 300.0f));
    ok32 &= rgb_same(fresnel_film_rgb(f32, 0.6f, NAN), fresnel_film_rgb(f32, 0.6f, 0.0f));
    CHECK("film binary32: NaN, infinite, negative and huge inputs give the clamped input's result, in [0, 1]",
          ok32, "a result differs or leaves [0, 1]");
    {
        static const int32_t cq[] = {INT32_MIN, -1, 0, 9830, 32768, 32769, INT32_MAX};
        static const int32_t dq[] = {INT32_MIN, -1, 0, 1, 400 * 65536, FRESNEL_FILM_D_MAX_Q16, INT32_MAX};
        for (i = 0; i < 7; i++)
            for (k = 0; k < 7; k++) {
                int32_t cc = cq[i] < 0 ? 0 : (cq[i] > 32768 ? 32768 : cq[i]);
                int32_t dc = dq[k] < 0 ? 0 : (dq[k] > FRESNEL_FILM_D_MAX_Q16 ? FRESNEL_FILM_D_MAX_Q16 : dq[k]);
                fresnel_rgb_q15 o = fresnel_film_q15_rgb(q15, cq[i], dq[k]), e = fresnel_film_q15_rgb(q15, cc, dc);
                okq &= o.r <= 32768 && o.g <= 32768 && o.b <= 32768 && o.r == e.r && o.g == e.g && o.b == e.b;
            }
        CHECK("film Q1.15: extreme int32 cosines and thicknesses give the clamped input's result, in [0, one]",
              okq, "a result differs or leaves [0, 32768]");
    }
#if FRESNEL_HAS_F16
    {
        fresnel_film_f16 *f16 = malloc(sizeof *f16);
        int ok16 = 1;
        if (f16) {
            film_encode_f16(m, f16);
            for (i = 0; i < 7; i++)
                for (k = 0; k < 8; k++) {
                    fresnel_f16 c = (fresnel_f16)cs[i], d = (fresnel_f16)ds[k];
                    fresnel_f16 cc = c > (fresnel_f16)0.0f ? (c < (fresnel_f16)1.0f ? c : (fresnel_f16)1.0f) : (fresnel_f16)0.0f;
                    fresnel_f16 dc = d > (fresnel_f16)0.0f ? (d < (fresnel_f16)FRESNEL_FILM_D_MAX ? d : (fresnel_f16)FRESNEL_FILM_D_MAX) : (fresnel_f16)0.0f;
                    fresnel_rgb_f16 o = fresnel_film_f16_rgb(f16, c, d), e = fresnel_film_f16_rgb(f16, cc, dc);
                    ok16 &= o.r >= 0 && o.r <= 1 && o.g >= 0 && o.g <= 1 && o.b >= 0 && o.b <= 1 &&
                            (float)o.r == (float)e.r && (float)o.g == (float)e.g && (float)o.b == (float)e.b;
                }
            {
                fresnel_rgb_f16 o = fresnel_film_f16_rgb(f16, (fresnel_f16)NAN, (fresnel_f16)NAN);
                fresnel_rgb_f16 e = fresnel_film_f16_rgb(f16, (fresnel_f16)0.0f, (fresnel_f16)0.0f);
                ok16 &= (float)o.r == (float)e.r && (float)o.g == (float)e.g && (float)o.b == (float)e.b;
            }
            CHECK("film binary16: NaN, infinite, negative and huge inputs give the clamped input's result, in [0, 1]",
                  ok16, "a result differs or leaves [0, 1]");
            free(f16);
        }
    }
#endif
    for (k = 0; k < 8; k++) {
        fresnel_rgb o = fresnel_film_rgb(f32, 0.0f, ds[k]);
        fresnel_rgb_q15 oq = fresnel_film_q15_rgb(q15, 0, (fresnel_q16)(ds[k] > 0 && ds[k] < 5000.0f ? ds[k] * 65536.0f : 0.0f));
        grazing = fmax(grazing, fmax(1.0 - fmin(o.r, fmin(o.g, o.b)), 1.0 - fmin(oq.r, fmin(oq.g, oq.b)) / 32768.0));
    }
    CHECK("film at grazing incidence (c = 0) reflects (1, 1, 1) within 1e-4 at every thickness, binary32 and Q1.15",
          grazing <= 1e-4, "worst 1 - R %.3g", grazing);
    free(m);
    free(f32);
    free(q15);
}

/* ---- the fixed-point tables, recomputed from their definitions */
static void test_tables(void)
{
    int i, ok = 1;
    for (i = 0; i <= 256; i++)
        ok &= fresnel_i_film_sin_q15[i] == (uint16_t)floor(32768.0 * sin(3.14159265358979323846 / 2.0 * i / 256.0) + 0.5);
    for (i = 0; i <= 64; i++)
        ok &= fresnel_i_film_exp2_q15[i] == (uint16_t)floor(32768.0 * pow(2.0, -i / 64.0) + 0.5);
    for (i = 0; i <= 256; i++)
        ok &= fresnel_i_film_recip_q15[i] == (uint16_t)floor(32768.0 / (1.0 + i / 256.0) + 0.5);
    CHECK("film Q1.15 tables: quarter sine, 2^-x and 1/x recomputed entry by entry", ok, "an entry differs");
    CHECK("film tables per material within 8 KiB: binary32, Q1.15, binary16",
          sizeof(fresnel_film) <= 8192 && sizeof(fresnel_film_q15) <= 8192, "binary32 %u, Q1.15 %u bytes",
          (unsigned)sizeof(fresnel_film), (unsigned)sizeof(fresnel_film_q15));
    NOTE("film table bytes per material: binary32 %u, Q1.15 %u, binary16 %u", (unsigned)sizeof(fresnel_film),
         (unsigned)sizeof(fresnel_film_q15), (unsigned)(sizeof(fresnel_film) / 2));
}

/* ---- outside the goal matrix, measured: thick films (1000-5000 nm, the
 * truth's resolved range) and a film less dense than its ambient (total
 * reflection inside the film past its critical angle) */
static void test_outside_goal(const gen_context *g, const film_model *poles, spectrum *const *s)
{
    lab_space ls;
    film_model *m = malloc(sizeof *m);
    int pass, a, n;
    if (!m || lab_space_init(&ls, &g->cs))
        return;
    for (pass = 0; pass < 3; pass++) {
        film_stack f;
        double sum = 0.0, max = 0.0, sum_far = 0.0, max_far = 0.0, theta_c = 0.0;
        long cnt = 0, cnt_far = 0;
        f.n1 = pass == 2 ? 1.52 : 1.0;
        f.film = NULL;
        f.film_n = pass == 0 ? 2.5 : (pass == 1 ? 1.8 : 1.2);
        f.substrate = s[pass == 1 ? 5 : 0];
        if (pass == 2)
            theta_c = asin(1.2 / 1.52) * 180.0 / 3.14159265358979323846;
        *m = *poles;
        if (pass < 2 ? (fit_of(g, poles, s, pass == 1 ? 5 : 0, pass == 1 ? 1 : 2) == NULL ||
                        (*m = *fit_of(g, poles, s, pass == 1 ? 5 : 0, pass == 1 ? 1 : 2), 0))
                     : film_fit_material(&f, &g->cm, &g->cs, m))
            continue;
        for (a = 0; a <= 85; a += 5) {
            double c = cos(a * 3.14159265358979323846 / 180.0);
            film_optics_table *t = film_truth_prepare(&f, c);
            for (n = 0; n <= 40 && t; n++) {
                double d = pass == 2 ? n * 25.0 : 1000.0 + n * 100.0, truth[3], rgb[3], l0[3], l1[3], de;
                int ch;
                film_truth_at(t, &g->cm, &g->cs, d, truth);
                for (ch = 0; ch < 3; ch++)
                    truth[ch] = clamp01(truth[ch]);
                ref_film_model(m, c, d, 1, rgb);
                lab_space_lab(&ls, truth, l0);
                lab_space_lab(&ls, rgb, l1);
                de = ciede2000(l0, l1);
                sum += de;
                cnt++;
                max = fmax(max, de);
                if (fabs(a - theta_c) > 10.0) {
                    sum_far += de;
                    cnt_far++;
                    max_far = fmax(max_far, de);
                }
            }
            free(t);
        }
        if (pass < 2)
            NOTE("film %s under a %.1f film, d 1000-5000 nm, theta 0-85: CIEDE2000 mean %.3f max %.3f (double model)",
                 substrates[pass == 1 ? 5 : 0], f.film_n, sum / cnt, max);
        else {
            fresnel_film_q15 *q15 = malloc(sizeof *q15);
            NOTE("film gold under a 1.2 film in glass (1.52; critical angle %.1f deg), d 0-1000 nm: CIEDE2000 mean "
                 "%.3f max %.3f; more than 10 deg from the critical angle mean %.3f max %.3f (double model)",
                 theta_c, sum / cnt, max, sum_far / cnt_far, max_far);
            CHECK("film Q1.15 layout refuses the table of a film in total reflection (its A, B leave [-1, 1])",
                  q15 && film_encode_q15(m, q15) == -1, "encoded");
            free(q15);
        }
    }
    free(m);
}

/* The film's identities through the runtime: a film of no thickness, and a
 * film of the ambient's index at any thickness, are the bare substrate
 * (its spectral ground truth, held to [0, 1] as the runtime holds its
 * result), within CIEDE2000 0.1 (fresnel_film.h; measured 0.056): the
 * model is a fit there as everywhere. Every 5 degrees, every substrate. */
static void test_identities(const gen_context *g, const film_model *poles, spectrum *const *s)
{
    static const float ds[] = {0.0f, 250.0f, 1000.0f, 5000.0f};
    film_model *m = malloc(sizeof *m);
    fresnel_film *f32 = malloc(sizeof *f32);
    lab_space ls;
    double worst_d0 = 0.0, worst_n1 = 0.0;
    int i, a, k, ch;
    if (!m || !f32 || lab_space_init(&ls, &g->cs)) {
        CHECK("film identities: memory", 0, "out of memory");
        return;
    }
    for (i = 0; i < N_SUB; i++) {
        const film_model *thick = fit_of(g, poles, s, i, 1);
        film_stack f;
        f.n1 = 1.0;
        f.film = NULL;
        f.film_n = 1.0; /* the ambient's index */
        f.substrate = s[i];
        *m = *poles;
        if (!thick || film_fit_material(&f, &g->cm, &g->cs, m)) {
            CHECK("film identities: the substrates fit", 0, "%s", substrates[i]);
            continue;
        }
        for (a = 0; a <= 90; a += 5) {
            double c = a == 90 ? 0.0 : cos(a * 3.14159265358979323846 / 180.0), bare[3], lab0[3], lab[3], rgb[3];
            fresnel_rgb r;
            ground_truth(s[i], &g->cm, &g->cs, 1.0, c, bare);
            for (ch = 0; ch < 3; ch++)
                bare[ch] = fmin(fmax(bare[ch], 0.0), 1.0);
            lab_space_lab(&ls, bare, lab0);
            film_encode_f32(thick, f32); /* a 1.8 film of no thickness */
            r = fresnel_film_rgb(f32, (float)c, 0.0f);
            rgb[0] = r.r, rgb[1] = r.g, rgb[2] = r.b;
            lab_space_lab(&ls, rgb, lab);
            worst_d0 = fmax(worst_d0, ciede2000(lab0, lab));
            film_encode_f32(m, f32); /* a film of the ambient's index */
            for (k = 0; k < 4; k++) {
                r = fresnel_film_rgb(f32, (float)c, ds[k]);
                rgb[0] = r.r, rgb[1] = r.g, rgb[2] = r.b;
                lab_space_lab(&ls, rgb, lab);
                worst_n1 = fmax(worst_n1, ciede2000(lab0, lab));
            }
        }
    }
    NOTE("film identities, binary32 against the bare substrate's truth: d = 0 (a 1.8 film) CIEDE2000 max %.3f; "
         "n_f = n1 at 0, 250, 1000, 5000 nm max %.3f", worst_d0, worst_n1);
    CHECK("film binary32 of no thickness is the bare substrate within CIEDE2000 0.1", worst_d0 <= 0.1, "max %.3f",
          worst_d0);
    CHECK("film binary32 of the ambient's index is the bare substrate at every thickness within CIEDE2000 0.1",
          worst_n1 <= 0.1, "max %.3f", worst_n1);
    free(m);
    free(f32);
}

int main(void)
{
    gen_context *g = malloc(sizeof *g);
    film_model *poles = malloc(sizeof *poles);
    spectrum *s[N_SUB];
    double pole_error = 0.0;
    int i, ok = g && poles;
    for (i = 0; i < N_SUB; i++) {
        s[i] = malloc(sizeof *s[i]);
        ok = ok && s[i];
    }
    if (!ok || gen_context_load(data_dir(NULL), "srgb", g)) {
        CHECK("film: data loads", 0, "colorimetry missing");
        return harness_exit();
    }
    for (i = 0; i < N_SUB; i++)
        if (spectrum_load(data_dir(NULL), substrates[i], s[i])) {
            CHECK("film: substrates load", 0, "%s", substrates[i]);
            return harness_exit();
        }
    CHECK("film poles: the observer's six-pole fit converges within 0.02 of S(0)",
          film_fit_poles(&g->cm, &g->cs, poles, &pole_error) == 0 && pole_error <= 0.02, "max error %.4g",
          pole_error);
    test_tables();
    test_hostile(fit_of(g, poles, s, 0, 2));
    test_outside_goal(g, poles, s);
    test_identities(g, poles, s);
    de_matrix(g, poles, s, getenv("FILM_FULL") != NULL);
    for (i = 0; i < N_SUB; i++) {
        int k;
        for (k = 0; k < N_FILMS; k++)
            free(fitted[i][k]);
        free(s[i]);
    }
    free(poles);
    free(g);
    return harness_exit();
}
