/* fresnel_conductor_batch and fresnel_conductor_rgb_batch against
 * fresnel_conductor_prepared, lane by lane and bit for bit, on a dense
 * eta x kappa x c grid with the edge inputs (NaN, +-Inf, -0, c > 1,
 * subnormal c; eta, kappa out of range; each form: matched index,
 * dielectric, conductor, tiny eta kappa), at every length 0..3 vectors and
 * every offset 0..3, each call on a copy of exactly n floats (ASan finds a
 * read past n) with guards after out (a write past n). The RGB batch with
 * each grid material in all three channels and with its two neighbours
 * (mostly one form: the one-pass kernel), and with triples of one form and
 * of mixed forms at every length and offset. Built for the host (every
 * pass) and for each SIMD kernel, AArch64 NEON under qemu included, by gcc
 * and clang in ISO C and the GNU modes (tests/runtime/f32/test_batch_simd.sh). Needs
 * only the library and libm. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fresnel.h"
#include "harness.h"

#define NC_GRID 1025
#define MAX_C (NC_GRID + 64)
#define MAX_LEN 67

static float cs[MAX_C];
static int ncs;

static void make_cosines(void)
{
    static const float edge[] = {0.0f, -0.0f, 1.0f, 2.0f, -1.0f, 1e-20f, 1e-45f, 1.1754944e-38f,
                                 0.99999994f, 1.0000001f, 0.5f, 0.70710677f, 1e-4f, 3.4e38f, -3.4e38f};
    int i;
    ncs = 0;
    for (i = 0; i < NC_GRID; i++)
        cs[ncs++] = (float)i / (NC_GRID - 1);
    for (i = 0; i < (int)(sizeof edge / sizeof edge[0]); i++)
        cs[ncs++] = edge[i];
    cs[ncs++] = NAN;
    cs[ncs++] = -NAN;
    cs[ncs++] = INFINITY;
    cs[ncs++] = -INFINITY;
    /* shuffle the edges among the grid so every lane position meets them */
    for (i = NC_GRID; i < ncs; i++) {
        int j = (i * 37) % NC_GRID;
        float t = cs[i];
        cs[i] = cs[j];
        cs[j] = t;
    }
}

static int make_values(float *v, float lo, float hi, int n, const float *extra, int ne)
{
    int i, k = 0;
    for (i = 0; i < n; i++)
        v[k++] = lo * powf(hi / lo, (float)i / (float)(n - 1));
    for (i = 0; i < ne; i++)
        v[k++] = extra[i];
    return k;
}

static long differ_total, guard_bad, rgb_differ, rgb_guard_bad, n_calls;
static char first[200];

static int same(float a, float b) { return memcmp(&a, &b, sizeof a) == 0; }

/* batch of the n cosines at cs + off on an exact-size heap copy */
static void check_slice(const fresnel_conductor_prep *p, const float *want, int off, int n, float eta, float kappa)
{
    float *c = malloc(n > 0 ? (size_t)n * sizeof *c : 1);
    float *out = malloc(((size_t)n + 4) * sizeof *out);
    int i;
    if (!c || !out)
        abort();
    memcpy(c, cs + off, (size_t)n * sizeof *c);
    for (i = 0; i < n + 4; i++)
        out[i] = -7.0f;
    fresnel_conductor_batch(p, c, out, n);
    n_calls++;
    for (i = 0; i < n; i++)
        if (!same(out[i], want[off + i])) {
            if (!differ_total)
                snprintf(first, sizeof first, "eta %g kappa %g c %g: batch %.9g, prepared %.9g", eta, kappa,
                         cs[off + i], out[i], want[off + i]);
            differ_total++;
        }
    for (i = n; i < n + 4; i++)
        guard_bad += out[i] != -7.0f;
    free(c);
    free(out);
}

