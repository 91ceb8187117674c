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

typedef union fresnel_i_film_bits {
    float f;
    int32_t i;
} fresnel_i_film_bits;

#if defined(__GNUC__) && !defined(__clang__)
#define FRESNEL_I_FILM_UNROLL _Pragma("GCC unroll 64")
#else
#define FRESNEL_I_FILM_UNROLL
#endif

/* where the run's last 8 values begin; whether 8 lanes of term k would
 * read past the run; the lanes of term k */
#define FRESNEL_I_FILM_TAIL (FRESNEL_I_FILM_TERMS * FRESNEL_FILM_POLES - FRESNEL_I_FILM_PAD)
#define FRESNEL_I_FILM_IN_TAIL(k) ((k) * FRESNEL_FILM_POLES > FRESNEL_I_FILM_TAIL)
#define FRESNEL_I_FILM_TERM(k, j) \
    (FRESNEL_I_FILM_IN_TAIL(k) ? tail[(k) * FRESNEL_FILM_POLES - FRESNEL_I_FILM_TAIL + (j)] : v[k][j])
typedef char fresnel_i_film_tail_check[FRESNEL_I_FILM_TAIL >= 0 ? 1 : -1];

/* 1 for the lanes of the poles, 0 past them (eight lanes written out) */
#define FRESNEL_I_FILM_LIVE(j) ((j) < FRESNEL_FILM_POLES ? 1.0f : 0.0f)
typedef char fresnel_i_film_live_check[FRESNEL_I_FILM_PAD == 8 ? 1 : -1];
static const float fresnel_i_film_live[FRESNEL_I_FILM_PAD] = {
    FRESNEL_I_FILM_LIVE(0), FRESNEL_I_FILM_LIVE(1), FRESNEL_I_FILM_LIVE(2), FRESNEL_I_FILM_LIVE(3),
    FRESNEL_I_FILM_LIVE(4), FRESNEL_I_FILM_LIVE(5), FRESNEL_I_FILM_LIVE(6), FRESNEL_I_FILM_LIVE(7),
};

