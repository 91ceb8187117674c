/* Host side of the fixed-point runtime: double model parameters converted to
 * the formats of include/fresnel_q15.h (its LAYOUT section), rounded to
 * nearest. This is the reference implementation of what `fresnel gen` emits
 * for fixed-point scenes. Host only (libm). */
#ifndef FRESNEL_Q15_PARAMS_H
#define FRESNEL_Q15_PARAMS_H

#include "fresnel_q15.h"
#include "fresnel_q15_fast.h"

fresnel_qf q15_qf(double x);          /* x >= 0; 0 for x <= 0 or NaN */
int32_t q15_code(double x);            /* round(x 32768), x clamped to [0, 65535/32768] (Q15 headroom) */
fresnel_q16 q16_code(double x);        /* round(x 65536), clamped to int32 */
/* eta, kappa relative to the incident medium, clamped like fresnel.h. */
void q15_ior(double eta, double kappa, fresnel_ior_prep_q15 *out);
/* fresnel_conductor_q15_fast's constants (fresnel_q15_fast.h layout). */
void q15_conductor_fast(double eta, double kappa, fresnel_conductor_prep_q15_fast *out);
/* 1 where eta, kappa lie in fresnel_conductor_q15_fast's documented domain
 * (FRESNEL_CONDUCTOR_*_Q15_FAST), where its bound holds; else 0. */
int q15_conductor_fast_in_domain(double eta, double kappa);
void q15_nk(double n, double k, fresnel_nk_prep_q15 *out);
void q15_lsk(double n, double k, double a, double alpha, fresnel_lsk_prep_q15 *out);
double q15_qf_value(fresnel_qf x);    /* m 2^e */
/* fresnel_f82_q15_fast's a_q12 for the Q15 codes f0, f82 (clamped to [0, one]):
 * round(4096 ((7^7/6^6)(F0 - F82) + (49/6)(1 - F0))). */
int32_t q15_f82_a_q12(int32_t f0, int32_t f82);

#endif
