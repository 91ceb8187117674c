/* WHERE PRECISION IS LOST, AND WHY NOT HERE
 *
 * The textbook forms of the Fresnel equations are written for real numbers.
 * Evaluated in binary32 (ulp(1) = 1.2e-7) some of them subtract nearly equal
 * numbers, divide by a vanishing one or overflow, and lose digits where the
 * physics is perfectly tame. This test implements each textbook form in
 * binary32 next to the runtime's and measures both against the double
 * reference (gen/common/reference.c) on the inputs where the textbook form breaks.
 * It asserts that the runtime stays within its documented FRESNEL_BOUND_*
 * while the textbook form is outside that bound, so neither half can pass by
 * accident: a case whose textbook form comes within the bound shows nothing,
 * and the test says so. `build/tests/test_precision`
 * prints the table (NOTE lines); the numbers below are from that run.
 *
 *  where                               textbook form (binary32)                     max |err|    runtime   bound
 *  kappa >> eta, conductor              2a^2 = sqrt(A^2 + 4 eta^2 kappa^2) + A,      gold red 0.17+3.5i: 6.1e-7   1.9e-7   4e-7
 *   (A = eta^2 - kappa^2 - sin^2)       a^2 cancels when A << 0                      silver 0.05+4i:     2.3e-6   2.2e-7
 *                                                                                    0.17+1000i:         6.8e-6   2.1e-7
 *  near the critical angle              w^2 = eta^2 - sin^2, sin^2 = 1 - c^2          eta 0.9999:         2.7e-2   1.2e-7
 *  eta ~ n1 near grazing                the same w^2 = eta^2 - (1 - c^2)             eta 1.0001:         3.6e-5   2.0e-7
 *                                       (conductor form, kappa 1e-3)                 eta 1.0001+1e-3i:   4.5e-6   2.5e-7
 *  c -> 0                               Rp = Rs (.. - 2a sin tan + sin^2 tan^2)/(..) NaN for c < 1e-19 and at c = 0
 *  Gulbrandsen k, r -> 1, g -> 0        k^2 = (r(n+1)^2 - (n-1)^2)/(1 - r)            r 0.9999:           1.1e-5   2.7e-7
 *  Cook-Torrance, F'(1) -> 1            (F'(c) - F'(1))/(1 - F'(1))                  kappa 10:           2.3e-5   1.6e-7
 *                                                                                    kappa 100:          1.8e-3   0
 *  generalized Schlick, large p         powf(1 - c, p): p times the rounding of 1-c  p 40:               1.2e-6   8.5e-8
 *  F0 in a medium, F0 -> 1              ((sqrt F0 - s)/(1 - sqrt F0 s))^2             F0 0.999997:        9.0e-6   4.1e-7
 *
 *  (FRESNEL_BOUND_F0_IN_MEDIUM, 5.3e-7, is measured near F0 = 1, where this
 *      case lies.)
 *
 * Why the runtime does not lose them (see src/f32/exact.c, src/f32/internal.h):
 *   - eta^2 - kappa^2 - sin^2 is (eta^2 + c^2 - 1) - kappa^2 with eta^2 and
 *     c^2 formed exactly and their sum's rounding carried: no 1 - c^2, and
 *     correct to a rounding of itself near the critical angle and at eta ~ 1;
 *   - of u^2, v^2 (a^2, b^2) only the larger comes from (m +- A)/2, a sum of
 *     positives; the smaller from u v = eta kappa;
 *   - Rp from the complex form ((P-u)^2 + (Q-v)^2)/((P+u)^2 + (Q+v)^2), which
 *     has no tan theta, so c = 0 is an ordinary input;
 *   - Gulbrandsen's k^2 is factored so no large terms are subtracted;
 *   - Cook-Torrance's ratio is T'(c)/T'(1) of two transmittances computed
 *     directly (sums of non-negative terms), not 1 - F' twice;
 *   - (1-c)^p as exp(p log1p(-c)).
 */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "fresnel.h"
#include "fresnel_f16.h"
#include "fresnel_fixed.h"
#include "harness.h"
#include "common/reference.h"

/* ---- the textbook forms, in binary32 ---- */

