/* What every test of a shading-language port runs and compares (Vulkan:
 * vulkan_test.c; MSL on the host: msl_host_test.c): the cosines, the thin
 * film's thickness per cosine, the port functions no scene model calls with
 * their C runtime values, and each scene model's C runtime values on the
 * cosines (what the C header of the same manifest computes). Static
 * functions, one copy per test program. */
#ifndef FRESNEL_TESTS_PORT_CHECKS_H
#define FRESNEL_TESTS_PORT_CHECKS_H

#include <stdlib.h>

#include "fresnel.h"
#include "fresnel_f16.h"
#include "fresnel_film.h"
#include "2_derive/derive.h"
#include "model/encoded_scene.h"
#include "model/registry.h"
#include "scene/scene.h"
#include "port_scene.h"

/* every cosine c = i/1024, i = -1..1025 (both ends just outside [0, 1]) */
#define C_LO (-1)
#define C_HI 1025
#define NCOS (C_HI - C_LO + 1)
/* max |port - C| on the binary32 routes */
#define HIGHP_BOUND 1e-5

/* The thin film's thickness at cosine index i, the same binary32 value in
 * a shader (FILM_D is valid GLSL, HLSL and MSL) and here: 0-1195 nm,
 * scattered over the cosines (every product exact). */
#define FILM_D "float((i * 157) % 256) * 4.6875"
static inline float film_d(int i) { return (float)((i * 157) % 256) * 4.6875f; }

static inline float port_cosine(int k) { return (float)(k + C_LO) / 1024.0f; }

/* The port functions no scene model calls: each an expression of c valid in
 * GLSL, HLSL and MSL, and the C runtime's value. 1/1.5 and 1/1.33 as their
 * binary32 values, so both sides see the same eta. */
static float f_diel(float c) { return fresnel_dielectric(1.5f, c); }
static float f_diel_in(float c) { return fresnel_dielectric(0.666666687f, c); }
static float f_internal(float c) { return fresnel_schlick_internal(0.04f, 0.751879692f, c); }
static float f_gen(float c) { return fresnel_schlick_gen(0.04f, 0.9f, 3.7f, c); }
static float f_medium(float c) { return fresnel_f0_in_medium(c, 1.33f); }
static float f_ior(float c) { return fresnel_f0_from_ior(4.0f * c, 2.0f); }
static float f_rg_r(float c) { return fresnel_gulbrandsen_rg(4.0f * c, 2.0f).r; }
static float f_rg_g(float c) { return fresnel_gulbrandsen_rg(4.0f * c, 2.0f).g; }
static float f_nk_n(float c) { return fresnel_gulbrandsen_nk(c, 0.3f).n; }
static float f_nk_k(float c) { return fresnel_gulbrandsen_nk(c, 0.3f).k; }
/* rel: compared relative to max(|C|, 1) (n and k reach 4e4 at r = 0.9999) */
static const struct port_func {
    const char *expr;
    float (*eval)(float c);
    int rel;
} port_funcs[] = {
    {"fresnel_dielectric(1.5, c)", f_diel, 0},
    {"fresnel_dielectric(0.666666687, c)", f_diel_in, 0},
    {"fresnel_schlick_internal(0.04, 0.751879692, c)", f_internal, 0},
    {"fresnel_schlick_gen(0.04, 0.9, 3.7, c)", f_gen, 0},
    {"fresnel_f0_in_medium(c, 1.33)", f_medium, 0},
    {"fresnel_f0_from_ior(4.0 * c, 2.0)", f_ior, 0},
    {"fresnel_gulbrandsen_rg(4.0 * c, 2.0).x", f_rg_r, 0},
    {"fresnel_gulbrandsen_rg(4.0 * c, 2.0).y", f_rg_g, 0},
    {"fresnel_gulbrandsen_nk(c, 0.3).x", f_nk_n, 1},
    {"fresnel_gulbrandsen_nk(c, 0.3).y", f_nk_k, 1},
};
#define NFUNCS ((int)(sizeof port_funcs / sizeof port_funcs[0]))

/* |port - C| for port function k, relative where the function's is. */
static inline double port_func_diff(int k, double got, float c)
{
    double e = port_funcs[k].eval(c), d = got > e ? got - e : e - got;
    if (port_funcs[k].rel && (e > 1.0 || e < -1.0))
        d /= e > 0.0 ? e : -e;
    return d;
}

