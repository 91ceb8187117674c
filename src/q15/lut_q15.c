/* Lookup tables of reflectance curves in fixed point (fresnel_q15.h):
 * linear interpolation at a position in Q15 node units, no division.
 *
 * The position: uniform in c, exact; uniform in sqrt(c), sqrt(c) (n-1) with
 * sqrt(c) the exact floor in Q30 (fresnel_i_sqrt_q30: two small tables and
 * two integer tests, no loop), rounded to a 15-bit fraction of a segment.
 * _u8 nodes are decoded to Q15 first (+-0.5 LSB); residual frac 14 (s16)
 * and 6 (s8) hold a residual of 1, the largest the generator's residual
 * nodes reach.
 *
 * The bound: the final rounding, 0.5 LSB, plus the position's error times
 * the table's steepest node-to-node change: half a position step, 2^-16 of
 * a segment (0.5 LSB for a two-node table spanning [0, 1]), and for nodes
 * uniform in sqrt(c) the floor of sqrt(c) in Q30, (n-1) 2^-30 of a segment.
 *
 * The cubic: the position of fresnel_lut_u16_q15, Catmull-Rom weights in Q15
 * (shared by the three channels of the _rgb form), a 4-term sum in Q30,
 * rounded and clamped; the weights' rounding to Q15 is what its bound
 * allows for on any table. */
#include "internal.h"

#if FRESNEL_HAS_Q15


/* Position of x (Q30, [0, 2^30]) along n nodes (1 <= n <= FRESNEL_I_LUT_N_MAX, as
 * fresnel_i_qlut_n gives it and the callers have checked n != 0),
 * as the node i before it (FRESNEL_I_NEXT the one after) and a 15-bit fraction, rounded to
 * nearest (a floor would cost up to one LSB on a steep two-node table).
 * R: n - 1 <= 2^15 - 1: (x >> 15)(n-1) < 2^30, (x & 0x7fff)(n-1) + 2^14 <
 * 2^31, and the position is at most (n-1) 2^15, index <= n - 1. x = 1 lands
 * on the last segment's end: index n - 2 with fraction 2^15. One node is a
 * constant curve: i = 0, t = 0. */
typedef struct fresnel_i_pos {
    int i;
    uint32_t t;
} fresnel_i_pos;

/* The node after i: i itself for a one-node table. */
#define FRESNEL_I_NEXT(p, n) ((p).i + ((n) > 1))

static fresnel_i_pos fresnel_i_position(uint32_t x, int n)
{
    fresnel_i_pos p;
    uint32_t nodes = (uint32_t)n - 1u, pos;
    FRESNEL_I_RANGE("lut n", n, 1, FRESNEL_I_LUT_N_MAX);
    p.i = 0;
    p.t = 0;
    if (nodes == 0)
        return p;
    pos = (x >> 15) * nodes + (((x & 0x7fffu) * nodes + (1u << 14)) >> 15);
    FRESNEL_I_RANGE("lut position", pos, 0, nodes << 15);
    p.i = (int)(pos >> 15);
    p.t = pos & 0x7fffu;
    if (p.i >= (int)nodes) {
        p.i = (int)nodes - 1;
        p.t = 1u << 15;
    }
    return p;
}

/* The tables of fresnel_i_sqrt_q30 (math_q15.h), here with their only
 * user: fresnel_i_sqrt_chord_q15[k] = floor(sqrt(c_k 2^15) 2^16) at
 * c_k = 2^13 + 256 k, k = 0..97 (python: math.isqrt((8192 + 256*k) << 47)),
 * and fresnel_i_rsqrt_chord_q15[k] = ceil(2^44 / sqrt(c_k 2^15)) at
 * c_k = 2^13 + 128 k, k = 0..193 (python: the least g with
 * g*g*c_k*2**15 >= 2**88); tests/runtime/q15/test_q15_math.c recomputes every entry. */
