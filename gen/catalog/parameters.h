/* The parameters the generator derives for each material and a scene's
 * header may hold, one line each, in the order every back end writes them.
 * The list is expanded by the material's record (2_derive/derive.h:
 * material_params), the encoder (3_encode/encode.h: encoded_material,
 * binary32, Q1.15 and binary16), the range check every scene passes
 * (model/encoded_scene.c), the back ends (4_emit/emit_floats.c,
 * emit_f16.c, emit_q15.c) and `fresnel params`. A new parameter is a line
 * here and its derivation in 2_derive/derive_parameters.c.
 *
 *   X(field, count, group, constant, row, why, q15, q15_why)
 *
 * field     its member in material_params and encoded_material (binary16:
 *           h_<field>, Q1.15 codes: q_<field>)
 * count     3 (r, g, b) or 1 (one number)
 * group     the MP_* bit of the scene models that read it (model rows:
 *           model/registry.c), MP_F_AVG for the scene's f_avg key
 * constant  its name in a generated header: fresnel_<scene>_<material>_<constant>
 * row       its row in `fresnel params`
 * why       the constant's comment in the header
 * q15       how the Q1.15 header holds it: Q15_NONE (not as a code: the
 *           prepared constants of fresnel_q15.h hold the indices),
 *           Q15_CODE (round(v 32768) in [0, 65535]), Q15_CODE_ONE (in
 *           [0, 32768]), Q15_CODE_HELD (F0: above one it is held to one,
 *           as every Q1.15 function reads it)
 * q15_why   the Q1.15 constant's comment */
#ifndef FRESNEL_CATALOG_PARAMETERS_H
#define FRESNEL_CATALOG_PARAMETERS_H

/* Which parameters a scene model reads, one bit per group (the model rows'
 * `reads`), in the order above. */
#define MP_F0 0x01u
#define MP_F82 0x02u
#define MP_ETA_FIT 0x04u
#define MP_LSK 0x08u
#define MP_ETA_GAUSS 0x10u
#define MP_ETA_POINT 0x20u
#define MP_GULB 0x40u
#define MP_CT 0x80u
#define MP_F_AVG 0x100u /* no model reads it: the scene's f_avg key asks for it */

/* Prepared Q1.15 constants (fresnel_q15.h) a scene model reads (the
 * model rows' `q15_reads`), in the order the Q1.15 back end writes them,
 * after the codes above. */
#define MQ_LSK 0x01u
#define MQ_LSK_COMP 0x02u
#define MQ_IOR 0x04u
#define MQ_IOR_GAUSS 0x08u
#define MQ_IOR_POINT 0x10u
#define MQ_NK 0x20u
#define MQ_CT 0x40u

#define DERIVED_PARAMETERS(X)                                                                                          \
    X(f0, 3, MP_F0, "f0", "f0", "F0: ground truth at normal incidence", Q15_CODE_HELD, "F0")                            \
    X(f_avg, 3, MP_F_AVG, "f_avg", "f_avg",                                                                            \
      "F_avg: 2 int F(mu) mu dmu of the ground truth (multiple-scattering albedo)", Q15_CODE,                           \
      "F_avg = 2 int F(mu) mu dmu of the ground truth")                                                                \
    X(f82, 3, MP_F82, "f82", "f82", "F82: ground truth at cos theta = 1/7 (fresnel_f82_rgb)", Q15_CODE, "F82")         \
    X(eta_fit, 3, MP_ETA_FIT, "eta", "eta_fit", "eta fitted to the ground truth (exact, lsk, approx-conductor)",        \
      Q15_NONE, "")                                                                                                    \
    X(kappa_fit, 3, MP_ETA_FIT, "kappa", "kappa_fit", "kappa fitted to the ground truth", Q15_NONE, "")                 \
    X(lsk_a, 3, MP_LSK, "lsk_a", "lsk_a", "LSK compensation weight a (fresnel_lsk_comp_rgb)", Q15_NONE, "")             \
    X(lsk_alpha, 3, MP_LSK, "lsk_alpha", "lsk_alpha", "LSK compensation exponent alpha", Q15_NONE, "")                  \
    X(eta_gauss, 3, MP_ETA_GAUSS, "eta_gaussian", "eta_gaussian",                                                      \
      "Metzgar: eta' in a Gaussian window (fresnel_conductor_rgb)", Q15_NONE, "")                                      \
    X(kappa_gauss, 3, MP_ETA_GAUSS, "kappa_gaussian", "kappa_gaussian", "Metzgar: kappa' in a Gaussian window",         \
      Q15_NONE, "")                                                                                                    \
    X(eta_point, 3, MP_ETA_POINT, "eta_point", "eta_point",                                                            \
      "eta point-sampled at the dominant wavelengths (fresnel_conductor_rgb)", Q15_NONE, "")                           \
    X(kappa_point, 3, MP_ETA_POINT, "kappa_point", "kappa_point", "kappa point-sampled at the dominant wavelengths",    \
      Q15_NONE, "")                                                                                                    \
    X(gulb_r, 3, MP_GULB, "gulbrandsen_r", "gulbrandsen_r", "Gulbrandsen reflectivity r = F0 (fresnel_gulbrandsen_rgb)", \
      Q15_CODE_ONE, "Gulbrandsen r")                                                                                   \
    X(gulb_g, 3, MP_GULB, "gulbrandsen_g", "gulbrandsen_g", "Gulbrandsen edge tint g from F0 and the fitted eta",       \
      Q15_CODE_ONE, "Gulbrandsen g")                                                                                   \
    X(ct_eta, 1, MP_CT, "ct_eta", "cook_torrance_eta",                                                                 \
      "Cook-Torrance representative IOR at the green wavelength (fresnel_cook_torrance_rgb)", Q15_NONE, "")           \
    X(ct_kappa, 1, MP_CT, "ct_kappa", "cook_torrance_kappa", "Cook-Torrance representative kappa", Q15_NONE, "")

/* Spelling helpers for the expansions: a member of `count` numbers of a
 * type (PARAM_ARRAY_3 [3], PARAM_ARRAY_1 nothing), its first number's
 * address, and the largest Q1.15 code of a q15 kind (0: none). */
#define PARAM_ARRAY_3 [3]
#define PARAM_ARRAY_1
#define PARAM_ADDRESS_3(v) (v)
#define PARAM_ADDRESS_1(v) (&(v))
#define Q15_MAX_Q15_NONE 0L
#define Q15_MAX_Q15_CODE 65535L
#define Q15_MAX_Q15_CODE_ONE 32768L
#define Q15_MAX_Q15_CODE_HELD 65535L

#endif
