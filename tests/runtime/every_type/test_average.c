/* The hemispherical averages F_avg = 2 int_0^1 F(c) c dc of the runtime's
 * Schlick, generalized Schlick and F82 models (fresnel.h, fresnel_fixed.h):
 * first the closed forms in double against Simpson's rule on the models'
 * own double curves (the formulas), then the binary32 and Q15 functions
 * against the double closed form over their whole argument domain (the
 * stated bounds), and non-finite arguments. Then the LUT averages
 * (lut_avg.c, lut_avg_q15.c): the weighted node sums against the integral
 * of the interpolant itself, by a 4-point Gauss-Legendre rule on each
 * interval (exact for its degree-6 integrand up to rounding), on tables
 * inside [0, 1], with headroom up to 2, and of Fresnel shape. */
#include <math.h>
#include <stdint.h>

#include "fresnel.h"
#include "fresnel_fixed.h"
#include "harness.h"

#define SIMPSON_N 4000

static double schlick_gen_curve(double f0, double f90, double p, double c)
{
    return f0 + (f90 - f0) * pow(1.0 - c, p);
}

static double f82_a(double f0, double f82)
{
    return (823543.0 / 46656.0) * (f0 - f82) + (49.0 / 6.0) * (1.0 - f0);
}

static double f82_curve(double f0, double f82, double c)
{
    return f0 + (1.0 - f0) * pow(1.0 - c, 5) - f82_a(f0, f82) * c * pow(1.0 - c, 6);
}

/* 2 int_0^1 f(c) c dc by Simpson's rule; exact for these polynomials up to rounding. */
#define AVERAGE_OF(expr, out)                                                                          \
    do {                                                                                               \
        int k_;                                                                                        \
        double sum_ = 0.0;                                                                             \
        for (k_ = 0; k_ <= SIMPSON_N; k_++) {                                                          \
            double c = (double)k_ / SIMPSON_N;                                                         \
            double w_ = (k_ == 0 || k_ == SIMPSON_N) ? 1.0 : (k_ % 2 ? 4.0 : 2.0);                     \
            sum_ += w_ * (expr) * c;                                                                   \
        }                                                                                              \
        (out) = 2.0 * sum_ / (3.0 * SIMPSON_N);                                                        \
    } while (0)

static double schlick_gen_avg_exact(double f0, double f90, double p)
{
    return f0 + (f90 - f0) * 2.0 / ((p + 1.0) * (p + 2.0));
}

static double f82_avg_exact(double f0, double f82)
{
    return f0 + (1.0 - f0) / 21.0 - f82_a(f0, f82) / 126.0;
}

/* 1 if the F82 curve of (f0, f82) stays inside [0, 1] (where the runtime's clamp does nothing). */
static int f82_inside(double f0, double f82)
{
    int k;
    for (k = 0; k <= 1000; k++) {
        double v = f82_curve(f0, f82, k / 1000.0);
        if (v < 0.0 || v > 1.0)
            return 0;
    }
    return 1;
}

static double clampd(double x) { return x < 0.0 ? 0.0 : x > 1.0 ? 1.0 : x; }

/* The interpolant of fresnel_lut (form 0), fresnel_lut_cubic (1) or
 * fresnel_lut_linear (2) at position u in node units on interval j. */
static double interp_at(const double *t, int n, int form, int j, double u)
{
    int last = n - 1, q0 = j > 0 ? j - 1 : 0, q3 = j + 2 <= last ? j + 2 : last;
    double p0 = t[q0], p1 = t[j], p2 = t[j + 1], p3 = t[q3];
    if (form != 1)
        return p1 + u * (p2 - p1);
    return p1 + 0.5 * u * (p2 - p0 + u * (2.0 * p0 - 5.0 * p1 + 4.0 * p2 - p3 + u * (3.0 * (p1 - p2) + p3 - p0)));
}

