/* Other renderers' metals: the table of targets (targets.h). Each row's
 * formula is transcribed in common/reference_targets.c beside its source;
 * the ranges are what that source states, and where it states none the
 * row says what the fit assumes. */
#include "2_derive/targets.h"

#include <string.h>

#include "fresnel.h"
#include "common/reference.h"
#include "common/reference_film.h"

/* MaterialX states no range for generalized_schlick_bsdf's inputs; the fit
 * searches this box. The 16 metals of data/scenes/report.scene fit inside
 * it with room to spare (colours at most 1.024, exponents 3.3-6.5 in linear
 * sRGB); a result on its edge would show in the parameters printed. */
#define MX_COLOUR_MAX 2.0
#define MX_EXPONENT_MIN 1.0
#define MX_EXPONENT_MAX 10.0
/* MaterialX's shader generators sum the film's series to this order by
 * default (GenOptions::hwAiryFresnelIterations). */
#define MX_AIRY_ITERATIONS 2

static double clamp_to(double x, double lo, double hi) { return ref_clamp(x, lo, hi); }

/* The F82-tint value that puts the curve through f82 at cos = 1/7: the
 * edge value over Schlick's there. */
static double tint_through(double f0, double f82)
{
    double edge = f0 + (1.0 - f0) * (7776.0 / 16807.0); /* (6/7)^5 */
    return edge > 0.0 ? f82 / edge : 1.0;
}

/* glTF's film over its metal: x = baseColorFactor r, g, b, the film's
 * index, its thickness in nm; in air, the result held to [0, 1] as a
 * renderer's stored colour is. */
static void eval_gltf_film(const double *x, double c, const film_cmfs *k, double rgb[3])
{
    int ch;
    (void)k;
    ref_film_khr_iridescence(1.0, x[3], x[4], c, x, rgb);
    for (ch = 0; ch < 3; ch++)
        rgb[ch] = ref_clamp(rgb[ch], 0.0, 1.0);
}

/* OpenPBR's film over its metal: x = base_color, specular_color, the film's
 * index and thickness in nm; MaterialX's film with color90 = 1, exponent 5
 * (the specification's reference graph, libraries/bxdf/open_pbr_surface.mtlx
 * of MaterialX: the metal a generalized_schlick_bsdf with color0 =
 * base_color, color82 = specular_color, under thinfilm_thickness
 * = thin_film_thickness x 1000 and thinfilm_ior). */
static void eval_openpbr_film(const double *x, double c, const film_cmfs *k, double rgb[3])
{
    const double one[3] = {1.0, 1.0, 1.0};
    (void)k;
    ref_film_materialx(x[6], x[7], c, x, x + 3, one, 5.0, MX_AIRY_ITERATIONS, rgb);
}

/* MaterialX's: x = color0, color82, color90, exponent, index, thickness. */
static void eval_materialx_film(const double *x, double c, const film_cmfs *k, double rgb[3])
{
    (void)k;
    ref_film_materialx(x[10], x[11], c, x, x + 3, x + 6, x[9], MX_AIRY_ITERATIONS, rgb);
}

/* Blender's: x = base_color, specular_tint, index, thickness. */
static void eval_blender_film(const double *x, double c, const film_cmfs *k, double rgb[3])
{
    ref_film_blender(x[6], x[7], c, x, x + 3, k, rgb);
}

static void eval_openpbr(const double *x, double c, double rgb[3])
{
    int ch;
    for (ch = 0; ch < 3; ch++)
        rgb[ch] = ref_openpbr_f82_tint(x[ch], x[3 + ch], c);
}

static void eval_materialx(const double *x, double c, double rgb[3])
{
    int ch;
    for (ch = 0; ch < 3; ch++)
        rgb[ch] = ref_materialx_schlick(x[ch], x[3 + ch], x[6 + ch], x[9], c);
}

static void eval_blender(const double *x, double c, double rgb[3])
{
    int ch;
    for (ch = 0; ch < 3; ch++)
        rgb[ch] = ref_blender_f82_tint(x[ch], x[3 + ch], c);
}

