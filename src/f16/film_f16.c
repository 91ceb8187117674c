/* Thin-film iridescence in binary16 (fresnel_film.h): the algorithm of
 * src/f32/film.c with every operation rounded to half (the helpers of
 * internal.h), as a mediump shader evaluates it; cos and sin of the half
 * angle and exp are evaluated in binary32 and rounded to half (a GPU's
 * built-ins): cos, sin by the quarter-turn reduction and Taylor
 * polynomials of src/f32/film.c (this folder is self-contained), exp by
 * expf. The phase is d (opd nu) - d (decay gamma) turns, its fraction
 * taken in half: a film of 1000 nm at n_f 2.5 is 12 turns, where binary16
 * keeps 2^-7 of a turn. */
#include "internal.h"
#include "fresnel_film.h"

#if FRESNEL_HAS_F16

/* cos, sin of 2 pi r for r in [0, 1), in binary32 (errors below 4e-7) */
static void fresnel_i_film_cis_h(float r, float *co, float *si)
{
    float q4 = r * 4.0f;
    int32_t q = (int32_t)(q4 + 0.5f);
    float x = 6.28318530718f * (r - 0.25f * (float)q), x2 = x * x;
    float s = x * (1.0f - x2 * (1.0f / 6.0f - x2 * (1.0f / 120.0f - x2 * (1.0f / 5040.0f))));
    float c = 1.0f - x2 * (0.5f - x2 * (1.0f / 24.0f - x2 * (1.0f / 720.0f - x2 * (1.0f / 40320.0f))));
    switch ((uint32_t)q & 3u) {
    case 0: *co = c; *si = s; break;
    case 1: *co = -s; *si = c; break;
    case 2: *co = -c; *si = -s; break;
    default: *co = s; *si = -c; break;
    }
}

