/* The GLSL port (ports/glsl/fresnel.glsl) in a real GL pipeline: Mesa's
 * llvmpipe through OSMesa, off screen. Built and run by tests/shader_ports/test_glsl_port_osmesa.sh
 * (the Makefile's test rule links without -lOSMesa, hence not test_*.c).
 *
 *   1. what the context offers: GL and GLSL versions, mediump's format;
 *      that llvmpipe really computes mediump in binary16;
 *   2. fresnel.glsl compiles in every dialect the context accepts, vertex
 *      and fragment, mediump and highp default, and highp forced down to
 *      mediump (a failed compile prints the info log);
 *   3. every function renders a strip of cosines per material into an
 *      RGBA32F target and matches the C float runtime (build/libfresnel.a)
 *      on the same binary32 inputs: highp within 1e-5;
 *   4. the same through the default RGBA8 framebuffer: within 1 LSB;
 *   5. ES shaders with precision mediump: against the C runtime on the same
 *      binary16 inputs, within the per-model bounds below, no NaN, in [0, 1];
 *      with FRESNEL_HIGHP forced to mediump only measured (it shows why
 *      those functions are highp); where the tree has the C binary16 path
 *      (include/fresnel_f16.h) the renders are also compared with it.
 * The table at the end (NOTE lines) is ports/glsl/README.md's.
 *
 * Usage: glsl_port_osmesa PORT_DIR   (PORT_DIR = ports/glsl) */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fresnel.h"
/* The C binary16 runtime, where the compiler has _Float16: the mediump
 * results are also compared with it (NOTE lines only; its domain and LUT
 * layout are its own). */
#include "fresnel_f16.h"
#include "glctx.h"
#include "harness.h"
#include "png.h"
#include "common/reference.h"

#define W 512     /* cosines per strip (a power of two: u = x / W is exact) */
#define MAXROWS 8
#define LUT_N 32  /* nodes per channel of the test tables */
#define LUT_W (3 * LUT_N)
#define LUT_VARIANTS 4 /* uniform in sqrt(c), in c, and their residual forms */

#define HIGHP_BOUND 1e-5 /* highp against the C float runtime */

/* ------------------------------------------------------------ fp16 */

/* Round to the nearest binary16 value (ties to even), as a float: inputs for
 * mediump runs are made representable so both sides see the same numbers. */
static float f16(float x)
{
    float a = fabsf(x), q;
    int e;
    if (isnan(x))
        return x;
    if (!(a < 65520.0f))
        return x > 0.0f ? INFINITY : -INFINITY;
    if (a < 6.103515625e-05f) {
        q = 5.9604644775390625e-08f; /* 2^-24, the subnormal spacing */
    } else {
        (void)frexpf(a, &e);
        q = ldexpf(1.0f, e - 11);
    }
    return copysignf(nearbyintf(a / q) * q, x);
}

/* ------------------------------------------------------------ materials */

/* eta, kappa relative to air in the order r, g, b = 650, 550, 450 nm:
 * linear interpolation of data/<id>.csv at those wavelengths (the awk
 * one-liner in ports/glsl/README.md prints them). au-fit is the black-box fit
 * `build/fresnel params --material au` prints (eta_fit, kappa_fit): its red
 * kappa 19.1 is the case that overflows binary16. */
struct material {
    const char *name;
    float eta[3], kappa[3];
};
static const struct material metals[] = {
    {"au", {0.1556f, 0.4241f, 1.383f}, {3.602f, 2.472f, 1.915f}},
    {"cu", {0.2378f, 1.007f, 1.24f}, {3.626f, 2.582f, 2.393f}},
    {"ag", {0.05222f, 0.05958f, 0.04f}, {4.409f, 3.597f, 2.648f}},
    {"al", {1.558f, 1.015f, 0.6332f}, {7.712f, 6.627f, 5.454f}},
    {"cr", {3.107f, 3.181f, 2.323f}, {3.331f, 3.329f, 3.135f}},
    {"au-fit", {0.105033164f, 0.499094795f, 1.46976061f}, {19.1189693f, 2.26072735f, 1.77438135f}},
    {"glass", {1.5f, 1.5f, 1.5f}, {0.0f, 0.0f, 0.0f}},
};
/* Dielectrics: glass, water, diamond from air, the first two from inside,
 * and matched index. */
static const struct material dielectrics[] = {
    {"glass", {1.5f, 1.5f, 1.5f}, {0, 0, 0}},
    {"water", {1.33f, 1.33f, 1.33f}, {0, 0, 0}},
    {"diamond", {2.42f, 2.42f, 2.42f}, {0, 0, 0}},
    {"glass-inside", {1.0f / 1.5f, 1.0f / 1.5f, 1.0f / 1.5f}, {0, 0, 0}},
    {"water-inside", {1.0f / 1.33f, 1.0f / 1.33f, 1.0f / 1.33f}, {0, 0, 0}},
    {"matched", {1.0f, 1.0f, 1.0f}, {0, 0, 0}},
};
#define NMETALS ((int)(sizeof metals / sizeof metals[0]))
#define NDIEL ((int)(sizeof dielectrics / sizeof dielectrics[0]))

/* LUT tables per metal and variant, each LUT_W = 3 LUT_N floats (r, g, b):
 * the exact conductor (or its difference from Schlick) at the nodes of
 * src/f32/lut.c, uniform in sqrt(c) or in c. */
static float lut_tables[NMETALS][LUT_VARIANTS][LUT_W];

static void build_luts(void)
{
    int m, v, ch, i;
    for (m = 0; m < NMETALS; m++)
        for (v = 0; v < LUT_VARIANTS; v++)
            for (ch = 0; ch < 3; ch++)
                for (i = 0; i < LUT_N; i++) {
                    double x = i / (double)(LUT_N - 1);
                    float c = (float)((v & 1) ? x : x * x);
                    float e = metals[m].eta[ch], k = metals[m].kappa[ch];
                    float f = fresnel_conductor(e, k, c);
                    if (v & 2)
                        f -= fresnel_schlick(fresnel_f0_from_ior(e, k), c);
                    lut_tables[m][v][ch * LUT_N + i] = f;
                }
}

/* ---------------------------------------------------------------- cases */

/* What one row of a strip needs: four vec3 parameters, and for the LUT
 * cases the table (texture row and the same floats for C and the array). */
struct row {
    float p[4][3];
    float strip[3];
    const float *table;
};

enum { OUT_REFL, OUT_PAIR_ABS, OUT_PAIR_REL };
enum { ROWS_METALS, ROWS_DIEL };
enum { PAR_NK, PAR_F0, PAR_GEN, PAR_INTERNAL, PAR_F82, PAR_RG, PAR_CT };

struct mcase {
    const char *name;
    const char *expr;   /* GLSL vec4 from c, P0..P3, FR_LUT, FR_STRIP, FR_N, FR_ARR */
    int rows;           /* ROWS_* */
    int nch;            /* channels compared */
    int out;            /* OUT_* */
    int mediump_safe;   /* fresnel.glsl's classification */
    int min_version;    /* 0, or 130 for the array macros */
    int lut_variant;    /* -1, or which table */
    int lut_first;      /* first node of the strip (LUT_N: the green channel) */
    int params;         /* PAR_*: what setup_row derives */
    void (*eval)(const struct row *r, float c, float out[3]);
    double mp_bound;    /* mediump bound (documented per model) */
};

static void set3(float d[3], float a, float b, float c)
{
    d[0] = a;
    d[1] = b;
    d[2] = c;
}
static void put_rgb(float out[3], fresnel_rgb v) { set3(out, v.r, v.g, v.b); }

