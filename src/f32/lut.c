/* Lookup tables of reflectance curves, interpolated linearly (see fresnel.h).
 * Nodes uniform in sqrt(c) crowd toward grazing incidence, where Fresnel
 * curves bend (the first interval is 1/(n-1)^2 wide), and still cover
 * normal incidence. */
#include "internal.h"

#if FRESNEL_HAS_FLOAT
#include <math.h>

/* The number of nodes used of an n-node table (fresnel.h): none for n < 1,
 * at most FRESNEL_LUT_N_MAX, so that n - 1 and every position are exact
 * binary32 integers and the index never leaves the table. */
static int fresnel_i_lut_n(int n)
{
    return n < 1 ? 0 : (n < FRESNEL_LUT_N_MAX ? n : FRESNEL_LUT_N_MAX);
}

/* Offset of channel ch (0, 1, 2) in an RGB table of n nodes per channel;
 * added as pointers, so 2n never overflows an int. */
static const float *fresnel_i_lut_channel(const float *table, int n, int ch)
{
    const float *p = table;
    if (n > 0)
        while (ch-- > 0)
            p += n;
    return p;
}

/* A curve table's result: in [0, max(1, the nodes interpolated)], so that
 * a table whose nodes carry values above 1 (the generator's keep policy)
 * keeps them, and any other stays in [0, 1]; NaN gives 0. */
static float fresnel_i_lut_clamp(float v, float hi)
{
    return v >= 0.0f ? (v < hi ? v : hi) : 0.0f;
}

static float fresnel_i_max1(float a, float b)
{
    float m = a > b ? a : b;
    return m > 1.0f ? m : 1.0f;
}

/* Interpolate table at position x in [0, 1] along its n nodes; a curve's
 * (curve = 1) is clamped as fresnel_i_lut_clamp says, a residual's not. */
static float fresnel_i_interp(const float *table, int n, float x, int curve)
{
    float pos, t, v;
    int i;
    n = fresnel_i_lut_n(n);
    if (n < 2)
        return n == 1 ? (curve ? fresnel_i_lut_clamp(table[0], fresnel_i_max1(table[0], 0.0f)) : table[0]) : 0.0f;
    pos = x * (float)(n - 1);
    i = (int)pos;
    if (i >= n - 1)
        i = n - 2; /* x = 1 lands on the last segment's end */
    t = pos - (float)i;
    v = table[i] + t * (table[i + 1] - table[i]);
    return curve ? fresnel_i_lut_clamp(v, fresnel_i_max1(table[i], table[i + 1])) : v;
}

/* Catmull-Rom through the four nodes around x, the outer ones clamped to the
 * table's ends, as a Hermite cubic on node differences (lut_f16.c explains
 * why differences): F = p1 + t (m1 + t (3d - 2 m1 - m2 + t (m1 + m2 - 2d))),
 * d = p2 - p1, m1 = (p2 - p0)/2, m2 = (p3 - p1)/2. The outer nodes are
 * picked by index arithmetic, p0 = table[i - (i > 0)] and
 * p3 = table[i + 1 + (i < n - 2)], not by branches on the data (the last
 * segment takes an eighth of uniformly spread cosines on a 16-node table). */
static float fresnel_i_cubic(const float *table, int n, float x)
{
    float pos, t, p0, p1, p2, p3, d, m1, m2;
    int i, last;
    n = fresnel_i_lut_n(n);
    if (n < 2)
        return n == 1 ? fresnel_i_lut_clamp(table[0], fresnel_i_max1(table[0], 0.0f)) : 0.0f;
    last = n - 1;
    pos = x * (float)last;
    i = (int)pos;
    i = i < last ? i : last - 1; /* x = 1 lands on the last segment's end */
    t = pos - (float)i;
    p0 = table[i - (i > 0)];
    p3 = table[i + 1 + (i < last - 1)];
    table += i;
    p1 = table[0];
    p2 = table[1];
    d = p2 - p1;
    m1 = 0.5f * (p2 - p0);
    m2 = 0.5f * (p3 - p1);
    return fresnel_i_lut_clamp(p1 + t * (m1 + t * ((3.0f * d - 2.0f * m1 - m2) + t * (m1 + m2 - 2.0f * d))),
                               fresnel_i_max1(p1, p2));
}

float fresnel_lut_cubic(const float *table, int n, float c)
{
    return fresnel_i_cubic(table, n, sqrtf(fresnel_i_unit(c)));
}

fresnel_rgb fresnel_lut_cubic_rgb(const float *table, int n, float c)
{
    float x = sqrtf(fresnel_i_unit(c));
    FRESNEL_I_RGB(fresnel_i_cubic(table, n, x), fresnel_i_cubic(fresnel_i_lut_channel(table, n, 1), n, x),
            fresnel_i_cubic(fresnel_i_lut_channel(table, n, 2), n, x));
}

float fresnel_lut(const float *table, int n, float c)
{
    return fresnel_i_interp(table, n, sqrtf(fresnel_i_unit(c)), 1);
}

float fresnel_lut_linear(const float *table, int n, float c)
{
    return fresnel_i_interp(table, n, fresnel_i_unit(c), 1);
}

float fresnel_lut_residual(float f0, const float *table, int n, float c)
{
    c = fresnel_i_unit(c);
    return fresnel_i_unit(fresnel_schlick(f0, c) + fresnel_i_interp(table, n, sqrtf(c), 0));
}

float fresnel_lut_linear_residual(float f0, const float *table, int n, float c)
{
    c = fresnel_i_unit(c);
    return fresnel_i_unit(fresnel_schlick(f0, c) + fresnel_i_interp(table, n, c, 0));
}

fresnel_rgb fresnel_lut_rgb(const float *table, int n, float c)
{
    FRESNEL_I_RGB(fresnel_lut(table, n, c), fresnel_lut(fresnel_i_lut_channel(table, n, 1), n, c), fresnel_lut(fresnel_i_lut_channel(table, n, 2), n, c));
}

fresnel_rgb fresnel_lut_linear_rgb(const float *table, int n, float c)
{
    FRESNEL_I_RGB(fresnel_lut_linear(table, n, c), fresnel_lut_linear(fresnel_i_lut_channel(table, n, 1), n, c),
            fresnel_lut_linear(fresnel_i_lut_channel(table, n, 2), n, c));
}

fresnel_rgb fresnel_lut_residual_rgb(fresnel_rgb f0, const float *table, int n, float c)
{
    FRESNEL_I_RGB(fresnel_lut_residual(f0.r, table, n, c), fresnel_lut_residual(f0.g, fresnel_i_lut_channel(table, n, 1), n, c),
            fresnel_lut_residual(f0.b, fresnel_i_lut_channel(table, n, 2), n, c));
}

fresnel_rgb fresnel_lut_linear_residual_rgb(fresnel_rgb f0, const float *table, int n, float c)
{
    FRESNEL_I_RGB(fresnel_lut_linear_residual(f0.r, table, n, c),
            fresnel_lut_linear_residual(f0.g, fresnel_i_lut_channel(table, n, 1), n, c),
            fresnel_lut_linear_residual(f0.b, fresnel_i_lut_channel(table, n, 2), n, c));
}

#else
typedef int fresnel_i_lut_disabled; /* FRESNEL_CFG_NO_FLOAT: ISO C wants a declaration */
#endif
