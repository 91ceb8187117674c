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
 * (or c) on each interval (tests/test_average.c checks the sums against
 * the interpolant's integral by Gauss-Legendre quadrature).
 *
 * The sum is formed exactly, as src/q15/lut_avg_q15.c forms it (the same
 * integer weights c_i / D and multi-word integers; each folder stands
 * alone): each node is read as an integer below 2^31 in units of 2^-k, k
 * set by the largest |node| (at least 1) so that it fills 31 bits, and its
 * sign chooses the sum. The error is then the truncation of the nodes
 * (below 2^-k each, times weights whose magnitudes sum to at most 1.04)
 * and of the quotient (below 2^-k), and the one rounding of the quotient
 * to binary32: under half an ulp of the result plus 2.04 2^-k, with
 * 2^-k = 2^-30 for nodes below 2 (FRESNEL_BOUND_LUT_AVG). */
#include "internal.h"

#if FRESNEL_HAS_FLOAT

static int fresnel_i_avg_n(int n)
{
    return n < 1 ? 0 : (n < FRESNEL_LUT_N_MAX ? n : FRESNEL_LUT_N_MAX);
}

/* A non-negative integer in 16-bit limbs held in uint32_t, least
 * significant first (a limb times a 16-bit factor plus a 16-bit carry fits
 * 32 bits): 128 bits, as the sums and D 2^32 in the division need
 * (|c_i| < 2^57 times a node below 2^31 times n <= 2^15; D <= 210 N^4
 * < 2^68). */
#define FRESNEL_I_LIMBS 8
typedef struct fresnel_i_big {
    uint32_t d[FRESNEL_I_LIMBS];
} fresnel_i_big;

static void fresnel_i_big_set(fresnel_i_big *x, uint32_t v)
{
    int k;
    x->d[0] = v & 0xffffu;
    x->d[1] = v >> 16;
    for (k = 2; k < FRESNEL_I_LIMBS; k++)
        x->d[k] = 0;
}

/* x = x m + a for m, a < 2^16, over the low len limbs of x (the result
 * must fit them). R: limb m + carry <= (2^16-1)^2 + 2^16-1 < 2^32. */
static void fresnel_i_big_mul_add(fresnel_i_big *x, uint32_t m, uint32_t a, int len)
{
    uint32_t carry = a, p;
    int k;
    for (k = 0; k < len; k++) {
        p = x->d[k] * m + carry;
        x->d[k] = p & 0xffffu;
        carry = p >> 16;
    }
}

/* acc = acc + x m 2^(16 s) for m < 2^16 and x in its low len limbs.
 * R: as above, plus a limb of acc. */
static void fresnel_i_big_add_mul(fresnel_i_big *acc, const fresnel_i_big *x, uint32_t m, int s, int len)
{
    uint32_t carry = 0, p;
    int k;
    for (k = s; k < FRESNEL_I_LIMBS && (k < s + len || carry); k++) {
        p = acc->d[k] + (k < s + len ? x->d[k - s] * m : 0u) + carry;
        acc->d[k] = p & 0xffffu;
        carry = p >> 16;
    }
}

static int fresnel_i_big_ge(const fresnel_i_big *a, const fresnel_i_big *b)
{
    int k;
    for (k = FRESNEL_I_LIMBS - 1; k >= 0; k--)
        if (a->d[k] != b->d[k])
            return a->d[k] > b->d[k];
    return 1;
}

/* a = a - b for a >= b */
static void fresnel_i_big_sub(fresnel_i_big *a, const fresnel_i_big *b)
{
    uint32_t borrow = 0, p;
    int k;
    for (k = 0; k < FRESNEL_I_LIMBS; k++) {
        p = a->d[k] + 0x10000u - b->d[k] - borrow;
        a->d[k] = p & 0xffffu;
        borrow = 1u - (p >> 16);
    }
}

/* floor(a / b) for b > 0, a < b 2^32, by shift and subtract: b 2^32 (two
 * limbs up) halved 32 times. a is left as the remainder. */
static uint32_t fresnel_i_big_div(fresnel_i_big *a, const fresnel_i_big *b)
{
    fresnel_i_big s;
    uint32_t q = 0;
    int i, k;
    s.d[0] = s.d[1] = 0;
    for (k = 2; k < FRESNEL_I_LIMBS; k++)
        s.d[k] = b->d[k - 2];
    for (i = 0; i < 32; i++) {
        for (k = 0; k < FRESNEL_I_LIMBS; k++) /* s = s / 2 */
            s.d[k] = (s.d[k] >> 1) | (k + 1 < FRESNEL_I_LIMBS ? (s.d[k + 1] & 1u) << 15 : 0u);
        q <<= 1;
        if (fresnel_i_big_ge(a, &s)) {
            fresnel_i_big_sub(a, &s);
            q |= 1u;
        }
    }
    return q;
}

/* The weights of one interpolant, c_i / D with D = den N^deg and
 *   c_i = sum_j coef[j] v^j  (v = i for interior nodes, v = N at the ends):
 * form 0, linear in sqrt(c): D = 5 N^4, c_0 = 1, c_i = 20 i^3 + 10 i,
 *   c_N = 10 N^3 - 10 N^2 + 5 N - 1;
 * form 1, Catmull-Rom in sqrt(c), N >= 3: D = 210 N^4, c_0 = -66,
 *   c_1 = 836, c_i = 840 i^3, c_(N-1) = 875 N^3 - 2478 N^2 + 2541 N - 836,
 *   c_N = 385 N^3 - 252 N^2 - 21 N + 66 (n = 2, 3 below);
 * form 2, linear in c: D = 3 N^2, c_0 = 1, c_i = 6 i, c_N = 3 N - 1. */
typedef struct fresnel_i_avg_form {
    uint16_t den, deg;
    int16_t interior[4], first[4], last[4];
    int cubic; /* nodes 1 and N-1 have weights of their own */
    int16_t second[4], next_to_last[4];
} fresnel_i_avg_form;
static const fresnel_i_avg_form fresnel_i_avg_forms[3] = {
    {5, 4, {0, 10, 0, 20}, {1, 0, 0, 0}, {-1, 5, -10, 10}, 0, {0, 0, 0, 0}, {0, 0, 0, 0}},
    {210, 4, {0, 0, 0, 840}, {-66, 0, 0, 0}, {66, -21, -252, 385}, 1, {836, 0, 0, 0}, {-836, 2541, -2478, 875}},
    {3, 2, {0, 6, 0, 0}, {1, 0, 0, 0}, {-1, 3, 0, 0}, 0, {0, 0, 0, 0}, {0, 0, 0, 0}},
};
/* The cubic for n = 2 (D = 35) and n = 3 (D = 1680). */
static const int16_t fresnel_i_avg_cubic_small[2][3] = {{6, 29, 0}, {-33, 665, 1048}};

/* plus += (the positive terms of c at v) t, minus += (the negative ones) t,
 * each part by Horner (coefficients below 2^16, v < 2^15, so each part is
 * below 2^57: four limbs), t < 2^32 in two 16-bit halves. */
static void fresnel_i_avg_add(fresnel_i_big *plus, fresnel_i_big *minus, const int16_t coef[4], uint32_t v,
                              uint32_t t)
{
    fresnel_i_big x;
    int sign, j;
    for (sign = 1; sign >= -1; sign -= 2) {
        if (coef[0] * sign <= 0 && coef[1] * sign <= 0 && coef[2] * sign <= 0 && coef[3] * sign <= 0)
            continue;
        fresnel_i_big_set(&x, 0);
        for (j = 3; j >= 0; j--)
            fresnel_i_big_mul_add(&x, v, coef[j] * sign > 0 ? (uint32_t)(coef[j] * sign) : 0u, 4);
        fresnel_i_big_add_mul(sign > 0 ? plus : minus, &x, t & 0xffffu, 0, 4);
        if (t >> 16)
            fresnel_i_big_add_mul(sign > 0 ? plus : minus, &x, t >> 16, 1, 4);
    }
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
    const fresnel_i_avg_form *f = &fresnel_i_avg_forms[form];
    fresnel_i_big plus, minus, d;
    float big = 1.0f, top = 1.0f, scale;
    uint32_t last;
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
    last = (uint32_t)n - 1u;
    fresnel_i_big_set(&plus, 0);
    fresnel_i_big_set(&minus, 0);
    if (f->cubic && n <= 3)
        fresnel_i_big_set(&d, n == 2 ? 35u : 1680u);
    else {
        fresnel_i_big_set(&d, f->den);
        for (i = 0; i < f->deg; i++)
            fresnel_i_big_mul_add(&d, last, 0u, FRESNEL_I_LIMBS);
    }
    for (i = 0; i < n; i++) {
        float a = fabsf(table[i]);
        uint32_t t = (uint32_t)((a < FLT_MAX ? a : FLT_MAX) * scale), v = (uint32_t)i;
        const int16_t small[4] = {(int16_t)(f->cubic && n <= 3 ? fresnel_i_avg_cubic_small[n - 2][i] : 0), 0, 0, 0};
        const int16_t *c = f->interior;
        fresnel_i_big *pos = table[i] < 0.0f ? &minus : &plus, *neg = table[i] < 0.0f ? &plus : &minus;
        if (f->cubic && n <= 3)
            c = small;
        else if (i == 0)
            c = f->first;
        else if ((uint32_t)i == last)
            c = f->last, v = last;
        else if (f->cubic && (uint32_t)i == last - 1u)
            c = f->next_to_last, v = last;
        else if (f->cubic && i == 1)
            c = f->second;
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