/* 2 int_0^1 L(c) c dc: in x = sqrt(c) it is int L 4x^3 dx (forms 0, 1). */
static double lut_avg_ref(const double *t, int n, int form)
{
    static const double gx[4] = {0.0694318442029737, 0.3300094782075719, 0.6699905217924281, 0.9305681557970263};
    static const double gw[4] = {0.1739274225687269, 0.3260725774312731, 0.3260725774312731, 0.1739274225687269};
    double h = 1.0 / (n - 1), sum = 0.0;
    int j, k;
    if (n == 1)
        return t[0];
    for (j = 0; j < n - 1; j++)
        for (k = 0; k < 4; k++) {
            double x = (j + gx[k]) * h, v = interp_at(t, n, form, j, gx[k]);
            sum += gw[k] * h * v * (form == 2 ? 2.0 * x : 4.0 * x * x * x);
        }
    return sum;
}

static uint32_t lcg = 2463534242u;
static double next01(void)
{
    lcg = lcg * 1664525u + 1013904223u;
    return (lcg >> 8) / 16777216.0;
}

/* The n of the worst-case search: every n to 300, then pairs (odd and even
 * N) about 8% apart up to FRESNEL_LUT_N_MAX, which is the last. */
static int search_sizes(int *out)
{
    int k = 0, m;
    for (m = 1; m <= 300; m++)
        out[k++] = m;
    for (m = 300 + 24; m < FRESNEL_LUT_N_MAX; m += m / 12) {
        out[k++] = m;
        out[k++] = m + 1;
    }
    out[k++] = FRESNEL_LUT_N_MAX - 1;
    out[k++] = FRESNEL_LUT_N_MAX;
    return k;
}

/* Node i of table kind `kind` (nodes in [0, 2 - 2^-15]): random in [0, 1],
 * random up to the top, a Fresnel shape, alternating extremes (both
 * phases), random extremes, constants 1 and top, a step at a random node,
 * and nodes just off the extremes. */
#define TABLE_KINDS 11
static double table_node(int kind, int n, int i, int pick)
{
    const double top = 65535.0 / 32768.0;
    double x = n > 1 ? (double)i / (n - 1) : 1.0, c = x * x;
    switch (kind) {
    case 0: return next01();
    case 1: return top * next01();
    case 2: return 0.9 + 0.1 * pow(1 - c, 5) - 0.3 * c * pow(1 - c, 6);
    case 3: return i % 2 ? top : 0.0;
    case 4: return i % 2 ? 0.0 : top;
    case 5: return next01() < 0.5 ? 0.0 : top;
    case 6: return 1.0;
    case 7: return top;
    case 8: return i < pick ? 0.0 : top;
    case 9: return i < pick ? top : 0.0;
    default: return next01() < 0.5 ? 1.0 / 32768.0 : top - 1.0 / 32768.0;
    }
}