const uint32_t fresnel_i_sqrt_chord_q15[98] = {
    1073741824u, 1090389976u, 1106787738u, 1122946078u, 1138875187u, 1154584552u,
    1170083025u, 1185378877u, 1200479854u, 1215393219u, 1230125796u, 1244684004u,
    1259073893u, 1273301168u, 1287371221u, 1301289153u, 1315059792u, 1328687718u,
    1342177280u, 1355532606u, 1368757628u, 1381856085u, 1394831545u, 1407687407u,
    1420426919u, 1433053184u, 1445569170u, 1457977717u, 1470281544u, 1482483260u,
    1494585365u, 1506590260u, 1518500249u, 1530317550u, 1542044293u, 1553682528u,
    1565234230u, 1576701301u, 1588085574u, 1599388817u, 1610612736u, 1621758977u,
    1632829133u, 1643824740u, 1654747283u, 1665598201u, 1676378885u, 1687090680u,
    1697734891u, 1708312781u, 1718825574u, 1729274458u, 1739660584u, 1749985070u,
    1760249000u, 1770453427u, 1780599375u, 1790687838u, 1800719781u, 1810696144u,
    1820617841u, 1830485761u, 1840300768u, 1850063706u, 1859775393u, 1869436629u,
    1879048192u, 1888610839u, 1898125312u, 1907592330u, 1917012596u, 1926386797u,
    1935715601u, 1944999662u, 1954239617u, 1963436090u, 1972589688u, 1981701005u,
    1990770622u, 1999799107u, 2008787013u, 2017734884u, 2026643249u, 2035512627u,
    2044343526u, 2053136442u, 2061891861u, 2070610259u, 2079292101u, 2087937843u,
    2096547933u, 2105122807u, 2113662894u, 2122168614u, 2130640378u, 2139078591u,
    2147483648u, 2155855935u,
};
const uint32_t fresnel_i_rsqrt_chord_q15[194] = {
    1073741824u, 1065450258u, 1057347857u, 1049427537u, 1041682578u, 1034106604u,
    1026693558u, 1019437682u, 1012333500u, 1005375799u, 998559614u, 991880210u,
    985333075u, 978913898u, 972618567u, 966443148u, 960383884u, 954437177u,
    948599586u, 942867814u, 937238702u, 931709222u, 926276469u, 920937655u,
    915690105u, 910531246u, 905458609u, 900469819u, 895562590u, 890734724u,
    885984105u, 881308694u, 876706529u, 872175715u, 867714429u, 863320910u,
    858993460u, 854730439u, 850530264u, 846391406u, 842312387u, 838291780u,
    834328203u, 830420321u, 826566842u, 822766515u, 819018128u, 815320511u,
    811672526u, 808073073u, 804521087u, 801015531u, 797555405u, 794139734u,
    790767576u, 787438014u, 784150158u, 780903145u, 777696137u, 774528319u,
    771398899u, 768307107u, 765252196u, 762233438u, 759250125u, 756301570u,
    753387102u, 750506070u, 747657840u, 744841793u, 742057328u, 739303859u,
    736580815u, 733887640u, 731223793u, 728588743u, 725981977u, 723402992u,
    720851298u, 718326417u, 715827883u, 713355241u, 710908046u, 708485865u,
    706088274u, 703714862u, 701365223u, 699038964u, 696735699u, 694455052u,
    692196656u, 689960150u, 687745184u, 685551414u, 683378504u, 681226125u,
    679093957u, 676981685u, 674889000u, 672815604u, 670761200u, 668725502u,
    666708225u, 664709096u, 662727842u, 660764200u, 658817909u, 656888717u,
    654976373u, 653080634u, 651201261u, 649338021u, 647490683u, 645659022u,
    643842819u, 642041856u, 640255923u, 638484810u, 636728315u, 634986237u,
    633258380u, 631544552u, 629844564u, 628158230u, 626485369u, 624825802u,
    623179354u, 621545854u, 619925132u, 618317022u, 616721363u, 615137993u,
    613566757u, 612007500u, 610460070u, 608924319u, 607400100u, 605887271u,
    604385689u, 602895217u, 601415717u, 599947056u, 598489103u, 597041727u,
    595604801u, 594178201u, 592761802u, 591355485u, 589959130u, 588572621u,
    587195841u, 585828677u, 584471019u, 583122757u, 581783782u, 580453989u,
    579133273u, 577821531u, 576518662u, 575224567u, 573939147u, 572662307u,
    571393950u, 570133984u, 568882316u, 567638856u, 566403514u, 565176203u,
    563956835u, 562745326u, 561541592u, 560345549u, 559157115u, 557976212u,
    556802759u, 555636679u, 554477894u, 553326329u, 552181910u, 551044562u,
    549914212u, 548790791u, 547674227u, 546564450u, 545461393u, 544364987u,
    543275166u, 542191864u, 541115017u, 540044561u, 538980433u, 537922571u,
    536870912u, 535825399u,
};

