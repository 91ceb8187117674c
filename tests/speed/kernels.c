/* The timed kernels (kernels.h), in their own translation unit, compiled
 * with the flags of the run like the library beside them. "call" rows call
 * a function of another translation unit per cosine (the library's, or a
 * peer's from gen/bench/bench_compare.c); "inline" rows inline a header's
 * static function into the loop, which the compiler may vectorise; "batch"
 * is the library's array function; "floor" rows bound what any loop over
 * the arrays costs. */
#include "kernels.h"

#include "bench/bench_compare.h"
#include "bench/peers.h"
#include "fresnel_film.h"
#include "fresnel_fixed.h"
#include "fresnel_fixed_fast.h"
#include "speed_film.h" /* `fresnel gen tests/speed/film.scene` (the Makefile) */

/* The material's scalars are read into locals before the loop, as a
 * renderer holds them: a store to out[] cannot alias them, so an inlined
 * formula may keep them in registers and the compiler may vectorise. */
#define LOOP_BODY(dst, expr)                                                                                  \
    const float eta = x->eta, kappa = x->kappa, f0 = x->f0;                                                  \
    const int32_t f0q = x->f0q;                                                                               \
    int i;                                                                                                    \
    (void)eta, (void)kappa, (void)f0, (void)f0q, (void)c, (void)cq, (void)out, (void)outq, (void)outrgb;       \
    for (i = 0; i < n; i++)                                                                                   \
        dst[i] = (expr);
#define LOOP(name, expr)                                                                                      \
    static void name(const speed_ctx *x, const float *c, const int32_t *cq, float *out, int32_t *outq,         \
                     fresnel_rgb *outrgb, int n)                                                              \
    {                                                                                                         \
        LOOP_BODY(out, expr)                                                                                  \
    }
#define LOOP_Q15(name, expr)                                                                                  \
    static void name(const speed_ctx *x, const float *c, const int32_t *cq, float *out, int32_t *outq,         \
                     fresnel_rgb *outrgb, int n)                                                              \
    {                                                                                                         \
        LOOP_BODY(outq, expr)                                                                                 \
    }

/* Schlick's formula written out in the loop, no clamp: the cheapest loop
 * that still computes a Fresnel factor. */
static inline float schlick_minimal(float f0, float c)
{
    float m = 1.0f - c, m2 = m * m;
    return f0 + (1.0f - f0) * (m2 * m2 * m);
}

/* The square roots and divisions of the exact forms alone, chained as
 * there: the conductor batch needs two roots and one division per cosine,
 * Mitsuba's form two and two. Where one unit executes them (not
 * pipelined), these loops are the floor of each, whatever else the loop
 * does. Both results in [0, 1]. */
static inline float roots_div(float c)
{
    float a = sqrtf(c + 1.0f), b = sqrtf(a + c);
    return c / b;
}
static inline float roots_div_div(float c)
{
    float a = sqrtf(c + 1.0f), b = sqrtf(a + c);
    return (c / b) / a;
}

LOOP(k_copy, c[i])
LOOP(k_roots_div, roots_div(c[i]))
LOOP(k_roots_div_div, roots_div_div(c[i]))
LOOP(k_schlick_inline, schlick_minimal(f0, c[i]))
LOOP(k_schlick, fresnel_schlick(f0, c[i]))
LOOP_Q15(k_schlick_q15, fresnel_schlick_q15(f0q, cq[i]))
LOOP_Q15(k_schlick_q15_fast, fresnel_schlick_q15_fast(f0q, cq[i]))
LOOP(k_conductor, fresnel_conductor(eta, kappa, c[i]))
LOOP(k_conductor_prepared, fresnel_conductor_prepared(&x->prep, c[i]))
LOOP(k_mitsuba_call, cmp_mitsuba_conductor(eta, kappa, c[i]))
LOOP(k_mitsuba_inline, peer_mitsuba_conductor(eta, kappa, c[i]))
LOOP(k_pbrt_call, cmp_pbrt_conductor(eta, kappa, c[i]))
LOOP(k_pbrt_inline, peer_pbrt_conductor(eta, kappa, c[i]))
LOOP(k_lut16_cubic, fresnel_lut_cubic(x->lut16, 16, c[i]))
LOOP(k_lut32, fresnel_lut(x->lut32, 32, c[i]))
LOOP(k_lut16_linear, fresnel_lut_linear(x->lin16, 16, c[i]))
LOOP_Q15(k_lut32_q15, fresnel_lut_u16_q15(x->q32, 32, cq[i]))
LOOP_Q15(k_lut16_cubic_q15, fresnel_lut_cubic_u16_q15(x->q16, 16, cq[i]))
LOOP_Q15(k_lut16_linear_q15, fresnel_lut_linear_u16_q15(x->qlin16, 16, cq[i]))
LOOP_Q15(k_lut32_q15_fast, fresnel_lut_u16_q15_fast(x->q32, 32, cq[i]))

