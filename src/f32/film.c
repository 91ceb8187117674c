/* Thin-film iridescence in binary32 (fresnel_film.h): the pole form of the
 * Airy sum, with the material's terms interpolated linearly between the
 * table's cosines.
 *
 * Written as loops of fixed length over independent lanes (the table's
 * terms, the poles padded to 8), without branches, so that the compiler
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
    float turns[FRESNEL_I_FILM_PAD], decay[FRESNEL_I_FILM_PAD];
    float zc[FRESNEL_I_FILM_PAD], zs[FRESNEL_I_FILM_PAD];
    float fr[FRESNEL_FILM_TERMS], fi[FRESNEL_FILM_TERMS];
    int i, j, l, ch;
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

    /* zeta_j = exp(2 pi i (x + i y)(nu_j + i gamma_j)): turns of the phase
     * and the exponent of the decay */
    for (j = 0; j < FRESNEL_I_FILM_PAD; j++) {
        float nu = j < FRESNEL_FILM_POLES ? m->freq[j] : 0.0f, g = j < FRESNEL_FILM_POLES ? m->damp[j] : 0.0f;
        turns[j] = x * nu - y * g;
        decay[j] = 6.28318530718f * (x * g + y * nu);
    }
    for (j = 0; j < FRESNEL_I_FILM_PAD; j++) {
        /* cos, sin of 2 pi turns: |turns| < 2^22 (clamped: beyond, binary32
         * holds no fraction of a turn); the nearest quarter turn q, then
         * Taylor polynomials on |x| <= pi/4 (errors below 4e-7, 3e-8) and
         * the quadrant's rotation. */
        float tt = fresnel_i_clamp(turns[j], -4194304.0f, 4194304.0f);
        float rr = tt - (float)(int32_t)tt;             /* (-1, 1), exact */
        float q4 = rr * 4.0f;
        int32_t q = (int32_t)(q4 + (q4 < 0.0f ? -0.5f : 0.5f));
        float xr = 6.28318530718f * (rr - 0.25f * (float)q); /* [-pi/4, pi/4] */
        float x2 = xr * xr;
        float s = xr * (1.0f - x2 * (1.0f / 6.0f - x2 * (1.0f / 120.0f - x2 * (1.0f / 5040.0f))));
        float co = 1.0f - x2 * (0.5f - x2 * (1.0f / 24.0f - x2 * (1.0f / 720.0f - x2 * (1.0f / 40320.0f))));
        uint32_t odd = (uint32_t)q & 1u, neg_c = ((uint32_t)q + 1u) & 2u, neg_s = (uint32_t)q & 2u;
        float cq = odd ? s : co, sq = odd ? co : s;
        /* exp(-decay) = 2^-v, v = k + f: 2^-f = 2^-1/2 exp(-(f - 1/2) ln 2)
         * by a degree-6 Taylor polynomial (below 2e-7 relative), 2^-k from
         * the exponent bits; decay clamped to [0, 87] (NaN to 0). */
        float v = fresnel_i_clamp(decay[j], 0.0f, 87.0f) * 1.44269504089f;
        int32_t k = (int32_t)v;
        float e = (0.5f - (v - (float)k)) * 0.69314718056f;
        float p = 1.0f + e * (1.0f + e * (0.5f + e * (1.0f / 6.0f + e * (1.0f / 24.0f + e * (1.0f / 120.0f + e * (1.0f / 720.0f))))));
        union {
            uint32_t bits;
            float f;
        } scale;
        scale.bits = (uint32_t)(127 - k) << 23; /* 2^-k, k <= 125 */
        p *= 0.70710678119f * scale.f;
        zc[j] = (neg_c ? -cq : cq) * p;
        zs[j] = (neg_s ? -sq : sq) * p;
    }

    /* kappa zeta / (1 - q zeta) = kappa zeta conj(den) / |den|^2 for each
     * term (pole l % POLES, s then p) */
    for (l = 0; l < FRESNEL_FILM_TERMS; l++) {
        int jj = l < FRESNEL_FILM_POLES ? l : l - FRESNEL_FILM_POLES;
        float kr = u * lo->kappa_re[l] + t * hi->kappa_re[l], ki = u * lo->kappa_im[l] + t * hi->kappa_im[l];
        float qr = u * lo->q_re[l] + t * hi->q_re[l], qi = u * lo->q_im[l] + t * hi->q_im[l];
        float a = zc[jj], b = zs[jj];
        float dr = 1.0f - (qr * a - qi * b), di = -(qr * b + qi * a);
        float nr = kr * a - ki * b, ni = kr * b + ki * a;
        float inv = 1.0f / (dr * dr + di * di);
        fr[l] = (nr * dr + ni * di) * inv;
        fi[l] = (ni * dr - nr * di) * inv;
    }
    for (ch = 0; ch < 3; ch++) {
        float sum = u * lo->a0[ch] + t * hi->a0[ch];
        for (j = 0; j < FRESNEL_FILM_POLES; j++)
            sum += m->weight[ch][j][0] * (fr[j] + fr[j + FRESNEL_FILM_POLES]) -
                   m->weight[ch][j][1] * (fi[j] + fi[j + FRESNEL_FILM_POLES]);
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