static void check_rgb(const fresnel_conductor_prep p[3], int off, int n)
{
    float *c = malloc(n > 0 ? (size_t)n * sizeof *c : 1);
    fresnel_rgb *out = malloc(((size_t)n + 2) * sizeof *out);
    int i;
    if (!c || !out)
        abort();
    memcpy(c, cs + off, (size_t)n * sizeof *c);
    for (i = 0; i < n + 2; i++)
        out[i].r = out[i].g = out[i].b = -7.0f;
    fresnel_conductor_rgb_batch(p, c, out, n);
    for (i = 0; i < n; i++)
        rgb_differ += !same(out[i].r, fresnel_conductor_prepared(&p[0], c[i])) +
                      !same(out[i].g, fresnel_conductor_prepared(&p[1], c[i])) +
                      !same(out[i].b, fresnel_conductor_prepared(&p[2], c[i]));
    for (i = n; i < n + 2; i++)
        rgb_guard_bad += out[i].r != -7.0f || out[i].g != -7.0f || out[i].b != -7.0f;
    free(c);
    free(out);
}

int main(void)
{
    static const float eta_extra[] = {1.0f, 0.99999994f, 1.0000001f, FRESNEL_ETA_MIN, FRESNEL_ETA_MAX, 1e-30f,
                                      1e30f, -1.0f, -0.0f, 0.0f, NAN, INFINITY, -INFINITY, 0.15f, 1.5f, 0.6666667f};
    static const float kappa_extra[] = {0.0f, -0.0f, 1e-19f, FRESNEL_KAPPA_TINY, 1e-12f, FRESNEL_KAPPA_MAX, 1e30f,
                                        -1.0f, NAN, INFINITY, -INFINITY, 3.5f};
    static float want3[3][MAX_C];
    static fresnel_rgb got3[MAX_C];
    float etas[64], kappas[64], want[MAX_C], got[MAX_C];
    fresnel_conductor_prep rgb[3], hist[3];
    long grid_rgb_differ = 0;
    int ne, nk, ei, ki, i, off, len, mats = 0, out_range = 0;
    make_cosines();
    ne = make_values(etas, FRESNEL_ETA_MIN, FRESNEL_ETA_MAX, 33, eta_extra, (int)(sizeof eta_extra / sizeof *eta_extra));
    nk = make_values(kappas + 1, 1e-18f, FRESNEL_KAPPA_MAX, 33, kappa_extra, (int)(sizeof kappa_extra / sizeof *kappa_extra)) + 1;
    kappas[0] = 0.0f;
    for (ei = 0; ei < ne; ei++)
        for (ki = 0; ki < nk; ki++) {
            fresnel_conductor_prep p = fresnel_conductor_prepare(etas[ei], kappas[ki]);
            for (i = 0; i < ncs; i++)
                want[i] = fresnel_conductor_prepared(&p, cs[i]);
            fresnel_conductor_batch(&p, cs, got, ncs);
            for (i = 0; i < ncs; i++) {
                out_range += !(got[i] >= 0.0f && got[i] <= 1.0f);
                if (!same(got[i], want[i])) {
                    if (!differ_total)
                        snprintf(first, sizeof first, "eta %g kappa %g c %g: batch %.9g, prepared %.9g", etas[ei],
                                 kappas[ki], cs[i], got[i], want[i]);
                    differ_total++;
                }
            }
            /* three channels: this material in each, and it with the two before it (mostly one form) */
            hist[0] = ki >= 2 ? hist[1] : p;
            hist[1] = ki >= 1 ? hist[2] : p;
            hist[2] = p;
            memcpy(want3[0], ki >= 2 ? want3[1] : want, sizeof want);
            memcpy(want3[1], ki >= 1 ? want3[2] : want, sizeof want);
            memcpy(want3[2], want, sizeof want);
            rgb[0] = rgb[1] = rgb[2] = p;
            fresnel_conductor_rgb_batch(rgb, cs, got3, ncs);
            for (i = 0; i < ncs; i++)
                grid_rgb_differ += !same(got3[i].r, want[i]) + !same(got3[i].g, want[i]) + !same(got3[i].b, want[i]);
            fresnel_conductor_rgb_batch(hist, cs, got3, ncs);
            for (i = 0; i < ncs; i++)
                grid_rgb_differ += !same(got3[i].r, want3[0][i]) + !same(got3[i].g, want3[1][i]) +
                                   !same(got3[i].b, want3[2][i]);
            if ((ei * nk + ki) % 23 == 0) { /* every length and offset on a sample of materials */
                for (off = 0; off < 4; off++)
                    for (len = 0; len <= MAX_LEN; len++)
                        check_slice(&p, want, off + 3 * len, len, etas[ei], kappas[ki]);
                check_slice(&p, want, 5, ncs - 5, etas[ei], kappas[ki]);
            }
            mats++;
        }
    CHECK("batch: fresnel_conductor_batch gives fresnel_conductor_prepared's result bit for bit in every lane "
          "(eta x kappa x c grid with NaN, Inf, -0, c > 1; every length 0..67 at offsets 0..3)",
          differ_total == 0, "%ld differ, first %s", differ_total, first);
    CHECK("batch: results in [0, 1] for every input", out_range == 0, "%d outside", out_range);
    CHECK("batch: nothing written at or beyond n", guard_bad == 0, "%ld guards overwritten", guard_bad);

    CHECK("batch: fresnel_conductor_rgb_batch gives each channel's fresnel_conductor_prepared bit for bit "
          "(every grid material in all three channels, and with the two materials before it)",
          grid_rgb_differ == 0, "%ld differ", grid_rgb_differ);

    /* three channels of different forms: conductor, dielectric, tiny eta kappa; and a matched channel */
    for (i = 0; i < 2; i++) {
        rgb[0] = fresnel_conductor_prepare(0.15f, 3.5f);
        rgb[1] = fresnel_conductor_prepare(i ? 1.0f : 0.6666667f, 0.0f);
        rgb[2] = fresnel_conductor_prepare(FRESNEL_ETA_MIN, i ? 1e-18f : 2.5f);
        for (off = 0; off < 4; off++)
            for (len = 0; len <= 3 * MAX_LEN; len++)
                check_rgb(rgb, off + len, len);
        check_rgb(rgb, 1, ncs - 1);
    }
    /* three channels of one form: conductors (copper), dielectrics with a critical angle, tiny eta kappa,
     * matched index */
    for (i = 0; i < 4; i++) {
        static const float mats3[4][3][2] = {{{0.27f, 3.4f}, {0.68f, 2.6f}, {1.22f, 2.3f}},
                                             {{0.6666667f, 0.0f}, {1.5f, 0.0f}, {0.75f, 0.0f}},
                                             {{FRESNEL_ETA_MIN, 1e-18f}, {1.0f, 1e-20f}, {0.5f, 1e-19f}},
                                             {{1.0f, 0.0f}, {1.0f, 0.0f}, {1.0f, 0.0f}}};
        int ch;
        for (ch = 0; ch < 3; ch++)
            rgb[ch] = fresnel_conductor_prepare(mats3[i][ch][0], mats3[i][ch][1]);
        for (off = 0; off < 4; off++)
            for (len = 0; len <= 3 * MAX_LEN; len++)
                check_rgb(rgb, off + len, len);
        check_rgb(rgb, 1, ncs - 1);
    }
    CHECK("batch: fresnel_conductor_rgb_batch gives each channel's fresnel_conductor_prepared bit for bit "
          "(lengths 0..201, offsets 0..3, three channels of one form and of mixed forms)",
          rgb_differ == 0, "%ld differ", rgb_differ);
    CHECK("batch: rgb_batch writes nothing at or beyond n", rgb_guard_bad == 0, "%ld overwritten", rgb_guard_bad);
    NOTE("batch: %d materials x %d cosines, %ld short calls", mats, ncs, n_calls);
    return harness_exit();
}
