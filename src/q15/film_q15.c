/* Thin-film iridescence in Q1.15 (fresnel_film.h): the pole form of the
 * Airy sum of src/f32/film.c in 32-bit integers, for cores without an FPU.
 * No float, no division instruction (reciprocals from a table), no int64
 * (the two 64-bit products are formed from 16-bit halves), no libm.
 *
 * Formats (the generator fills the table in them, gen/3_encode/film_encode.c):
 * c Q15, d Q16.16 nm; node values a0 Q14, opd and decay Q12, A, B
 * Q15 (|A| + |B| < 1), P Q14 (|P| < 2), Q Q15 (|Q| < 1); poles' turn_*
 * 2^32 turns per nm of path,
 * octave_* 2^32 octaves of decay per nm (2 pi log2(e) nu, gamma); weights
 * Q12. Products of signed values are shifted with fresnel_i_film_asr. */
#include "internal.h"
#include "fresnel_film.h"

#if FRESNEL_HAS_Q15

/* floor(x / 2^s), 0 <= s <= 31: the arithmetic shift. C99 leaves the
 * right shift of a negative number to the implementation; gcc and clang
 * define it as this (their manuals, "Integers implementation"), and the
 * check below stops a build where a compiler does otherwise. One ASRS on
 * a Cortex-M0, where the portable form (a bias of 2^31 added and taken
 * away again) costs five instructions and this file shifts about 150
 * signed values per call. */
typedef char fresnel_i_film_asr_check[((-5) >> 1) == -3 && ((int32_t)-1 >> 31) == -1 ? 1 : -1];
#if defined(__GNUC__)
#define FRESNEL_I_FILM_INLINE static inline __attribute__((always_inline))
#else
#define FRESNEL_I_FILM_INLINE static inline
#endif
FRESNEL_I_FILM_INLINE int32_t fresnel_i_film_asr(int32_t x, int s)
{
    return x >> s;
}

/* a + (b - a) t / 2^15, rounded, t in [0, 2^15]. R: |b - a| <= 65535,
 * times t <= 2^15 plus 2^14 < 2^31. */
FRESNEL_I_FILM_INLINE int32_t fresnel_i_film_lerp(int32_t a, int32_t b, int32_t t)
{
    return a + fresnel_i_film_asr((b - a) * t + (1 << 14), 15);
}

/* floor(x n / 2^15) mod 2^32 (turns of a phase: only the fraction counts),
 * from 16-bit halves; carries above bit 47 fall out with the modulus. */
static inline uint32_t fresnel_i_film_turns(uint32_t x, uint32_t n)
{
    uint32_t xl = x & 0xffffu, xh = x >> 16, nl = n & 0xffffu, nh = n >> 16;
    return ((xh * nh) << 17) + ((xl * nh + xh * nl) << 1) + ((xl * nl) >> 15);
}

/* x n / 2^31 for x < 2^32, n < 2^27 (octaves of decay, Q16), the three
 * partial products each shifted: low by up to 3 units of 2^-16 octave. */
static inline uint32_t fresnel_i_film_octaves(uint32_t x, uint32_t n)
{
    uint32_t xl = x & 0xffffu, xh = x >> 16, nl = n & 0xffffu, nh = n >> 16;
    return ((xh * nh) << 1) + ((xl * nh) >> 15) + ((xh * nl) >> 15) + ((xl * nl) >> 31);
}

/* round(32768 sin(pi/2 i/256)), i = 0..256 (python: round(32768 *
 * math.sin(math.pi / 2 * i / 256))); tests/runtime/thin_film/test_film.c recomputes them. */
