/* The thin film's error bounds (fresnel_film.h: FRESNEL_BOUND_FILM, _Q15,
 * _F16) held to a search for the worst case (tests/common/search.h), each number
 * type against the double model of its own stored constants
 * (gen/common/reference_film.c), over the film model's domain.
 * passes: first other (tests/runtime/thin_film/test_film.c runs the film's runtime under the sanitizers)
 *
 * Per stack (incident medium n1, film n_f, substrate) and type, over
 * (cosine, thickness):
 *   - Q1.15: every cosine code 0-32768 at the thicknesses 0, 1/65536 nm,
 *     FRESNEL_FILM_D_MAX and thirteen between (a fringe period of n_f 2.5
 *     at 380 nm is 76 nm: the sweep sees every phase over the codes; the
 *     fast pass every third of them), then random (c, d) codes and local
 *     maximisation from the worst;
 *   - binary16: every binary16 cosine in [0, 1] at the same thicknesses,
 *     then random and local in the binary16 values;
 *   - binary32: cosines 0, 1 and every 1/4096 at those thicknesses, then
 *     random and local maximisation in (c, d) as floats.
 * Stacks: the fast pass (make test) takes the corpus's stacks (the worst
 * found by the long pass, tests/data/worst_inputs/film.txt) and the goal
 * substrates (Au, Cu, Al, Ti, Fe, BK7) under a 2.5 film in air;
 * the long pass (SEARCH_LONG=1, make search) a film of the ambient's
 * index and films 1.0-4.0 by 0.5 on twelve substrates (the goal's, Ag,
 * Cr, Si, water, diamond, SF11) in air, water (1.33), 1.4,
 * glass (1.5) and the densest ambient that keeps a dielectric substrate in
 * the model's domain (its edge, by bisection), every stack in the domain
 * (film_stack_domain). FILM_SEARCH_STACK="n1 n_f substrate" searches one
 * stack, FILM_SEARCH_STACK="edge substrate" the films at its domain's
 * edge; FILM_SEARCH_VERBOSE=1 prints each stack's maxima. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "harness.h"
#include "search.h"
#include "1_spectral/spectral.h"
#include "2_derive/derive.h"
#include "2_derive/film_fit.h"
#include "3_encode/film_encode.h"

#define CORPUS "tests/data/worst_inputs/film.txt"

enum { T_F32, T_Q15, T_F16, T_TYPES };
static const char *const type_key[] = {"f32", "q15", "f16"};

typedef struct film_case {
    film_model ref[T_TYPES]; /* each type's table decoded: the double model of its constants */
    fresnel_film f32;
    fresnel_film_q15 q15;
#if FRESNEL_HAS_F16
    fresnel_film_f16 f16;
#endif
    int type;
} film_case;

static double chan_err(const double ref[3], double r, double g, double b)
{
    return fmax(fabs(r - ref[0]), fmax(fabs(g - ref[1]), fabs(b - ref[2])));
}

/* x[0] cosine, x[1] thickness: Q1.15 in codes (c Q15, d Q16.16), else in
 * the type's own values (rounded to it here). Error: binary32 and
 * binary16 absolute, Q1.15 in LSB. */
static double film_error(void *ctx, const double *x)
{
    film_case *k = ctx;
    double r[3];
    if (k->type == T_Q15) {
        int32_t c = (int32_t)x[0], d = (int32_t)x[1];
        fresnel_rgb_q15 o = fresnel_film_q15_rgb(&k->q15, c, d);
        ref_film_model(&k->ref[T_Q15], c / 32768.0, d / 65536.0, 1, r);
        return 32768.0 * chan_err(r, o.r / 32768.0, o.g / 32768.0, o.b / 32768.0);
    }
#if FRESNEL_HAS_F16
    if (k->type == T_F16) {
        fresnel_f16 c = (fresnel_f16)x[0], d = (fresnel_f16)x[1];
        fresnel_rgb_f16 o = fresnel_film_f16_rgb(&k->f16, c, d);
        ref_film_model(&k->ref[T_F16], (double)c, (double)d, 1, r);
        return chan_err(r, (double)o.r, (double)o.g, (double)o.b);
    }
#endif
    {
        float c = (float)x[0], d = (float)x[1];
        fresnel_rgb o = fresnel_film_rgb(&k->f32, c, d);
        ref_film_model(&k->ref[T_F32], c, d, 1, r);
        return chan_err(r, o.r, o.g, o.b);
    }
}

static const double sweep_d[] = {0.0, 1.0 / 65536.0, 17.0, 49.5, 96.25, 131.0, 184.65, 222.2, 266.25, 350.0,
                                 512.0, 777.7, 1000.0, 2500.0, 3333.3, 5000.0};
