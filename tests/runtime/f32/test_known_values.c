/* Known values and physical properties of the runtime and the reference,
 * the independent complex-amplitude cross-check of the reference, and the
 * documented input policy (clamping, NaN, Inf). */
#include <math.h>
#include <stdio.h>

#include "fresnel.h"
#include "grid.h"
#include "harness.h"
#include "common/reference.h"

#define NEAR(a, b, tol) (fabs((double)(a) - (double)(b)) <= (tol))

static void known_values(void)
{
    /* F0 = ((1.5-1)/(1.5+1))^2 = 0.04 exactly */
    CHECK("glass F0 = 0.04 (dielectric)", NEAR(fresnel_dielectric(1.5f, 1.0f), 0.04, 3e-8), "%.9g",
          fresnel_dielectric(1.5f, 1.0f));
    CHECK("glass F0 = 0.04 (conductor, kappa 0)", NEAR(fresnel_conductor(1.5f, 0.0f, 1.0f), 0.04, 3e-8),
          "%.9g", fresnel_conductor(1.5f, 0.0f, 1.0f));
    CHECK("glass F0 = 0.04 (f0_from_ior)", NEAR(fresnel_f0_from_ior(1.5f, 0.0f), 0.04, 3e-8), "%.9g",
          fresnel_f0_from_ior(1.5f, 0.0f));
    CHECK("glass F0 = 0.04 (lsk)", NEAR(fresnel_lsk(1.5f, 0.0f, 1.0f), 0.04, 3e-8), "%.9g",
          fresnel_lsk(1.5f, 0.0f, 1.0f));
    CHECK("reference glass F0 = 0.04", NEAR(ref_dielectric(1.5, 1.0), 0.04, 1e-16), "%.17g",
          ref_dielectric(1.5, 1.0));
    {
        /* R = 1 at grazing incidence for every interface but matched index */
        static const float etas[] = {0.01f, 0.5f, 0.9f, 1.01f, 1.5f, 2.42f, 100.0f};
        static const float kappas[] = {0.0f, 1e-6f, 0.5f, 3.5f, 1000.0f};
        int i, j, ok = 1;
        for (i = 0; i < 7; i++)
            for (j = 0; j < 5; j++)
                ok &= fresnel_conductor(etas[i], kappas[j], 0.0f) == 1.0f &&
                      (kappas[j] > 0.0f || fresnel_dielectric(etas[i], 0.0f) == 1.0f) &&
                      ref_conductor(etas[i], kappas[j], 0.0) == 1.0;
        CHECK("R = 1 at c = 0", ok, "some interface did not reflect fully at grazing");
    }
    {
        /* Brewster: tan(theta_B) = eta, so Rp = 0 and R = Rs / 2 */
        static const double etas[] = {1.33, 1.5, 2.42, 1.0 / 1.5};
        int i;
        for (i = 0; i < 4; i++) {
            double e = etas[i], cb = 1.0 / sqrt(1.0 + e * e), rs, rp, rs2, rp2;
            ref_conductor_sp(e, 0.0, cb, &rs, &rp);
            ref_conductor_complex_sp(e, 0.0, cb, &rs2, &rp2);
            CHECK("Brewster angle: Rp = 0 (reference, both forms)", rp < 1e-30 && rp2 < 1e-30,
                  "eta %g: rp %.3g / %.3g", e, rp, rp2);
            CHECK("Brewster angle: runtime R = Rs/2", NEAR(fresnel_dielectric((float)e, (float)cb), rs / 2, 3e-7),
                  "eta %g: %.9g vs %.9g", e, fresnel_dielectric((float)e, (float)cb), rs / 2);
        }
    }
    {
        /* Reciprocity: air->glass at theta equals glass->air at the refracted
         * angle. Near grazing the refracted angle approaches the critical one,
         * where R has infinite slope, so the runtime is allowed twice its bound
         * plus slope x (the rounding of the refracted cosine to binary32). */
        double worst = 0.0, worst_ref = 0.0;
        int i;
        for (i = 1; i <= 200; i++) {
            double ci = i / 200.0, e = 1.5;
            double ct = sqrt(1.0 - (1.0 - ci * ci) / (e * e));
            float ctf = (float)ct, eif = (float)(1.0 / e);
            double slope = (ref_dielectric(eif, ct + 1e-9) - ref_dielectric(eif, ct - 1e-9)) / 2e-9;
            double a = fresnel_dielectric((float)e, (float)ci), b = fresnel_dielectric(eif, ctf);
            double ra = ref_dielectric(e, ci), rb = ref_dielectric(1.0 / e, ct);
            double excess = fabs(a - b) - (2.0 * FRESNEL_BOUND_DIELECTRIC + fabs(slope) * fabs(ctf - ct) +
                                           fabs(ref_dielectric(eif, ct) - rb));
            if (excess > worst)
                worst = excess;
            if (fabs(ra - rb) > worst_ref)
                worst_ref = fabs(ra - rb);
        }
        CHECK("air->glass equals glass->air at corresponding angles (runtime)", worst <= 0.0,
              "exceeds the allowance by %.3g", worst);
        CHECK("air->glass equals glass->air at corresponding angles (reference)", worst_ref < 1e-13,
              "max diff %.3g", worst_ref);
    }
    {
        /* Total internal reflection, continuity at the critical angle, monotone external reflection */
        static const float etas[] = {1.0f / 1.5f, 1.0f / 2.42f, 1.0f / 1.33f, 0.999f, 0.05f};
        int i, ok_tir = 1, ok_cont = 1, ok_mono = 1;
        for (i = 0; i < 5; i++) {
            double e = etas[i];
            float cc = (float)sqrt((1.0 - e) * (1.0 + e)); /* critical cosine */
            float below = nextafterf(cc, 0.0f), k;
            ok_tir &= fresnel_dielectric(etas[i], below) == 1.0f &&
                      fresnel_dielectric(etas[i], cc * 0.5f) == 1.0f &&
                      fresnel_schlick_internal(0.04f, etas[i], below) == 1.0f;
            /* just past the critical angle R is within the physics' slope of 1 */
            for (k = cc; k <= cc + 1e-5f; k = nextafterf(k, 2.0f)) {
                double r = fresnel_dielectric(etas[i], k), rr = ref_dielectric(etas[i], k);
                ok_cont &= fabs(r - rr) <= FRESNEL_BOUND_DIELECTRIC;
            }
        }
        for (i = 1; i <= 4096; i++) {
            float c0 = (i - 1) / 4096.0f, c1 = i / 4096.0f;
            ok_mono &= fresnel_dielectric(1.5f, c1) <= fresnel_dielectric(1.5f, c0);
        }
        CHECK("total internal reflection past the critical angle", ok_tir, "R != 1 under TIR");
        CHECK("continuous and accurate just inside the critical angle", ok_cont, "error above bound near c_crit");
        CHECK("external dielectric reflection decreases with c", ok_mono, "not monotone");
    }
    CHECK("matched index gives 0 at every c",
          fresnel_dielectric(1.0f, 0.0f) == 0.0f && fresnel_dielectric(1.0f, 1e-30f) == 0.0f &&
              fresnel_conductor(1.0f, 0.0f, 0.0f) == 0.0f && fresnel_conductor(1.0f, 0.0f, 0.5f) == 0.0f &&
              ref_conductor(1.0, 0.0, 0.0) == 0.0 && ref_dielectric(1.0, 1e-30) == 0.0,
          "matched index reflected");
    {
        /* LSK rescaled is Schlick with the exact F0 (for one IOR) */
        double worst = 0.0;
        int i;
        for (i = 0; i <= 100; i++) {
            double c = i / 100.0;
            double d = fabs(ref_lsk(0.2, 3.5, c) - ref_schlick(ref_f0_from_ior(0.2, 3.5), c));
            if (d > worst)
                worst = d;
        }
        CHECK("LSK rescaled == Schlick(exact F0)", worst < 1e-15, "diff %.3g", worst);
    }
    CHECK("F82 model passes through F82 at c = 1/7",
          NEAR(ref_f82(0.9, 0.8, 1.0 / 7.0), 0.8, 1e-15) && NEAR(fresnel_f82(0.9f, 0.8f, 1.0f / 7.0f), 0.8, 5e-7),
          "%.17g %.9g", ref_f82(0.9, 0.8, 1.0 / 7.0), fresnel_f82(0.9f, 0.8f, 1.0f / 7.0f));
    CHECK("F82 model leaving [0,1] is clamped",
          fresnel_f82(0.02f, 1.0f, 0.05f) <= 1.0f && fresnel_f82(0.98f, 0.0f, 1.0f / 7.0f) == 0.0f,
          "%.9g %.9g", fresnel_f82(0.02f, 1.0f, 0.05f), fresnel_f82(0.98f, 0.0f, 1.0f / 7.0f));
    CHECK("external medium: F0 of the medium itself becomes 0",
          NEAR(fresnel_f0_in_medium(fresnel_f0_from_ior(1.33f, 0.0f), 1.33f), 0.0, 1e-9), "%.9g",
          fresnel_f0_in_medium(fresnel_f0_from_ior(1.33f, 0.0f), 1.33f));
    {
        /* the dielectric adjustment is exact for dielectrics: glass in water = eta 1.5/1.33 */
        double want = ref_f0_from_ior(1.5 / 1.33, 0.0);
        CHECK("external medium: glass in water", NEAR(fresnel_f0_in_medium(0.04f, 1.33f), want, 4e-7),
              "%.9g vs %.9g", fresnel_f0_in_medium(0.04f, 1.33f), want);
    }
}

