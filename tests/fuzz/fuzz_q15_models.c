/* Differential fuzzing of the Q15 fixed-point runtime (fresnel_fixed.h)
 * against the double reference (gen/common/reference.c).
 *
 * Inputs: cosine and reflectance codes as arbitrary int32 (the API takes
 * int32 so that a signed dot product can be passed), Q16.16 eta, kappa, p,
 * a, alpha as arbitrary int32, a material as double eta, kappa prepared on
 * the host (gen/3_encode/q15_params.c, as `fresnel gen` does), and LUTs of random
 * nodes.
 * Oracle:
 *   - every result is a code in [0, 32768], whatever the input;
 *   - where the inputs lie in the documented domain (eta in [2^-10, 32767],
 *     kappa <= 32767; codes anything, as they are clamped onto the whole
 *     domain), |result / 32768 - reference| <= FRESNEL_BOUND_*_Q15
 *     LSB, the reference evaluated at the values the codes stand for, with
 *     the runtime's documented clamps (eta >= 64/65536, Gulbrandsen r <=
 *     code 32764, generalized Schlick p >= 66/65536) applied to its inputs. */
#include <limits.h>

#include "fuzz.h"

#include "3_encode/q15_params.h"
#include "fresnel.h"
#include "fresnel_fixed.h"
#include "fresnel_fixed_fast.h"
#include "model/registry.h"
#include "common/reference.h"

#define LSB (1.0 / 32768.0)

/* Inputs that once broke a bound or the range stay in the corpus
 * (tests/fuzz/corpus/fuzz_q15_models/): Gulbrandsen at r -> 1, g = 1;
 * a0 + c^2 at the int32 limit; generalized Schlick beyond p = 64; the exact
 * forms and Cook-Torrance near a critical angle of a tiny eta or kappa << 1;
 * the dielectric at eta -> 0 near normal incidence. Every function is held
 * to its documented bound on the whole documented domain. */

/* What the prepared layout of fresnel_fixed.h (shift in [0, 30],
 * |a0| < 2^31 - 2^(30 - shift)) is for: a0 + c^2, c^2 up to 2^(30 - shift),
 * must fit int32. (fresnel_ior_prepare_q15 returns a0 = -2^30 with shift 0
 * for eta^2 - kappa^2 = 0, outside the letter of the layout but harmless:
 * only the positive side can overflow, so only it is checked.) */
static int ior_layout_ok(const fresnel_ior_prep_q15 *m)
{
    return m->shift >= 0 && m->shift <= 30 && (double)m->a0 + ldexp(1.0, 30 - m->shift) <= 2147483647.0;
}

static void check_layout(const char *who, const fresnel_ior_prep_q15 *m, const char *args)
{
    if (!ior_layout_ok(m))
        FUZZ_FAIL("%s: a0 %ld with shift %d breaks |a0| < 2^31 - 2^(30 - shift) (%s)", who, (long)m->a0,
                  (int)m->shift, args);
}

static int32_t fuzz_code(fuzz_bytes *b)
{
    static const int32_t special[] = {0, 1, 2, 16384, 32767, 32768, 32769, 65535, 65536, -1, -32768,
                                      INT32_MIN, INT32_MAX, 1311, 31130, 34079, 4681, 32764, 32765};
    uint8_t mode = fuzz_u8(b);
    uint32_t u = fuzz_u32(b);
    switch (mode % 6) {
    case 0: return (int32_t)u;
    case 1: return special[u % (sizeof special / sizeof special[0])];
    case 2: return (int32_t)(u % 32769u);
    case 3: return (int32_t)(u % 33u) - 16;
    case 4: return 32768 - 16 + (int32_t)(u % 33u);
    default: return (int32_t)(u % 32769u) & ~(int32_t)(fuzz_u8(b) & 0xff); /* coarse codes */
    }
}