#define N_SWEEP_D (int)(sizeof sweep_d / sizeof sweep_d[0])

/* The next binary16 value above x (x >= 0, finite). */
static double f16_next(double x)
{
    int e;
    double m;
    if (x < 6.103515625e-05)
        return x + 5.9604644775390625e-08; /* 2^-24, the subnormal spacing */
    m = frexp(x, &e);                      /* x = m 2^e, m in [0.5, 1) */
    (void)m;
    return x + ldexp(1.0, e - 11);
}

static const char *const tnames[] = {"binary32", "Q1.15", "binary16"};

typedef struct worst_of {
    double err;
    char where[160];
} worst_of;

/* The search over one stack and type; returns the largest error found. */
static double search_stack(film_case *k, int type, const char *stack_key, long random_n, int climb, worst_of *w)
{
    search_space sp;
    search_state s;
    char key[160];
    int di;
    memset(&sp, 0, sizeof sp);
    sp.dims = 2;
    k->type = type;
    if (type == T_Q15) {
        sp.hi[0] = 32768.0;
        sp.hi[1] = FRESNEL_FILM_D_MAX_Q16;
        sp.quantum[0] = sp.quantum[1] = 1.0;
    } else {
        sp.hi[0] = 1.0;
        sp.hi[1] = FRESNEL_FILM_D_MAX;
    }
    search_init(&s, &sp, film_error, k, 0x51F7u + (uint64_t)type);
    snprintf(key, sizeof key, "%s:%s", type_key[type], stack_key);
    search_corpus(&s, CORPUS, key);
    for (di = 0; di < N_SWEEP_D; di += search_long() ? 1 : 3) { /* the fast pass: every third */
        double x[2];
        x[1] = type == T_Q15 ? floor(sweep_d[di] * 65536.0 + 0.5) : sweep_d[di];
        if (type == T_Q15)
            for (x[0] = 0.0; x[0] <= 32768.0; x[0] += 1.0)
                search_eval(&s, x);
        else if (type == T_F16)
            for (x[0] = 0.0; x[0] <= 1.0; x[0] = f16_next(x[0]))
                search_eval(&s, x);
        else {
            int i;
            for (i = 0; i <= 4096; i++) {
                x[0] = i / 4096.0;
                search_eval(&s, x);
            }
        }
    }
    search_random(&s, random_n);
    search_climb(&s, climb, 48);
    search_corpus_write(&s, key, 3);
    if (s.top[0].err > w->err) {
        w->err = s.top[0].err;
        if (type == T_Q15)
            snprintf(w->where, sizeof w->where, "%s c %.0f d %.0f (Q16.16)", stack_key, s.top[0].x[0], s.top[0].x[1]);
        else
            snprintf(w->where, sizeof w->where, "%s c %.9g d %.9g", stack_key, s.top[0].x[0], s.top[0].x[1]);
    }
    return s.top[0].err;
}

typedef struct stack_spec {
    double n1, nf;
    const char *sub;
} stack_spec;

/* One stack: fit, domain, encode, search every type. */
static void run_stack(const gen_context *g, const film_model *poles, const stack_spec *st, long random_n, int climb,
                      film_case *k, worst_of w[T_TYPES])
{
    spectrum *sub = malloc(sizeof *sub);
    film_model *m = malloc(sizeof *m);
    film_stack f;
    char key[96], why[256];
    int ty;
    if (!sub || !m || spectrum_load(data_dir(NULL), st->sub, sub)) {
        CHECK("film search: substrate loads", 0, "%s", st->sub);
        goto done;
    }
    f.n1 = st->n1;
    f.film = NULL;
    f.film_n = st->nf;
    f.substrate = sub;
    snprintf(key, sizeof key, "%s/%.4g/%.4g", st->sub, st->nf, st->n1);
    if (film_stack_domain(&f, why, sizeof why))
        goto done; /* outside the domain: refused by the tool, not bounded */
    *m = *poles;
    if (film_fit_material(&f, &g->cm, &g->cs, m) || film_encode_q15(m, &k->q15)) {
        CHECK("film search: a stack in the domain fits and encodes", 0, "%s", key);
        goto done;
    }
    film_encode_f32(m, &k->f32);
    film_decode_f32(&k->f32, &k->ref[T_F32]);
    film_decode_q15(&k->q15, &k->ref[T_Q15]);
#if FRESNEL_HAS_F16
    film_encode_f16(m, &k->f16);
    film_decode_f16(&k->f16, &k->ref[T_F16]);
#endif
    for (ty = 0; ty < (FRESNEL_HAS_F16 ? T_TYPES : T_F16); ty++) {
        double e = search_stack(k, ty, key, random_n, climb, &w[ty]);
        if (getenv("FILM_SEARCH_VERBOSE"))
            printf("NOTE film search %-16s %-8s %.4g\n", key, tnames[ty], e);
    }
done:
    free(sub);
    free(m);
}

