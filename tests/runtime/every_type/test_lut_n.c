/* Every n for every LUT function (fresnel.h, fresnel_f16.h): the result of
 * each n is defined (n < 1 contributes 0, n = 1 is table[0], n above the
 * maximum uses the first maximum nodes) and no n reads outside the table.
 * The tables are exactly as long as the nodes the function may read, so the
 * ASan pass of `make test` catches any read past them. */
#include "fresnel.h"
#include "fresnel_f16.h"
#include "harness.h"

#include <limits.h>
#include <math.h>
#include <stdlib.h>

static const int ns[] = {INT_MIN, -1, 0, 1, 2, 3, 4, 255, FRESNEL_LUT_N_MAX - 1, FRESNEL_LUT_N_MAX,
                         FRESNEL_LUT_N_MAX + 1, 65521, 1 << 24, (1 << 24) + 1, INT_MAX};
#define NN ((int)(sizeof ns / sizeof ns[0]))

/* The ends of a table (c 0, c 1) are interpolated, not copied: a few
 * roundings of a node step (binary32 ulp(1) 1.2e-7, binary16 9.8e-4). */
#define END_TOL 1e-6f
#define END_TOL_H 4e-3f

static float unit(float x) { return x > 0.0f ? (x < 1.0f ? x : 1.0f) : 0.0f; }

/* node values in [-0.25, 1.25]: the clamp of the result is exercised too */
static float node(int i) { return (float)((i * 37) % 61) / 40.0f - 0.25f; }

typedef float (*plain_fn)(const float *, int, float);
typedef float (*resid_fn)(float, const float *, int, float);