/* Parameters derived from a material in C, as the generator would ship them. */
static void setup_row(const struct mcase *mc, int ri, struct row *r)
{
    const struct material *m = mc->rows == ROWS_METALS ? &metals[ri] : &dielectrics[ri];
    /* exponents for schlick_gen: the p = 5 fast path and pow() paths */
    static const float ps[MAXROWS] = {5.0f, 3.7f, 0.5f, 8.0f, 40.0f, 1.0f, 5.0f, 2.0f};
    int ch;
    memset(r, 0, sizeof *r);
    for (ch = 0; ch < 3; ch++) {
        float e = m->eta[ch], k = m->kappa[ch];
        float f0 = fresnel_f0_from_ior(e, k);
        fresnel_rg rg = fresnel_gulbrandsen_rg(e, k);
        double a, al;
        switch (mc->params) {
        case PAR_F0:
            r->p[0][ch] = f0;
            break;
        case PAR_GEN:
            r->p[0][ch] = f0;
            r->p[1][ch] = 1.0f - 0.05f * (float)ch;
            r->p[2][ch] = ps[ri];
            break;
        case PAR_INTERNAL: /* a dispersion-like spread so the channels differ */
            r->p[0][ch] = fresnel_f0_from_ior(e * (0.99f + 0.01f * (float)ch), 0.0f);
            r->p[1][ch] = e;
            break;
        case PAR_F82:
            r->p[0][ch] = f0;
            r->p[1][ch] = fresnel_conductor(e, k, 1.0f / 7.0f);
            break;
        case PAR_RG:
            r->p[0][ch] = rg.r;
            r->p[1][ch] = rg.g;
            break;
        case PAR_CT: /* one representative IOR: the material's green */
            r->p[0][ch] = f0;
            set3(r->p[1], m->eta[1], m->kappa[1], 0.0f);
            break;
        default:
            ref_lsk_fit(e, k, &a, &al);
            r->p[0][ch] = e;
            r->p[1][ch] = k;
            r->p[2][ch] = (float)a;
            r->p[3][ch] = (float)al;
            break;
        }
    }
    if (mc->lut_variant >= 0) {
        r->table = lut_tables[ri][mc->lut_variant];
        set3(r->strip, ((float)mc->lut_first + 0.5f) / (float)LUT_W,
             ((float)(ri * LUT_VARIANTS + mc->lut_variant) + 0.5f) / (float)(NMETALS * LUT_VARIANTS),
             1.0f / (float)LUT_W);
    }
}

#define P(i, ch) (r->p[i][ch])
#define RGB(i) fr_rgb(r->p[i])
static fresnel_rgb fr_rgb(const float *v)
{
    fresnel_rgb o;
    o.r = v[0];
    o.g = v[1];
    o.b = v[2];
    return o;
}

/* C evaluations, one per case, of the same function on the same inputs. */
#define SCALAR(fn, call) \
    static void fn(const struct row *r, float c, float o[3]) { set3(o, (call), 0.0f, 0.0f); }
#define VEC(fn, call) \
    static void fn(const struct row *r, float c, float o[3]) { put_rgb(o, (call)); }
SCALAR(e_schlick, fresnel_schlick(P(0, 1), c))
VEC(e_schlick_rgb, fresnel_schlick_rgb(RGB(0), c))
SCALAR(e_schlick_gen, fresnel_schlick_gen(P(0, 1), P(1, 1), P(2, 1), c))
VEC(e_schlick_gen_rgb, fresnel_schlick_gen_rgb(RGB(0), RGB(1), P(2, 0), c))
SCALAR(e_schlick_internal, fresnel_schlick_internal(P(0, 1), P(1, 1), c))
VEC(e_schlick_internal_rgb, fresnel_schlick_internal_rgb(RGB(0), P(1, 1), c))
SCALAR(e_f0_in_medium, fresnel_f0_in_medium(c, P(0, 1)))
SCALAR(e_f0_from_ior, fresnel_f0_from_ior(4.0f * c, P(1, 1)))
SCALAR(e_lsk, fresnel_lsk(P(0, 1), P(1, 1), c))
VEC(e_lsk_rgb, fresnel_lsk_rgb(RGB(0), RGB(1), c))
SCALAR(e_lsk_comp, fresnel_lsk_comp(P(0, 1), P(1, 1), P(2, 1), P(3, 1), c))
VEC(e_lsk_comp_rgb, fresnel_lsk_comp_rgb(RGB(0), RGB(1), RGB(2), RGB(3), c))
SCALAR(e_f82, fresnel_f82(P(0, 1), P(1, 1), c))
VEC(e_f82_rgb, fresnel_f82_rgb(RGB(0), RGB(1), c))
SCALAR(e_approx, fresnel_approx_conductor(P(0, 1), P(1, 1), c))
VEC(e_approx_rgb, fresnel_approx_conductor_rgb(RGB(0), RGB(1), c))
SCALAR(e_gulb, fresnel_gulbrandsen(P(0, 1), P(1, 1), c))
VEC(e_gulb_rgb, fresnel_gulbrandsen_rgb(RGB(0), RGB(1), c))
SCALAR(e_ct, fresnel_cook_torrance(P(0, 1), P(1, 0), P(1, 1), c))
VEC(e_ct_rgb, fresnel_cook_torrance_rgb(RGB(0), P(1, 0), P(1, 1), c))
SCALAR(e_cond, fresnel_conductor(P(0, 1), P(1, 1), c))
VEC(e_cond_rgb, fresnel_conductor_rgb(RGB(0), RGB(1), c))
SCALAR(e_diel, fresnel_dielectric(P(0, 1), c))
SCALAR(e_lut, fresnel_lut(r->table + LUT_N, LUT_N, c))
SCALAR(e_lut_lin, fresnel_lut_linear(r->table + LUT_N, LUT_N, c))
SCALAR(e_lut_res, fresnel_lut_residual(P(0, 1), r->table + LUT_N, LUT_N, c))
SCALAR(e_lut_lin_res, fresnel_lut_linear_residual(P(0, 1), r->table + LUT_N, LUT_N, c))
VEC(e_lut_rgb, fresnel_lut_rgb(r->table, LUT_N, c))
VEC(e_lut_lin_rgb, fresnel_lut_linear_rgb(r->table, LUT_N, c))
VEC(e_lut_res_rgb, fresnel_lut_residual_rgb(RGB(0), r->table, LUT_N, c))
VEC(e_lut_lin_res_rgb, fresnel_lut_linear_residual_rgb(RGB(0), r->table, LUT_N, c))
static void e_gulb_nk(const struct row *r, float c, float o[3])
{
    fresnel_nk nk = fresnel_gulbrandsen_nk(c, P(1, 1));
    set3(o, nk.n, nk.k, 0.0f);
}
static void e_gulb_rg(const struct row *r, float c, float o[3])
{
    fresnel_rg rg = fresnel_gulbrandsen_rg(4.0f * c, P(1, 1));
    set3(o, rg.r, rg.g, 0.0f);
}

/* Bounds for ES shaders with precision mediump, against the C runtime on
 * the same binary16 inputs: what this test measured on llvmpipe (Mesa 22.3,
 * the table it prints), rounded up. Binary16 spacing is 2^-11 = 4.9e-4 just
 * below 1; the largest errors are at grazing incidence, where 1 - c is
 * rounded to that spacing and (1 - c)^5 multiplies the rounding by 5. */
#define MP_SCHLICK 2.5e-3 /* measured 1.7e-3 */
#define MP_POW 4e-3       /* pow(), sqrt(): measured 2.6e-3 (schlick_gen), 2.9e-3 (f0_in_medium) */
#define MP_RATIONAL MP_SCHLICK
#define MP_HIGHP 5e-4     /* highp inside, the result converted: measured 2.6e-4 */