/* The stacks of the corpus with the largest errors, `per_type` distinct
 * ones per type (keys "TYPE:SUBSTRATE/N_F/N1"); the count. */
static int corpus_stacks(stack_spec *out, char (*subs)[32], int per_type)
{
    struct {
        double err;
        int type;
        char sub[32];
        double nf, n1;
    } best[T_TYPES][8];
    char line[512];
    int n = 0, ty, i, j;
    FILE *f = fopen(CORPUS, "r");
    memset(best, 0, sizeof best);
    if (!f)
        return 0;
    while (fgets(line, sizeof line, f)) {
        char type[8], sub[32];
        double nf, n1, err;
        const char *hash = strchr(line, '#');
        if (!hash || sscanf(line, "%7[^:]:%31[^/]/%lf/%lf", type, sub, &nf, &n1) != 4 ||
            sscanf(hash + 1, "%lf", &err) != 1)
            continue;
        for (ty = 0; ty < T_TYPES && strcmp(type, type_key[ty]); ty++)
            ;
        if (ty == T_TYPES)
            continue;
        for (i = 0; i < per_type && !(best[ty][i].nf == nf && best[ty][i].n1 == n1 && !strcmp(best[ty][i].sub, sub));
             i++)
            ;
        if (i < per_type) { /* the stack is kept: its best error */
            if (err > best[ty][i].err)
                best[ty][i].err = err;
        } else if (err > best[ty][per_type - 1].err) {
            i = per_type - 1;
            best[ty][i].err = err;
            snprintf(best[ty][i].sub, sizeof best[ty][i].sub, "%s", sub);
            best[ty][i].nf = nf;
            best[ty][i].n1 = n1;
        } else
            continue;
        for (; i > 0 && best[ty][i - 1].err < best[ty][i].err; i--) {
            double e = best[ty][i].err;
            char sv[32];
            double a = best[ty][i].nf, b = best[ty][i].n1;
            snprintf(sv, sizeof sv, "%s", best[ty][i].sub);
            best[ty][i] = best[ty][i - 1];
            best[ty][i - 1].err = e;
            snprintf(best[ty][i - 1].sub, sizeof best[ty][i - 1].sub, "%s", sv);
            best[ty][i - 1].nf = a;
            best[ty][i - 1].n1 = b;
        }
    }
    fclose(f);
    for (ty = 0; ty < T_TYPES; ty++)
        for (i = 0; i < per_type && best[ty][i].err > 0.0; i++) {
            for (j = 0; j < n && !(out[j].nf == best[ty][i].nf && out[j].n1 == best[ty][i].n1 &&
                                   !strcmp(out[j].sub, best[ty][i].sub));
                 j++)
                ;
            if (j < n)
                continue;
            snprintf(subs[n], 32, "%s", best[ty][i].sub);
            out[n].sub = subs[n];
            out[n].nf = best[ty][i].nf;
            out[n].n1 = best[ty][i].n1;
            n++;
        }
    return n;
}

/* The densest incident medium (n1 <= 4) in which the substrate is still in
 * the domain, by bisection: the stacks at the domain's edge; 0 where every
 * n1 up to 4 is inside (a metal). */
static double domain_edge_n1(const char *sub_id)
{
    spectrum *sub = malloc(sizeof *sub);
    film_stack f;
    char why[256];
    double lo = 1.0, hi = 4.0;
    int i;
    if (!sub || spectrum_load(data_dir(NULL), sub_id, sub)) {
        free(sub);
        return 0.0;
    }
    f.film = NULL;
    f.film_n = 4.0;
    f.substrate = sub;
    f.n1 = hi;
    if (film_stack_domain(&f, why, sizeof why) == 0) {
        free(sub);
        return 0.0;
    }
    for (i = 0; i < 40; i++) {
        f.n1 = 0.5 * (lo + hi);
        if (film_stack_domain(&f, why, sizeof why) == 0)
            lo = f.n1;
        else
            hi = f.n1;
    }
    free(sub);
    return floor(lo * 1000.0) / 1000.0; /* inside, and exact in the corpus's keys */
}

