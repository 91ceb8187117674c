/* Properties on the extreme and stiff cases (the cases
 * `fresnel extremes` prints, gen/report/extremes.h), in every number type of the
 * runtime (binary32, Q15, binary16 where the compiler has _Float16):
 *   - no NaN or Inf, result in [0, 1], for every input including NaN, +-Inf
 *     (Q15: every int32 cosine code, the extreme ones included);
 *   - inputs outside the domain give exactly the documented substitute
 *     (c < 0, -0, NaN, -Inf as c = 0; c > 1, +Inf as c = 1; F0 1.04 as 1);
 *   - agreement with the double reference within the documented bound where
 *     the inputs are in the range the bound was measured on;
 *   - matched index (eta = n1, kappa = 0) gives 0 at every c, c = 0 included;
 *   - monotone in c for external dielectric reflection (where physics makes
 *     it so: eta <= 2 + sqrt 3);
 *   - total internal reflection is exactly one, and the curve is continuous
 *     across the critical angle (each representable cosine near it within
 *     the bound of the continuous reference, so no step the reference does
 *     not have). */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "report/extremes.h"
#include "fresnel.h"
#include "fresnel_f16.h"
#include "fresnel_fixed.h"
#include "harness.h"
#include "model/registry.h"
#include "common/reference.h"

#define GRID_MAX 2100

/* Every check below asserts. The binary16 exact forms at a critical angle
 * and binary16 F82 on far-apart F0, F82 are held to the bounds
 * fresnel_f16.h documents (none at a critical angle; 4.0e-3 for F82 over a
 * grid of pairs). */

/* Binary32, Q15 and binary16 steps of the cosine in [0.5, 1). */
static double ulp_upper(const extreme_type *ty)
{
    return ty->type->id == TYPE_Q15 ? 0x1p-15 : ty->type->id == TYPE_F16 ? 0x1p-11 : 0x1p-24;
}

static int eval(const model *m, const extreme_type *ty, const extreme_typed *t, double x, double *got)
{
    double ref_c;
    return extreme_eval(ty, m, t, x, got, &ref_c);
}

/* Range, NaN and the documented substitutes for c outside [0, 1]. */
static void test_cosine_policy(const extreme_type *ty)
{
    long bad_range = 0, bad_subst = 0, tried = 0;
    int ei, mi, ci;
    char first[256] = "", name[200];
    for (ei = 0; ei < extreme_case_count; ei++) {
        extreme_typed t;
        extreme_prepare(ty, &extreme_cases[ei], &t);
        for (mi = 0; mi < model_count; mi++) {
            const model *m = &model_table[mi];
            double at0, at1;
            if (!ty->type->has(m))
                continue;
            eval(m, ty, &t, 0.0, &at0);
            eval(m, ty, &t, 1.0, &at1);
            for (ci = 0; ci < extreme_cosine_count; ci++) {
                const extreme_cos *x = &extreme_cosines[ci];
                double c = extreme_cos_input(ty, x), got;
                if (!eval(m, ty, &t, c, &got))
                    continue; /* not representable in this type (NaN in Q15) */
                tried++;
                if (!(got >= 0.0 && got <= 1.0)) {
                    bad_range++;
                    if (!*first)
                        snprintf(first, sizeof first, "%s on %s at c = %s: %g", m->name, extreme_cases[ei].name,
                                 x->label, got);
                }
                /* c > 1 and +Inf are clamped to 1; c < 0, -0, NaN and -Inf to 0. */
                if (!(c >= 0.0 && c <= 1.0) || (c == 0.0 && signbit(c))) {
                    double want = c > 1.0 ? at1 : at0;
                    if (got != want) {
                        bad_subst++;
                        if (!*first)
                            snprintf(first, sizeof first, "%s on %s at c = %s: %.9g, expected %.9g", m->name,
                                     extreme_cases[ei].name, x->label, got, want);
                    }
                }
            }
        }
    }
    snprintf(name, sizeof name,
             "extremes %s: every model, case and cosine (NaN, +-Inf, -0, <0, >1, one LSB) gives a number in [0, 1]",
             ty->type->name);
    CHECK(name, bad_range == 0 && tried > 0, "%ld bad of %ld, first %s", bad_range, tried, first);
    snprintf(name, sizeof name, "extremes %s: c < 0, -0, NaN, -Inf give exactly f(0); c > 1, +Inf exactly f(1)",
             ty->type->name);
    CHECK(name, bad_subst == 0, "%ld differ, first %s", bad_subst, first);
}

