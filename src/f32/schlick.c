/* Schlick's approximation and the F0 helpers that go with it [Sch94, Hof20]. */
#include "internal.h"

#if FRESNEL_HAS_FLOAT
#include <math.h>

float fresnel_schlick(float f0, float c)
{
    f0 = fresnel_i_unit(f0);
    return fresnel_i_unit(f0 + (1.0f - f0) * fresnel_i_pow5(1.0f - fresnel_i_unit(c)));
}

fresnel_rgb fresnel_schlick_rgb(fresnel_rgb f0, float c)
{
    FRESNEL_I_RGB(fresnel_schlick(f0.r, c), fresnel_schlick(f0.g, c), fresnel_schlick(f0.b, c));
}

/* p == 5 takes the multiplications of fresnel_schlick; other p evaluate
 * (1-c)^p as expf(p log1pf(-c)) (fresnel_i_pow_one_minus), so that the
 * rounding of 1 - c is not multiplied by p. */
float fresnel_schlick_gen(float f0, float f90, float p, float c)
{
    float x = 1.0f - fresnel_i_unit(c);
    float t;
    f0 = fresnel_i_unit(f0);
    f90 = fresnel_i_unit(f90);
    p = fresnel_i_clamp(p, FRESNEL_P_MIN, FRESNEL_P_MAX);
    t = p == 5.0f ? fresnel_i_pow5(x) : fresnel_i_pow_one_minus(fresnel_i_unit(c), p);
    return fresnel_i_unit(f0 + (f90 - f0) * t);
}

fresnel_rgb fresnel_schlick_gen_rgb(fresnel_rgb f0, fresnel_rgb f90, float p, float c)
{
    FRESNEL_I_RGB(fresnel_schlick_gen(f0.r, f90.r, p, c), fresnel_schlick_gen(f0.g, f90.g, p, c),
            fresnel_schlick_gen(f0.b, f90.b, p, c));
}

/* 2 int_0^1 (1-c)^p c dc = 2 B(2, p+1) = 2 / ((p+1)(p+2)); p = 5 gives 1/21. */
float fresnel_schlick_avg(float f0)
{
    f0 = fresnel_i_unit(f0);
    return f0 + (1.0f - f0) * (1.0f / 21.0f);
}

fresnel_rgb fresnel_schlick_avg_rgb(fresnel_rgb f0)
{
    FRESNEL_I_RGB(fresnel_schlick_avg(f0.r), fresnel_schlick_avg(f0.g), fresnel_schlick_avg(f0.b));
}

float fresnel_schlick_gen_avg(float f0, float f90, float p)
{
    f0 = fresnel_i_unit(f0);
    f90 = fresnel_i_unit(f90);
    p = fresnel_i_clamp(p, FRESNEL_P_MIN, FRESNEL_P_MAX);
    return fresnel_i_unit(f0 + (f90 - f0) * (2.0f / ((p + 1.0f) * (p + 2.0f))));
}

/* The Fresnel curve is the same function of the angle on either side, so
 * Schlick is evaluated with the cosine in the less dense medium: ct, from
 * eta^2 ct^2 = eta^2 - sin^2 formed without cancellation
 * (fresnel_i_eta2_minus_sin2), so that it keeps its digits up to the
 * critical angle. */
float fresnel_schlick_internal(float f0, float eta, float c)
{
    float ct2;
    eta = fresnel_i_eta(eta);
    c = fresnel_i_unit(c);
    if (eta >= 1.0f)
        return fresnel_schlick(f0, c);
    ct2 = fresnel_i_eta2_minus_sin2(eta, c, 0.0f); /* eta^2 ct^2 */
    if (!(ct2 > 0.0f))
        return 1.0f;
    return fresnel_schlick(f0, sqrtf(ct2) / eta);
}

fresnel_rgb fresnel_schlick_internal_rgb(fresnel_rgb f0, float eta, float c)
{
    FRESNEL_I_RGB(fresnel_schlick_internal(f0.r, eta, c), fresnel_schlick_internal(f0.g, eta, c),
            fresnel_schlick_internal(f0.b, eta, c));
}

float fresnel_f0_in_medium(float f0, float eta_e)
{
    /* With s = (etaE-1)/(etaE+1) and r = sqrt F0, r - s and 1 - r s are
     * rebuilt from 1 - s = 2/(etaE+1) and 1 - r = (1 - F0)/(1 + r), each exact
     * to a rounding: the direct 1 - r s cancels when F0 and etaE are both large. */
    float r, one_minus_s, one_minus_r, q;
    eta_e = fresnel_i_eta(eta_e);
    f0 = fresnel_i_unit(f0);
    r = sqrtf(f0);
    if (eta_e < 1.0f) {
        /* s < 0: r - s and 1 - r s are sums of positive terms, and the
         * direct form rounds least. */
        float s = (eta_e - 1.0f) / (eta_e + 1.0f);
        q = (r - s) / (1.0f - r * s);
        return fresnel_i_unit(q * q);
    }
    one_minus_s = 2.0f / (eta_e + 1.0f);
    one_minus_r = (1.0f - f0) / (1.0f + r);
    q = (one_minus_s - one_minus_r) / (one_minus_r + r * one_minus_s); /* denominator > 0 */
    return fresnel_i_unit(q * q);
}

float fresnel_f0_from_ior(float eta, float kappa)
{
    float k2, num, den;
    eta = fresnel_i_eta(eta);
    kappa = fresnel_i_kappa(kappa);
    k2 = kappa * kappa;
    num = (eta - 1.0f) * (eta - 1.0f) + k2;
    den = (eta + 1.0f) * (eta + 1.0f) + k2;
    return fresnel_i_unit(num / den);
}

#else
typedef int fresnel_i_schlick_disabled; /* FRESNEL_CFG_NO_FLOAT: ISO C wants a declaration */
#endif
