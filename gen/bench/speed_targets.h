/* The library's host speed targets and the file `make bench` prints (one per
 * compiler flag set; tests/speed/speed.c writes it, `fresnel report --speed FILE`
 * reads it). A benchmark: nothing here is asserted by tests.
 *
 * File format, one item per line, fields separated by blanks:
 *   # opt: OPT                    the Makefile's OPT (the flag set), then
 *   # KEY: VALUE                  compiler, cflags, cpu, vector, workload: free text
 *   row NAME FORM MIN Q1 MED Q3 MAX XMED XQ1 XQ3
 *       ns per evaluation over the interleaved rounds (min, quartiles, max),
 *       and the time over the schlick-f32 row's in the same round (median and
 *       quartiles); FORM is call, inline, batch or floor
 *   target ID MED Q1 Q3 ...       a target's ratio (NUM row / DEN row in the
 *       same round: median and quartiles), then free text (goal and mark)
 * Other lines starting with '#' and blank lines are comments. */
#ifndef FRESNEL_BENCH_SPEED_TARGETS_H
#include <stdio.h>

#define FRESNEL_BENCH_SPEED_TARGETS_H

#define SPEED_FLAGSETS 2 /* the target's flag sets: "-O2" and "-O3 -march=native" */
extern const char *const speed_flagset_names[SPEED_FLAGSETS];

/* One target: row num's time over row den's time, measured in one process,
 * at most goal[k] at flag set k. */
typedef struct speed_target {
    const char *id, *num, *den;
    const char *what; /* what is compared, for the report's row */
    double goal[SPEED_FLAGSETS];
    const char *tried; /* for a miss: what was tried, and where the time goes (NULL: nothing to say) */
} speed_target;
extern const speed_target speed_targets[];
extern const int speed_target_count;

/* 0 for "-O2", 1 for "-O3 -march=native" (blanks between flags ignored), -1
 * for any other flag set. */
int speed_flagset(const char *opt);

#define SPEED_NAME 40
#define SPEED_MAX_ROWS 48
typedef struct speed_row {
    char name[SPEED_NAME], form[16];
    double ns[5];   /* min, q1, median, q3, max */
    double x[3];    /* over schlick-f32: median, q1, q3 */
} speed_row;
typedef struct speed_ratio {
    char id[SPEED_NAME];
    double med, q1, q3;
} speed_ratio;
typedef struct speed_file {
    char opt[96], compiler[128], cpu[128], vector[96];
    int n_rows, n_targets;
    speed_row rows[SPEED_MAX_ROWS];
    speed_ratio targets[SPEED_MAX_ROWS];
} speed_file;

/* Reads a file in the format above from in (opened by the caller; path
 * names it): 0, or -1 with where = "path:line" (or "path"; wherelen bytes)
 * and *what = what was expected there, or 1 after a read error (errno
 * set). An "# opt:" line is required. */
int speed_file_read(FILE *in, const char *path, speed_file *f, char *where, int wherelen, const char **what);
/* The target with this id in f, or NULL. */
const speed_ratio *speed_file_target(const speed_file *f, const char *id);
const speed_row *speed_file_row(const speed_file *f, const char *name);

#endif
