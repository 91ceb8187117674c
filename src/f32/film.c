/* Thin-film iridescence in binary32 (fresnel_film.h): the pole form of the
 * Airy sum, with the material's terms interpolated linearly between the
 * table's cosines.
 *
 * Written as loops of fixed length over independent lanes (the poles,
 * padded to 8), without branches, so that the compiler
 * vectorises them at -O2 (gcc 12 and clang: SSE2 on x86-64, NEON on
 * AArch64). The trigonometric and exponential factors come from short
 * polynomials here, no libm call: 1e-7 is all the result can use. */
#include "internal.h"
#include "fresnel_film.h"

#if FRESNEL_HAS_FLOAT

#define FRESNEL_I_FILM_PAD 8 /* poles, padded to a whole number of vectors */

typedef char fresnel_i_film_pad_check[FRESNEL_FILM_POLES <= FRESNEL_I_FILM_PAD ? 1 : -1];

fresnel_rgb fresnel_film_rgb(const fresnel_film *m, float c, float d_nm)
{
    const fresnel_film_node *lo, *hi;
    float pos, t, u, x, y, r[3];
    float nu[FRESNEL_I_FILM_PAD], ga[FRESNEL_I_FILM_PAD], v[8][FRESNEL_I_FILM_PAD];
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

    /* the poles' constants and A, B, P, Q interpolated, padded with zeros */
    for (j = 0; j < FRESNEL_I_FILM_PAD; j++) {
        int in = j < FRESNEL_FILM_POLES, jj = in ? j : 0;
        nu[j] = in ? m->freq[jj] : 0.0f;
        ga[j] = in ? m->damp[jj] : 0.0f;
        v[0][j] = in ? u * lo->a_re[jj] + t * hi->a_re[jj] : 0.0f;
        v[1][j] = in ? u * lo->a_im[jj] + t * hi->a_im[jj] : 0.0f;
        v[2][j] = in ? u * lo->b_re[jj] + t * hi->b_re[jj] : 0.0f;
        v[3][j] = in ? u * lo->b_im[jj] + t * hi->b_im[jj] : 0.0f;
        v[4][j] = in ? u * lo->p_re[jj] + t * hi->p_re[jj] : 0.0f;
        v[5][j] = in ? u * lo->p_im[jj] + t * hi->p_im[jj] : 0.0f;
        v[6][j] = in ? u * lo->q_re[jj] + t * hi->q_re[jj] : 0.0f;
        v[7][j] = in ? u * lo->q_im[jj] + t * hi->q_im[jj] : 0.0f;
    }
    for (j = 0; j < FRESNEL_I_FILM_PAD; j++) {
        /* zeta = exp(2 pi i (x + i y)(nu + i gamma)): cos, sin of 2 pi turns
         * (|turns| clamped below 2^22, where binary32 still holds a
         * fraction of a turn): the nearest quarter turn q, Taylor
         * polynomials on |x| <= pi/4 (errors below 4e-7, 3e-8) and the
         * quadrant's rotation */
        float tt = fresnel_i_clamp(x * nu[j] - y * ga[j], -4194304.0f, 4194304.0f);
        float rr = tt - (float)(int32_t)tt; /* (-1, 1), exact */
        float q4 = rr * 4.0f;
        int32_t q = (int32_t)(q4 + (q4 < 0.0f ? -0.5f : 0.5f));
        float xr = 6.28318530718f * (rr - 0.25f * (float)q); /* [-pi/4, pi/4] */
        float x2 = xr * xr;
        float s = xr * (1.0f - x2 * (1.0f / 6.0f - x2 * (1.0f / 120.0f - x2 * (1.0f / 5040.0f))));
        float co = 1.0f - x2 * (0.5f - x2 * (1.0f / 24.0f - x2 * (1.0f / 720.0f - x2 * (1.0f / 40320.0f))));
        uint32_t odd = (uint32_t)q & 1u, neg_c = ((uint32_t)q + 1u) & 2u, neg_s = (uint32_t)q & 2u;
        float cq = odd ? s : co, sq = odd ? co : s;
        /* and exp(-2 pi (x gamma + y nu)) = 2^-w, w = k + f: 2^-f = 2^-1/2
         * exp(-(f - 1/2) ln 2) by a degree-6 Taylor polynomial (below 2e-7
         * relative), 2^-k from the exponent bits; w clamped to [0, 125] */
        float w = fresnel_i_clamp(9.06472028365f * (x * ga[j] + y * nu[j]), 0.0f, 125.0f);
        int32_t kk = (int32_t)w;
        float e = (0.5f - (w - (float)kk)) * 0.69314718056f;
        float p = 1.0f + e * (1.0f + e * (0.5f + e * (1.0f / 6.0f + e * (1.0f / 24.0f + e * (1.0f / 120.0f + e * (1.0f / 720.0f))))));
        union {
            uint32_t bits;
            float f;
        } scale;
        float a, b, z2r, z2i, nr0, ni0, nr, ni, dr, di, inv;
        scale.bits = (uint32_t)(127 - kk) << 23; /* 2^-k */
        p *= 0.70710678119f * scale.f;
        a = (neg_c ? -cq : cq) * p;
        b = (neg_s ? -sq : sq) * p;
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