/* Conductor reflectance as printed in most references and shader code
 * (a^2, b^2 from the square root of A^2 + 4 eta^2 kappa^2; Rp from Rs and
 * tan theta). */
static float textbook_conductor(float eta, float kappa, float c)
{
    float s2 = 1.0f - c * c;
    float t = eta * eta - kappa * kappa - s2;
    float m = sqrtf(t * t + 4.0f * eta * eta * kappa * kappa);
    float a2 = 0.5f * (m + t), b2 = 0.5f * (m - t);
    float a = sqrtf(a2 > 0.0f ? a2 : 0.0f);
    float rs = (a2 + b2 - 2.0f * a * c + c * c) / (a2 + b2 + 2.0f * a * c + c * c);
    float sn = sqrtf(s2), tn = sn / c;
    float rp = rs * (a2 + b2 - 2.0f * a * sn * tn + s2 * tn * tn) / (a2 + b2 + 2.0f * a * sn * tn + s2 * tn * tn);
    return 0.5f * (rs + rp);
}

/* Dielectric reflectance with the transmitted cosine from 1 - c^2. */
static float textbook_dielectric(float eta, float c)
{
    float w2 = eta * eta - (1.0f - c * c), w, rs, rp;
    if (w2 < 0.0f)
        return 1.0f;
    w = sqrtf(w2);
    rs = (c - w) / (c + w);
    rp = (eta * eta * c - w) / (eta * eta * c + w);
    return 0.5f * (rs * rs + rp * rp);
}

/* Gulbrandsen's mapping as printed in the paper, then the same approximate
 * conductor the runtime uses, so only the mapping differs. */
static float textbook_gulbrandsen(float r, float g, float c)
{
    float sr = sqrtf(r), nmin = (1.0f - r) / (1.0f + r), nmax = (1.0f + sr) / (1.0f - sr);
    float n = g * nmin + (1.0f - g) * nmax;
    float k2 = (r * (n + 1.0f) * (n + 1.0f) - (n - 1.0f) * (n - 1.0f)) / (1.0f - r);
    return fresnel_approx_conductor(n, k2 > 0.0f ? sqrtf(k2) : 0.0f, c);
}

/* Hoffman's Cook-Torrance interpolant as written, on the runtime's own F'. */
static float textbook_cook_torrance(float f0, float eta, float kappa, float c)
{
    float f1 = fresnel_conductor(eta, kappa, 1.0f), fc = fresnel_conductor(eta, kappa, c);
    float t = (fc - f1) / (1.0f - f1);
    float r = f0 + (1.0f - f0) * (t > 0.0f ? t : 0.0f);
    return r < 1.0f ? r : 1.0f;
}

static float textbook_schlick_gen(float f0, float f90, float p, float c)
{
    return f0 + (f90 - f0) * powf(1.0f - c, p);
}

static float textbook_f0_in_medium(float f0, float eta_e)
{
    float r = sqrtf(f0), s = (eta_e - 1.0f) / (eta_e + 1.0f), q = (r - s) / (1.0f - r * s);
    return q * q;
}

/* ---- measuring ---- */

typedef struct measure {
    double textbook, runtime; /* max |err| */
    long textbook_nan;
    float at; /* cosine (or the swept input) of the textbook's maximum */
} measure;

static void take(measure *m, float textbook, float runtime, double ref, float at)
{
    double et = fabs((double)textbook - ref), er = fabs((double)runtime - ref);
    if (textbook != textbook)
        m->textbook_nan++;
    else if (et > m->textbook) {
        m->textbook = et;
        m->at = at;
    }
    if (!(er <= m->runtime))
        m->runtime = er; /* NaN from the runtime would stick here and fail */
}

/* Cosines from lo to hi, uniform (or geometric when geometric != 0). */
static float sweep(float lo, float hi, int i, int n, int geometric)
{
    return geometric ? (float)(lo * pow((double)hi / lo, (double)i / n)) : (float)(lo + (hi - lo) * (double)i / n);
}

/* One row of the table and its two assertions: runtime within `bound`,
 * textbook outside it (by max |err| or by NaN). */
