/* Integer square root, bit-by-bit division and reciprocal (public), and the
 * mantissa-exponent arithmetic and power function the fixed-point models
 * share (math_q15.h). 32-bit integers only: no int64, no division
 * instruction, no count-leading-zeros instruction (Cortex-M0 has none). */
#include "math_q15.h"

#if FRESNEL_HAS_Q15

/* Digit-by-digit square root (the binary form of the schoolbook method):
 * `bit` walks down the even powers of 4; root gains one bit per step.
 * *rem receives x - root^2, which fresnel_i_qf_sqrt uses to add 15 more bits. */
static uint32_t fresnel_i_isqrt_rem(uint32_t x, uint32_t *rem)
{
    uint32_t root = 0, bit = 1u << 30;
    while (bit > x)
        bit >>= 2;
    while (bit) {
        if (x >= root + bit) {
            x -= root + bit;
            root = (root >> 1) + bit;
        } else {
            root >>= 1;
        }
        bit >>= 2;
    }
    *rem = x;
    return root;
}

uint32_t fresnel_isqrt_u32(uint32_t x)
{
    uint32_t rem;
    return fresnel_i_isqrt_rem(x, &rem);
}

/* Restoring division. Invariant: n < 2d before each step, so 2n < 4d < 2^33
 * would overflow -- but after the compare-subtract n < d < 2^31, and n << 1
 * < 2^32. */
uint32_t fresnel_udiv_frac_u32(uint32_t n, uint32_t d, int k)
{
    uint32_t q = 0;
    int i;
    FRESNEL_I_RANGE("udiv d", d, 1, 0x7fffffffu);
    FRESNEL_I_RANGE("udiv n < 2d", n, 0, 2ull * d - 1);
    for (i = 0; i <= k; i++) {
        q <<= 1;
        if (n >= d) {
            n -= d;
            q |= 1u;
        }
        n <<= 1;
    }
    return q;
}

fresnel_q16 fresnel_recip_q16(fresnel_q16 x)
{
    uint32_t ux, n = 4;
    int j = 2;
    if (x <= 2)
        return 0x7fffffff; /* 2^32 / 2 = 2^31 does not fit; below 2 even less */
    if (x == 3)
        return 1431655765; /* round(2^32 / 3): the general path needs x >= 4 */
    ux = (uint32_t)x;
    /* n = 2^j with 2^j <= x < 2^(j+1): n < 2x as the divider needs, and
     * floor(2^j 2^(33-j) / x) = floor(2^33 / x) < 2^32 for x >= 4. */
    while ((n << 1) <= ux && j < 30) {
        n <<= 1;
        j++;
    }
    return (fresnel_q16)((fresnel_udiv_frac_u32(n, ux, 33 - j) + 1u) >> 1);
}

/* ---------------------------------------------------------------- fresnel_qf */

/* Normalise m 2^e to m in [2^30, 2^31) without a clz instruction: at most
 * one right shift (inputs from sums and products are < 2^32), or a binary
 * search of left shifts. */
fresnel_qf fresnel_i_qf(uint32_t m, int32_t e)
{
    fresnel_qf r;
    if (m == 0) {
        r.m = 0;
        r.e = 0;
        return r;
    }
    if (m >= 0x80000000u) {
        m >>= 1;
        e += 1;
    } else {
        if (m < (1u << 15)) {
            m <<= 16;
            e -= 16;
        }
        if (m < (1u << 23)) {
            m <<= 8;
            e -= 8;
        }
        if (m < (1u << 27)) {
            m <<= 4;
            e -= 4;
        }
        if (m < (1u << 29)) {
            m <<= 2;
            e -= 2;
        }
        if (m < (1u << 30)) {
            m <<= 1;
            e -= 1;
        }
    }
    r.m = m;
    r.e = e;
    return r;
}

