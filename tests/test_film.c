/* The thin-film runtime (fresnel_film.h): each number type against the
 * double evaluation of its own constants (gen/model/reference_film.c),
 * hostile inputs, the fixed-point tables, and CIEDE2000 against the
 * film's spectral truth over the goal matrix: films n_f 1.2-2.5 on Au, Cu,
 * Al, Ti, Fe and BK7 in air, theta 0-89 degrees, d 0-1000 nm.
 *
 * The default run samples that matrix: films 1.2, 1.5, 1.8, 2.1, 2.5 (the
 * ends and three between: the error grows with n_f, whose reflection at
 * the film's top makes the fringes deep), theta every 5 degrees and 89
 * (the model's table has a node every 1/31 in cos(theta), every 2-3
 * degrees near normal incidence and 0.3-2 near grazing, so steps of 5
 * degrees fall between nodes as often as on them), d every 10 nm (a
 * tenth of the fastest fringe period at n_f 2.5). FILM_FULL=1 runs the
 * whole matrix (n_f every 0.1, every degree, every 5 nm: minutes). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "harness.h"
#include "1_spectral/colour_difference.h"
#include "2_derive/derive.h"
#include "2_derive/film_fit.h"
#include "3_encode/film_encode.h"

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

enum { T_MODEL, T_F32, T_Q15, T_F16, T_TYPES };
static const char *const type_names[] = {"double model", "binary32", "Q1.15", "binary16"};

static void de_matrix(const gen_context *g, const film_model *poles, spectrum *const *s, int full)
{
    static const double films_sample[] = {1.2, 1.5, 1.8, 2.1, 2.5};
    lab_space ls;
    de_stats st[T_TYPES];
    film_model *m = malloc(sizeof *m), *m32 = malloc(sizeof *m32);
    fresnel_film *f32 = malloc(sizeof *f32);
    fresnel_film_q15 *q15 = malloc(sizeof *q15);
#if FRESNEL_HAS_F16
    fresnel_film_f16 *f16 = malloc(sizeof *f16);
#endif
    int n_films = full ? 14 : 5, theta_step = full ? 1 : 5, i, a, k, ty;
    double d_step = full ? 5.0 : 10.0;
    memset(st, 0, sizeof st);
    if (!m || !m32 || !f32 || !q15 || lab_space_init(&ls, &g->cs)) {
        CHECK("film: memory", 0, "out of memory");
        return;
    }
    for (i = 0; i < N_SUB; i++)
        for (k = 0; k < n_films; k++) {
            film_stack f;
            double nf = full ? 1.2 + 0.1 * k : films_sample[k];
            f.n1 = 1.0;
            f.film = NULL;
            f.film_n = nf;
            f.substrate = s[i];
            *m = *poles;
            if (film_fit_material(&f, &g->cm, &g->cs, m) || film_encode_q15(m, q15)) {
                CHECK("film: goal materials fit and encode", 0, "%s n_f %.1f", substrates[i], nf);
                continue;
            }
            film_encode_f32(m, f32);
#if FRESNEL_HAS_F16
            film_encode_f16(m, f16);
#endif
            for (a = 0; a <= 89; a = a == 85 ? 89 : a + theta_step) {
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
                    memcpy(rgb[T_F16], rgb[T_MODEL], sizeof rgb[T_F16]);
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
    for (ty = 0; ty < T_TYPES; ty++)
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
    de_matrix(g, poles, s, getenv("FILM_FULL") != NULL);
    for (i = 0; i < N_SUB; i++)
        free(s[i]);
    free(poles);
    free(g);
    return harness_exit();
}
