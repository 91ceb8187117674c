/* The accuracy of the rows of the library's speed targets (see bench_targets.h). */
#include "bench/bench_targets.h"

#include <math.h>
#include <stdint.h>
#include <string.h>

#include "bench/bench_compare.h"
#include "fresnel.h"
#include "fresnel_q15.h"
#include "fresnel_q15_fast.h"
#include "common/reference.h"

/* ---- rows */
enum {
    R_SCHLICK,
    R_SCHLICK_Q15,
    R_CONDUCTOR,
    R_PREPARED,
    R_BATCH,
    R_MITSUBA,
    R_PBRT,
    R_LUT16,
    R_LUT32,
    R_LUT16_Q15,
    R_LUT32_Q15,
    R_LUT16_LIN,
    R_LUT16_LIN_Q15,
    R_LUT16_CUBIC,
    R_LUT16_CUBIC_Q15,
    R_LUT32_Q15_FAST,
    R_COUNT
};

static const char *const rows_def[R_COUNT] = {
    "schlick",
    "schlick-q15",
    "conductor",
    "conductor-prepared",
    "conductor-batch",
    "mitsuba-style",
    "pbrt-style",
    "lut16-f32",
    "lut32-f32",
    "lut16-q15",
    "lut32-q15",
    "lut16-linear-f32",
    "lut16-linear-q15",
    "lut16-cubic-f32",
    "lut16-cubic-q15",
    "lut32-q15-fast",
};

typedef char targets_rows_fit[R_COUNT <= BENCH_TARGET_ROWS ? 1 : -1];

typedef struct targets_ctx {
    float lut16[16], lut32[32], lin16[16];
    uint16_t q16[16], q32[32], qlin16[16]; /* lut16, lut32 also serve the cubic rows */
} targets_ctx;

/* Tables of ref_conductor(eta, kappa) at the nodes: uniform in sqrt(c)
 * (fresnel_lut) or in c (fresnel_lut_linear), binary32 and Q15 codes. */
static void make_tables(float eta, float kappa, targets_ctx *t)
{
    int i;
    for (i = 0; i < 32; i++) {
        double x = i / 31.0;
        t->lut32[i] = (float)ref_conductor(eta, kappa, x * x);
        t->q32[i] = (uint16_t)lround(ref_conductor(eta, kappa, x * x) * 32768.0);
    }
    for (i = 0; i < 16; i++) {
        double x = i / 15.0;
        t->lut16[i] = (float)ref_conductor(eta, kappa, x * x);
        t->q16[i] = (uint16_t)lround(ref_conductor(eta, kappa, x * x) * 32768.0);
        t->lin16[i] = (float)ref_conductor(eta, kappa, x);
        t->qlin16[i] = (uint16_t)lround(ref_conductor(eta, kappa, x) * 32768.0);
    }
}

/* ---- errors */
#define GRID_ETA 49
#define GRID_KAPPA 49 /* 0, then 48 log-spaced in [0.01, 10] */
#define COS_MAX 2100

static float grid_eta_at(int i) { return (float)(0.1 * pow(50.0, i / (GRID_ETA - 1.0))); }
static float grid_kappa_at(int i) { return i == 0 ? 0.0f : (float)(0.01 * pow(1e3, (i - 1) / (GRID_KAPPA - 2.0))); }

static int cosines(float *c)
{
    static const float near[] = {0.0f, 1e-8f, 1e-7f, 1e-6f};
    int n = 0, i;
    for (i = 0; i < 4; i++) {
        c[n++] = near[i];
        c[n++] = 1.0f - near[i];
    }
    for (i = 1; i < 1024; i++) {
        c[n++] = (float)(i / 1024.0);
        c[n++] = (float)cos(i / 1024.0 * 1.5707963267948966);
    }
    return n; /* 2054 */
}

static void worse(double *w, double got, double ref)
{
    double e = fabs(got - ref);
    if (!(e <= *w)) /* NaN sticks */
        *w = isnan(e) ? NAN : e;
}

