/* Integer square root, bit-by-bit division and reciprocal of the fixed-point
 * runtime, exhaustively where that is feasible; the mantissa-exponent
 * operations and the power function against double; the power function's
 * tables recomputed from their definitions. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>

#include "q15/internal.h"
#include "harness.h"

/* A small deterministic generator, so that failures reproduce. */
static uint32_t rng_state = 0x12345678u;
static uint32_t rng(void)
{
    rng_state ^= rng_state << 13;
    rng_state ^= rng_state >> 17;
    rng_state ^= rng_state << 5;
    return rng_state;
}

static void check_isqrt(void)
{
    uint32_t x, k, bad = 0, first = 0;
    /* every x < 2^24 */
    for (x = 0; x < (1u << 24); x++) {
        uint32_t r = fresnel_isqrt_u32(x);
        if (!(r * r <= x && (r + 1) * (r + 1) > x) && bad++ == 0)
            first = x;
    }
    CHECK("isqrt: every x < 2^24", bad == 0, "%u wrong, first x = %u", bad, first);
    /* floor(sqrt) steps only at perfect squares: both sides of every step
     * k^2 for k < 2^16, and the top of the range */
    bad = 0;
    for (k = 1; k < 65536; k++) {
        uint32_t sq = k * k;
        if (fresnel_isqrt_u32(sq) != k || fresnel_isqrt_u32(sq - 1) != k - 1 ||
            (k < 65535 && fresnel_isqrt_u32(sq + 2 * k) != k))
            if (bad++ == 0)
                first = k;
    }
    if (fresnel_isqrt_u32(0xffffffffu) != 65535u)
        bad++;
    CHECK("isqrt: k^2 - 1, k^2, (k+1)^2 - 1 for every k < 2^16, and 2^32 - 1", bad == 0, "%u wrong, first k = %u",
          bad, first);
    bad = 0;
    for (k = 0; k < 10000000u; k++) {
        uint32_t v = rng();
        uint64_t r = fresnel_isqrt_u32(v);
        if (!(r * r <= v && (r + 1) * (r + 1) > v) && bad++ == 0)
            first = v;
    }
    CHECK("isqrt: 10^7 random x", bad == 0, "%u wrong, first x = %u", bad, first);
}

static int udiv_ok(uint32_t n, uint32_t d, int k)
{
    return fresnel_udiv_frac_u32(n, d, k) == (uint32_t)(((uint64_t)n << k) / d);
}

static void check_udiv(void)
{
    static const int ks[] = {0, 15, 31};
    uint32_t n, d, bad = 0, fn = 0, fd = 0, i;
    int ik, k;
    for (ik = 0; ik < 3; ik++)
        for (d = 1; d < 4096; d++)
            for (n = 0; n < 2 * d; n++)
                if (!udiv_ok(n, d, ks[ik]) && bad++ == 0)
                    fn = n, fd = d;
    CHECK("udiv: every (n, d), d < 2^12, n < 2d, k = 0, 15, 31", bad == 0, "%u wrong, first %u/%u", bad, fn, fd);
    bad = 0;
    for (i = 0; i < 10000000u; i++) {
        d = (rng() >> 1) | 1u;
        d >>= rng() % 31;
        if (d == 0)
            d = 1;
        n = (uint32_t)(((uint64_t)rng() * (2ull * d)) >> 32);
        k = (int)(rng() % 32);
        if (!udiv_ok(n, d, k) && bad++ == 0)
            fn = n, fd = d;
    }
    CHECK("udiv: 10^7 random (n, d, k)", bad == 0, "%u wrong, first %u/%u", bad, fn, fd);
}

static int recip_ok(int32_t x)
{
    /* round(2^32 / x) = floor((2^33 / x + 1) / 2) */
    uint64_t want = (((1ull << 33) / (uint64_t)x) + 1) >> 1;
    if (want > 0x7fffffffu)
        want = 0x7fffffffu;
    return fresnel_recip_q16(x) == (int32_t)want;
}

static void check_recip(void)
{
    int32_t x;
    uint32_t bad = 0, i;
    int32_t first = 0;
    for (x = 1; x < (1 << 24); x++)
        if (!recip_ok(x) && bad++ == 0)
            first = x;
    for (i = 0; i < 10000000u; i++) {
        x = (int32_t)(rng() >> 1);
        if (x > 0 && !recip_ok(x) && bad++ == 0)
            first = x;
    }
    CHECK("recip_q16: every x < 2^24 and 10^7 random x, round(2^32 / x)", bad == 0, "%u wrong, first x = %d", bad,
          (int)first);
    CHECK("recip_q16 saturates at and below 2", fresnel_recip_q16(2) == 0x7fffffff && fresnel_recip_q16(0) == 0x7fffffff &&
          fresnel_recip_q16(-5) == 0x7fffffff, "recip(2) = %d", (int)fresnel_recip_q16(2));
}