static void k_conductor_batch(const speed_ctx *x, const float *c, const int32_t *cq, float *out, int32_t *outq,
                              fresnel_rgb *outrgb, int n)
{
    (void)cq, (void)outq, (void)outrgb;
    fresnel_conductor_batch(&x->prep, c, out, n);
}

/* Three channels of one material per cosine: the library's RGB batch, and
 * the Mitsuba formula inlined in the loop once per channel. */
static void k_conductor_rgb_batch(const speed_ctx *x, const float *c, const int32_t *cq, float *out, int32_t *outq,
                                  fresnel_rgb *outrgb, int n)
{
    (void)cq, (void)out, (void)outq;
    fresnel_conductor_rgb_batch(x->prep3, c, outrgb, n);
}

static void k_mitsuba_inline_rgb(const speed_ctx *x, const float *c, const int32_t *cq, float *out, int32_t *outq,
                                 fresnel_rgb *outrgb, int n)
{
    const float er = x->eta3[0], eg = x->eta3[1], eb = x->eta3[2];
    const float kr = x->kappa3[0], kg = x->kappa3[1], kb = x->kappa3[2];
    int i;
    (void)cq, (void)out, (void)outq;
    for (i = 0; i < n; i++) {
        outrgb[i].r = peer_mitsuba_conductor(er, kr, c[i]);
        outrgb[i].g = peer_mitsuba_conductor(eg, kg, c[i]);
        outrgb[i].b = peer_mitsuba_conductor(eb, kb, c[i]);
    }
}

/* RGB per cosine: Schlick's three channels, and the thin film (a 1.5 film on
 * gold, thickness 0-1022 nm from the index) on the table gen writes. */
static void k_schlick_rgb(const speed_ctx *x, const float *c, const int32_t *cq, float *out, int32_t *outq,
                          fresnel_rgb *outrgb, int n)
{
    int i;
    (void)cq, (void)out, (void)outq;
    for (i = 0; i < n; i++)
        outrgb[i] = fresnel_schlick_rgb(x->f0_3, c[i]);
}

static void k_film(const speed_ctx *x, const float *c, const int32_t *cq, float *out, int32_t *outq,
                   fresnel_rgb *outrgb, int n)
{
    int i;
    (void)x, (void)cq, (void)out, (void)outq;
    for (i = 0; i < n; i++)
        outrgb[i] = fresnel_film_rgb(&fresnel_speed_au_thin_film, c[i], (float)(2 * (i & 511)));
}

/* The same film by the KHR_materials_iridescence form (gen/bench/peers.h),
 * inlined as a glTF renderer runs it, given gold's F0 (the film's own table
 * at normal incidence and no film: speed_ctx_init), its result held to
 * [0, 1] as fresnel_film_rgb holds its own (the form sets only negatives
 * to 0). */
static void k_khr_iridescence(const speed_ctx *x, const float *c, const int32_t *cq, float *out, int32_t *outq,
                              fresnel_rgb *outrgb, int n)
{
    const float f0[3] = {x->film_f0.r, x->film_f0.g, x->film_f0.b};
    int i;
    (void)cq, (void)out, (void)outq;
    for (i = 0; i < n; i++) {
        float rgb[3];
        peer_khr_iridescence_rgb(1.5f, (float)(2 * (i & 511)), peer_clamp01(c[i]), f0, rgb);
        outrgb[i].r = peer_clamp01(rgb[0]), outrgb[i].g = peer_clamp01(rgb[1]), outrgb[i].b = peer_clamp01(rgb[2]);
    }
}

/* The same film by the polarised form of the same family
 * (peer_belcour_polarised_rgb), given gold's per-channel eta, kappa. */
static void k_polarised_film(const speed_ctx *x, const float *c, const int32_t *cq, float *out, int32_t *outq,
                             fresnel_rgb *outrgb, int n)
{
    int i;
    (void)cq, (void)out, (void)outq;
    for (i = 0; i < n; i++) {
        float rgb[3];
        peer_belcour_polarised_rgb(1.5f, (float)(2 * (i & 511)), peer_clamp01(c[i]), x->film_eta, x->film_kappa, rgb);
        outrgb[i].r = peer_clamp01(rgb[0]), outrgb[i].g = peer_clamp01(rgb[1]), outrgb[i].b = peer_clamp01(rgb[2]);
    }
}

