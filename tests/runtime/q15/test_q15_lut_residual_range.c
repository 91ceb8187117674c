/* The Q15 residual LUT encodings at the ends of their ranges: int16_t nodes
 * with frac 14 (what the generator writes when a node reaches +-1, at a
 * total-reflection edge) and int8_t nodes with frac 6, every node pair from
 * the types' extremes (-2 .. 2), against the same interpolation in double
 * plus Schlick, clamped, with F0 from zero to one. The bound is
 * FRESNEL_BOUND_LUT_Q15's parts for a step of s between the two nodes: 0.5
 * for the rounding plus the position's half step (2^-16 of a segment) times
 * s 2^15, 0.5 s LSB; the documented 1.01 is that for s <= 1. In range:
 * Schlick 1 plus a residual of 1 must give one (the sum reaches 2^31). */
#include <math.h>
#include <stdint.h>

#include "fresnel_fixed.h"
#include "harness.h"
#include "common/reference.h"

static double ref(double f0, const double *v, int n, int linear, double c)
{
    double x = linear ? c : sqrt(c), pos = x * (n - 1), t;
    int i = (int)pos;
    if (i > n - 2)
        i = n - 2;
    t = pos - i;
    return ref_clamp(ref_schlick(f0, c) + v[i] + (v[i + 1] - v[i]) * t, 0.0, 1.0);
}

int main(void)
{
    static const int s16v[] = {-32768, -16384, -1, 0, 1, 16383, 16384, 32767};
    static const int s8v[] = {-128, -64, 0, 64, 127};
    static const int32_t f0s[] = {0, 1311, 16384, 32768};
    double worst16 = 0.0, worst8 = 0.0;
    long out = 0;
    int a, b, fi, lin;
    for (fi = 0; fi < 4; fi++)
        for (lin = 0; lin < 2; lin++) {
            for (a = 0; a < 8; a++)
                for (b = 0; b < 8; b++) {
                    int16_t t[2];
                    double v[2];
                    int32_t c;
                    t[0] = (int16_t)s16v[a], t[1] = (int16_t)s16v[b];
                    v[0] = ldexp(t[0], -14), v[1] = ldexp(t[1], -14);
                    for (c = 0; c <= 32768; c += 7) {
                        int32_t got = lin ? fresnel_lut_linear_residual_s16_q15(f0s[fi], t, 2, 14, c)
                                          : fresnel_lut_residual_s16_q15(f0s[fi], t, 2, 14, c);
                        double e = fabs(got - 32768.0 * ref(f0s[fi] / 32768.0, v, 2, lin, c / 32768.0)) -
                                   0.5 * fabs(v[1] - v[0]);
                        out += got < 0 || got > 32768;
                        worst16 = e > worst16 ? e : worst16;
                    }
                }
            for (a = 0; a < 5; a++)
                for (b = 0; b < 5; b++) {
                    int8_t t[2];
                    double v[2];
                    int32_t c;
                    t[0] = (int8_t)s8v[a], t[1] = (int8_t)s8v[b];
                    v[0] = ldexp(t[0], -6), v[1] = ldexp(t[1], -6);
                    for (c = 0; c <= 32768; c += 7) {
                        int32_t got = lin ? fresnel_lut_linear_residual_s8_q15(f0s[fi], t, 2, 6, c)
                                          : fresnel_lut_residual_s8_q15(f0s[fi], t, 2, 6, c);
                        double e = fabs(got - 32768.0 * ref(f0s[fi] / 32768.0, v, 2, lin, c / 32768.0)) -
                                   0.5 * fabs(v[1] - v[0]);
                        out += got < 0 || got > 32768;
                        worst8 = e > worst8 ? e : worst8;
                    }
                }
        }
    CHECK("Q15 residual s16 with frac 14 (nodes -2..2) within 0.51 + 0.5 step LSB of double", worst16 <= 0.51,
          "worst %.4f LSB beyond 0.5 step", worst16);
    CHECK("Q15 residual s8 with frac 6 (nodes -2..2) within 0.51 + 0.5 step LSB of double", worst8 <= 0.51,
          "worst %.4f LSB beyond 0.5 step", worst8);
    CHECK("Q15 residual s16/s8 at the range ends stay in [0, one]", out == 0, "%ld results out of range", out);
    return harness_exit();
}