static const struct mcase cases[] = {
    {"schlick", "vec4(fresnel_schlick(P0.y, c))", ROWS_METALS, 1, OUT_REFL, 1, 0, -1, 0, PAR_F0, e_schlick, MP_SCHLICK},
    {"schlick_rgb", "vec4(fresnel_schlick_rgb(P0, c), 1.0)", ROWS_METALS, 3, OUT_REFL, 1, 0, -1, 0, PAR_F0, e_schlick_rgb, MP_SCHLICK},
    {"schlick_gen", "vec4(fresnel_schlick_gen(P0.y, P1.y, P2.y, c))", ROWS_METALS, 1, OUT_REFL, 1, 0, -1, 0, PAR_GEN, e_schlick_gen, MP_POW},
    {"schlick_gen_rgb", "vec4(fresnel_schlick_gen_rgb(P0, P1, P2.x, c), 1.0)", ROWS_METALS, 3, OUT_REFL, 1, 0, -1, 0, PAR_GEN, e_schlick_gen_rgb, MP_POW},
    {"schlick_internal", "vec4(fresnel_schlick_internal(P0.y, P1.y, c))", ROWS_DIEL, 1, OUT_REFL, 0, 0, -1, 0, PAR_INTERNAL, e_schlick_internal, MP_SCHLICK},
    {"schlick_internal_rgb", "vec4(fresnel_schlick_internal_rgb(P0, P1.y, c), 1.0)", ROWS_DIEL, 3, OUT_REFL, 0, 0, -1, 0, PAR_INTERNAL, e_schlick_internal_rgb, MP_SCHLICK},
    {"f0_in_medium", "vec4(fresnel_f0_in_medium(c, P0.y))", ROWS_DIEL, 1, OUT_REFL, 1, 0, -1, 0, PAR_NK, e_f0_in_medium, MP_POW},
    {"f0_from_ior", "vec4(fresnel_f0_from_ior(4.0 * c, P1.y))", ROWS_METALS, 1, OUT_REFL, 1, 0, -1, 0, PAR_NK, e_f0_from_ior, MP_RATIONAL},
    {"lsk", "vec4(fresnel_lsk(P0.y, P1.y, c))", ROWS_METALS, 1, OUT_REFL, 1, 0, -1, 0, PAR_NK, e_lsk, MP_RATIONAL},
    {"lsk_rgb", "vec4(fresnel_lsk_rgb(P0, P1, c), 1.0)", ROWS_METALS, 3, OUT_REFL, 1, 0, -1, 0, PAR_NK, e_lsk_rgb, MP_RATIONAL},
    {"lsk_comp", "vec4(fresnel_lsk_comp(P0.y, P1.y, P2.y, P3.y, c))", ROWS_METALS, 1, OUT_REFL, 1, 0, -1, 0, PAR_NK, e_lsk_comp, MP_POW},
    {"lsk_comp_rgb", "vec4(fresnel_lsk_comp_rgb(P0, P1, P2, P3, c), 1.0)", ROWS_METALS, 3, OUT_REFL, 1, 0, -1, 0, PAR_NK, e_lsk_comp_rgb, MP_POW},
    {"f82", "vec4(fresnel_f82(P0.y, P1.y, c))", ROWS_METALS, 1, OUT_REFL, 1, 0, -1, 0, PAR_F82, e_f82, MP_RATIONAL},
    {"f82_rgb", "vec4(fresnel_f82_rgb(P0, P1, c), 1.0)", ROWS_METALS, 3, OUT_REFL, 1, 0, -1, 0, PAR_F82, e_f82_rgb, MP_RATIONAL},
    {"approx_conductor", "vec4(fresnel_approx_conductor(P0.y, P1.y, c))", ROWS_METALS, 1, OUT_REFL, 1, 0, -1, 0, PAR_NK, e_approx, MP_RATIONAL},
    {"approx_conductor_rgb", "vec4(fresnel_approx_conductor_rgb(P0, P1, c), 1.0)", ROWS_METALS, 3, OUT_REFL, 1, 0, -1, 0, PAR_NK, e_approx_rgb, MP_RATIONAL},
    {"gulbrandsen", "vec4(fresnel_gulbrandsen(P0.y, P1.y, c))", ROWS_METALS, 1, OUT_REFL, 0, 0, -1, 0, PAR_RG, e_gulb, MP_HIGHP},
    {"gulbrandsen_rgb", "vec4(fresnel_gulbrandsen_rgb(P0, P1, c), 1.0)", ROWS_METALS, 3, OUT_REFL, 0, 0, -1, 0, PAR_RG, e_gulb_rgb, MP_HIGHP},
    {"gulbrandsen_nk", "vec4(fresnel_gulbrandsen_nk(c, P1.y), 0.0, 1.0)", ROWS_METALS, 2, OUT_PAIR_REL, 0, 0, -1, 0, PAR_RG, e_gulb_nk, 0.0},
    {"gulbrandsen_rg", "vec4(fresnel_gulbrandsen_rg(4.0 * c, P1.y), 0.0, 1.0)", ROWS_METALS, 2, OUT_PAIR_ABS, 0, 0, -1, 0, PAR_NK, e_gulb_rg, 0.0},
    {"cook_torrance", "vec4(fresnel_cook_torrance(P0.y, P1.x, P1.y, c))", ROWS_METALS, 1, OUT_REFL, 0, 0, -1, 0, PAR_CT, e_ct, MP_HIGHP},
    {"cook_torrance_rgb", "vec4(fresnel_cook_torrance_rgb(P0, P1.x, P1.y, c), 1.0)", ROWS_METALS, 3, OUT_REFL, 0, 0, -1, 0, PAR_CT, e_ct_rgb, MP_HIGHP},
    {"conductor", "vec4(fresnel_conductor(P0.y, P1.y, c))", ROWS_METALS, 1, OUT_REFL, 0, 0, -1, 0, PAR_NK, e_cond, MP_HIGHP},
    {"conductor_rgb", "vec4(fresnel_conductor_rgb(P0, P1, c), 1.0)", ROWS_METALS, 3, OUT_REFL, 0, 0, -1, 0, PAR_NK, e_cond_rgb, MP_HIGHP},
    {"dielectric", "vec4(fresnel_dielectric(P0.y, c))", ROWS_DIEL, 1, OUT_REFL, 0, 0, -1, 0, PAR_NK, e_diel, MP_HIGHP},
    {"lut", "vec4(fresnel_lut(FR_LUT, FR_STRIP, FR_N, c))", ROWS_METALS, 1, OUT_REFL, 0, 0, 0, LUT_N, PAR_F0, e_lut, MP_HIGHP},
    {"lut_linear", "vec4(fresnel_lut_linear(FR_LUT, FR_STRIP, FR_N, c))", ROWS_METALS, 1, OUT_REFL, 0, 0, 1, LUT_N, PAR_F0, e_lut_lin, MP_HIGHP},
    {"lut_residual", "vec4(fresnel_lut_residual(P0.y, FR_LUT, FR_STRIP, FR_N, c))", ROWS_METALS, 1, OUT_REFL, 0, 0, 2, LUT_N, PAR_F0, e_lut_res, MP_SCHLICK},
    {"lut_linear_residual", "vec4(fresnel_lut_linear_residual(P0.y, FR_LUT, FR_STRIP, FR_N, c))", ROWS_METALS, 1, OUT_REFL, 0, 0, 3, LUT_N, PAR_F0, e_lut_lin_res, MP_SCHLICK},
    {"lut_rgb", "vec4(fresnel_lut_rgb(FR_LUT, FR_STRIP, FR_N, c), 1.0)", ROWS_METALS, 3, OUT_REFL, 0, 0, 0, 0, PAR_F0, e_lut_rgb, MP_HIGHP},
    {"lut_linear_rgb", "vec4(fresnel_lut_linear_rgb(FR_LUT, FR_STRIP, FR_N, c), 1.0)", ROWS_METALS, 3, OUT_REFL, 0, 0, 1, 0, PAR_F0, e_lut_lin_rgb, MP_HIGHP},
    {"lut_residual_rgb", "vec4(fresnel_lut_residual_rgb(P0, FR_LUT, FR_STRIP, FR_N, c), 1.0)", ROWS_METALS, 3, OUT_REFL, 0, 0, 2, 0, PAR_F0, e_lut_res_rgb, MP_SCHLICK},
    {"lut_linear_residual_rgb", "vec4(fresnel_lut_linear_residual_rgb(P0, FR_LUT, FR_STRIP, FR_N, c), 1.0)", ROWS_METALS, 3, OUT_REFL, 0, 0, 3, 0, PAR_F0, e_lut_lin_res_rgb, MP_SCHLICK},
    {"lut_array", "vec4(FRESNEL_LUT_ARRAY(FR_ARR, 32, c))", ROWS_METALS, 1, OUT_REFL, 0, 130, 0, LUT_N, PAR_F0, e_lut, MP_HIGHP},
    {"lut_array_rgb", "vec4(FRESNEL_LUT_ARRAY_RGB(FR_ARR, 32, c), 1.0)", ROWS_METALS, 3, OUT_REFL, 0, 130, 0, 0, PAR_F0, e_lut_rgb, MP_HIGHP},
    {"lut_linear_residual_array_rgb", "vec4(FRESNEL_LUT_LINEAR_RESIDUAL_ARRAY_RGB(P0, FR_ARR, 32, c), 1.0)", ROWS_METALS, 3, OUT_REFL, 0, 130, 3, 0, PAR_F0, e_lut_lin_res_rgb, MP_SCHLICK},
};
#define NCASES ((int)(sizeof cases / sizeof cases[0]))