const speed_kernel_def speed_kernels[] = {
    {"copy", "floor", k_copy, 0, 0},
    {"schlick-inline", "floor", k_schlick_inline, 0, 0},
    {"sqrt2-div1", "floor", k_roots_div, 0, 0},
    {"sqrt2-div2", "floor", k_roots_div_div, 0, 0},
    {"schlick-f32", "call", k_schlick, 0, 0},
    {"schlick-q15", "call", k_schlick_q15, 1, 0},
    {"schlick-q15-fast", "inline", k_schlick_q15_fast, 1, 0},
    {"conductor-call", "call", k_conductor, 0, 0},
    {"conductor-prepared", "call", k_conductor_prepared, 0, 0},
    {"conductor-batch", "batch", k_conductor_batch, 0, 0},
    {"mitsuba-call", "call", k_mitsuba_call, 0, 0},
    {"mitsuba-inline", "inline", k_mitsuba_inline, 0, 0},
    {"conductor-rgb-batch", "batch", k_conductor_rgb_batch, 0, 1},
    {"mitsuba-inline-rgb", "inline", k_mitsuba_inline_rgb, 0, 1},
    {"pbrt-call", "call", k_pbrt_call, 0, 0},
    {"pbrt-inline", "inline", k_pbrt_inline, 0, 0},
    {"lut16-cubic-f32", "call", k_lut16_cubic, 0, 0},
    {"lut32-f32", "call", k_lut32, 0, 0},
    {"lut16-linear-f32", "call", k_lut16_linear, 0, 0},
    {"lut32-q15", "call", k_lut32_q15, 1, 0},
    {"lut16-cubic-q15", "call", k_lut16_cubic_q15, 1, 0},
    {"lut16-linear-q15", "call", k_lut16_linear_q15, 1, 0},
    {"lut32-q15-fast", "inline", k_lut32_q15_fast, 1, 0},
    {"schlick-rgb-f32", "call", k_schlick_rgb, 0, 1},
    {"film-f32", "call", k_film, 0, 1},
    {"khr-iridescence-inline", "inline", k_khr_iridescence, 0, 1},
    {"polarised-film-inline", "inline", k_polarised_film, 0, 1},
};
const int speed_kernel_count = (int)(sizeof speed_kernels / sizeof speed_kernels[0]);

static int32_t q15(float v) { return (int32_t)(v * 32768.0f + 0.5f); }

/* The tables hold the library's own exact conductor at the nodes: uniform in
 * sqrt(c) (fresnel_lut*, cubic) or in c (linear). */
void speed_ctx_init(speed_ctx *x, float eta, float kappa)
{
    int i;
    x->eta = eta;
    x->kappa = kappa;
    x->f0 = fresnel_conductor(eta, kappa, 1.0f);
    x->f0q = q15(x->f0);
    x->prep = fresnel_conductor_prepare(eta, kappa);
    for (i = 0; i < 3; i++) { /* copper's channels: red as above, green and blue about 550 and 450 nm */
        static const float e3[3] = {0.24f, 1.0f, 1.24f}, k3[3] = {3.63f, 2.58f, 2.4f};
        x->eta3[i] = e3[i];
        x->kappa3[i] = k3[i];
        x->prep3[i] = fresnel_conductor_prepare(e3[i], k3[i]);
    }
    x->f0_3.r = fresnel_conductor(x->eta3[0], x->kappa3[0], 1.0f);
    x->f0_3.g = fresnel_conductor(x->eta3[1], x->kappa3[1], 1.0f);
    x->f0_3.b = fresnel_conductor(x->eta3[2], x->kappa3[2], 1.0f);
    x->film_f0 = fresnel_film_rgb(&fresnel_speed_au_thin_film, 1.0f, 0.0f);
    for (i = 0; i < 3; i++) { /* `fresnel params --material au`: eta_gaussian, kappa_gaussian (srgb) */
        static const float e3[3] = {0.231009409f, 0.471031517f, 1.27337468f},
                           k3[3] = {3.19236207f, 2.45557332f, 1.89368963f};
        x->film_eta[i] = e3[i];
        x->film_kappa[i] = k3[i];
    }
    for (i = 0; i < 32; i++) {
        float s = (float)i / 31.0f;
        x->lut32[i] = fresnel_conductor(eta, kappa, s * s);
        x->q32[i] = (uint16_t)q15(x->lut32[i]);
    }
    for (i = 0; i < 16; i++) {
        float s = (float)i / 15.0f;
        x->lut16[i] = fresnel_conductor(eta, kappa, s * s);
        x->q16[i] = (uint16_t)q15(x->lut16[i]);
        x->lin16[i] = fresnel_conductor(eta, kappa, s);
        x->qlin16[i] = (uint16_t)q15(x->lin16[i]);
    }
}