/* A Q16.16 code for a positive quantity of natural scale [lo, hi]. */
static fresnel_q16 fuzz_q16(fuzz_bytes *b, float lo, float hi)
{
    uint8_t mode = fuzz_u8(b);
    if (mode % 4 == 0)
        return (fresnel_q16)fuzz_u32(b);
    {
        float x = fuzz_float(b, lo, hi);
        double v = (double)x * 65536.0;
        if (!(v == v))
            return 0;
        return v >= 2147483647.0 ? INT32_MAX : v <= -2147483648.0 ? INT32_MIN : (fresnel_q16)floor(v + 0.5);
    }
}

static double unit_code(int32_t c) { return c / 32768.0; } /* the reference clamps */

/* Results are in [0, top]: top is one, or for a uint16_t curve table the
 * larger of one and its largest node (fresnel_fixed.h). */
static void check_top(const char *fn, int32_t got, double ref, double bound_lsb, int32_t top, int in_domain,
                      const char *args)
{
    double err = fabs(got * LSB - ref);
    if (!(got >= 0 && got <= top))
        FUZZ_FAIL("%s(%s) = %d, outside [0, %d]", fn, args, (int)got, (int)top);
    else if (in_domain && !(err <= bound_lsb * LSB))
        FUZZ_FAIL("%s(%s) = %d, reference %.17g (%.3f LSB): |err| %.3f LSB > bound %.3f", fn, args, (int)got, ref,
                  ref * 32768.0, err * 32768.0, bound_lsb);
}

static void check(const char *fn, int32_t got, double ref, double bound_lsb, int in_domain, const char *args)
{
    check_top(fn, got, ref, bound_lsb, 32768, in_domain, args);
}

static int measured_eta(double eta) { return eta >= FRESNEL_ETA_MIN_Q16 / 65536.0 && eta <= 32767.0; }
static int measured_kappa(double kappa) { return kappa >= 0.0 && kappa <= 32767.0; }

/* The model table's Q15 entries on a material prepared on the host. */
static void fuzz_prepared(fuzz_bytes *b, int32_t c)
{
    double eta = fuzz_float(b, 0.0009765625f, 32767.0f), kappa = fuzz_float(b, 1e-4f, 32767.0f);
    double f90 = fuzz_float(b, 1e-3f, 1.0f), p = fuzz_float(b, 0.25f, 40.0f);
    model_params mp;
    model_q15 mf;
    int mi, in;
    char args[160];
    /* The host preparation takes finite, positive parameters (the generator's). */
    if (!(eta > 0.0 && eta <= 1e5 && kappa >= 0.0 && kappa <= 1e5 && f90 == f90 && p > 0.0 && p <= 1e3))
        return;
    model_derive(eta, kappa, 1.0, ref_clamp(f90, 0.0, 1.0), p, &mp);
    model_params_round_q15(&mp);
    model_q15_from_params(&mp, &mf);
    in = measured_eta(mp.eta) && measured_kappa(mp.kappa);
    snprintf(args, sizeof args, "eta %.9g kappa %.9g p %.9g f90 %.9g, c %d", eta, kappa, p, f90, (int)c);
    check_layout("q15_ior (host)", &mf.ior, args);
    check_layout("q15_ior (host)", &mf.dior, args);
    /* The runtime's clamps: Gulbrandsen's r to code 32764, p to Q16.16 code 66 at least. */
    mp.r = ref_clamp(mp.r, 0.0, FRESNEL_GULBRANDSEN_R_MAX_Q15 / 32768.0);
    mp.p = ref_clamp(mp.p, FRESNEL_P_MIN_Q16 / 65536.0, FRESNEL_P_MAX_Q16 / 65536.0);
    for (mi = 0; mi < model_count; mi++) {
        const model *m = &model_table[mi];
        double bound = m->q15_bound;
        if (!m->q15->scalar)
            continue;
        check(m->name, m->q15->scalar(&mf, c), m->ref->scalar(&mp, ref_clamp(unit_code(c), 0.0, 1.0)), bound, in, args);
    }
    /* The exact conductor's fast path on its own domain (fresnel_fixed_fast.h,
     * the generator's test: c in [0, one] is a precondition, so c is
     * clamped here), held to its documented bound. */
    if (q15_conductor_fast_in_domain(eta, kappa)) {
        fresnel_conductor_prep_q15_fast cf;
        int32_t cc = c < 0 ? 0 : (c > 32768 ? 32768 : c);
        q15_conductor_fast(eta, kappa, &cf);
        check("fresnel_conductor_q15_fast", fresnel_conductor_q15_fast(&cf, cc), ref_conductor(eta, kappa, cc / 32768.0),
              FRESNEL_BOUND_CONDUCTOR_Q15_FAST, 1, args);
    }
}