static void measure_errors(double *err)
{
    static float c[COS_MAX], batch_out[COS_MAX];
    static double ref[COS_MAX];
    int nc = cosines(c), ie, ik, i, f;
    for (i = 0; i < R_COUNT; i++)
        err[i] = 0.0;
    for (f = 0; f <= 64; f++)
        for (i = 0; i < nc; i++) {
            float f0 = (float)(f / 64.0);
            int32_t cq = (int32_t)lround(c[i] * 32768.0), f0q = (int32_t)lround(f0 * 32768.0);
            worse(&err[R_SCHLICK], fresnel_schlick(f0, c[i]), ref_schlick(f0, c[i]));
            worse(&err[R_SCHLICK_Q15], fresnel_schlick_q15(f0q, cq) / 32768.0, ref_schlick(f0q / 32768.0, cq / 32768.0));
        }
    for (ie = 0; ie < GRID_ETA; ie++)
        for (ik = 0; ik < GRID_KAPPA; ik++) {
            float eta = grid_eta_at(ie), kappa = grid_kappa_at(ik);
            fresnel_conductor_prep p = fresnel_conductor_prepare(eta, kappa);
            targets_ctx t;
            fresnel_conductor_batch(&p, c, batch_out, nc);
            for (i = 0; i < nc; i++) {
                ref[i] = ref_conductor(eta, kappa, c[i]);
                worse(&err[R_CONDUCTOR], fresnel_conductor(eta, kappa, c[i]), ref[i]);
                worse(&err[R_PREPARED], fresnel_conductor_prepared(&p, c[i]), ref[i]);
                worse(&err[R_BATCH], batch_out[i], ref[i]);
                worse(&err[R_MITSUBA], cmp_mitsuba_conductor(eta, kappa, c[i]), ref[i]);
                worse(&err[R_PBRT], cmp_pbrt_conductor(eta, kappa, c[i]), ref[i]);
            }
            if (kappa < 1.0f)
                continue;
            make_tables(eta, kappa, &t);
            for (i = 0; i < nc; i++) {
                int32_t cq = (int32_t)lround(c[i] * 32768.0);
                double ref_q = ref_conductor(eta, kappa, cq / 32768.0);
                worse(&err[R_LUT16], fresnel_lut(t.lut16, 16, c[i]), ref[i]);
                worse(&err[R_LUT32], fresnel_lut(t.lut32, 32, c[i]), ref[i]);
                worse(&err[R_LUT16_LIN], fresnel_lut_linear(t.lin16, 16, c[i]), ref[i]);
                worse(&err[R_LUT16_Q15], fresnel_lut_u16_q15(t.q16, 16, cq) / 32768.0, ref_q);
                worse(&err[R_LUT32_Q15], fresnel_lut_u16_q15(t.q32, 32, cq) / 32768.0, ref_q);
                worse(&err[R_LUT16_LIN_Q15], fresnel_lut_linear_u16_q15(t.qlin16, 16, cq) / 32768.0, ref_q);
                worse(&err[R_LUT16_CUBIC], fresnel_lut_cubic(t.lut16, 16, c[i]), ref[i]);
                worse(&err[R_LUT16_CUBIC_Q15], fresnel_lut_cubic_u16_q15(t.q16, 16, cq) / 32768.0, ref_q);
                worse(&err[R_LUT32_Q15_FAST], fresnel_lut_u16_q15_fast(t.q32, 32, cq) / 32768.0, ref_q);
            }
        }
}

/* Matched index (eta = 1, kappa = 0) at c = 0 and c = 1e-4: exact answer 0. */
static void matched(int row, double *at0, double *at1e4)
{
    fresnel_conductor_prep p = fresnel_conductor_prepare(1.0f, 0.0f);
    const float cs[2] = {0.0f, 1e-4f};
    float out[2];
    int i;
    for (i = 0; i < 2; i++) {
        double v;
        switch (row) {
        case R_CONDUCTOR: v = fresnel_conductor(1.0f, 0.0f, cs[i]); break;
        case R_PREPARED: v = fresnel_conductor_prepared(&p, cs[i]); break;
        case R_BATCH: fresnel_conductor_batch(&p, cs, out, 2); v = out[i]; break;
        case R_MITSUBA: v = cmp_mitsuba_conductor(1.0f, 0.0f, cs[i]); break;
        case R_PBRT: v = cmp_pbrt_conductor(1.0f, 0.0f, cs[i]); break;
        default: v = -1.0; /* not a conductor row */
        }
        *(i ? at1e4 : at0) = v;
    }
}

int bench_target_errors(bench_target_row *rows, int max_rows)
{
    double err[R_COUNT];
    int i, n = max_rows < R_COUNT ? max_rows : R_COUNT;
    measure_errors(err);
    for (i = 0; i < n; i++) {
        rows[i].name = rows_def[i];
        rows[i].max_abs_err = err[i];
        matched(i, &rows[i].matched_c0, &rows[i].matched_c1e4);
    }
    return n < 0 ? 0 : n;
}
