/* Built against the header `fresnel gen` writes for tests/gen/test_gen_fast_rgb.sh's
 * q15-only scene (gold and copper; schlick, f82, exact), as a firmware
 * writes it: the three-channel fast paths of fresnel_q15_fast.h take the
 * emitted constants as they are. On every cos code 0..32768 each channel of
 * fresnel_f82_q15_rgb_fast and fresnel_conductor_q15_rgb_fast equals the
 * one-channel fast path's, and lies within the fast bound plus the clamped
 * function's bound of fresnel_f82_q15_rgb and fresnel_conductor_q15_rgb.
 * FRESNEL_SINGLE: the runtime from fresnel_single_q15.h, implemented here.
 * Prints PASS/FAIL lines. */
#include <math.h>
#include <stdio.h>

#ifdef FRESNEL_SINGLE
#define FRESNEL_IMPLEMENTATION
#include "fresnel_single_q15.h"
#else
#include "fresnel_q15_fast.h"
#endif
#include "metals.h"

static int channel(fresnel_rgb_q15 v, int ch) { return ch == 0 ? v.r : (ch == 1 ? v.g : v.b); }

static void check(const char *what, const fresnel_rgb_q15 f0, const fresnel_rgb_q15 f82, const int32_t a_q12[3],
                  const fresnel_ior_prep_q15 ior[3], const fresnel_conductor_prep_q15_fast fast[3])
{
    const double bound_f82 = FRESNEL_BOUND_F82_Q15_FAST + FRESNEL_BOUND_F82_Q15;
    const double bound_exact = FRESNEL_BOUND_CONDUCTOR_Q15_FAST + FRESNEL_BOUND_CONDUCTOR_Q15;
    double worst_f82 = 0.0, worst_exact = 0.0, d;
    long differ = 0;
    int32_t c;
    int ch;
    for (c = 0; c <= 32768; c++) {
        const fresnel_rgb_q15 f = fresnel_f82_q15_rgb_fast(f0, a_q12, c), e = fresnel_conductor_q15_rgb_fast(fast, c);
        const fresnel_rgb_q15 f_ref = fresnel_f82_q15_rgb(f0, f82, c), e_ref = fresnel_conductor_q15_rgb(ior, c);
        for (ch = 0; ch < 3; ch++) {
            differ += channel(f, ch) != fresnel_f82_q15_fast(channel(f0, ch), a_q12[ch], c);
            differ += channel(e, ch) != fresnel_conductor_q15_fast(&fast[ch], c);
            d = fabs((double)channel(f, ch) - channel(f_ref, ch));
            worst_f82 = d > worst_f82 ? d : worst_f82;
            d = fabs((double)channel(e, ch) - channel(e_ref, ch));
            worst_exact = d > worst_exact ? d : worst_exact;
        }
    }
    printf("%s %s: fresnel_f82_q15_rgb_fast and fresnel_conductor_q15_rgb_fast on the emitted constants, every cos "
           "code: %ld channels differ from the one-channel fast paths; within %.0f and %.0f LSB of the clamped rgb "
           "functions (bounds %.1f, %.1f)\n",
           differ == 0 && worst_f82 <= bound_f82 && worst_exact <= bound_exact ? "PASS" : "FAIL", what, differ,
           worst_f82, worst_exact, bound_f82, bound_exact);
}

int main(void)
{
    check("gold", fresnel_metals_au_f0_q15, fresnel_metals_au_f82_q15, fresnel_metals_au_f82_a_q12, fresnel_metals_au_ior_q15,
          fresnel_metals_au_ior_fast_q15);
    check("copper", fresnel_metals_cu_f0_q15, fresnel_metals_cu_f82_q15, fresnel_metals_cu_f82_a_q12, fresnel_metals_cu_ior_q15,
          fresnel_metals_cu_ior_fast_q15);
    return 0;
}