static void report(const char *where, const measure *m, double bound, const char *bound_name)
{
    char name[256];
    char nan[40] = "";
    if (m->textbook_nan)
        snprintf(nan, sizeof nan, " (+%ld NaN/Inf)", m->textbook_nan);
    printf("NOTE %-44s textbook %9.2e%s  runtime %9.2e  bound %.2g\n", where, m->textbook, nan, m->runtime, bound);
    snprintf(name, sizeof name, "precision: %s: runtime within %s", where, bound_name);
    CHECK(name, m->runtime <= bound, "max|err| %.3g > %.3g", m->runtime, bound);
    snprintf(name, sizeof name, "precision: %s: the textbook form is outside it (the case shows a loss)", where);
    CHECK(name, m->textbook > bound || m->textbook_nan > 0,
          "textbook max|err| %.3g within %.3g: this case demonstrates nothing", m->textbook, bound);
}

static void conductor_case(const char *where, float eta, float kappa, float lo, float hi, int geometric)
{
    measure m;
    int i;
    memset(&m, 0, sizeof m);
    for (i = 0; i <= 20000; i++) {
        float c = sweep(lo, hi, i, 20000, geometric);
        take(&m, textbook_conductor(eta, kappa, c), fresnel_conductor(eta, kappa, c), ref_conductor(eta, kappa, c), c);
    }
    report(where, &m, FRESNEL_BOUND_CONDUCTOR, "FRESNEL_BOUND_CONDUCTOR");
}

static void dielectric_case(const char *where, float eta, float lo, float hi, int geometric)
{
    measure m;
    int i;
    memset(&m, 0, sizeof m);
    for (i = 0; i <= 20000; i++) {
        float c = sweep(lo, hi, i, 20000, geometric);
        take(&m, textbook_dielectric(eta, c), fresnel_dielectric(eta, c), ref_dielectric(eta, c), c);
    }
    report(where, &m, FRESNEL_BOUND_DIELECTRIC, "FRESNEL_BOUND_DIELECTRIC");
}

/* How many digits the textbook a^2 keeps for gold in the red (the intermediate
 * the header's comment talks about), against u^2 in double. */
static void gold_a2_digits(void)
{
    const float eta = 0.17f, kappa = 3.5f;
    double worst = 0.0;
    int i;
    for (i = 0; i <= 1000; i++) {
        float c = (float)(i / 1000.0);
        float s2 = 1.0f - c * c, t = eta * eta - kappa * kappa - s2;
        float m = sqrtf(t * t + 4.0f * eta * eta * kappa * kappa), a2 = 0.5f * (m + t);
        double td = (double)eta * eta - (double)kappa * kappa - (1.0 - (double)c * c);
        double md = sqrt(td * td + 4.0 * (double)eta * eta * (double)kappa * kappa);
        double a2d = 2.0 * (double)eta * eta * (double)kappa * kappa / (md - td); /* from a b = eta kappa */
        double rel = fabs(a2 - a2d) / a2d;
        worst = rel > worst ? rel : worst;
    }
    printf("NOTE gold red 0.17+3.5i: textbook a^2 relative error up to %.2e (%.1f of 7.2 decimal digits left)\n", worst,
           -log10(worst));
    /* More than 16 ulps is cancellation, not the few roundings of the formula. */
    CHECK("precision: gold red: the textbook a^2 is off by more than 16 ulps (cancellation)", worst > 16.0 * FLT_EPSILON,
          "rel %.3g", worst);
}

/* ---- Q15: (1-c)^5 by truncating shifts, as fixed-point code usually writes it ---- */

static int32_t textbook_schlick_q15(int32_t f0, int32_t c)
{
    int32_t x = 32768 - c, x2 = (x * x) >> 15, x4 = (x2 * x2) >> 15, x5 = (x4 * x) >> 15; /* all <= 2^30 */
    return f0 + (((32768 - f0) * x5) >> 15);
}