typedef char lut_width_is_96[LUT_W == 96 ? 1 : -1]; /* FR_ARR[96] below */

/* ------------------------------------------------------------ strips */

/* The cosines: the ends, values a GPU produces outside [0, 1] (dot products
 * of normalised vectors reach 1.00001), 440 angles uniform in theta, and 64
 * points closing in on the critical angles of glass and water seen from
 * inside, where eta^2 + c^2 - 1 cancels. */
static float cos_hp[W], cos_mp[W];

static void build_cosines(void)
{
    static const float special[8] = {0.0f, 1.0f, 1.00001f, 1.0009765625f, -1e-3f, 1.5f, 1e-6f, 0.99999994f};
    const double crit[2] = {sqrt(1.0 - 1.0 / (1.5 * 1.5)), sqrt(1.0 - 1.0 / (1.33 * 1.33))};
    int i, n = 0;
    for (i = 0; i < 8; i++)
        cos_hp[n++] = special[i];
    for (i = 0; i < 440; i++)
        cos_hp[n++] = (float)cos((i + 0.5) / 440.0 * 1.5707963267948966);
    for (i = 0; i < 64; i++) {
        int k = 4 + (i / 4) % 16;
        double s = (i & 1) ? 1.0 : -1.0;
        cos_hp[n++] = (float)(crit[(i >> 1) & 1] * (1.0 + s * ldexp(1.0, -k)));
    }
    for (i = 0; i < W; i++)
        cos_mp[i] = f16(cos_hp[i]);
}

/* ------------------------------------------------------------ shaders */

struct dialect {
    const char *name, *prelude_file;
    int es, version;
};
static const struct dialect dialects[] = {
    {"es100", "prelude_es100.glsl", 1, 100},
    {"es300", "prelude_es300.glsl", 1, 300},
    {"glsl330", "prelude_330.glsl", 0, 330},
};
#define NDIALECTS 3
enum { MODE_HIGHP, MODE_MEDIUMP, MODE_FORCED, NMODES };
static const char *const mode_names[NMODES] = {"highp", "mediump", "mediump-forced"};

static char *port_src;
static char *preludes[NDIALECTS];
static glctx g;
static GLuint fbo, fbo_tex, tex_cos_hp, tex_cos_mp, tex_lut;
static char glsl_log[16384];

static const char frag_header[] =
    "uniform vec3 P0;\nuniform vec3 P1;\nuniform vec3 P2;\nuniform vec3 P3;\n"
    "uniform highp sampler2D FR_COS;\nuniform highp sampler2D FR_LUT;\n"
    "uniform highp vec3 FR_STRIP;\nuniform highp float FR_N;\n"
    "#if __VERSION__ >= 130\nuniform highp float FR_ARR[96];\nin highp vec2 fr_uv;\nout highp vec4 fr_out;\n"
    "#define FR_OUT fr_out\n#else\nvarying highp vec2 fr_uv;\n#define FR_OUT gl_FragColor\n#endif\n";

static const char *mode_extra(const struct dialect *d, int mode)
{
    if (mode == MODE_FORCED)
        return "#define FRESNEL_HIGHP mediump\n";
    return mode == MODE_HIGHP && d->es ? "precision highp float;\n" : "";
}

static GLuint strip_program(const struct dialect *d, int mode, const char *expr)
{
    const char *parts[7];
    const char *vsrc = glctx_vertex_source(d->es, d->version);
    GLuint vs, fs;
    parts[0] = preludes[d - dialects];
    parts[1] = mode_extra(d, mode);
    parts[2] = port_src;
    parts[3] = frag_header;
    parts[4] = "void main() {\n    float c = FRESNEL_TEXTURE(FR_COS, vec2(fr_uv.x, 0.5)).r;\n    FR_OUT = ";
    parts[5] = expr;
    parts[6] = ";\n}\n";
    fs = glctx_shader(GL_FRAGMENT_SHADER, parts, 7, glsl_log, sizeof glsl_log);
    if (!fs)
        return 0;
    vs = glctx_shader(GL_VERTEX_SHADER, &vsrc, 1, glsl_log, sizeof glsl_log);
    if (!vs) {
        glDeleteShader(fs);
        return 0;
    }
    return glctx_program(vs, fs, glsl_log, sizeof glsl_log);
}

/* ------------------------------------------------------------ rendering */

static int nrows_of(const struct mcase *mc) { return mc->rows == ROWS_METALS ? NMETALS : NDIEL; }
static const char *row_name(const struct mcase *mc, int ri)
{
    return mc->rows == ROWS_METALS ? metals[ri].name : dielectrics[ri].name;
}

static void round_row_f16(struct row *r)
{
    int i, ch;
    for (i = 0; i < 4; i++)
        for (ch = 0; ch < 3; ch++)
            r->p[i][ch] = f16(r->p[i][ch]);
}

/* Renders every row of the case with prog; the float results go to out_f
 * (RGBA, rows of W) when rgba8 is 0, the bytes of the default framebuffer to
 * out_8 otherwise. Returns 0, or -1 after a GL error. */
static float out_f[MAXROWS * W * 4];
static unsigned char out_8[MAXROWS * W * 4];

static int render_case(GLuint prog, int mode, const struct mcase *mc, int rgba8)
{
    int ri, nrows = nrows_of(mc);
    glUseProgram(prog);
    glBindFramebuffer(GL_FRAMEBUFFER, rgba8 ? 0 : fbo);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, mode == MODE_HIGHP ? tex_cos_hp : tex_cos_mp);
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, tex_lut);
    glUniform1i(glGetUniformLocation(prog, "FR_COS"), 0);
    glUniform1i(glGetUniformLocation(prog, "FR_LUT"), 1);
    glUniform1f(glGetUniformLocation(prog, "FR_N"), (float)LUT_N);
    for (ri = 0; ri < nrows; ri++) {
        struct row r;
        setup_row(mc, ri, &r);
        if (mode != MODE_HIGHP)
            round_row_f16(&r);
        glUniform3fv(glGetUniformLocation(prog, "P0"), 1, r.p[0]);
        glUniform3fv(glGetUniformLocation(prog, "P1"), 1, r.p[1]);
        glUniform3fv(glGetUniformLocation(prog, "P2"), 1, r.p[2]);
        glUniform3fv(glGetUniformLocation(prog, "P3"), 1, r.p[3]);
        glUniform3fv(glGetUniformLocation(prog, "FR_STRIP"), 1, r.strip);
        /* the array holds the table from the strip's first node on */
        if (r.table)
            glUniform1fv(glGetUniformLocation(prog, "FR_ARR"), LUT_W - mc->lut_first, r.table + mc->lut_first);
        glViewport(0, ri, W, 1);
        glctx_draw(&g);
    }
    if (rgba8)
        glReadPixels(0, 0, W, nrows, GL_RGBA, GL_UNSIGNED_BYTE, out_8);
    else
        glReadPixels(0, 0, W, nrows, GL_RGBA, GL_FLOAT, out_f);
    glUseProgram(0);
    return glGetError() == GL_NO_ERROR ? 0 : (snprintf(glsl_log, sizeof glsl_log, "GL error"), -1);
}