/* Q15 cosines are int32 codes: every code outside [0, 32768] is clamped. */
static void test_q15_codes(void)
{
    static const int32_t low[] = {-1, -32768, -65536, INT32_MIN + 1, INT32_MIN};
    static const int32_t high[] = {32769, 65535, 65536, 1 << 30, INT32_MAX};
    long bad = 0;
    int ei, mi, i;
    for (ei = 0; ei < extreme_case_count; ei++) {
        model_params p;
        model_q15 q;
        model_derive(extreme_cases[ei].eta, extreme_cases[ei].kappa, extreme_cases[ei].n1, 1.0, 5.0, &p);
        model_params_round_q15(&p);
        model_q15_from_params(&p, &q);
        for (mi = 0; mi < model_count; mi++) {
            const model *m = &model_table[mi];
            int32_t at0, at1;
            if (!m->q15->scalar)
                continue;
            at0 = m->q15->scalar(&q, 0);
            at1 = m->q15->scalar(&q, 32768);
            bad += !(at0 >= 0 && at0 <= 32768 && at1 >= 0 && at1 <= 32768);
            for (i = 0; i < 5; i++)
                bad += m->q15->scalar(&q, low[i]) != at0 || m->q15->scalar(&q, high[i]) != at1;
        }
    }
    CHECK("extremes q15: cosine codes below 0 (to INT32_MIN) give f(0), above 32768 (to INT32_MAX) f(one)", bad == 0,
          "%ld differ", bad);
}

/* Every model against the reference on every case over the cosine grid. */
static void test_bounds(const extreme_type *ty)
{
    int ei, mi;
    for (mi = 0; mi < model_count; mi++) {
        const model *m = &model_table[mi];
        double worst = 0.0, worst_out = 0.0;
        const char *where = "", *where_out = "";
        long bad = 0;
        char name[200];
        if (!ty->type->has(m))
            continue;
        for (ei = 0; ei < extreme_case_count; ei++) {
            extreme_typed t;
            int b;
            double err;
            extreme_prepare(ty, &extreme_cases[ei], &t);
            err = extreme_max_err(m, ty, &t, &b);
            bad += b;
            if (t.in_domain && !(err <= worst)) {
                worst = err;
                where = extreme_cases[ei].name;
            } else if (!t.in_domain && !(err <= worst_out)) {
                worst_out = err;
                where_out = extreme_cases[ei].name;
            }
        }
        snprintf(name, sizeof name, "extremes %s: %s in [0, 1] on every case", ty->type->name, m->name);
        CHECK(name, bad == 0, "%ld cases with a result outside [0, 1] or NaN", bad);
        snprintf(name, sizeof name, "extremes %s: %s within its bound %.1e on every case in the measured range",
                 ty->type->name, m->name, ty->type->bound(m));
        CHECK(name, worst <= ty->type->bound(m), "max|err| %.3g on %s", worst, where);
        if (*where_out)
            NOTE("extremes %s: %s outside the measured range (%s): max|err| %.3g", ty->type->name, m->name, where_out,
                 worst_out);
    }
}