static void fixed_cases(void)
{
    double wt = 0.0, wr = 0.0;
    int f, c, wc = 0;
    for (f = 0; f <= 32768; f += 1311)
        for (c = 0; c <= 32768; c++) {
            double ref = ref_schlick(f / 32768.0, c / 32768.0);
            double et = fabs(textbook_schlick_q15(f, c) / 32768.0 - ref) * 32768.0;
            double er = fabs(fresnel_schlick_q15(f, c) / 32768.0 - ref) * 32768.0;
            if (et > wt) {
                wt = et;
                wc = c;
            }
            wr = er > wr ? er : wr;
        }
    printf("NOTE %-44s textbook %9.3f LSB (c code %d)  runtime %.3f LSB  bound %.3f LSB\n",
           "Q15 Schlick, (1-c)^5 by truncating shifts", wt, wc, wr, FRESNEL_BOUND_SCHLICK_Q15);
    CHECK("precision: Q15 Schlick: runtime within FRESNEL_BOUND_SCHLICK_Q15", wr <= FRESNEL_BOUND_SCHLICK_Q15,
          "%.3f LSB", wr);
    CHECK("precision: Q15 Schlick: truncating (1-c)^5 is outside it (each shift drops up to 1 LSB)",
          wt > FRESNEL_BOUND_SCHLICK_Q15, "%.3f LSB", wt);
}

#if FRESNEL_HAS_F16
/* ---- binary16: one rounding per operation, as a mediump shader ---- */

typedef fresnel_f16 half;
static half hmul(half a, half b) { return (half)(a * b); }
static half hadd(half a, half b) { return (half)(a + b); }
static half hsub(half a, half b) { return (half)(a - b); }
static half hdiv(half a, half b) { return (half)(a / b); }
static half hsqrt(half a) { return (half)sqrtf((float)a); }

/* pow as a GPU evaluates it: exp2(p log2 x), each step rounded to half. */
static half gpu_pow(half x, half p)
{
    return x > (half)0.0f ? (half)exp2f((float)hmul(p, (half)log2f((float)x))) : (half)0.0f;
}

static half textbook_schlick_f16(half f0, half c)
{
    return hadd(f0, hmul(hsub((half)1.0f, f0), gpu_pow(hsub((half)1.0f, c), (half)5.0f)));
}

/* The textbook conductor (as textbook_conductor) in binary16. */
static half textbook_conductor_f16(half eta, half kappa, half c)
{
    half one = (half)1.0f, two = (half)2.0f, s2 = hsub(one, hmul(c, c));
    half t = hsub(hsub(hmul(eta, eta), hmul(kappa, kappa)), s2);
    half m = hsqrt(hadd(hmul(t, t), hmul(hmul((half)4.0f, hmul(eta, eta)), hmul(kappa, kappa))));
    half a2 = hmul((half)0.5f, hadd(m, t)), b2 = hmul((half)0.5f, hsub(m, t));
    half a = hsqrt(a2 > (half)0.0f ? a2 : (half)0.0f), ab = hadd(a2, b2);
    half rs = hdiv(hadd(hsub(ab, hmul(hmul(two, a), c)), hmul(c, c)), hadd(hadd(ab, hmul(hmul(two, a), c)), hmul(c, c)));
    half sn = hsqrt(s2), tn = hdiv(sn, c), st = hmul(sn, tn), s2t2 = hmul(s2, hmul(tn, tn));
    half rp = hmul(rs, hdiv(hadd(hsub(ab, hmul(hmul(two, a), st)), s2t2), hadd(hadd(ab, hmul(hmul(two, a), st)), s2t2)));
    return hmul((half)0.5f, hadd(rs, rp));
}

/* Cook-Torrance's (F'(c) - F'(1)) / (1 - F'(1)) on the runtime's own binary16 F'. */
static half textbook_cook_torrance_f16(half f0, half eta, half kappa, half c)
{
    half f1 = fresnel_conductor_f16(eta, kappa, (half)1.0f), fc = fresnel_conductor_f16(eta, kappa, c);
    half t = hdiv(hsub(fc, f1), hsub((half)1.0f, f1));
    if (!(t > (half)0.0f))
        t = (half)0.0f;
    return hadd(f0, hmul(hsub((half)1.0f, f0), t));
}

static half half_bits(unsigned bits)
{
    union {
        unsigned short u;
        half h;
    } v;
    v.u = (unsigned short)bits;
    return v.h;
}

