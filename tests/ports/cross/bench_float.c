/* Instruction counts of the binary32 (fresnel.h) and binary16
 * (fresnel_f16.h) runtimes on a target, as tests/ports/cross/bench.c does for the
 * fixed-point one: same markers, same 33 cosines, copper at 550 nm. On the
 * Cortex-M0 both run on libgcc's soft-float and newlib's libm; on the
 * Cortex-M4F binary32 is the FPU and binary16 converts in hardware.
 * With BENCH_BATCH_N (the AArch64 build, ports/cross.sh) the conductor
 * batches join the binary32 rows: each call covers BENCH_BATCH_N cosines
 * uniform in [0, 1], and the row's name line carries that number after a
 * tab, so that ports/count.sh reports instructions per cosine, and so
 * do Schlick's RGB and the thin film's (fresnel_film.h). */
#include "conform.h"
#include "fresnel.h"
#include "fresnel_f16.h"
#include "fresnel_film.h"
#include "port.h"

#define BENCH_CODES 33

volatile float bench_sink;
static float lut[CONFORM_LUT_N], lut_linear[CONFORM_LUT_N], residual[CONFORM_LUT_N];

typedef float (*f32_eval)(const float *m, float c);
static float e_none(const float *m, float c) { return m[0] + c; }
static float e_schlick(const float *m, float c) { return fresnel_schlick(m[2], c); }
static float e_schlick_gen(const float *m, float c) { return fresnel_schlick_gen(m[2], 1.0f, 3.7f, c); }
static float e_lsk(const float *m, float c) { return fresnel_lsk(m[0], m[1], c); }
static float e_lsk_comp(const float *m, float c) { return fresnel_lsk_comp(m[0], m[1], m[4], m[5], c); }
static float e_f82(const float *m, float c) { return fresnel_f82(m[2], m[3], c); }
static float e_gulbrandsen(const float *m, float c) { return fresnel_gulbrandsen(m[6], m[7], c); }
static float e_cook_torrance(const float *m, float c) { return fresnel_cook_torrance(m[2], m[0], m[1], c); }
static float e_conductor(const float *m, float c) { return fresnel_conductor(m[0], m[1], c); }
static float e_dielectric(const float *m, float c) { return fresnel_dielectric(m[0], c); }
static float e_approx(const float *m, float c) { return fresnel_approx_conductor(m[0], m[1], c); }
static float e_internal(const float *m, float c) { return fresnel_schlick_internal(m[2], m[0], c); }
static float e_lut(const float *m, float c) { (void)m; return fresnel_lut(lut, CONFORM_LUT_N, c); }
static float e_lut_cubic(const float *m, float c) { (void)m; return fresnel_lut_cubic(lut, CONFORM_LUT_N, c); }
static float e_lut_linear(const float *m, float c) { (void)m; return fresnel_lut_linear(lut_linear, CONFORM_LUT_N, c); }
static float e_lut_residual(const float *m, float c) { return fresnel_lut_residual(m[2], residual, CONFORM_LUT_N, c); }

#ifdef BENCH_BATCH_N
/* copper at 550 nm prepared once, in each of the three channels */
static fresnel_conductor_prep prep[3];
static float batch_cos[BENCH_BATCH_N], batch_out[BENCH_BATCH_N];
static fresnel_rgb batch_rgb[BENCH_BATCH_N];
static float e_prepared(const float *m, float c) { (void)m; return fresnel_conductor_prepared(&prep[0], c); }
static float e_batch(const float *m, float c)
{
    (void)m, (void)c;
    fresnel_conductor_batch(&prep[0], batch_cos, batch_out, BENCH_BATCH_N);
    return batch_out[0];
}
static float e_rgb_batch(const float *m, float c)
{
    (void)m, (void)c;
    fresnel_conductor_rgb_batch(prep, batch_cos, batch_rgb, BENCH_BATCH_N);
    return batch_rgb[0].r;
}
/* RGB per cosine, the three channels summed: Schlick's, and the thin film
 * (a 2.5 film on gold, 4096 c nm thick) */