static void gulbrandsen_round_trip(void)
{
    double worst = 0.0, worst_f = 0.0;
    int ir, ig;
    for (ir = 0; ir <= 40; ir++)
        for (ig = 0; ig <= 40; ig++) {
            double r = 0.98 * ir / 40.0, g = ig / 40.0, n, k, r2, g2;
            fresnel_nk nk;
            fresnel_rg rg;
            ref_gulbrandsen_nk(r, g, &n, &k);
            ref_gulbrandsen_rg(n, k, &r2, &g2);
            if (r > 0.0 && fabs(r2 - r) + fabs(g2 - g) > worst)
                worst = fabs(r2 - r) + fabs(g2 - g);
            nk = fresnel_gulbrandsen_nk((float)r, (float)g);
            rg = fresnel_gulbrandsen_rg(nk.n, nk.k);
            if (r > 0.0 && fabs(rg.r - r) + fabs(rg.g - g) > worst_f)
                worst_f = fabs(rg.r - r) + fabs(rg.g - g);
        }
    NOTE("Gulbrandsen r,g -> n,k -> r,g: max error %.3g (double), %.3g (binary32)", worst, worst_f);
    CHECK("Gulbrandsen round trip (reference)", worst < 1e-9, "%.3g", worst);
    CHECK("Gulbrandsen round trip (binary32, r <= 0.98)", worst_f < 5e-4, "%.3g", worst_f);
    {
        /* the paper's closed form for k, in long double, at moderate r */
        long double r = 0.6L, g = 0.3L, sr = sqrtl(r);
        long double n = g * (1 - r) / (1 + r) + (1 - g) * (1 + sr) / (1 - sr);
        long double k = sqrtl((r * (n + 1) * (n + 1) - (n - 1) * (n - 1)) / (1 - r));
        double n2, k2;
        ref_gulbrandsen_nk((double)r, (double)g, &n2, &k2);
        CHECK("Gulbrandsen factored k equals the paper's form", fabsl(k - k2) < 1e-13L && fabsl(n - n2) < 1e-13L,
              "%.17Lg vs %.17g", k, k2);
    }
}

