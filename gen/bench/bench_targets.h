/* The library's speed targets: time per evaluation of the exact conductor (ours
 * and two other renderers' algorithms) and of the lookup tables, as a ratio
 * to Schlick measured in the same run, with each row's largest error.
 * `fresnel bench --targets` prints it; the report's targets table reads it.
 * A benchmark: nothing here is asserted by tests. */
#ifndef FRESNEL_BENCH_TARGETS_H
#define FRESNEL_BENCH_TARGETS_H

typedef struct bench_target_row {
    const char *name;        /* static string, e.g. "conductor", "mitsuba-style" */
    double ns;               /* median ns per evaluation, one channel */
    double ratio_to_schlick; /* ns / ns of row 0 ("schlick") of the same run */
    /* Largest |result - double reference| (NaN if a result was NaN):
     *   schlick*: against ref_schlick, F0 in 0..1 by 1/64;
     *   conductor rows (ours, mitsuba-style, pbrt-style):
     *     against ref_conductor over the "ordinary" grid: eta 0.1..5 (49,
     *     log), kappa 0 and 0.01..10 (48, log), 2060 cosines in [0, 1]
     *     (uniform in c and in angle, and 0, 1 and points within 1e-6 of them);
     *   lut*: the table holds ref_conductor at its nodes; the error is
     *     interpolation plus rounding against ref_conductor, over the grid's
     *     metal-like part (kappa >= 1) and the same cosines. */
    double max_abs_err;
    /* Conductor rows: the result at matched index (eta = 1, kappa = 0) at
     * c = 0 and at c = 1e-4 (the exact answer is 0 at every c), NaN for a
     * NaN result. -1 for the other rows (not applicable). */
    double matched_c0, matched_c1e4;
} bench_target_row;

#define BENCH_TARGET_ROWS 20 /* at most this many rows */

/* Default workload: BENCH_TARGETS_COUNT cosines per batch (fits in L2),
 * median of BENCH_TARGETS_RUNS rounds. */
#define BENCH_TARGETS_COUNT (1 << 16)
#define BENCH_TARGETS_RUNS 21

/* One run: every row timed back to back in rounds (bench_ns_per_eval_rounds),
 * one material (copper at 650 nm as in README: eta 0.24, kappa 3.63; Schlick's
 * F0 is its normal-incidence reflectance; the LUTs tabulate its curve), then each row's error.
 * Writes min(rows available, max_rows) rows, row 0 Schlick; returns the
 * count written, or -1 when out of memory. */
int bench_speed_targets(bench_target_row *rows, int max_rows);

/* The same with the batch size and round count given (count >= 1, runs >= 0;
 * runs = 0 times nothing: ns and ratios are 0, the callgrind workload). */
int bench_speed_targets_run(bench_target_row *rows, int max_rows, int count, int runs);

#endif