static float e_schlick_rgb(const float *m, float c)
{
    fresnel_rgb f0, r;
    f0.r = m[2], f0.g = 0.5f * m[2], f0.b = 0.25f * m[2];
    r = fresnel_schlick_rgb(f0, c);
    return r.r + r.g + r.b;
}
static float e_film(const float *m, float c)
{
    fresnel_rgb r = fresnel_film_rgb(&conform_film_f32, c, 4096.0f * c);
    (void)m;
    return r.r + r.g + r.b;
}
#define BENCH_STR_(x) #x
#define BENCH_STR(x) BENCH_STR_(x)
#endif

static const struct {
    const char *name;
    f32_eval fn;
} f32_rows[] = {
    {"f32 schlick", e_schlick},
    {"f32 schlick-gen p=3.7", e_schlick_gen},
    {"f32 lsk", e_lsk},
    {"f32 lsk-comp", e_lsk_comp},
    {"f32 f82", e_f82},
    {"f32 gulbrandsen", e_gulbrandsen},
    {"f32 cook-torrance", e_cook_torrance},
    {"f32 exact-conductor", e_conductor},
    {"f32 exact-dielectric", e_dielectric},
    {"f32 approx-conductor", e_approx},
    {"f32 schlick-internal", e_internal},
    {"f32 lut", e_lut},
    {"f32 lut-cubic", e_lut_cubic},
    {"f32 lut-linear", e_lut_linear},
    {"f32 lut-residual", e_lut_residual},
#ifdef BENCH_BATCH_N
    {"f32 exact-conductor prepared", e_prepared},
    {"f32 conductor-batch\t" BENCH_STR(BENCH_BATCH_N), e_batch},
    {"f32 conductor-rgb-batch\t" BENCH_STR(BENCH_BATCH_N), e_rgb_batch},
    {"f32 schlick-rgb", e_schlick_rgb},
    {"f32 thin-film", e_film},
#endif
};

static void run32(const char *name, f32_eval fn, const float *cs)
{
    int k;
    port_puts(name);
    port_puts("\n");
    for (k = 0; k < BENCH_CODES; k++) {
        port_mark((uint32_t)k);
        bench_sink += fn(conform_bench_float, cs[k]);
    }
    port_mark(BENCH_CODES);
}

#if FRESNEL_HAS_F16
typedef fresnel_f16 (*f16_eval)(const fresnel_f16 *m, fresnel_f16 c);
static fresnel_f16 m16[8], lut16[CONFORM_LUT_N], lut_linear16[CONFORM_LUT_N], residual16[CONFORM_LUT_N];
static fresnel_f16 h_none(const fresnel_f16 *m, fresnel_f16 c) { (void)m; return c; }
static fresnel_f16 h_schlick(const fresnel_f16 *m, fresnel_f16 c) { return fresnel_schlick_f16(m[2], c); }
static fresnel_f16 h_schlick_gen(const fresnel_f16 *m, fresnel_f16 c)
{
    return fresnel_schlick_gen_f16(m[2], (fresnel_f16)1.0f, (fresnel_f16)3.7f, c);
}
static fresnel_f16 h_lsk(const fresnel_f16 *m, fresnel_f16 c) { return fresnel_lsk_f16(m[0], m[1], c); }
static fresnel_f16 h_lsk_comp(const fresnel_f16 *m, fresnel_f16 c) { return fresnel_lsk_comp_f16(m[0], m[1], m[4], m[5], c); }
static fresnel_f16 h_f82(const fresnel_f16 *m, fresnel_f16 c) { return fresnel_f82_f16(m[2], m[3], c); }
static fresnel_f16 h_gulbrandsen(const fresnel_f16 *m, fresnel_f16 c) { return fresnel_gulbrandsen_f16(m[6], m[7], c); }
static fresnel_f16 h_cook_torrance(const fresnel_f16 *m, fresnel_f16 c) { return fresnel_cook_torrance_f16(m[2], m[0], m[1], c); }
static fresnel_f16 h_conductor(const fresnel_f16 *m, fresnel_f16 c) { return fresnel_conductor_f16(m[0], m[1], c); }
static fresnel_f16 h_dielectric(const fresnel_f16 *m, fresnel_f16 c) { return fresnel_dielectric_f16(m[0], c); }
static fresnel_f16 h_approx(const fresnel_f16 *m, fresnel_f16 c) { return fresnel_approx_conductor_f16(m[0], m[1], c); }
static fresnel_f16 h_internal(const fresnel_f16 *m, fresnel_f16 c) { return fresnel_schlick_internal_f16(m[2], m[0], c); }
static fresnel_f16 h_lut(const fresnel_f16 *m, fresnel_f16 c) { (void)m; return fresnel_lut_f16(lut16, CONFORM_LUT_N, c); }
static fresnel_f16 h_lut_cubic(const fresnel_f16 *m, fresnel_f16 c)
{
    (void)m;
    return fresnel_lut_cubic_f16(lut16, CONFORM_LUT_N, c);
}
static fresnel_f16 h_lut_linear(const fresnel_f16 *m, fresnel_f16 c)
{
    (void)m;
    return fresnel_lut_linear_f16(lut_linear16, CONFORM_LUT_N, c);
}
static fresnel_f16 h_lut_residual(const fresnel_f16 *m, fresnel_f16 c)
{
    return fresnel_lut_residual_f16(m[2], residual16, CONFORM_LUT_N, c);
}

