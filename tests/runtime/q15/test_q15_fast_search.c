/* The Q1.15 fast paths (fresnel_fixed_fast.h) held to their bounds by a
 * search for the worst case (tests/common/search.h) over every input code of
 * their documented domains, where tests/runtime/q15/test_q15_fast.c sweeps grids
 * and material sets:
 *   fresnel_schlick_q15_fast: (F0 code, c code), FRESNEL_BOUND_SCHLICK_Q15_FAST
 *     (the long pass: every pair);
 *   fresnel_f82_q15_fast: (F0 code, F82 code, c code), a_q12 as the host
 *     prepares it, against fresnel_f82 at the codes, every c code at the
 *     four (F0, F82) corners first; FRESNEL_BOUND_F82_Q15_FAST;
 *   fresnel_conductor_q15_fast: (log10 eta, log10 kappa, c code) inside
 *     FRESNEL_CONDUCTOR_*_Q15_FAST's domain (q15_conductor_fast_in_domain;
 *     a point outside it counts as no error), FRESNEL_BOUND_CONDUCTOR_Q15_FAST.
 * Results outside [0, one] count as an infinite error. The long pass
 * (SEARCH_LONG=1, make search) writes the corpus
 * tests/data/worst_inputs/fast.txt that the fast pass replays. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fresnel_fixed.h"
#include "fresnel_fixed_fast.h"
#include "harness.h"
#include "search.h"
#include "3_encode/q15_params.h"
#include "common/reference.h"

#define CORPUS "tests/data/worst_inputs/fast.txt"

static double lsb(int32_t got, double ref)
{
    return got < 0 || got > 32768 ? HUGE_VAL : fabs(got / 32768.0 - ref) * 32768.0;
}

static double schlick_error(void *ctx, const double *x)
{
    int32_t f0 = (int32_t)x[0], c = (int32_t)x[1];
    (void)ctx;
    return lsb(fresnel_schlick_q15_fast(f0, c), ref_schlick(f0 / 32768.0, c / 32768.0));
}

static double f82_error(void *ctx, const double *x)
{
    int32_t f0 = (int32_t)x[0], f82 = (int32_t)x[1], c = (int32_t)x[2];
    (void)ctx;
    return lsb(fresnel_f82_q15_fast(f0, q15_f82_a_q12(f0, f82), c),
               ref_f82(f0 / 32768.0, f82 / 32768.0, c / 32768.0));
}

static double conductor_error(void *ctx, const double *x)
{
    double eta = pow(10.0, x[0]), kappa = x[1] < -4.0 ? 0.0 : pow(10.0, x[1]);
    int32_t c = (int32_t)x[2];
    fresnel_conductor_prep_q15_fast p;
    (void)ctx;
    if (!q15_conductor_fast_in_domain(eta, kappa))
        return 0.0;
    q15_conductor_fast(eta, kappa, &p);
    return lsb(fresnel_conductor_q15_fast(&p, c), ref_conductor(eta, kappa, c / 32768.0));
}

static void run(const char *name, search_error_fn *fn, const search_space *sp, double bound, long random_n,
                const double (*seeds)[SEARCH_DIMS], int n_seeds)
{
    search_state s;
    char label[160];
    int i;
    search_init(&s, sp, fn, NULL, 0xFA57u + (uint64_t)sp->dims);
    search_corpus(&s, CORPUS, name);
    for (i = 0; i < n_seeds; i++)
        search_eval(&s, seeds[i]);
    if (fn == f82_error) { /* every c code at the four (F0, F82) corners, where a is largest */
        double x[SEARCH_DIMS] = {0};
        for (i = 0; i < 4 * 32769; i++) {
            x[0] = i / 32769 % 2 ? 32768.0 : 0.0;
            x[1] = i / 32769 / 2 ? 32768.0 : 0.0;
            x[2] = i % 32769;
            search_eval(&s, x);
        }
    }
    search_random(&s, random_n);
    search_climb(&s, search_long() ? 12 : 6, 64);
    search_corpus_write(&s, name, 3);
    printf("NOTE search q15 fast %-10s max|err| %.4g LSB at", name, s.top[0].err);
    for (i = 0; i < sp->dims; i++)
        printf(" %.9g", s.top[0].x[i]);
    printf(", %ld evaluations\n", s.evals);
    snprintf(label, sizeof label, "fixed fast %s: results in [0, one] and within the stated bound (searched)", name);
    CHECK(label, s.top[0].err <= bound, "max|err| %.4g LSB, bound %.4g", s.top[0].err, bound);
}

