/* Built against the header `fresnel gen` writes for tests/gen/test_gen_q15.sh's
 * scene (types f32 q15): every Q1.15 constant and table must evaluate, through
 * the fixed-point runtime, to what the binary32 runtime gives with the f32
 * constants of the same header, within Q15's rounding. Prints PASS/FAIL. */
#include <math.h>
#include <stdio.h>

#include "fresnel.h"
#include "fresnel_fixed.h"
#include "fresnel_fixed_fast.h"
#include "scene_fx.h"

static int failures;

static void check(const char *name, fresnel_rgb_q15 q, fresnel_rgb f, double tol, double *worst)
{
    double d[3];
    int ch;
    d[0] = fabs(q.r / 32768.0 - f.r);
    d[1] = fabs(q.g / 32768.0 - f.g);
    d[2] = fabs(q.b / 32768.0 - f.b);
    for (ch = 0; ch < 3; ch++)
        if (d[ch] > *worst)
            *worst = d[ch];
    (void)name;
    (void)tol;
}

#define MODEL(label, qexpr, fexpr, tol)                                                            \
    do {                                                                                           \
        double worst = 0.0;                                                                        \
        int c;                                                                                     \
        for (c = 0; c <= 32768; c += 64) {                                                         \
            float cf = c / 32768.0f;                                                               \
            check(label, qexpr, fexpr, tol, &worst);                                               \
        }                                                                                          \
        if (worst <= (tol))                                                                        \
            printf("PASS gen q15: %s constants agree with f32 (max %.2g)\n", label, worst);       \
        else {                                                                                     \
            printf("FAIL gen q15: %s: max |q15 - f32| %.3g > %.3g\n", label, worst, (double)(tol)); \
            failures++;                                                                            \
        }                                                                                          \
    } while (0)