/* sqrt(c) in Q30 (fresnel_lut_*: nodes uniform in sqrt(c), as lut.c): with
 * c the Q15 code, the exact floor(sqrt(c 2^45)) (fresnel_i_sqrt_q30).
 * Fifteen bits would not do: the position sqrt(c) (n-1) must keep 15
 * fraction bits for 1024 nodes, and the floor costs at most (n-1) 2^-30 of
 * a node (2^-20 for n <= 1024). */
static uint32_t fresnel_i_sqrt_w(int32_t c) { return fresnel_i_sqrt_q30(fresnel_i_q15_arg(c)); }

/* c in Q30 for linear spacing. */
static uint32_t fresnel_i_linear_w(int32_t c) { return fresnel_i_q15_arg(c) << 15; }

/* Interpolate two values v0, v1 <= 2^16 - 1 with a 15-bit fraction: the
 * result is scaled by 2^15 (Q30 for Q15 values). R: v0 2^15 < 2^31,
 * |v1 - v0| t < 2^31; the sum is a convex combination in [0, 2^31), so the
 * uint32 arithmetic, modulo 2^32 where v1 < v0, gives it exactly (and no
 * branch on the direction of the segment). */
static uint32_t fresnel_i_lerp_q30(uint32_t v0, uint32_t v1, uint32_t t)
{
    return (v0 << 15) + (v1 - v0) * t;
}

/* round(v / 255) for v <= 255 2^15 without a division: (n 257) >> 16 with
 * n = v + 127 is n / 255.0039, so floor(n / 255) or one less, and the
 * remainder test settles it. R: n 257 <= (255 2^15 + 127) 257 < 2^31. */
static uint32_t fresnel_i_div255_round(uint32_t v)
{
    uint32_t n = v + 127u, q = (n * 257u) >> 16;
    if (n - q * 255u >= 255u)
        q++;
    return q;
}

/* A curve's result rounded from Q30 and held to [0, max(one, the nodes
 * interpolated)]: uint16_t nodes carry values up to 2 - 2^-15 (the
 * generator's keep policy), and a table whose nodes are all in [0, one]
 * gives results in [0, one]. R: v < 2^32 - 2^14. */
static fresnel_q15 fresnel_i_curve_q15(uint32_t v, uint32_t a, uint32_t b)
{
    uint32_t hi = a > b ? a : b, r = (v + (1u << 14)) >> 15;
    if (hi < FRESNEL_I_ONE_Q15)
        hi = FRESNEL_I_ONE_Q15;
    return (fresnel_q15)(r < hi ? r : hi);
}

/* Channel ch (0 for the scalar forms) of a table of n nodes per channel,
 * n as fresnel_i_qlut_n gives it: 0 reads nothing. */
