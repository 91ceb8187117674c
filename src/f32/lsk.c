/* Lazanyi and Szirmay-Kalos: Schlick rescaled for kappa, and its error
 * compensation -a c (1-c)^alpha [LS05].
 *
 * For one index the rescaling is exactly "Schlick with the exact F0". The
 * host fits the compensation (ref_lsk_fit, `fresnel params`): a = 2n, the
 * slope of exact Fresnel at c = 0 for large k, and alpha such that the term
 * equals exact - rescaled at c = 0.15; where exact - rescaled >= 0 there, or
 * the fit would need alpha <= 0, a = 0.
 *
 * The compensated result is the difference of the LSK value and a term of
 * about the same size when a = 200 and n is small, and keeps the roundings
 * of both (log1pf, expf and two products on the term); alpha ln(1-c) is
 * formed exactly (two floats). For larger a the binary32 rounding of that
 * exponent is multiplied by the term's size. */
#include "internal.h"

#if FRESNEL_HAS_FLOAT
#include <math.h>

float fresnel_lsk(float n, float k, float c)
{
    float k2, num, den;
    n = fresnel_i_eta(n);
    k = fresnel_i_kappa(k);
    c = fresnel_i_unit(c);
    k2 = k * k;
    num = (n - 1.0f) * (n - 1.0f) + 4.0f * n * fresnel_i_pow5(1.0f - c) + k2;
    den = (n + 1.0f) * (n + 1.0f) + k2;
    return fresnel_i_unit(num / den);
}

fresnel_rgb fresnel_lsk_rgb(fresnel_rgb n, fresnel_rgb k, float c)
{
    FRESNEL_I_RGB(fresnel_lsk(n.r, k.r, c), fresnel_lsk(n.g, k.g, c), fresnel_lsk(n.b, k.b, c));
}

float fresnel_lsk_comp(float n, float k, float a, float alpha, float c)
{
    float comp;
    c = fresnel_i_unit(c);
    a = fresnel_i_clamp(a, 0.0f, FRESNEL_A_MAX);
    alpha = fresnel_i_clamp(alpha, 0.0f, FRESNEL_ALPHA_MAX);
    /* alpha reaches ~50 for metals: see fresnel_i_pow_one_minus. */
    comp = alpha > 0.0f ? a * c * fresnel_i_pow_one_minus(c, alpha) : a * c;
    return fresnel_i_unit(fresnel_lsk(n, k, c) - comp);
}

fresnel_rgb fresnel_lsk_comp_rgb(fresnel_rgb n, fresnel_rgb k, fresnel_rgb a, fresnel_rgb alpha,
                                 float c)
{
    FRESNEL_I_RGB(fresnel_lsk_comp(n.r, k.r, a.r, alpha.r, c), fresnel_lsk_comp(n.g, k.g, a.g, alpha.g, c),
            fresnel_lsk_comp(n.b, k.b, a.b, alpha.b, c));
}

#else
typedef int fresnel_i_lsk_disabled; /* FRESNEL_CFG_NO_FLOAT: ISO C wants a declaration */
#endif
