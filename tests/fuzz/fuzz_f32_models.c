/* Differential fuzzing of every binary32 runtime function against the double
 * reference (gen/common/reference.c).
 *
 * Oracle, for every input including NaN, +-Inf and subnormals:
 *   - the result is in [0, 1] and not NaN (fresnel.h CONVENTIONS);
 *   - the RGB form equals the scalar form channel by channel, bit for bit;
 *   - where the inputs, after the documented clamps, lie in the region the
 *     bounds were measured on (eta in [0.01, 100], kappa in [0, 1000]; c, F0,
 *     F82, F90, r, g anything since they are clamped onto their whole
 *     domain; p, a, alpha anywhere in their documented domain), the absolute
 *     difference from the reference evaluated on the same binary32 inputs is
 *     within the FRESNEL_BOUND_* the header documents.
 * The reference applies the same clamps as the runtime, so comparing on the
 * raw (unclamped) inputs also checks that the two clamp alike. */
#include "fuzz.h"

#include "fresnel.h"
#include "common/reference.h"

/* The region of eta and kappa where fresnel.h says the bounds were measured. */
static int measured_eta(float e)
{
    double x = ref_clamp(e, FRESNEL_ETA_MIN, FRESNEL_ETA_MAX);
    return x >= (double)0.01f && x <= 100.0; /* (float)0.01 is just below 0.01 */
}
static int measured_kappa(float k)
{
    double x = ref_clamp(k, 0.0, FRESNEL_KAPPA_MAX);
    return x <= 1000.0;
}

/* LSK's a is 2n from the host's fit (fresnel.h), so the measured eta range
 * gives a <= 200. The documented domain goes on to FRESNEL_A_MAX = 1e6,
 * where the error grows with a as fresnel.h says (6.8e-7 at a <= 2000,
 * 1.2e-6 at a near 1e6): outside a <= 200 only the range is checked. */
static int measured_a(float a)
{
    return ref_clamp(a, 0.0, FRESNEL_A_MAX) <= 200.0;
}

/* Results are in [0, top]: top is 1, or for a curve table the larger of 1
 * and its largest node (fresnel.h). */
static void check_range_top(const char *fn, float got, float top, const float *in, int nin)
{
    if (!(got >= 0.0f && got <= top)) {
        char args[256];
        int i, len = 0;
        for (i = 0; i < nin && len < 200; i++)
            len += snprintf(args + len, sizeof args - (size_t)len, "%s%a", i ? ", " : "", (double)in[i]);
        FUZZ_FAIL("%s(%s) = %.9g, outside [0, %.9g]", fn, args, (double)got, (double)top);
    }
}

static void check_range(const char *fn, float got, const float *in, int nin)
{
    check_range_top(fn, got, 1.0f, in, nin);
}

static void check_bound_top(const char *fn, float got, double ref, double bound, float top, const float *in,
                            int nin)
{
    double err = fabs((double)got - ref);
    check_range_top(fn, got, top, in, nin);
    if (!(err <= bound)) {
        char args[256];
        int i, len = 0;
        for (i = 0; i < nin && len < 200; i++)
            len += snprintf(args + len, sizeof args - (size_t)len, "%s%.9g", i ? ", " : "", (double)in[i]);
        FUZZ_FAIL("%s(%s) = %.9g, reference %.17g: |err| %.3g > bound %.3g", fn, args, (double)got,
                  ref, err, bound);
    }
}

static void check_bound(const char *fn, float got, double ref, double bound, const float *in, int nin)
{
    check_bound_top(fn, got, ref, bound, 1.0f, in, nin);
}

static void check_rgb(const char *fn, fresnel_rgb got, float r, float g, float b)
{
    if (memcmp(&got.r, &r, sizeof r) || memcmp(&got.g, &g, sizeof g) || memcmp(&got.b, &b, sizeof b))
        FUZZ_FAIL("%s: RGB (%.9g, %.9g, %.9g) differs from the scalar form (%.9g, %.9g, %.9g)", fn,
                  (double)got.r, (double)got.g, (double)got.b, (double)r, (double)g, (double)b);
}

static fresnel_rgb rgb3(float r, float g, float b)
{
    fresnel_rgb x;
    x.r = r;
    x.g = g;
    x.b = b;
    return x;
}

/* Linear interpolation in double on the same nodes as src/f32/lut.c. */
static double ref_interp(const float *t, int n, double x)
{
    double pos = x * (n - 1);
    int i = (int)pos;
    if (i >= n - 1)
        i = n - 2;
    return t[i] + (pos - i) * ((double)t[i + 1] - t[i]);
}