static fresnel_q15 fresnel_i_lut_u16(const uint16_t *table, int n, int ch, uint32_t x)
{
    fresnel_i_pos p;
    if (n == 0)
        return 0;
    table += ch * n;
    p = fresnel_i_position(x, n);
    return fresnel_i_curve_q15(fresnel_i_lerp_q30(table[p.i], table[FRESNEL_I_NEXT(p, n)], p.t), table[p.i],
                               table[FRESNEL_I_NEXT(p, n)]);
}

/* uint8 nodes mean v / 255: interpolated in units of 2^-15 / 255 (the lerp
 * of the raw codes, <= 255 2^15) and divided by 255 once, so the encoding
 * adds no rounding of its own. */
static fresnel_q15 fresnel_i_lut_u8(const uint8_t *table, int n, int ch, uint32_t x)
{
    fresnel_i_pos p;
    if (n == 0)
        return 0;
    table += ch * n;
    p = fresnel_i_position(x, n);
    return (fresnel_q15)fresnel_i_div255_round(fresnel_i_lerp_q30(table[p.i], table[FRESNEL_I_NEXT(p, n)], p.t));
}

/* Signed residual nodes v0, v1 (|v| <= 2^15) scaled by 2^-frac, interpolated
 * and brought to Q30. R: v0 2^15 and (v1 - v0) t are each < 2^31 in
 * magnitude (|v1 - v0| <= 2^16 - 1, t <= 2^15) and their sum is the convex
 * combination, |.| <= 2^30, so the signed addition cannot overflow. The
 * value is in units of 2^-(frac + 15); Q30 needs a shift by frac - 15, to
 * the left by at most 1 (s16, frac 14: |.| <= 2^31) or 9 (s8, frac 6,
 * |v| <= 2^22: |.| <= 2^31), in uint32. The result is held to
 * [-2^30, 2^30 - 1]: Schlick is in [0, 2^30], so a residual of -2^30 or less
 * gives zero and one of 2^30 - 1 or more one (2^30 - 1 rounds to one), and
 * Schlick plus the residual stays inside int32. */
static int32_t fresnel_i_residual_q30(int32_t v0, int32_t v1, uint32_t t, int frac)
{
    int32_t v = v0 * 32768 + (v1 - v0) * (int32_t)t;
    uint32_t mag = (uint32_t)(v < 0 ? -v : v);
    int sh = frac - 15;
    FRESNEL_I_RANGE("lut residual", v, -(1 << 30), 1 << 30);
    if (sh > 0)
        mag = (mag + (1u << (sh - 1))) >> sh;
    else if (sh < 0)
        mag <<= -sh;
    if (mag > FRESNEL_I_ONE_Q30 - (v < 0 ? 0u : 1u))
        mag = FRESNEL_I_ONE_Q30 - (v < 0 ? 0u : 1u);
    return v < 0 ? -(int32_t)mag : (int32_t)mag;
}

/* Schlick (Q30) plus a residual (Q30, in [-2^30, 2^30 - 1]), clamped and
 * rounded. R: the sum is in [-2^30, 2^31 - 1]. */
static fresnel_q15 fresnel_i_plus_schlick(int32_t f0, int32_t c, int32_t residual)
{
    uint32_t s = fresnel_i_schlick_q30(fresnel_i_q15_arg(f0), fresnel_i_pow5_q30(FRESNEL_I_ONE_Q15 - fresnel_i_q15_arg(c)));
    return fresnel_i_q30s_to_q15((int32_t)s + residual);
}

static int fresnel_i_frac(int frac, int lo, int hi) { return frac < lo ? lo : (frac > hi ? hi : frac); }

/* Residual tables: no node (n = 0) is a zero residual, Schlick alone. */
static fresnel_q15 fresnel_i_lut_s16(int32_t f0, const int16_t *table, int n, int ch, int frac, uint32_t x, int32_t c)
{
    fresnel_i_pos p;
    if (n == 0)
        return fresnel_i_plus_schlick(f0, c, 0);
    table += ch * n;
    p = fresnel_i_position(x, n);
    return fresnel_i_plus_schlick(f0, c, fresnel_i_residual_q30(table[p.i], table[FRESNEL_I_NEXT(p, n)], p.t, fresnel_i_frac(frac, 14, 30)));
}

