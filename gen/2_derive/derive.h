/* The generator's later steps [MS18, Hof20], after the spectral ground truth
 * (spectral.h): parameters fitted to it, tables encoded from it, one C header
 * emitted per scene.
 *
 *   derive_parameters.c   F0, F82, RGB eta/kappa (Gaussian window and fit),
 *                         LSK a/alpha, Gulbrandsen r/g, Cook-Torrance IOR
 *   encode_lut.c          LUT node values fitted to the ground truth
 *   emit_header.c         the scene's const arrays, nothing else
 *
 * OUT-OF-GAMUT POLICY. A material's spectral ground truth can leave [0, 1]
 * in a display's linear RGB (gold's red F0 is about 1.04 in linear sRGB with
 * this data: its colour is outside the sRGB gamut). The runtime's results are
 * reflectances in [0, 1], so the ground truth is clamped per channel to
 * [0, 1] before any parameter is derived from it, as a display would clip.
 * Of the peers' choices (keep the value, rescale the colour by its maximum as
 * Filament's tool does, clamp) clamping changes the fewest channels and keeps
 * grazing incidence white; `fresnel params` still prints the unclamped F0.
 * The report measures every model against the clamped ground truth (what a
 * model can represent) and states the clamp's own CIEDE2000 cost separately. */
#ifndef FRESNEL_DERIVE_H
#define FRESNEL_DERIVE_H

#include "1_spectral/spectral.h"

#define GEN_FIT_ANGLES 91 /* ground truth samples for fitting: theta = 0, 1, ..., 90 degrees */

/* Everything the generator knows about one material in one colour space.
 * eta and kappa are relative to the incident medium n1, as the runtime
 * takes them. */
typedef struct material_params {
    material_info info;
    double measured_lo, measured_hi; /* nm, within 360-830; outside, end values held */
    double n1, sigma;
    double nm[3];               /* dominant wavelengths of the space's primaries */
    double f0_unclamped[3];     /* ground truth at normal incidence */
    double f0[3], f82[3];       /* clamped ground truth at c = 1 and c = 1/7 */
    double f_avg[3], f_avg_unclamped[3]; /* 2 x integral of F(mu) mu over [0, 1]: clamped and not */
    double eta_gauss[3], kappa_gauss[3]; /* Metzgar's Gaussian window, sigma nm */
    double eta_point[3], kappa_point[3]; /* point-sampled at the dominant wavelengths (Hoffman's "PS") */
    double eta_fit[3], kappa_fit[3];     /* Hoffman's black-box fit to the ground truth */
    double fit_rms[3];
    double lsk_a[3], lsk_alpha[3];       /* compensation of LSK on the fitted eta, kappa */
    double gulb_r[3], gulb_g[3];         /* r = F0, g from F0 and the fitted eta */
    double ct_eta, ct_kappa;             /* Cook-Torrance: the IOR at the green wavelength */
} material_params;

/* Colour science shared by every material of a run. */
typedef struct gen_context {
    const char *dir;
    colorimetry cm;
    colour_space cs;
    double nm[3];
} gen_context;
int gen_context_load(const char *dir, const char *space, gen_context *g);

/* The cosine-weighted hemispherical average F_avg = 2 int_0^1 F(mu) mu dmu
 * of the ground truth, clamped (the policy above) or not, per channel, by a
 * composite 5-point Gauss-Legendre rule on `panels` panels. */
#define GEN_AVG_PANELS 64
void ground_truth_average(const spectrum *s, const gen_context *g, double n1, int clamped, int panels,
                          double avg[3]);

/* Clamped ground truth (the policy above) at cosine c. */
void ground_truth_clamped(const spectrum *s, const gen_context *g, double n1, double c,
                          double rgb[3]);

/* Load the material (data/<id>.csv or the user's file) and derive
 * everything; 0 or CLI_BAD_INPUT. *s receives the resampled spectrum for
 * callers that need more ground truth. */
int derive_parameters(const gen_context *g, const material_source *m, double sigma, double n1, spectrum *s,
                      material_params *out);

#endif
