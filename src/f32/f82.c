/* Hoffman's F82 model: Lazanyi's compensation term reparameterised by the
 * reflectance at c = 1/7 [Hof20]. Extreme F0/F82 pairs (F82 well above or
 * below F0) push the curve outside [0, 1]: the clamp leaves a C1 kink there,
 * as Hoffman notes. */
#include "internal.h"

#if FRESNEL_HAS_FLOAT

float fresnel_f82(float f0, float f82, float c)
{
    float x, x5, a;
    f0 = fresnel_i_unit(f0);
    f82 = fresnel_i_unit(f82);
    c = fresnel_i_unit(c);
    x = 1.0f - c;
    x5 = fresnel_i_pow5(x);
    /* 823543/46656 = 7^7/6^6 and 49/6 make the curve pass through F82 at c = 1/7. */
    a = (823543.0f / 46656.0f) * (f0 - f82) + (49.0f / 6.0f) * (1.0f - f0);
    return fresnel_i_unit(f0 + (1.0f - f0) * x5 - a * c * x5 * x);
}

fresnel_rgb fresnel_f82_rgb(fresnel_rgb f0, fresnel_rgb f82, float c)
{
    FRESNEL_I_RGB(fresnel_f82(f0.r, f82.r, c), fresnel_f82(f0.g, f82.g, c), fresnel_f82(f0.b, f82.b, c));
}

/* 2 int c (1-c)^5 dc = 1/21 and 2 int c^2 (1-c)^6 dc = 2 B(3, 7) = 1/126, so
 * F_avg = F0 + (1 - F0)/21 - a/126, which with a's two terms collects to
 * F0 - (13/756)(1 - F0) - (K1/126)(F0 - F82): one rounding fewer. */
float fresnel_f82_avg(float f0, float f82)
{
    f0 = fresnel_i_unit(f0);
    f82 = fresnel_i_unit(f82);
    return fresnel_i_unit(f0 - (13.0f / 756.0f) * (1.0f - f0) - (823543.0f / 5878656.0f) * (f0 - f82));
}

fresnel_rgb fresnel_f82_avg_rgb(fresnel_rgb f0, fresnel_rgb f82)
{
    FRESNEL_I_RGB(fresnel_f82_avg(f0.r, f82.r), fresnel_f82_avg(f0.g, f82.g), fresnel_f82_avg(f0.b, f82.b));
}

#else
typedef int fresnel_i_f82_disabled; /* FRESNEL_CFG_NO_FLOAT: ISO C wants a declaration */
#endif