static fresnel_q15 fresnel_i_lut_s8(int32_t f0, const int8_t *table, int n, int ch, int frac, uint32_t x, int32_t c)
{
    fresnel_i_pos p;
    if (n == 0)
        return fresnel_i_plus_schlick(f0, c, 0);
    table += ch * n;
    p = fresnel_i_position(x, n);
    return fresnel_i_plus_schlick(f0, c, fresnel_i_residual_q30(table[p.i], table[FRESNEL_I_NEXT(p, n)], p.t, fresnel_i_frac(frac, 6, 22)));
}

/* Catmull-Rom weights in Q15 for a fraction t in [0, 2^15], s = 1 - t:
 *   w0 = -t s^2/2, w3 = -t^2 s/2, w2 = t + t s (3t - 1)/2, w1 = 1 - w0 - w2 - w3
 * (w1 = s + t s (3s - 1)/2 up to rounding: taking it from the sum keeps a
 * constant table constant). The negative weights are kept as magnitudes.
 * R: t s <= 2^28 -> ts <= 2^13; ts s, ts t <= 2^28; 3 ts t <= 3 2^28. */
typedef struct fresnel_i_cubic_w {
    int32_t w0, w1, w2, w3; /* w0, w3: magnitudes of the negative weights */
} fresnel_i_cubic_w;

static fresnel_i_cubic_w fresnel_i_cubic_weights(uint32_t t)
{
    fresnel_i_cubic_w w;
    uint32_t s = FRESNEL_I_ONE_Q15 - t, ts = (t * s + (1u << 14)) >> 15;
    w.w0 = (int32_t)((ts * s + (1u << 15)) >> 16);
    w.w3 = (int32_t)((ts * t + (1u << 15)) >> 16);
    w.w2 = (int32_t)(t + ((3u * ts * t + (1u << 15)) >> 16)) - (int32_t)((ts + 1u) >> 1);
    w.w1 = (int32_t)FRESNEL_I_ONE_Q15 + w.w0 + w.w3 - w.w2;
    return w;
}

/* The outer nodes repeat the end ones (index clamped to [0, n-1]). The
 * positive and negative terms are summed apart in uint32: w1, w2 >= 0 and
 * w1 + w2 <= 1.125 2^15 + 2, node values < 2^16, so the positive sum is
 * below 2.5 10^9 < 2^32 - 2^14 and the negative one below 2^29; a negative
 * total is 0.
 * The result is held as fresnel_i_curve_q15 holds it (the cubic may pass
 * its two nodes; it is kept to [0, max(one, v1, v2)]). */
static fresnel_q15 fresnel_i_cubic_u16(const uint16_t *table, int n, int ch, fresnel_i_pos p, fresnel_i_cubic_w w)
{
    int last = n - 1;
    uint32_t v0, v1, v2, v3, pos, neg;
    table += ch * n;
    v0 = table[p.i > 0 ? p.i - 1 : 0];
    v1 = table[p.i];
    v2 = table[FRESNEL_I_NEXT(p, n)];
    v3 = table[FRESNEL_I_NEXT(p, n) + 1 <= last ? FRESNEL_I_NEXT(p, n) + 1 : last];
    FRESNEL_I_RANGE("cubic weight w1", w.w1, 0, 37000);
    FRESNEL_I_RANGE("cubic weight w2", w.w2, 0, 37000);
    pos = (uint32_t)w.w1 * v1 + (uint32_t)w.w2 * v2;
    neg = (uint32_t)w.w0 * v0 + (uint32_t)w.w3 * v3;
    return neg >= pos ? 0 : fresnel_i_curve_q15(pos - neg, v1, v2);
}

