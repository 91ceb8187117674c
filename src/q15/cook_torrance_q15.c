/* Cook-Torrance colour interpolation in fixed point (fresnel_q15.h):
 * (F'(c) - F'(1)) / (1 - F'(1)) = 1 - T(c) / T(1), T = 1 - F', as in
 * cook_torrance.c, with T(c) from the exact model's transmittance form. */
#include "internal.h"

#if FRESNEL_HAS_Q15

/* max(0, 1 - T(c)/T(1)) in Q30 */
static uint32_t fresnel_i_ct_weight_q30(const fresnel_ior_prep_q15 *m, int32_t c)
{
    fresnel_qf t = fresnel_i_conductor_transmittance_q15(m, fresnel_i_q15_arg(c));
    return FRESNEL_I_ONE_Q30 - fresnel_i_qf_to_q30_unit(fresnel_i_qf_mul(t, m->t1_inv));
}

fresnel_q15 fresnel_cook_torrance_q15(int32_t f0, const fresnel_ior_prep_q15 *m, int32_t c)
{
    return fresnel_i_q30_to_q15(fresnel_i_schlick_q30(fresnel_i_q15_arg(f0), fresnel_i_ct_weight_q30(m, c)));
}

fresnel_rgb_q15 fresnel_cook_torrance_q15_rgb(fresnel_rgb_q15 f0, const fresnel_ior_prep_q15 *m, int32_t c)
{
    uint32_t w = fresnel_i_ct_weight_q30(m, c); /* one interpolant for the three channels */
    FRESNEL_I_RGB_Q15(fresnel_i_q30_to_q15(fresnel_i_schlick_q30(fresnel_i_q15_arg(f0.r), w)),
                fresnel_i_q30_to_q15(fresnel_i_schlick_q30(fresnel_i_q15_arg(f0.g), w)),
                fresnel_i_q30_to_q15(fresnel_i_schlick_q30(fresnel_i_q15_arg(f0.b), w)));
}

#else
typedef int fresnel_i_cook_torrance_q15_disabled;
#endif
