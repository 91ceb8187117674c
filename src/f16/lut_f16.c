/* Lookup tables in binary16 (fresnel_f16.h): binary16 nodes, lut.c's
 * interpolation in binary32 (the position of c among the nodes, its index
 * and fraction, and the blend), the result rounded to half: what the GLSL
 * port computes in highp (fresnel_lut_pos, fresnel_lut_lerp,
 * fresnel_lut_cubic_blend) and returns in mediump. In binary16 the
 * position would keep fewer than 3 fraction bits above 256 nodes, a
 * segment's worth of error across a total-reflection edge, and the
 * cubic's terms (up to 9 for nodes in [0, 2]) their half-ulps. */
#include "internal.h"

#if FRESNEL_HAS_F16

/* The number of nodes used of an n-node table (fresnel_f16.h): none for
 * n < 1, at most FRESNEL_LUT_N_MAX_F16. */
static int fresnel_i_lut_n_h(int n)
{
    return n < 1 ? 0 : (n < FRESNEL_LUT_N_MAX_F16 ? n : FRESNEL_LUT_N_MAX_F16);
}

/* max(1, a, b): a curve's result is clamped to [0, max(1, the nodes
 * interpolated)] (lut.c). */
static float fresnel_i_top_h(fresnel_i_h a, fresnel_i_h b)
{
    float m = (float)a > (float)b ? (float)a : (float)b;
    return m > 1.0f ? m : 1.0f;
}

/* The index i of the segment of x in [0, 1] in an n-node table, n >= 2,
 * and the fraction *t: x (n - 1) < 2049 has 12 fraction bits in binary32,
 * and pos - i is exact. */
static int fresnel_i_lut_pos_h(int n, float x, float *t)
{
    float pos = x * (float)(n - 1);
    int i = (int)pos;
    if (i >= n - 1)
        i = n - 2;
    *t = pos - (float)i;
    return i;
}

/* Linear (cubic = 0) or lut.c's Catmull-Rom as a Hermite cubic on node
 * differences, F = p1 + t (m1 + t (3d - 2 m1 - m2 + t (m1 + m2 - 2d))),
 * d = p2 - p1, m1 = (p2 - p0)/2, m2 = (p3 - p1)/2, the outer nodes clamped
 * to the table's ends; *hi receives the top of the clamp. */
static float fresnel_i_interp_h(const fresnel_i_h *table, int n, float x, int cubic, float *hi)
{
    float t, p0, p1, p2, p3, d, m1, m2;
    int i;
    n = fresnel_i_lut_n_h(n);
    *hi = 1.0f;
    if (n < 2) {
        if (n == 1)
            *hi = fresnel_i_top_h(table[0], table[0]);
        return n == 1 ? (float)table[0] : 0.0f;
    }
    i = fresnel_i_lut_pos_h(n, x, &t);
    p1 = (float)table[i];
    p2 = (float)table[i + 1];
    *hi = fresnel_i_top_h(table[i], table[i + 1]);
    if (!cubic)
        return p1 + t * (p2 - p1);
    p0 = (float)table[i > 0 ? i - 1 : 0];
    p3 = (float)table[i + 2 < n ? i + 2 : n - 1];
    d = p2 - p1;
    m1 = 0.5f * (p2 - p0);
    m2 = 0.5f * (p3 - p1);
    return p1 + t * (m1 + t * ((3.0f * d - 2.0f * m1 - m2) + t * (m1 + m2 - 2.0f * d)));
}

/* v clamped to [0, hi] (NaN: 0), rounded to half; hi is a half value, so
 * the rounding stays inside. */
static fresnel_f16 fresnel_i_lut_result_h(float v, float hi)
{
    return (fresnel_f16)(v > 0.0f ? (v < hi ? v : hi) : 0.0f);
}

static fresnel_f16 fresnel_i_curve_h(const fresnel_f16 *table, int n, float x, int cubic)
{
    float hi, v = fresnel_i_interp_h(table, n, x, cubic, &hi);
    return fresnel_i_lut_result_h(v, hi);
}

/* Schlick at F0 in binary16 (a mediump function in the port) plus the
 * interpolated residual, summed in binary32, clamped to [0, 1]. */
static fresnel_f16 fresnel_i_residual_h(fresnel_f16 f0, const fresnel_f16 *table, int n, fresnel_i_h c, float x)
{
    float hi, v = (float)fresnel_i_schlick_h(f0, c) + fresnel_i_interp_h(table, n, x, 0, &hi);
    return fresnel_i_lut_result_h(v, 1.0f);
}

fresnel_f16 fresnel_lut_cubic_f16(const fresnel_f16 *table, int n, fresnel_f16 c)
{
    return fresnel_i_curve_h(table, n, sqrtf((float)fresnel_i_hunit(c)), 1);
}

fresnel_f16 fresnel_lut_f16(const fresnel_f16 *table, int n, fresnel_f16 c)
{
    return fresnel_i_curve_h(table, n, sqrtf((float)fresnel_i_hunit(c)), 0);
}

fresnel_f16 fresnel_lut_linear_f16(const fresnel_f16 *table, int n, fresnel_f16 c)
{
    return fresnel_i_curve_h(table, n, (float)fresnel_i_hunit(c), 0);
}

fresnel_f16 fresnel_lut_residual_f16(fresnel_f16 f0, const fresnel_f16 *table, int n, fresnel_f16 c)
{
    c = fresnel_i_hunit(c);
    return fresnel_i_residual_h(f0, table, n, c, sqrtf((float)c));
}

fresnel_f16 fresnel_lut_linear_residual_f16(fresnel_f16 f0, const fresnel_f16 *table, int n, fresnel_f16 c)
{
    c = fresnel_i_hunit(c);
    return fresnel_i_residual_h(f0, table, n, c, (float)c);
}

#else
typedef int fresnel_i_lut_f16_disabled;
#endif
