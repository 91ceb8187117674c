/* The hemispherical averages F_avg = 2 int_0^1 F(c) c dc of the runtime's
 * Schlick, generalized Schlick and F82 models (fresnel.h, fresnel_fixed.h):
 * first the closed forms in double against Simpson's rule on the models'
 * own double curves (the formulas), then the binary32 and Q15 functions
 * against the double closed form over their whole argument domain (the
 * stated bounds), and non-finite arguments. */
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
    CHECK("fresnel_schlick_gen_avg within FRESNEL_BOUND_SCHLICK_GEN_AVG (F0, F90 every 1/64, p over its range)",
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
    CHECK("fresnel_f82_avg within FRESNEL_BOUND_F82_AVG (F0, F82 every 1/512)", worst <= FRESNEL_BOUND_F82_AVG, "%.3g",
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
    return harness_exit();
}