fresnel_q15 fresnel_lut_cubic_u16_q15(const uint16_t *table, int n_in, int32_t c)
{
    int n = fresnel_i_qlut_n(n_in);
    fresnel_i_pos p;
    if (n == 0)
        return 0;
    p = fresnel_i_position(fresnel_i_sqrt_w(c), n);
    return fresnel_i_cubic_u16(table, n, 0, p, fresnel_i_cubic_weights(p.t));
}

fresnel_rgb_q15 fresnel_lut_cubic_u16_q15_rgb(const uint16_t *table, int n_in, int32_t c)
{
    int n = fresnel_i_qlut_n(n_in);
    fresnel_i_pos p;
    fresnel_i_cubic_w w;
    if (n == 0)
        FRESNEL_I_RGB_Q15(0, 0, 0);
    p = fresnel_i_position(fresnel_i_sqrt_w(c), n);
    w = fresnel_i_cubic_weights(p.t);
    FRESNEL_I_RGB_Q15(fresnel_i_cubic_u16(table, n, 0, p, w), fresnel_i_cubic_u16(table, n, 1, p, w), fresnel_i_cubic_u16(table, n, 2, p, w));
}

fresnel_q15 fresnel_lut_u16_q15(const uint16_t *table, int n, int32_t c)
{
    return fresnel_i_lut_u16(table, fresnel_i_qlut_n(n), 0, fresnel_i_sqrt_w(c));
}
fresnel_q15 fresnel_lut_linear_u16_q15(const uint16_t *table, int n, int32_t c)
{
    return fresnel_i_lut_u16(table, fresnel_i_qlut_n(n), 0, fresnel_i_linear_w(c));
}
fresnel_q15 fresnel_lut_u8_q15(const uint8_t *table, int n, int32_t c)
{
    return fresnel_i_lut_u8(table, fresnel_i_qlut_n(n), 0, fresnel_i_sqrt_w(c));
}
fresnel_q15 fresnel_lut_linear_u8_q15(const uint8_t *table, int n, int32_t c)
{
    return fresnel_i_lut_u8(table, fresnel_i_qlut_n(n), 0, fresnel_i_linear_w(c));
}
fresnel_q15 fresnel_lut_residual_s16_q15(int32_t f0, const int16_t *table, int n, int frac, int32_t c)
{
    return fresnel_i_lut_s16(f0, table, fresnel_i_qlut_n(n), 0, frac, fresnel_i_sqrt_w(c), c);
}
fresnel_q15 fresnel_lut_linear_residual_s16_q15(int32_t f0, const int16_t *table, int n, int frac, int32_t c)
{
    return fresnel_i_lut_s16(f0, table, fresnel_i_qlut_n(n), 0, frac, fresnel_i_linear_w(c), c);
}
fresnel_q15 fresnel_lut_residual_s8_q15(int32_t f0, const int8_t *table, int n, int frac, int32_t c)
{
    return fresnel_i_lut_s8(f0, table, fresnel_i_qlut_n(n), 0, frac, fresnel_i_sqrt_w(c), c);
}
fresnel_q15 fresnel_lut_linear_residual_s8_q15(int32_t f0, const int8_t *table, int n, int frac, int32_t c)
{
    return fresnel_i_lut_s8(f0, table, fresnel_i_qlut_n(n), 0, frac, fresnel_i_linear_w(c), c);
}

