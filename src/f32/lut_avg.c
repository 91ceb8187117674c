/* Hemispherical averages of lookup tables (fresnel.h): the exact integral
 * F_avg = 2 int_0^1 F(c) c dc of the interpolant itself, as a weighted sum
 * of the nodes. With N = n - 1, h = 1/N and node i at x_i = i h:
 *
 * Nodes uniform in x = sqrt(c): F_avg = int_0^1 L(x) 4x^3 dx. Linear
 * interpolation integrates, interval by interval, to
 *   w_0 = 4h^4 / 20,   w_i = 4h^4 (i^3 + i/2) = 4h x_i^3 + 2h^3 x_i,
 *   w_N = 4h (1/2 - h/2 + h^2/4 - h^3/20).
 * Catmull-Rom (outer nodes repeated at the ends) has a kernel whose first
 * three moments vanish past the zeroth, so an interior node weighs exactly
 * 4h x_i^3 (2 <= i <= N-2); the four end nodes, for N >= 3,
 *   w_0 = -4h^4 11/140,   w_1 = 4h^4 209/210,
 *   w_{N-1} = 4h (25/24 - 59h/20 + 121h^2/40 - 209h^3/210),
 *   w_N     = 4h (11/24 - 3h/10 - h^2/40 + 11h^3/140),
 * and for n = 2, 3 the weights are the constants below. Nodes uniform in c:
 * F_avg = int_0^1 L(c) 2c dc, w_0 = h^2/3, w_i = 2h c_i, w_N = h - h^2/3.
 * The weights sum to 1 (a constant table averages to itself); the
 * derivation integrates the interpolant's basis polynomials against x^3
 * (or c) on each interval (tests/runtime/every_type/test_average.c checks the sums against
 * the interpolant's integral by Gauss-Legendre quadrature).
 *
 * The sum is formed exactly, as src/q15/lut_avg_q15.c forms it, with the
 * integer weights c_i / D and the multi-word integers of
 * include/fresnel_lut_avg_sum.h: each node is read as an integer below
 * 2^31 in units of 2^-k, k set by the largest |node| (at least 1) so that
 * it fills 31 bits, and its sign chooses the sum. The error is then the truncation of the nodes
 * (below 2^-k each, times weights whose magnitudes sum to at most 1.04)
 * and of the quotient (below 2^-k), and the one rounding of the quotient
 * to binary32: under half an ulp of the result plus 2.04 2^-k, with
 * 2^-k = 2^-30 for nodes below 2 (FRESNEL_BOUND_LUT_AVG). */
#include "internal.h"

#if FRESNEL_HAS_FLOAT

#include "fresnel_lut_avg_sum.h"

static int fresnel_i_avg_n(int n)
{
    return n < 1 ? 0 : (n < FRESNEL_LUT_N_MAX ? n : FRESNEL_LUT_N_MAX);
}

/* 2^e as binary32 for e in [-126, 127]. */
static float fresnel_i_pow2(int e)
{
    union {
        uint32_t u;
        float f;
    } p;
    p.u = (uint32_t)(e + 127) << 23;
    return p.f;
}

/* The exponent of x for x in [1, FLT_MAX]. */
static int fresnel_i_exponent(float x)
{
    union {
        float f;
        uint32_t u;
    } p;
    p.f = x;
    return (int)(p.u >> 23) - 127;
}

/* The nodes' weighted sum, held to [0, max(1, largest node)] as the curve
 * forms are (the cubic's negative end weight can take the integral below
 * 0). A NaN node gives 0; an infinite one counts as FLT_MAX. */
static float fresnel_i_avg(const float *table, int n, int form)
{
    fresnel_i_big plus, minus, d;
    float big = 1.0f, top = 1.0f, scale;
    int i;
    n = fresnel_i_avg_n(n);
    if (n < 2)
        return n == 1 && table[0] >= 0.0f ? table[0] : 0.0f;
    for (i = 0; i < n; i++) {
        float a = fabsf(table[i]);
        if (a != a)
            return 0.0f;
        big = a > big ? (a < FLT_MAX ? a : FLT_MAX) : big;
        top = table[i] > top ? table[i] : top;
    }
    /* a node t is read as floor(|t| 2^k), with big 2^k in [2^30, 2^31) */
    scale = fresnel_i_pow2(30 - fresnel_i_exponent(big));
    fresnel_i_big_set(&plus, 0);
    fresnel_i_big_set(&minus, 0);
    fresnel_i_avg_den(&d, form, (uint32_t)n);
    for (i = 0; i < n; i++) {
        float a = fabsf(table[i]);
        uint32_t t = (uint32_t)((a < FLT_MAX ? a : FLT_MAX) * scale), v;
        int16_t small[4];
        const int16_t *c = fresnel_i_avg_coef(form, (uint32_t)n, (uint32_t)i, &v, small);
        fresnel_i_big *pos = table[i] < 0.0f ? &minus : &plus, *neg = table[i] < 0.0f ? &plus : &minus;
        fresnel_i_avg_add(pos, neg, c, v, t);
    }
    if (fresnel_i_big_ge(&minus, &plus))
        return 0.0f;
    fresnel_i_big_sub(&plus, &minus);
    /* (plus - minus) / D = sum_i w_i t_i < 2^31 1.04 (the weights'
     * magnitudes sum to at most 1.04, the cubic's at n = 3) */
    big = (float)fresnel_i_big_div(&plus, &d) / scale;
    return big < top ? big : top;
}

float fresnel_lut_avg(const float *table, int n) { return fresnel_i_avg(table, n, 0); }
float fresnel_lut_cubic_avg(const float *table, int n) { return fresnel_i_avg(table, n, 1); }
float fresnel_lut_linear_avg(const float *table, int n) { return fresnel_i_avg(table, n, 2); }

static fresnel_rgb fresnel_i_avg_rgb(const float *table, int n, int form)
{
    int m = fresnel_i_avg_n(n);
    FRESNEL_I_RGB(fresnel_i_avg(table, m, form), fresnel_i_avg(table + m, m, form), fresnel_i_avg(table + 2 * m, m, form));
}

fresnel_rgb fresnel_lut_avg_rgb(const float *table, int n) { return fresnel_i_avg_rgb(table, n, 0); }
fresnel_rgb fresnel_lut_cubic_avg_rgb(const float *table, int n) { return fresnel_i_avg_rgb(table, n, 1); }
fresnel_rgb fresnel_lut_linear_avg_rgb(const float *table, int n) { return fresnel_i_avg_rgb(table, n, 2); }

#else
typedef int fresnel_i_lut_avg_disabled;
#endif
