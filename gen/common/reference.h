/* Double-precision reference of every model: the yardstick for every error
 * bound in the project. Host only, never linked into the runtime.
 *
 * Same conventions as include/fresnel.h (relative eta and kappa, inputs
 * clamped to the same domains, results in [0, 1]), evaluated in binary64.
 * ref_conductor is the careful real form; ref_conductor_complex is an
 * independent evaluation through complex amplitudes (C99 complex), and the
 * tests hold the two to 1e-12 relative. */
#ifndef FRESNEL_REFERENCE_H
#define FRESNEL_REFERENCE_H

double ref_schlick(double f0, double c);
double ref_schlick_gen(double f0, double f90, double p, double c);
double ref_schlick_internal(double f0, double eta, double c);
double ref_f0_in_medium(double f0, double eta_e);
double ref_f0_from_ior(double eta, double kappa);

double ref_lsk(double n, double k, double c);
double ref_lsk_comp(double n, double k, double a, double alpha, double c);
/* LSK's derived constants [LS05]: a = 2n and alpha matching exact - rescaled
 * at c = 0.15; a = alpha = 0 (no compensation) where that error is >= 0 or
 * the fit would need alpha <= 0. */
void ref_lsk_fit(double n, double k, double *a, double *alpha);
/* The same fit against any curve: target_015 is its value at c = 0.15 (the
 * generator passes the spectral ground truth there). */
void ref_lsk_fit_target(double n, double k, double target_015, double *a, double *alpha);

double ref_f82(double f0, double f82, double c);
/* F82's coefficient a = (7^7/6^6)(F0 - F82) + (49/6)(1 - F0) of
 * F = Schlick(F0) - a c (1 - c)^6 (Hoffman's F82 model), F0 and F82 as
 * given. */
double ref_f82_a(double f0, double f82);

void ref_gulbrandsen_nk(double r, double g, double *n, double *k);
void ref_gulbrandsen_rg(double n, double k, double *r, double *g);
/* Edge tint g for a given reflectivity r and eta (Hoffman's route: r from the
 * spectral F0, eta from elsewhere), clamped to [0, 1]. */
double ref_gulbrandsen_g(double r, double n);
double ref_gulbrandsen(double r, double g, double c);

double ref_approx_conductor(double n, double k, double c);
double ref_cook_torrance(double f0, double eta, double kappa, double c);

/* Exact unpolarised reflectance, careful real form; *_sp gives Rs and Rp. */
double ref_conductor(double eta, double kappa, double c);
void ref_conductor_sp(double eta, double kappa, double c, double *rs, double *rp);
/* 1 - ref_conductor, accurate when the reflectance is near 1. */
double ref_conductor_transmittance(double eta, double kappa, double c);
/* Independent: r_s, r_p from complex amplitudes with cos(theta_t) on the
 * branch where the transmitted wave decays (Im >= 0). */
double ref_conductor_complex(double eta, double kappa, double c);
void ref_conductor_complex_sp(double eta, double kappa, double c, double *rs, double *rp);
double ref_dielectric(double eta, double c);

/* Same clamps as the runtime (fresnel.h CONVENTIONS); NaN gives lo. */
double ref_clamp(double x, double lo, double hi);

/* A LUT of n >= 2 nodes v[0..n-1] at position x in [0, 1] (x = sqrt(c) or c,
 * as the table's spacing), unclamped: linear between the two nodes around
 * x, or (cubic) Catmull-Rom through the four around it, the outer ones
 * clamped to the table's ends, written as weights (src/f32/lut.c uses a Hermite
 * form on differences). */
double ref_lut(const double *v, int n, int cubic, double x);

#endif

/* Renderers' metal Fresnel formulas, transcribed from their specifications
 * (reference_targets.c: the source beside each); `fresnel params --for`
 * fits their parameters (2_derive/targets.h). Each keeps its renderer's own
 * clamps and no others: where the source clamps nothing, neither do these.
 * mu (or VoH) is the cosine of the angle of incidence. Two renderers need
 * no function of their own: glTF's metal Fresnel is ref_schlick (F0 =
 * baseColor), Filament's is ref_schlick_gen with exponent 5 and
 * f90 = ref_filament_f90(F0), and Gulbrandsen's is ref_gulbrandsen. */

/* OpenPBR's F82-tint: Schlick minus mu (1 - mu)^6 b, with b such that
 * F(1/7) = specular_color * Schlick(1/7). The project's F82 model
 * (ref_f82) is the same curve named by its value at 1/7 instead:
 * ref_f82(f0, t * ref_schlick(f0, 1/7), mu) for t <= 1. */
double ref_openpbr_f82_tint(double base_color, double specular_color, double mu);
/* MaterialX generalized_schlick_bsdf: Hoffman's generalisation (color90,
 * exponent) of the same dip; color82 is a multiplier of the curve at 1/7. */
double ref_materialx_schlick(double color0, double color82, double color90, double exponent, double mu);
/* Blender Principled BSDF, metallic: OpenPBR's curve with base colour and
 * specular tint clamped to [0, 1] and the result to [0, 1]. */
double ref_blender_f82_tint(double base_color, double specular_tint, double mu);
/* Unreal Engine's F_AdobeF82, written as its source writes it (the same
 * curve as OpenPBR's, F82 being the tint; the test derives it), result
 * clamped to [0, 1]. */
double ref_unreal_adobe_f82(double f0, double f82, double voh);
/* Filament's f90 for an RGB f0 (shared by the three channels). */
double ref_filament_f90(const double f0[3]);
