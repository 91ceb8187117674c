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
 * (or c) on each interval (tests/test_average.c checks every weight
 * against Simpson's rule on the interpolant itself). */
#include "internal.h"

#if FRESNEL_HAS_FLOAT

static int fresnel_i_avg_n(int n)
{
    return n < 1 ? 0 : (n < FRESNEL_LUT_N_MAX ? n : FRESNEL_LUT_N_MAX);
}

/* Weight of node i of an n-node table (n >= 2) for each form. */
static float fresnel_i_avg_weight(int form, int n, int i)
{
    static const float cubic2[2] = {6.0f / 35.0f, 29.0f / 35.0f};
    static const float cubic3[3] = {-11.0f / 560.0f, 19.0f / 48.0f, 131.0f / 210.0f};
    int last = n - 1;
    float h = 1.0f / (float)last, x = (float)i * h, h4 = h * h * h * h;
    if (form == 2) { /* uniform in c */
        if (i == 0)
            return h * h / 3.0f;
        return i == last ? h - h * h / 3.0f : 2.0f * h * x;
    }
    if (form == 0) { /* linear in sqrt(c) */
        if (i == 0)
            return 0.2f * h4;
        if (i == last)
            return 4.0f * h * (0.5f + h * (-0.5f + h * (0.25f - 0.05f * h)));
        return 4.0f * h * x * x * x + 2.0f * h * h * h * x;
    }
    if (n == 2)
        return cubic2[i];
    if (n == 3)
        return cubic3[i];
    if (i == 0)
        return -4.0f * h4 * (11.0f / 140.0f);
    if (i == last)
        return 4.0f * h * (11.0f / 24.0f + h * (-0.3f + h * (-0.025f + h * (11.0f / 140.0f))));
    if (i == last - 1)
        return 4.0f * h * (25.0f / 24.0f + h * (-2.95f + h * (3.025f - h * (209.0f / 210.0f))));
    if (i == 1)
        return 4.0f * h4 * (209.0f / 210.0f);
    return 4.0f * h * x * x * x;
}

/* The nodes' weighted sum, compensated (Neumaier): a plain binary32 sum of
 * 32768 terms drifts by 5e-6. Held to [0, max(1, largest node)] as the
 * curve forms are: the cubic's negative end weight could otherwise take a
 * table of zeros and one small node a hair below 0. NaN gives 0. */
static float fresnel_i_avg(const float *table, int n, int form)
{
    float s = 0.0f, comp = 0.0f, top = 1.0f;
    int i;
    n = fresnel_i_avg_n(n);
    if (n < 2)
        return n == 1 && table[0] >= 0.0f ? table[0] : 0.0f;
    for (i = 0; i < n; i++) {
        float term = fresnel_i_avg_weight(form, n, i) * table[i], t = s + term;
        comp += (s >= term) == (s >= -term) ? (s - t) + term : (term - t) + s; /* |s| >= |term| */
        s = t;
        top = table[i] > top ? table[i] : top;
    }
    s += comp;
    return s >= 0.0f ? (s < top ? s : top) : 0.0f;
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
