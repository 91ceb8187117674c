/* Built by tests/gen/test_gen_q15.sh against the header `fresnel gen` writes
 * for two user materials of constant n, k (models = exact, types = f32
 * q15), whose fast-path constants take one word at every code while
 * a0 + c^2 is -32767 at one code (4815, 25616): each channel of
 * <prefix>_ior_fast_q15 must be what q15_conductor_fast makes of the same
 * n, k (a0_lo within 2: the fitted eta is the file's to about 1e-14), and
 * fresnel_conductor_q15_fast on it within FRESNEL_BOUND_CONDUCTOR_Q15_FAST
 * of the double reference at every code. Prints PASS/FAIL. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "3_encode/q15_params.h"
#include "fresnel_fixed.h"
#include "fresnel_fixed_fast.h"
#include "common/reference.h"
#include "scene_rep.h"

static int failures;

static void check(const char *name, const fresnel_conductor_prep_q15_fast got[3], double eta, double kappa)
{
    fresnel_conductor_prep_q15_fast want;
    double worst = 0.0;
    int ch, at = 0, same = 1;
    int32_t c;
    q15_conductor_fast(eta, kappa, &want);
    for (ch = 0; ch < 3; ch++) {
        const fresnel_conductor_prep_q15_fast *g = &got[ch];
        same &= g->a0 == want.a0 && labs((long)g->a0_lo - want.a0_lo) <= 2 && g->shift == want.shift &&
                g->b1 == want.b1 && g->b2 == want.b2 && g->bm == want.bm && g->be == want.be && g->span == want.span;
        for (c = 0; c <= 32768; c++) {
            double e = fabs(fresnel_conductor_q15_fast(g, c) / 32768.0 - ref_conductor(eta, kappa, c / 32768.0)) * 32768.0;
            if (e > worst)
                worst = e, at = c;
        }
    }
    if (same)
        printf("PASS gen q15: %s ior_fast_q15 is q15_conductor_fast of the file's n, k\n", name);
    else {
        printf("FAIL gen q15: %s ior_fast_q15 {%ld, %ld, %ld, %ld, %ld, %ld, %ld, %lu}, q15_conductor_fast "
               "{%ld, %ld, %ld, %ld, %ld, %ld, %ld, %lu}\n",
               name, (long)got[0].a0, (long)got[0].a0_lo, (long)got[0].shift, (long)got[0].b1, (long)got[0].b2,
               (long)got[0].bm, (long)got[0].be, (unsigned long)got[0].span, (long)want.a0, (long)want.a0_lo,
               (long)want.shift, (long)want.b1, (long)want.b2, (long)want.bm, (long)want.be, (unsigned long)want.span);
        failures++;
    }
    if (worst <= FRESNEL_BOUND_CONDUCTOR_Q15_FAST)
        printf("PASS gen q15: %s exact fast on the emitted constants within %.1f LSB at every code (max %.3f)\n", name,
               FRESNEL_BOUND_CONDUCTOR_Q15_FAST, worst);
    else {
        printf("FAIL gen q15: %s exact fast on the emitted constants: %.1f LSB at c %d, bound %.1f\n", name, worst, at,
               FRESNEL_BOUND_CONDUCTOR_Q15_FAST);
        failures++;
    }
}

int main(void)
{
    check("rep1", fresnel_rep_rep1_ior_fast_q15, REP1_N, REP1_K);
    check("rep2", fresnel_rep_rep2_ior_fast_q15, REP2_N, REP2_K);
    return failures ? 1 : 0;
}