static void test_matched_index(const extreme_type *ty)
{
    static const char *const exact[] = {"exact", "exact-conductor", "exact-dielectric"};
    int ei, k, ci, cases = 0;
    long bad = 0;
    char name[200];
    for (ei = 0; ei < extreme_case_count; ei++) {
        const extreme_case *e = &extreme_cases[ei];
        extreme_typed t;
        if (!(e->eta / e->n1 == 1.0 && e->kappa == 0.0))
            continue;
        cases++;
        extreme_prepare(ty, e, &t);
        for (k = 0; k < 3; k++) {
            const model *m = model_find(exact[k]);
            for (ci = 0; ci < extreme_cosine_count; ci++) {
                double c = extreme_cos_input(ty, &extreme_cosines[ci]), got, ref_c;
                if (extreme_eval(ty, m, &t, c, &got, &ref_c))
                    bad += got != 0.0 || m->ref->scalar(&t.p, ref_c) != 0.0;
            }
        }
    }
    snprintf(name, sizeof name,
             "extremes %s: matched index (eta = n1, kappa = 0) gives 0 at every c, c = 0 included, and so does the reference",
             ty->type->name);
    CHECK(name, bad == 0 && cases >= 2, "%ld non-zero results over %d cases", bad, cases);
}

/* Cosines sorted ascending: the grid plus points next to 0 and 1, where the
 * curve is steepest (c -> 0) or flattest (c -> 1). */
static int sorted_cosines(double *c, int max)
{
    static float g[GRID_MAX];
    int n = extreme_cos_grid(g, max - 400 < GRID_MAX ? max - 400 : GRID_MAX), i, j;
    for (i = 0; i < n; i++)
        c[i] = g[i];
    for (i = 1; i <= 200; i++) {
        c[n++] = 1.0 - i * 0x1p-24;
        c[n++] = i * 1e-9;
    }
    for (i = 1; i < n; i++) /* insertion sort: small n */
        for (j = i; j > 0 && c[j - 1] > c[j]; j--) {
            double t = c[j];
            c[j] = c[j - 1];
            c[j - 1] = t;
        }
    return n;
}

/* Unpolarised reflectance of a dielectric seen from outside falls
 * monotonically from grazing to normal incidence only for eta <= 2 + sqrt 3:
 * above it the Brewster dip of Rp takes (Rs + Rp)/2 below F0 (eta 100 dips
 * to 0.50 against F0 = 0.96). So the physics is checked first on the
 * reference, then each type on the cases where it holds. Rounding is
 * monotone, so Schlick and LSK, built from monotone steps, must be exactly
 * monotone; the exact forms are not built that way, and where the curve is
 * flat (c -> 1) their rounding may step up by an ulp of R: those rises are
 * held to twice the documented bound (what the bound allows), and the
 * largest is printed. */