/* The product a.m b.m / 2^30 rounded to 31 bits, from 16-bit halves:
 * a.m, b.m < 2^31 so ah, bh < 2^15, al, bl < 2^16. R: ah bh < 2^30,
 * ah bl + al bh < 2 (2^15 - 1)(2^16 - 1) < 2^32, + (al bl >> 16) < 2^32;
 * hi = floor(a.m b.m / 2^30) is in [2^30, 2^32). Rounded to nearest rather
 * than truncated: x^1000 is ten squarings, and a truncation's bias would
 * double with each. */
fresnel_qf fresnel_i_qf_mul(fresnel_qf a, fresnel_qf b)
{
    uint32_t ah, al, bh, bl, mid, hi;
    int32_t e = a.e + b.e + 30;
    if (a.m == 0 || b.m == 0)
        return fresnel_i_qf(0, 0);
    FRESNEL_I_RANGE("qf mul a", a.m, 1u << 30, 0x7fffffffu);
    FRESNEL_I_RANGE("qf mul b", b.m, 1u << 30, 0x7fffffffu);
    ah = a.m >> 16;
    al = a.m & 0xffffu;
    bh = b.m >> 16;
    bl = b.m & 0xffffu;
    mid = ah * bl + al * bh + ((al * bl) >> 16);
    hi = ((ah * bh) << 2) + (mid >> 14);
    if (hi >= 0x80000000u) /* 32 bits: keep 31, rounding on the bit shifted out */
        return fresnel_i_qf((hi >> 1) + (hi & 1u), e + 1);
    /* 31 bits: round on the next bit of the product, bit 13 of mid */
    return fresnel_i_qf(hi + ((mid >> 13) & 1u), e);
}

fresnel_qf fresnel_i_qf_add(fresnel_qf a, fresnel_qf b)
{
    int32_t d;
    if (b.m == 0)
        return a;
    if (a.m == 0)
        return b;
    if (a.e < b.e) {
        fresnel_qf t = a;
        a = b;
        b = t;
    }
    d = a.e - b.e;
    if (d > 31)
        return a;
    /* R: a.m + (b.m >> d) < 2^31 + 2^31 */
    return fresnel_i_qf(a.m + (b.m >> d), a.e);
}

fresnel_qf fresnel_i_qf_sub(fresnel_qf a, fresnel_qf b, int *negative)
{
    int32_t d;
    int neg = fresnel_i_qf_cmp(a, b) < 0;
    if (negative)
        *negative = neg;
    if (neg) {
        fresnel_qf t = a;
        a = b;
        b = t;
    }
    if (b.m == 0)
        return a;
    d = a.e - b.e; /* >= 0: a >= b and both normalised */
    if (d > 31)
        return a;
    /* Within one octave the difference can cancel to a few bits: form it
     * exactly at b's scale (a.m << 1 < 2^32). Further apart, a - b > a/2 and
     * the bits of b shifted out cost at most 2^-30 relative. */
    if (d == 0)
        return fresnel_i_qf(a.m - b.m, b.e);
    if (d == 1)
        return fresnel_i_qf((a.m << 1) - b.m, b.e);
    return fresnel_i_qf(a.m - (b.m >> d), a.e);
}

fresnel_qf fresnel_i_qf_div(fresnel_qf a, fresnel_qf b)
{
    uint32_t n = a.m;
    int32_t e = a.e - b.e - 30;
    if (a.m == 0 || b.m == 0)
        return fresnel_i_qf(0, 0); /* b == 0 is a caller bug; 0 keeps it harmless */
    if (n < b.m) {
        n <<= 1; /* R: < 2^32; now b.m <= n < 2 b.m */
        e -= 1;
    }
    /* 31 quotient bits: floor(n 2^30 / b.m) in [2^30, 2^31) */
    return fresnel_i_qf(fresnel_udiv_frac_u32(n, b.m, 30), e);
}

/* sqrt(m 2^e) with e made even: m in [2^30, 2^32), y = floor(sqrt(m)) in
 * [2^15, 2^16), r = m - y^2 <= 2y. One Newton step from y, sqrt(m) =
 * y + r/(2y) - r^2/(8 y^3) + ..., gives 15 more bits: the neglected term is
 * below 2^15 / (2y) <= 1/2 unit of the 31-bit result. */