static double qv(fresnel_qf a) { return ldexp((double)a.m, a.e); }

static int normalised(fresnel_qf a) { return a.m == 0 || (a.m >= (1u << 30) && a.m < (1u << 31)); }

/* The mantissa-exponent operations: relative error below 2^-29 against
 * double on random operands spanning 2^-40 .. 2^40. */
static void check_qf(void)
{
    double worst[6] = {0, 0, 0, 0, 0, 0};
    static const char *const names[6] = {"mul", "add", "sub", "div", "sqrt", "to_fix"};
    uint32_t i, denorm = 0;
    int j;
    for (i = 0; i < 2000000u; i++) {
        fresnel_qf a = fresnel_i_qf(rng() >> (rng() % 32), (int32_t)(rng() % 81) - 40 - 15);
        fresnel_qf b = fresnel_i_qf(rng() >> (rng() % 32), (int32_t)(rng() % 81) - 40 - 15);
        double da = qv(a), db = qv(b), r[6], e[6];
        fresnel_qf res[5];
        int neg;
        if (a.m == 0 || b.m == 0)
            continue;
        res[0] = fresnel_i_qf_mul(a, b);
        res[1] = fresnel_i_qf_add(a, b);
        res[2] = fresnel_i_qf_sub(a, b, &neg);
        res[3] = fresnel_i_qf_div(a, b);
        res[4] = fresnel_i_qf_sqrt(a);
        r[0] = da * db;
        r[1] = da + db;
        r[2] = fabs(da - db);
        r[3] = da / db;
        r[4] = sqrt(da);
        for (j = 0; j < 5; j++) {
            denorm += !normalised(res[j]);
            /* sub: relative to the larger operand, where cancellation is exact */
            e[j] = fabs(qv(res[j]) - r[j]) / (j == 2 ? (da > db ? da : db) : r[j]);
        }
        denorm += neg != (da < db);
        /* to_fix at a scale that keeps the result below 2^31 */
        {
            int32_t frac = 30 - a.e - 31;
            uint32_t fx = fresnel_i_qf_to_fix(a, frac);
            r[5] = ldexp(da, frac);
            e[5] = fabs(fx - r[5]) <= 0.5 ? 0.0 : 1.0;
        }
        for (j = 0; j < 6; j++)
            if (e[j] > worst[j])
                worst[j] = e[j];
    }
    for (j = 0; j < 6; j++)
        NOTE("qf %-6s max relative error %.3g (2^%.1f)", names[j], worst[j], worst[j] > 0 ? log2(worst[j]) : -99.0);
    CHECK("qf results normalised, sub's sign right", denorm == 0, "%u", denorm);
    CHECK("qf mul, add, sub, div, sqrt within 2^-29 relative, to_fix rounds to nearest",
          worst[0] <= 0x1p-29 && worst[1] <= 0x1p-29 && worst[2] <= 0x1p-29 && worst[3] <= 0x1p-29 &&
              worst[4] <= 0x1p-29 && worst[5] == 0.0,
          "mul %.3g add %.3g sub %.3g div %.3g sqrt %.3g to_fix %.3g", worst[0], worst[1], worst[2], worst[3],
          worst[4], worst[5]);
}

/* The power function's tables against their definitions, and x^p for every
 * x code against pow() in double: relative error below 2^-21 (the repeated
 * squaring of x^1000 costs about 1000 2^-30), below 2^-24 for p <= 64. */
