/* Thin-film iridescence in binary32 (fresnel_film.h): the pole form of the
 * Airy sum, with the material's terms interpolated linearly between the
 * table's cosines.
 *
 * Written as loops of fixed length over independent lanes (the poles,
 * padded to 8), without branches, so that the compiler vectorises the
 * poles' loop at -O2 and at -O3 -march=native (gcc 12 and clang 14: SSE2
 * and AVX on x86-64, NEON on AArch64; gcc -fopt-info-vec says which). The
 * trigonometric and exponential factors come from short polynomials
 * here, no libm call: 1e-7 is all the result can use. */
#include "internal.h"
#include "fresnel_film.h"

#include <stddef.h>

#if FRESNEL_HAS_FLOAT

#define FRESNEL_I_FILM_PAD 8 /* poles, padded to a whole number of vectors */
#define FRESNEL_I_FILM_TERMS 8 /* A, B, P, Q, real and imaginary parts */

typedef char fresnel_i_film_pad_check[FRESNEL_FILM_POLES <= FRESNEL_I_FILM_PAD ? 1 : -1];
/* a node's A, B, P, Q are read as one run of 8 x POLES floats */
typedef char fresnel_i_film_run_check[offsetof(fresnel_film_node, q_im) - offsetof(fresnel_film_node, a_re) ==
                                              (FRESNEL_I_FILM_TERMS - 1) * FRESNEL_FILM_POLES * sizeof(float)
                                          ? 1
                                          : -1];

static const float *fresnel_i_film_terms(const fresnel_film_node *n)
{
    return (const float *)(const void *)((const char *)n + offsetof(fresnel_film_node, a_re));
}

/* The clamps of the loop below on the bits of the float, as integer
 * minimum and maximum: a compiler keeps them branch-free, where a float
 * comparison can be turned into a branch (gcc -O3 specialises the clamped
 * case) that stops the loop's vectorisation. Finite floats of one sign
 * order as their bits; NaN gives the upper end. */
typedef union fresnel_i_film_bits {
    float f;
    int32_t i;
} fresnel_i_film_bits;

/* x clamped to [0, hi], hi > 0 */
static inline float fresnel_i_film_clamp_unsigned(float x, float hi)
{
    fresnel_i_film_bits v, h;
    v.f = x;
    h.f = hi;
    v.i = v.i < h.i ? v.i : h.i;
    v.i = v.i > 0 ? v.i : 0;
    return v.f;
}

/* |x| clamped to hi > 0, the sign kept */
static inline float fresnel_i_film_clamp_signed(float x, float hi)
{
    fresnel_i_film_bits v, h;
    int32_t mag;
    v.f = x;
    h.f = hi;
    mag = v.i & 0x7fffffff;
    mag = mag < h.i ? mag : h.i;
    v.i = (int32_t)((uint32_t)v.i & 0x80000000u) | mag;
    return v.f;
}

