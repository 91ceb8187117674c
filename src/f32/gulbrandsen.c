/* Gulbrandsen's reflectivity/edge-tint parameterisation [Gul14]. Hoffman
 * [Hof20] explains why it is unsound for colour; it is here because
 * production renderers use it. */
#include "internal.h"

#if FRESNEL_HAS_FLOAT
#include <math.h>

fresnel_nk fresnel_gulbrandsen_nk(float r, float g)
{
    fresnel_nk out;
    float sr, nmin, nmax, k2;
    r = fresnel_i_clamp(r, 0.0f, FRESNEL_GULBRANDSEN_R_MAX);
    g = fresnel_i_unit(g);
    sr = sqrtf(r);
    nmin = (1.0f - r) / (1.0f + r);
    /* (1 + sqrt r)/(1 - sqrt r) = (1 + sqrt r)^2/(1 - r): 1 - r is exact for
     * r >= 0.5, whereas 1 - sqrt r loses the digits of r near 1. */
    nmax = (1.0f + sr) * (1.0f + sr) / (1.0f - r);
    out.n = g * nmin + (1.0f - g) * nmax;
    /* r (n+1)^2 - (n-1)^2 = (1 - sqrt r) g (nmax - nmin) (sqrt r (n+1) + n - 1):
     * dividing by 1 - r = (1 - sqrt r)(1 + sqrt r) leaves no difference of
     * large terms (the paper's form subtracts two numbers near 1.6e9 when
     * r = 0.9999 and g = 0). The last factor is written
     * n (1 + sqrt r) - (1 - r)/(1 + sqrt r), since sqrt r - 1 cancels too. */
    k2 = g * (nmax - nmin) * (out.n * (1.0f + sr) - (1.0f - r) / (1.0f + sr)) / (1.0f + sr);
    out.k = k2 > 0.0f ? sqrtf(k2) : 0.0f;
    return out;
}

fresnel_rg fresnel_gulbrandsen_rg(float n, float k)
{
    fresnel_rg out;
    float rc, omr, sr, nmax1, span;
    out.r = fresnel_f0_from_ior(n, k);
    n = fresnel_i_eta(n);
    k = fresnel_i_kappa(k);
    /* 1 - r = 4n/((n+1)^2 + k^2) directly, and r clamped by it: 1 - r from
     * the rounded r has an absolute error of ulp(1)/2, a relative error of
     * 6e-8/(1 - r) in nmax, and g changes by 1/(1 - r) per unit of r. */
    omr = 4.0f * n / ((n + 1.0f) * (n + 1.0f) + k * k);
    if (omr > 1.0f - FRESNEL_GULBRANDSEN_R_MAX) {
        rc = out.r;
    } else {
        omr = 1.0f - FRESNEL_GULBRANDSEN_R_MAX;
        rc = FRESNEL_GULBRANDSEN_R_MAX;
    }
    sr = sqrtf(rc);
    /* g = (nmax - n)/(nmax - nmin) with both differences formed without
     * cancellation: for r -> 0 (n -> 1, k -> 0) nmax = 1 + 2 sqrt r and
     * nmin = 1 - 2r round to 1 and would leave g = 0 where it is 1. With
     * s = sqrt r: nmax - 1 = 2s(1+s)/(1-r), nmax - nmin = 2s(1+s)^2 /
     * ((1-r)(1+r)), and n - 1 is exact near 1 (Sterbenz). */
    nmax1 = 2.0f * sr * (1.0f + sr) / omr;
    span = nmax1 * (1.0f + sr) / (1.0f + rc);
    /* r = 0 (n 1, k 0) gives n = 1 for every g; report 0. */
    out.g = span > 0.0f ? fresnel_i_unit((nmax1 - (n - 1.0f)) / span) : 0.0f;
    return out;
}

float fresnel_gulbrandsen(float r, float g, float c)
{
    fresnel_nk nk = fresnel_gulbrandsen_nk(r, g);
    return fresnel_approx_conductor(nk.n, nk.k, c);
}

fresnel_rgb fresnel_gulbrandsen_rgb(fresnel_rgb r, fresnel_rgb g, float c)
{
    FRESNEL_I_RGB(fresnel_gulbrandsen(r.r, g.r, c), fresnel_gulbrandsen(r.g, g.g, c),
            fresnel_gulbrandsen(r.b, g.b, c));
}

#else
typedef int fresnel_i_gulbrandsen_disabled; /* FRESNEL_CFG_NO_FLOAT: ISO C wants a declaration */
#endif
