/* Hemispherical averages of uint16_t lookup tables (fresnel_fixed.h): the
 * weighted node sums of src/f32/lut_avg.c (whose header comment derives
 * the weights), exact, in integers.
 *
 * With N = n - 1 every weight is c_i / D: an integer polynomial c_i in i
 * (interior nodes) or N (end nodes) over one integer D for the table
 * (fresnel_i_qavg_forms). So the average in Q15 codes is the ratio of two
 * integers, sum_i c_i table[i] / D, of at most 88 and 68 bits, summed
 * exactly in multi-word integers and divided once: the result is the
 * interpolant's integral rounded to the nearest code (halves up), for
 * every n and every table. The cubic's negative terms are summed apart. */
#include "internal.h"

#if FRESNEL_HAS_FIXED

#define FRESNEL_I_AVG_N_MAX 32768

/* A non-negative integer in 16-bit limbs held in uint32_t, least
 * significant first (a limb times a 16-bit factor plus a 16-bit carry fits
 * 32 bits): 128 bits, as the sums and D 2^32 in the division need
 * (|c_i| < 2^57 times a node below 2^31 times n <= 2^15; D <= 210 N^4
 * < 2^68). */
#define FRESNEL_I_LIMBS 8
typedef struct fresnel_i_qbig {
    uint32_t d[FRESNEL_I_LIMBS];
} fresnel_i_qbig;

static void fresnel_i_qbig_set(fresnel_i_qbig *x, uint32_t v)
{
    int k;
    x->d[0] = v & 0xffffu;
    x->d[1] = v >> 16;
    for (k = 2; k < FRESNEL_I_LIMBS; k++)
        x->d[k] = 0;
}

/* x = x m + a for m, a < 2^16, over the low len limbs of x (the result
 * must fit them). R: limb m + carry <= (2^16-1)^2 + 2^16-1 < 2^32. */
static void fresnel_i_qbig_mul_add(fresnel_i_qbig *x, uint32_t m, uint32_t a, int len)
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
static void fresnel_i_qbig_add_mul(fresnel_i_qbig *acc, const fresnel_i_qbig *x, uint32_t m, int s, int len)
{
    uint32_t carry = 0, p;
    int k;
    for (k = s; k < FRESNEL_I_LIMBS && (k < s + len || carry); k++) {
        p = acc->d[k] + (k < s + len ? x->d[k - s] * m : 0u) + carry;
        acc->d[k] = p & 0xffffu;
        carry = p >> 16;
    }
}

static int fresnel_i_qbig_ge(const fresnel_i_qbig *a, const fresnel_i_qbig *b)
{
    int k;
    for (k = FRESNEL_I_LIMBS - 1; k >= 0; k--)
        if (a->d[k] != b->d[k])
            return a->d[k] > b->d[k];
    return 1;
}