/* Largest difference over a case's rows, cosines and channels. */
struct stats {
    double max;       /* abs (relative for OUT_PAIR_REL; LSB for rgba8) */
    int row, col;
    long bad;         /* NaN, Inf or outside [0, 1] */
    float gpu, ref;
};

static void compare(const struct mcase *mc, int mode, int rgba8, struct stats *s)
{
    int ri, x, ch;
    memset(s, 0, sizeof *s);
    for (ri = 0; ri < nrows_of(mc); ri++) {
        struct row r;
        setup_row(mc, ri, &r);
        if (mode != MODE_HIGHP)
            round_row_f16(&r);
        for (x = 0; x < W; x++) {
            float ref[3];
            float c = mode == MODE_HIGHP ? cos_hp[x] : cos_mp[x];
            mc->eval(&r, c, ref);
            for (ch = 0; ch < mc->nch; ch++) {
                size_t at = ((size_t)ri * W + (size_t)x) * 4 + (size_t)ch;
                double d;
                float gpu;
                if (rgba8) {
                    gpu = out_8[at] / 255.0f;
                    d = fabs((double)out_8[at] - (double)lrintf(ref[ch] * 255.0f));
                } else {
                    gpu = out_f[at];
                    d = fabs((double)gpu - (double)ref[ch]);
                    if (mc->out == OUT_PAIR_REL)
                        d /= fabs(ref[ch]) > 1.0 ? fabs(ref[ch]) : 1.0;
                    if (mc->out == OUT_REFL && !(gpu >= 0.0f && gpu <= 1.0f))
                        s->bad++;
                    if (isnan(d))
                        d = INFINITY;
                }
                if (d > s->max || (ri == 0 && x == 0 && ch == 0)) {
                    s->max = d;
                    s->row = ri;
                    s->col = x;
                    s->gpu = gpu;
                    s->ref = ref[ch];
                }
            }
        }
    }
}

/* Per case, for the table at the end. */
struct summary {
    double hp, mp, forced;
    double lsb;
    long forced_bad;
    int hp_row, hp_col, mp_row, mp_col, fo_row, fo_col;
    int mp_seen, forced_seen;
    double f16, f16_forced; /* mediump against the C binary16 path */
    int f16_seen, f16_forced_seen;
};
static struct summary summaries[64];

/* The C binary16 function of a scalar case, on the same binary16 inputs. */
typedef float (*eval16_fn)(const struct row *r, float c);
#if FRESNEL_HAS_F16
#define H(x) ((fresnel_f16)(x))
static float h_schlick(const struct row *r, float c) { return (float)fresnel_schlick_f16(H(P(0, 1)), H(c)); }
static float h_schlick_gen(const struct row *r, float c)
{
    return (float)fresnel_schlick_gen_f16(H(P(0, 1)), H(P(1, 1)), H(P(2, 1)), H(c));
}
static float h_schlick_internal(const struct row *r, float c)
{
    return (float)fresnel_schlick_internal_f16(H(P(0, 1)), H(P(1, 1)), H(c));
}
static float h_f0_in_medium(const struct row *r, float c) { return (float)fresnel_f0_in_medium_f16(H(c), H(P(0, 1))); }
static float h_f0_from_ior(const struct row *r, float c) { return (float)fresnel_f0_from_ior_f16(H(4.0f * c), H(P(1, 1))); }
static float h_lsk(const struct row *r, float c) { return (float)fresnel_lsk_f16(H(P(0, 1)), H(P(1, 1)), H(c)); }
static float h_lsk_comp(const struct row *r, float c)
{
    return (float)fresnel_lsk_comp_f16(H(P(0, 1)), H(P(1, 1)), H(P(2, 1)), H(P(3, 1)), H(c));
}
static float h_f82(const struct row *r, float c) { return (float)fresnel_f82_f16(H(P(0, 1)), H(P(1, 1)), H(c)); }
static float h_approx(const struct row *r, float c)
{
    return (float)fresnel_approx_conductor_f16(H(P(0, 1)), H(P(1, 1)), H(c));
}
static float h_gulb(const struct row *r, float c) { return (float)fresnel_gulbrandsen_f16(H(P(0, 1)), H(P(1, 1)), H(c)); }
static float h_ct(const struct row *r, float c)
{
    return (float)fresnel_cook_torrance_f16(H(P(0, 1)), H(P(1, 0)), H(P(1, 1)), H(c));
}
static float h_cond(const struct row *r, float c) { return (float)fresnel_conductor_f16(H(P(0, 1)), H(P(1, 1)), H(c)); }
static float h_diel(const struct row *r, float c) { return (float)fresnel_dielectric_f16(H(P(0, 1)), H(c)); }
static const struct {
    const char *name;
    eval16_fn fn;
} evals16[] = {
    {"schlick", h_schlick}, {"schlick_gen", h_schlick_gen}, {"schlick_internal", h_schlick_internal},
    {"f0_in_medium", h_f0_in_medium}, {"f0_from_ior", h_f0_from_ior}, {"lsk", h_lsk}, {"lsk_comp", h_lsk_comp},
    {"f82", h_f82}, {"approx_conductor", h_approx}, {"gulbrandsen", h_gulb}, {"cook_torrance", h_ct},
    {"conductor", h_cond}, {"dielectric", h_diel},
};
#endif

static eval16_fn eval16_of(const char *name)
{
#if FRESNEL_HAS_F16
    size_t i;
    for (i = 0; i < sizeof evals16 / sizeof evals16[0]; i++)
        if (!strcmp(evals16[i].name, name))
            return evals16[i].fn;
#else
    (void)name;
#endif
    return NULL;
}

/* Largest |GPU mediump - C binary16| over the case's rows and cosines. */
static double compare16(const struct mcase *mc, eval16_fn fn)
{
    double worst = 0.0;
    int ri, x;
    for (ri = 0; ri < nrows_of(mc); ri++) {
        struct row r;
        setup_row(mc, ri, &r);
        round_row_f16(&r);
        for (x = 0; x < W; x++) {
            double d = fabs((double)out_f[((size_t)ri * W + (size_t)x) * 4] - (double)fn(&r, cos_mp[x]));
            if (!(d <= worst))
                worst = isnan(d) ? INFINITY : d;
        }
    }
    return worst;
}

/* The checks of one case after its float render (prog is still needed for
 * the RGBA8 one). */
static void judge_case(const struct dialect *d, int mode, int ci, GLuint prog)
{
    const struct mcase *mc = &cases[ci];
    struct summary *sm = &summaries[ci];
    struct stats s;
    char name[256];
    compare(mc, mode, 0, &s);
    if (mode == MODE_HIGHP) {
        snprintf(name, sizeof name, "glsl %s highp %s: max|gpu - C| %.2g <= %.0g, %ld outside [0,1]", d->name,
                 mc->name, s.max, HIGHP_BOUND, s.bad);
        CHECK(name, s.max <= HIGHP_BOUND && s.bad == 0, "at %s c = %.9g: gpu %.9g, C %.9g", row_name(mc, s.row),
              (double)cos_hp[s.col], (double)s.gpu, (double)s.ref);
        if (s.max >= sm->hp) {
            sm->hp = s.max;
            sm->hp_row = s.row;
            sm->hp_col = s.col;
        }
        if (mc->out == OUT_PAIR_REL)
            return; /* n, k do not fit 8 bits */
        snprintf(name, sizeof name, "glsl %s rgba8 %s renders", d->name, mc->name);
        if (render_case(prog, mode, mc, 1) != 0) {
            CHECK(name, 0, "%s", glsl_log);
            return;
        }
        compare(mc, mode, 1, &s);
        snprintf(name, sizeof name, "glsl %s rgba8 %s: max %.0f LSB <= 1", d->name, mc->name, s.max);
        CHECK(name, s.max <= 1.0, "at %s c = %.9g: gpu %.9g, C %.9g", row_name(mc, s.row), (double)cos_hp[s.col],
              (double)s.gpu, (double)s.ref);
        if (s.max > sm->lsb)
            sm->lsb = s.max;
    } else if (mc->out != OUT_REFL) {
        return; /* n, k and r, g are highp quantities: not a mediump interface */
    } else if (mode == MODE_MEDIUMP) {
        snprintf(name, sizeof name, "glsl %s mediump %s: max|gpu - C| %.2g <= %.1g, %ld NaN/outside [0,1]", d->name,
                 mc->name, s.max, mc->mp_bound, s.bad);
        CHECK(name, s.max <= mc->mp_bound && s.bad == 0, "at %s c = %.9g: gpu %.9g, C %.9g",
              row_name(mc, s.row), (double)cos_mp[s.col], (double)s.gpu, (double)s.ref);
        if (s.max >= sm->mp) {
            sm->mp = s.max;
            sm->mp_row = s.row;
            sm->mp_col = s.col;
        }
        sm->mp_seen = 1;
        if (eval16_of(mc->name)) {
            double d16 = compare16(mc, eval16_of(mc->name));
            if (!(d16 <= sm->f16))
                sm->f16 = d16;
            sm->f16_seen = 1;
        }
    } else {
        if (s.max > sm->forced || isinf(s.max)) {
            sm->forced = s.max;
            sm->fo_row = s.row;
            sm->fo_col = s.col;
        }
        sm->forced_bad += s.bad;
        sm->forced_seen = 1;
        if (eval16_of(mc->name)) {
            double d16 = compare16(mc, eval16_of(mc->name));
            if (!(d16 <= sm->f16_forced))
                sm->f16_forced = d16;
            sm->f16_forced_seen = 1;
        }
    }
}