static void f16_cases(void)
{
    static const float f0s[] = {0.0f, 0.04f, 0.5f, 0.95f};
    measure m;
    unsigned b;
    int i;
    /* (1-c)^5: the GPU's pow against three multiplications. */
    memset(&m, 0, sizeof m);
    for (i = 0; i < 4; i++)
        for (b = 0; b <= 0x3c00; b++) {
            half c = half_bits(b), f0 = (half)f0s[i];
            take(&m, (float)textbook_schlick_f16(f0, c), (float)fresnel_schlick_f16(f0, c),
                 ref_schlick((double)f0, (double)c), (float)c);
        }
    printf("NOTE %-44s textbook %9.2e          runtime %9.2e  bound %.1e\n", "f16 Schlick, (1-c)^5 by GPU pow", m.textbook,
           m.runtime, FRESNEL_BOUND_SCHLICK_F16);
    CHECK("precision: f16 Schlick: runtime within FRESNEL_BOUND_SCHLICK_F16", m.runtime <= FRESNEL_BOUND_SCHLICK_F16,
          "%.3g", m.runtime);
    /* Measured, not a loss: near c = 1, (1-c)^5 underflows binary16 in both
     * forms, harmlessly in absolute terms, and mid-range the pow's rounded
     * product costs no more than the multiplications' roundings. */
    CHECK("precision: f16 Schlick: the GPU pow form is within the bound too (no loss to show in fp16)",
          m.textbook <= FRESNEL_BOUND_SCHLICK_F16, "%.3g", m.textbook);
    for (i = 0; i < 2; i++) {
        const float eta = i ? 0.05f : 0.17f, kappa = i ? 16.0f : 3.5f;
        char where[96];
        memset(&m, 0, sizeof m);
        for (b = 0; b <= 0x3c00; b++) {
            half c = half_bits(b), he = (half)eta, hk = (half)kappa;
            take(&m, (float)textbook_conductor_f16(he, hk, c), (float)fresnel_conductor_f16(he, hk, c),
                 ref_conductor((double)he, (double)hk, (double)c), (float)c);
        }
        /* A conductor has no critical angle: the binary16 bound away from one applies. */
        snprintf(where, sizeof where, "f16 conductor %g+%gi, every half c", (double)eta, (double)kappa);
        report(where, &m, FRESNEL_BOUND_F16_NONCRITICAL, "FRESNEL_BOUND_F16_NONCRITICAL");
    }
    for (i = 0; i < 4; i++) {
        const float eta = i == 0 ? 0.2f : i == 1 ? 0.05f : i == 2 ? 0.01f : FRESNEL_ETA_MIN_F16, kappa = 16.0f;
        char where[96];
        int f;
        memset(&m, 0, sizeof m);
        for (f = 0; f <= 10; f++)
            for (b = 0; b <= 0x3c00; b++) {
                half c = half_bits(b), he = (half)eta, hk = (half)kappa, f0 = (half)(f / 10.0f);
                take(&m, (float)textbook_cook_torrance_f16(f0, he, hk, c), (float)fresnel_cook_torrance_f16(f0, he, hk, c),
                     ref_cook_torrance((double)f0, (double)he, (double)hk, (double)c), (float)c);
            }
        /* T(c) = 1 - F'(c) near grazing incidence is 4cu (m + s^2) s^2 /
         * den_p of the scaled p-polarised terms, which for eta 0.05 and 0.01
         * under kappa 16 would pass through binary16's subnormals if formed
         * left to right (1.1e-2 and 3.2e-2); at eta 2^-10, d / (4 eta)
         * would overflow binary16 (an error of 1 at every c). */
        snprintf(where, sizeof where, "f16 Cook-Torrance 1 - F'(1) -> 0: %g+%gi", (double)eta, (double)kappa);
        report(where, &m, FRESNEL_BOUND_F16_NONCRITICAL, "FRESNEL_BOUND_F16_NONCRITICAL");
    }
}
#endif