static void test_monotone(const extreme_type *ty)
{
    static const char *const exact[] = {"exact", "exact-conductor", "exact-dielectric"};
    static const char *const schlick[] = {"schlick", "lsk"};
    static double c[GRID_MAX + 400];
    const double eta_brewster = 2.0 + sqrt(3.0);
    int n = sorted_cosines(c, GRID_MAX + 400), ei, k, ci, i, cases = 0, physics_bad = 0;
    long strict_bad = 0, exact_bad = 0;
    double worst_rise = 0.0;
    char first[200] = "", name[200];
    for (ei = 0; ei < extreme_case_count; ei++) {
        const extreme_case *e = &extreme_cases[ei];
        extreme_typed t;
        double prev_r;
        int ref_monotone = 1;
        if (!(e->kappa == 0.0 && e->eta > e->n1))
            continue; /* external reflection at a dielectric */
        extreme_prepare(ty, e, &t);
        prev_r = ref_dielectric(t.p.eta, 0.0);
        for (i = 1; i <= 100000; i++) {
            double r = ref_dielectric(t.p.eta, i / 1e5);
            if (r > prev_r * (1.0 + 1e-13))
                ref_monotone = 0;
            prev_r = r;
        }
        if (ref_monotone != (t.p.eta <= eta_brewster)) {
            physics_bad++;
            NOTE("reference on %s (eta %.6g): monotone %d, expected %d", e->name, t.p.eta, ref_monotone,
                 t.p.eta <= eta_brewster);
        }
        for (k = 0; k < 2; k++) {
            const model *m = model_find(schlick[k]);
            double prev, r;
            eval(m, ty, &t, c[0], &prev);
            for (ci = 1; ci < n; ci++) {
                eval(m, ty, &t, c[ci], &r);
                strict_bad += r > prev;
                prev = r;
            }
        }
        if (!ref_monotone || !t.in_domain)
            continue;
        cases++;
        for (k = 0; k < 3; k++) {
            const model *m = model_find(exact[k]);
            double prev, r;
            eval(m, ty, &t, c[0], &prev);
            for (ci = 1; ci < n; ci++) {
                double rise;
                eval(m, ty, &t, c[ci], &r);
                rise = r - prev;
                if (rise > worst_rise)
                    worst_rise = rise;
                if (rise > 2.0 * ty->type->bound(m)) {
                    exact_bad++;
                    if (!*first)
                        snprintf(first, sizeof first, "%s on %s: R(%.9g) = %.9g > R(%.9g) = %.9g", m->name, e->name,
                                 c[ci], r, c[ci - 1], prev);
                }
                prev = r;
            }
        }
    }
    snprintf(name, sizeof name, "extremes %s: reference dielectric reflectance is monotone in c exactly when eta <= 2 + sqrt 3",
             ty->type->name);
    CHECK(name, physics_bad == 0, "%d cases disagree", physics_bad);
    snprintf(name, sizeof name, "extremes %s: Schlick and LSK never increase with c (every case)", ty->type->name);
    CHECK(name, strict_bad == 0, "%ld increases", strict_bad);
    snprintf(name, sizeof name,
             "extremes %s: exact forms on external dielectric reflection (eta <= 2 + sqrt 3) never rise by more than 2x the bound",
             ty->type->name);
    CHECK(name, exact_bad == 0 && cases >= 4, "%ld rises over %d cases, first %s", exact_bad, cases, first);
    NOTE("extremes %s: largest rise of the exact forms with c on those cases: %.3g (flat curve near c = 1)", ty->type->name,
         worst_rise);
}

/* Total internal reflection and the critical angle, for every case with
 * eta/n1 < 1 and kappa = 0: below the critical cosine exactly one; across
 * it, 128 consecutive cosines of the type each within the bound of the
 * reference and no step between neighbours that the reference lacks. */
static void test_critical_angle(const extreme_type *ty)
{
    static const char *const names[] = {"exact", "exact-conductor", "exact-dielectric", "schlick-internal"};
    const double ulp = ulp_upper(ty);
    int ei, k, i, cases = 0;
    char name[240];
    for (ei = 0; ei < extreme_case_count; ei++) {
        const extreme_case *e = &extreme_cases[ei];
        extreme_typed t;
        double cc, c0;
        if (!(e->kappa == 0.0 && e->eta < e->n1))
            continue;
        cases++;
        extreme_prepare(ty, e, &t);
        cc = sqrt((1.0 - t.p.eta) * (1.0 + t.p.eta)); /* the reference's critical cosine */
        c0 = floor(cc / ulp) * ulp;                    /* representable in the type: cc is in [0.5, 1) */
        for (k = 0; k < 4; k++) {
            const model *m = model_find(names[k]);
            long not_one = 0, over = 0, jump = 0;
            double worst = 0.0, worst_step = 0.0, prev_f = 0.0, prev_r = 0.0;
            for (i = 0; i <= 1000; i++) {
                double x = floor(cc * i / 1000.0 / ulp) * ulp, got;
                if (x < cc && eval(m, ty, &t, x, &got) && got != 1.0)
                    not_one++;
            }
            for (i = -64; i < 64; i++) {
                double x = c0 + i * ulp, got, ref_c, r, err;
                if (x > 1.0 || !extreme_eval(ty, m, &t, x, &got, &ref_c))
                    continue;
                r = m->ref->scalar(&t.p, ref_c);
                err = fabs(got - r);
                if (ref_c < cc && got != 1.0)
                    not_one++;
                if (!(err <= ty->type->bound(m)))
                    over++;
                worst = err > worst ? err : worst;
                if (i > -64) {
                    double step = fabs(got - prev_f), ref_step = fabs(r - prev_r);
                    if (step > ref_step + 2.0 * ty->type->bound(m))
                        jump++;
                    worst_step = step > worst_step ? step : worst_step;
                }
                prev_f = got;
                prev_r = r;
            }
            snprintf(name, sizeof name, "extremes %s: %s on %s: exactly one under total internal reflection",
                     ty->type->name, m->name, e->name);
            CHECK(name, not_one == 0, "%ld cosines below the critical %.9g do not give one", not_one, cc);
            snprintf(name, sizeof name,
                     "extremes %s: %s on %s: continuous across the critical angle (128 cosines within %.1e of the reference)",
                     ty->type->name, m->name, e->name, ty->type->bound(m));
            CHECK(name, over == 0 && jump == 0, "%ld beyond the bound (max %.3g), %ld steps not in the reference", over,
                  worst, jump);
            NOTE("%s %s on %s: largest step between neighbouring cosines at the critical angle %.3g", ty->type->name, m->name,
                 e->name, worst_step);
        }
    }
    snprintf(name, sizeof name, "extremes %s: at least three total-internal-reflection cases", ty->type->name);
    CHECK(name, cases >= 3, "%d", cases);
}