/* RGB: n red nodes, then n green, then n blue (n as fresnel_i_qlut_n gives it). */
fresnel_rgb_q15 fresnel_lut_u16_q15_rgb(const uint16_t *table, int n, int32_t c)
{
    uint32_t x = fresnel_i_sqrt_w(c);
    n = fresnel_i_qlut_n(n);
    FRESNEL_I_RGB_Q15(fresnel_i_lut_u16(table, n, 0, x), fresnel_i_lut_u16(table, n, 1, x), fresnel_i_lut_u16(table, n, 2, x));
}
fresnel_rgb_q15 fresnel_lut_linear_u16_q15_rgb(const uint16_t *table, int n, int32_t c)
{
    uint32_t x = fresnel_i_linear_w(c);
    n = fresnel_i_qlut_n(n);
    FRESNEL_I_RGB_Q15(fresnel_i_lut_u16(table, n, 0, x), fresnel_i_lut_u16(table, n, 1, x), fresnel_i_lut_u16(table, n, 2, x));
}
fresnel_rgb_q15 fresnel_lut_u8_q15_rgb(const uint8_t *table, int n, int32_t c)
{
    uint32_t x = fresnel_i_sqrt_w(c);
    n = fresnel_i_qlut_n(n);
    FRESNEL_I_RGB_Q15(fresnel_i_lut_u8(table, n, 0, x), fresnel_i_lut_u8(table, n, 1, x), fresnel_i_lut_u8(table, n, 2, x));
}
fresnel_rgb_q15 fresnel_lut_linear_u8_q15_rgb(const uint8_t *table, int n, int32_t c)
{
    uint32_t x = fresnel_i_linear_w(c);
    n = fresnel_i_qlut_n(n);
    FRESNEL_I_RGB_Q15(fresnel_i_lut_u8(table, n, 0, x), fresnel_i_lut_u8(table, n, 1, x), fresnel_i_lut_u8(table, n, 2, x));
}
fresnel_rgb_q15 fresnel_lut_residual_s16_q15_rgb(fresnel_rgb_q15 f0, const int16_t *table, int n, int frac,
                                                 int32_t c)
{
    uint32_t x = fresnel_i_sqrt_w(c);
    n = fresnel_i_qlut_n(n);
    FRESNEL_I_RGB_Q15(fresnel_i_lut_s16(f0.r, table, n, 0, frac, x, c), fresnel_i_lut_s16(f0.g, table, n, 1, frac, x, c),
                fresnel_i_lut_s16(f0.b, table, n, 2, frac, x, c));
}
fresnel_rgb_q15 fresnel_lut_linear_residual_s16_q15_rgb(fresnel_rgb_q15 f0, const int16_t *table, int n,
                                                        int frac, int32_t c)
{
    uint32_t x = fresnel_i_linear_w(c);
    n = fresnel_i_qlut_n(n);
    FRESNEL_I_RGB_Q15(fresnel_i_lut_s16(f0.r, table, n, 0, frac, x, c), fresnel_i_lut_s16(f0.g, table, n, 1, frac, x, c),
                fresnel_i_lut_s16(f0.b, table, n, 2, frac, x, c));
}
fresnel_rgb_q15 fresnel_lut_residual_s8_q15_rgb(fresnel_rgb_q15 f0, const int8_t *table, int n, int frac,
                                                int32_t c)
{
    uint32_t x = fresnel_i_sqrt_w(c);
    n = fresnel_i_qlut_n(n);
    FRESNEL_I_RGB_Q15(fresnel_i_lut_s8(f0.r, table, n, 0, frac, x, c), fresnel_i_lut_s8(f0.g, table, n, 1, frac, x, c),
                fresnel_i_lut_s8(f0.b, table, n, 2, frac, x, c));
}
fresnel_rgb_q15 fresnel_lut_linear_residual_s8_q15_rgb(fresnel_rgb_q15 f0, const int8_t *table, int n,
                                                       int frac, int32_t c)
{
    uint32_t x = fresnel_i_linear_w(c);
    n = fresnel_i_qlut_n(n);
    FRESNEL_I_RGB_Q15(fresnel_i_lut_s8(f0.r, table, n, 0, frac, x, c), fresnel_i_lut_s8(f0.g, table, n, 1, frac, x, c),
                fresnel_i_lut_s8(f0.b, table, n, 2, frac, x, c));
}

#else
typedef int fresnel_i_lut_q15_disabled;
#endif