static void check_pow(void)
{
    static const double ps[] = {0.001, 0.1, 0.25, 0.5, 0.9999, 1.0, 1.5, 2.0, 3.7, 5.0, 6.7850, 8.0, 13.3686, 20.5,
                                40.0, 99.9, 1000.0};
    int j, bad = 0;
    size_t ip;
    double worst = 0.0, worst64 = 0.0, wp = 0, wx = 0;
    for (j = 0; j < 64; j++) {
        double r = floor(65536.0 / (1.0 + (j + 0.5) / 64.0) + 0.5);
        bad += fresnel_i_log2_r[j] != (uint16_t)r;
        bad += fresnel_i_log2_t[j] != (uint32_t)floor(log2(65536.0 / r) * 1073741824.0 + 0.5);
        bad += fresnel_i_exp2_t[j] != (uint32_t)floor(1073741824.0 * exp2(-j / 64.0) + 0.5);
    }
    CHECK("pow tables equal their definitions", bad == 0, "%d entries differ", bad);
    for (ip = 0; ip < sizeof ps / sizeof ps[0]; ip++) {
        uint32_t p = (uint32_t)floor(ps[ip] * 65536.0 + 0.5), x;
        double pd = p / 65536.0;
        for (x = 0; x <= 32768u; x++) {
            double want = pow(x / 32768.0, pd), got = qv(fresnel_i_pow_q15(x, p));
            double err = want > 0 ? fabs(got - want) / want : fabs(got);
            if (want < 1e-300)
                continue; /* below double's range the qf value is still meaningful, the comparison is not */
            if (err > worst)
                worst = err, wp = pd, wx = x / 32768.0;
            if (pd <= 64.0 && err > worst64)
                worst64 = err;
        }
    }
    NOTE("pow: max relative error %.3g (2^%.1f) at x %.6f p %g; for p <= 64: %.3g (2^%.1f)", worst, log2(worst), wx,
         wp, worst64, log2(worst64));
    CHECK("pow: p <= 64 (the materials' alpha): relative error < 2^-24", worst64 < 0x1p-24, "%.3g", worst64);
    CHECK("pow: every x code, p in [0.001, 1000]: relative error < 2^-21", worst < 0x1p-21, "%.3g", worst);
}

/* floor(sqrt(v)) for v < 2^62, in 64-bit integers. */
static uint64_t isqrt64(uint64_t v)
{
    uint64_t r = (uint64_t)sqrt((double)v);
    while (r * r > v)
        r--;
    while ((r + 1) * (r + 1) <= v)
        r++;
    return r;
}

/* fresnel_i_sqrt_q30 (the LUTs' sqrt(c) in Q30): its tables against their
 * definitions, the table's chord against 2^44 / sqrt(c 2^15) (never below,
 * at most 2^-15.4 above: the root's comment counts on both) for every
 * normalised c, and the root against floor(sqrt(c 2^45)) for every c. */
static void check_sqrt_q30(void)
{
    uint32_t c, k, bad = 0, first = 0;
    double worst = 0.0;
    for (k = 0; k < 194; k++) {
        /* g = ceil(2^44 / sqrt(c_k 2^15)), c_k 2^15 = D 2^22 with D = 64 + k: the least g with
         * g^2 >= n = ceil(2^66 / D), n from 2^63 / D in 64-bit integers */
        uint64_t d = 64u + k, g = fresnel_i_rsqrt_chord_q15[k], r = ((1ull << 63) % d) * 8u;
        uint64_t n = ((1ull << 63) / d) * 8u + r / d + (r % d != 0);
        bad += !(g * g >= n && (g - 1) * (g - 1) < n);
    }
    for (k = 0; k < 98; k++)
        bad += fresnel_i_sqrt_chord_q15[k] != isqrt64((uint64_t)(8192u + 256u * k) << 47);
    CHECK("sqrt_q30 tables equal their definitions", bad == 0, "%u entries differ", bad);
    bad = 0;
    for (c = 8192; c <= 32768u; c++) {
        const uint32_t *t = fresnel_i_rsqrt_chord_q15 + ((c >> 7) - 64u);
        uint32_t g = t[0] - (((t[0] - t[1]) * (c & 127u)) >> 7);
        double rel = g * sqrt((double)c * 32768.0) / 0x1p44 - 1.0;
        bad += rel < 0.0;
        if (rel > worst)
            worst = rel;
    }
    NOTE("sqrt_q30: the table's chord is up to 2^%.2f above 2^44 / sqrt(c 2^15)", log2(worst));
    CHECK("sqrt_q30: chord never below, at most 2^-15.4 above", bad == 0 && worst <= 0x1.8p-16,
          "%u below, worst 2^%.2f", bad, log2(worst));
    bad = 0;
    for (c = 0; c <= 32768u; c++)
        if (fresnel_i_sqrt_q30(c) != isqrt64((uint64_t)c << 45) && bad++ == 0)
            first = c;
    CHECK("sqrt_q30: floor(sqrt(c 2^45)) for every c in [0, 2^15]", bad == 0, "%u wrong, first c = %u", bad, first);
}

int main(void)
{
    check_isqrt();
    check_udiv();
    check_recip();
    check_qf();
    check_pow();
    check_sqrt_q30();
    return harness_exit();
}
