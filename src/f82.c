/* Hoffman's F82 model: Lazanyi's compensation term reparameterised by the
 * reflectance at c = 1/7 [Hof20]. */
#include "internal.h"

#if FRESNEL_HAS_FLOAT

float fresnel_f82(float f0, float f82, float c)
{
    float x, x5, a;
    f0 = fr__unit(f0);
    f82 = fr__unit(f82);
    c = fr__unit(c);
    x = 1.0f - c;
    x5 = fr__pow5(x);
    /* 823543/46656 = 7^7/6^6 and 49/6 make the curve pass through F82 at c = 1/7. */
    a = (823543.0f / 46656.0f) * (f0 - f82) + (49.0f / 6.0f) * (1.0f - f0);
    return fr__unit(f0 + (1.0f - f0) * x5 - a * c * x5 * x);
}

fresnel_rgb fresnel_f82_rgb(fresnel_rgb f0, fresnel_rgb f82, float c)
{
    FR__RGB(fresnel_f82(f0.r, f82.r, c), fresnel_f82(f0.g, f82.g, c), fresnel_f82(f0.b, f82.b, c));
}

#else
typedef int fr__f82_disabled; /* FRESNEL_CFG_NO_FLOAT: ISO C wants a declaration */
#endif