int main(void)
{
    measure m;
    int i, j;

    printf("NOTE binary32: max |result - double reference|, textbook form vs runtime\n");
    gold_a2_digits();
    conductor_case("kappa >> eta: gold red 0.17+3.5i", 0.17f, 3.5f, 0.0f, 1.0f, 0);
    conductor_case("kappa >> eta: silver 0.05+4i", 0.05f, 4.0f, 0.0f, 1.0f, 0);
    conductor_case("kappa >> eta: 0.17+1000i", 0.17f, 1000.0f, 0.0f, 1.0f, 0);
    dielectric_case("critical angle: eta 0.9999, c 1e-4..0.1", 0.9999f, 1e-4f, 0.1f, 1);
    dielectric_case("eta ~ n1 grazing: eta 1.0001, c 1e-6..0.1", 1.0001f, 1e-6f, 0.1f, 1);
    conductor_case("eta ~ n1 grazing: 1.0001+1e-3i, c 1e-6..0.1", 1.0001f, 1e-3f, 1e-6f, 0.1f, 1);
    conductor_case("tan theta, c -> 0: gold red, c 1e-30..1e-3", 0.17f, 3.5f, 1e-30f, 1e-3f, 1);

    {
        float c0 = 0.0f;
        float t = textbook_conductor(0.17f, 3.5f, c0), r = fresnel_conductor(0.17f, 3.5f, c0);
        CHECK("precision: tan theta at c = 0: textbook NaN, runtime exactly 1", t != t && r == 1.0f,
              "textbook %g runtime %.9g", (double)t, (double)r);
    }

    memset(&m, 0, sizeof m);
    for (i = 0; i <= 100; i++)
        for (j = 0; j <= 200; j++) {
            float g = (float)(i / 1000.0), c = (float)(j / 200.0);
            take(&m, textbook_gulbrandsen(0.9999f, g, c), fresnel_gulbrandsen(0.9999f, g, c),
                 ref_gulbrandsen(0.9999f, g, c), g);
        }
    report("Gulbrandsen k: r 0.9999, g 0..0.1", &m, FRESNEL_BOUND_GULBRANDSEN, "FRESNEL_BOUND_GULBRANDSEN");

    for (i = 0; i < 2; i++) {
        const float kappa = i ? 100.0f : 10.0f;
        char where[80];
        int f, k;
        memset(&m, 0, sizeof m);
        for (f = 0; f <= 10; f++)
            for (k = 0; k <= 1000; k++) {
                float f0 = (float)(f / 10.0), c = (float)(k / 1000.0);
                take(&m, textbook_cook_torrance(f0, 0.17f, kappa, c), fresnel_cook_torrance(f0, 0.17f, kappa, c),
                     ref_cook_torrance(f0, 0.17f, kappa, c), c);
            }
        snprintf(where, sizeof where, "Cook-Torrance 1 - F'(1): 0.17+%gi", (double)kappa);
        report(where, &m, FRESNEL_BOUND_COOK_TORRANCE, "FRESNEL_BOUND_COOK_TORRANCE");
    }

    memset(&m, 0, sizeof m);
    for (i = 0; i <= 100000; i++) {
        float c = (float)(i / 1e6);
        take(&m, textbook_schlick_gen(0.04f, 1.0f, 40.0f, c), fresnel_schlick_gen(0.04f, 1.0f, 40.0f, c),
             ref_schlick_gen(0.04f, 1.0f, 40.0f, c), c);
    }
    report("generalized Schlick powf(1-c, 40), c 0..0.1", &m, FRESNEL_BOUND_SCHLICK_GEN, "FRESNEL_BOUND_SCHLICK_GEN");

    /* The runtime near F0 = 1 within FRESNEL_BOUND_F0_IN_MEDIUM. */
    memset(&m, 0, sizeof m);
    for (i = 0; i <= 2000; i++)
        for (j = 0; j <= 200; j++) {
            float f0 = (float)(1.0 - pow(10.0, -6.0 * i / 2000)), e = (float)(0.01 * pow(1e4, j / 200.0));
            take(&m, textbook_f0_in_medium(f0, e), fresnel_f0_in_medium(f0, e), ref_f0_in_medium(f0, e), f0);
        }
    report("F0 in a medium, F0 -> 1", &m, FRESNEL_BOUND_F0_IN_MEDIUM, "FRESNEL_BOUND_F0_IN_MEDIUM");
    fixed_cases();
#if FRESNEL_HAS_F16
    f16_cases();
#endif
    return harness_exit();
}