/* The scene's C runtime values: ref[(m nmat + i) NCOS 3 + 3 k + ch] for
 * model m, material i, cosine index k (the thin film at film_d(k)), and
 * each material's prepared models in models[i model_count + m] (the film's
 * table for a test that hands it to a GPU). 0, or -1 (the scene's
 * materials did not derive). */
static inline int port_scene_refs(const scene *sc, const gen_context *gc, material_params *params,
                                  spectrum *spectra, scene_model *models, float *ref)
{
    int i, m, k, nmat = sc->material_count;
    for (i = 0; i < nmat; i++) {
        material_source ms = scene_material(sc, i);
        if (derive_parameters(gc, &ms, sc->sigma, sc->n1, &spectra[i], &params[i]))
            return -1;
        for (m = 0; m < sc->model_count; m++) {
            scene_model *sm = &models[i * sc->model_count + m];
            if (scene_model_prepare(&sc->models[m], sc->spacing, &spectra[i], gc, &params[i], sm))
                return -1;
            for (k = 0; k < NCOS; k++) {
                float *r = ref + 3 * (((size_t)m * nmat + i) * NCOS + k);
                model_rgb q = scene_model_rgb(sm);
                fresnel_rgb v;
                q.d_nm = film_d(k); /* read by the thin film only */
                v = q.def->f32->scene(&q, port_cosine(k));
                r[0] = v.r, r[1] = v.g, r[2] = v.b;
            }
        }
    }
    return 0;
}

/* A cell of a port's NOTE table: the max difference, or "not run". */
static inline void port_cell(char cell[32], int ran, double worst)
{
    if (ran)
        snprintf(cell, 32, "%.2g", worst);
    else
        snprintf(cell, 32, "not run");
}

/* The binary16 bound of scene model m (fresnel_f16.h's FRESNEL_BOUND_*). */
static inline double port_f16_bound(const scene *sc, int m)
{
    const model *row = model_of(sc->models[m].row);
    if (row->f16_bound > 0.0)
        return row->f16_bound;
    if (sc->models[m].lut_n)
        return row->form == LUT_CUBIC ? FRESNEL_BOUND_LUT_CUBIC_F16 : FRESNEL_BOUND_LUT_F16;
    return 0.0;
}

/* The bound of scene model m where the mediump-safe functions compute in
 * binary16 (MSL's FRESNEL_MSL_HALF, SPIR-V's Float16 from mediump): they
 * keep the binary16 runtime's bound (fresnel_f16.h, below 1 for each of
 * them), and so does a residual table's Schlick base; the exact conductor and dielectric, Gulbrandsen,
 * the tables and the film compute in float whatever FRESNEL_MP is (1e-5);
 * Cook-Torrance interpolates in float between F0 and 1 with F0 and its
 * result in half: one binary16 rounding of each, 2 x 2^-11 below 1. */
static inline double port_half_bound(const scene *sc, int m)
{
    const model *row = model_of(sc->models[m].row);
    if (sc->models[m].row == MODEL_ROW_cook_torrance)
        return 2.0 * 0x1p-11;
    if (sc->models[m].row == MODEL_ROW_gulbrandsen || (row->offered & MODEL_FILM))
        return HIGHP_BOUND; /* highp functions in every port */
    if (sc->models[m].lut_n && row->form == LUT_RESIDUAL)
        return FRESNEL_BOUND_SCHLICK_F16;
    if (sc->models[m].lut_n || row->f16_bound >= 1.0)
        return HIGHP_BOUND;
    return port_f16_bound(sc, m);
}

/* A mediump shader's bound for scene model m after SPIR-V's relaxed
 * precision became explicit binary16 (spirv-opt --convert-relaxed-to-half):
 * the binary16 bound of the functions that compute in binary16
 * (port_half_bound), and at least one binary16 rounding of the result
 * (2^-12 below 1) for the highp ones, whose vec3 result a mediump shader
 * returns in mediump. */
static inline double port_float16_bound(const scene *sc, int m)
{
    double b = port_half_bound(sc, m);
    return b > 0x1p-12 + HIGHP_BOUND ? b : 0x1p-12 + HIGHP_BOUND;
}

#endif
