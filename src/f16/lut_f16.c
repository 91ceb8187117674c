/* Lookup tables in binary16 (fresnel_f16.h): lut.c's interpolation, with
 * the position, the fraction and the blend in half, as a shader computes
 * them (the index itself is exact: pos < 2048 has an exact integer part).
 * fresnel_lut_*: nodes uniform in sqrt(c) as in lut.c and the GLSL port's
 * fresnel_lut_pos, the root of the half cosine rounded to half, as a
 * shader's sqrt. */
#include "internal.h"

#if FRESNEL_HAS_F16

/* The number of nodes used of an n-node table (fresnel_f16.h): none for
 * n < 1, at most FRESNEL_LUT_N_MAX_F16, so that n - 1 is an exact half, the
 * position at most n - 1 and the index inside the table. */
static int fresnel_i_lut_n_h(int n)
{
    return n < 1 ? 0 : (n < FRESNEL_LUT_N_MAX_F16 ? n : FRESNEL_LUT_N_MAX_F16);
}

/* A curve's result is clamped to [0, max(1, the nodes interpolated)] (lut.c):
 * *hi receives that top. */
static fresnel_i_h fresnel_i_max1_h(fresnel_i_h a, fresnel_i_h b)
{
    fresnel_i_h m = a > b ? a : b;
    return m > fresnel_i_hc(1.0f) ? m : fresnel_i_hc(1.0f);
}

static fresnel_i_h fresnel_i_interp_h(const fresnel_i_h *table, int n, fresnel_i_h x, fresnel_i_h *hi)
{
    fresnel_i_h pos, t;
    int i;
    n = fresnel_i_lut_n_h(n);
    *hi = fresnel_i_hc(1.0f);
    if (n < 2) {
        if (n == 1)
            *hi = fresnel_i_max1_h(table[0], table[0]);
        return n == 1 ? table[0] : fresnel_i_hc(0.0f);
    }
    pos = fresnel_i_hmul(x, (fresnel_i_h)(float)(n - 1));
    i = (int)(float)pos;
    if (i >= n - 1)
        i = n - 2;
    t = fresnel_i_hsub(pos, (fresnel_i_h)(float)i);
    *hi = fresnel_i_max1_h(table[i], table[i + 1]);
    return fresnel_i_hadd(table[i], fresnel_i_hmul(t, fresnel_i_hsub(table[i + 1], table[i])));
}

/* lut.c's Catmull-Rom as a Hermite cubic on node differences, one half
 * rounding per operation: F = p1 + t (m1 + t (3d - 2 m1 - m2 + t (m1 + m2 -
 * 2d))), d = p2 - p1, m1 = (p2 - p0)/2, m2 = (p3 - p1)/2. Every term is the
 * size of a step between nodes, where lut.c's coefficients (2p0 - 5p1 + ...)
 * are the size of 5 p1, whose half ulp near 4.5 is 4e-3. */
static fresnel_i_h fresnel_i_cubic_h(const fresnel_i_h *table, int n, fresnel_i_h x, fresnel_i_h *hi)
{
    fresnel_i_h pos, t, half = fresnel_i_hc(0.5f), p0, p1, p2, p3, d, m1, m2, k2, k3;
    int i;
    n = fresnel_i_lut_n_h(n);
    *hi = fresnel_i_hc(1.0f);
    if (n < 2) {
        if (n == 1)
            *hi = fresnel_i_max1_h(table[0], table[0]);
        return n == 1 ? table[0] : fresnel_i_hc(0.0f);
    }
    pos = fresnel_i_hmul(x, (fresnel_i_h)(float)(n - 1));
    i = (int)(float)pos;
    if (i >= n - 1)
        i = n - 2;
    t = fresnel_i_hsub(pos, (fresnel_i_h)(float)i);
    p0 = table[i > 0 ? i - 1 : 0];
    p1 = table[i];
    p2 = table[i + 1];
    p3 = table[i + 2 < n ? i + 2 : n - 1];
    *hi = fresnel_i_max1_h(p1, p2);
    d = fresnel_i_hsub(p2, p1);
    m1 = fresnel_i_hmul(half, fresnel_i_hsub(p2, p0));
    m2 = fresnel_i_hmul(half, fresnel_i_hsub(p3, p1));
    k2 = fresnel_i_hsub(fresnel_i_hsub(fresnel_i_hmul(fresnel_i_hc(3.0f), d), fresnel_i_hmul(fresnel_i_hc(2.0f), m1)), m2);
    k3 = fresnel_i_hsub(fresnel_i_hadd(m1, m2), fresnel_i_hmul(fresnel_i_hc(2.0f), d));
    return fresnel_i_hadd(p1, fresnel_i_hmul(t, fresnel_i_hadd(m1, fresnel_i_hmul(t, fresnel_i_hadd(k2, fresnel_i_hmul(t, k3))))));
}

fresnel_f16 fresnel_lut_cubic_f16(const fresnel_f16 *table, int n, fresnel_f16 c)
{
    fresnel_i_h hi, v = fresnel_i_cubic_h(table, n, fresnel_i_hsqrt(fresnel_i_hunit(c)), &hi);
    return fresnel_i_hclamp(v, fresnel_i_hc(0.0f), hi);
}

fresnel_f16 fresnel_lut_f16(const fresnel_f16 *table, int n, fresnel_f16 c)
{
    fresnel_i_h hi, v = fresnel_i_interp_h(table, n, fresnel_i_hsqrt(fresnel_i_hunit(c)), &hi);
    return fresnel_i_hclamp(v, fresnel_i_hc(0.0f), hi);
}

fresnel_f16 fresnel_lut_linear_f16(const fresnel_f16 *table, int n, fresnel_f16 c)
{
    fresnel_i_h hi, v = fresnel_i_interp_h(table, n, fresnel_i_hunit(c), &hi);
    return fresnel_i_hclamp(v, fresnel_i_hc(0.0f), hi);
}

fresnel_f16 fresnel_lut_residual_f16(fresnel_f16 f0, const fresnel_f16 *table, int n, fresnel_f16 c)
{
    fresnel_i_h hi;
    c = fresnel_i_hunit(c);
    return fresnel_i_hunit(fresnel_i_hadd(fresnel_i_schlick_h(f0, c), fresnel_i_interp_h(table, n, fresnel_i_hsqrt(c), &hi)));
}

fresnel_f16 fresnel_lut_linear_residual_f16(fresnel_f16 f0, const fresnel_f16 *table, int n, fresnel_f16 c)
{
    fresnel_i_h hi;
    c = fresnel_i_hunit(c);
    return fresnel_i_hunit(fresnel_i_hadd(fresnel_i_schlick_h(f0, c), fresnel_i_interp_h(table, n, c, &hi)));
}

#else
typedef int fresnel_i_lut_f16_disabled;
#endif
