/* The largest error of a series of measurements and where it occurred, and
 * the pair of checks every bound test makes of it (results in range, error
 * within the documented bound). Shared by the fixed-point, fast-path and
 * binary16 bound tests. A NaN error is the worst possible. */
#ifndef FRESNEL_TESTS_WORST_H
#define FRESNEL_TESTS_WORST_H

#include <math.h>
#include <stdio.h>

#include "harness.h"

typedef struct worst {
    double err;
    char where[128];
} worst;

static void note_worst(worst *w, double err, const char *what, double c)
{
    if (err > w->err || err != err) {
        w->err = err != err ? HUGE_VAL : err;
        snprintf(w->where, sizeof w->where, "%.100s c %.6g", what, c);
    }
}

/* prefix names the type ("fixed", "fixed fast", "f16"); lsb: errors and
 * bound in LSB of Q15 (else absolute). */
static void check_worst(const char *prefix, const char *name, const worst *w, double bound, long bad_range, int lsb)
{
    char label[192];
    if (lsb)
        printf("NOTE %s %-28s max|err| %.5f LSB at %s\n", prefix, name, w->err, w->where);
    else
        printf("NOTE %s %-28s max|err| %.3e at %s\n", prefix, name, w->err, w->where);
    snprintf(label, sizeof label, "%s %s results in [0, %s]", prefix, name, lsb ? "one" : "1");
    CHECK(label, bad_range == 0, "%ld results outside the range or NaN", bad_range);
    if (lsb)
        snprintf(label, sizeof label, "%s %s within %.3f LSB", prefix, name, bound);
    else
        snprintf(label, sizeof label, "%s %s within %.2e", prefix, name, bound);
    CHECK(label, w->err <= bound, "max|err| %.5g exceeds the documented %.5g at %s", w->err, bound, w->where);
}

#endif