fresnel_qf fresnel_i_qf_sqrt(fresnel_qf a)
{
    uint32_t m = a.m, y, r;
    int32_t e = a.e;
    if (m == 0)
        return a;
    if (e & 1) {
        m <<= 1; /* R: < 2^32 */
        e -= 1;
    }
    y = fresnel_i_isqrt_rem(m, &r);
    FRESNEL_I_RANGE("qf sqrt root", y, 1u << 15, 0xffffu);
    FRESNEL_I_RANGE("qf sqrt rem", r, 0, 2u * y);
    /* r <= 2y, so r / (2y) <= 1 as the divider needs; R: y 2^15 + 2^15 <= 2^31 */
    return fresnel_i_qf((y << 15) + fresnel_udiv_frac_u32(r, 2u * y, 15), e / 2 - 15);
}

uint32_t fresnel_i_qf_to_fix(fresnel_qf a, int32_t frac)
{
    int32_t s = a.e + frac;
    uint32_t sh;
    if (a.m == 0)
        return 0;
    if (s >= 0)
        return s == 0 ? a.m : (s == 1 ? a.m << 1 : 0xffffffffu); /* m >= 2^30: s >= 2 overflows */
    if (s < -31)
        return 0; /* < 2^31 2^-32 = 1/2 */
    sh = (uint32_t)-s;
    /* R: m + 2^(sh-1) < 2^31 + 2^30 */
    return (a.m + (1u << (sh - 1))) >> sh;
}

int fresnel_i_qf_cmp(fresnel_qf a, fresnel_qf b)
{
    if (a.m == 0 || b.m == 0)
        return a.m == b.m ? 0 : (a.m == 0 ? -1 : 1);
    if (a.e != b.e)
        return a.e < b.e ? -1 : 1;
    return a.m < b.m ? -1 : (a.m > b.m ? 1 : 0);
}

/* ------------------------------------------------------------- x^p, x in [0,1] */

/* log2 table: X in [2^14, 2^15) with top bits j (X >> 8 & 63) is scaled by
 * r_j = round(2^16 / (1 + (j + 1/2)/64)), so that X r_j = 2^30 (1 + d) with
 * |d| < 2^-7; fresnel_i_log2_t[j] = log2(2^16 / r_j) in Q30. Computed in double
 * (python: round(2**16/(1+(j+0.5)/64)), round(log2(2**16/r)*2**30));
 * tests/runtime/q15/test_q15_math.c recomputes every entry. */