/* The tables are generated, smooth curves; the header's 3e-7 covers the
 * interpolation arithmetic. A node position off by d (rounding of sqrt(c),
 * half an ulp of 1 at most, times n - 1, plus that of the product) moves the result by
 * d times the step between neighbouring nodes, which for a smooth table is
 * small; the fuzzer's tables are not smooth, so that term is added with the
 * steepest step of the table. */
static double lut_bound(const float *t, int n)
{
    double step = 0.0;
    int i;
    for (i = 0; i + 1 < n; i++)
        if (fabs((double)t[i + 1] - t[i]) > step)
            step = fabs((double)t[i + 1] - t[i]);
    return 3e-7 + step * (n - 1) * 4.0 * FLT_EPSILON;
}

#define LUT_MAX 64

static void fuzz_luts(fuzz_bytes *b, float c, float f0)
{
    float table[3 * LUT_MAX], res[3 * LUT_MAX];
    int n = 2 + fuzz_u8(b) % (LUT_MAX - 1), i;
    fresnel_rgb f03 = rgb3(f0, f0, f0), got;
    double cc = ref_clamp(c, 0.0, 1.0), w = sqrt(cc), bound; /* nodes uniform in sqrt(c) */
    float in[2], top = 1.0f;
    in[0] = c;
    in[1] = (float)n;
    /* Reflectance tables in [0, 2] (above 1: headroom, as the keep policy
     * makes); residual tables in [-1, 1]. */
    for (i = 0; i < 3 * n; i++) {
        uint8_t v = fuzz_u8(b);
        table[i] = v / 127.5f;
        res[i] = (v - 127.5f) / 127.5f;
    }
    bound = lut_bound(table, n);
    /* linear interpolation stays between its nodes: no clamp acts */
    for (i = 0; i < n; i++)
        top = table[i] > top ? table[i] : top;
    check_bound_top("fresnel_lut", fresnel_lut(table, n, c), ref_interp(table, n, w), bound, top, in, 2);
    check_bound_top("fresnel_lut_linear", fresnel_lut_linear(table, n, c), ref_interp(table, n, cc), bound, top, in,
                    2);
    bound = lut_bound(res, n) + FRESNEL_BOUND_SCHLICK;
    check_bound("fresnel_lut_residual", fresnel_lut_residual(f0, res, n, c),
                ref_clamp(ref_schlick(f0, cc) + ref_interp(res, n, w), 0.0, 1.0), bound, in, 2);
    check_bound("fresnel_lut_linear_residual", fresnel_lut_linear_residual(f0, res, n, c),
                ref_clamp(ref_schlick(f0, cc) + ref_interp(res, n, cc), 0.0, 1.0), bound, in, 2);
    got = fresnel_lut_rgb(table, n, c);
    check_rgb("fresnel_lut_rgb", got, fresnel_lut(table, n, c), fresnel_lut(table + n, n, c),
              fresnel_lut(table + 2 * n, n, c));
    got = fresnel_lut_linear_rgb(table, n, c);
    check_rgb("fresnel_lut_linear_rgb", got, fresnel_lut_linear(table, n, c),
              fresnel_lut_linear(table + n, n, c), fresnel_lut_linear(table + 2 * n, n, c));
    got = fresnel_lut_residual_rgb(f03, res, n, c);
    check_rgb("fresnel_lut_residual_rgb", got, fresnel_lut_residual(f0, res, n, c),
              fresnel_lut_residual(f0, res + n, n, c), fresnel_lut_residual(f0, res + 2 * n, n, c));
    got = fresnel_lut_linear_residual_rgb(f03, res, n, c);
    check_rgb("fresnel_lut_linear_residual_rgb", got, fresnel_lut_linear_residual(f0, res, n, c),
              fresnel_lut_linear_residual(f0, res + n, n, c),
              fresnel_lut_linear_residual(f0, res + 2 * n, n, c));
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz_bytes b;
    float c, eta, kappa, f0, f82, f90, p, a, alpha, r, g, in[5];
    float s0, s1, s2;
    int eta_ok, kappa_ok;
    fresnel_nk nk;
    fresnel_rg rg;
    b.p = data;
    b.n = size;
    c = fuzz_float(&b, 1e-8f, 1.0f);
    eta = fuzz_float(&b, 0.01f, 100.0f);
    kappa = fuzz_float(&b, 1e-6f, 1000.0f);
    f0 = fuzz_float(&b, 1e-4f, 1.0f);
    f82 = fuzz_float(&b, 1e-4f, 1.0f);
    f90 = fuzz_float(&b, 1e-4f, 1.0f);
    p = fuzz_float(&b, 0.25f, 40.0f);
    a = fuzz_float(&b, 0.02f, 200.0f);
    alpha = fuzz_float(&b, 0.1f, 100.0f);
    r = fuzz_float(&b, 1e-4f, 1.0f);
    g = fuzz_float(&b, 1e-4f, 1.0f);
    eta_ok = measured_eta(eta);
    kappa_ok = measured_kappa(kappa);

    in[0] = f0;
    in[1] = c;
    s0 = fresnel_schlick(f0, c);
    check_bound("fresnel_schlick", s0, ref_schlick(f0, c), FRESNEL_BOUND_SCHLICK, in, 2);
    check_rgb("fresnel_schlick_rgb", fresnel_schlick_rgb(rgb3(f0, f82, f90), c), s0,
              fresnel_schlick(f82, c), fresnel_schlick(f90, c));

    in[0] = f0, in[1] = f90, in[2] = p, in[3] = c;
    s0 = fresnel_schlick_gen(f0, f90, p, c);
    check_bound("fresnel_schlick_gen", s0, ref_schlick_gen(f0, f90, p, c), FRESNEL_BOUND_SCHLICK_GEN, in, 4);
    check_rgb("fresnel_schlick_gen_rgb", fresnel_schlick_gen_rgb(rgb3(f0, f82, r), rgb3(f90, g, 1.0f), p, c),
              s0, fresnel_schlick_gen(f82, g, p, c), fresnel_schlick_gen(r, 1.0f, p, c));

    in[0] = f0, in[1] = eta, in[2] = c;
    s0 = fresnel_schlick_internal(f0, eta, c);
    if (eta_ok)
        check_bound("fresnel_schlick_internal", s0, ref_schlick_internal(f0, eta, c),
                    FRESNEL_BOUND_SCHLICK_INTERNAL, in, 3);
    else
        check_range("fresnel_schlick_internal", s0, in, 3);
    check_rgb("fresnel_schlick_internal_rgb", fresnel_schlick_internal_rgb(rgb3(f0, f82, f90), eta, c),
              s0, fresnel_schlick_internal(f82, eta, c), fresnel_schlick_internal(f90, eta, c));

    in[0] = f0, in[1] = eta;
    s0 = fresnel_f0_in_medium(f0, eta);
    if (eta_ok)
        check_bound("fresnel_f0_in_medium", s0, ref_f0_in_medium(f0, eta),
                    FRESNEL_BOUND_F0_IN_MEDIUM, in, 2);
    else
        check_range("fresnel_f0_in_medium", s0, in, 2);

    in[0] = eta, in[1] = kappa, in[2] = c;
    s0 = fresnel_f0_from_ior(eta, kappa);
    if (eta_ok && kappa_ok)
        check_bound("fresnel_f0_from_ior", s0, ref_f0_from_ior(eta, kappa), FRESNEL_BOUND_F0_FROM_IOR, in, 2);
    else
        check_range("fresnel_f0_from_ior", s0, in, 2);

    s0 = fresnel_lsk(eta, kappa, c);
    if (eta_ok && kappa_ok)
        check_bound("fresnel_lsk", s0, ref_lsk(eta, kappa, c), FRESNEL_BOUND_LSK, in, 3);
    else
        check_range("fresnel_lsk", s0, in, 3);
    check_rgb("fresnel_lsk_rgb", fresnel_lsk_rgb(rgb3(eta, eta, f0), rgb3(kappa, f82, kappa), c), s0,
              fresnel_lsk(eta, f82, c), fresnel_lsk(f0, kappa, c));

    in[0] = eta, in[1] = kappa, in[2] = a, in[3] = alpha, in[4] = c;
    s0 = fresnel_lsk_comp(eta, kappa, a, alpha, c);
    if (eta_ok && kappa_ok && measured_a(a))
        check_bound("fresnel_lsk_comp", s0, ref_lsk_comp(eta, kappa, a, alpha, c), FRESNEL_BOUND_LSK_COMP,
                    in, 5);
    else
        check_range("fresnel_lsk_comp", s0, in, 5);
    check_rgb("fresnel_lsk_comp_rgb",
              fresnel_lsk_comp_rgb(rgb3(eta, eta, eta), rgb3(kappa, kappa, 0.0f), rgb3(a, 0.0f, a),
                                   rgb3(alpha, alpha, alpha), c),
              s0, fresnel_lsk_comp(eta, kappa, 0.0f, alpha, c), fresnel_lsk_comp(eta, 0.0f, a, alpha, c));

    in[0] = f0, in[1] = f82, in[2] = c;
    s0 = fresnel_f82(f0, f82, c);
    check_bound("fresnel_f82", s0, ref_f82(f0, f82, c), FRESNEL_BOUND_F82, in, 3);
    check_rgb("fresnel_f82_rgb", fresnel_f82_rgb(rgb3(f0, f82, r), rgb3(f82, f0, g), c), s0,
              fresnel_f82(f82, f0, c), fresnel_f82(r, g, c));

    in[0] = r, in[1] = g, in[2] = c;
    s0 = fresnel_gulbrandsen(r, g, c);
    check_bound("fresnel_gulbrandsen", s0, ref_gulbrandsen(r, g, c),
                FRESNEL_BOUND_GULBRANDSEN, in, 3);
    check_rgb("fresnel_gulbrandsen_rgb", fresnel_gulbrandsen_rgb(rgb3(r, g, f0), rgb3(g, r, f82), c), s0,
              fresnel_gulbrandsen(g, r, c), fresnel_gulbrandsen(f0, f82, c));
    nk = fresnel_gulbrandsen_nk(r, g);
    if (!(nk.n > 0.0f && nk.n <= FLT_MAX && nk.k >= 0.0f && nk.k <= FLT_MAX))
        FUZZ_FAIL("fresnel_gulbrandsen_nk(%a, %a) = (%g, %g): expected n > 0, k >= 0, finite", (double)r,
                  (double)g, (double)nk.n, (double)nk.k);
    rg = fresnel_gulbrandsen_rg(eta, kappa);
    if (!(rg.r >= 0.0f && rg.r <= 1.0f && rg.g >= 0.0f && rg.g <= 1.0f))
        FUZZ_FAIL("fresnel_gulbrandsen_rg(%a, %a) = (%g, %g): expected both in [0, 1]", (double)eta,
                  (double)kappa, (double)rg.r, (double)rg.g);
    else if (eta == eta && kappa == kappa) {
        /* the edge tint over the whole domain (r -> 0 and r -> 1 included) */
        double rr, rgg;
        ref_gulbrandsen_rg(eta, kappa, &rr, &rgg);
        if (!(fabs((double)rg.g - rgg) <= FRESNEL_BOUND_GULBRANDSEN_RG))
            FUZZ_FAIL("fresnel_gulbrandsen_rg(%a, %a).g = %.9g, reference %.9g: beyond %g", (double)eta,
                      (double)kappa, (double)rg.g, rgg, (double)FRESNEL_BOUND_GULBRANDSEN_RG);
    }

    in[0] = eta, in[1] = kappa, in[2] = c;
    s0 = fresnel_approx_conductor(eta, kappa, c);
    if (eta_ok && kappa_ok)
        check_bound("fresnel_approx_conductor", s0, ref_approx_conductor(eta, kappa, c),
                    FRESNEL_BOUND_APPROX_CONDUCTOR, in, 3);
    else
        check_range("fresnel_approx_conductor", s0, in, 3);
    check_rgb("fresnel_approx_conductor_rgb",
              fresnel_approx_conductor_rgb(rgb3(eta, f0, eta), rgb3(kappa, kappa, f82), c), s0,
              fresnel_approx_conductor(f0, kappa, c), fresnel_approx_conductor(eta, f82, c));

    s0 = fresnel_conductor(eta, kappa, c);
    if (eta_ok && kappa_ok)
        check_bound("fresnel_conductor", s0, ref_conductor(eta, kappa, c), FRESNEL_BOUND_CONDUCTOR, in, 3);
    else
        check_range("fresnel_conductor", s0, in, 3);
    check_rgb("fresnel_conductor_rgb", fresnel_conductor_rgb(rgb3(eta, f0, eta), rgb3(kappa, kappa, f82), c),
              s0, fresnel_conductor(f0, kappa, c), fresnel_conductor(eta, f82, c));

    in[0] = eta, in[1] = c;
    s0 = fresnel_dielectric(eta, c);
    if (eta_ok)
        check_bound("fresnel_dielectric", s0, ref_dielectric(eta, c), FRESNEL_BOUND_DIELECTRIC, in, 2);
    else
        check_range("fresnel_dielectric", s0, in, 2);

    in[0] = f0, in[1] = eta, in[2] = kappa, in[3] = c;
    s0 = fresnel_cook_torrance(f0, eta, kappa, c);
    if (eta_ok && kappa_ok)
        check_bound("fresnel_cook_torrance", s0, ref_cook_torrance(f0, eta, kappa, c),
                    FRESNEL_BOUND_COOK_TORRANCE, in, 4);
    else
        check_range("fresnel_cook_torrance", s0, in, 4);
    s1 = fresnel_cook_torrance(f82, eta, kappa, c);
    s2 = fresnel_cook_torrance(r, eta, kappa, c);
    check_rgb("fresnel_cook_torrance_rgb", fresnel_cook_torrance_rgb(rgb3(f0, f82, r), eta, kappa, c), s0,
              s1, s2);

    fuzz_luts(&b, c, f0);
    return 0;
}
