/* The approximate conductor Fresnel form of Glassner, used by Gulbrandsen
 * and Metzgar. */
#include "internal.h"

#if FRESNEL_HAS_FLOAT

float fresnel_approx_conductor(float n, float k, float c)
{
    float kc, rs, rp, nk2;
    n = fresnel_i_eta(n);
    k = fresnel_i_kappa(k);
    c = fresnel_i_unit(c);
    nk2 = n * n + k * k;
    kc = k * c;
    /* n^2+k^2 -+ 2nc + c^2 = (n -+ c)^2 + k^2 and (n^2+k^2)c^2 -+ 2nc + 1 =
     * (nc -+ 1)^2 + (kc)^2: the minus forms never subtract nearly equal terms. */
    rs = ((n - c) * (n - c) + k * k) / ((n + c) * (n + c) + k * k);
    rp = ((n * c - 1.0f) * (n * c - 1.0f) + kc * kc) / (nk2 * c * c + 2.0f * n * c + 1.0f);
    return fresnel_i_unit(0.5f * (rs + rp));
}

fresnel_rgb fresnel_approx_conductor_rgb(fresnel_rgb n, fresnel_rgb k, float c)
{
    FRESNEL_I_RGB(fresnel_approx_conductor(n.r, k.r, c), fresnel_approx_conductor(n.g, k.g, c),
            fresnel_approx_conductor(n.b, k.b, c));
}

#else
typedef int fresnel_i_approx_conductor_disabled; /* FRESNEL_CFG_NO_FLOAT: ISO C wants a declaration */
#endif
