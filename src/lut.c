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

/* Catmull-Rom through the four nodes around x, the outer ones clamped to the
 * table's ends, in Horner form: p1 + t/2 (d1 + t (d2 + t d3)). */
static float fr__cubic(const float *table, int n, float x)
{
    float pos = x * (float)(n - 1);
    int i = (int)pos;
    float t, p0, p1, p2, p3;
    if (i >= n - 1)
        i = n - 2;
    t = pos - (float)i;
    p0 = table[i > 0 ? i - 1 : 0];
    p1 = table[i];
    p2 = table[i + 1];
    p3 = table[i + 2 < n ? i + 2 : n - 1];
    return p1 + 0.5f * t *
                    ((p2 - p0) + t * ((2.0f * p0 - 5.0f * p1 + 4.0f * p2 - p3) + t * (3.0f * (p1 - p2) + p3 - p0)));
}

float fresnel_lut_cubic(const float *table, int n, float c)
{
    return fr__unit(fr__cubic(table, n, sqrtf(fr__unit(c))));
}

fresnel_rgb fresnel_lut_cubic_rgb(const float *table, int n, float c)
{
    float x = sqrtf(fr__unit(c));
    FR__RGB(fr__unit(fr__cubic(table, n, x)), fr__unit(fr__cubic(table + n, n, x)),
            fr__unit(fr__cubic(table + 2 * n, n, x)));
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