static void check_float(void)
{
    static const float cs[] = {-1.0f, 0.0f, 0.5f, 1.0f, 0x1.000002p0f, 1e30f, INFINITY, -INFINITY, NAN};
    static const plain_fn plain[] = {fresnel_lut, fresnel_lut_linear, fresnel_lut_cubic};
    static const char *plain_name[] = {"fresnel_lut", "fresnel_lut_linear", "fresnel_lut_cubic"};
    static const resid_fn resid[] = {fresnel_lut_residual, fresnel_lut_linear_residual};
    static const char *resid_name[] = {"fresnel_lut_residual", "fresnel_lut_linear_residual"};
    int nmax = FRESNEL_LUT_N_MAX, len = 3 * (nmax + 1), i, k, f, ic;
    float *tab = malloc((size_t)len * sizeof *tab);
    char name[160];
    if (!tab) {
        CHECK("lut n: allocation", 0, "out of memory");
        return;
    }
    for (i = 0; i < len; i++)
        tab[i] = node(i);
    for (f = 0; f < 3; f++) {
        int bad = 0;
        for (k = 0; k < NN; k++) {
            int n = ns[k], used = n < 1 ? 0 : (n < nmax ? n : nmax);
            /* a table of exactly the nodes that may be read, at the end of the block */
            const float *t = used > 0 ? tab + len - used : tab + len;
            for (ic = 0; ic < (int)(sizeof cs / sizeof cs[0]); ic++) {
                float c = cs[ic], got = plain[f](t, n, c), want;
                float cc = c > 0.0f ? (c < 1.0f ? c : 1.0f) : 0.0f;
                if (n < 1)
                    want = 0.0f;
                else if (n == 1)
                    want = unit(t[0]);
                else if (n > nmax)
                    want = plain[f](t, nmax, c);
                else if (cc == 0.0f)
                    want = unit(t[0]);
                else if (cc == 1.0f)
                    want = unit(t[n - 1]);
                else
                    want = got; /* interior: only the range checks below */
                if (!(fabsf(got - want) <= (n >= 2 && n <= nmax ? END_TOL : 0.0f) && got >= 0.0f && got <= 1.0f)) {
                    if (bad++ < 3)
                        printf("  %s(n %d, c %a) = %a, want %a\n", plain_name[f], n, (double)c, (double)got,
                               (double)want);
                }
            }
        }
        snprintf(name, sizeof name, "%s: n in {INT_MIN .. INT_MAX}, c in {-1, 0, .5, 1, 1+ulp, 1e30, inf, nan}",
                 plain_name[f]);
        CHECK(name, bad == 0, "%d wrong results", bad);
    }
    for (f = 0; f < 2; f++) {
        int bad = 0;
        for (k = 0; k < NN; k++) {
            int n = ns[k], used = n < 1 ? 0 : (n < nmax ? n : nmax);
            const float *t = used > 0 ? tab + len - used : tab + len;
            for (ic = 0; ic < (int)(sizeof cs / sizeof cs[0]); ic++) {
                float c = cs[ic], f0 = 0.3f, got = resid[f](f0, t, n, c), want;
                float cc = c > 0.0f ? (c < 1.0f ? c : 1.0f) : 0.0f;
                if (n < 1)
                    want = fresnel_schlick(f0, c);
                else if (n == 1)
                    want = unit(fresnel_schlick(f0, c) + t[0]);
                else if (n > nmax)
                    want = resid[f](f0, t, nmax, c);
                else if (cc == 1.0f)
                    want = unit(fresnel_schlick(f0, c) + t[n - 1]);
                else
                    want = got;
                if (!(fabsf(got - want) <= (n >= 2 && n <= nmax ? END_TOL : 0.0f) && got >= 0.0f && got <= 1.0f)) {
                    if (bad++ < 3)
                        printf("  %s(n %d, c %a) = %a, want %a\n", resid_name[f], n, (double)c, (double)got,
                               (double)want);
                }
            }
        }
        snprintf(name, sizeof name, "%s: n in {INT_MIN .. INT_MAX}: < 1 Schlick, 1 Schlick + table[0], > max as max",
                 resid_name[f]);
        CHECK(name, bad == 0, "%d wrong results", bad);
    }
    /* RGB: channel k of n nodes starts at table + k n; the table holds 3n */
    {
        static const int rn[] = {INT_MIN, -1, 0, 1, 2, 3, 4, FRESNEL_LUT_N_MAX, FRESNEL_LUT_N_MAX + 1};
        int bad = 0;
        for (k = 0; k < (int)(sizeof rn / sizeof rn[0]); k++) {
            int n = rn[k], used = n < 1 ? 0 : n;
            const float *t = tab + len - 3 * used;
            for (ic = 0; ic < (int)(sizeof cs / sizeof cs[0]); ic++) {
                float c = cs[ic];
                fresnel_rgb f0 = {0.1f, 0.5f, 0.9f}, g[6], w[6];
                int j;
                g[0] = fresnel_lut_rgb(t, n, c);
                g[1] = fresnel_lut_linear_rgb(t, n, c);
                g[2] = fresnel_lut_cubic_rgb(t, n, c);
                g[3] = fresnel_lut_residual_rgb(f0, t, n, c);
                g[4] = fresnel_lut_linear_residual_rgb(f0, t, n, c);
                g[5] = g[0];
                for (j = 0; j < 3; j++) {
                    w[j].r = plain[j](t, n, c);
                    w[j].g = plain[j](t + used, n, c);
                    w[j].b = plain[j](t + 2 * used, n, c);
                }
                for (j = 0; j < 2; j++) {
                    w[3 + j].r = resid[j](f0.r, t, n, c);
                    w[3 + j].g = resid[j](f0.g, t + used, n, c);
                    w[3 + j].b = resid[j](f0.b, t + 2 * used, n, c);
                }
                w[5] = w[0];
                for (j = 0; j < 6; j++)
                    if (!(g[j].r == w[j].r && g[j].g == w[j].g && g[j].b == w[j].b) && bad++ < 3)
                        printf("  rgb form %d (n %d, c %a): channel mismatch\n", j, n, (double)c);
            }
        }
        CHECK("fresnel_lut*_rgb: n in {INT_MIN, -1, 0 .. 4, max, max+1}: each channel as the scalar form on its n nodes",
              bad == 0, "%d wrong results", bad);
    }
    free(tab);
}

#if FRESNEL_HAS_F16
typedef fresnel_f16 (*plain_h)(const fresnel_f16 *, int, fresnel_f16);
typedef fresnel_f16 (*resid_h)(fresnel_f16, const fresnel_f16 *, int, fresnel_f16);