static void complex_cross_check(void)
{
    float cs[2048];
    int nc = grid_cos(cs, 2048), ie, ik, ic;
    double worst = 0.0;
    long count = 0;
    for (ie = 0; ie < GRID_ETA_N; ie++)
        for (ik = 0; ik < GRID_KAPPA_N; ik++)
            for (ic = 0; ic < nc; ic++) {
                double e = grid_eta(ie), k = grid_kappa(ik), c = cs[ic];
                double a = ref_conductor(e, k, c), b = ref_conductor_complex(e, k, c);
                /* relative, with an absolute floor for results that are 0 in one form and 1e-33 in the other */
                double rel = fabs(a - b) / fmax(fmax(a, b), 1e-4);
                count++;
                if (rel > worst)
                    worst = rel;
            }
    NOTE("reference a^2/b^2 vs complex amplitudes: max relative difference %.3g over %ld points", worst, count);
    CHECK("reference cross-check to 1e-12 relative", worst <= 1e-12, "%.3g", worst);
}

static void input_policy(void)
{
    const float nan = NAN, inf = INFINITY;
    fresnel_rgb f0 = {0.9f, 0.6f, 0.3f}, eta = {0.2f, 0.9f, 1.4f}, kap = {3.5f, 2.5f, 1.9f};
    fresnel_rgb v;
    CHECK("c > 1 is clamped to 1", fresnel_schlick(0.5f, 1.00001f) == 0.5f, "%.9g", fresnel_schlick(0.5f, 1.00001f));
    CHECK("c < 0 is clamped to 0", fresnel_schlick(0.5f, -0.3f) == 1.0f, "%.9g", fresnel_schlick(0.5f, -0.3f));
    CHECK("c = NaN and -Inf give c = 0, +Inf gives 1",
          fresnel_schlick(0.5f, nan) == 1.0f && fresnel_schlick(0.5f, -inf) == 1.0f && fresnel_schlick(0.5f, inf) == 0.5f,
          "%.9g %.9g %.9g", fresnel_schlick(0.5f, nan), fresnel_schlick(0.5f, -inf), fresnel_schlick(0.5f, inf));
    CHECK("F0 above 1 is evaluated as 1", fresnel_schlick(1.04f, 0.5f) == 1.0f, "%.9g", fresnel_schlick(1.04f, 0.5f));
    CHECK("negative F0 is evaluated as 0", fresnel_schlick(-0.1f, 1.0f) == 0.0f, "%.9g", fresnel_schlick(-0.1f, 1.0f));
    {
        /* every function, every non-finite argument: a number in [0, 1] */
        const float odd[] = {nan, inf, -inf, -1.0f, 0.0f, 1e-30f, 2.0f, 1e30f};
        int a, b, c, ok = 1;
        for (a = 0; a < 8; a++)
            for (b = 0; b < 8; b++)
                for (c = 0; c < 8; c++) {
                    float x = odd[a], y = odd[b], z = odd[c];
                    float r[11];
                    fresnel_nk nk = fresnel_gulbrandsen_nk(x, y);
                    fresnel_rg rg = fresnel_gulbrandsen_rg(x, y);
                    int i;
                    r[0] = fresnel_schlick(x, z);
                    r[1] = fresnel_schlick_gen(x, y, z, odd[(a + b) % 8]);
                    r[2] = fresnel_schlick_internal(x, y, z);
                    r[3] = fresnel_lsk(x, y, z);
                    r[4] = fresnel_lsk_comp(x, y, z, odd[(a + c) % 8], odd[(b + c) % 8]);
                    r[5] = fresnel_f82(x, y, z);
                    r[6] = fresnel_gulbrandsen(x, y, z);
                    r[7] = fresnel_approx_conductor(x, y, z);
                    r[8] = fresnel_cook_torrance(x, y, z, odd[(a + b + c) % 8]);
                    r[9] = fresnel_conductor(x, y, z);
                    r[10] = fresnel_dielectric(x, z) + fresnel_f0_in_medium(x, y) * 0.0f;
                    for (i = 0; i < 11; i++)
                        ok &= r[i] >= 0.0f && r[i] <= 1.0f;
                    ok &= fresnel_f0_in_medium(x, y) >= 0.0f && fresnel_f0_in_medium(x, y) <= 1.0f;
                    ok &= fresnel_f0_from_ior(x, y) >= 0.0f && fresnel_f0_from_ior(x, y) <= 1.0f;
                    ok &= isfinite(nk.n) && isfinite(nk.k) && nk.n > 0.0f && nk.k >= 0.0f;
                    ok &= rg.r >= 0.0f && rg.r <= 1.0f && rg.g >= 0.0f && rg.g <= 1.0f;
                }
        CHECK("non-finite and out-of-domain inputs give results in [0, 1]", ok, "some result was NaN or out of range");
    }
    v = fresnel_conductor_rgb(eta, kap, 0.3f);
    CHECK("RGB = scalar per channel (conductor)",
          v.r == fresnel_conductor(eta.r, kap.r, 0.3f) && v.g == fresnel_conductor(eta.g, kap.g, 0.3f) &&
              v.b == fresnel_conductor(eta.b, kap.b, 0.3f),
          "mismatch");
    v = fresnel_cook_torrance_rgb(f0, 0.9f, 2.5f, 0.3f);
    CHECK("RGB = scalar per channel (Cook-Torrance)",
          v.r == fresnel_cook_torrance(f0.r, 0.9f, 2.5f, 0.3f) && v.b == fresnel_cook_torrance(f0.b, 0.9f, 2.5f, 0.3f),
          "mismatch");
    v = fresnel_schlick_rgb(f0, 0.3f);
    CHECK("RGB = scalar per channel (Schlick)", v.g == fresnel_schlick(f0.g, 0.3f), "mismatch");
}

int main(void)
{
    known_values();
    gulbrandsen_round_trip();
    complex_cross_check();
    input_policy();
    return harness_exit();
}