static const struct {
    const char *name;
    f16_eval fn;
} f16_rows[] = {
    {"f16 schlick", h_schlick},
    {"f16 schlick-gen p=3.7", h_schlick_gen},
    {"f16 lsk", h_lsk},
    {"f16 lsk-comp", h_lsk_comp},
    {"f16 f82", h_f82},
    {"f16 gulbrandsen", h_gulbrandsen},
    {"f16 cook-torrance", h_cook_torrance},
    {"f16 exact-conductor", h_conductor},
    {"f16 exact-dielectric", h_dielectric},
    {"f16 approx-conductor", h_approx},
    {"f16 schlick-internal", h_internal},
    {"f16 lut", h_lut},
    {"f16 lut-cubic", h_lut_cubic},
    {"f16 lut-linear", h_lut_linear},
    {"f16 lut-residual", h_lut_residual},
};

volatile fresnel_f16 bench_sink16;

static void run16(const char *name, f16_eval fn, const fresnel_f16 *cs)
{
    int k;
    port_puts(name);
    port_puts("\n");
    for (k = 0; k < BENCH_CODES; k++) {
        port_mark((uint32_t)k);
        bench_sink16 = fn(m16, cs[k]);
    }
    port_mark(BENCH_CODES);
}
#endif

int main(void)
{
    float cs[BENCH_CODES];
    int k;
    for (k = 0; k < BENCH_CODES; k++)
        cs[k] = (float)k / 32.0f;
    for (k = 0; k < CONFORM_LUT_N; k++) {
        lut[k] = conform_lut_u16[0][k] / 32768.0f;
        lut_linear[k] = conform_lut_u16[1][k] / 32768.0f;
        residual[k] = conform_lut_s16[0][k] / (float)(1L << conform_lut_frac16);
    }
#ifdef BENCH_BATCH_N
    for (k = 0; k < 3; k++)
        prep[k] = fresnel_conductor_prepare(conform_bench_float[0], conform_bench_float[1]);
    for (k = 0; k < BENCH_BATCH_N; k++)
        batch_cos[k] = (float)k / (float)(BENCH_BATCH_N - 1);
#endif
    port_puts("BENCH\n");
    run32("(loop f32)", e_none, cs);
    for (k = 0; k < (int)(sizeof f32_rows / sizeof f32_rows[0]); k++)
        run32(f32_rows[k].name, f32_rows[k].fn, cs);
#if FRESNEL_HAS_F16
    {
        fresnel_f16 cs16[BENCH_CODES];
        for (k = 0; k < 8; k++)
            m16[k] = (fresnel_f16)conform_bench_float[k];
        for (k = 0; k < CONFORM_LUT_N; k++) {
            lut16[k] = (fresnel_f16)lut[k];
            lut_linear16[k] = (fresnel_f16)lut_linear[k];
            residual16[k] = (fresnel_f16)residual[k];
        }
        for (k = 0; k < BENCH_CODES; k++)
            cs16[k] = (fresnel_f16)cs[k];
        port_puts("END\nBENCH\n");
        run16("(loop f16)", h_none, cs16);
        for (k = 0; k < (int)(sizeof f16_rows / sizeof f16_rows[0]); k++)
            run16(f16_rows[k].name, f16_rows[k].fn, cs16);
    }
#endif
    port_puts("END\n");
    return 0;
}