/* Linear interpolation in double on the nodes lut_q15.c documents: uniform
 * in sqrt(c), or in c. */
static double ref_interp(const double *v, int n, double x)
{
    double pos = x * (n - 1);
    int i = (int)pos;
    if (i >= n - 1)
        i = n - 2;
    return v[i] + (pos - i) * (v[i + 1] - v[i]);
}

#define LUT_MAX 48

static double lut_steepest(const double *v, int n)
{
    double d = 0.0;
    int i;
    for (i = 0; i + 1 < n; i++)
        d = fabs(v[i + 1] - v[i]) > d ? fabs(v[i + 1] - v[i]) : d;
    return d;
}

static void fuzz_luts(fuzz_bytes *b, int32_t f0, int32_t c)
{
    uint16_t u16[3 * LUT_MAX];
    uint8_t u8[3 * LUT_MAX];
    int16_t s16[3 * LUT_MAX];
    int8_t s8[3 * LUT_MAX];
    double v16[LUT_MAX], v8[LUT_MAX], r16[LUT_MAX], r8[LUT_MAX];
    int n = 2 + fuzz_u8(b) % (LUT_MAX - 1), i;
    int32_t top16 = 32768;
    int frac16 = 15 + fuzz_u8(b) % 16, frac8 = 7 + fuzz_u8(b) % 16;
    double cc = ref_clamp(unit_code(c), 0.0, 1.0), w = sqrt(cc), s = ref_schlick(unit_code(f0), cc);
    double bound16, bound8, rbound16, rbound8, step;
    char args[96];
    fresnel_rgb_q15 rgb, f03;
    for (i = 0; i < 3 * n; i++) {
        uint32_t u = fuzz_u32(b);
        u16[i] = (uint16_t)u; /* the whole code range: nodes above one are headroom */
        u8[i] = (uint8_t)u;
        s16[i] = (int16_t)(u >> 16);
        s8[i] = (int8_t)(u >> 8);
    }
    for (i = 0; i < n; i++) {
        v16[i] = u16[i] * LSB;
        v8[i] = u8[i] / 255.0;
        r16[i] = ldexp(s16[i], -frac16);
        r8[i] = ldexp(s8[i], -frac8);
    }
    /* fresnel_fixed.h: 0.5 LSB rounding plus the position's error times the
     * steepest node-to-node change: half a position step (2^-16 of a segment)
     * and the floor of sqrt(c) in Q30 ((n-1) 2^-30 of a segment), that is
     * 0.5 + (n-1) 2^-15 LSB per unit of reflectance (1.01 for a two-node
     * table spanning [0, 1]). */
    step = 0.5 + (n - 1) * LSB;
    bound16 = 0.51 + step * lut_steepest(v16, n);
    bound8 = 0.51 + step * lut_steepest(v8, n);
    rbound16 = 0.51 + step * lut_steepest(r16, n);
    rbound8 = 0.51 + step * lut_steepest(r8, n);
    snprintf(args, sizeof args, "n %d, f0 %d, c %d, frac %d/%d", n, (int)f0, (int)c, frac16, frac8);
    for (i = 0; i < n; i++)
        top16 = u16[i] > top16 ? u16[i] : top16;
    check_top("fresnel_lut_u16_q15", fresnel_lut_u16_q15(u16, n, c), ref_interp(v16, n, w), bound16, top16, 1, args);
    check_top("fresnel_lut_linear_u16_q15", fresnel_lut_linear_u16_q15(u16, n, c), ref_interp(v16, n, cc), bound16,
              top16, 1, args);
    check("fresnel_lut_u8_q15", fresnel_lut_u8_q15(u8, n, c), ref_interp(v8, n, w), bound8, 1, args);
    check("fresnel_lut_linear_u8_q15", fresnel_lut_linear_u8_q15(u8, n, c), ref_interp(v8, n, cc), bound8, 1, args);
    check("fresnel_lut_residual_s16_q15", fresnel_lut_residual_s16_q15(f0, s16, n, frac16, c),
          ref_clamp(s + ref_interp(r16, n, w), 0.0, 1.0), rbound16, 1, args);
    check("fresnel_lut_linear_residual_s16_q15", fresnel_lut_linear_residual_s16_q15(f0, s16, n, frac16, c),
          ref_clamp(s + ref_interp(r16, n, cc), 0.0, 1.0), rbound16, 1, args);
    check("fresnel_lut_residual_s8_q15", fresnel_lut_residual_s8_q15(f0, s8, n, frac8, c),
          ref_clamp(s + ref_interp(r8, n, w), 0.0, 1.0), rbound8, 1, args);
    check("fresnel_lut_linear_residual_s8_q15", fresnel_lut_linear_residual_s8_q15(f0, s8, n, frac8, c),
          ref_clamp(s + ref_interp(r8, n, cc), 0.0, 1.0), rbound8, 1, args);
    /* n outside [2, 32768]: n <= 0 reads nothing (a null table) and gives 0,
     * or Schlick alone for a residual table; n = 1 is the constant table[0]. */
    {
        static const int small[] = {INT_MIN, -65536, -1, 0};
        int ns = small[fuzz_u8(b) % 4];
        if (fresnel_lut_u16_q15(NULL, ns, c) != 0 || fresnel_lut_linear_u8_q15(NULL, ns, c) != 0 ||
            fresnel_lut_cubic_u16_q15(NULL, ns, c) != 0 || fresnel_lut_u16_q15_fast(NULL, ns, c) != 0 ||
            fresnel_lut_pl_u16_q15_fast(NULL, ns, c) != 0 ||
            fresnel_lut_residual_s16_q15(f0, NULL, ns, frac16, c) != fresnel_schlick_q15(f0, c))
            FUZZ_FAIL("LUT with n = %d is not 0 / Schlick (%s)", ns, args);
        if (fresnel_lut_u16_q15(u16, 1, c) != u16[0] || fresnel_lut_linear_u16_q15(u16, 1, c) != u16[0] ||
            fresnel_lut_cubic_u16_q15(u16, 1, c) != u16[0] || fresnel_lut_u16_q15_fast(u16, 1, c) != u16[0] ||
            fresnel_lut_pl_u16_q15_fast(u16, 1, c) != u16[0])
            FUZZ_FAIL("LUT with n = 1 is not table[0] = %d (%s)", (int)u16[0], args);
    }
    /* RGB forms: channel by channel the scalar ones. */
    rgb = fresnel_lut_u16_q15_rgb(u16, n, c);
    if (rgb.r != fresnel_lut_u16_q15(u16, n, c) || rgb.g != fresnel_lut_u16_q15(u16 + n, n, c) ||
        rgb.b != fresnel_lut_u16_q15(u16 + 2 * n, n, c))
        FUZZ_FAIL("fresnel_lut_u16_q15_rgb differs from the scalar form (%s)", args);
    f03.r = f03.g = f03.b = (fresnel_q15)(f0 < 0 ? 0 : f0 > 32768 ? 32768 : f0);
    rgb = fresnel_lut_residual_s8_q15_rgb(f03, s8, n, frac8, c);
    if (rgb.r != fresnel_lut_residual_s8_q15(f03.r, s8, n, frac8, c) ||
        rgb.b != fresnel_lut_residual_s8_q15(f03.b, s8 + 2 * n, n, frac8, c))
        FUZZ_FAIL("fresnel_lut_residual_s8_q15_rgb differs from the scalar form (%s)", args);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz_bytes b;
    int32_t c, f0, f82, f90, r, g;
    fresnel_q16 eta, kappa, p, a, alpha;
    double e, k, pe, si;
    char args[200];
    fresnel_ior_prep_q15 ior, dior;
    fresnel_nk_prep_q15 nk;
    fresnel_lsk_prep_q15 lsk;
    fresnel_rgb_q15 rgb, x3;
    int in;
    b.p = data;
    b.n = size;
    c = fuzz_code(&b);
    f0 = fuzz_code(&b);
    f82 = fuzz_code(&b);
    f90 = fuzz_code(&b);
    r = fuzz_code(&b);
    g = fuzz_code(&b);
    eta = fuzz_q16(&b, 0.0009765625f, 32767.0f);
    kappa = fuzz_q16(&b, 1e-3f, 32767.0f);
    p = fuzz_q16(&b, 0.25f, 40.0f);
    a = fuzz_q16(&b, 0.02f, 200.0f);
    alpha = fuzz_q16(&b, 0.1f, 100.0f);
    /* The runtime's clamps of Q16.16 inputs (fresnel_fixed.h). */
    e = (eta < FRESNEL_ETA_MIN_Q16 ? FRESNEL_ETA_MIN_Q16 : eta) / 65536.0;
    k = (kappa < 0 ? 0 : kappa) / 65536.0;
    pe = (p < FRESNEL_P_MIN_Q16 ? FRESNEL_P_MIN_Q16 : p > FRESNEL_P_MAX_Q16 ? FRESNEL_P_MAX_Q16 : p) / 65536.0;
    in = measured_eta(e) && measured_kappa(k);
    snprintf(args, sizeof args, "f0 %d f82 %d f90 %d r %d g %d eta %d kappa %d p %d a %d alpha %d, c %d", (int)f0,
             (int)f82, (int)f90, (int)r, (int)g, (int)eta, (int)kappa, (int)p, (int)a, (int)alpha, (int)c);

    check("fresnel_schlick_q15", fresnel_schlick_q15(f0, c), ref_schlick(unit_code(f0), unit_code(c)),
          FRESNEL_BOUND_SCHLICK_Q15, 1, args);
    check("fresnel_schlick_gen_q15", fresnel_schlick_gen_q15(f0, f90, p, c),
          ref_schlick_gen(unit_code(f0), unit_code(f90), pe, unit_code(c)),
          FRESNEL_BOUND_SCHLICK_GEN_Q15, 1, args);
    check("fresnel_f82_q15", fresnel_f82_q15(f0, f82, c), ref_f82(unit_code(f0), unit_code(f82), unit_code(c)),
          FRESNEL_BOUND_F82_Q15, 1, args);
    check("fresnel_gulbrandsen_q15", fresnel_gulbrandsen_q15(r, g, c),
          ref_gulbrandsen(ref_clamp(unit_code(r), 0.0, FRESNEL_GULBRANDSEN_R_MAX_Q15 / 32768.0), unit_code(g),
                          unit_code(c)),
          FRESNEL_BOUND_GULBRANDSEN_Q15, 1, args);
    check("fresnel_f0_from_ior_q15", fresnel_f0_from_ior_q15(eta, kappa), ref_f0_from_ior(e, k), FRESNEL_BOUND_F0_FROM_IOR_Q15,
          in, args);
    check("fresnel_f0_in_medium_q15", fresnel_f0_in_medium_q15(f0, eta), ref_f0_in_medium(unit_code(f0), e),
          FRESNEL_BOUND_F0_IN_MEDIUM_Q15, measured_eta(e), args);

    ior = fresnel_ior_prepare_q15(eta, kappa);
    dior = fresnel_ior_prepare_q15(eta, 0);
    nk = fresnel_nk_prepare_q15(eta, kappa);
    lsk = fresnel_lsk_prepare_q15(eta, kappa, a, alpha);
    check_layout("fresnel_ior_prepare_q15", &ior, args);
    check_layout("fresnel_ior_prepare_q15 (kappa 0)", &dior, args);
    /* The two words a0, a0_lo hold eta^2 - kappa^2 - 1 of the Q16.16 codes
     * exactly, so the reference takes eta and kappa as given, also at a
     * critical angle, where the result is as sensitive to eta as the physics
     * makes it. Schlick internal: ct^2 = (eta^2 - 1 + c^2) / eta^2, one past
     * the critical angle, Schlick at c for eta >= 1. */
    {
        double cc = ref_clamp(unit_code(c), 0.0, 1.0), A = (e - 1.0) * (e + 1.0) + cc * cc;
        si = e >= 1.0 ? ref_schlick(unit_code(f0), cc) : A <= 0.0 ? 1.0 : ref_schlick(unit_code(f0), sqrt(A) / e);
    }
    check("fresnel_conductor_q15", fresnel_conductor_q15(&ior, c), ref_conductor(e, k, unit_code(c)),
          FRESNEL_BOUND_CONDUCTOR_Q15, in, args);
    check("fresnel_dielectric_q15", fresnel_dielectric_q15(&dior, c), ref_dielectric(e, unit_code(c)),
          FRESNEL_BOUND_DIELECTRIC_Q15, in, args);
    check("fresnel_cook_torrance_q15", fresnel_cook_torrance_q15(f0, &ior, c),
          ref_cook_torrance(unit_code(f0), e, k, unit_code(c)), FRESNEL_BOUND_COOK_TORRANCE_Q15, in, args);
    check("fresnel_schlick_internal_q15", fresnel_schlick_internal_q15(f0, &dior, c), si, FRESNEL_BOUND_SCHLICK_INTERNAL_Q15,
          in, args);
    check("fresnel_approx_conductor_q15", fresnel_approx_conductor_q15(&nk, c), ref_approx_conductor(e, k, unit_code(c)),
          FRESNEL_BOUND_APPROX_CONDUCTOR_Q15, in, args);
    check("fresnel_lsk_q15", fresnel_lsk_q15(&lsk, c), ref_lsk(e, k, unit_code(c)), FRESNEL_BOUND_LSK_Q15, in, args);
    /* a and alpha as the Q16.16 codes say, clamped to [0, 1e6] and [0, 1000] */
    check("fresnel_lsk_comp_q15", fresnel_lsk_comp_q15(&lsk, c),
          ref_lsk_comp(e, k, (a < 0 ? 0 : a) / 65536.0, (alpha < 0 ? 0 : alpha) / 65536.0, unit_code(c)),
          FRESNEL_BOUND_LSK_COMP_Q15, in && a >= 0 && a <= 200 * 65536, args);

    /* RGB forms equal the scalar ones channel by channel. */
    x3.r = (fresnel_q15)(f0 < 0 ? 0 : f0 > 32768 ? 32768 : f0);
    x3.g = (fresnel_q15)(f82 < 0 ? 0 : f82 > 32768 ? 32768 : f82);
    x3.b = (fresnel_q15)(f90 < 0 ? 0 : f90 > 32768 ? 32768 : f90);
    rgb = fresnel_schlick_q15_rgb(x3, c);
    if (rgb.r != fresnel_schlick_q15(x3.r, c) || rgb.g != fresnel_schlick_q15(x3.g, c) ||
        rgb.b != fresnel_schlick_q15(x3.b, c))
        FUZZ_FAIL("fresnel_schlick_q15_rgb differs from the scalar form (%s)", args);
    rgb = fresnel_cook_torrance_q15_rgb(x3, &ior, c);
    if (rgb.r != fresnel_cook_torrance_q15(x3.r, &ior, c) || rgb.b != fresnel_cook_torrance_q15(x3.b, &ior, c))
        FUZZ_FAIL("fresnel_cook_torrance_q15_rgb differs from the scalar form (%s)", args);

    fuzz_prepared(&b, c);
    fuzz_luts(&b, f0, c);
    return 0;
}