static void run_case(const struct dialect *d, int mode, int ci)
{
    const struct mcase *mc = &cases[ci];
    char name[256];
    GLuint prog;
    if (mc->min_version > 0 && !(d->es && d->version >= 300) && !(!d->es && d->version >= mc->min_version))
        return;
    if (mode == MODE_FORCED && mc->mediump_safe) {
        /* no FRESNEL_HIGHP inside: the same shader as MODE_MEDIUMP */
        summaries[ci].forced = summaries[ci].mp;
        summaries[ci].fo_row = summaries[ci].mp_row;
        summaries[ci].fo_col = summaries[ci].mp_col;
        summaries[ci].forced_seen = 1;
        return;
    }
    snprintf(name, sizeof name, "glsl %s %s %s compiles and renders", d->name, mode_names[mode], mc->name);
    prog = strip_program(d, mode, mc->expr);
    if (prog && render_case(prog, mode, mc, 0) == 0)
        judge_case(d, mode, ci, prog);
    else
        CHECK(name, 0, "%s", glsl_log);
    if (prog)
        glDeleteProgram(prog);
}

/* ------------------------------------------------------------ probes */

/* What the context is, and whether mediump is binary16 here. */
static void probe_context(void)
{
    GLint n = 0, i, range[2], prec;
    char list[1024] = "";
    NOTE("GL_VERSION %s; GL_SHADING_LANGUAGE_VERSION %s; GL_RENDERER %s", (const char *)glGetString(GL_VERSION),
         (const char *)glGetString(GL_SHADING_LANGUAGE_VERSION), (const char *)glGetString(GL_RENDERER));
    glGetIntegerv(GL_NUM_SHADING_LANGUAGE_VERSIONS, &n);
    for (i = 0; i < n; i++) {
        const char *v = (const char *)glGetStringi(GL_SHADING_LANGUAGE_VERSION, (GLuint)i);
        if (v && strlen(list) + strlen(v) + 4 < sizeof list) {
            strcat(list, *v ? v : "(empty: 110)");
            strcat(list, i + 1 < n ? ", " : "");
        }
    }
    NOTE("GLSL versions the context lists: %s", list);
    {
        /* the compatibility profile, for the record; the tests use core */
        static unsigned char px[16 * 4];
        int attr[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_PROFILE, OSMESA_COMPAT_PROFILE, 0};
        OSMesaContext compat = OSMesaCreateContextAttribs(attr, NULL);
        if (compat && OSMesaMakeCurrent(compat, px, GL_UNSIGNED_BYTE, 4, 4))
            NOTE("compatibility profile: GL_VERSION %s", (const char *)glGetString(GL_VERSION));
        else
            NOTE("compatibility profile: not available");
        if (compat)
            OSMesaDestroyContext(compat);
        OSMesaMakeCurrent(g.ctx, g.pixels, GL_UNSIGNED_BYTE, g.width, g.height);
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    }
    glGetShaderPrecisionFormat(GL_FRAGMENT_SHADER, GL_MEDIUM_FLOAT, range, &prec);
    NOTE("fragment mediump float: range 2^+-%d, %d significand bits after the point", (int)range[0], (int)prec);
    glGetShaderPrecisionFormat(GL_FRAGMENT_SHADER, GL_HIGH_FLOAT, range, &prec);
    NOTE("fragment highp float: range 2^+-%d, %d significand bits after the point", (int)range[0], (int)prec);
}

/* From uniforms, so nothing is folded at compile time; each probe ends in
 * an exact multiplication, because Mesa drops a binary16 rounding that is
 * immediately converted back to binary32 (f2f32(f2fmp(x)) -> x), so the
 * last operation before a highp output may keep binary32 precision.
 * U = (1.0001, 300, 2^-20, 1 + 3 2^-12), V = (1, 0.5). */
static void probe_mediump(const struct dialect *d)
{
    static const char body[] =
        "uniform vec4 U;\nuniform vec2 V;\n"
        "#if __VERSION__ >= 130\nout highp vec4 fr_out;\n#define FR_OUT fr_out\n#else\n#define FR_OUT gl_FragColor\n#endif\n"
        "void main() { FR_OUT = vec4((U.x * V.x) * V.y, (U.y * U.y) * V.y, (U.z * V.x) * V.y,"
        " ((U.w * V.x) - V.x) * 1024.0); }\n";
    const char *parts[2];
    const char *vsrc = glctx_vertex_source(d->es, d->version);
    float v[4];
    char name[256];
    GLuint fs, vs, p;
    parts[0] = preludes[d - dialects];
    parts[1] = body;
    fs = glctx_shader(GL_FRAGMENT_SHADER, parts, 2, glsl_log, sizeof glsl_log);
    vs = glctx_shader(GL_VERTEX_SHADER, &vsrc, 1, glsl_log + 8192, 8192);
    p = fs && vs ? glctx_program(vs, fs, glsl_log, sizeof glsl_log) : 0;
    snprintf(name, sizeof name, "glsl %s mediump probe compiles", d->name);
    CHECK(name, p != 0, "%s", glsl_log);
    if (!p)
        return;
    glUseProgram(p);
    glUniform4f(glGetUniformLocation(p, "U"), 1.0001f, 300.0f, 9.5367431640625e-07f, 1.000732421875f);
    glUniform2f(glGetUniformLocation(p, "V"), 1.0f, 0.5f);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glViewport(0, 0, 1, 1);
    glctx_draw(&g);
    glReadPixels(0, 0, 1, 1, GL_RGBA, GL_FLOAT, v);
    glUseProgram(0);
    glDeleteProgram(p);
    NOTE("%s mediump on this context: 1.0001 * 1 -> %.9g (binary32 1.0001, binary16 1), 300 * 300 -> %g "
         "(binary32 90000, binary16 Inf), 2^-20 * 1 -> %g (%s), 1 + 3 2^-12 -> 1 + %g 2^-10 (%s)",
         d->name, (double)(2.0f * v[0]), (double)(2.0f * v[1]), (double)(2.0f * v[2]),
         v[2] == 0.0f ? "binary16 subnormals flushed to 0" : "binary16 subnormal kept", (double)v[3],
         v[3] == 1.0f ? "rounded to nearest" : v[3] == 0.0f ? "rounded toward 0" : "not rounded to binary16");
    snprintf(name, sizeof name, "glsl %s: llvmpipe computes mediump in binary16 (11-bit significand, Inf past 65504)",
             d->name);
    CHECK(name, v[0] == 0.5f && isinf(v[1]), "got %.9g and %g: mediump is not binary16 here, so the mediump "
          "figures say nothing about mobile GPUs", (double)(2.0f * v[0]), (double)(2.0f * v[1]));
}