static void check_lut_averages(void)
{
    static double t[32768], tq[32768];
    static float tf[32768];
    static uint16_t q[32768];
    static int sizes[600];
    double worst_f32 = 0.0, worst_q15 = 0.0;
    int worst_f32_n = 0, worst_q15_n = 0, worst_f32_kind = 0, worst_q15_kind = 0, ns = search_sizes(sizes), si;
    int n, kind, form, i, ok_range = 1, ok_const = 1;
    for (si = 0; si < ns; si++) {
        n = sizes[si];
        for (kind = 0; kind < TABLE_KINDS; kind++) {
            int pick = (int)(next01() * n);
            for (i = 0; i < n; i++) {
                tf[i] = (float)table_node(kind, n, i, pick);
                q[i] = (uint16_t)floor(tf[i] * 32768.0 + 0.5);
                tq[i] = q[i] / 32768.0;
                t[i] = tf[i];
            }
            for (form = 0; form < 3; form++) {
                double ref = lut_avg_ref(t, n, form), refq = lut_avg_ref(tq, n, form), top = 1.0, tqtop = 1.0;
                float v = form == 0 ? fresnel_lut_avg(tf, n) : (form == 1 ? fresnel_lut_cubic_avg(tf, n) : fresnel_lut_linear_avg(tf, n));
                fresnel_q15 r = form == 0 ? fresnel_lut_avg_u16_q15(q, n)
                                          : (form == 1 ? fresnel_lut_cubic_avg_u16_q15(q, n) : fresnel_lut_linear_avg_u16_q15(q, n));
                double eq, ef;
                for (i = 0; i < n; i++) {
                    top = fmax(top, t[i]);
                    tqtop = fmax(tqtop, tq[i]);
                }
                /* the results are held to [0, max(1, largest node)]: a cubic's negative end weight can take
                 * the integral below 0 */
                eq = fabs(r - 32768.0 * fmin(fmax(refq, 0.0), tqtop));
                ef = fabs(v - fmin(fmax(ref, 0.0), top));
                ok_range &= v >= 0.0f && v <= top && r <= 32768.0 * tqtop;
                if (kind == 6)
                    ok_const &= fabs(v - 1.0) <= 4e-7 && (r >= 32767 && r <= 32769);
                if (ef > worst_f32) {
                    worst_f32 = ef;
                    worst_f32_n = n;
                    worst_f32_kind = kind;
                }
                if (eq > worst_q15) {
                    worst_q15 = eq;
                    worst_q15_n = n;
                    worst_q15_kind = kind;
                }
            }
        }
    }
    NOTE("LUT averages against the interpolant's integral, %d values of n from 1 to %d, %d table kinds: binary32 "
         "%.3g (n %d, kind %d), Q15 %.4f LSB (n %d, kind %d)",
         ns, FRESNEL_LUT_N_MAX, TABLE_KINDS, worst_f32, worst_f32_n, worst_f32_kind, worst_q15, worst_q15_n,
         worst_q15_kind);
    CHECK("fresnel_lut_*_avg within FRESNEL_BOUND_LUT_AVG of the interpolant's integral",
          worst_f32 <= FRESNEL_BOUND_LUT_AVG, "%.3g at n %d, table kind %d", worst_f32, worst_f32_n, worst_f32_kind);
    CHECK("fresnel_lut_*_avg_u16_q15 within FRESNEL_BOUND_LUT_AVG_Q15 LSB", worst_q15 <= FRESNEL_BOUND_LUT_AVG_Q15,
          "%.4f at n %d, table kind %d", worst_q15, worst_q15_n, worst_q15_kind);
    CHECK("LUT averages in [0, max(1, largest node)]; a constant table of 1 averages to 1", ok_range && ok_const,
          "range %d, constant %d", ok_range, ok_const);
    {
        /* binary32 nodes outside [0, 2]: negative ones (against the integral held to [0, top]), large
         * ones (relative error), infinite ones (FLT_MAX: a finite result), a NaN (0) */
        static const float odd[4] = {-1.5f, 1e30f, INFINITY, NAN};
        double worst_neg = 0.0, worst_big = 0.0;
        int ok_inf = 1, ok_nan = 1, o;
        for (o = 0; o < 4; o++)
            for (n = 2; n <= 70; n++)
                for (form = 0; form < 3; form++) {
                    float v;
                    double ref, top = 1.0;
                    for (i = 0; i < n; i++) {
                        tf[i] = (i * 7) % 3 == 0 ? odd[o] : (float)next01();
                        t[i] = tf[i];
                        top = fmax(top, t[i]);
                    }
                    v = form == 0 ? fresnel_lut_avg(tf, n) : (form == 1 ? fresnel_lut_cubic_avg(tf, n) : fresnel_lut_linear_avg(tf, n));
                    ref = o < 2 ? fmin(fmax(lut_avg_ref(t, n, form), 0.0), top) : 0.0;
                    if (o == 0)
                        worst_neg = fmax(worst_neg, fabs(v - ref));
                    else if (o == 1)
                        worst_big = fmax(worst_big, ref > 0.0 ? fabs(v - ref) / ref : v);
                    else if (o == 2)
                        ok_inf &= isfinite(v) && v >= 0.0f;
                    else
                        ok_nan &= v == 0.0f;
                }
        CHECK("fresnel_lut_*_avg on nodes outside [0, 2]: negative nodes within FRESNEL_BOUND_LUT_AVG, nodes of 1e30 "
              "within 2^-23 relative, infinite nodes give a finite result, a NaN node 0",
              worst_neg <= FRESNEL_BOUND_LUT_AVG && worst_big <= 0x1p-23 && ok_inf && ok_nan,
              "negative %.3g, large %.3g relative, infinite %d, NaN %d", worst_neg, worst_big, ok_inf, ok_nan);
    }
    {
        /* RGB forms are the scalar ones per channel; n <= 0 gives 0. */
        int ok = 1;
        fresnel_rgb f;
        fresnel_rgb_q15 r;
        for (i = 0; i < 48; i++) {
            tf[i] = (float)next01();
            q[i] = (uint16_t)(tf[i] * 32768.0f);
        }
        f = fresnel_lut_cubic_avg_rgb(tf, 16);
        r = fresnel_lut_avg_u16_q15_rgb(q, 16);
        ok &= f.r == fresnel_lut_cubic_avg(tf, 16) && f.g == fresnel_lut_cubic_avg(tf + 16, 16) &&
              f.b == fresnel_lut_cubic_avg(tf + 32, 16);
        ok &= r.r == fresnel_lut_avg_u16_q15(q, 16) && r.g == fresnel_lut_avg_u16_q15(q + 16, 16) &&
              r.b == fresnel_lut_avg_u16_q15(q + 32, 16);
        r = fresnel_lut_cubic_avg_u16_q15_rgb(q, 16);
        ok &= r.r == fresnel_lut_cubic_avg_u16_q15(q, 16) && r.g == fresnel_lut_cubic_avg_u16_q15(q + 16, 16) &&
              r.b == fresnel_lut_cubic_avg_u16_q15(q + 32, 16);
        r = fresnel_lut_linear_avg_u16_q15_rgb(q, 16);
        ok &= r.r == fresnel_lut_linear_avg_u16_q15(q, 16) && r.g == fresnel_lut_linear_avg_u16_q15(q + 16, 16) &&
              r.b == fresnel_lut_linear_avg_u16_q15(q + 32, 16);
        ok &= fresnel_lut_avg(tf, 0) == 0.0f && fresnel_lut_linear_avg_u16_q15(q, -5) == 0;
        CHECK("LUT average RGB forms equal the scalar ones; n <= 0 gives 0", ok, "differ");
    }
    {
        /* Schlick's and F82's Q1.15 averages: the RGB form is the scalar
         * one per channel, on codes across [0, one] and beyond */
        static const int32_t codes[] = {-5, 0, 1, 1311, 16384, 31130, 32767, 32768, 40000};
        int ok = 1, a, b;
        for (a = 0; a < 9; a++)
            for (b = 0; b < 9; b++) {
                fresnel_rgb_q15 f0, f82, r;
                f0.r = (fresnel_q15)codes[a];
                f0.g = (fresnel_q15)codes[b];
                f0.b = (fresnel_q15)codes[(a + b) % 9];
                f82.r = f0.g, f82.g = f0.b, f82.b = f0.r;
                r = fresnel_schlick_avg_q15_rgb(f0);
                ok &= r.r == fresnel_schlick_avg_q15(f0.r) && r.g == fresnel_schlick_avg_q15(f0.g) &&
                      r.b == fresnel_schlick_avg_q15(f0.b);
                r = fresnel_f82_avg_q15_rgb(f0, f82);
                ok &= r.r == fresnel_f82_avg_q15(f0.r, f82.r) && r.g == fresnel_f82_avg_q15(f0.g, f82.g) &&
                      r.b == fresnel_f82_avg_q15(f0.b, f82.b);
            }
        CHECK("fresnel_schlick_avg_q15_rgb and fresnel_f82_avg_q15_rgb equal the scalar forms per channel", ok,
              "differ");
    }
    {
        /* The binary32 RGB averages: each channel is the scalar form (the
         * tables' channels one after another, n nodes each), on values
         * across [0, 1] and beyond, and Schlick's average of a grey F0
         * within FRESNEL_BOUND_SCHLICK_AVG of the closed form in double. */
        static const float vals[] = {-0.5f, 0.0f, 1e-8f, 0.04f, 0.5f, 0.9f, 1.0f, 1.04f, 3.0f};
        int ok = 1, ok_lut = 1, a, b, m;
        double worst_ref = 0.0;
        fresnel_rgb f0, f82, r;
        for (a = 0; a < 9; a++)
            for (b = 0; b < 9; b++) {
                f0.r = vals[a];
                f0.g = vals[b];
                f0.b = vals[(a + b) % 9];
                f82.r = f0.g, f82.g = f0.b, f82.b = f0.r;
                r = fresnel_schlick_avg_rgb(f0);
                ok &= r.r == fresnel_schlick_avg(f0.r) && r.g == fresnel_schlick_avg(f0.g) &&
                      r.b == fresnel_schlick_avg(f0.b);
                r = fresnel_f82_avg_rgb(f0, f82);
                ok &= r.r == fresnel_f82_avg(f0.r, f82.r) && r.g == fresnel_f82_avg(f0.g, f82.g) &&
                      r.b == fresnel_f82_avg(f0.b, f82.b);
            }
        for (a = 0; a <= 16; a++) {
            f0.r = f0.g = f0.b = (float)a / 16.0f;
            r = fresnel_schlick_avg_rgb(f0);
            worst_ref = fmax(worst_ref, fabs(r.g - schlick_gen_avg_exact(f0.g, 1.0, 5.0)));
        }
        CHECK("fresnel_schlick_avg_rgb and fresnel_f82_avg_rgb equal the scalar forms per channel; Schlick's "
              "within FRESNEL_BOUND_SCHLICK_AVG of the closed form",
              ok && worst_ref <= FRESNEL_BOUND_SCHLICK_AVG, "per channel %s, closed form %.3g", ok ? "equal" : "differ",
              worst_ref);
        for (m = -1; m <= 16; m++) {
            for (a = 0; a < 48; a++)
                tf[a] = (float)(2.0 * next01());
            r = fresnel_lut_avg_rgb(tf, m);
            ok_lut &= r.r == fresnel_lut_avg(tf, m) && r.g == fresnel_lut_avg(tf + (m > 0 ? m : 0), m) &&
                      r.b == fresnel_lut_avg(tf + 2 * (m > 0 ? m : 0), m);
            r = fresnel_lut_linear_avg_rgb(tf, m);
            ok_lut &= r.r == fresnel_lut_linear_avg(tf, m) && r.g == fresnel_lut_linear_avg(tf + (m > 0 ? m : 0), m) &&
                      r.b == fresnel_lut_linear_avg(tf + 2 * (m > 0 ? m : 0), m);
            if (m <= 0)
                ok_lut &= r.r == 0.0f && r.g == 0.0f && r.b == 0.0f;
        }
        CHECK("fresnel_lut_avg_rgb and fresnel_lut_linear_avg_rgb equal the scalar forms per channel, n -1..16",
              ok_lut, "differ");
    }
}

