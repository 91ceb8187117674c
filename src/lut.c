/* Lookup tables of reflectance curves, interpolated linearly (see fresnel.h). */
#include "internal.h"

#if FRESNEL_HAS_FLOAT
#include <math.h>

/* Interpolate table at position x in [0, 1] along its n nodes. */
static float fr__interp(const float *table, int n, float x)
{
    float pos = x * (float)(n - 1);
    int i = (int)pos;
    float t;
    if (i >= n - 1)
        i = n - 2; /* x = 1 lands on the last segment's end */
    t = pos - (float)i;
    return table[i] + t * (table[i + 1] - table[i]);
}

float fresnel_lut(const float *table, int n, float c)
{
    return fr__unit(fr__interp(table, n, sqrtf(fr__unit(c))));
}

float fresnel_lut_linear(const float *table, int n, float c)
{
    return fr__unit(fr__interp(table, n, fr__unit(c)));
}

float fresnel_lut_residual(float f0, const float *table, int n, float c)
{
    c = fr__unit(c);
    return fr__unit(fresnel_schlick(f0, c) + fr__interp(table, n, sqrtf(c)));
}

float fresnel_lut_linear_residual(float f0, const float *table, int n, float c)
{
    c = fr__unit(c);
    return fr__unit(fresnel_schlick(f0, c) + fr__interp(table, n, c));
}

fresnel_rgb fresnel_lut_rgb(const float *table, int n, float c)
{
    FR__RGB(fresnel_lut(table, n, c), fresnel_lut(table + n, n, c), fresnel_lut(table + 2 * n, n, c));
}

fresnel_rgb fresnel_lut_linear_rgb(const float *table, int n, float c)
{
    FR__RGB(fresnel_lut_linear(table, n, c), fresnel_lut_linear(table + n, n, c),
            fresnel_lut_linear(table + 2 * n, n, c));
}

fresnel_rgb fresnel_lut_residual_rgb(fresnel_rgb f0, const float *table, int n, float c)
{
    FR__RGB(fresnel_lut_residual(f0.r, table, n, c), fresnel_lut_residual(f0.g, table + n, n, c),
            fresnel_lut_residual(f0.b, table + 2 * n, n, c));
}

fresnel_rgb fresnel_lut_linear_residual_rgb(fresnel_rgb f0, const float *table, int n, float c)
{
    FR__RGB(fresnel_lut_linear_residual(f0.r, table, n, c),
            fresnel_lut_linear_residual(f0.g, table + n, n, c),
            fresnel_lut_linear_residual(f0.b, table + 2 * n, n, c));
}

#else
typedef int fr__lut_disabled; /* FRESNEL_CFG_NO_FLOAT: ISO C wants a declaration */
#endif