/* GLSL leaves NaN undefined; record what llvmpipe does with non-finite c
 * (the C runtime: NaN and -Inf give c = 0, +Inf gives 1). */
static void probe_nonfinite(void)
{
    const float cs[4] = {NAN, INFINITY, -INFINITY, 0.5f};
    const char *expr = "vec4(fresnel_schlick(0.04, c), fresnel_conductor(0.2, 3.0, c), fresnel_dielectric(1.5, c),"
                       " fresnel_f82(0.9, 0.8, c))";
    GLuint prog = strip_program(&dialects[1], MODE_HIGHP, expr), tex;
    int i;
    if (!prog) {
        CHECK("glsl non-finite probe compiles", 0, "%s", glsl_log);
        return;
    }
    tex = glctx_r32f_texture(4, 1, cs);
    glUseProgram(prog);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, tex);
    glUniform1i(glGetUniformLocation(prog, "FR_COS"), 0);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glViewport(0, 0, W, 1);
    glctx_draw(&g);
    glUseProgram(0);
    glDeleteProgram(prog);
    glDeleteTextures(1, &tex);
    /* texel i of a 4-wide texture covers pixels 128 i .. 128 i + 127 */
    for (i = 0; i < 4; i++) {
        float px[4];
        glReadPixels(128 * i + 64, 0, 1, 1, GL_RGBA, GL_FLOAT, px);
        NOTE("es300 highp, c = %g: schlick %g, conductor %g, dielectric %g, f82 %g (C runtime: %g %g %g %g)",
             (double)cs[i], (double)px[0], (double)px[1], (double)px[2], (double)px[3],
             (double)fresnel_schlick(0.04f, cs[i]), (double)fresnel_conductor(0.2f, 3.0f, cs[i]),
             (double)fresnel_dielectric(1.5f, cs[i]), (double)fresnel_f82(0.9f, 0.8f, cs[i]));
    }
}

/* The gallery's PNG writer: the two checksums on known values. */
static void check_png(void)
{
    CHECK("png: CRC-32 of \"IEND\" is 0xAE426082", png_crc32(0, (const unsigned char *)"IEND", 4) == 0xAE426082u,
          "got 0x%08lX", (unsigned long)png_crc32(0, (const unsigned char *)"IEND", 4));
    CHECK("png: Adler-32 of \"Wikipedia\" is 0x11E60398",
          png_adler32(1, (const unsigned char *)"Wikipedia", 9) == 0x11E60398u, "got 0x%08lX",
          (unsigned long)png_adler32(1, (const unsigned char *)"Wikipedia", 9));
}

/* Every function of the port in one shader, to compile in each dialect. */
static const char all_calls[] =
    "uniform vec3 P0;\nuniform FRESNEL_HIGHP sampler2D FR_LUT;\n"
    "#if __VERSION__ >= 130\nuniform FRESNEL_HIGHP float FR_ARR[96];\n#endif\n"
    "vec4 fr_all() {\n"
    "    float c = 0.5 + 0.1 * P0.x;\n"
    "    vec3 e = P0 + 0.2, k = P0 * 3.0, s = vec3(0.0);\n"
    "    vec3 st = vec3(0.5 / 96.0, 0.5, 1.0 / 96.0);\n"
    "    s += fresnel_schlick(P0.x, c) + fresnel_schlick_rgb(P0, c);\n"
    "    s += fresnel_schlick_gen(P0.x, 1.0, 3.0, c) + fresnel_schlick_gen_rgb(P0, P0, 5.0, c);\n"
    "    s += fresnel_schlick_internal(P0.x, 0.7, c) + fresnel_schlick_internal_rgb(P0, 0.7, c);\n"
    "    s += fresnel_f0_in_medium(P0.x, 1.33) + fresnel_f0_from_ior(e.x, k.x);\n"
    "    s += fresnel_lsk(e.x, k.x, c) + fresnel_lsk_rgb(e, k, c);\n"
    "    s += fresnel_lsk_comp(e.x, k.x, 0.3, 8.0, c) + fresnel_lsk_comp_rgb(e, k, e, k, c);\n"
    "    s += fresnel_f82(P0.x, P0.y, c) + fresnel_f82_rgb(P0, P0.zyx, c);\n"
    "    s += fresnel_approx_conductor(e.x, k.x, c) + fresnel_approx_conductor_rgb(e, k, c);\n"
    "    s += vec3(fresnel_gulbrandsen_nk(P0.x, P0.y), 0.0) + vec3(fresnel_gulbrandsen_rg(e.x, k.x), 0.0);\n"
    "    s += fresnel_gulbrandsen(P0.x, P0.y, c) + fresnel_gulbrandsen_rgb(P0, P0.zyx, c);\n"
    "    s += fresnel_cook_torrance(P0.x, e.x, k.x, c) + fresnel_cook_torrance_rgb(P0, e.x, k.x, c);\n"
    "    s += fresnel_conductor(e.x, k.x, c) + fresnel_conductor_rgb(e, k, c) + fresnel_dielectric(e.x, c);\n"
    "    s += fresnel_lut(FR_LUT, st, 32.0, c) + fresnel_lut_linear(FR_LUT, st, 32.0, c);\n"
    "    s += fresnel_lut_residual(P0.x, FR_LUT, st, 32.0, c) + fresnel_lut_linear_residual(P0.x, FR_LUT, st, 32.0, c);\n"
    "    s += fresnel_lut_rgb(FR_LUT, st, 32.0, c) + fresnel_lut_linear_rgb(FR_LUT, st, 32.0, c);\n"
    "    s += fresnel_lut_residual_rgb(P0, FR_LUT, st, 32.0, c) + fresnel_lut_linear_residual_rgb(P0, FR_LUT, st, 32.0, c);\n"
    "    s += fresnel_lut_packed_rgb(FR_LUT, st, 32.0, c) + fresnel_lut_linear_packed_rgb(FR_LUT, st, 32.0, c);\n"
    "    s += fresnel_lut_residual_packed_rgb(P0, FR_LUT, st, 32.0, c) + fresnel_lut_cubic_packed_rgb(FR_LUT, st, 32.0, c);\n"
    "    s += fresnel_lut_linear_residual_packed_rgb(P0, FR_LUT, st, 32.0, c);\n"
    "#if __VERSION__ >= 130\n"
    "    s += FRESNEL_LUT_ARRAY(FR_ARR, 32, c) + FRESNEL_LUT_LINEAR_ARRAY(FR_ARR, 32, c);\n"
    "    s += FRESNEL_LUT_RESIDUAL_ARRAY(P0.x, FR_ARR, 32, c) + FRESNEL_LUT_LINEAR_RESIDUAL_ARRAY(P0.x, FR_ARR, 32, c);\n"
    "    s += FRESNEL_LUT_ARRAY_RGB(FR_ARR, 32, c) + FRESNEL_LUT_LINEAR_ARRAY_RGB(FR_ARR, 32, c);\n"
    "    s += FRESNEL_LUT_RESIDUAL_ARRAY_RGB(P0, FR_ARR, 32, c) + FRESNEL_LUT_LINEAR_RESIDUAL_ARRAY_RGB(P0, FR_ARR, 32, c);\n"
    "    s += fresnel_lut_lerp(FR_ARR[0], FR_ARR[1], fresnel_lut_pos(32.0, c).y);\n"
    "#endif\n"
    "    return vec4(s, 1.0);\n}\n";

/* A const array table (what `fresnel gen --glsl` would emit) must also
 * compile in the dialects that have array initialisers. */
static const char const_array[] =
    "const highp float FR_CONST[4] = float[4](0.9, 0.92, 0.95, 1.0);\n"
    "vec4 fr_const() { return vec4(FRESNEL_LUT_ARRAY(FR_CONST, 4, P0.x)); }\n";

/* Compile the port in every GLSL version the context lists: both stages,
 * mediump and highp default (ES), and with FRESNEL_HIGHP forced to mediump. */