const uint16_t fresnel_i_log2_r[64] = {
    65028u, 64035u, 63072u, 62138u, 61231u, 60350u, 59494u, 58662u, 57852u, 57065u,
    56299u, 55554u, 54828u, 54120u, 53431u, 52759u, 52103u, 51464u, 50840u, 50231u,
    49637u, 49056u, 48489u, 47935u, 47393u, 46864u, 46346u, 45839u, 45344u, 44859u,
    44384u, 43919u, 43464u, 43019u, 42582u, 42154u, 41734u, 41323u, 40920u, 40525u,
    40137u, 39756u, 39383u, 39017u, 38657u, 38304u, 37958u, 37617u, 37283u, 36954u,
    36631u, 36314u, 36003u, 35696u, 35395u, 35099u, 34808u, 34521u, 34239u, 33962u,
    33689u, 33421u, 33157u, 32897u,
};
const uint32_t fresnel_i_log2_t[64] = {
    12054435u, 35891922u, 59364972u, 82476057u, 105253946u, 127704248u,
    149833629u, 171649830u, 193188472u, 214406335u, 235340933u, 255976645u,
    276354057u, 296487800u, 316335725u, 335942035u, 355323909u, 374439572u,
    393336960u, 412005072u, 430432707u, 448671631u, 466680537u, 484481103u,
    502096316u, 519484371u, 536702111u, 553741596u, 570560589u, 587218838u,
    603709115u, 620024072u, 636156241u, 652098046u, 667914561u, 683563464u,
    699075096u, 714406203u, 729587679u, 744613578u, 759516468u, 774291347u,
    788893803u, 803357276u, 817716611u, 831927180u, 845983618u, 859962859u,
    873778528u, 887508914u, 901108335u, 914572235u, 927896003u, 941161769u,
    954279504u, 967288582u, 980185301u, 993010788u, 1005717116u, 1018300453u,
    1030802905u, 1043175314u, 1055460447u, 1067655421u,
};
/* exp2 table: round(2^30 2^(-j/64)), j = 0..63 (python: round(2**30*2**(-j/64))). */
const uint32_t fresnel_i_exp2_t[64] = {
    1073741824u, 1062175491u, 1050733751u, 1039415261u, 1028218693u, 1017142735u,
    1006186087u, 995347464u, 984625594u, 974019220u, 963527098u, 953147997u,
    942880699u, 932724001u, 922676710u, 912737649u, 902905651u, 893179563u,
    883558244u, 874040567u, 864625413u, 855311680u, 846098274u, 836984114u,
    827968132u, 819049271u, 810226483u, 801498734u, 792865000u, 784324269u,
    775875538u, 767517817u, 759250125u, 751071493u, 742980960u, 734977579u,
    727060411u, 719228525u, 711481005u, 703816941u, 696235434u, 688735596u,
    681316545u, 673977412u, 666717336u, 659535466u, 652430958u, 645402981u,
    638450708u, 631573326u, 624770026u, 618040012u, 611382493u, 604796689u,
    598281827u, 591837143u, 585461881u, 579155293u, 572916640u, 566745190u,
    560640218u, 554601009u, 548626854u, 542717053u,
};

#define FRESNEL_I_INV_LN2_M1_Q30 475340181u /* round((1/ln 2 - 1) 2^30) */
#define FRESNEL_I_LN2_Q20 726818u      /* round(2^20 ln 2) */

/* -log2(x / 2^15) in Q26 for x in [1, 2^15 - 1]; absolute error < 2^-25.
 * R: result in (0, 15] * 2^26 < 2^30. */
static uint32_t fresnel_i_neg_log2_q26(uint32_t x)
{
    uint32_t s = 0, j, ad, sq, cube, l1, corr;
    int32_t delta, lg;
    while (x < (1u << 14)) { /* at most 14 steps for a 15-bit x */
        x <<= 1;
        s++;
    }
    j = (x >> 8) & 63u;
    /* R: x < 2^15, r_j < 2^16: product < 2^31; |delta| < 2^-7 (< 2^23 in Q30) */
    delta = (int32_t)(x * fresnel_i_log2_r[j]) - (int32_t)(1u << 30);
    FRESNEL_I_RANGE("log2 delta", delta, -(1 << 23), 1 << 23);
    ad = (uint32_t)(delta < 0 ? -delta : delta);
    /* log2(1 + d) = (d - d^2/2 + d^3/3 - ...) / ln 2; |d|^4/4 < 2^-30.
     * R: (ad >> 8) < 2^15, its square < 2^30, d^2/2 in Q30 < 2^15;
     * (d^2/2)(ad >> 8) < 2^30, >> 22 is d^3/2 in Q30 (< 2^9), times 2/3
     * (43691 / 2^16) < 2^25 */
    sq = ((ad >> 8) * (ad >> 8)) >> 15;
    cube = ((((sq * (ad >> 8)) >> 22) * 43691u) >> 16);
    lg = delta - (int32_t)sq + (delta < 0 ? -(int32_t)cube : (int32_t)cube); /* Q30, |.| < 2^23 */
    l1 = (uint32_t)(lg < 0 ? -lg : lg);
    /* l1 / ln 2 = l1 + l1 (1/ln 2 - 1), the second factor below one so that
     * fresnel_i_mul_q30 keeps 30 bits. R: l1 < 2^23, result < 2^24 */
    corr = l1 + fresnel_i_mul_q30(l1, FRESNEL_I_INV_LN2_M1_Q30);
    /* log2(x/2^15) = -(s + 1) + T_j + log2(1+d); all in Q30, magnitude < 2^30
     * except (s+1), so the sum is formed in Q26. */
    {
        /* log2(X / 2^14) in [0, 1), in Q30; rounding can take it a hair
         * below 0 at X = 2^14 (clamped: no right shift of a negative int) */
        int32_t frac_q30 = (int32_t)fresnel_i_log2_t[j] + (lg < 0 ? -(int32_t)corr : (int32_t)corr);
        uint32_t frac_q26 = frac_q30 > 0 ? (uint32_t)frac_q30 >> 4 : 0u;
        return ((s + 1u) << 26) - frac_q26; /* R: (s+1) 2^26 <= 15 2^26; frac < 2^26 */
    }
}