static int same_bits(float a, float b) { return memcmp(&a, &b, sizeof a) == 0; }

/* Reflectance parameters beyond [0, 1]: the documented clamp, the F82 clamp
 * (binary32), and the F82 model's error on extreme pairs in every type. */
static void test_reflectances(void)
{
    int ri, k, ti;
    long bad = 0;
    for (k = 0; k <= 4096; k++) {
        float c = (float)(k / 4096.0);
        int32_t qc = k * 8;
        bad += !same_bits(fresnel_schlick(1.04f, c), fresnel_schlick(1.0f, c));
        bad += !same_bits(fresnel_f82(1.04f, 1.04f, c), fresnel_f82(1.0f, 1.0f, c));
        bad += !same_bits(fresnel_cook_torrance(1.04f, 0.17f, 3.5f, c), fresnel_cook_torrance(1.0f, 0.17f, 3.5f, c));
        bad += !same_bits(fresnel_schlick(NAN, c), fresnel_schlick(0.0f, c));
        bad += fresnel_schlick_q15(34079, qc) != fresnel_schlick_q15(32768, qc);
        bad += fresnel_f82_q15(34079, 34079, qc) != fresnel_f82_q15(32768, 32768, qc);
        bad += fresnel_schlick_q15(-5, qc) != fresnel_schlick_q15(0, qc);
#if FRESNEL_HAS_F16
        bad += fresnel_schlick_f16((fresnel_f16)1.04f, (fresnel_f16)c) != fresnel_schlick_f16((fresnel_f16)1.0f, (fresnel_f16)c);
        bad += fresnel_f82_f16((fresnel_f16)1.04f, (fresnel_f16)1.04f, (fresnel_f16)c) !=
               fresnel_f82_f16((fresnel_f16)1.0f, (fresnel_f16)1.0f, (fresnel_f16)c);
#endif
    }
    CHECK("extremes: F0 1.04 (out-of-gamut gold) evaluates exactly as F0 1 in every type; NaN / negative F0 as 0",
          bad == 0, "%ld differ", bad);
    bad = 0;
    for (ri = 0; ri < extreme_reflectance_count; ri++) {
        const extreme_reflectance *x = &extreme_reflectances[ri];
        double lo = 1e300, hi = -1e300;
        for (k = 0; k <= 4096; k++) {
            float c = (float)(k / 4096.0), got = fresnel_f82(x->f0, x->f82, c);
            double u = extreme_f82_unclamped(x->f0, x->f82, c);
            lo = u < lo ? u : lo;
            hi = u > hi ? u : hi;
            /* Where the unclamped curve leaves [0, 1], the result is the end it crossed. */
            if (u < -1e-6)
                bad += got != 0.0f;
            if (u > 1.0 + 1e-6)
                bad += got != 1.0f;
        }
        if (ri == 4)
            CHECK("extremes: F82 > F0 (0.2, 0.9) takes the F82 curve above 1", hi > 1.0, "max %.4g", hi);
        if (ri == 6)
            CHECK("extremes: F82 << F0 (0.9, 0) takes the F82 curve below 0", lo < 0.0, "min %.4g", lo);
    }
    CHECK("extremes f32: F82 model on extreme F0/F82 pairs is clamped to the end its curve crosses", bad == 0,
          "%ld bad", bad);
    for (ti = 0; ti < extreme_type_count; ti++) {
        const extreme_type *ty = &extreme_types[ti];
        double worst = 0.0, bound = extreme_direct_bound(0, ti);
        char name[200];
        bad = 0;
        for (ri = 0; ri < extreme_reflectance_count; ri++) {
            const extreme_reflectance *x = &extreme_reflectances[ri];
            int b, na;
            double err = extreme_direct_max_err(0, ti, x->f0, x->f82, &b, &na);
            bad += b;
            worst = err > worst ? err : worst;
        }
        snprintf(name, sizeof name, "extremes %s: F82 model on extreme F0/F82 pairs in [0, 1] and within %.1e",
                 ty->type->name, bound);
        CHECK(name, bad == 0 && worst <= bound, "%ld bad, max|err| %.3g", bad, worst);
    }
}

