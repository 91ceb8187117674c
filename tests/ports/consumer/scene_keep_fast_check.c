/* Built against the header `fresnel gen` writes for tests/gen/test_gen_q15.sh's
 * gamut = keep scene (gold, whose red F0 is above 1 there; copper), under
 * UBSan with unsigned wrap-around trapped where the compiler offers it: the
 * fast paths of fresnel_fixed_fast.h that take an F0 (Schlick, its RGB form,
 * F82), fed the emitted F0 and F82 a, on every cos code 0..32768, give
 * results in [0, one] within their bounds of the model the clamping
 * functions evaluate (F0 and F82 above one read as one). Prints PASS/FAIL. */
#include <math.h>
#include <stdio.h>

#include "fresnel_fixed_fast.h"
#include "scene_keep.h"

static int failures;

static double unit(double x) { return x < 0.0 ? 0.0 : (x > 1.0 ? 1.0 : x); }
static double code(int v) { return unit(v / 32768.0); }

static void check(const char *what, const fresnel_rgb_q15 f0, const fresnel_rgb_q15 f82, const int32_t a_q12[3])
{
    double worst_s = 0.0, worst_f = 0.0;
    long outside = 0;
    int c, ch;
    for (c = 0; c <= 32768; c++) {
        double x = 1.0 - c / 32768.0, x5 = pow(x, 5.0);
        fresnel_rgb_q15 rgb = fresnel_schlick_q15_rgb_fast(f0, c);
        for (ch = 0; ch < 3; ch++) {
            int32_t f0c = ch == 0 ? f0.r : (ch == 1 ? f0.g : f0.b);
            int32_t f82c = ch == 0 ? f82.r : (ch == 1 ? f82.g : f82.b);
            double F0 = code(f0c), F82 = code(f82c);
            double a = (823543.0 / 46656.0) * (F0 - F82) + (49.0 / 6.0) * (1.0 - F0);
            double s_ref = F0 + (1.0 - F0) * x5, f_ref = unit(s_ref - a * (c / 32768.0) * x5 * x);
            int s = fresnel_schlick_q15_fast(f0c, c), f = fresnel_f82_q15_fast(f0c, a_q12[ch], c);
            int s3 = ch == 0 ? rgb.r : (ch == 1 ? rgb.g : rgb.b);
            outside += (s < 0 || s > 32768) + (f < 0 || f > 32768) + (s3 != s);
            if (fabs(s / 32768.0 - s_ref) > worst_s)
                worst_s = fabs(s / 32768.0 - s_ref);
            if (fabs(f / 32768.0 - f_ref) > worst_f)
                worst_f = fabs(f / 32768.0 - f_ref);
        }
    }
    worst_s *= 32768.0;
    worst_f *= 32768.0;
    if (outside == 0 && worst_s <= FRESNEL_BOUND_SCHLICK_Q15_FAST && worst_f <= FRESNEL_BOUND_F82_Q15_FAST)
        printf("PASS gen keep: %s F0 (%d, %d, %d) through fresnel_schlick_q15_fast, _rgb_fast and fresnel_f82_q15_fast: "
               "every cos code in [0, one], max error %.2f and %.2f LSB (bounds %.1f, %.1f)\n",
               what, f0.r, f0.g, f0.b, worst_s, worst_f, FRESNEL_BOUND_SCHLICK_Q15_FAST, FRESNEL_BOUND_F82_Q15_FAST);
    else {
        printf("FAIL gen keep: %s F0 (%d, %d, %d): %ld results outside [0, one] or rgb != scalar, max error %.2f and "
               "%.2f LSB (bounds %.1f, %.1f)\n",
               what, f0.r, f0.g, f0.b, outside, worst_s, worst_f, FRESNEL_BOUND_SCHLICK_Q15_FAST,
               FRESNEL_BOUND_F82_Q15_FAST);
        failures++;
    }
}

int main(void)
{
    check("au", fresnel_keep_au_f0_q15, fresnel_keep_au_f82_q15, fresnel_keep_au_f82_a_q12);
    check("cu", fresnel_keep_cu_f0_q15, fresnel_keep_cu_f82_q15, fresnel_keep_cu_f82_a_q12);
    return failures ? 1 : 0;
}
