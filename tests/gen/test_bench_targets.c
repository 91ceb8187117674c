/* bench_target_errors (gen/bench/bench_targets.c), the rows of `fresnel bench
 * --targets` and the errors the report's speed targets quote: the documented
 * rows in their order, and the errors it measures for this runtime within
 * the documented bounds. Nothing is timed: speeds are benchmarks (make
 * bench), never tests. */
#include <math.h>
#include <string.h>

#include "bench/bench_targets.h"
#include "fresnel.h"
#include "harness.h"

int main(void)
{
    static const char *const names[] = {"schlick", "schlick-q15", "conductor", "conductor-prepared",
                                        "conductor-batch", "mitsuba-style", "pbrt-style",
                                        "lut16-f32", "lut32-f32", "lut16-q15", "lut32-q15",
                                        "lut16-linear-f32", "lut16-linear-q15", "lut16-cubic-f32", "lut16-cubic-q15", "lut32-q15-fast"};
    enum { ROWS = (int)(sizeof names / sizeof names[0]) };
    bench_target_row rows[BENCH_TARGET_ROWS];
    int n = bench_target_errors(rows, BENCH_TARGET_ROWS), i, named = 1;
    CHECK("bench_target_errors: every documented row", n == ROWS, "%d rows", n);
    for (i = 0; i < n && i < ROWS && named; i++)
        named = !strcmp(rows[i].name, names[i]);
    CHECK("bench_target_errors: row names in the documented order", named, "row %d", i - 1);
    if (n != ROWS)
        return harness_exit();
    CHECK("bench_target_errors: schlick row within FRESNEL_BOUND_SCHLICK",
          rows[0].max_abs_err <= FRESNEL_BOUND_SCHLICK, "%g", rows[0].max_abs_err);
    for (i = 2; i <= 4; i++) {
        CHECK(rows[i].name, rows[i].max_abs_err <= FRESNEL_BOUND_CONDUCTOR_PREPARED, "max|err| %g",
              rows[i].max_abs_err);
        CHECK(rows[i].name, rows[i].matched_c0 == 0.0 && rows[i].matched_c1e4 == 0.0, "matched index: %g, %g",
              rows[i].matched_c0, rows[i].matched_c1e4);
    }
    NOTE("errors on the ordinary grid: conductor %.3g, mitsuba-style %.3g, pbrt-style %.3g; matched index at "
         "c = 1e-4: mitsuba-style %g, pbrt-style %g",
         rows[2].max_abs_err, rows[5].max_abs_err, rows[6].max_abs_err, rows[5].matched_c1e4, rows[6].matched_c1e4);
    CHECK("bench_target_errors: the comparators are the textbook binary32 forms (error > 1e-6, 1 at matched index "
          "near grazing)",
          rows[5].max_abs_err > 1e-6 && rows[6].max_abs_err > 1e-6 && rows[5].matched_c1e4 == 1.0 &&
              rows[6].matched_c1e4 == 1.0,
          "%g %g %g %g", rows[5].max_abs_err, rows[6].max_abs_err, rows[5].matched_c1e4, rows[6].matched_c1e4);
    CHECK("bench_target_errors: non-conductor rows mark matched_* not applicable (-1)",
          rows[0].matched_c0 == -1.0 && rows[8].matched_c1e4 == -1.0, "%g %g", rows[0].matched_c0,
          rows[8].matched_c1e4);
    return harness_exit();
}
