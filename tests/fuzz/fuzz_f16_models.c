/* Differential fuzzing of the binary16 runtime (fresnel_f16.h) against the
 * double reference (gen/common/reference.c).
 *
 * Needs _Float16, which clang 14 on x86-64 lacks: `make fuzz` compiles this
 * file and src/f16/\*.c with gcc (ASan, UBSan and gcc's comparison tracing,
 * -fsanitize-coverage=trace-cmp, which libFuzzer's value profile reads) and
 * links them into the clang-built libFuzzer binary (see the Makefile's
 * fuzzing section and gcc_cov_stubs.c). Without _Float16 the target is empty.
 *
 * Inputs: every parameter as a binary16 value, either a raw 16-bit pattern
 * (NaN payloads, +-Inf, subnormals, -0) or a float rounded to binary16;
 * LUTs of 2 to FRESNEL_LUT_N_MAX_F16 nodes, tabulated from a fuzzed
 * material (total reflection included) or random nodes anywhere in the
 * documented node range (curves [0, 2], residuals [-1, 1]).
 * Oracle:
 *   - every result is a number in [0, 1] (a curve table's in [0, max(1,
 *     the nodes around c)]), whatever the input;
 *   - inside the documented domain (fresnel_f16.h ERROR BOUNDS: after the
 *     runtime's clamps, every input but kappa in (0, 1e-3)), |result -
 *     reference| <= FRESNEL_DOMAIN_*_F16, the reference evaluated at the
 *     binary16 values with the runtime's documented clamps (eta to
 *     [2^-10, 16], kappa to [0, 16], p to [2^-10, 64], LSK a and alpha to
 *     [0, 64], Gulbrandsen r to the largest half below 1 and its n, k to the
 *     domain), a LUT's at the table's values.
 * The largest error of each function is printed at exit (NOTE lines), the
 * measurement behind FRESNEL_DOMAIN_*_F16; with FUZZ_SAVE_WORST set to a
 * folder, each function's worst input is written there (worst_<function>),
 * for the seed corpus, whose replay holds it to the bound; with
 * FUZZ_MEASURE set, a result beyond its bound is measured, not a failure. */
#include "fuzz.h"

#include "fresnel_f16.h"
#include "common/reference.h"

#if FRESNEL_HAS_F16

typedef struct largest {
    const char *fn;
    double max;
    char where[256];
    uint8_t input[512];
    size_t size;
} largest;
static largest largests[24];
static int largest_count;
static const uint8_t *current_input;
static size_t current_size;

static void print_largest(void)
{
    const char *dir = getenv("FUZZ_SAVE_WORST");
    int i;
    for (i = 0; i < largest_count; i++) {
        printf("NOTE f16 fuzz: %s max |err| %.3g at %s\n", largests[i].fn, largests[i].max, largests[i].where);
        if (dir && largests[i].size) {
            char path[512];
            FILE *f;
            snprintf(path, sizeof path, "%s/worst_%s", dir, largests[i].fn);
            f = fopen(path, "wb");
            if (f) {
                fwrite(largests[i].input, 1, largests[i].size, f);
                fclose(f);
            }
        }
    }
    fflush(stdout);
}

static void note_error(const char *fn, double err, const char *args)
{
    int i;
    for (i = 0; i < largest_count && strcmp(largests[i].fn, fn); i++)
        ;
    if (i == largest_count) {
        if (largest_count == (int)(sizeof largests / sizeof largests[0]))
            return;
        if (largest_count == 0)
            atexit(print_largest);
        largest_count++;
        largests[i].fn = fn;
        largests[i].max = -1.0;
    }
    if (err > largests[i].max) {
        largests[i].max = err;
        snprintf(largests[i].where, sizeof largests[i].where, "%s", args);
        largests[i].size = current_size <= sizeof largests[i].input ? current_size : 0;
        if (largests[i].size)
            memcpy(largests[i].input, current_input, current_size);
    }
}

static fresnel_f16 fuzz_half(fuzz_bytes *b, float lo, float hi)
{
    uint8_t mode = fuzz_u8(b);
    if (mode % 3 == 0) {
        uint16_t bits = (uint16_t)((fuzz_u8(b) << 8) | fuzz_u8(b));
        fresnel_f16 h;
        memcpy(&h, &bits, sizeof h);
        return h;
    }
    return (fresnel_f16)fuzz_float(b, lo, hi);
}

/* The runtime's clamp of a binary16 input, in double; NaN gives lo. */
static double hclamp(fresnel_f16 x, double lo, double hi) { return ref_clamp((double)x, lo, hi); }

/* The oracle: a result in [0, top], and within bound of the reference
 * where the inputs are in the documented domain. */
static void check_top(const char *fn, fresnel_f16 got_h, double ref, double bound, double top, int in_domain,
                      const char *args)
{
    double got = (double)got_h, err = fabs(got - ref);
    if (!(got >= 0.0 && got <= top))
        FUZZ_FAIL("%s(%s) = %g, outside [0, %g]", fn, args, got, top);
    else if (in_domain) {
        note_error(fn, err, args);
        if (!(err <= bound) && !getenv("FUZZ_MEASURE"))
            FUZZ_FAIL("%s(%s) = %.6g, reference %.6g: |err| %.3g beyond FRESNEL_DOMAIN bound %.3g", fn, args, got,
                      ref, err, bound);
    }
}