static void compile_everywhere(void)
{
    GLint n = 0, i;
    glGetIntegerv(GL_NUM_SHADING_LANGUAGE_VERSIONS, &n);
    for (i = 0; i < n; i++) {
        const char *v = (const char *)glGetStringi(GL_SHADING_LANGUAGE_VERSION, (GLuint)i);
        int es = v && strstr(v, " es") != NULL;
        int ver = v ? atoi(v) : 0;
        int stage, prec;
        char version_line[64];
        if (!v)
            continue;
        if (!*v)
            ver = 110; /* the empty string stands for the version without a #version line */
        es = es || ver == 100;
        snprintf(version_line, sizeof version_line, "#version %d%s\n", ver, es && ver > 100 ? " es" : "");
        for (stage = 0; stage < 2; stage++)
            for (prec = 0; prec < (es ? 3 : 1); prec++) {
                const char *parts[8];
                char name[160];
                int np = 0;
                GLuint s;
                parts[np++] = version_line;
                if (es || ver >= 130)
                    parts[np++] = prec == 1 ? "precision highp float;\n" : "precision mediump float;\n";
                if (prec == 2)
                    parts[np++] = "#define FRESNEL_HIGHP mediump\n";
                parts[np++] = port_src;
                parts[np++] = all_calls;
                if (es ? ver >= 300 : ver >= 330)
                    parts[np++] = const_array;
                if (stage == 0)
                    parts[np++] = "void main() { gl_Position = fr_all(); }\n";
                else if (ver >= 130)
                    parts[np++] = "out highp vec4 fr_o;\nvoid main() { fr_o = fr_all(); }\n";
                else
                    parts[np++] = "void main() { gl_FragColor = fr_all(); }\n";
                s = glctx_shader(stage ? GL_FRAGMENT_SHADER : GL_VERTEX_SHADER, parts, np, glsl_log,
                                 sizeof glsl_log);
                snprintf(name, sizeof name, "glsl compiles: #version %d%s, %s shader, %s", ver,
                         es && ver > 100 ? " es" : "", stage ? "fragment" : "vertex",
                         !es ? "binary32 throughout"
                         : prec == 0 ? "mediump default" : prec == 1 ? "highp default" : "FRESNEL_HIGHP mediump");
                CHECK(name, s != 0, "info log:\n%s", glsl_log);
                if (s)
                    glDeleteShader(s);
            }
    }
}

/* ------------------------------------------------------------ main */

int main(int argc, char **argv)
{
    char path[1024], err[256];
    int di, mode, ci, i;
    float *lut_tex;
    if (argc != 2) {
        fprintf(stderr, "usage: glsl_port_osmesa PORT_DIR\n");
        return 2;
    }
    snprintf(path, sizeof path, "%s/fresnel.glsl", argv[1]);
    port_src = glctx_read_file(path);
    CHECK("glsl: ports/glsl/fresnel.glsl readable", port_src != NULL, "cannot read %s", path);
    for (di = 0; di < NDIALECTS; di++) {
        snprintf(path, sizeof path, "%s/%s", argv[1], dialects[di].prelude_file);
        preludes[di] = glctx_read_file(path);
        CHECK("glsl: prelude readable", preludes[di] != NULL, "cannot read %s", path);
        if (!preludes[di])
            return harness_exit();
    }
    if (!port_src)
        return harness_exit();
    if (glctx_open(&g, W, MAXROWS, err, sizeof err) != 0) {
        CHECK("glsl: OSMesa context", 0, "%s", err);
        return harness_exit();
    }
    CHECK("glsl: OSMesa context", 1, "%s", "");
    fbo = glctx_float_target(W, MAXROWS, &fbo_tex);
    CHECK("glsl: RGBA32F framebuffer complete", fbo != 0, "glCheckFramebufferStatus failed");
    if (!fbo)
        return harness_exit();

    build_cosines();
    build_luts();
    tex_cos_hp = glctx_r32f_texture(W, 1, cos_hp);
    tex_cos_mp = glctx_r32f_texture(W, 1, cos_mp);
    lut_tex = malloc(sizeof(float) * LUT_W * NMETALS * LUT_VARIANTS);
    if (!lut_tex)
        return 1;
    for (i = 0; i < NMETALS * LUT_VARIANTS; i++)
        memcpy(lut_tex + (size_t)i * LUT_W, lut_tables[i / LUT_VARIANTS][i % LUT_VARIANTS], sizeof(float) * LUT_W);
    tex_lut = glctx_r32f_texture(LUT_W, NMETALS * LUT_VARIANTS, lut_tex);
    free(lut_tex);

    if (!FRESNEL_HAS_F16)
        NOTE("the C binary16 path (include/fresnel_f16.h with _Float16) is not available to this build");
    check_png();
    probe_context();
    probe_nonfinite();
    probe_mediump(&dialects[0]);
    probe_mediump(&dialects[1]);
    compile_everywhere();

    for (di = 0; di < NDIALECTS; di++)
        for (mode = 0; mode < NMODES; mode++) {
            if (!dialects[di].es && mode != MODE_HIGHP)
                continue; /* desktop GLSL ignores precision qualifiers */
            for (ci = 0; ci < NCASES; ci++)
                run_case(&dialects[di], mode, ci);
        }

    NOTE("table: function | highp max|gpu-C| (ES 1.00, ES 3.00, 3.30) | worst at | RGBA8 max LSB | "
         "mediump max|gpu-C| (ES 1.00, 3.00) | worst at | FRESNEL_HIGHP=mediump max|gpu-C| (NaN/out of range) | "
         "worst at");
    for (ci = 0; ci < NCASES; ci++) {
        const struct mcase *mc = &cases[ci];
        const struct summary *sm = &summaries[ci];
        char mp[96] = "-", fo[96] = "-", lsb[16] = "-", hpat[64];
        if (sm->mp_seen && sm->mp > 0.0)
            snprintf(mp, sizeof mp, "%.2g | %s c=%.4g", sm->mp, row_name(mc, sm->mp_row), (double)cos_mp[sm->mp_col]);
        else if (sm->mp_seen)
            snprintf(mp, sizeof mp, "0 | -");
        else
            snprintf(mp, sizeof mp, "- | -");
        if (sm->forced_seen && sm->forced > 0.0)
            snprintf(fo, sizeof fo, "%.2g (%ld) | %s c=%.4g", sm->forced, sm->forced_bad, row_name(mc, sm->fo_row),
                     (double)cos_mp[sm->fo_col]);
        else if (sm->forced_seen)
            snprintf(fo, sizeof fo, "0 (%ld) | -", sm->forced_bad);
        else
            snprintf(fo, sizeof fo, "- | -");
        if (mc->out != OUT_PAIR_REL)
            snprintf(lsb, sizeof lsb, "%.0f", sm->lsb);
        if (sm->hp > 0.0)
            snprintf(hpat, sizeof hpat, "%s c=%.6g", row_name(mc, sm->hp_row), (double)cos_hp[sm->hp_col]);
        else
            snprintf(hpat, sizeof hpat, "-");
        NOTE("table: %s | %.2g | %s | %s | %s | %s", mc->name, sm->hp, hpat, lsb, mp, fo);
        if (sm->f16_seen && sm->f16_forced_seen)
            NOTE("f16: %s: mediump GPU against the C binary16 path (fresnel_%s_f16) on the same inputs: max %.2g; "
                 "with FRESNEL_HIGHP = mediump: max %.2g", mc->name, mc->name, sm->f16, sm->f16_forced);
        else if (sm->f16_seen)
            NOTE("f16: %s: mediump GPU against the C binary16 path (fresnel_%s_f16) on the same inputs: max %.2g",
                 mc->name, mc->name, sm->f16);
    }
    glDeleteTextures(1, &tex_cos_hp);
    glDeleteTextures(1, &tex_cos_mp);
    glDeleteTextures(1, &tex_lut);
    glDeleteTextures(1, &fbo_tex);
    glDeleteFramebuffers(1, &fbo);
    glctx_close(&g);
    free(port_src);
    for (di = 0; di < NDIALECTS; di++)
        free(preludes[di]);
    return harness_exit();
}
