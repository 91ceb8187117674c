/* Timing harness (see bench.h). */
#include "bench/bench.h"

#include <stdlib.h>
#include <string.h>
#include <time.h>

#ifndef FRESNEL_CFLAGS
#define FRESNEL_CFLAGS "unknown flags"
#endif

static volatile double sink;

static double now_ns(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec * 1e9 + t.tv_nsec;
}

static int by_value(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

/* The same n pseudo-random cosines every call (xorshift32, fixed seed), as
 * binary32 and as Q1.15 codes. 0, or -1 when out of memory. */
static int make_inputs(int n, float **c, int32_t **cq)
{
    unsigned x = 2463534242u;
    int i;
    *c = malloc((size_t)(n > 0 ? n : 1) * sizeof **c);
    *cq = malloc((size_t)(n > 0 ? n : 1) * sizeof **cq);
    if (!*c || !*cq) {
        free(*c);
        free(*cq);
        return -1;
    }
    for (i = 0; i < n; i++) {
        x ^= x << 13;
        x ^= x >> 17;
        x ^= x << 5;
        (*c)[i] = (float)(x >> 8) / 16777216.0f;
        (*cq)[i] = (int32_t)((*c)[i] * 32768.0f + 0.5f);
    }
    return 0;
}

double bench_ns_per_eval(bench_batch fn, const void *ctx, int n, int runs)
{
    double ns;
    return bench_ns_per_eval_rounds(&fn, &ctx, 1, n, runs, &ns) ? -1.0 : ns;
}

int bench_ns_per_eval_rounds(const bench_batch *fns, const void *const *ctxs, int k, int n, int runs, double *ns)
{
    float *c;
    int32_t *cq;
    double *t;
    int j, r;
    if (make_inputs(n, &c, &cq))
        return -1;
    if (!(t = malloc((size_t)(k > 0 ? k : 1) * (size_t)(runs > 0 ? runs : 1) * sizeof *t))) {
        free(c);
        free(cq);
        return -1;
    }
    for (j = 0; j < k; j++) {
        sink = fns[j](ctxs[j], c, cq, n); /* warm caches and branch predictors; runs = 0: only this */
        ns[j] = 0.0;
    }
    for (r = 0; r < runs; r++)
        for (j = 0; j < k; j++) {
            double t0 = now_ns(), sum = fns[j](ctxs[j], c, cq, n);
            t[j * runs + r] = (now_ns() - t0) / n;
            sink = sum;
        }
    for (j = 0; j < k && runs > 0; j++) {
        qsort(t + j * runs, (size_t)runs, sizeof *t, by_value);
        ns[j] = t[j * runs + runs / 2];
    }
    free(c);
    free(cq);
    free(t);
    return 0;
}

const char *bench_compiler(void)
{
    static char text[256];
#ifdef __VERSION__
    const char *v = __VERSION__;
#else
    const char *v = "unknown compiler";
#endif
    if (!text[0]) {
        strncpy(text, "cc ", sizeof text - 1);
        strncat(text, v, sizeof text - strlen(text) - 1);
        strncat(text, ", runtime built with ", sizeof text - strlen(text) - 1);
        strncat(text, FRESNEL_CFLAGS, sizeof text - strlen(text) - 1);
    }
    return text;
}