/* The long pass's stacks on one substrate: a film of the ambient's index
 * and films 1.0-4.0 by 0.5 in air, 1.33, 1.4, 1.5 and at the domain's edge
 * (edge_only: there alone). */
static void long_substrate(const gen_context *g, const film_model *poles, const char *sub, int edge_only,
                           long random_n, int climb, film_case *k, worst_of w[T_TYPES])
{
    double n1s[5] = {1.0, 1.33, 1.4, 1.5, 0.0};
    int a, c;
    n1s[4] = domain_edge_n1(sub);
    for (a = edge_only ? 4 : 0; a < 5; a++)
        for (c = -1; c <= 6; c++) {
            stack_spec st;
            st.n1 = n1s[a];
            st.nf = c < 0 ? st.n1 : 1.0 + 0.5 * c; /* a film of the ambient's index, then the grid */
            st.sub = sub;
            if (st.n1 > 0.0 && st.nf >= st.n1 && (c < 0 || st.nf > st.n1))
                run_stack(g, poles, &st, random_n, climb, k, w);
        }
}

int main(void)
{
    static const char *const goal[] = {"au", "cu", "al", "ti", "fe", "bk7"};
    gen_context *g = malloc(sizeof *g);
    film_model *poles = malloc(sizeof *poles);
    film_case *k = malloc(sizeof *k);
    worst_of w[T_TYPES];
    int longpass = search_long(), i;
    long random_n = longpass ? 60000 : 20000;
    int climb = longpass ? 6 : 4;
    const char *only = getenv("FILM_SEARCH_STACK"); /* "n1 nf substrate", or "edge substrate" */
    memset(w, 0, sizeof w);
    if (!g || !poles || !k || gen_context_load(data_dir(NULL), "srgb", g) ||
        film_fit_poles(&g->cm, &g->cs, poles, NULL)) {
        CHECK("film search: data loads and the poles fit", 0, "failed");
        return harness_exit();
    }
    if (only) {
        stack_spec st;
        char sub[32];
        if (sscanf(only, "edge %31s", sub) == 1)
            long_substrate(g, poles, sub, 1, random_n, climb, k, w);
        else if (sscanf(only, "%lf %lf %31s", &st.n1, &st.nf, sub) == 3) {
            st.sub = sub;
            run_stack(g, poles, &st, random_n, climb, k, w);
        }
    } else if (longpass) {
        static const char *const subs[] = {"au", "cu", "al", "ti", "fe", "ag", "cr", "si",
                                           "bk7", "water", "diamond", "sf11"};
        for (i = 0; i < 12; i++)
            long_substrate(g, poles, subs[i], 0, random_n, climb, k, w);
    } else {
        stack_spec st[12 + 3 * T_TYPES];
        char subs[3 * T_TYPES][32];
        int n = corpus_stacks(st, subs, 3), j;
        for (i = 0; i < 6; i++) {
            stack_spec goal_st;
            goal_st.n1 = 1.0;
            goal_st.nf = 2.5;
            goal_st.sub = goal[i];
            for (j = 0; j < n && !(st[j].n1 == 1.0 && st[j].nf == goal_st.nf && !strcmp(st[j].sub, goal_st.sub)); j++)
                ;
            if (j == n)
                st[n++] = goal_st;
        }
        for (i = 0; i < n; i++)
            run_stack(g, poles, &st[i], random_n, climb, k, w);
    }
    NOTE("film search, worst found against the double model of the same constants: binary32 %.3g (%s), "
         "Q1.15 %.2f LSB (%s), binary16 %.3g (%s)",
         w[T_F32].err, w[T_F32].where, w[T_Q15].err, w[T_Q15].where, w[T_F16].err, w[T_F16].where);
    CHECK("film binary32 within FRESNEL_BOUND_FILM of the double model of its constants (searched)",
          w[T_F32].err <= FRESNEL_BOUND_FILM, "%.3g at %s", w[T_F32].err, w[T_F32].where);
    CHECK("film Q1.15 within FRESNEL_BOUND_FILM_Q15 LSB of the double model of its constants (searched)",
          w[T_Q15].err <= FRESNEL_BOUND_FILM_Q15, "%.2f LSB at %s", w[T_Q15].err, w[T_Q15].where);
#if FRESNEL_HAS_F16
    CHECK("film binary16 within FRESNEL_BOUND_FILM_F16 of the double model of its constants (searched)",
          w[T_F16].err <= FRESNEL_BOUND_FILM_F16, "%.3g at %s", w[T_F16].err, w[T_F16].where);
#endif
    free(g);
    free(poles);
    free(k);
    return harness_exit();
}