static void test_gulbrandsen(void)
{
    int ri, ti;
    for (ti = 0; ti < extreme_type_count; ti++) {
        const extreme_type *ty = &extreme_types[ti];
        double worst = 0.0, bound = extreme_direct_bound(1, ti);
        long bad = 0;
        char name[200];
        for (ri = 0; ri < extreme_gulbrandsen_count; ri++) {
            const extreme_reflectance *x = &extreme_gulbrandsen[ri];
            int b, na;
            double err = extreme_direct_max_err(1, ti, x->f0, x->f82, &b, &na);
            bad += b;
            worst = err > worst ? err : worst;
        }
        snprintf(name, sizeof name, "extremes %s: Gulbrandsen at the ends of r and g: in [0, 1], within %.1e", ty->type->name,
                 bound);
        CHECK(name, bad == 0 && worst <= bound, "%ld bad, max|err| %.3g", bad, worst);
    }
}

/* fresnel_conductor_prepared and fresnel_conductor_batch on every
 * extreme case and cosine, the binary32 input policy included: results in
 * [0, 1]; c < 0, -0, NaN, -Inf exactly f(0) and c > 1, +Inf exactly f(1);
 * the batch bit for bit the prepared function; matched index 0 at every c;
 * within FRESNEL_BOUND_CONDUCTOR_PREPARED of ref_conductor where the bound
 * was measured, and across each critical angle; out-of-domain eta, kappa
 * (NaN, +-Inf, negative, huge, tiny) prepared as their clamped values; the
 * two-division form (eta kappa < 2^-30) and the domain's corners. */
