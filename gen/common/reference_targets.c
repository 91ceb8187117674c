/* Renderers' metal Fresnel formulas (reference.h). Facts from each
 * renderer's specification or source text, transcribed with their
 * citation; no renderer's code. */
#include "common/reference.h"

#include <math.h>

/* The cosine every F82 form is anchored at: arccos(1/7) = 81.79 degrees. */
#define MU_BAR (1.0 / 7.0)

static double pow6(double x)
{
    double x3 = x * x * x;
    return x3 * x3;
}

static double clamp01(double x) { return ref_clamp(x, 0.0, 1.0); }

static double schlick_unclamped(double f0, double mu) { return f0 + (1.0 - f0) * pow(1.0 - mu, 5.0); }

/* OpenPBR Surface specification v1.1.1,
 * https://academysoftwarefoundation.github.io/OpenPBR/ (index.html), section
 * "Metal" [Kutz, Hasan, Edmondson 2021, "Novel aspects of the Adobe Standard
 * Material"]:
 *   F_Schlick(mu) = F0 + (1 - F0) (1 - mu)^5, F0 = base_weight * base_color
 *   F_82(mu) = F_Schlick(mu) - mu (1 - mu)^6 / (mubar (1 - mubar)^6)
 *                              * (F_Schlick(mubar) - F(mubar)), mubar = 1/7
 *   F(mubar) = specular_color * F_Schlick(mubar)
 *   F_metal(mu) = specular_weight * F_82(mu)
 * base_weight = specular_weight = 1 here. The specification states the
 * ranges (base_color, specular_color in [0, 1]^3) and no clamp of F. */
double ref_openpbr_f82_tint(double base_color, double specular_color, double mu)
{
    double edge = schlick_unclamped(base_color, MU_BAR);
    return schlick_unclamped(base_color, mu) -
           mu * pow6(1.0 - mu) / (MU_BAR * pow6(1.0 - MU_BAR)) * (edge - specular_color * edge);
}

/* MaterialX Physically Based Shading Nodes (documents/Specification/
 * MaterialX.PBRSpec.md in AcademySoftwareFoundation/MaterialX), node
 * generalized_schlick_bsdf, "Generalized Schlick Equations" [Hoffman 2023,
 * "Generalization of Adobe's Fresnel Model"]; ports color0 = r0,
 * color82 = t, color90 = r90, exponent = q:
 *   a = [r0 + (r90 - r0)(1 - cos theta_max)^q] (1 - t)
 *       / (cos theta_max (1 - cos theta_max)^6),  cos theta_max = 1/7
 *   F = r0 + (r90 - r0)(1 - cos theta)^q - a cos theta (1 - cos theta)^6
 * The node table states no accepted range for the four and no clamp. */
double ref_materialx_schlick(double color0, double color82, double color90, double exponent, double mu)
{
    double a = (color0 + (color90 - color0) * pow(1.0 - MU_BAR, exponent)) * (1.0 - color82) /
               (MU_BAR * pow6(1.0 - MU_BAR));
    return color0 + (color90 - color0) * pow(1.0 - mu, exponent) - a * mu * pow6(1.0 - mu);
}

/* Blender 4.x, Principled BSDF, metallic component (Cycles): the F82-tint
 * curve with F0 = Base Color and tint = Specular Tint.
 * intern/cycles/kernel/svm/closure.h clamps the base colour to [0, 1]
 * (max with 0, then min with 1) and the tint to at most 1;
 * intern/cycles/kernel/closure/bsdf_util.h, fresnel_f82tint_B and
 * fresnel_f82: B = Schlick(F0, 1/7) (7 / (6/7)^6) (1 - tint),
 * F = saturate(Schlick(F0, mu) - B mu (1 - mu)^6). EEVEE subtracts the same B
 * through its split-sum table (brdf_f82_tint_lut), and the Metallic BSDF's
 * "F82 Tint" mode passes Base Color and Edge Tint the same way (the manual
 * calls Edge Tint the colour at 82 degrees; both engines multiply Schlick's
 * value there by it). 7 / (6/7)^6 = 1 / (mubar (1 - mubar)^6): OpenPBR's
 * curve. */
double ref_blender_f82_tint(double base_color, double specular_tint, double mu)
{
    return clamp01(ref_openpbr_f82_tint(clamp01(base_color), clamp01(specular_tint), mu));
}

/* Unreal Engine, Engine/Shaders/Private/BRDF.ush, F_AdobeF82(F0, F82, VoH)
 * [Kutz et al. 2021, section 2.3; the source's own comment says the paper's
 * formulas do not match the code and the code is correct]:
 *   Fc = (1 - VoH)^5, K = 49 / 46656
 *   b = (K - K F82) (7776 + 9031 F0)
 *   F = saturate(F0 + Fc ((1 - F0) - b (VoH - VoH^2)))
 * Unreal's source is distributed under Epic's licence, not publicly; the
 * formula is the function's text as public ports quote it. */
double ref_unreal_adobe_f82(double f0, double f82, double voh)
{
    const double k = 49.0 / 46656.0;
    double fc = pow(1.0 - voh, 5.0);
    double b = (k - k * f82) * (7776.0 + 9031.0 * f0);
    return clamp01(f0 + fc * ((1.0 - f0) - b * (voh - voh * voh)));
}

/* Filament, shaders/src/surface_brdf.fs, fresnel(f0, LoH) at the default
 * quality: F_Schlick(f0, f90, LoH) = f0 + (f90 - f0) (1 - LoH)^5 with
 * f90 = saturate(dot(f0, vec3(50.0 * 0.33))) (1 at FILAMENT_QUALITY_LOW);
 * f0 = baseColor * metallic + dielectric f0 (1 - metallic)
 * (shaders/src/common_material.fs, computeF0), baseColor for a metal. */
double ref_filament_f90(const double f0[3])
{
    return clamp01((f0[0] + f0[1] + f0[2]) * (50.0 * 0.33));
}