/* fresnel_schlick_q15_fast at every (F0, c) code pair: the space is small
 * enough (2^30 pairs, seconds) for the long pass to leave nothing out. */
static void schlick_exhaustive(void)
{
    double worst = 0.0;
    int32_t f0, c, wf = 0, wc = 0;
    for (f0 = 0; f0 <= 32768; f0++)
        for (c = 0; c <= 32768; c++) {
            double e = lsb(fresnel_schlick_q15_fast(f0, c), ref_schlick(f0 / 32768.0, c / 32768.0));
            if (!(e <= worst)) {
                worst = e;
                wf = f0;
                wc = c;
            }
        }
    printf("NOTE q15 fast schlick, every (F0, c) code: max|err| %.4g LSB at %d %d\n", worst, (int)wf, (int)wc);
    {
        const char *path = getenv("SEARCH_CORPUS_OUT");
        FILE *f = path ? fopen(path, "a") : NULL;
        if (f) {
            fprintf(f, "schlick %d %d # %.6g\n", (int)wf, (int)wc, worst);
            fclose(f);
        }
    }
    CHECK("fixed fast schlick: every (F0, c) code within the stated bound", worst <= FRESNEL_BOUND_SCHLICK_Q15_FAST,
          "max|err| %.4g LSB at F0 %d c %d", worst, (int)wf, (int)wc);
}

int main(void)
{
    long n = search_long() ? 4000000 : 150000;
    search_space sp;
    /* the corners: F0 0 and one, F82 at both ends, grazing and normal light */
    static const double corners[][SEARCH_DIMS] = {{0, 32768, 0, 0},     {0, 32768, 4654, 0}, {0, 32768, 32768, 0},
                                                  {32768, 0, 4654, 0},  {0, 0, 1, 0},        {32768, 32768, 1, 0},
                                                  {16384, 32768, 4654, 0}};
    /* the domain's corners: eta at its ends, kappa 0 and 16, the matched index */
    static const double dom[][SEARCH_DIMS] = {{-1.5228787, 1.2041200, 1, 0}, {0.9030900, 1.2041200, 32768, 0},
                                              {-1.1549020, -5.0, 12000, 0},  {0.9030900, -5.0, 100, 0},
                                              {0.0004, -5.0, 4000, 0}};
    memset(&sp, 0, sizeof sp);
    sp.dims = 2;
    sp.hi[0] = sp.hi[1] = 32768.0;
    sp.quantum[0] = sp.quantum[1] = 1.0;
    run("schlick", schlick_error, &sp, FRESNEL_BOUND_SCHLICK_Q15_FAST, n, corners, 6);
    if (search_long())
        schlick_exhaustive();
    sp.dims = 3;
    sp.hi[2] = 32768.0;
    sp.quantum[2] = 1.0;
    run("f82", f82_error, &sp, FRESNEL_BOUND_F82_Q15_FAST, n, corners, 7);
    sp.lo[0] = log10(FRESNEL_CONDUCTOR_ETA_MIN_Q15_FAST), sp.hi[0] = log10(FRESNEL_CONDUCTOR_ETA_MAX_Q15_FAST);
    sp.lo[1] = -4.5, sp.hi[1] = log10(FRESNEL_CONDUCTOR_KAPPA_MAX_Q15_FAST);
    sp.quantum[0] = sp.quantum[1] = 0.0;
    run("conductor", conductor_error, &sp, FRESNEL_BOUND_CONDUCTOR_Q15_FAST, n / 3, dom, 5);
    return harness_exit();
}