int main(void)
{
    double worst = 0.0, v, f0, f82, f90, p;
    int i, j, k, inside = 0;

    /* ---- the closed forms are the averages of the curves */
    for (i = 0; i <= 10; i++)
        for (k = 0; k < 6; k++) {
            static const double ps[6] = {1.0, 1.5, 2.0, 5.0, 7.5, 40.0}; /* p < 1: a cusp at c = 1 Simpson resolves slowly */
            f0 = i / 10.0;
            AVERAGE_OF(schlick_gen_curve(f0, 1.0 - 0.3 * f0, ps[k], c), v);
            worst = fmax(worst, fabs(v - schlick_gen_avg_exact(f0, 1.0 - 0.3 * f0, ps[k])));
        }
    CHECK("generalized Schlick: F0 + (F90 - F0) 2/((p+1)(p+2)) is the curve's average", worst < 1e-9, "%.3g", worst);
    worst = 0.0;
    for (i = 0; i <= 32; i++)
        for (j = 0; j <= 32; j++) {
            double avg_clamped;
            f0 = i / 32.0;
            f82 = j / 32.0;
            AVERAGE_OF(f82_curve(f0, f82, c), v);
            worst = fmax(worst, fabs(v - f82_avg_exact(f0, f82)));
            if (f82_inside(f0, f82)) {
                AVERAGE_OF(clampd(f82_curve(f0, f82, c)), avg_clamped);
                worst = fmax(worst, fabs(avg_clamped - f82_avg_exact(f0, f82)));
                inside++;
            }
        }
    CHECK("F82: F0 + (1-F0)/21 - a/126 is the curve's average (and the clamped model's where it stays in [0, 1])",
          worst < 1e-9, "%.3g", worst);
    NOTE("F82 pairs on a 1/32 grid whose curve stays inside [0, 1]: %d of %d", inside, 33 * 33);

    /* ---- binary32 against the double closed form, over the domain */
    worst = 0.0;
    for (i = 0; i <= 1 << 16; i++) {
        f0 = (double)(float)(i / 65536.0);
        worst = fmax(worst, fabs(fresnel_schlick_avg((float)f0) - (f0 + (1.0 - f0) / 21.0)));
    }
    CHECK("fresnel_schlick_avg within FRESNEL_BOUND_SCHLICK_AVG (F0 every 2^-16)", worst <= FRESNEL_BOUND_SCHLICK_AVG,
          "%.3g", worst);
    NOTE("fresnel_schlick_avg: max error %.3g", worst);
    worst = 0.0;
    for (i = 0; i <= 64; i++)
        for (j = 0; j <= 64; j++)
            for (k = 0; k <= 60; k++) {
                float pf = (float)(FRESNEL_P_MIN * pow(FRESNEL_P_MAX / FRESNEL_P_MIN, k / 60.0));
                f0 = (double)(float)(i / 64.0);
                f90 = (double)(float)(j / 64.0);
                p = (double)pf;
                v = fresnel_schlick_gen_avg((float)f0, (float)f90, pf);
                worst = fmax(worst, fabs(v - clampd(schlick_gen_avg_exact(f0, f90, p))));
            }
    for (i = 0; i < 1000000; i++) { /* and random F0, F90, log p */
        float pf = (float)(FRESNEL_P_MIN * pow(FRESNEL_P_MAX / FRESNEL_P_MIN, next01()));
        f0 = (double)(float)next01();
        f90 = (double)(float)next01();
        v = fresnel_schlick_gen_avg((float)f0, (float)f90, pf);
        worst = fmax(worst, fabs(v - clampd(schlick_gen_avg_exact(f0, f90, (double)pf))));
    }
    CHECK("fresnel_schlick_gen_avg within FRESNEL_BOUND_SCHLICK_GEN_AVG (F0, F90 every 1/64, p over its range; 1e6 "
          "random)",
          worst <= FRESNEL_BOUND_SCHLICK_GEN_AVG, "%.3g", worst);
    NOTE("fresnel_schlick_gen_avg: max error %.3g", worst);
    worst = 0.0;
    for (i = 0; i <= 512; i++)
        for (j = 0; j <= 512; j++) {
            f0 = (double)(float)(i / 512.0);
            f82 = (double)(float)(j / 512.0);
            v = fresnel_f82_avg((float)f0, (float)f82);
            worst = fmax(worst, fabs(v - clampd(f82_avg_exact(f0, f82))));
        }
    for (i = 0; i < 1000000; i++) { /* and random F0, F82 */
        f0 = (double)(float)next01();
        f82 = (double)(float)next01();
        v = fresnel_f82_avg((float)f0, (float)f82);
        worst = fmax(worst, fabs(v - clampd(f82_avg_exact(f0, f82))));
    }
    CHECK("fresnel_f82_avg within FRESNEL_BOUND_F82_AVG (F0, F82 every 1/512; 1e6 random)", worst <= FRESNEL_BOUND_F82_AVG, "%.3g",
          worst);
    NOTE("fresnel_f82_avg: max error %.3g", worst);
    {
        float bad[4] = {NAN, INFINITY, -INFINITY, 1e30f};
        int ok = 1;
        for (i = 0; i < 4; i++) {
            float a = fresnel_schlick_avg(bad[i]), b = fresnel_f82_avg(bad[i], 0.5f), c = fresnel_f82_avg(0.5f, bad[i]),
                  d = fresnel_schlick_gen_avg(bad[i], bad[i], bad[i]);
            ok &= a >= 0.0f && a <= 1.0f && b >= 0.0f && b <= 1.0f && c >= 0.0f && c <= 1.0f && d >= 0.0f && d <= 1.0f;
        }
        CHECK("binary32 averages: NaN and infinite arguments give results in [0, 1]", ok, "out of range");
    }

    /* ---- Q15 against the exact average of the argument codes, every code */
    worst = 0.0;
    for (i = -2; i <= 32770; i++) {
        double x = i < 0 ? 0.0 : i > 32768 ? 1.0 : i / 32768.0;
        worst = fmax(worst, fabs(fresnel_schlick_avg_q15(i) - 32768.0 * (x + (1.0 - x) / 21.0)));
    }
    CHECK("fresnel_schlick_avg_q15 within FRESNEL_BOUND_SCHLICK_AVG_Q15 LSB (every code, and beyond)",
          worst <= FRESNEL_BOUND_SCHLICK_AVG_Q15, "%.4f LSB", worst);
    NOTE("fresnel_schlick_avg_q15: max error %.4f LSB", worst);
    worst = 0.0;
    for (i = 0; i <= 32768; i += 8)
        for (j = 0; j <= 32768; j += 8) {
            int32_t a = i == 32768 ? 32768 : i + (j & 7), b = j;
            double exact = 32768.0 * clampd(f82_avg_exact(a / 32768.0, b / 32768.0));
            worst = fmax(worst, fabs(fresnel_f82_avg_q15(a, b) - exact));
        }
    CHECK("fresnel_f82_avg_q15 within FRESNEL_BOUND_F82_AVG_Q15 LSB (F0, F82 codes every 8)",
          worst <= FRESNEL_BOUND_F82_AVG_Q15, "%.4f LSB", worst);
    NOTE("fresnel_f82_avg_q15: max error %.4f LSB", worst);
    {
        int32_t bad[4] = {INT32_MIN, -1, 32769, INT32_MAX};
        int ok = 1;
        for (i = 0; i < 4; i++)
            for (j = 0; j < 4; j++) {
                fresnel_q15 a = fresnel_f82_avg_q15(bad[i], bad[j]), b = fresnel_schlick_avg_q15(bad[i]);
                ok &= a <= 32768 && b <= 32768; /* fresnel_q15 is unsigned */
            }
        CHECK("Q15 averages: codes outside [0, 32768] are clamped, results in [0, 32768]", ok, "out of range");
    }
    check_lut_averages();
    return harness_exit();
}