static void eval_unreal(const double *x, double c, double rgb[3])
{
    int ch;
    for (ch = 0; ch < 3; ch++)
        rgb[ch] = ref_unreal_adobe_f82(x[ch], x[3 + ch], c);
}

static void eval_gltf(const double *x, double c, double rgb[3])
{
    int ch;
    for (ch = 0; ch < 3; ch++)
        rgb[ch] = ref_schlick(x[ch], c);
}

static void eval_filament(const double *x, double c, double rgb[3])
{
    double f90 = ref_filament_f90(x);
    int ch;
    for (ch = 0; ch < 3; ch++)
        rgb[ch] = ref_schlick_gen(x[ch], f90, 5.0, c);
}

static void eval_gulbrandsen(const double *x, double c, double rgb[3])
{
    int ch;
    for (ch = 0; ch < 3; ch++)
        rgb[ch] = ref_gulbrandsen(x[ch], x[3 + ch], c);
}

/* F0 and the tint through F82, each in [0, 1]. */
static void naive_f82_tint(const target_anchor *a, double *x)
{
    int ch;
    for (ch = 0; ch < 3; ch++) {
        x[ch] = clamp_to(a->f0[ch], 0.0, 1.0);
        x[3 + ch] = clamp_to(tint_through(x[ch], a->f82[ch]), 0.0, 1.0);
    }
}

/* The same with Schlick's ends (color90 = 1, exponent 5) in MaterialX's box. */
static void naive_materialx(const target_anchor *a, double *x)
{
    int ch;
    for (ch = 0; ch < 3; ch++) {
        x[ch] = clamp_to(a->f0[ch], 0.0, MX_COLOUR_MAX);
        x[3 + ch] = clamp_to(tint_through(x[ch], a->f82[ch]), 0.0, MX_COLOUR_MAX);
        x[6 + ch] = 1.0;
    }
    x[9] = 5.0;
}

static void naive_f0(const target_anchor *a, double *x)
{
    int ch;
    for (ch = 0; ch < 3; ch++)
        x[ch] = clamp_to(a->f0[ch], 0.0, 1.0);
}

/* The generator's own Gulbrandsen route: r = F0, g from r and the fitted eta. */
static void naive_gulbrandsen(const target_anchor *a, double *x)
{
    int ch;
    for (ch = 0; ch < 3; ch++) {
        x[ch] = clamp_to(a->f0[ch], 0.0, FRESNEL_GULBRANDSEN_R_MAX);
        x[3 + ch] = ref_gulbrandsen_g(x[ch], a->eta[ch]);
    }
}