static void check(const char *fn, fresnel_f16 got_h, double ref, double bound, int in_domain, const char *args)
{
    check_top(fn, got_h, ref, bound, 1.0, in_domain, args);
}

/* A table's nodes: 0, a material's exact curve at the nodes (and its
 * residual from Schlick at its F0); 1, random nodes in [0, 2] and [-1, 1];
 * 2, random nodes in [0, 1] and [-1/4, 1/4]. The random ones come from a
 * 64-bit LCG seeded by the input. */
static unsigned long long lcg_next(unsigned long long *st)
{
    *st = *st * 6364136223846793005ull + 1442695040888963407ull;
    return *st >> 11;
}

static void fuzz_luts(fuzz_bytes *b, fresnel_f16 c)
{
    static fresnel_f16 tab[FRESNEL_LUT_N_MAX_F16], res[FRESNEL_LUT_N_MAX_F16];
    static double dtab[FRESNEL_LUT_N_MAX_F16], dres[FRESNEL_LUT_N_MAX_F16];
    int n = 2 + (int)(((unsigned)fuzz_u8(b) << 8 | fuzz_u8(b)) % (FRESNEL_LUT_N_MAX_F16 - 1)), kind = fuzz_u8(b) % 3;
    int i, sp;
    double eta = hclamp(fuzz_half(b, 0.05f, 16.0f), FRESNEL_ETA_MIN_F16, 16.0);
    double kappa = hclamp(fuzz_half(b, 1e-3f, 16.0f), 0.0, 16.0);
    unsigned long long seed = fuzz_u32(b);
    fresnel_f16 f0 = (fresnel_f16)ref_f0_from_ior(eta, kappa);
    double cd = hclamp(c, 0.0, 1.0);
    char args[128];
    snprintf(args, sizeof args, "%s table n %d (eta %.6g kappa %.6g seed %llu), c %a",
             kind == 0 ? "curve" : "random", n, eta, kappa, seed, (double)c);
    for (sp = 0; sp < 2; sp++) {
        double x = sp == 0 ? sqrt(cd) : cd, pos = x * (n - 1), top;
        unsigned long long st = seed;
        int k;
        for (i = 0; i < n; i++) {
            double u = i / (double)(n - 1), cn = sp == 0 ? u * u : u, curve, r;
            if (kind == 0) {
                curve = ref_conductor(eta, kappa, cn);
                r = curve - ref_schlick((double)f0, cn);
            } else {
                double scale = kind == 1 ? 2.0 : 1.0;
                curve = scale * (double)lcg_next(&st) / 9007199254740992.0;
                r = scale * ((double)lcg_next(&st) / 4503599627370496.0 - 1.0) / (kind == 1 ? 2.0 : 4.0);
            }
            tab[i] = (fresnel_f16)curve;
            res[i] = (fresnel_f16)r;
            dtab[i] = (double)tab[i];
            dres[i] = (double)res[i];
        }
        k = (int)pos < n - 1 ? (int)pos : n - 2;
        top = dtab[k] > dtab[k + 1] ? dtab[k] : dtab[k + 1];
        top = top > 1.0 ? top : 1.0;
        check_top(sp ? "fresnel_lut_linear_f16" : "fresnel_lut_f16",
                  sp ? fresnel_lut_linear_f16(tab, n, c) : fresnel_lut_f16(tab, n, c),
                  ref_clamp(ref_lut(dtab, n, 0, x), 0.0, top), FRESNEL_DOMAIN_LUT_F16, top, 1, args);
        check(sp ? "fresnel_lut_linear_residual_f16" : "fresnel_lut_residual_f16",
              sp ? fresnel_lut_linear_residual_f16(f0, res, n, c) : fresnel_lut_residual_f16(f0, res, n, c),
              ref_clamp(ref_schlick((double)f0, cd) + ref_lut(dres, n, 0, x), 0.0, 1.0),
              FRESNEL_DOMAIN_LUT_RESIDUAL_F16, 1, args);
        if (sp == 0)
            check_top("fresnel_lut_cubic_f16", fresnel_lut_cubic_f16(tab, n, c),
                      ref_clamp(ref_lut(dtab, n, 1, x), 0.0, top), FRESNEL_DOMAIN_LUT_CUBIC_F16, top, 1, args);
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz_bytes b;
    fresnel_f16 c, eta, kappa, f0, f82, f90, p, a, alpha, r, g;
    double cd, e, k, pd, ad, al, n, kk;
    int in;
    char args[256];
    b.p = data;
    b.n = size;
    c = fuzz_half(&b, 1e-4f, 1.0f);
    eta = fuzz_half(&b, 0.01f, 16.0f);
    kappa = fuzz_half(&b, 1e-3f, 16.0f);
    f0 = fuzz_half(&b, 1e-3f, 1.0f);
    f82 = fuzz_half(&b, 1e-3f, 1.0f);
    f90 = fuzz_half(&b, 1e-3f, 1.0f);
    p = fuzz_half(&b, 0.25f, 40.0f);
    a = fuzz_half(&b, 0.02f, 32.0f);
    alpha = fuzz_half(&b, 0.1f, 64.0f);
    r = fuzz_half(&b, 1e-3f, 1.0f);
    g = fuzz_half(&b, 1e-3f, 1.0f);
    /* What the runtime evaluates, by fresnel_f16.h's clamps. */
    cd = (double)c;
    e = hclamp(eta, FRESNEL_ETA_MIN_F16, FRESNEL_ETA_MAX_F16);
    k = hclamp(kappa, 0.0, FRESNEL_KAPPA_MAX_F16);
    pd = hclamp(p, FRESNEL_P_MIN_F16, FRESNEL_P_MAX_F16);
    ad = hclamp(a, 0.0, 64.0);
    al = hclamp(alpha, 0.0, FRESNEL_P_MAX_F16);
    /* The domain of the bounds: kappa 0 or at least 1e-3 (fresnel_f16.h). */
    in = k == 0.0 || k >= 1e-3;
    current_input = data;
    current_size = size;
    snprintf(args, sizeof args, "c %a eta %a kappa %a f0 %a f82 %a f90 %a p %a a %a alpha %a r %a g %a", cd,
             (double)eta, (double)kappa, (double)f0, (double)f82, (double)f90, (double)p, (double)a, (double)alpha,
             (double)r, (double)g);

    check("fresnel_schlick_f16", fresnel_schlick_f16(f0, c), ref_schlick((double)f0, cd), FRESNEL_DOMAIN_SCHLICK_F16,
          1, args);
    check("fresnel_schlick_gen_f16", fresnel_schlick_gen_f16(f0, f90, p, c),
          ref_schlick_gen((double)f0, (double)f90, pd, cd), FRESNEL_DOMAIN_SCHLICK_GEN_F16, 1, args);
    check("fresnel_f82_f16", fresnel_f82_f16(f0, f82, c), ref_f82((double)f0, (double)f82, cd),
          FRESNEL_DOMAIN_F82_F16, 1, args);
    check("fresnel_schlick_internal_f16", fresnel_schlick_internal_f16(f0, eta, c),
          ref_schlick_internal((double)f0, e, cd), FRESNEL_DOMAIN_SCHLICK_INTERNAL_F16, 1, args);
    check("fresnel_f0_in_medium_f16", fresnel_f0_in_medium_f16(f0, eta), ref_f0_in_medium((double)f0, e),
          FRESNEL_DOMAIN_F0_IN_MEDIUM_F16, 1, args);
    check("fresnel_f0_from_ior_f16", fresnel_f0_from_ior_f16(eta, kappa), ref_f0_from_ior(e, k),
          FRESNEL_DOMAIN_F0_FROM_IOR_F16, in, args);
    check("fresnel_lsk_f16", fresnel_lsk_f16(eta, kappa, c), ref_lsk(e, k, cd), FRESNEL_DOMAIN_LSK_F16, in, args);
    check("fresnel_lsk_comp_f16", fresnel_lsk_comp_f16(eta, kappa, a, alpha, c), ref_lsk_comp(e, k, ad, al, cd),
          FRESNEL_DOMAIN_LSK_COMP_F16, in, args);
    check("fresnel_approx_conductor_f16", fresnel_approx_conductor_f16(eta, kappa, c), ref_approx_conductor(e, k, cd),
          FRESNEL_DOMAIN_APPROX_CONDUCTOR_F16, in, args);
    check("fresnel_conductor_f16", fresnel_conductor_f16(eta, kappa, c), ref_conductor(e, k, cd),
          FRESNEL_DOMAIN_CONDUCTOR_F16, in, args);
    check("fresnel_dielectric_f16", fresnel_dielectric_f16(eta, c), ref_dielectric(e, cd),
          FRESNEL_DOMAIN_DIELECTRIC_F16, 1, args);
    check("fresnel_cook_torrance_f16", fresnel_cook_torrance_f16(f0, eta, kappa, c),
          ref_cook_torrance((double)f0, e, k, cd), FRESNEL_DOMAIN_COOK_TORRANCE_F16, in, args);
    /* Gulbrandsen: r to the largest half below 1, then n, k to the domain. */
    ref_gulbrandsen_nk(hclamp(r, 0.0, 1.0 - 0x1p-11), (double)g, &n, &kk);
    check("fresnel_gulbrandsen_f16", fresnel_gulbrandsen_f16(r, g, c),
          ref_approx_conductor(ref_clamp(n, FRESNEL_ETA_MIN_F16, FRESNEL_ETA_MAX_F16),
                               ref_clamp(kk, 0.0, FRESNEL_KAPPA_MAX_F16), cd),
          FRESNEL_DOMAIN_GULBRANDSEN_F16, 1, args);
    fuzz_luts(&b, c);
    return 0;
}

#else

/* No _Float16 in this compiler: nothing to fuzz (fresnel_f16.h declares nothing). */
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    (void)data;
    (void)size;
    return 0;
}

#endif
