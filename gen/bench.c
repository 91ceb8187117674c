/* Timing harness (see bench.h). */
#include "bench.h"

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

double bench_ns_per_eval(bench_batch fn, const void *ctx, int n, int runs)
{
    float *c = malloc((size_t)n * sizeof *c);
    int32_t *cq = malloc((size_t)n * sizeof *cq);
    double *t = malloc((size_t)(runs > 0 ? runs : 1) * sizeof *t), median;
    unsigned x = 2463534242u; /* xorshift32, fixed seed: the same inputs every run */
    int i, r;
    if (!c || !cq || !t) {
        free(c);
        free(cq);
        free(t);
        return -1.0;
    }
    for (i = 0; i < n; i++) {
        x ^= x << 13;
        x ^= x >> 17;
        x ^= x << 5;
        c[i] = (float)(x >> 8) / 16777216.0f;
        cq[i] = (int32_t)(c[i] * 32768.0f + 0.5f);
    }
    sink = fn(ctx, c, cq, n); /* warm caches and branch predictors; runs = 0: only this */
    if (runs == 0) {
        free(c);
        free(cq);
        free(t);
        return 0.0;
    }
    for (r = 0; r < runs; r++) {
        double t0 = now_ns(), sum = fn(ctx, c, cq, n);
        t[r] = (now_ns() - t0) / n;
        sink = sum;
    }
    qsort(t, (size_t)runs, sizeof *t, by_value);
    median = t[runs / 2];
    free(c);
    free(cq);
    free(t);
    return median;
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
