/* A search for the worst case of an error over a box of inputs: what every
 * stated error bound is held to. A grid finds the largest error at its own
 * points; rounding error is jagged and its peaks fall between them, so the
 * bound is what this search could not beat:
 *   1. the caller's dense sweeps where the error concentrates (grazing
 *      incidence, critical angles, fringe extrema, the ends of each range),
 *      and the regression corpus of earlier worst inputs, through
 *      search_eval;
 *   2. search_random: uniform samples over the box (deterministic: the
 *      generator is seeded, so a run is repeatable and a failure replays;
 *      SEARCH_SEED=N moves a run to other points);
 *   3. search_climb: from each of the best points kept so far, a local
 *      random search whose radius shrinks from a sixteenth of the box to
 *      one input code (or 1e-9 of the range for a continuous input):
 *      a move to any better neighbour, the radius halved after a round
 *      without one. Rounding error has no gradient, so the search samples
 *      rather than steps.
 * Inputs with a quantum (a Q1.15 code, a binary16 value's spacing through a
 * caller's rounding) are rounded to it before each evaluation, so every
 * point evaluated is an input the runtime can receive.
 *
 * The corpus (one file per check in tests/data/worst_inputs/) holds lines
 * "key x0 x1 ... # err" for the best points of earlier long runs;
 * search_corpus replays the lines of one key, and with SEARCH_CORPUS_OUT set a run appends its best points
 * there (`make search` rewrites the corpus from the long pass). */
#ifndef FRESNEL_TESTS_SEARCH_H
#define FRESNEL_TESTS_SEARCH_H

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define SEARCH_DIMS 4
#define SEARCH_TOP 12

typedef double search_error_fn(void *ctx, const double *x);

typedef struct search_space {
    int dims;
    double lo[SEARCH_DIMS], hi[SEARCH_DIMS];
    /* 0: continuous; > 0: inputs are multiples of it (a code's spacing) */
    double quantum[SEARCH_DIMS];
} search_space;

typedef struct search_point {
    double err;
    double x[SEARCH_DIMS];
} search_point;

typedef struct search_state {
    search_space sp;
    search_error_fn *fn;
    void *ctx;
    search_point top[SEARCH_TOP]; /* the best distinct points, worst first */
    int n_top;
    long evals;
    uint64_t rng;
} search_state;

static void search_init(search_state *s, const search_space *sp, search_error_fn *fn, void *ctx, uint64_t seed)
{
    const char *extra = getenv("SEARCH_SEED"); /* another long run explores other points */
    if (extra)
        seed += 0x10000u * (uint64_t)strtoul(extra, NULL, 10);
    memset(s, 0, sizeof *s);
    s->sp = *sp;
    s->fn = fn;
    s->ctx = ctx;
    s->rng = seed * 0x9E3779B97F4A7C15ull + 0x2545F4914F6CDD1Dull;
}

/* uniform in [0, 1) (xorshift64*) */
static double search_uniform(search_state *s)
{
    s->rng ^= s->rng >> 12;
    s->rng ^= s->rng << 25;
    s->rng ^= s->rng >> 27;
    return (double)((s->rng * 0x2545F4914F6CDD1Dull) >> 11) * (1.0 / 9007199254740992.0);
}

static void search_clip(const search_space *sp, double *x)
{
    int i;
    for (i = 0; i < sp->dims; i++) {
        if (sp->quantum[i] > 0.0)
            x[i] = floor(x[i] / sp->quantum[i] + 0.5) * sp->quantum[i];
        x[i] = x[i] < sp->lo[i] ? sp->lo[i] : (x[i] > sp->hi[i] ? sp->hi[i] : x[i]);
    }
}

/* Two points are the same peak when every input is within 1/64 of its range. */
static int search_near(const search_space *sp, const double *a, const double *b)
{
    int i;
    for (i = 0; i < sp->dims; i++)
        if (fabs(a[i] - b[i]) > (sp->hi[i] - sp->lo[i]) / 64.0)
            return 0;
    return 1;
}

/* Keeps x among the best distinct points: a better point near a kept one
 * replaces it, a point near a better kept one is dropped. */