const uint16_t fresnel_i_film_sin_q15[257] = {
    0, 201, 402, 603, 804, 1005, 1206, 1407, 1608, 1809, 2009, 2210,
    2411, 2611, 2811, 3012, 3212, 3412, 3612, 3812, 4011, 4211, 4410, 4609,
    4808, 5007, 5205, 5404, 5602, 5800, 5998, 6195, 6393, 6590, 6787, 6983,
    7180, 7376, 7571, 7767, 7962, 8157, 8351, 8546, 8740, 8933, 9127, 9319,
    9512, 9704, 9896, 10088, 10279, 10469, 10660, 10850, 11039, 11228, 11417, 11605,
    11793, 11980, 12167, 12354, 12540, 12725, 12910, 13095, 13279, 13463, 13646, 13828,
    14010, 14192, 14373, 14553, 14733, 14912, 15091, 15269, 15447, 15624, 15800, 15976,
    16151, 16326, 16500, 16673, 16846, 17018, 17190, 17361, 17531, 17700, 17869, 18037,
    18205, 18372, 18538, 18703, 18868, 19032, 19195, 19358, 19520, 19681, 19841, 20001,
    20160, 20318, 20475, 20632, 20788, 20943, 21097, 21251, 21403, 21555, 21706, 21856,
    22006, 22154, 22302, 22449, 22595, 22740, 22884, 23028, 23170, 23312, 23453, 23593,
    23732, 23870, 24008, 24144, 24279, 24414, 24548, 24680, 24812, 24943, 25073, 25202,
    25330, 25457, 25583, 25708, 25833, 25956, 26078, 26199, 26320, 26439, 26557, 26674,
    26791, 26906, 27020, 27133, 27246, 27357, 27467, 27576, 27684, 27791, 27897, 28002,
    28106, 28209, 28311, 28411, 28511, 28610, 28707, 28803, 28899, 28993, 29086, 29178,
    29269, 29359, 29448, 29535, 29622, 29707, 29792, 29875, 29957, 30038, 30118, 30196,
    30274, 30350, 30425, 30499, 30572, 30644, 30715, 30784, 30853, 30920, 30986, 31050,
    31114, 31177, 31238, 31298, 31357, 31415, 31471, 31527, 31581, 31634, 31686, 31737,
    31786, 31834, 31881, 31927, 31972, 32015, 32058, 32099, 32138, 32177, 32214, 32251,
    32286, 32319, 32352, 32383, 32413, 32442, 32470, 32496, 32522, 32546, 32568, 32590,
    32610, 32629, 32647, 32664, 32679, 32693, 32706, 32718, 32729, 32738, 32746, 32753,
    32758, 32762, 32766, 32767, 32768,
};
/* round(32768 2^(-i/64)), i = 0..64 */
const uint16_t fresnel_i_film_exp2_q15[65] = {
    32768, 32415, 32066, 31720, 31379, 31041, 30706, 30376, 30048, 29725, 29405, 29088,
    28774, 28464, 28158, 27855, 27554, 27258, 26964, 26674, 26386, 26102, 25821, 25543,
    25268, 24995, 24726, 24460, 24196, 23936, 23678, 23423, 23170, 22921, 22674, 22430,
    22188, 21949, 21713, 21479, 21247, 21019, 20792, 20568, 20347, 20127, 19911, 19696,
    19484, 19274, 19066, 18861, 18658, 18457, 18258, 18061, 17867, 17674, 17484, 17296,
    17109, 16925, 16743, 16562, 16384,
};
/* round(32768 / (1 + i/256)), i = 0..256 */
const uint16_t fresnel_i_film_recip_q15[257] = {
    32768, 32640, 32514, 32388, 32264, 32140, 32018, 31896, 31775, 31655, 31536, 31418,
    31301, 31184, 31069, 30954, 30840, 30728, 30615, 30504, 30394, 30284, 30175, 30067,
    29959, 29853, 29747, 29642, 29537, 29434, 29331, 29229, 29127, 29026, 28926, 28827,
    28728, 28630, 28533, 28436, 28340, 28244, 28150, 28056, 27962, 27869, 27777, 27685,
    27594, 27504, 27414, 27324, 27236, 27148, 27060, 26973, 26887, 26801, 26715, 26631,
    26546, 26462, 26379, 26297, 26214, 26133, 26052, 25971, 25891, 25811, 25732, 25653,
    25575, 25497, 25420, 25343, 25267, 25191, 25116, 25041, 24966, 24892, 24818, 24745,
    24672, 24600, 24528, 24457, 24385, 24315, 24245, 24175, 24105, 24036, 23967, 23899,
    23831, 23764, 23697, 23630, 23564, 23498, 23432, 23367, 23302, 23237, 23173, 23109,
    23046, 22982, 22920, 22857, 22795, 22733, 22672, 22611, 22550, 22490, 22429, 22370,
    22310, 22251, 22192, 22134, 22075, 22017, 21960, 21902, 21845, 21789, 21732, 21676,
    21620, 21565, 21509, 21454, 21400, 21345, 21291, 21237, 21183, 21130, 21077, 21024,
    20972, 20919, 20867, 20815, 20764, 20713, 20662, 20611, 20560, 20510, 20460, 20410,
    20361, 20311, 20262, 20214, 20165, 20117, 20068, 20021, 19973, 19925, 19878, 19831,
    19784, 19738, 19692, 19645, 19600, 19554, 19508, 19463, 19418, 19373, 19329, 19284,
    19240, 19196, 19152, 19108, 19065, 19022, 18979, 18936, 18893, 18851, 18809, 18766,
    18725, 18683, 18641, 18600, 18559, 18518, 18477, 18437, 18396, 18356, 18316, 18276,
    18236, 18197, 18157, 18118, 18079, 18040, 18001, 17963, 17924, 17886, 17848, 17810,
    17772, 17735, 17697, 17660, 17623, 17586, 17549, 17513, 17476, 17440, 17404, 17368,
    17332, 17296, 17261, 17225, 17190, 17155, 17120, 17085, 17050, 17015, 16981, 16947,
    16913, 16878, 16845, 16811, 16777, 16744, 16710, 16677, 16644, 16611, 16578, 16546,
    16513, 16481, 16448, 16416, 16384,
};