/* 2^(-y) for y in Q26, y >= 0, as Q30 mantissa times 2^-n.
 * 2^-y = 2^-n 2^(-j/64) 2^(-h), h < 1/64: exp(-z) = 1 - z + z^2/2 - z^3/6
 * with z = h ln 2 < 0.011 (neglected z^4/24 < 2^-30). */
static fresnel_qf fresnel_i_exp2_neg_q26(uint32_t y)
{
    uint32_t n = y >> 26, g = y & ((1u << 26) - 1u), j = g >> 20, h = g & ((1u << 20) - 1u);
    uint32_t z, zr, z2, z3, p;
    /* z = h ln2 in Q30 = h ln2_q20 / 2^16, h split at 2^10.
     * R: (h >> 10) < 2^10, (h & 1023) < 2^10, times 726818 < 2^30 each */
    z = (((h >> 10) * FRESNEL_I_LN2_Q20) >> 6) + (((h & 1023u) * FRESNEL_I_LN2_Q20) >> 16);
    FRESNEL_I_RANGE("exp2 z", z, 0, 12000000);
    zr = z >> 8;                 /* R: < 2^16 (Q22) */
    z2 = (zr * zr) >> 15;        /* z^2/2 in Q30, R: < 2^17 */
    z3 = (((z2 * zr) >> 22) * 21845u) >> 16; /* z^3/6: R: z2 zr < 2^31 (z < 0.0109) */
    p = FRESNEL_I_ONE_Q30 - z + z2 - z3; /* R: (0.98, 1] * 2^30 */
    if (n > 60)
        return fresnel_i_qf(0, 0);
    return fresnel_i_qf(fresnel_i_mul_q30(fresnel_i_exp2_t[j], p), -30 - (int32_t)n);
}

fresnel_qf fresnel_i_pow_q15(uint32_t x, uint32_t p)
{
    fresnel_qf result, base;
    uint32_t k = p >> 16, f = p & 0xffffu;
    if (x == 0)
        return fresnel_i_qf(0, 0);
    if (x >= FRESNEL_I_ONE_Q15)
        return fresnel_i_qf(1u, 0);
    base = fresnel_i_qf(x, -15);
    result = fresnel_i_qf(1u, 0);
    /* integer part by repeated squaring: relative error < 2^-29 per product,
     * about 2 log2(k) of them */
    while (k) {
        if (k & 1u)
            result = fresnel_i_qf_mul(result, base);
        k >>= 1;
        if (k)
            base = fresnel_i_qf_mul(base, base);
    }
    if (f) {
        /* x^f = 2^(-f L), L = -log2 x in [0, 15]: y = f L in Q26, L split at
         * 2^16. R: f < 2^16, L >> 16 < 2^14, product < 2^30; f (L & 0xffff) < 2^32. */
        uint32_t l = fresnel_i_neg_log2_q26(x);
        uint32_t y = f * (l >> 16) + ((f * (l & 0xffffu)) >> 16);
        result = fresnel_i_qf_mul(result, fresnel_i_exp2_neg_q26(y));
    }
    return result;
}

#else
typedef int fresnel_i_math_q15_disabled; /* ISO C wants a declaration in every file */
#endif