static void search_keep(search_state *s, const double *x, double err)
{
    int i, at = -1;
    search_point p;
    for (i = 0; i < s->n_top; i++)
        if (search_near(&s->sp, s->top[i].x, x)) {
            if (s->top[i].err >= err)
                return;
            at = i;
            break;
        }
    if (at < 0) {
        if (s->n_top < SEARCH_TOP)
            at = s->n_top++;
        else if (err > s->top[SEARCH_TOP - 1].err)
            at = SEARCH_TOP - 1;
        else
            return;
    }
    p.err = err;
    memcpy(p.x, x, sizeof p.x);
    for (i = at; i > 0 && s->top[i - 1].err < err; i--)
        s->top[i] = s->top[i - 1];
    s->top[i] = p;
}

/* The error at x (rounded to the inputs' quanta, held in the box); a NaN
 * error counts as infinite. */
static double search_eval(search_state *s, const double *x_in)
{
    double x[SEARCH_DIMS] = {0}, err;
    memcpy(x, x_in, sizeof(double) * (size_t)s->sp.dims);
    search_clip(&s->sp, x);
    err = s->fn(s->ctx, x);
    if (err != err)
        err = HUGE_VAL;
    s->evals++;
    search_keep(s, x, err);
    return err;
}

static void search_random(search_state *s, long n)
{
    double x[SEARCH_DIMS];
    long k;
    int i;
    for (k = 0; k < n; k++) {
        for (i = 0; i < s->sp.dims; i++)
            x[i] = s->sp.lo[i] + (s->sp.hi[i] - s->sp.lo[i]) * search_uniform(s);
        search_eval(s, x);
    }
}

/* Local maximisation from each of the best `starts` points, `per_round`
 * neighbours per radius; stops at the smallest radius. */
static void search_climb(search_state *s, int starts, int per_round)
{
    search_point from[SEARCH_TOP];
    int n = starts < s->n_top ? starts : s->n_top, j, i, k;
    memcpy(from, s->top, sizeof from);
    for (j = 0; j < n; j++) {
        search_point best = from[j];
        double r = 1.0 / 16.0;
        while (1) {
            int moved = 0, smallest = 1;
            for (k = 0; k < per_round; k++) {
                double x[SEARCH_DIMS], e;
                for (i = 0; i < s->sp.dims; i++) {
                    double range = s->sp.hi[i] - s->sp.lo[i], step = r * range;
                    double floor_step = s->sp.quantum[i] > 0.0 ? s->sp.quantum[i] : 1e-9 * range;
                    if (step < floor_step)
                        step = floor_step;
                    else
                        smallest = 0;
                    x[i] = best.x[i] + step * (2.0 * search_uniform(s) - 1.0);
                }
                e = search_eval(s, x);
                if (e > best.err) {
                    search_clip(&s->sp, x);
                    best.err = e;
                    memcpy(best.x, x, sizeof x);
                    moved = 1;
                }
            }
            if (!moved) {
                if (smallest)
                    break;
                r *= 0.5;
            }
        }
    }
}

/* Replays the corpus lines of `key` from path (a missing file: none). */
static int search_corpus(search_state *s, const char *path, const char *key)
{
    char line[512];
    int n = 0;
    FILE *f = fopen(path, "r");
    if (!f)
        return 0;
    while (fgets(line, sizeof line, f)) {
        char k[128];
        double x[SEARCH_DIMS] = {0};
        int used = 0, i;
        if (line[0] == '#' || sscanf(line, "%127s%n", k, &used) != 1 || strcmp(k, key))
            continue;
        for (i = 0; i < s->sp.dims; i++) {
            int more = 0;
            if (sscanf(line + used, "%lf%n", &x[i], &more) != 1)
                break;
            used += more;
        }
        if (i == s->sp.dims) {
            search_eval(s, x);
            n++;
        }
    }
    fclose(f);
    return n;
}

/* With SEARCH_CORPUS_OUT set, appends the best points under key. */
static void search_corpus_write(const search_state *s, const char *key, int count)
{
    const char *path = getenv("SEARCH_CORPUS_OUT");
    FILE *f;
    int j, i;
    if (!path || !(f = fopen(path, "a")))
        return;
    for (j = 0; j < count && j < s->n_top; j++) {
        fprintf(f, "%s", key);
        for (i = 0; i < s->sp.dims; i++)
            fprintf(f, " %.17g", s->top[j].x[i]);
        fprintf(f, " # %.6g\n", s->top[j].err);
    }
    fclose(f);
}

/* 1 when SEARCH_LONG is set: the long pass (make search). */
static int search_long(void)
{
    const char *v = getenv("SEARCH_LONG");
    return v && *v && strcmp(v, "0");
}

#endif
