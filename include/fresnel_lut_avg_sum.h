/* The exact sum behind the LUT averages of every number type
 * (src/f32/lut_avg.c derives the weights; src/q15/lut_avg_q15.c): each
 * weight is c_i / D, an integer polynomial over one integer denominator, so
 * a table's average is the ratio of two integers, summed here exactly in
 * multi-word integers and divided once. Integer arithmetic only (no
 * division instruction, no int64), so the Q1.15 runtime takes it as it is.
 * Internal: no public name; the runtime's .c files include it (a vendoring
 * project copies include/ whole, so every type's folder finds it). */
#ifndef FRESNEL_LUT_AVG_SUM_H
#define FRESNEL_LUT_AVG_SUM_H

#include <stdint.h>

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

/* D of form `form` for a table of n >= 2 nodes, N = n - 1. */
static void fresnel_i_avg_den(fresnel_i_big *d, int form, uint32_t n)
{
    const fresnel_i_avg_form *f = &fresnel_i_avg_forms[form];
    int i;
    if (f->cubic && n <= 3) {
        fresnel_i_big_set(d, n == 2 ? 35u : 1680u);
        return;
    }
    fresnel_i_big_set(d, f->den);
    for (i = 0; i < f->deg; i++)
        fresnel_i_big_mul_add(d, n - 1u, 0u, FRESNEL_I_LIMBS);
}

/* Node i's coefficients c (with small[] as the storage of the small
 * cubics' constant) and the value *v they are evaluated at. */
static const int16_t *fresnel_i_avg_coef(int form, uint32_t n, uint32_t i, uint32_t *v, int16_t small[4])
{
    const fresnel_i_avg_form *f = &fresnel_i_avg_forms[form];
    uint32_t last = n - 1u;
    *v = i;
    if (f->cubic && n <= 3) {
        small[0] = fresnel_i_avg_cubic_small[n - 2u][i];
        small[1] = small[2] = small[3] = 0;
        return small;
    }
    if (i == 0)
        return f->first;
    if (i == last)
        return *v = last, f->last;
    if (f->cubic && i == last - 1u)
        return *v = last, f->next_to_last;
    if (f->cubic && i == 1)
        return f->second;
    return f->interior;
}

#endif