fresnel_rgb_f16 fresnel_film_f16_rgb(const fresnel_film_f16 *m, fresnel_f16 c_in, fresnel_f16 d_in)
{
    const fresnel_film_node_f16 *lo, *hi;
    fresnel_i_h zero = fresnel_i_hc(0.0f), one = fresnel_i_hc(1.0f);
    fresnel_i_h c = fresnel_i_hunit(c_in), d = fresnel_i_hclamp(d_in, zero, fresnel_i_hc(FRESNEL_FILM_D_MAX));
    fresnel_i_h pos, t, u, opd, decay, r[3];
    int i, j, ch;
    fresnel_rgb_f16 out;
    pos = fresnel_i_hmul(fresnel_i_hsqrt(c), fresnel_i_hc((float)(FRESNEL_FILM_NODES - 1)));
    i = (int)(float)pos;
    i = i > FRESNEL_FILM_NODES - 2 ? FRESNEL_FILM_NODES - 2 : i;
    t = fresnel_i_hsub(pos, fresnel_i_hc((float)i));
    u = fresnel_i_hsub(one, t);
    lo = &m->node[i];
    hi = &m->node[i + 1];
#define FRESNEL_I_FILM_LERP(field) fresnel_i_hadd(fresnel_i_hmul(u, lo->field), fresnel_i_hmul(t, hi->field))
    opd = FRESNEL_I_FILM_LERP(opd);
    decay = FRESNEL_I_FILM_LERP(decay);
    for (ch = 0; ch < 3; ch++)
        r[ch] = FRESNEL_I_FILM_LERP(a0[ch]);
    for (j = 0; j < FRESNEL_FILM_POLES; j++) {
        fresnel_i_h nu = m->freq[j], ga = m->damp[j];
        fresnel_i_h turns = fresnel_i_hsub(fresnel_i_hmul(d, fresnel_i_hmul(opd, nu)), fresnel_i_hmul(d, fresnel_i_hmul(decay, ga)));
        float whole = (float)(int32_t)(float)turns, cos_a, sin_a;
        fresnel_i_h frac = fresnel_i_hsub(turns, (fresnel_i_h)(whole > (float)turns ? whole - 1.0f : whole));
        fresnel_i_h w = fresnel_i_hmul(fresnel_i_hc(6.28318530718f),
                                       fresnel_i_hmul(d, fresnel_i_hadd(fresnel_i_hmul(opd, ga), fresnel_i_hmul(decay, nu))));
        fresnel_i_h mag = (fresnel_i_h)expf(-(float)w);
        fresnel_i_h a, b;
        fresnel_i_film_cis_h((float)frac, &cos_a, &sin_a);
        a = fresnel_i_hmul(mag, (fresnel_i_h)cos_a);
        b = fresnel_i_hmul(mag, (fresnel_i_h)sin_a);
        fresnel_i_h ar = FRESNEL_I_FILM_LERP(a_re[j]), ai = FRESNEL_I_FILM_LERP(a_im[j]);
        fresnel_i_h br = FRESNEL_I_FILM_LERP(b_re[j]), bi = FRESNEL_I_FILM_LERP(b_im[j]);
        fresnel_i_h pr = FRESNEL_I_FILM_LERP(p_re[j]), pi = FRESNEL_I_FILM_LERP(p_im[j]);
        fresnel_i_h qr = FRESNEL_I_FILM_LERP(q_re[j]), qi = FRESNEL_I_FILM_LERP(q_im[j]);
        /* zeta (A + B zeta) / (1 - P zeta + Q zeta^2) */
        fresnel_i_h z2r = fresnel_i_hsub(fresnel_i_hmul(a, a), fresnel_i_hmul(b, b));
        fresnel_i_h z2i = fresnel_i_hmul(fresnel_i_hc(2.0f), fresnel_i_hmul(a, b));
        fresnel_i_h sr = fresnel_i_hadd(ar, fresnel_i_hsub(fresnel_i_hmul(br, a), fresnel_i_hmul(bi, b)));
        fresnel_i_h si = fresnel_i_hadd(ai, fresnel_i_hadd(fresnel_i_hmul(br, b), fresnel_i_hmul(bi, a)));
        fresnel_i_h nr = fresnel_i_hsub(fresnel_i_hmul(a, sr), fresnel_i_hmul(b, si));
        fresnel_i_h ni = fresnel_i_hadd(fresnel_i_hmul(a, si), fresnel_i_hmul(b, sr));
        fresnel_i_h dr = fresnel_i_hadd(fresnel_i_hsub(one, fresnel_i_hsub(fresnel_i_hmul(pr, a), fresnel_i_hmul(pi, b))),
                                        fresnel_i_hsub(fresnel_i_hmul(qr, z2r), fresnel_i_hmul(qi, z2i)));
        fresnel_i_h di = fresnel_i_hadd(fresnel_i_hsub(zero, fresnel_i_hadd(fresnel_i_hmul(pr, b), fresnel_i_hmul(pi, a))),
                                        fresnel_i_hadd(fresnel_i_hmul(qr, z2i), fresnel_i_hmul(qi, z2r)));
        fresnel_i_h inv = fresnel_i_hdiv(one, fresnel_i_hadd(fresnel_i_hmul(dr, dr), fresnel_i_hmul(di, di)));
        fresnel_i_h fr = fresnel_i_hmul(fresnel_i_hadd(fresnel_i_hmul(nr, dr), fresnel_i_hmul(ni, di)), inv);
        fresnel_i_h fi = fresnel_i_hmul(fresnel_i_hsub(fresnel_i_hmul(ni, dr), fresnel_i_hmul(nr, di)), inv);
        for (ch = 0; ch < 3; ch++)
            r[ch] = fresnel_i_hadd(r[ch], fresnel_i_hsub(fresnel_i_hmul(m->weight[ch][j][0], fr),
                                                         fresnel_i_hmul(m->weight[ch][j][1], fi)));
    }
#undef FRESNEL_I_FILM_LERP
    out.r = fresnel_i_hunit(r[0]);
    out.g = fresnel_i_hunit(r[1]);
    out.b = fresnel_i_hunit(r[2]);
    return out;
}

#else
typedef int fresnel_i_film_f16_disabled; /* ISO C wants a declaration in every file */
#endif