fresnel_rgb fresnel_film_rgb(const fresnel_film *m, float c, float d_nm)
{
    const fresnel_film_node *lo, *hi;
    const float *tlo, *thi;
    float pos, t, u, x, y, r[3];
    float nu[FRESNEL_I_FILM_PAD], ga[FRESNEL_I_FILM_PAD], v[FRESNEL_I_FILM_TERMS][FRESNEL_I_FILM_PAD];
    float fr[FRESNEL_I_FILM_PAD], fi[FRESNEL_I_FILM_PAD];
    int i, j, k, ch;
    fresnel_rgb out;
    c = fresnel_i_unit(c);
    d_nm = fresnel_i_clamp(d_nm, 0.0f, FRESNEL_FILM_D_MAX);
    pos = sqrtf(c) * (float)(FRESNEL_FILM_NODES - 1);
    i = (int)pos;
    i = i > FRESNEL_FILM_NODES - 2 ? FRESNEL_FILM_NODES - 2 : i;
    t = pos - (float)i;
    u = 1.0f - t;
    lo = &m->node[i];
    hi = &m->node[i + 1];
    x = d_nm * (u * lo->opd + t * hi->opd);
    y = d_nm * (u * lo->decay + t * hi->decay);

    /* A, B, P, Q interpolated; lanes past the poles: nu = gamma = 0 and
     * A = B = P = Q = 0, so F = 0 */
    tlo = fresnel_i_film_terms(lo);
    thi = fresnel_i_film_terms(hi);
    for (k = 0; k < FRESNEL_I_FILM_TERMS; k++) {
        for (j = 0; j < FRESNEL_FILM_POLES; j++)
            v[k][j] = u * tlo[k * FRESNEL_FILM_POLES + j] + t * thi[k * FRESNEL_FILM_POLES + j];
        for (; j < FRESNEL_I_FILM_PAD; j++)
            v[k][j] = 0.0f;
    }
    for (j = 0; j < FRESNEL_FILM_POLES; j++) {
        nu[j] = m->freq[j];
        ga[j] = m->damp[j];
    }
    for (; j < FRESNEL_I_FILM_PAD; j++)
        nu[j] = ga[j] = 0.0f;
    for (j = 0; j < FRESNEL_I_FILM_PAD; j++) {
        /* zeta = exp(2 pi i (x + i y)(nu + i gamma)) = 2^-w e^(2 pi i tt).
         * The phase: tt (|tt| clamped below 2^22, where binary32 still
         * holds a fraction of a turn) less its nearest whole turn, h in
         * [-1/2, 1/2] (exact); cos and sin of a quarter of it, pi h / 2 in
         * [-pi/4, pi/4], by polynomials fitted for the least maximum
         * relative error (3.3e-8 and 3.2e-9), then doubled twice
         * (cos 2a = (cos a - sin a)(cos a + sin a), sin 2a = 2 sin a cos a):
         * no quadrant to select, so no branch in the loop. */
        float tt = fresnel_i_film_clamp_signed(x * nu[j] - y * ga[j], 4194304.0f);
        float rr = tt - (float)(int32_t)tt;                  /* (-1, 1) */
        float h = rr - (float)((int32_t)(rr + 1.5f) - 1);  /* [-1/2, 1/2] */
        float qa = 1.57079632679f * h, q2 = qa * qa, q4 = q2 * q2; /* (Estrin's scheme: short chains) */
        float s4 = qa * ((0.999999997f - 0.166666502f * q2) + q4 * (0.00833201724f - 0.000195018938f * q2));
        float c4 = (0.999999968f - 0.499998427f * q2) + q4 * (0.0416544269f - 0.00135794706f * q2);
        float c2 = (c4 - s4) * (c4 + s4), s2 = 2.0f * s4 * c4;
        float co = (c2 - s2) * (c2 + s2), si = 2.0f * s2 * c2;
        /* the magnitude: w = k + f, 2^-f by a polynomial fitted for the
         * least maximum relative error (7.5e-8), 2^-k from the exponent
         * bits; w clamped to [0, 125] */
        float w = fresnel_i_film_clamp_unsigned(9.06472028365f * (x * ga[j] + y * nu[j]), 125.0f);
        int32_t kk = (int32_t)w;
        float f = w - (float)kk;
        float f2 = f * f;
        float p = (0.999999925f - 0.693142253f * f) + f2 * ((0.240172189f - 0.0552797214f * f) + f2 * (0.00918861005f - 0.000938787553f * f));
        union {
            uint32_t bits;
            float f;
        } scale;
        float a, b, z2r, z2i, nr0, ni0, nr, ni, dr, di, inv;
        scale.bits = (uint32_t)(127 - kk) << 23; /* 2^-k */
        p *= scale.f;
        a = co * p;
        b = si * p;
        /* zeta (A + B zeta) / (1 - P zeta + Q zeta^2) */
        z2r = a * a - b * b;
        z2i = 2.0f * a * b;
        nr0 = v[0][j] + (v[2][j] * a - v[3][j] * b);
        ni0 = v[1][j] + (v[2][j] * b + v[3][j] * a);
        nr = a * nr0 - b * ni0;
        ni = a * ni0 + b * nr0;
        dr = 1.0f - (v[4][j] * a - v[5][j] * b) + (v[6][j] * z2r - v[7][j] * z2i);
        di = -(v[4][j] * b + v[5][j] * a) + (v[6][j] * z2i + v[7][j] * z2r);
        inv = 1.0f / (dr * dr + di * di);
        fr[j] = (nr * dr + ni * di) * inv;
        fi[j] = (ni * dr - nr * di) * inv;
    }
    for (ch = 0; ch < 3; ch++) {
        float sum = u * lo->a0[ch] + t * hi->a0[ch];
        for (k = 0; k < FRESNEL_FILM_POLES; k++)
            sum += m->weight[ch][k][0] * fr[k] - m->weight[ch][k][1] * fi[k];
        r[ch] = sum;
    }
    out.r = fresnel_i_unit(r[0]);
    out.g = fresnel_i_unit(r[1]);
    out.b = fresnel_i_unit(r[2]);
    return out;
}

#else
typedef int fresnel_i_film_disabled; /* FRESNEL_CFG_NO_FLOAT: ISO C wants a declaration */
#endif