const target target_table[TARGETS] = {
    [TARGET_openpbr] = {TARGET_NAME(openpbr), "OpenPBR Surface 1.1, metal (base_metalness = 1, base_weight = specular_weight = 1)",
     "F82-tint: Schlick with a dip scaled by specular_color at cos theta = 1/7",
     "OpenPBR Surface specification v1.1.1, section Metal (academysoftwarefoundation.github.io/OpenPBR)",
     "linear RGB of the host's working space; base_color and specular_color in [0, 1]^3 (specular_color <= 1: "
     "the edge is never brighter than Schlick's)",
     2,
     {{"base_color", 0, 0.0, 1.0}, {"specular_color", 0, 0.0, 1.0}},
     0, "base_color = F0; specular_color = F82 / Schlick(F0) at cos theta = 1/7, at most 1",
     eval_openpbr, naive_f82_tint,
     {"thin_film_weight", "thin_film_thickness", NULL, 1e-3, "thin_film_ior",
      "OpenPBR's thin-film layer over the base: thin_film_thickness in micrometres (specification v1.1.1, "
      "Parameter reference)",
      eval_openpbr_film,
      "the specification's reference graph in MaterialX: its thin film over a generalized_schlick_bsdf with "
      "color0 = base_color, color82 = specular_color, color90 = 1, exponent 5 (common/reference_film.c)"}},
    [TARGET_materialx] = {TARGET_NAME(materialx), "MaterialX generalized_schlick_bsdf (a metal: reflection only)",
     "Hoffman's generalized Schlick: color0 to color90 with exponent, a dip scaled by color82 at cos theta = 1/7",
     "MaterialX PBR specification, node generalized_schlick_bsdf (documents/Specification/MaterialX.PBRSpec.md)",
     "linear RGB of the document's colorspace; the specification states no range: the fit keeps colours in "
     "[0, 2] and the exponent in [1, 10]",
     4,
     {{"color0", 0, 0.0, MX_COLOUR_MAX},
      {"color82", 0, 0.0, MX_COLOUR_MAX},
      {"color90", 0, 0.0, MX_COLOUR_MAX},
      {"exponent", 1, MX_EXPONENT_MIN, MX_EXPONENT_MAX}},
     0, "color0 = F0; color82 = F82 / Schlick(F0) at cos theta = 1/7; color90 = 1; exponent 5",
     eval_materialx, naive_materialx,
     {NULL, "thickness", NULL, 1.0, "ior",
      "a thin_film_bsdf as the top of a layer node over the generalized_schlick_bsdf: thickness in nanometres "
      "(MaterialX PBR specification, node thin_film_bsdf)",
      eval_materialx_film,
      "mx_fresnel_airy of MaterialX's GLSL: Belcour and Barla 2017, the base's index from color0 as a "
      "dielectric's, half its generalized Schlick inside the film, orders m <= 2, CIE RGB (common/reference_film.c)"}},
    [TARGET_blender] = {TARGET_NAME(blender), "Blender 4.x Principled BSDF, Metallic = 1 (Cycles and EEVEE)",
     "OpenPBR's F82-tint, base colour and tint clamped to [0, 1], result clamped to [0, 1]",
     "Blender source: intern/cycles/kernel/svm/closure.h (Principled metallic), "
     "intern/cycles/kernel/closure/bsdf_util.h (fresnel_f82tint_B, fresnel_f82)",
     "Base Color and Specular Tint as scene-linear RGB (Linear Rec.709 by default; the colour picker's RGB "
     "fields, not its hex), each in [0, 1]",
     2,
     {{"base_color", 0, 0.0, 1.0}, {"specular_tint", 0, 0.0, 1.0}},
     0, "base_color = F0; specular_tint = F82 / Schlick(F0) at cos theta = 1/7, at most 1",
     eval_blender, naive_f82_tint,
     {NULL, "Thin Film Thickness", NULL, 1.0, "Thin Film IOR",
      "Principled BSDF (Blender 4.2 and later): Thin Film Thickness in nanometres",
      eval_blender_film,
      "Cycles: Belcour and Barla 2017 with the exact phases, the F82-tint metal read as Gulbrandsen's r, g for "
      "its index, orders m <= 3 against the scene's CIE 1931 sensitivities (common/reference_film.c)"}},
    [TARGET_unreal] = {TARGET_NAME(unreal), "Unreal Engine F_AdobeF82(F0, F82, VoH)",
     "Adobe F82 as BRDF.ush writes it: the same curve as OpenPBR's, F82 being the tint at cos theta = 1/7",
     "Unreal Engine Engine/Shaders/Private/BRDF.ush, F_AdobeF82 (source under Epic's licence; which material "
     "input feeds F82 is not publicly documented: the Substrate Slab documents F0 and F90)",
     "linear RGB of the working colour space (Rec.709 by default); F0 and F82 in [0, 1]: the function clamps "
     "only its result",
     2,
     {{"F0", 0, 0.0, 1.0}, {"F82", 0, 0.0, 1.0}},
     0, "F0 = F0; F82 = F82 / Schlick(F0) at cos theta = 1/7, at most 1",
     eval_unreal, naive_f82_tint, {NULL, NULL, NULL, 0.0, NULL, NULL, NULL, NULL}}, /* no thin-film input known */
    [TARGET_gltf] = {TARGET_NAME(gltf), "glTF 2.0 metallic-roughness, metallicFactor = 1",
     "Schlick with F0 = baseColor and F90 = 1 (KHR_materials_specular changes dielectrics only)",
     "glTF 2.0 specification, Appendix B, B.3.4 and B.3.5 (metal_brdf, conductor_fresnel)",
     "baseColorFactor, linear Rec.709 (sRGB primaries, D65), in [0, 1]; a baseColorTexture holds the same "
     "values sRGB-encoded",
     1,
     {{"baseColorFactor", 0, 0.0, 1.0}},
     1, "baseColorFactor = F0",
     eval_gltf, naive_f0,
     {"iridescenceFactor", "iridescenceThicknessMaximum", "iridescenceThicknessMinimum", 1.0, "iridescenceIor",
      "KHR_materials_iridescence: thicknesses in nanometres; without an iridescenceThicknessTexture the maximum is "
      "the thickness, and the minimum is set to it too",
      eval_gltf_film,
      "KHR_materials_iridescence as the glTF Sample Viewer evaluates it: Belcour and Barla 2017 with Schlick at both "
      "interfaces, the base's index from baseColor as F0 (common/reference_film.c)"}},
    [TARGET_filament] = {TARGET_NAME(filament), "Filament standard lit material, metallic = 1",
     "Schlick with f0 = baseColor and f90 = saturate(dot(f0, 50 * 0.33)) (1 for every metal)",
     "Filament source: shaders/src/surface_brdf.fs (fresnel), shaders/src/common_material.fs (computeF0)",
     "baseColor, linear Rec.709 (sRGB primaries), in [0, 1]",
     1,
     {{"baseColor", 0, 0.0, 1.0}},
     1, "baseColor = F0",
     eval_filament, naive_f0, {NULL, NULL, NULL, 0.0, NULL, NULL, NULL, NULL}}, /* no thin-film input known */
    [TARGET_gulbrandsen] = {TARGET_NAME(gulbrandsen), "Gulbrandsen's artist-friendly metallic Fresnel (reflectivity r, edge tint g)",
     "r, g to n, k, then the approximate unpolarised conductor Fresnel, as the paper defines it",
     "Gulbrandsen 2014, \"Artist Friendly Metallic Fresnel\", JCGT 3(4), section 2.3.3 (n, k from r, g) and "
     "equations 4-6 (the approximate Fresnel); common/reference.c, ref_gulbrandsen",
     "linear RGB of the renderer's working space; reflectivity in [0, 1) (0.9999 here, the runtime's clamp), "
     "edge_tint in [0, 1]",
     2,
     {{"reflectivity", 0, 0.0, FRESNEL_GULBRANDSEN_R_MAX}, {"edge_tint", 0, 0.0, 1.0}},
     0, "reflectivity = F0; edge_tint = the generator's Gulbrandsen g, from F0 and the fitted eta",
     eval_gulbrandsen, naive_gulbrandsen, {NULL, NULL, NULL, 0.0, NULL, NULL, NULL, NULL}}, /* no thin-film input known */
};
const int target_count = (int)(sizeof target_table / sizeof target_table[0]);

int target_film_rows(const target *t, double n, double d_nm, const char *names[4], double values[4])
{
    const target_film *f = &t->film;
    int k = 0;
    if (!f->thickness)
        return 0;
    if (f->weight)
        names[k] = f->weight, values[k++] = 1.0;
    names[k] = f->thickness, values[k++] = d_nm * f->per_nm;
    if (f->thickness_min)
        names[k] = f->thickness_min, values[k++] = d_nm * f->per_nm;
    names[k] = f->ior, values[k++] = n;
    return k;
}

const target *target_find(const char *name)
{
    int id = target_parse(name);
    return id < 0 ? NULL : &target_table[id];
}

int target_x_count(const target *t)
{
    int i, n = 0;
    for (i = 0; i < t->param_count; i++)
        n += t->param[i].scalar ? 1 : 3;
    return n;
}

int target_above_one(const target *t)
{
    int i;
    for (i = 0; i < t->param_count; i++)
        if (!t->param[i].scalar && t->param[i].hi > 1.0)
            return 1;
    return 0;
}
