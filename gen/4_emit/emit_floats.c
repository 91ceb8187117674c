/* A material's floating-point constants, the same list in every
 * floating-point number type and back end (emit.h: emit_float_params), and
 * the C float literal. */
#include <stdio.h>
#include <string.h>

#include "4_emit/emit.h"

/* A binary32 literal that reads back to the same float (GLSL and HLSL:
 * emit_glsl.c's emit_shader_float). */
void emit_c_float(FILE *f, double v)
{
    char buf[40];
    snprintf(buf, sizeof buf, "%.9g", (double)(float)v);
    fputs(buf, f);
    if (!strpbrk(buf, ".e"))
        fputs(".0", f);
    fputc('f', f);
}

static void d3(fresnel_rgb v, double out[3])
{
    out[0] = v.r;
    out[1] = v.g;
    out[2] = v.b;
}

void emit_material_params(FILE *f, const scene *sc, const encoded_material *e, const char *prefix, emit_rgb_fn rgb,
                          emit_float_fn flt)
{
    emit_floats v;
    int src;
    d3(e->f0, v.f0);
    d3(e->f_avg, v.f_avg);
    d3(e->f82, v.f82);
    d3(e->lsk_a, v.lsk_a);
    d3(e->lsk_alpha, v.lsk_alpha);
    d3(e->gulb_r, v.gulb_r);
    d3(e->gulb_g, v.gulb_g);
    for (src = 0; src < ETA_SOURCES; src++) {
        d3(e->eta[src], v.eta[src]);
        d3(e->kappa[src], v.kappa[src]);
    }
    v.ct_eta = e->ct_eta;
    v.ct_kappa = e->ct_kappa;
    emit_float_params(f, sc, &v, prefix, rgb, flt);
}

/* One material's floating-point parameters, those its scene's models need:
 * the same list in every floating-point type and back end, each giving its
 * own syntax. */
void emit_float_params(FILE *f, const scene *sc, const emit_floats *v, const char *prefix, emit_rgb_fn rgb,
                       emit_float_fn flt)
{
    unsigned reads = scene_reads(sc, 0);
    if (reads & MP_F0)
        rgb(f, prefix, "f0", v->f0, "F0: ground truth at normal incidence");
    if (sc->f_avg)
        rgb(f, prefix, "f_avg", v->f_avg, "F_avg: 2 int F(mu) mu dmu of the ground truth (multiple-scattering albedo)");
    if (reads & MP_F82)
        rgb(f, prefix, "f82", v->f82, "F82: ground truth at cos theta = 1/7 (fresnel_f82_rgb)");
    if (reads & MP_ETA_FIT) {
        rgb(f, prefix, "eta", v->eta[ETA_FIT], "eta fitted to the ground truth (exact, lsk, approx-conductor)");
        rgb(f, prefix, "kappa", v->kappa[ETA_FIT], "kappa fitted to the ground truth");
    }
    if (reads & MP_LSK) {
        rgb(f, prefix, "lsk_a", v->lsk_a, "LSK compensation weight a (fresnel_lsk_comp_rgb)");
        rgb(f, prefix, "lsk_alpha", v->lsk_alpha, "LSK compensation exponent alpha");
    }
    if (reads & MP_ETA_GAUSS) {
        rgb(f, prefix, "eta_gaussian", v->eta[ETA_GAUSS], "Metzgar: eta' in a Gaussian window (fresnel_conductor_rgb)");
        rgb(f, prefix, "kappa_gaussian", v->kappa[ETA_GAUSS], "Metzgar: kappa' in a Gaussian window");
    }
    if (reads & MP_ETA_POINT) {
        rgb(f, prefix, "eta_point", v->eta[ETA_POINT],
            "eta point-sampled at the dominant wavelengths (fresnel_conductor_rgb)");
        rgb(f, prefix, "kappa_point", v->kappa[ETA_POINT], "kappa point-sampled at the dominant wavelengths");
    }
    if (reads & MP_GULB) {
        rgb(f, prefix, "gulbrandsen_r", v->gulb_r, "Gulbrandsen reflectivity r = F0 (fresnel_gulbrandsen_rgb)");
        rgb(f, prefix, "gulbrandsen_g", v->gulb_g, "Gulbrandsen edge tint g from F0 and the fitted eta");
    }
    if (reads & MP_CT) {
        flt(f, prefix, "ct_eta", v->ct_eta,
            "Cook-Torrance representative IOR at the green wavelength (fresnel_cook_torrance_rgb)");
        flt(f, prefix, "ct_kappa", v->ct_kappa, "Cook-Torrance representative kappa");
    }
}
