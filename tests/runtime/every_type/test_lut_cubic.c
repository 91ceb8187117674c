/* fresnel_lut_cubic in binary32, Q1.15 and binary16 against the same
 * Catmull-Rom in double at the table's own values: the runtime's rounding
 * only (the table's error is the generator's, tests/gen/test_lut_targets.c).
 * Tables: every node 0 or 1 alternating (the largest sums the Q15 weights
 * meet), steps, random, and smooth Fresnel-like curves; n = 2, 3, 4, 16,
 * 33, 256; and the same with headroom: nodes up to 2 - 2^-15 alternating
 * with 0, and an out-of-gamut curve above 1 (the keep policy's tables),
 * whose results are clamped to [0, max(1, p1, p2)]. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "fresnel.h"
#include "fresnel_f16.h"
#include "fresnel_fixed.h"
#include "harness.h"
#include "common/reference.h"

static double cubic_ref(const double *t, int n, double c)
{
    double x = sqrt(c) * (n - 1), hi = 1.0;
    int i = (int)x;
    if (i > n - 2)
        i = n - 2;
    hi = fmax(hi, fmax(t[i], t[i + 1]));
    return ref_clamp(ref_lut(t, n, 1, sqrt(c)), 0.0, hi); /* the weights form, not src/f32/lut.c's */
}

static double table_top(const double *t, int n)
{
    double top = 1.0;
    int i;
    for (i = 0; i < n; i++)
        top = fmax(top, t[i]);
    return top;
}

static uint32_t rng = 12345u;
static double uniform01(void)
{
    rng = rng * 1664525u + 1013904223u;
    return (rng >> 8) / 16777216.0;
}

#define KINDS 8
#define FIRST_CURVE 3 /* kinds from here on are reflectance curves */
#define HEADROOM 6    /* kinds from here on have nodes above 1 */
static void make_table(int kind, int n, double *t)
{
    int i;
    for (i = 0; i < n; i++) {
        double x = (double)i / (n - 1), c = x * x;
        switch (kind) {
        case 0: t[i] = i % 2; break;
        case 1: t[i] = i < n / 2 ? 0.0 : 1.0; break;
        case 2: t[i] = uniform01(); break;
        case 3: t[i] = 0.9 + 0.1 * pow(1 - c, 5) - 0.3 * c * pow(1 - c, 6); break; /* F82-like */
        case 4: t[i] = ref_conductor(0.18, 3.4, c); break; /* gold's red */
        case 5: t[i] = ref_conductor(3.1, 3.3, c); break; /* chromium */
        case 6: t[i] = i % 2 ? 65535.0 / 32768.0 : 0.0; break;
        default: t[i] = 1.0 + 0.04 * (1.0 - pow(1 - c, 5)) - 0.2 * pow(1 - c, 6); break; /* above 1, then below */
        }
    }
}