int main(void)
{
    /* Q15 rounds parameters and results to 2^-15 (3.1e-5); the exact models'
     * constants carry more digits than binary32 needs, so 2 LSB covers both. */
    const double lsb2 = 2.0 / 32768.0;
    MODEL("cu schlick", fresnel_schlick_q15_rgb(fresnel_fx_cu_f0_q15, c),
          fresnel_schlick_rgb(fresnel_fx_cu_f0, cf), lsb2);
    MODEL("cu f82", fresnel_f82_q15_rgb(fresnel_fx_cu_f0_q15, fresnel_fx_cu_f82_q15, c),
          fresnel_f82_rgb(fresnel_fx_cu_f0, fresnel_fx_cu_f82, cf), lsb2);
    MODEL("au exact", fresnel_conductor_q15_rgb(fresnel_fx_au_ior_q15, c),
          fresnel_conductor_rgb(fresnel_fx_au_eta, fresnel_fx_au_kappa, cf), lsb2);
    MODEL("au exact-gaussian", fresnel_conductor_q15_rgb(fresnel_fx_au_ior_gaussian_q15, c),
          fresnel_conductor_rgb(fresnel_fx_au_eta_gaussian, fresnel_fx_au_kappa_gaussian, cf), lsb2);
    MODEL("cu lsk-comp", fresnel_lsk_comp_q15_rgb(fresnel_fx_cu_lsk_comp_q15, c),
          fresnel_lsk_comp_rgb(fresnel_fx_cu_eta, fresnel_fx_cu_kappa, fresnel_fx_cu_lsk_a, fresnel_fx_cu_lsk_alpha, cf),
          lsb2);
    MODEL("cu lsk", fresnel_lsk_q15_rgb(fresnel_fx_cu_lsk_q15, c),
          fresnel_lsk_rgb(fresnel_fx_cu_eta, fresnel_fx_cu_kappa, cf), lsb2);
    MODEL("al approx-conductor", fresnel_approx_conductor_q15_rgb(fresnel_fx_al_nk_q15, c),
          fresnel_approx_conductor_rgb(fresnel_fx_al_eta, fresnel_fx_al_kappa, cf), lsb2);
    MODEL("al gulbrandsen", fresnel_gulbrandsen_q15_rgb(fresnel_fx_al_gulbrandsen_r_q15, fresnel_fx_al_gulbrandsen_g_q15, c),
          fresnel_gulbrandsen_rgb(fresnel_fx_al_gulbrandsen_r, fresnel_fx_al_gulbrandsen_g, cf), lsb2);
    MODEL("cu cook-torrance", fresnel_cook_torrance_q15_rgb(fresnel_fx_cu_f0_q15, &fresnel_fx_cu_ct_ior_q15, c),
          fresnel_cook_torrance_rgb(fresnel_fx_cu_f0, fresnel_fx_cu_ct_eta, fresnel_fx_cu_ct_kappa, cf), lsb2);
    MODEL("cu lut32", fresnel_lut_u16_q15_rgb(fresnel_fx_cu_lut32_q15, 32, c),
          fresnel_lut_rgb(fresnel_fx_cu_lut32, 32, cf), lsb2);
    MODEL("cu lut16-residual",
          fresnel_lut_residual_s16_q15_rgb(fresnel_fx_cu_f0_q15, fresnel_fx_cu_lut16_residual_q15, 16,
                                           fresnel_fx_cu_lut16_residual_frac, c),
          fresnel_lut_residual_rgb(fresnel_fx_cu_f0, fresnel_fx_cu_lut16_residual, 16, cf), lsb2);
    {
        /* the exact conductor's inline fast path on the emitted constants:
         * within its bound, plus 1 LSB for binary32's constants and rounding */
        const double tol = (FRESNEL_BOUND_CONDUCTOR_Q15_FAST + 1.0) / 32768.0;
        MODEL("au exact fast",
              ((fresnel_rgb_q15){fresnel_conductor_q15_fast(&fresnel_fx_au_ior_fast_q15[0], c),
                                 fresnel_conductor_q15_fast(&fresnel_fx_au_ior_fast_q15[1], c),
                                 fresnel_conductor_q15_fast(&fresnel_fx_au_ior_fast_q15[2], c)}),
              fresnel_conductor_rgb(fresnel_fx_au_eta, fresnel_fx_au_kappa, cf), tol);
        MODEL("cu exact fast",
              ((fresnel_rgb_q15){fresnel_conductor_q15_fast(&fresnel_fx_cu_ior_fast_q15[0], c),
                                 fresnel_conductor_q15_fast(&fresnel_fx_cu_ior_fast_q15[1], c),
                                 fresnel_conductor_q15_fast(&fresnel_fx_cu_ior_fast_q15[2], c)}),
              fresnel_conductor_rgb(fresnel_fx_cu_eta, fresnel_fx_cu_kappa, cf), tol);
    }
    {
        /* the inline fast path with the emitted a: within its bound plus Q15 rounding of the parameters */
        const double lsb8 = 8.0 / 32768.0;
        MODEL("cu f82 fast",
              ((fresnel_rgb_q15){fresnel_f82_q15_fast(fresnel_fx_cu_f0_q15.r, fresnel_fx_cu_f82_a_q12[0], c),
                                 fresnel_f82_q15_fast(fresnel_fx_cu_f0_q15.g, fresnel_fx_cu_f82_a_q12[1], c),
                                 fresnel_f82_q15_fast(fresnel_fx_cu_f0_q15.b, fresnel_fx_cu_f82_a_q12[2], c)}),
              fresnel_f82_rgb(fresnel_fx_cu_f0, fresnel_fx_cu_f82, cf), lsb8);
    }
    MODEL("au lut16-cubic", fresnel_lut_cubic_u16_q15_rgb(fresnel_fx_au_lut16_cubic_q15, 16, c),
          fresnel_lut_cubic_rgb(fresnel_fx_au_lut16_cubic, 16, cf), lsb2);
    return failures ? 1 : 0;
}