static fresnel_f16 res_lut(fresnel_f16 f0, const fresnel_f16 *t, int n, fresnel_f16 c)
{
    return fresnel_lut_residual_f16(f0, t, n, c);
}

static void check_f16(void)
{
    static const float cs[] = {-1.0f, 0.0f, 0.5f, 1.0f, 1.0f + 1.0f / 1024.0f, 65504.0f, INFINITY, -INFINITY, NAN};
    static const int hn[] = {INT_MIN, -1, 0, 1, 2, 3, 4, 255, FRESNEL_LUT_N_MAX_F16 - 1, FRESNEL_LUT_N_MAX_F16,
                             FRESNEL_LUT_N_MAX_F16 + 1, 65521, 1 << 24, INT_MAX};
    static const plain_h plain[] = {fresnel_lut_f16, fresnel_lut_linear_f16, fresnel_lut_cubic_f16};
    static const char *plain_name[] = {"fresnel_lut_f16", "fresnel_lut_linear_f16", "fresnel_lut_cubic_f16"};
    static const resid_h resid[] = {res_lut, fresnel_lut_linear_residual_f16};
    static const char *resid_name[] = {"fresnel_lut_residual_f16", "fresnel_lut_linear_residual_f16"};
    int nmax = FRESNEL_LUT_N_MAX_F16, len = nmax, i, k, f, ic;
    fresnel_f16 *tab = malloc((size_t)len * sizeof *tab);
    char name[160];
    if (!tab) {
        CHECK("lut n f16: allocation", 0, "out of memory");
        return;
    }
    for (i = 0; i < len; i++)
        tab[i] = (fresnel_f16)node(i);
    for (f = 0; f < 5; f++) {
        int bad = 0;
        for (k = 0; k < (int)(sizeof hn / sizeof hn[0]); k++) {
            int n = hn[k], used = n < 1 ? 0 : (n < nmax ? n : nmax);
            const fresnel_f16 *t = tab + len - used;
            for (ic = 0; ic < (int)(sizeof cs / sizeof cs[0]); ic++) {
                fresnel_f16 c = (fresnel_f16)cs[ic], f0 = (fresnel_f16)0.3f;
                float cc = cs[ic] > 0.0f ? (cs[ic] < 1.0f ? cs[ic] : 1.0f) : 0.0f, got, want, base;
                base = f < 3 ? 0.0f : (float)fresnel_schlick_f16(f0, c);
                got = f < 3 ? (float)plain[f](t, n, c) : (float)resid[f - 3](f0, t, n, c);
                if (n < 1)
                    want = base;
                else if (n == 1)
                    want = (float)(fresnel_f16)unit((float)(fresnel_f16)(base + (float)t[0]));
                else if (n > nmax)
                    want = f < 3 ? (float)plain[f](t, nmax, c) : (float)resid[f - 3](f0, t, nmax, c);
                else if (cc == 0.0f && f < 3)
                    want = unit((float)t[0]);
                else if (cc == 1.0f && f < 3)
                    want = unit((float)t[n - 1]);
                else
                    want = got;
                if (!(fabsf(got - want) <= (n >= 2 && n <= nmax ? END_TOL_H : 0.0f) && got >= 0.0f && got <= 1.0f) &&
                    bad++ < 3)
                    printf("  %s(n %d, c %a) = %a, want %a\n",
                           f < 3 ? plain_name[f] : resid_name[f - 3], n, (double)cs[ic], (double)got, (double)want);
            }
        }
        snprintf(name, sizeof name, "%s: n in {INT_MIN .. INT_MAX}, c in {-1, 0, .5, 1, 1+ulp, 65504, inf, nan}",
                 f < 3 ? plain_name[f] : resid_name[f - 3]);
        CHECK(name, bad == 0, "%d wrong results", bad);
    }
    free(tab);
}
#endif

int main(void)
{
    check_float();
#if FRESNEL_HAS_F16
    check_f16();
#endif
    return harness_exit();
}