static void test_conductor_prepared(void)
{
    static float grid[GRID_MAX], out[GRID_MAX];
    float cs[32];
    int ng = extreme_cos_grid(grid, GRID_MAX), ncs = extreme_cosine_count, ei, i;
    long bad_range = 0, bad_subst = 0, differ = 0, matched_bad = 0, over = 0, crit_over = 0;
    double worst = 0.0, worst_out = 0.0, worst_crit = 0.0;
    char first[256] = "";
    for (i = 0; i < ncs; i++)
        cs[i] = extreme_cosines[i].c;
    for (ei = 0; ei < extreme_case_count; ei++) {
        const extreme_case *e = &extreme_cases[ei];
        model_params mp;
        fresnel_conductor_prep p;
        float at0, at1, eta, kappa;
        extreme_params(e, &mp);
        eta = (float)mp.eta;
        kappa = (float)mp.kappa;
        p = fresnel_conductor_prepare(eta, kappa);
        at0 = fresnel_conductor_prepared(&p, 0.0f);
        at1 = fresnel_conductor_prepared(&p, 1.0f);
        fresnel_conductor_batch(&p, cs, out, ncs);
        for (i = 0; i < ncs; i++) {
            float c = cs[i], got = fresnel_conductor_prepared(&p, c);
            if (!(got >= 0.0f && got <= 1.0f)) {
                bad_range++;
                if (!*first)
                    snprintf(first, sizeof first, "%s at c = %s: %g", e->name, extreme_cosines[i].label, got);
            }
            if ((!(c >= 0.0f && c <= 1.0f) || (c == 0.0f && signbit(c))) && got != (c > 1.0f ? at1 : at0))
                bad_subst++;
            differ += memcmp(&got, &out[i], sizeof got) != 0;
            if (mp.eta == 1.0 && mp.kappa == 0.0)
                matched_bad += got != 0.0f;
        }
        fresnel_conductor_batch(&p, grid, out, ng);
        for (i = 0; i < ng; i++) {
            double err = fabs(out[i] - ref_conductor(eta, kappa, grid[i]));
            if (extreme_in_measured_domain(&mp)) {
                if (!(err <= worst))
                    worst = err;
                over += !(err <= FRESNEL_BOUND_CONDUCTOR_PREPARED);
            } else if (!(err <= worst_out))
                worst_out = err;
        }
        if (kappa == 0.0f && eta < 1.0f) { /* 2000 consecutive cosines across the critical one */
            double cc = sqrt((1.0 - eta) * (1.0 + eta));
            float x = nextafterf((float)cc, 0.0f);
            int k;
            for (k = 0; k < 1000; k++)
                x = nextafterf(x, 0.0f);
            for (k = 0; k < 2000; k++, x = nextafterf(x, 2.0f)) {
                double err = fabs(fresnel_conductor_prepared(&p, x) - ref_conductor(eta, kappa, x));
                if (!(err <= worst_crit))
                    worst_crit = err;
                crit_over += !(err <= FRESNEL_BOUND_CONDUCTOR_PREPARED);
            }
        }
    }
    CHECK("extremes f32: conductor-prepared and -batch give a number in [0, 1] on every case and cosine",
          bad_range == 0, "%ld bad, first %s", bad_range, first);
    CHECK("extremes f32: conductor-prepared: c < 0, -0, NaN, -Inf give exactly f(0); c > 1, +Inf exactly f(1)",
          bad_subst == 0, "%ld differ", bad_subst);
    CHECK("extremes f32: conductor-batch gives the prepared function's results bit for bit", differ == 0,
          "%ld differ", differ);
    CHECK("extremes f32: conductor-prepared: matched index gives 0 at every c, c = 0 included", matched_bad == 0,
          "%ld non-zero", matched_bad);
    NOTE("extremes f32: conductor-prepared max|err| %.3g in the measured range, %.3g outside it; %.3g across the "
         "critical angles (2000 consecutive cosines each)", worst, worst_out, worst_crit);
    CHECK("extremes f32: conductor-prepared within its bound where it was measured", over == 0, "%ld over, max %.3g",
          over, worst);
    CHECK("extremes f32: conductor-prepared within its bound across each critical angle", crit_over == 0,
          "%ld over, max %.3g", crit_over, worst_crit);
    {
        /* out-of-domain material parameters are prepared as their clamped values */
        static const float bad[] = {NAN, INFINITY, -INFINITY, -1.0f, 0.0f, 1e-30f, 1e30f};
        long wrong = 0, range = 0;
        int a, b, k;
        for (a = 0; a < 7; a++)
            for (b = 0; b < 7; b++) {
                float e = bad[a], kp = bad[b];
                float ce = e > FRESNEL_ETA_MIN ? (e < FRESNEL_ETA_MAX ? e : FRESNEL_ETA_MAX) : FRESNEL_ETA_MIN;
                float ck = kp >= FRESNEL_KAPPA_TINY ? (kp < FRESNEL_KAPPA_MAX ? kp : FRESNEL_KAPPA_MAX) : 0.0f;
                fresnel_conductor_prep p = fresnel_conductor_prepare(e, kp), q = fresnel_conductor_prepare(ce, ck);
                for (k = 0; k < ncs; k++) {
                    float r = fresnel_conductor_prepared(&p, cs[k]);
                    wrong += r != fresnel_conductor_prepared(&q, cs[k]);
                    range += !(r >= 0.0f && r <= 1.0f);
                }
            }
        CHECK("extremes f32: conductor-prepare of NaN, +-Inf, < 0, 0, tiny, huge eta and kappa: the clamped values, "
              "results in [0, 1]",
              wrong == 0 && range == 0, "%ld differ, %ld outside", wrong, range);
    }
    {
        /* the two-division form (eta kappa < 2^-30), near-dielectrics, and the domain's corners */
        static const float mat[][2] = {{0.5f, 1e-12f}, {1.0001f, 1e-15f}, {2.0f, 1e-18f}, {0.9f, 1e-10f},
                                       {0.9999999f, 1e-12f}, {1.0f, 1e-18f}, {1e-3f, 1e-6f}, {0.01f, 1e-7f},
                                       {1e5f, 1e5f}, {1e5f, 1e-3f}, {1e-3f, 1e5f}, {1e5f, 0.0f}, {1e-3f, 0.0f},
                                       {FRESNEL_ETA_MIN, 1e-6f}, {FRESNEL_ETA_MIN, 1e5f}, {FRESNEL_ETA_MIN, 0.0f}};
        double w_in = 0.0, w_out = 0.0;
        long range = 0;
        int m, k;
        for (m = 0; m < (int)(sizeof mat / sizeof mat[0]); m++) {
            fresnel_conductor_prep p = fresnel_conductor_prepare(mat[m][0], mat[m][1]);
            int in = mat[m][0] >= 0.01f && mat[m][0] <= 100.0f && mat[m][1] <= 1000.0f;
            fresnel_conductor_batch(&p, grid, out, ng);
            for (k = 0; k < ng; k++) {
                double err = fabs(out[k] - ref_conductor(mat[m][0], mat[m][1], grid[k]));
                range += !(out[k] >= 0.0f && out[k] <= 1.0f);
                if (in ? !(err <= w_in) : !(err <= w_out)) {
                    if (in)
                        w_in = err;
                    else
                        w_out = err;
                }
            }
        }
        NOTE("extremes f32: conductor-prepared on tiny kappa (two divisions below eta kappa = 2^-30): max|err| %.3g "
             "for eta in [0.01, 100]; %.3g at the domain's corners (eta 2^-10, 1e-3 or 1e5, kappa 1e-3 or 1e5)", w_in, w_out);
        CHECK("extremes f32: conductor-prepared on tiny kappa within its bound, results in [0, 1] at the corners",
              w_in <= FRESNEL_BOUND_CONDUCTOR_PREPARED && range == 0, "max %.3g, %ld outside", w_in, range);
    }
}

int main(void)
{
    int ti;
    for (ti = 0; ti < extreme_type_count; ti++) {
        const extreme_type *ty = &extreme_types[ti];
        test_cosine_policy(ty);
        test_bounds(ty);
        test_matched_index(ty);
        test_monotone(ty);
        test_critical_angle(ty);
    }
    test_q15_codes();
    test_reflectances();
    test_gulbrandsen();
    test_conductor_prepared();
    CHECK("extremes: the runtime's number types are all covered (f32, q15, and f16 where the compiler has it)",
          extreme_type_count == 2 + FRESNEL_HAS_F16, "%d types", extreme_type_count);
    return harness_exit();
}
