/* The timing harness (gen/bench/bench.c) runs on a tiny batch and returns a sane
 * number. No timing assertions: speeds are measured by `make bench` and
 * `make report`, never asserted by tests. */
#include <math.h>
#include <string.h>

#include "bench/bench.h"
#include "fresnel.h"
#include "harness.h"

typedef struct probe {
    float f0;
    long calls;
    int n_seen;
    int inputs_ok;   /* cosines in [0, 1], Q1.15 codes the same values */
    double first[4]; /* the first cosines of the first call, to compare calls */
    int same_inputs; /* every call saw the same first cosines */
} probe;

static double schlick_batch(const void *ctx, const float *c, const int32_t *cq, int n)
{
    probe *p = (probe *)ctx; /* the harness passes ctx through untouched */
    double sum = 0.0;
    int i;
    for (i = 0; i < n; i++) {
        fresnel_rgb f0 = {p->f0, p->f0, p->f0}, r = fresnel_schlick_rgb(f0, c[i]);
        sum += r.r + r.g + r.b;
        if (!(c[i] >= 0.0f && c[i] <= 1.0f) || fabsf(cq[i] / 32768.0f - c[i]) > 1.0f / 32768.0f)
            p->inputs_ok = 0;
    }
    for (i = 0; i < 4 && i < n; i++) {
        if (p->calls == 0)
            p->first[i] = c[i];
        else if (p->first[i] != c[i])
            p->same_inputs = 0;
    }
    p->calls++;
    p->n_seen = n;
    return sum;
}

int main(void)
{
    probe p = {0.04f, 0, 0, 1, {0.0, 0.0, 0.0, 0.0}, 1};
    double ns = bench_ns_per_eval(schlick_batch, &p, 1000, 5);
    const char *who = bench_compiler();

    CHECK("bench_ns_per_eval: positive and finite on a tiny batch (1000 x 5 runs)",
          ns > 0.0 && isfinite(ns), "%g", ns);
    NOTE("tiny batch, Schlick RGB f32: %.3g ns per evaluation (not a benchmark)", ns);
    CHECK("bench_ns_per_eval: one warm-up and 5 timed calls of the whole batch",
          p.calls == 6 && p.n_seen == 1000, "%ld calls of %d", p.calls, p.n_seen);
    CHECK("bench_ns_per_eval: cosines in [0, 1], Q1.15 codes of the same values", p.inputs_ok,
          "bad input");
    CHECK("bench_ns_per_eval: the same inputs every run", p.same_inputs, "inputs changed");
    {
        probe q = {0.04f, 0, 0, 1, {0.0, 0.0, 0.0, 0.0}, 1};
        double z;
        bench_ns_per_eval(schlick_batch, &q, 16, 1);
        z = q.first[0];
        q.calls = 0;
        bench_ns_per_eval(schlick_batch, &q, 16, 1);
        CHECK("bench_ns_per_eval: the same inputs in every call of the harness (fixed seed)",
              q.first[0] == z && q.same_inputs, "%g vs %g", q.first[0], z);
    }
    {
        probe q = {0.04f, 0, 0, 1, {0.0, 0.0, 0.0, 0.0}, 1};
        double zero = bench_ns_per_eval(schlick_batch, &q, 100, 0);
        CHECK("bench_ns_per_eval: runs 0 runs only the warm-up and returns 0",
              zero == 0.0 && q.calls == 1, "%g, %ld calls", zero, q.calls);
    }
    CHECK("bench_compiler: names the compiler and the runtime's flags",
          who && strlen(who) > 10 && strstr(who, __VERSION__) != NULL, "'%s'", who ? who : "(null)");
    NOTE("build: %s", who);
    return harness_exit();
}
