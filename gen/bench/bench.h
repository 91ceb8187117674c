/* Timing for `make bench` and the report's cost columns: never used by tests
 * to assert anything about speed (performance goals live in benchmarks, not
 * in timed unit tests). */
#ifndef FRESNEL_BENCH_H
#define FRESNEL_BENCH_H

#include <stdint.h>

/* Evaluate one model for one material on n cosines (given as binary32 and
 * as Q1.15 codes, the same values), returning a checksum of the RGB results
 * so that no evaluation can be optimised away. No stores: a fixed-point
 * model is not charged for converting its results to float. */
typedef double (*bench_batch)(const void *ctx, const float *cos_theta, const int32_t *cos_q15, int n);

/* Median over `runs` runs of the time per cosine, in ns, for a batch of n
 * fixed pseudo-random cosines in [0, 1] (the same every run and every
 * model), after one untimed warm-up batch. runs = 0 runs only the warm-up
 * (a fixed workload for instruction counting) and returns 0. The checksums
 * go to a volatile sink. */
double bench_ns_per_eval(bench_batch fn, const void *ctx, int n, int runs);

/* k batch functions timed in rounds on the same inputs as bench_ns_per_eval:
 * one untimed warm-up call of each, then runs rounds, each timing every
 * function once, back to back, so that a change in machine load falls on
 * all of them alike. ns[j] = the median over the rounds of fns[j]'s time per
 * cosine (0 when runs = 0). Returns 0, or -1 when out of memory. */
int bench_ns_per_eval_rounds(const bench_batch *fns, const void *const *ctxs, int k, int n, int runs, double *ns);

/* "gcc 12.2.0, -O2 ..." : compiler and the runtime's flags (FRESNEL_CFLAGS
 * from the Makefile). */
const char *bench_compiler(void);

#endif