int main(void)
{
    static const int sizes[] = {2, 3, 4, 16, 33, 256};
    double worst_f32 = 0.0, worst_q15 = 0.0, worst_q15_headroom = 0.0, worst_f16 = 0.0, any_f32 = 0.0, any_f16 = 0.0;
    int in_range = 1, k, kind, j;
    for (k = 0; k < (int)(sizeof sizes / sizeof sizes[0]); k++)
        for (kind = 0; kind < KINDS; kind++) {
            int n = sizes[k], i, code;
            double t[256], tq[256], th[256];
            float tf[256];
            uint16_t q[256];
#if FRESNEL_HAS_F16
            fresnel_f16 h[256];
#endif
            make_table(kind, n, t);
            for (i = 0; i < n; i++) {
                tf[i] = (float)t[i];
                q[i] = (uint16_t)lround(t[i] * 32768.0);
                tq[i] = q[i] / 32768.0;
#if FRESNEL_HAS_F16
                h[i] = (fresnel_f16)t[i];
                th[i] = (double)h[i];
#else
                th[i] = t[i];
#endif
            }
            for (i = 0; i < n; i++)
                t[i] = tf[i]; /* the reference reads the float table */
            for (code = 0; code <= 32768; code++) {
                fresnel_q15 r = fresnel_lut_cubic_u16_q15(q, n, code);
                double e = fabs(r - 32768.0 * cubic_ref(tq, n, code / 32768.0));
                in_range &= r <= 32768.0 * table_top(tq, n);
                if (kind < HEADROOM && e > worst_q15)
                    worst_q15 = e;
                if (kind >= HEADROOM && e > worst_q15_headroom)
                    worst_q15_headroom = e;
            }
            for (j = 0; j <= 200000; j++) {
                float c = j == 200000 ? 1.0f : (float)(j / 200000.0) * (float)(j / 200000.0);
                float v = fresnel_lut_cubic(tf, n, c);
                double e = fabs(v - cubic_ref(t, n, c));
#if FRESNEL_HAS_F16
                fresnel_f16 hc = (fresnel_f16)c, hv = fresnel_lut_cubic_f16(h, n, hc);
                double eh = fabs((double)hv - cubic_ref(th, n, (double)hc));
                in_range &= (double)hv >= 0.0 && (double)hv <= table_top(th, n);
#else
                double eh = 0.0;
#endif
                in_range &= v >= 0.0f && v <= table_top(t, n);
                if (e > any_f32)
                    any_f32 = e;
                if (eh > any_f16)
                    any_f16 = eh;
                if (kind >= FIRST_CURVE && kind != HEADROOM && e > worst_f32)
                    worst_f32 = e;
                if (kind >= FIRST_CURVE && kind != HEADROOM && eh > worst_f16)
                    worst_f16 = eh;
            }
        }
    NOTE("lut cubic, max abs vs double at the table's values: reflectance curves binary32 %.3g, binary16 %.3g; "
         "any table binary32 %.3g, binary16 %.3g, Q1.15 %.4f LSB (nodes up to 2 - 2^-15: %.4f LSB)",
         worst_f32, worst_f16, any_f32, any_f16, worst_q15, worst_q15_headroom);
    CHECK("lut cubic binary32 within 5e-7 of double on reflectance curves (fresnel.h)", worst_f32 <= 5e-7, "%.3g",
          worst_f32);
    CHECK("lut cubic Q1.15 within FRESNEL_BOUND_LUT_CUBIC_Q15 LSB", worst_q15 <= FRESNEL_BOUND_LUT_CUBIC_Q15, "%.4f",
          worst_q15);
    CHECK("lut cubic Q1.15 with nodes above one within FRESNEL_BOUND_LUT_CUBIC_Q15_HEADROOM LSB",
          worst_q15_headroom <= FRESNEL_BOUND_LUT_CUBIC_Q15_HEADROOM, "%.4f", worst_q15_headroom);
#if FRESNEL_HAS_F16
    CHECK("lut cubic binary16 within FRESNEL_BOUND_LUT_CUBIC_F16 on reflectance curves", worst_f16 <= FRESNEL_BOUND_LUT_CUBIC_F16, "%.3g",
          worst_f16);
#endif
    CHECK("lut cubic results in [0, max(1, largest node)] in every type", in_range, "out of range");
    {
        /* the RGB forms are the scalar ones per channel */
        double t[48];
        float tf[48];
        uint16_t q[48];
        int ok = 1, code;
        make_table(3, 48, t);
        for (k = 0; k < 48; k++) {
            tf[k] = (float)t[k] * (k < 16 ? 1.0f : (k < 32 ? 0.7f : 0.4f));
            q[k] = (uint16_t)lround(tf[k] * 32768.0);
        }
        for (code = 0; code <= 32768; code += 7) {
            fresnel_rgb_q15 r = fresnel_lut_cubic_u16_q15_rgb(q, 16, code);
            fresnel_rgb f = fresnel_lut_cubic_rgb(tf, 16, code / 32768.0f);
            ok &= r.r == fresnel_lut_cubic_u16_q15(q, 16, code) && r.g == fresnel_lut_cubic_u16_q15(q + 16, 16, code) &&
                  r.b == fresnel_lut_cubic_u16_q15(q + 32, 16, code);
            ok &= f.r == fresnel_lut_cubic(tf, 16, code / 32768.0f) &&
                  f.g == fresnel_lut_cubic(tf + 16, 16, code / 32768.0f) &&
                  f.b == fresnel_lut_cubic(tf + 32, 16, code / 32768.0f);
        }
        CHECK("lut cubic RGB forms equal the scalar ones per channel", ok, "differ");
    }
    return harness_exit();
}
