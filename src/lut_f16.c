/* Lookup tables in binary16 (fresnel_f16.h): lut.c's interpolation, with
 * the position, the fraction and the blend in half, as a shader computes
 * them (the index itself is exact: pos < 2048 has an exact integer part).
 * fresnel_lut_*: nodes uniform in sqrt(c) as in lut.c and the GLSL port's
 * fresnel_lut_pos, the root of the half cosine rounded to half, as a
 * shader's sqrt. */
#include "f16_internal.h"

#if FRESNEL_HAS_F16

static fr__h fr__interp_h(const fr__h *table, int n, fr__h x)
{
    fr__h pos = fr__hmul(x, (fr__h)(float)(n - 1)), t;
    int i = (int)(float)pos;
    if (i >= n - 1)
        i = n - 2;
    t = fr__hsub(pos, (fr__h)(float)i);
    return fr__hadd(table[i], fr__hmul(t, fr__hsub(table[i + 1], table[i])));
}

/* lut.c's Catmull-Rom, one half rounding per operation, in the same order. */
static fr__h fr__cubic_h(const fr__h *table, int n, fr__h x)
{
    fr__h pos = fr__hmul(x, (fr__h)(float)(n - 1)), t, half = fr__hc(0.5f), p0, p1, p2, p3, d1, d2, d3;
    int i = (int)(float)pos;
    if (i >= n - 1)
        i = n - 2;
    t = fr__hsub(pos, (fr__h)(float)i);
    p0 = table[i > 0 ? i - 1 : 0];
    p1 = table[i];
    p2 = table[i + 1];
    p3 = table[i + 2 < n ? i + 2 : n - 1];
    d1 = fr__hsub(p2, p0);
    d2 = fr__hsub(fr__hadd(fr__hsub(fr__hmul(fr__hc(2.0f), p0), fr__hmul(fr__hc(5.0f), p1)), fr__hmul(fr__hc(4.0f), p2)),
                  p3);
    d3 = fr__hsub(fr__hadd(fr__hmul(fr__hc(3.0f), fr__hsub(p1, p2)), p3), p0);
    return fr__hadd(p1, fr__hmul(fr__hmul(half, t), fr__hadd(d1, fr__hmul(t, fr__hadd(d2, fr__hmul(t, d3))))));
}

fresnel_f16 fresnel_lut_cubic_f16(const fresnel_f16 *table, int n, fresnel_f16 c)
{
    return fr__hunit(fr__cubic_h(table, n, fr__hsqrt(fr__hunit(c))));
}

fresnel_f16 fresnel_lut_f16(const fresnel_f16 *table, int n, fresnel_f16 c)
{
    return fr__hunit(fr__interp_h(table, n, fr__hsqrt(fr__hunit(c))));
}

fresnel_f16 fresnel_lut_linear_f16(const fresnel_f16 *table, int n, fresnel_f16 c)
{
    return fr__hunit(fr__interp_h(table, n, fr__hunit(c)));
}

fresnel_f16 fresnel_lut_residual_f16(fresnel_f16 f0, const fresnel_f16 *table, int n, fresnel_f16 c)
{
    c = fr__hunit(c);
    return fr__hunit(fr__hadd(fr__schlick_h(f0, c), fr__interp_h(table, n, fr__hsqrt(c))));
}

fresnel_f16 fresnel_lut_linear_residual_f16(fresnel_f16 f0, const fresnel_f16 *table, int n, fresnel_f16 c)
{
    c = fr__hunit(c);
    return fr__hunit(fr__hadd(fr__schlick_h(f0, c), fr__interp_h(table, n, c)));
}

#else
typedef int fr__lut_f16_disabled;
#endif
