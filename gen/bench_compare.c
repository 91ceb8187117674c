/* Comparators for `fresnel bench --targets` (see bench_compare.h): the two
 * algorithms other renderers use for the exact conductor, written here from
 * their published formulas in plain C99 binary32.
 *
 * Sources of the algorithms (formulas only):
 *   - K. D. Moeller, Optics (University Science Books, 1988): the a^2 + b^2 /
 *     2ac real form, which Mitsuba 3 (fresnel_conductor) and MaterialX
 *     (mx_fresnel_conductor) evaluate;
 *   - M. Pharr, W. Jakob, G. Humphreys, Physically Based Rendering, 4th ed.,
 *     section 9.5 (FrComplex): the Fresnel amplitudes in complex arithmetic. */
#include "bench_compare.h"

#include <math.h>

#include "f32/internal.h" /* the runtime's clamps and exact squares, for cmp_careful_conductor */

static float clamp01(float c) { return c > 0.0f ? (c < 1.0f ? c : 1.0f) : 0.0f; }
static float sqrt0(float x) { return sqrtf(x > 0.0f ? x : 0.0f); }

float cmp_mitsuba_conductor(float eta, float kappa, float c)
{
    float c2, s2, s4, a0, ab, a, t1, t2, t3, t4, rs, rp;
    c = clamp01(c);
    c2 = c * c;
    s2 = 1.0f - c2;
    s4 = s2 * s2;
    a0 = eta * eta - kappa * kappa - s2;
    ab = sqrt0(a0 * a0 + 4.0f * kappa * kappa * eta * eta); /* a^2 + b^2 */
    a = sqrt0(0.5f * (ab + a0));
    t1 = ab + c2;
    t2 = 2.0f * c * a;
    rs = (t1 - t2) / (t1 + t2);
    t3 = ab * c2 + s4;
    t4 = t2 * s2;
    rp = rs * (t3 - t4) / (t3 + t4);
    return 0.5f * (rs + rp);
}

typedef struct cx {
    float re, im;
} cx;

static cx cx_make(float re, float im)
{
    cx z;
    z.re = re;
    z.im = im;
    return z;
}
static cx cx_add(cx a, cx b) { return cx_make(a.re + b.re, a.im + b.im); }
static cx cx_sub(cx a, cx b) { return cx_make(a.re - b.re, a.im - b.im); }
static cx cx_mul(cx a, cx b) { return cx_make(a.re * b.re - a.im * b.im, a.re * b.im + a.im * b.re); }
static cx cx_scale(cx a, float s) { return cx_make(a.re * s, a.im * s); }
static float cx_norm(cx a) { return a.re * a.re + a.im * a.im; }

/* (a + ib) / (c + id) = ((ac + bd) + i (bc - ad)) / (c^2 + d^2), one reciprocal */
static cx cx_div(cx a, cx b)
{
    float s = 1.0f / cx_norm(b);
    return cx_make(s * (a.re * b.re + a.im * b.im), s * (a.im * b.re - a.re * b.im));
}

/* Principal square root: t1 = sqrt((|z| + |Re z|)/2), t2 = Im z / (2 t1). */
static cx cx_sqrt(cx z)
{
    float n = sqrtf(cx_norm(z)), t1, t2;
    if (n == 0.0f)
        return cx_make(0.0f, 0.0f);
    t1 = sqrtf(0.5f * (n + fabsf(z.re)));
    t2 = 0.5f * z.im / t1;
    if (z.re >= 0.0f)
        return cx_make(t1, t2);
    return cx_make(fabsf(t2), copysignf(t1, z.im));
}

float cmp_pbrt_conductor(float eta, float kappa, float c)
{
    cx n = cx_make(eta, kappa), sin2t, cost, nc, ncost, r_par, r_perp;
    float s2;
    c = clamp01(c);
    s2 = 1.0f - c * c;
    sin2t = cx_div(cx_make(s2, 0.0f), cx_mul(n, n));
    cost = cx_sqrt(cx_sub(cx_make(1.0f, 0.0f), sin2t));
    nc = cx_scale(n, c);
    r_par = cx_div(cx_sub(nc, cost), cx_add(nc, cost));
    ncost = cx_mul(n, cost);
    r_perp = cx_div(cx_sub(cx_make(c, 0.0f), ncost), cx_add(cx_make(c, 0.0f), ncost));
    return 0.5f * (cx_norm(r_par) + cx_norm(r_perp));
}

/* The careful real form of the exact conductor: u and v from sqrt and
 * eta kappa / u, 3 divisions; the baseline for the one-division form. */
float cmp_careful_conductor(float eta, float kappa, float c)
{
    float ek, a, m, u, v, p, q, num_s, den_s, num_p, den_p, rs, rp;
    eta = fresnel_i_eta(eta);
    kappa = fresnel_i_kappa(kappa);
    c = fresnel_i_unit(c);
    if (eta == 1.0f && kappa == 0.0f)
        return 0.0f;
    ek = eta * kappa;
    a = fresnel_i_eta2_minus_sin2(eta, c, kappa * kappa);
    m = sqrtf(a * a + 4.0f * ek * ek);
    if (a >= 0.0f) {
        u = sqrtf(0.5f * (m + a));
        v = u > 0.0f ? ek / u : 0.0f;
    } else {
        v = sqrtf(0.5f * (m - a));
        u = ek / v;
    }
    p = c * ((eta - kappa) * (eta + kappa));
    q = 2.0f * eta * kappa * c;
    num_s = (c - u) * (c - u) + v * v;
    den_s = (c + u) * (c + u) + v * v;
    num_p = (p - u) * (p - u) + (q - v) * (q - v);
    den_p = (p + u) * (p + u) + (q + v) * (q + v);
    rs = den_s > 0.0f ? num_s / den_s : 0.0f;
    rp = den_p > 0.0f ? num_p / den_p : 0.0f;
    return fresnel_i_unit(0.5f * (rs + rp));
}