/* sin(pi/2 u / 2^16) in Q15 for u in [0, 2^16], linear between the table's
 * nodes (error below 5e-6, plus the rounding). */
static inline int32_t fresnel_i_film_quarter_sin(uint32_t u)
{
    uint32_t i = u >> 8, f = u & 255u;
    int32_t a = fresnel_i_film_sin_q15[i];
    return f ? a + fresnel_i_film_asr((fresnel_i_film_sin_q15[i + 1] - a) * (int32_t)f + 128, 8) : a;
}

fresnel_rgb_q15 fresnel_film_q15_rgb(const fresnel_film_q15 *m, int32_t c_in, fresnel_q16 d_in)
{
    const fresnel_film_node_q15 *lo, *hi;
    uint32_t c = fresnel_i_q15_arg(c_in), pos, d, x, y, opd, decay;
    int32_t t, zc[FRESNEL_FILM_POLES], zs[FRESNEL_FILM_POLES], acc[3];
    int32_t fr[FRESNEL_FILM_POLES], fi[FRESNEL_FILM_POLES], split[FRESNEL_FILM_POLES][4];
    int i, j, ch;
    fresnel_rgb_q15 out;
    d = d_in <= 0 ? 0u : (d_in >= FRESNEL_FILM_D_MAX_Q16 ? (uint32_t)FRESNEL_FILM_D_MAX_Q16 : (uint32_t)d_in);
    /* nodes uniform in sqrt(c): sqrt(c) Q30 (lut_q15.c's exact root) to Q15 */
    pos = ((fresnel_i_sqrt_q30(c) + (1u << 14)) >> 15) * (FRESNEL_FILM_NODES - 1);
    i = (int)(pos >> 15);
    t = (int32_t)(pos & 0x7fffu);
    if (i > FRESNEL_FILM_NODES - 2) {
        i = FRESNEL_FILM_NODES - 2;
        t = 32768;
    }
    lo = &m->node[i];
    hi = &m->node[i + 1];
    /* optical path in Q15 nm: d (<= 5000 2^16) times opd (Q12, < 16) / 2^13,
     * < 80000 2^15 < 2^32; from d's 16-bit halves */
    opd = (uint32_t)fresnel_i_film_lerp(lo->opd, hi->opd, t);
    decay = (uint32_t)fresnel_i_film_lerp(lo->decay, hi->decay, t);
    x = (((d >> 16) * opd) << 3) + (((d & 0xffffu) * opd) >> 13);
    y = decay ? (((d >> 16) * decay) << 3) + (((d & 0xffffu) * decay) >> 13) : 0u;

    for (j = 0; j < FRESNEL_FILM_POLES; j++) {
        /* zeta_j = 2^-octaves (cos, sin)(2 pi turns) */
        uint32_t turns = fresnel_i_film_turns(x, m->turn_nu[j]);
        uint32_t oct = fresnel_i_film_octaves(x, m->octave_gamma[j]), k, u;
        int32_t mag, s_u, c_u, sn, cs;
        if (y) {
            turns -= fresnel_i_film_turns(y, m->turn_gamma[j]);
            oct += fresnel_i_film_octaves(y, m->octave_nu[j]);
        }
        k = oct >> 16;
        if (k >= 16) {
            zc[j] = zs[j] = 0;
            continue;
        }
        {
            uint32_t f = oct & 0xffffu, e = f >> 10, g = f & 1023u;
            int32_t a = fresnel_i_film_exp2_q15[e];
            mag = (a - fresnel_i_film_asr((a - fresnel_i_film_exp2_q15[e + 1]) * (int32_t)g + 512, 10)) >> k;
        }
        u = (turns >> 14) & 0xffffu;
        s_u = fresnel_i_film_quarter_sin(u);
        c_u = fresnel_i_film_quarter_sin(65536u - u);
        switch (turns >> 30) {
        case 0: sn = s_u; cs = c_u; break;
        case 1: sn = c_u; cs = -s_u; break;
        case 2: sn = -s_u; cs = -c_u; break;
        default: sn = -c_u; cs = s_u; break;
        }
        zc[j] = fresnel_i_film_asr(cs * mag + (1 << 14), 15);
        zs[j] = fresnel_i_film_asr(sn * mag + (1 << 14), 15);
    }

    for (j = 0; j < FRESNEL_FILM_POLES; j++) {
        /* F = zeta (A + B zeta) / (1 - P zeta + Q zeta^2) in Q20 */
        int32_t a = zc[j], b = zs[j], ar, ai, br, bi, pr, pi, qr, qi, z2r, z2i, dr, di, sr, si, nr, ni;
        int32_t mag, sh, e2, r, xr, xi, out_r, out_i;
        uint32_t dd, ad, bd;
        fr[j] = fi[j] = 0;
        if ((a | b) == 0)
            continue;
        ar = fresnel_i_film_lerp(lo->a_re[j], hi->a_re[j], t);
        ai = fresnel_i_film_lerp(lo->a_im[j], hi->a_im[j], t);
        br = fresnel_i_film_lerp(lo->b_re[j], hi->b_re[j], t);
        bi = fresnel_i_film_lerp(lo->b_im[j], hi->b_im[j], t);
        pr = fresnel_i_film_lerp(lo->p_re[j], hi->p_re[j], t);
        pi = fresnel_i_film_lerp(lo->p_im[j], hi->p_im[j], t);
        qr = fresnel_i_film_lerp(lo->q_re[j], hi->q_re[j], t);
        qi = fresnel_i_film_lerp(lo->q_im[j], hi->q_im[j], t);
        /* zeta^2 in Q15. R: |zeta| <= 1, each part below 2^30 */
        z2r = fresnel_i_film_asr(a * a - b * b + (1 << 14), 15);
        z2i = fresnel_i_film_asr(a * b + (1 << 13), 14);
        /* den = 1 - P zeta + Q zeta^2 in Q28: P zeta Q29 (P Q14, |P| < 2),
         * Q zeta^2 Q30; |den| < 4 */
        dr = (1 << 28) - fresnel_i_film_asr(pr * a - pi * b, 1) + fresnel_i_film_asr(qr * z2r - qi * z2i, 2);
        di = -fresnel_i_film_asr(pr * b + pi * a, 1) + fresnel_i_film_asr(qr * z2i + qi * z2r, 2);
        /* num = zeta (A + B zeta) in Q15 (|A| + |B| < 1) */
        sr = ar + fresnel_i_film_asr(br * a - bi * b + (1 << 14), 15);
        si = ai + fresnel_i_film_asr(br * b + bi * a + (1 << 14), 15);
        nr = fresnel_i_film_asr(a * sr - b * si + (1 << 14), 15);
        ni = fresnel_i_film_asr(a * si + b * sr + (1 << 14), 15);
        /* den to 15 bits: den >> sh, the larger part in [2^14, 2^15) */
        ad = (uint32_t)(dr < 0 ? -dr : dr);
        bd = (uint32_t)(di < 0 ? -di : di);
        dd = ad | bd;
        sh = 0;
        if (dd >= (1u << 23)) { dd >>= 8; sh += 8; }
        if (dd >= (1u << 19)) { dd >>= 4; sh += 4; }
        if (dd >= (1u << 17)) { dd >>= 2; sh += 2; }
        if (dd >= (1u << 15)) { dd >>= 1; sh += 1; }
        if (dd >= (1u << 15)) { dd >>= 1; sh += 1; }
        if (dd < (1u << 7)) { dd <<= 8; sh -= 8; }
        if (dd < (1u << 11)) { dd <<= 4; sh -= 4; }
        if (dd < (1u << 13)) { dd <<= 2; sh -= 2; }
        if (dd < (1u << 14)) { dd <<= 1; sh -= 1; }
        if (sh > 0) {
            dr = fresnel_i_film_asr(dr, sh);
            di = fresnel_i_film_asr(di, sh);
        } else {
            dr *= 1 << -sh;
            di *= 1 << -sh;
        }
        /* |den_n|^2 in [2^28, 2^31), to [2^29, 2^30) by e2; r = 2^44 / that, Q15 of 1/v */
        dd = (uint32_t)(dr * dr) + (uint32_t)(di * di);
        e2 = 0;
        if (dd >= (1u << 30)) { dd >>= 1; e2 = 1; }
        if (dd < (1u << 29)) { dd <<= 1; e2 = -1; }
        {
            int32_t g = (int32_t)((dd >> 13) & 255u), x = (int32_t)((dd >> 21) & 255u);
            int32_t ra = fresnel_i_film_recip_q15[x];
            r = ra - fresnel_i_film_asr((ra - fresnel_i_film_recip_q15[x + 1]) * g + 128, 8);
        }
        /* num conj(den_n) (|.| < 2^30.5), times r / 2^15 from 15-bit halves;
         * F = that 2^(4 - e2 - sh) in Q20 */
        xr = nr * dr + ni * di;
        xi = ni * dr - nr * di;
        out_r = fresnel_i_film_asr(xr, 15) * r + fresnel_i_film_asr((xr & 0x7fff) * r, 15);
        out_i = fresnel_i_film_asr(xi, 15) * r + fresnel_i_film_asr((xi & 0x7fff) * r, 15);
        mag = 4 - e2 - sh;
        if (mag >= 0) {
            /* saturate: |F| is below 2^10 for the generator's tables */
            int32_t lim = 0x3fffffff >> mag;
            out_r = out_r > lim ? lim : (out_r < -lim ? -lim : out_r);
            out_i = out_i > lim ? lim : (out_i < -lim ? -lim : out_i);
            fr[j] = out_r * (1 << mag);
            fi[j] = out_i * (1 << mag);
        } else {
            fr[j] = fresnel_i_film_asr(out_r, -mag);
            fi[j] = fresnel_i_film_asr(out_i, -mag);
        }
    }

    /* R = a0 + sum_j Re(w_j F_j): w Q12 times F Q20, F split into its top
     * bits (F >> 15, below 2^15) and low 15 bits, whose products with w
     * (below 2^30) are summed at 2^-3 of their scale; Q17. One channel at a
     * time, the poles inside: few values live at once (a Cortex-M0 has
     * eight low registers). */
    for (j = 0; j < FRESNEL_FILM_POLES; j++) {
        split[j][0] = fresnel_i_film_asr(fr[j], 15);
        split[j][1] = fresnel_i_film_asr(fi[j], 15);
        split[j][2] = fr[j] & 0x7fff;
        split[j][3] = fi[j] & 0x7fff;
    }
    for (ch = 0; ch < 3; ch++) {
        const int16_t *w = m->weight[ch][0];
        int32_t high = fresnel_i_film_lerp(lo->a0[ch], hi->a0[ch], t) * 8, low = 0;
        for (j = 0; j < FRESNEL_FILM_POLES; j++, w += 2) {
            high += split[j][0] * w[0] - split[j][1] * w[1];
            low += fresnel_i_film_asr(split[j][2] * w[0] - split[j][3] * w[1], 3);
        }
        high = fresnel_i_film_asr(high + fresnel_i_film_asr(low, 12) + 2, 2);
        acc[ch] = high < 0 ? 0 : (high > 32768 ? 32768 : high);
    }
    out.r = (fresnel_q15)acc[0];
    out.g = (fresnel_q15)acc[1];
    out.b = (fresnel_q15)acc[2];
    return out;
}

#else
typedef int fresnel_i_film_q15_disabled;
#endif
