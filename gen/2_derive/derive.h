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
 * this data: its colour is outside the sRGB gamut, inside Display-P3's).
 * Every parameter, table and figure is derived from the ground truth under
 * the run's policy (a scene's `gamut` key, --gamut on the commands):
 *   map   (default) the in-gamut colour nearest in CIEDE2000 to the
 *         unclipped truth at each node angle, joined smoothly (gamut.c);
 *         for a display that shows [0, 1] only.
 *   clip  each channel clamped to [0, 1]: what a display does to a value
 *         above 1; kept to compare with.
 *   keep  no mapping; values above 1 stay (below 0 is 0), for pipelines
 *         that work in linear RGB with headroom and map the gamut at display.
 * `fresnel params` also prints the unclipped F0 and F_avg; the report
 * measures the policy's own cost and every model against the unclipped
 * truth for each material that leaves the gamut. */
#ifndef FRESNEL_DERIVE_H
#define FRESNEL_DERIVE_H

#include "1_spectral/colour_difference.h"
#include "1_spectral/spectral.h"
#include "catalog/choices.h"
#include "catalog/parameters.h"
#include "scene/scene.h"

/* Node angles of the map policy: theta_k = k 90 / (GAMUT_NODES - 1) degrees. */
#define GAMUT_NODES 181

#define GEN_FIT_ANGLES 91 /* ground truth samples for fitting: theta = 0, 1, ..., 90 degrees */

/* Everything the generator knows about one material in one colour space.
 * eta and kappa are relative to the incident medium n1, as the runtime
 * takes them. */
typedef struct material_params {
    material_info info;
    double measured_lo, measured_hi; /* nm, within 360-830; outside, end values held */
    double n1, sigma;
    double film_n;              /* the thin film's index on it (material_source); 0: none */
    double nm[3];               /* dominant wavelengths of the space's primaries */
    double f0_unclamped[3];     /* ground truth at normal incidence */
    double f_avg_unclamped[3];  /* 2 x integral of F(mu) mu over [0, 1], unclipped */
    double fit_rms[3];          /* of the fitted eta, kappa */
    /* every parameter of catalog/parameters.h (its line says what it is),
     * derived under the gamut policy by derive_parameters */
#define MATERIAL_PARAM_MEMBER(field, count, group, constant, row, why, q15, q15_why) double field PARAM_ARRAY_##count;
    DERIVED_PARAMETERS(MATERIAL_PARAM_MEMBER)
#undef MATERIAL_PARAM_MEMBER
    int gamut_mapped;                    /* the map policy moved some node (gamut.c) */
    double gamut_shift[GAMUT_NODES][3];  /* nearest in-gamut colour - truth at theta_k */
} material_params;

/* Colour science shared by every material of a run. */
typedef struct gen_context {
    const char *dir;
    colorimetry cm;
    colour_space cs;
    double nm[3];
    gamut_policy gamut;
} gen_context;
/* Loads the space's colorimetry; the policy is GAMUT_MAP until the caller
 * sets another. */
int gen_context_load(const char *dir, const char *space, gen_context *g);

/* The cosine-weighted hemispherical average F_avg = 2 int_0^1 F(mu) mu dmu
 * per channel of a curve, by a composite 5-point Gauss-Legendre rule on
 * `panels` panels; ground_truth_average's curve is the ground truth under
 * the policy (under_policy = 1) or unclipped (0). */
#define GEN_AVG_PANELS 64
void hemispherical_average(void (*curve)(const void *ctx, double mu, double rgb[3]), const void *ctx, int panels,
                           double avg[3]);
void ground_truth_average(const spectrum *s, const gen_context *g, const material_params *p, int under_policy,
                          int panels, double avg[3]);

/* gamut.c. Whether a colour lies in the gamut [0, 1]^3: every channel
 * within GAMUT_TOLERANCE of [0, 1]. A colour on the gamut's boundary comes
 * out of the spectral ground truth a rounding away from it: a perfect
 * reflector (every material at grazing incidence, c = 0) is
 * 1.0000000000000002 in linear Rec.2020's green, because the rows of the
 * XYZ-to-RGB matrix, each scaled so that white maps to 1, meet white with a
 * rounding of their own. The tolerance lies above that arithmetic's error
 * (471 positive products summed, then a row of three: about 1e-13 at most,
 * a few 1e-16 in practice) and far below what a colour difference sees (a
 * step of 1e-12 in one channel is a CIEDE2000 below 1e-8, tests/gen/test_gamut.c).
 * Every decision that a colour leaves the gamut is this one, at both ends:
 * the map policy's nodes, the keep policy's values at 1, `fresnel params`,
 * the report. */
#define GAMUT_TOLERANCE 1e-12
int gamut_contains(const double rgb[3]);
/* The ground truth at cosine c under g->gamut, for the material whose map
 * derive_parameters built into p. A channel within GAMUT_TOLERANCE outside
 * [0, 1] is on the boundary under every policy (keep too). */
void ground_truth_gamut(const spectrum *s, const gen_context *g, const material_params *p, double c,
                        double rgb[3]);
/* The map policy's nodes for p (p->n1 set); nothing for the other policies. */
void gamut_map_build(const spectrum *s, const gen_context *g, material_params *p);
/* The linear RGB in [0, 1]^3 nearest in CIEDE2000 to truth; returns the
 * difference. */
double gamut_nearest(const lab_space *ls, const double truth[3], double out[3]);

/* Material i of a scene as derive_parameters takes it (pointing into sc),
 * with its film's index where the scene has the thin-film model. */
material_source scene_material(const scene *sc, int i);

/* Load the material (data/<id>.csv or the user's file) and derive
 * everything; 0 or CLI_BAD_INPUT. *s receives the resampled spectrum for
 * callers that need more ground truth. */
int derive_parameters(const gen_context *g, const material_source *m, double sigma, double n1, spectrum *s,
                      material_params *out);

#endif