fresnel_rgb fresnel_film_rgb(const fresnel_film *m, float c, float d_nm)
{
    const fresnel_film_node *lo, *hi;
    const float *tlo, *thi;
    float pos, t, u, x, y, r[3];
    /* A, B, P, Q interpolated, 8 lanes per term: term k of pole j at
     * v[k][j], from the node's run of 8 x POLES values at k POLES + j;
     * where 8 lanes would read past the run, at tail[k POLES + j - TAIL],
     * interpolated from the run's last 8 values (zeros after them). The
     * lanes past the poles hold other terms' values or zeros and are
     * silenced below. */
    float v[FRESNEL_I_FILM_TERMS][FRESNEL_I_FILM_PAD], tail[2 * FRESNEL_I_FILM_PAD];
    float nu[FRESNEL_I_FILM_PAD], ga[FRESNEL_I_FILM_PAD], g[2 * FRESNEL_I_FILM_PAD];
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
    /* the optical path, and its decay in total reflection inside the film,
     * held below 2^21 nm: with the poles' 0 < nu, gamma < 1 (the fit's
     * range, gen/2_derive/film_fit.c) the phase below stays within 2^22
     * turns and the octaves of decay below 2^26, whatever the table's
     * node values */
    x = fresnel_i_clamp(d_nm * (u * lo->opd + t * hi->opd), 0.0f, 2097152.0f);
    y = fresnel_i_clamp(d_nm * (u * lo->decay + t * hi->decay), 0.0f, 2097152.0f);

    tlo = fresnel_i_film_terms(lo);
    thi = fresnel_i_film_terms(hi);
    FRESNEL_I_FILM_UNROLL
    for (k = 0; k < FRESNEL_I_FILM_TERMS; k++)
        if (!FRESNEL_I_FILM_IN_TAIL(k))
            for (j = 0; j < FRESNEL_I_FILM_PAD; j++)
                v[k][j] = u * tlo[k * FRESNEL_FILM_POLES + j] + t * thi[k * FRESNEL_FILM_POLES + j];
    for (j = 0; j < FRESNEL_I_FILM_PAD; j++) {
        tail[j] = u * tlo[FRESNEL_I_FILM_TAIL + j] + t * thi[FRESNEL_I_FILM_TAIL + j];
        tail[FRESNEL_I_FILM_PAD + j] = 0.0f;
    }
    for (j = 0; j < FRESNEL_FILM_POLES; j++) {
        nu[j] = m->freq[j];
        ga[j] = m->damp[j];
    }
    for (; j < FRESNEL_I_FILM_PAD; j++)
        nu[j] = ga[j] = 0.0f;
    for (j = 0; j < FRESNEL_I_FILM_PAD; j++) {
        /* zeta = exp(2 pi i (x + i y)(nu + i gamma)) = 2^-w e^(2 pi i tt).
         * The phase: tt (|tt| < 2^22, where binary32 still holds a
         * fraction of a turn) less its nearest whole turn, h in [-1/2, 1/2]
         * (exact); cos and sin of a quarter of it, pi h / 2 in
         * [-pi/4, pi/4], by polynomials fitted for the least maximum
         * relative error (3.3e-8 and 3.2e-9), then doubled twice
         * (cos 2a = (cos a - sin a)(cos a + sin a), sin 2a = 2 sin a cos a):
         * no quadrant to select, so no branch in the loop. */
        float tt = x * nu[j] - y * ga[j];
        float rr = tt - (float)(int32_t)tt;                  /* (-1, 1) */
        float h = rr - (float)((int32_t)(rr + 1.5f) - 1);  /* [-1/2, 1/2] */
        float qa = 1.57079632679f * h, q2 = qa * qa, q4 = q2 * q2; /* (Estrin's scheme: short chains) */
        float s4 = qa * ((0.999999997f - 0.166666502f * q2) + q4 * (0.00833201724f - 0.000195018938f * q2));
        float c4 = (0.999999968f - 0.499998427f * q2) + q4 * (0.0416544269f - 0.00135794706f * q2);
        float c2 = (c4 - s4) * (c4 + s4), s2 = 2.0f * s4 * c4;
        float co = (c2 - s2) * (c2 + s2), si = 2.0f * s2 * c2;
        /* the magnitude: w = k + f, 2^-f by a polynomial fitted for the
         * least maximum relative error (7.5e-8), 2^-k from the exponent
         * bits, 0 from k = 127 on (an integer maximum: no float comparison
         * for a compiler to turn into a branch) */
        float w = 9.06472028365f * (x * ga[j] + y * nu[j]);
        int32_t kk = (int32_t)w, e = 127 - kk;
        float f = w - (float)kk;
        float f2 = f * f;
        float p = (0.999999925f - 0.693142253f * f) + f2 * ((0.240172189f - 0.0552797214f * f) + f2 * (0.00918861005f - 0.000938787553f * f));
        fresnel_i_film_bits scale;
        float a, b, z2r, z2i, nr0, ni0, nr, ni, dr, di, inv;
        scale.i = (e > 0 ? e : 0) * 8388608; /* 2^-k, or 0 */
        p *= scale.f;
        p *= fresnel_i_film_live[j]; /* zeta = 0 past the poles: F = 0 there */
        a = co * p;
        b = si * p;
        /* zeta (A + B zeta) / (1 - P zeta + Q zeta^2) */
        z2r = a * a - b * b;
        z2i = 2.0f * a * b;
        nr0 = FRESNEL_I_FILM_TERM(0, j) + (FRESNEL_I_FILM_TERM(2, j) * a - FRESNEL_I_FILM_TERM(3, j) * b);
        ni0 = FRESNEL_I_FILM_TERM(1, j) + (FRESNEL_I_FILM_TERM(2, j) * b + FRESNEL_I_FILM_TERM(3, j) * a);
        nr = a * nr0 - b * ni0;
        ni = a * ni0 + b * nr0;
        dr = 1.0f - (FRESNEL_I_FILM_TERM(4, j) * a - FRESNEL_I_FILM_TERM(5, j) * b) + (FRESNEL_I_FILM_TERM(6, j) * z2r - FRESNEL_I_FILM_TERM(7, j) * z2i);
        di = -(FRESNEL_I_FILM_TERM(4, j) * b + FRESNEL_I_FILM_TERM(5, j) * a) + (FRESNEL_I_FILM_TERM(6, j) * z2i + FRESNEL_I_FILM_TERM(7, j) * z2r);
        inv = 1.0f / (dr * dr + di * di);
        g[2 * j] = (nr * dr + ni * di) * inv;      /* Re F */
        g[2 * j + 1] = (nr * di - ni * dr) * inv;  /* -Im F */
    }
    /* R = a0 + sum_j Re(w_j F_j): each channel's weights as one run of
     * (Re w, Im w) pairs against (Re F, -Im F), in four partial sums */
    for (ch = 0; ch < 3; ch++) {
        const float *w = (const float *)(const void *)m->weight[ch];
        float p0 = 0.0f, p1 = 0.0f, p2 = 0.0f, p3 = 0.0f;
        for (k = 0; k + 4 <= 2 * FRESNEL_FILM_POLES; k += 4) {
            p0 += w[k] * g[k];
            p1 += w[k + 1] * g[k + 1];
            p2 += w[k + 2] * g[k + 2];
            p3 += w[k + 3] * g[k + 3];
        }
        for (; k < 2 * FRESNEL_FILM_POLES; k++)
            p0 += w[k] * g[k];
        r[ch] = (u * lo->a0[ch] + t * hi->a0[ch]) + ((p0 + p1) + (p2 + p3));
    }
    out.r = fresnel_i_unit(r[0]);
    out.g = fresnel_i_unit(r[1]);
    out.b = fresnel_i_unit(r[2]);
    return out;
}

#else
typedef int fresnel_i_film_disabled; /* FRESNEL_CFG_NO_FLOAT: ISO C wants a declaration */
#endif
