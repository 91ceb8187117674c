/* Lookup tables in binary16 (fresnel_f16.h): lut.c's interpolation, with
 * the position, the fraction and the blend in half, as a shader computes
 * them (the index itself is exact: pos < 2048 has an exact integer part).
 * fresnel_lut_*: nodes uniform in sqrt(c) as in lut.c and the GLSL port's
 * fresnel_lut_pos, the root of the half cosine rounded to half, as a
 * shader's sqrt. */
#include "f16_internal.h"

#if FRESNEL_HAS_F16

/* The number of nodes used of an n-node table (fresnel_f16.h): none for
 * n < 1, at most FRESNEL_F16_LUT_N_MAX, so that n - 1 is an exact half, the
 * position at most n - 1 and the index inside the table. */
static int fr__lut_n_h(int n)
{
    return n < 1 ? 0 : (n < FRESNEL_F16_LUT_N_MAX ? n : FRESNEL_F16_LUT_N_MAX);
}

static fr__h fr__interp_h(const fr__h *table, int n, fr__h x)
{
    fr__h pos, t;
    int i;
    n = fr__lut_n_h(n);
    if (n < 2)
        return n == 1 ? table[0] : fr__hc(0.0f);
    pos = fr__hmul(x, (fr__h)(float)(n - 1));
    i = (int)(float)pos;
    if (i >= n - 1)
        i = n - 2;
    t = fr__hsub(pos, (fr__h)(float)i);
    return fr__hadd(table[i], fr__hmul(t, fr__hsub(table[i + 1], table[i])));
}

/* lut.c's Catmull-Rom as a Hermite cubic on node differences, one half
 * rounding per operation: F = p1 + t (m1 + t (3d - 2 m1 - m2 + t (m1 + m2 -
 * 2d))), d = p2 - p1, m1 = (p2 - p0)/2, m2 = (p3 - p1)/2. Every term is the
 * size of a step between nodes, where lut.c's coefficients (2p0 - 5p1 + ...)
 * are the size of 5 p1, whose half ulp near 4.5 is 4e-3. */
static fr__h fr__cubic_h(const fr__h *table, int n, fr__h x)
{
    fr__h pos, t, half = fr__hc(0.5f), p0, p1, p2, p3, d, m1, m2, k2, k3;
    int i;
    n = fr__lut_n_h(n);
    if (n < 2)
        return n == 1 ? table[0] : fr__hc(0.0f);
    pos = fr__hmul(x, (fr__h)(float)(n - 1));
    i = (int)(float)pos;
    if (i >= n - 1)
        i = n - 2;
    t = fr__hsub(pos, (fr__h)(float)i);
    p0 = table[i > 0 ? i - 1 : 0];
    p1 = table[i];
    p2 = table[i + 1];
    p3 = table[i + 2 < n ? i + 2 : n - 1];
    d = fr__hsub(p2, p1);
    m1 = fr__hmul(half, fr__hsub(p2, p0));
    m2 = fr__hmul(half, fr__hsub(p3, p1));
    k2 = fr__hsub(fr__hsub(fr__hmul(fr__hc(3.0f), d), fr__hmul(fr__hc(2.0f), m1)), m2);
    k3 = fr__hsub(fr__hadd(m1, m2), fr__hmul(fr__hc(2.0f), d));
    return fr__hadd(p1, fr__hmul(t, fr__hadd(m1, fr__hmul(t, fr__hadd(k2, fr__hmul(t, k3))))));
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