/* a = a - b for a >= b */
static void fresnel_i_qbig_sub(fresnel_i_qbig *a, const fresnel_i_qbig *b)
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
static uint32_t fresnel_i_qbig_div(fresnel_i_qbig *a, const fresnel_i_qbig *b)
{
    fresnel_i_qbig s;
    uint32_t q = 0;
    int i, k;
    s.d[0] = s.d[1] = 0;
    for (k = 2; k < FRESNEL_I_LIMBS; k++)
        s.d[k] = b->d[k - 2];
    for (i = 0; i < 32; i++) {
        for (k = 0; k < FRESNEL_I_LIMBS; k++) /* s = s / 2 */
            s.d[k] = (s.d[k] >> 1) | (k + 1 < FRESNEL_I_LIMBS ? (s.d[k + 1] & 1u) << 15 : 0u);
        q <<= 1;
        if (fresnel_i_qbig_ge(a, &s)) {
            fresnel_i_qbig_sub(a, &s);
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
typedef struct fresnel_i_qavg_form {
    uint16_t den, deg;
    int16_t interior[4], first[4], last[4];
    int cubic; /* nodes 1 and N-1 have weights of their own */
    int16_t second[4], next_to_last[4];
} fresnel_i_qavg_form;
static const fresnel_i_qavg_form fresnel_i_qavg_forms[3] = {
    {5, 4, {0, 10, 0, 20}, {1, 0, 0, 0}, {-1, 5, -10, 10}, 0, {0, 0, 0, 0}, {0, 0, 0, 0}},
    {210, 4, {0, 0, 0, 840}, {-66, 0, 0, 0}, {66, -21, -252, 385}, 1, {836, 0, 0, 0}, {-836, 2541, -2478, 875}},
    {3, 2, {0, 6, 0, 0}, {1, 0, 0, 0}, {-1, 3, 0, 0}, 0, {0, 0, 0, 0}, {0, 0, 0, 0}},
};
/* The cubic for n = 2 (D = 35) and n = 3 (D = 1680). */
static const int16_t fresnel_i_qavg_cubic_small[2][3] = {{6, 29, 0}, {-33, 665, 1048}};

/* plus += (the positive terms of c at v) t, minus += (the negative ones) t,
 * each part by Horner (coefficients below 2^16, v < 2^15, so each part is
 * below 2^57: four limbs), t < 2^32 in two 16-bit halves. */
static void fresnel_i_qavg_add(fresnel_i_qbig *plus, fresnel_i_qbig *minus, const int16_t coef[4], uint32_t v,
                              uint32_t t)
{
    fresnel_i_qbig x;
    int sign, j;
    for (sign = 1; sign >= -1; sign -= 2) {
        if (coef[0] * sign <= 0 && coef[1] * sign <= 0 && coef[2] * sign <= 0 && coef[3] * sign <= 0)
            continue;
        fresnel_i_qbig_set(&x, 0);
        for (j = 3; j >= 0; j--)
            fresnel_i_qbig_mul_add(&x, v, coef[j] * sign > 0 ? (uint32_t)(coef[j] * sign) : 0u, 4);
        fresnel_i_qbig_add_mul(sign > 0 ? plus : minus, &x, t & 0xffffu, 0, 4);
        if (t >> 16)
            fresnel_i_qbig_add_mul(sign > 0 ? plus : minus, &x, t >> 16, 1, 4);
    }
}

static fresnel_q15 fresnel_i_qavg_u16(const uint16_t *table, int n, int form)
{
    const fresnel_i_qavg_form *f = &fresnel_i_qavg_forms[form];
    fresnel_i_qbig plus, minus, d;
    uint32_t top = FRESNEL_I_ONE_Q15, last = (uint32_t)n - 1u, r;
    int i;
    if (n <= 1)
        return n == 1 ? table[0] : 0;
    fresnel_i_qbig_set(&plus, 0);
    fresnel_i_qbig_set(&minus, 0);
    if (f->cubic && n <= 3) {
        fresnel_i_qbig_set(&d, n == 2 ? 35u : 1680u);
        for (i = 0; i < n; i++) {
            const int16_t c[4] = {fresnel_i_qavg_cubic_small[n - 2][i], 0, 0, 0};
            fresnel_i_qavg_add(&plus, &minus, c, 0u, table[i]);
        }
    } else {
        fresnel_i_qbig_set(&d, f->den);
        for (i = 0; i < f->deg; i++)
            fresnel_i_qbig_mul_add(&d, last, 0u, FRESNEL_I_LIMBS);
        for (i = 0; i < n; i++) {
            const int16_t *c = f->interior;
            uint32_t v = (uint32_t)i;
            if (i == 0)
                c = f->first;
            else if ((uint32_t)i == last)
                c = f->last, v = last;
            else if (f->cubic && (uint32_t)i == last - 1u)
                c = f->next_to_last, v = last;
            else if (f->cubic && i == 1)
                c = f->second;
            fresnel_i_qavg_add(&plus, &minus, c, v, table[i]);
        }
    }
    for (i = 0; i < n; i++)
        top = table[i] > top ? table[i] : top;
    if (fresnel_i_qbig_ge(&minus, &plus))
        return 0;
    fresnel_i_qbig_sub(&plus, &minus);
    /* (plus - minus) / D is below 2^16, the largest code: rounded to the
     * nearest (halves up) from floor(2 (plus - minus) / D) */
    fresnel_i_qbig_set(&minus, 0);
    fresnel_i_qbig_add_mul(&minus, &plus, 2u, 0, FRESNEL_I_LIMBS);
    r = (fresnel_i_qbig_div(&minus, &d) + 1u) >> 1;
    return (fresnel_q15)(r < top ? r : top);
}

static int fresnel_i_qavg_n(int n) { return n <= 0 ? 0 : (n > FRESNEL_I_AVG_N_MAX ? FRESNEL_I_AVG_N_MAX : n); }

fresnel_q15 fresnel_lut_avg_u16_q15(const uint16_t *table, int n)
{
    return fresnel_i_qavg_u16(table, fresnel_i_qavg_n(n), 0);
}
fresnel_q15 fresnel_lut_cubic_avg_u16_q15(const uint16_t *table, int n)
{
    return fresnel_i_qavg_u16(table, fresnel_i_qavg_n(n), 1);
}
fresnel_q15 fresnel_lut_linear_avg_u16_q15(const uint16_t *table, int n)
{
    return fresnel_i_qavg_u16(table, fresnel_i_qavg_n(n), 2);
}

static fresnel_rgb_q15 fresnel_i_qavg_u16_rgb(const uint16_t *table, int n, int form)
{
    n = fresnel_i_qavg_n(n);
    FRESNEL_I_RGB_Q15(fresnel_i_qavg_u16(table, n, form), fresnel_i_qavg_u16(table + n, n, form),
                      fresnel_i_qavg_u16(table + 2 * n, n, form));
}

fresnel_rgb_q15 fresnel_lut_avg_u16_q15_rgb(const uint16_t *table, int n)
{
    return fresnel_i_qavg_u16_rgb(table, n, 0);
}
fresnel_rgb_q15 fresnel_lut_cubic_avg_u16_q15_rgb(const uint16_t *table, int n)
{
    return fresnel_i_qavg_u16_rgb(table, n, 1);
}
fresnel_rgb_q15 fresnel_lut_linear_avg_u16_q15_rgb(const uint16_t *table, int n)
{
    return fresnel_i_qavg_u16_rgb(table, n, 2);
}

#else
typedef int fresnel_i_lut_avg_q15_disabled;
#endif
