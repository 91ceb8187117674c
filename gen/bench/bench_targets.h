/* The accuracy side of the library's speed targets: each row of `make
 * bench` that computes the exact conductor or a table, with its largest
 * error against the double reference. `fresnel bench --targets` prints it;
 * `fresnel report`'s targets.md quotes it beside the speed (`make bench`,
 * tests/speed/speed.c, which times the same functions). Nothing is timed here. */
#ifndef FRESNEL_BENCH_TARGETS_H
#define FRESNEL_BENCH_TARGETS_H

typedef struct bench_target_row {
    const char *name; /* static string, e.g. "conductor", "mitsuba-style" */
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

/* Every row's errors over the grid above. Writes min(rows available,
 * max_rows) rows, row 0 Schlick; returns the count written. */
int bench_target_errors(bench_target_row *rows, int max_rows);

#endif
